//! The num-bigint big-integer kernel (pure Rust), selected by the
//! `num-kernel` feature or a build without ccd-arith's default features.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::Integer as _;
use num_traits::{Signed, ToPrimitive, Zero};

pub(crate) type Inner = BigInt;

crate::backend_refops::reference_operators!();

#[inline]
pub(crate) fn signum(a: &Inner) -> i32 {
    match a.sign() {
        Sign::Minus => -1,
        Sign::NoSign => 0,
        Sign::Plus => 1,
    }
}
#[inline]
pub(crate) fn bits(a: &Inner) -> u64 {
    a.bits()
}
#[inline]
pub(crate) fn div_rem_trunc(a: &Inner, b: &Inner) -> (Inner, Inner) {
    a.div_rem(b)
}
#[inline]
pub(crate) fn div_floor(a: &Inner, b: &Inner) -> Inner {
    a.div_floor(b)
}
/// `gcd(|a|, |b|)` by Lehmer's algorithm (Knuth, TAOCP 4.5.2, Algorithm
/// L): num-bigint's own gcd is binary (Stein), one shift of the whole
/// number per bit, quadratic in the *bit* length; Lehmer's replaces about
/// 30 Euclidean steps by one 2×2 cofactor product on the leading 63 bits,
/// and a size gap is closed by one division first.
pub(crate) fn gcd(a: &Inner, b: &Inner) -> Inner {
    BigInt::from(lehmer_gcd(a.magnitude().clone(), b.magnitude().clone()))
}

fn lehmer_gcd(mut a: BigUint, mut b: BigUint) -> BigUint {
    if a < b {
        std::mem::swap(&mut a, &mut b);
    }
    // Invariant: a >= b.
    while b.bits() > 64 {
        let n = a.bits();
        if n - b.bits() > 32 {
            let r = &a % &b;
            a = std::mem::replace(&mut b, r);
            continue;
        }
        let shift = n - 63;
        let leading = |x: &BigUint| (x >> shift).to_u64().expect("63 bits") as i128;
        let (mut x, mut y) = (leading(&a), leading(&b));
        let (mut ca, mut cb, mut cc, mut cd) = (1i128, 0i128, 0i128, 1i128);
        while y + cc != 0 && y + cd != 0 {
            let q = (x + ca) / (y + cc);
            if q != (x + cb) / (y + cd) {
                break;
            }
            (ca, cc) = (cc, ca - q * cc);
            (cb, cd) = (cd, cb - q * cd);
            (x, y) = (y, x - q * y);
        }
        if cb == 0 {
            let r = &a % &b;
            a = std::mem::replace(&mut b, r);
        } else {
            let (sa, sb) = (BigInt::from(a), BigInt::from(b));
            let na = &sa * BigInt::from(ca) + &sb * BigInt::from(cb);
            let nb = &sa * BigInt::from(cc) + &sb * BigInt::from(cd);
            a = na.into_parts().1;
            b = nb.into_parts().1;
            if a < b {
                std::mem::swap(&mut a, &mut b);
            }
        }
    }
    if b.is_zero() {
        return a;
    }
    // Both fit after one reduction: finish in machine words.
    let r = (&a % &b).to_u64().expect("below b");
    let (mut x, mut y) = (b.to_u64().expect("64 bits"), r);
    while y != 0 {
        (x, y) = (y, x % y);
    }
    BigUint::from(x)
}

#[inline]
pub(crate) fn shl(a: &Inner, k: u64) -> Inner {
    a << k
}
#[inline]
pub(crate) fn shr_floor(a: &Inner, k: u64) -> Inner {
    // num-bigint's >> on negatives rounds toward -inf.
    a >> k
}
#[inline]
pub(crate) fn trailing_zeros(a: &Inner) -> Option<u64> {
    a.trailing_zeros()
}
#[inline]
pub(crate) fn pow(a: &Inner, e: u32) -> Inner {
    num_traits::Pow::pow(a, e)
}
#[inline]
pub(crate) fn to_i64(a: &Inner) -> Option<i64> {
    a.to_i64()
}
#[inline]
pub(crate) fn u64_digit_of_abs(a: &Inner, i: usize) -> u64 {
    a.magnitude().iter_u64_digits().nth(i).unwrap_or(0)
}
#[inline]
pub(crate) fn mod_u64(a: &Inner, p: u64) -> u64 {
    let r = (a.magnitude() % p).to_u64().unwrap_or(0);
    if a.sign() == Sign::Minus && r != 0 {
        p - r
    } else {
        r
    }
}
/// The magnitude's 64-bit digits (num-bigint keeps no such slice: a copy).
#[inline]
pub(crate) fn abs_digits(a: &Inner) -> std::borrow::Cow<'_, [u64]> {
    std::borrow::Cow::Owned(a.magnitude().to_u64_digits())
}
pub(crate) fn to_u64_limbs(a: &Inner) -> (bool, Vec<u64>) {
    (a.sign() == Sign::Minus, a.magnitude().to_u64_digits())
}
pub(crate) fn from_u64_limbs(negative: bool, limbs: &[u64]) -> Inner {
    let mut halves = Vec::with_capacity(limbs.len() * 2);
    for &l in limbs {
        halves.push(l as u32);
        halves.push((l >> 32) as u32);
    }
    let mag = BigUint::new(halves);
    let s = if negative { Sign::Minus } else { Sign::Plus };
    BigInt::from_biguint(s, mag)
}
pub(crate) fn parse_decimal(s: &str) -> Option<Inner> {
    BigInt::parse_bytes(s.as_bytes(), 10)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn big(limbs: &[u64]) -> BigUint {
        limbs
            .iter()
            .fold(BigUint::zero(), |acc, &l| (acc << 64u32) + BigUint::from(l))
    }

    proptest! {
        /// Lehmer's gcd equals the binary gcd of num-bigint, on numbers
        /// built with a large common factor and on unrelated ones.
        #[test]
        fn lehmer_matches_binary_gcd(
            a in proptest::collection::vec(any::<u64>(), 0..12),
            b in proptest::collection::vec(any::<u64>(), 0..12),
            g in proptest::collection::vec(any::<u64>(), 0..6),
        ) {
            let (a, b, g) = (big(&a), big(&b), big(&g));
            for (x, y) in [(a.clone(), b.clone()), (&a * &g, &b * &g), (a.clone() * &g, g.clone())] {
                prop_assert_eq!(lehmer_gcd(x.clone(), y.clone()), x.gcd(&y));
            }
        }
    }
}
