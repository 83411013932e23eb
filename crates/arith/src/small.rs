//! [`SmallInt`]: an `i128` that detects overflow, the machine-word
//! companion of [`Int`] for exact computations whose numbers are usually
//! short (the constant quadrics of two static bodies and their `det(λA + B)`).

use crate::{Int, Ring, RingOps};

/// An exact integer in `i128`, or the marker that an exact value on the way
/// did not fit. Every [`RingOps`] operation is exact or overflows, and an
/// overflowed value stays overflowed through every later operation (an
/// exact division that does not divide counts as an overflow too): a
/// generic routine runs over `SmallInt` first and, when
/// [`SmallInt::to_int`] says `None`, again over [`Int`], with the same
/// result.
///
/// ```
/// use ccd_arith::{Int, RingOps, SmallInt};
/// let x = SmallInt::from_i64(i64::MAX);
/// assert_eq!(x.times(&x).to_int(), Some(&Int::from(i64::MAX) * &Int::from(i64::MAX)));
/// assert_eq!(x.times(&x).times(&x).to_int(), None); // about 2^189
/// ```
#[derive(Clone, Copy, Debug)]
pub struct SmallInt(i128);

/// Equal only as exact values: an overflowed value equals nothing, not even
/// another overflowed one (like a NaN), so no test `x == y` can pass on two
/// values that did not fit.
impl PartialEq for SmallInt {
    fn eq(&self, o: &SmallInt) -> bool {
        self.exact().is_some() && self.0 == o.0
    }
}

/// The overflow marker (so `−2^127` itself counts as an overflow: the
/// routine then runs over [`Int`], which is only slower).
const OVERFLOW: i128 = i128::MIN;

impl SmallInt {
    /// `x` if it fits, else overflowed.
    #[inline]
    pub fn of(x: &Int) -> SmallInt {
        SmallInt(x.to_i128().unwrap_or(OVERFLOW))
    }

    /// `v` (`−2^127`, the overflow marker, comes in overflowed).
    #[inline]
    pub fn from_i128(v: i128) -> SmallInt {
        SmallInt(v)
    }

    /// The overflowed value: what an operation whose exact result does
    /// not fit gives.
    #[inline]
    pub fn overflowed() -> SmallInt {
        SmallInt(OVERFLOW)
    }

    /// The exact value, `None` if an operation overflowed.
    #[inline]
    pub fn to_int(&self) -> Option<Int> {
        let v = self.exact()?;
        Some(i64::try_from(v).map_or_else(|_| Int::from_i128(v), Int::from_i64))
    }

    /// The exact value as an `i128`, `None` if an operation overflowed.
    #[inline]
    pub fn to_i128(&self) -> Option<i128> {
        self.exact()
    }

    /// The value, `None` when overflowed.
    #[inline]
    fn exact(self) -> Option<i128> {
        (self.0 != OVERFLOW).then_some(self.0)
    }

    /// The non-negative greatest common divisor (`gcd(0, 0) = 0`);
    /// overflowed when either is.
    pub fn gcd(&self, o: &SmallInt) -> SmallInt {
        let (Some(a), Some(b)) = (self.exact(), o.exact()) else {
            return SmallInt(OVERFLOW);
        };
        // |a|, |b| < 2^127: so is their gcd.
        SmallInt(gcd_u128(a.unsigned_abs(), b.unsigned_abs()) as i128)
    }

    /// `op` on both values, overflowed when either is or `op` says `None`.
    #[inline]
    fn zip(self, o: SmallInt, op: impl Fn(i128, i128) -> Option<i128>) -> SmallInt {
        match (self.exact(), o.exact()) {
            (Some(a), Some(b)) => SmallInt(op(a, b).unwrap_or(OVERFLOW)),
            _ => SmallInt(OVERFLOW),
        }
    }
}

impl RingOps for SmallInt {
    #[inline]
    fn zero() -> Self {
        SmallInt(0)
    }
    #[inline]
    fn one() -> Self {
        SmallInt(1)
    }
    #[inline]
    fn from_i64(v: i64) -> Self {
        SmallInt(i128::from(v))
    }
    #[inline]
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
    #[inline]
    fn plus(&self, o: &Self) -> Self {
        self.zip(*o, i128::checked_add)
    }
    #[inline]
    fn minus(&self, o: &Self) -> Self {
        self.zip(*o, i128::checked_sub)
    }
    /// Two values that fit `i64` multiply without a check (the product's
    /// magnitude is at most `2^126`); others through `checked_mul`.
    #[inline]
    fn times(&self, o: &Self) -> Self {
        match (i64::try_from(self.0), i64::try_from(o.0)) {
            (Ok(a), Ok(b)) => SmallInt(i128::from(a) * i128::from(b)),
            _ => self.zip(*o, i128::checked_mul),
        }
    }
    #[inline]
    fn negated(&self) -> Self {
        // −OVERFLOW does not fit: it stays overflowed.
        SmallInt(self.0.checked_neg().unwrap_or(OVERFLOW))
    }
    /// Exact division; a `k` that does not divide overflows.
    fn div_small(&self, k: i64) -> Self {
        self.div_exact(&SmallInt::from_i64(k))
    }
    #[inline]
    fn add_product(&mut self, x: &Self, y: &Self, negate: bool) {
        let p = x.times(y);
        *self = if negate {
            self.minus(&p)
        } else {
            self.plus(&p)
        };
    }
}

impl Ring for SmallInt {
    /// Exact division; a divisor that does not divide (or zero) overflows.
    fn div_exact(&self, o: &Self) -> Self {
        self.zip(*o, |a, b| match (i64::try_from(a), i64::try_from(b)) {
            // Machine words when both fit (an i128 division is a library
            // call) and neither a zero divisor nor i64::MIN / −1 can occur.
            (Ok(x), Ok(y)) if y != 0 && y != -1 => (x % y == 0).then(|| i128::from(x / y)),
            _ => (a.checked_rem(b)? == 0).then(|| a.checked_div(b))?,
        })
    }
}

/// Binary gcd (`gcd(0, 0) = 0`). When one operand is much shorter than
/// the other (a running content against a long coefficient), Euclid's
/// first step `gcd(a, b) = gcd(a, b mod a)` comes first: one division
/// instead of a chain of subtractions as long as `b`.
///
/// Operands that both fit a machine word take Euclid's algorithm in
/// `u64` (an `u128` remainder is a library call, and the binary loop
/// costs more on short numbers).
pub fn gcd_u128(a: u128, b: u128) -> u128 {
    if let (Ok(mut x), Ok(mut y)) = (u64::try_from(a), u64::try_from(b)) {
        while y != 0 {
            (x, y) = (y, x % y);
        }
        return u128::from(x);
    }
    let (mut a, mut b) = if a <= b { (a, b) } else { (b, a) };
    if a == 0 {
        return b;
    }
    if a.leading_zeros() > b.leading_zeros() + 8 {
        b %= a;
        if b == 0 {
            return a;
        }
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::SmallInt;
    use crate::{Int, Ring, RingOps};

    #[test]
    fn overflowed_values_equal_nothing() {
        let big = SmallInt::of(&Int::one().shl(200));
        let other = SmallInt::of(&Int::one().shl(300));
        assert!(big != other && big != big);
        assert!(big != SmallInt::from_i64(0));
        assert_eq!(SmallInt::from_i64(7), SmallInt::of(&Int::from(7)));
    }

    proptest::proptest! {
        /// Every operation is the exact one on `Int`, or overflowed only
        /// when the exact value does not fit `i128`.
        #[test]
        fn operations_are_exact_or_overflow(a in proptest::num::i128::ANY, b in proptest::num::i128::ANY, s in 0u32..128) {
            let (a, b) = ((a >> s).max(-i128::MAX), (b >> (127 - s.min(127))).max(-i128::MAX));
            let (x, y) = (SmallInt::of(&Int::from_i128(a)), SmallInt::of(&Int::from_i128(b)));
            let (ia, ib) = (Int::from_i128(a), Int::from_i128(b));
            // −2^127 is the overflow marker.
            let fits = |v: &Int| v.to_i128().filter(|x| *x != i128::MIN);
            let cases = [
                (x.plus(&y), &ia + &ib),
                (x.minus(&y), &ia - &ib),
                (x.times(&y), &ia * &ib),
                (x.negated(), -&ia),
                (x.gcd(&y), ia.gcd(&ib)),
            ];
            for (small, exact) in cases {
                proptest::prop_assert_eq!(small.to_int(), fits(&exact).map(Int::from_i128));
            }
            let mut acc = x;
            acc.add_product(&y, &y, true);
            proptest::prop_assert_eq!(acc.to_int(), fits(&(&ia - &(&ib * &ib))).map(Int::from_i128));
            if b != 0 {
                let q = x.times(&y).div_exact(&y);
                proptest::prop_assert!(q.to_int().is_none_or(|q| q == ia));
                proptest::prop_assert_eq!(x.div_exact(&y).to_int().is_some(), a.checked_rem(b) == Some(0));
            }
        }
    }
}
