//! The GMP big-integer kernel (rug), selected by the `gmp` feature.

use rug::integer::Order;
use rug::ops::{DivRounding, Pow};
use rug::{Complete, Integer};
use std::cmp::Ordering;

pub(crate) type Inner = Integer;

#[inline]
pub(crate) fn from_i64(v: i64) -> Inner {
    Integer::from(v)
}
#[inline]
pub(crate) fn from_u64(v: u64) -> Inner {
    Integer::from(v)
}
#[inline]
pub(crate) fn is_zero(a: &Inner) -> bool {
    a.is_zero()
}
#[inline]
pub(crate) fn signum(a: &Inner) -> i32 {
    match a.cmp0() {
        Ordering::Less => -1,
        Ordering::Equal => 0,
        Ordering::Greater => 1,
    }
}
#[inline]
pub(crate) fn bits(a: &Inner) -> u64 {
    u64::from(a.significant_bits())
}
#[inline]
pub(crate) fn abs(a: &Inner) -> Inner {
    Integer::from(a.abs_ref())
}
#[inline]
pub(crate) fn neg(a: &Inner) -> Inner {
    Integer::from(-a)
}
#[inline]
pub(crate) fn add(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a + b)
}
#[inline]
pub(crate) fn sub(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a - b)
}
#[inline]
pub(crate) fn mul(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a * b)
}
#[inline]
pub(crate) fn mul_i64(a: &Inner, b: i64) -> Inner {
    Integer::from(a * b)
}
crate::backend_refops::assigning_operators!();
#[inline]
pub(crate) fn div_trunc(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a / b)
}
#[inline]
pub(crate) fn div_rem_trunc(a: &Inner, b: &Inner) -> (Inner, Inner) {
    // Into two new numbers; `a.clone().div_rem(b.clone())` allocated two
    // copies first (every `div_exact` came here).
    a.div_rem_ref(b).complete()
}
#[inline]
pub(crate) fn div_floor(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a.div_floor(b))
}
#[inline]
pub(crate) fn gcd(a: &Inner, b: &Inner) -> Inner {
    Integer::from(a.gcd_ref(b))
}
#[inline]
pub(crate) fn shl(a: &Inner, k: u64) -> Inner {
    Integer::from(a << (k as u32))
}
#[inline]
pub(crate) fn shr_floor(a: &Inner, k: u64) -> Inner {
    // GMP's >> on Integer rounds toward -inf (fdiv_q_2exp).
    Integer::from(a >> (k as u32))
}
#[inline]
pub(crate) fn trailing_zeros(a: &Inner) -> Option<u64> {
    a.find_one(0).map(u64::from)
}
#[inline]
pub(crate) fn pow(a: &Inner, e: u32) -> Inner {
    Integer::from(a.pow(e))
}
#[inline]
pub(crate) fn to_i64(a: &Inner) -> Option<i64> {
    a.to_i64()
}
#[inline]
pub(crate) fn u64_digit_of_abs(a: &Inner, i: usize) -> u64 {
    a.as_limbs().get(i).map_or(0, |&l| l)
}
#[inline]
pub(crate) fn mod_u64(a: &Inner, p: u64) -> u64 {
    let pb = Integer::from(p);
    let mut r = Integer::from(a % &pb);
    if r.cmp0() == Ordering::Less {
        r += &pb;
    }
    r.to_u64().unwrap_or(0)
}
/// The magnitude's 64-bit limbs, borrowed.
#[inline]
pub(crate) fn abs_digits(a: &Inner) -> std::borrow::Cow<'_, [u64]> {
    std::borrow::Cow::Borrowed(a.as_limbs())
}
pub(crate) fn to_u64_limbs(a: &Inner) -> (bool, Vec<u64>) {
    let mut limbs = vec![0u64; a.significant_digits::<u64>()];
    a.write_digits(&mut limbs, Order::Lsf);
    (a.cmp0() == Ordering::Less, limbs)
}
pub(crate) fn from_u64_limbs(negative: bool, limbs: &[u64]) -> Inner {
    let m = Integer::from_digits(limbs, Order::Lsf);
    if negative {
        -m
    } else {
        m
    }
}
pub(crate) fn parse_decimal(s: &str) -> Option<Inner> {
    Integer::from_str_radix(s, 10).ok()
}
pub(crate) fn fmt(a: &Inner, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
    std::fmt::Display::fmt(a, f)
}
