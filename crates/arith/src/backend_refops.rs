//! The kernel functions that num-bigint and dashu spell alike: both build
//! from machine integers with `From` and implement the arithmetic operators
//! on references, so each function is one expression. With the `gmp`
//! feature (dashu's kernel, GMP for long operands: `backend_gmp`) the
//! products and divisions first offer their operands to GMP.

/// Defines `from_i64`, `is_zero`, `abs`, `from_u64`, `neg`, `add`, `sub`,
/// `mul`, `mul_i64`, the assigning operators ([`assigning_operators`]),
/// `div_trunc` and `fmt` for the calling module's `Inner`.
macro_rules! reference_operators {
    () => {
        #[inline]
        pub(crate) fn from_i64(v: i64) -> Inner {
            Inner::from(v)
        }
        #[inline]
        pub(crate) fn is_zero(a: &Inner) -> bool {
            a.is_zero()
        }
        #[inline]
        pub(crate) fn abs(a: &Inner) -> Inner {
            a.abs()
        }
        #[inline]
        pub(crate) fn from_u64(v: u64) -> Inner {
            Inner::from(v)
        }
        #[inline]
        pub(crate) fn neg(a: &Inner) -> Inner {
            -a
        }
        #[inline]
        pub(crate) fn add(a: &Inner, b: &Inner) -> Inner {
            a + b
        }
        #[inline]
        pub(crate) fn sub(a: &Inner, b: &Inner) -> Inner {
            a - b
        }
        #[inline]
        pub(crate) fn mul(a: &Inner, b: &Inner) -> Inner {
            #[cfg(feature = "gmp")]
            if crate::backend_gmp::both_long(a, b) {
                return crate::backend_gmp::mul(a, b);
            }
            a * b
        }
        #[inline]
        pub(crate) fn mul_i64(a: &Inner, b: i64) -> Inner {
            a * b
        }
        crate::backend_refops::assigning_operators!();
        /// Division by zero panics, as in every kernel.
        #[inline]
        pub(crate) fn div_trunc(a: &Inner, b: &Inner) -> Inner {
            #[cfg(feature = "gmp")]
            if crate::backend_gmp::both_long(a, b) {
                return crate::backend_gmp::div_rem_trunc(a, b).0;
            }
            a / b
        }
        pub(crate) fn fmt(a: &Inner, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            std::fmt::Display::fmt(a, f)
        }
    };
}
pub(crate) use reference_operators;

/// Defines `add_assign`, `sub_assign`, `mul_assign` and `add_mul`, which
/// both kernels spell with the assigning operators.
macro_rules! assigning_operators {
    () => {
        #[inline]
        pub(crate) fn add_assign(a: &mut Inner, b: &Inner) {
            *a += b;
        }
        #[inline]
        pub(crate) fn sub_assign(a: &mut Inner, b: &Inner) {
            *a -= b;
        }
        #[inline]
        pub(crate) fn mul_assign(a: &mut Inner, b: &Inner) {
            #[cfg(feature = "gmp")]
            if crate::backend_gmp::both_long(a, b) {
                *a = crate::backend_gmp::mul(a, b);
                return;
            }
            *a *= b;
        }
        #[inline]
        pub(crate) fn add_mul(acc: &mut Inner, b: &Inner, c: &Inner) {
            #[cfg(feature = "gmp")]
            if crate::backend_gmp::both_long(b, c) {
                *acc += crate::backend_gmp::mul(b, c);
                return;
            }
            *acc += b * c;
        }
    };
}
pub(crate) use assigning_operators;
