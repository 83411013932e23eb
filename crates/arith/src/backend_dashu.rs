//! The dashu big-integer kernel (pure Rust), the default (ccd-arith's
//! `dashu` feature). Numbers of up to 128 bits live inline, without a heap
//! buffer. With the `gmp` feature it stays the kernel, and long products,
//! gcds and divisions go to GMP (`backend_gmp`).
//!
//! dashu panics where the other kernels answer: `gcd(0, 0)` (num-bigint and
//! GMP give 0) and `IBig % u64` on a negative remainder (it converts the
//! remainder back to `u64`); the functions below guard both. Division by
//! zero panics, as in every kernel.

use dashu_int::ops::{Abs, BitTest, DivRem, Gcd, RemEuclid};
use dashu_int::{IBig, Sign};

pub(crate) type Inner = IBig;

crate::backend_refops::reference_operators!();

#[inline]
pub(crate) fn signum(a: &Inner) -> i32 {
    // dashu's zero has the positive sign.
    match a.sign() {
        _ if a.is_zero() => 0,
        Sign::Negative => -1,
        Sign::Positive => 1,
    }
}
#[inline]
pub(crate) fn bits(a: &Inner) -> u64 {
    a.bit_len() as u64
}
#[inline]
pub(crate) fn div_rem_trunc(a: &Inner, b: &Inner) -> (Inner, Inner) {
    #[cfg(feature = "gmp")]
    if crate::backend_gmp::both_long(a, b) {
        return crate::backend_gmp::div_rem_trunc(a, b);
    }
    a.div_rem(b)
}
#[inline]
pub(crate) fn div_floor(a: &Inner, b: &Inner) -> Inner {
    let (q, r) = div_rem_trunc(a, b);
    // The truncated remainder has the dividend's sign: step down when it
    // is non-zero and disagrees with the divisor's.
    if !r.is_zero() && (r.sign() != b.sign()) {
        q - IBig::ONE
    } else {
        q
    }
}
/// `gcd(|a|, |b|)`, with `gcd(0, 0) = 0` (dashu's own panics on two zeros;
/// it is Lehmer's algorithm on large operands already).
#[inline]
pub(crate) fn gcd(a: &Inner, b: &Inner) -> Inner {
    if a.is_zero() {
        b.abs()
    } else if b.is_zero() {
        a.abs()
    } else {
        #[cfg(feature = "gmp")]
        if crate::backend_gmp::both_long(a, b) {
            return crate::backend_gmp::gcd(a, b);
        }
        IBig::from(a.gcd(b))
    }
}
#[inline]
pub(crate) fn shl(a: &Inner, k: u64) -> Inner {
    a << shift_amount(k)
}
#[inline]
pub(crate) fn shr_floor(a: &Inner, k: u64) -> Inner {
    // dashu's >> on negatives rounds toward -inf.
    a >> shift_amount(k)
}
/// A shift count as dashu's `usize` (lossless on the 64-bit targets that
/// [`u64_digit_of_abs`] needs anyway).
#[inline]
fn shift_amount(k: u64) -> usize {
    usize::try_from(k).expect("shift count fits in usize")
}
#[inline]
pub(crate) fn trailing_zeros(a: &Inner) -> Option<u64> {
    a.trailing_zeros().map(|z| z as u64)
}
#[inline]
pub(crate) fn pow(a: &Inner, e: u32) -> Inner {
    a.pow(e as usize)
}
#[inline]
pub(crate) fn to_i64(a: &Inner) -> Option<i64> {
    i64::try_from(a).ok()
}
/// The magnitude's 64-bit words, least significant first (none for zero).
/// dashu's word is `u64` on 64-bit targets; elsewhere this does not compile.
#[inline]
fn words(a: &Inner) -> &[u64] {
    a.as_sign_words().1
}
#[inline]
pub(crate) fn u64_digit_of_abs(a: &Inner, i: usize) -> u64 {
    words(a).get(i).map_or(0, |&w| w)
}
#[inline]
pub(crate) fn mod_u64(a: &Inner, p: u64) -> u64 {
    let r = a.rem_euclid(IBig::from(p));
    u64::try_from(&r).expect("below p")
}
/// The magnitude's 64-bit words, borrowed.
#[inline]
pub(crate) fn abs_digits(a: &Inner) -> std::borrow::Cow<'_, [u64]> {
    std::borrow::Cow::Borrowed(words(a))
}
pub(crate) fn to_u64_limbs(a: &Inner) -> (bool, Vec<u64>) {
    (a.sign() == Sign::Negative, words(a).to_vec())
}
/// Numbers of up to two significant words are built inline (dashu's
/// `from_sign_words` allocates a buffer first, even for those).
pub(crate) fn from_u64_limbs(negative: bool, limbs: &[u64]) -> Inner {
    let s = if negative {
        Sign::Negative
    } else {
        Sign::Positive
    };
    let significant = limbs.iter().rposition(|&w| w != 0).map_or(0, |i| i + 1);
    if significant <= 2 {
        let digit = |i: usize| limbs.get(i).map_or(0, |&w| u128::from(w));
        return IBig::from_parts(s, dashu_int::UBig::from(digit(1) << 64 | digit(0)));
    }
    IBig::from_sign_words(s, &limbs[..significant])
}
pub(crate) fn parse_decimal(s: &str) -> Option<Inner> {
    IBig::from_str_radix(s, 10).ok()
}
