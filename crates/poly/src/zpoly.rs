//! [`ZPoly`]: dense polynomials in `Z[t]` in the power basis — the type,
//! its construction and ring arithmetic. The other operations are in the
//! submodules, one concept each: [`eval`] (values and signs at points),
//! [`division`] (exact and pseudo-division, content), [`substitution`]
//! (Taylor shifts, affine substitutions, reversal); the gcd is in
//! [`crate::modular`] and the Bernstein conversion in `crate::bernstein`.

pub(crate) mod division;
pub(crate) mod eval;
pub(crate) mod substitution;

use crate::mul::mul_coeffs;
use ccd_arith::{Int, Ring};
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A dense integer polynomial `p(t) = Σ_i coeffs[i]·t^i` in the power basis,
/// with no trailing zero coefficients (the zero polynomial has none).
///
/// ```
/// use ccd_poly::ZPoly;
/// let p = ZPoly::from_i64s(&[-1, 0, 1]); // t² − 1
/// let q = ZPoly::from_i64s(&[1, 1]); //     t + 1
/// assert_eq!(p.div_exact(&q), Some(ZPoly::from_i64s(&[-1, 1])));
/// assert_eq!(p.gcd(&ZPoly::from_i64s(&[2, 2, 0, 0])), q);
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct ZPoly {
    c: Vec<Int>,
}

/// Drops trailing zero coefficients.
fn trim(c: &mut Vec<Int>) {
    while c.last().is_some_and(Int::is_zero) {
        c.pop();
    }
}

impl ZPoly {
    /// The polynomial with the given coefficients (`coeffs[i]` of `t^i`);
    /// trailing zeros are dropped.
    pub fn new(mut coeffs: Vec<Int>) -> ZPoly {
        trim(&mut coeffs);
        ZPoly { c: coeffs }
    }
    /// From machine-integer coefficients, constant term first.
    pub fn from_i64s(c: &[i64]) -> ZPoly {
        ZPoly::new(c.iter().map(|&x| Int::from(x)).collect())
    }
    /// `0`.
    pub fn zero() -> ZPoly {
        ZPoly { c: Vec::new() }
    }
    /// `1`.
    pub fn one() -> ZPoly {
        ZPoly {
            c: vec![Int::one()],
        }
    }
    /// The constant polynomial `c`.
    pub fn constant(c: Int) -> ZPoly {
        ZPoly::new(vec![c])
    }
    /// The variable `t`.
    pub fn x() -> ZPoly {
        ZPoly {
            c: vec![Int::zero(), Int::one()],
        }
    }
    /// `c·t^k`.
    pub fn monomial(c: Int, k: usize) -> ZPoly {
        if c.is_zero() {
            return ZPoly::zero();
        }
        let mut v = vec![Int::zero(); k + 1];
        v[k] = c;
        ZPoly { c: v }
    }
    /// The coefficients, constant term first, without trailing zeros.
    pub fn coeffs(&self) -> &[Int] {
        &self.c
    }
    /// The coefficient vector, constant term first.
    pub fn into_coeffs(self) -> Vec<Int> {
        self.c
    }
    /// The coefficient of `t^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> Int {
        self.c.get(i).cloned().unwrap_or_default()
    }
    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }
    /// `self == 0`.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }
    /// The leading coefficient; `None` for zero.
    pub fn leading(&self) -> Option<&Int> {
        self.c.last()
    }
    /// `max_i bits(|c_i|)` (0 for the zero polynomial).
    pub fn max_bits(&self) -> u64 {
        self.c.iter().map(Int::bits).max().unwrap_or(0)
    }
    /// `c·p`.
    pub fn mul_int(&self, c: &Int) -> ZPoly {
        if c.is_zero() {
            return ZPoly::zero();
        }
        ZPoly {
            c: self.c.iter().map(|x| x * c).collect(),
        }
    }
    /// The derivative `p'(t) = Σ i·c_i t^(i−1)`.
    pub fn derivative(&self) -> ZPoly {
        ZPoly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, x)| x.mul_i64(i as i64))
                .collect(),
        )
    }
    /// `p^e` by repeated squaring (`p^0 = 1`).
    pub fn pow(&self, mut e: u32) -> ZPoly {
        let (mut base, mut acc) = (self.clone(), ZPoly::one());
        while e > 0 {
            if e & 1 == 1 {
                acc = &acc * &base;
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        acc
    }
    /// Approximate `f64` coefficients (not certified), constant term first.
    pub fn to_f64(&self) -> Vec<f64> {
        self.c.iter().map(Int::to_f64).collect()
    }
}

/// Coefficientwise `a + sign·b`.
fn add_signed(a: &ZPoly, b: &ZPoly, negate_b: bool) -> ZPoly {
    let n = a.c.len().max(b.c.len());
    let v = (0..n)
        .map(|i| match (a.c.get(i), b.c.get(i)) {
            (Some(x), Some(y)) if negate_b => x - y,
            (Some(x), Some(y)) => x + y,
            (Some(x), None) => x.clone(),
            (None, Some(y)) if negate_b => -y,
            (None, Some(y)) => y.clone(),
            (None, None) => unreachable!("index below the longer length"),
        })
        .collect();
    ZPoly::new(v)
}

impl Add<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    fn add(self, o: &ZPoly) -> ZPoly {
        add_signed(self, o, false)
    }
}
impl Sub<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    fn sub(self, o: &ZPoly) -> ZPoly {
        add_signed(self, o, true)
    }
}
impl Mul<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    /// The product, by [`crate::mul::mul_coeffs`] (schoolbook, Kronecker or
    /// multimodular by size).
    fn mul(self, o: &ZPoly) -> ZPoly {
        ZPoly::new(mul_coeffs(&self.c, &o.c))
    }
}
impl Neg for &ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        ZPoly {
            c: self.c.iter().map(|x| -x).collect(),
        }
    }
}
impl Neg for ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        ZPoly {
            c: self.c.into_iter().map(|x| -x).collect(),
        }
    }
}

/// The owned and mixed operator forms, and the compound assignments,
/// delegating to the `&T op &T` implementations.
macro_rules! forward_binops {
    ($t:ty) => {
        forward_binops!(@one $t, Add, add, AddAssign, add_assign);
        forward_binops!(@one $t, Sub, sub, SubAssign, sub_assign);
        forward_binops!(@one $t, Mul, mul, MulAssign, mul_assign);
    };
    (@one $t:ty, $tr:ident, $m:ident, $tra:ident, $ma:ident) => {
        impl $tr<$t> for $t {
            type Output = $t;
            fn $m(self, o: $t) -> $t {
                (&self).$m(&o)
            }
        }
        impl $tr<&$t> for $t {
            type Output = $t;
            fn $m(self, o: &$t) -> $t {
                (&self).$m(o)
            }
        }
        impl $tr<$t> for &$t {
            type Output = $t;
            fn $m(self, o: $t) -> $t {
                self.$m(&o)
            }
        }
        impl $tra<&$t> for $t {
            fn $ma(&mut self, o: &$t) {
                *self = (&*self).$m(o);
            }
        }
    };
}
pub(crate) use forward_binops;
forward_binops!(ZPoly);

ccd_arith::ring_ops_via_operators!(ZPoly, zero: ZPoly::zero(), one: ZPoly::one(), from_i64: |v| ZPoly::constant(Int::from(v)), is_zero: |x| ZPoly::is_zero(x), div_small: |a, k| a.div_exact_int(&Int::from(k)), squared: |x| ZPoly::new(crate::mul::sqr_coeffs(&x.c)), add_product: |acc, x, y, negate| {
    crate::mul::add_mul_coeffs(&mut acc.c, &x.c, &y.c, negate);
    trim(&mut acc.c);
});

impl Ring for ZPoly {
    /// The exact quotient in `Z[t]`; panics if `o` does not divide `self`.
    fn div_exact(&self, o: &Self) -> Self {
        ZPoly::div_exact(self, o)
            .expect("Ring::div_exact for ZPoly: the divisor does not divide exactly")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::zpoly;
    use ccd_arith::RingOps;
    use proptest::prelude::*;

    fn z(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    #[test]
    fn construction_trims_and_reports() {
        let p = ZPoly::new(vec![Int::from(3), Int::zero(), Int::from(-5), Int::zero()]);
        assert_eq!(p.degree(), Some(2));
        assert_eq!(p.leading(), Some(&Int::from(-5)));
        assert_eq!(p.coeff(7), Int::zero());
        assert_eq!(p.max_bits(), 3);
        assert_eq!(ZPoly::zero().degree(), None);
        assert_eq!(ZPoly::monomial(Int::from(4), 3), z(&[0, 0, 0, 4]));
        assert!(ZPoly::monomial(Int::zero(), 3).is_zero());
        assert_eq!(ZPoly::constant(Int::zero()), ZPoly::zero());
        assert_eq!(ZPoly::x().pow(3), z(&[0, 0, 0, 1]));
        assert_eq!(z(&[1, 1]).pow(0), ZPoly::one());
        assert_eq!(z(&[0, 1, 1]).reverse(), z(&[1, 1]));
        assert_eq!(<ZPoly as ccd_arith::RingOps>::from_i64(-2), z(&[-2]));
        assert_eq!(ZPoly::default(), ZPoly::zero());
        assert_eq!(
            z(&[6, -4, 2])
                .mul_int(&Int::from(3))
                .div_exact_int(&Int::from(6)),
            z(&[3, -2, 1])
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The in-place `add_product` and `squared` are the plain ring
        /// operations as polynomials (no trailing zeros: a product that
        /// cancels the accumulator leaves the zero polynomial).
        #[test]
        fn in_place_products_are_the_ring_operations(a in zpoly(8, 300), b in zpoly(8, 300), c in zpoly(8, 300), negate in any::<bool>()) {
            for acc in [c.clone(), &a * &b, -&(&a * &b)] {
                let mut got = acc.clone();
                got.add_product(&a, &b, negate);
                let want = if negate { acc.minus(&a.times(&b)) } else { acc.plus(&a.times(&b)) };
                prop_assert_eq!(&got, &want);
                prop_assert!(got.coeffs().last().is_none_or(|x| !x.is_zero()));
            }
            prop_assert_eq!(a.squared(), &a * &a);
        }

        #[test]
        fn ring_identities(a in zpoly(12, 300), b in zpoly(12, 300), c in zpoly(12, 300)) {
            prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
            prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
            prop_assert_eq!(&a * &b, &b * &a);
            prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
            prop_assert!((&a - &a).is_zero());
            prop_assert_eq!(-(-a.clone()), a.clone());
            prop_assert_eq!(&a * &ZPoly::one(), a.clone());
            let mut s = a.clone();
            s += &b;
            s -= &c;
            prop_assert_eq!(s, a.plus(&b).minus(&c));
            prop_assert_eq!(a.times(&b).negated(), -(a.clone() * b.clone()));
        }
    }
}
