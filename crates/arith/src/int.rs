//! [`Int`]: an arbitrary-precision integer whose kernel is chosen at build
//! time (dashu by default, num-bigint with the `num-kernel` feature; the
//! `gmp` feature keeps dashu and runs long products, gcds and divisions in
//! GMP through rug).
//!
//! Every crate above this one sees only [`Int`]; the three kernels pass the
//! same tests.

use crate::kernel as k;

use std::borrow::Cow;
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// An exact integer of any size.
///
/// ```
/// use ccd_arith::Int;
/// let a = Int::from(6) * Int::from(7);
/// assert_eq!(a.to_string(), "42");
/// assert_eq!(a.gcd(&Int::from(35)), Int::from(7));
/// ```
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Int(pub(crate) k::Inner);

impl Int {
    /// Zero.
    #[inline]
    pub fn zero() -> Int {
        Int(k::from_i64(0))
    }
    /// One.
    #[inline]
    pub fn one() -> Int {
        Int(k::from_i64(1))
    }
    /// From a machine integer.
    #[inline]
    pub fn from_i64(v: i64) -> Int {
        Int(k::from_i64(v))
    }
    /// From an unsigned machine integer.
    #[inline]
    pub fn from_u64(v: u64) -> Int {
        Int(k::from_u64(v))
    }
    /// `self == 0`.
    #[inline]
    pub fn is_zero(&self) -> bool {
        k::is_zero(&self.0)
    }
    /// −1, 0 or 1.
    #[inline]
    pub fn signum(&self) -> i32 {
        k::signum(&self.0)
    }
    /// `self > 0`.
    #[inline]
    pub fn is_positive(&self) -> bool {
        self.signum() > 0
    }
    /// `self < 0`.
    #[inline]
    pub fn is_negative(&self) -> bool {
        self.signum() < 0
    }
    /// `self == 1`.
    #[inline]
    pub fn is_one(&self) -> bool {
        self.to_i64() == Some(1)
    }
    /// Number of bits of `|self|` (0 for zero).
    #[inline]
    pub fn bits(&self) -> u64 {
        k::bits(&self.0)
    }
    /// `|self|`.
    #[inline]
    pub fn abs(&self) -> Int {
        Int(k::abs(&self.0))
    }
    /// `self · v` for a machine integer `v`.
    #[inline]
    pub fn mul_i64(&self, v: i64) -> Int {
        Int(k::mul_i64(&self.0, v))
    }
    /// `self += b · c`, without a temporary where the kernel allows it.
    #[inline]
    pub fn add_mul(&mut self, b: &Int, c: &Int) {
        k::add_mul(&mut self.0, &b.0, &c.0)
    }
    /// Exact quotient `self / d`; the caller guarantees `d | self`
    /// (checked in debug builds).
    #[inline]
    pub fn div_exact(&self, d: &Int) -> Int {
        let (q, r) = k::div_rem_trunc(&self.0, &d.0);
        debug_assert!(k::is_zero(&r), "div_exact: {self} is not divisible by {d}");
        Int(q)
    }
    /// Quotient rounded toward zero.
    #[inline]
    pub fn div_trunc(&self, d: &Int) -> Int {
        Int(k::div_trunc(&self.0, &d.0))
    }
    /// Quotient and remainder, quotient rounded toward zero.
    #[inline]
    pub fn div_rem_trunc(&self, d: &Int) -> (Int, Int) {
        let (q, r) = k::div_rem_trunc(&self.0, &d.0);
        (Int(q), Int(r))
    }
    /// Quotient rounded toward −∞.
    #[inline]
    pub fn div_floor(&self, d: &Int) -> Int {
        Int(k::div_floor(&self.0, &d.0))
    }
    /// `d | self` (with `d ≠ 0`).
    #[inline]
    pub fn is_divisible_by(&self, d: &Int) -> bool {
        k::is_zero(&k::div_rem_trunc(&self.0, &d.0).1)
    }
    /// How often `p ≥ 2` divides `self ≠ 0`, counted up to `cap` (the
    /// least of the two): by the largest power `P = p^m` in a word, a word
    /// remainder and a division by a word per `m` factors for the first
    /// `VALUATION_WORD_STEPS` (8) of them (the usual counts), then `P², P⁴,
    /// …` while they divide and back down the same powers (a number of
    /// divisions logarithmic in the count: `3^400000·x` took 0.56 s one
    /// word at a time), the last factors from a word remainder (`p = 2`:
    /// the trailing zeros).
    ///
    /// ```
    /// use ccd_arith::Int;
    /// let x = Int::from(10).pow(37) * Int::from(7);
    /// assert_eq!(x.valuation(10, u64::MAX), 37);
    /// assert_eq!(x.valuation(10, 20), 20);
    /// assert_eq!(x.valuation(3, u64::MAX), 0);
    /// ```
    pub fn valuation(&self, p: u32, cap: u64) -> u64 {
        debug_assert!(p >= 2 && !self.is_zero());
        if p == 2 {
            return self.trailing_zeros().unwrap_or(0).min(cap);
        }
        let p = u64::from(p);
        let (mut word, mut m) = (p, 1);
        while let Some(next) = word.checked_mul(p) {
            (word, m) = (next, m + 1);
        }
        let (mut v, mut rest) = (0, self.clone());
        let p_word = Int::from_u64(word);
        let mut r = rest.mod_u64(word);
        for _ in 0..VALUATION_WORD_STEPS {
            if v >= cap || r != 0 {
                break;
            }
            rest = rest.div_exact(&p_word);
            v += m;
            r = rest.mod_u64(word);
        }
        if v < cap && r == 0 {
            // P^(2^i) for i = 0, 1, … while it divides (and the cap is not
            // met), then back down: what is left is below P^(2^len).
            let mut powers = vec![p_word];
            while v < cap {
                let top = powers.last().expect("one power at least");
                let (q, rem) = rest.div_rem_trunc(top);
                if !rem.is_zero() {
                    break;
                }
                rest = q;
                v += m << (powers.len() - 1);
                let square = top * top;
                if square.bits() > rest.bits() {
                    break;
                }
                powers.push(square);
            }
            for (i, power) in powers.iter().enumerate().rev() {
                if v >= cap {
                    break;
                }
                let (q, rem) = rest.div_rem_trunc(power);
                if rem.is_zero() {
                    rest = q;
                    v += m << i;
                }
            }
            r = rest.mod_u64(word);
        }
        // Fewer than m factors p are left: one word remainder.
        while v < cap && r != 0 && r % p == 0 {
            (r, v) = (r / p, v + 1);
        }
        v.min(cap)
    }
    /// Non-negative greatest common divisor (`gcd(0, 0) = 0`).
    #[inline]
    pub fn gcd(&self, other: &Int) -> Int {
        Int(k::gcd(&self.0, &other.0))
    }
    /// Least common multiple (common denominators); `0` when either is `0`.
    ///
    /// ```
    /// use ccd_arith::Int;
    /// assert_eq!(Int::from(4).lcm(&Int::from(6)), Int::from(12));
    /// assert_eq!(Int::zero().lcm(&Int::zero()), Int::zero());
    /// ```
    pub fn lcm(&self, other: &Int) -> Int {
        if self.is_zero() || other.is_zero() {
            return Int::zero();
        }
        self.div_exact(&self.gcd(other)) * other
    }
    /// `self · 2^s`.
    #[inline]
    pub fn shl(&self, s: u64) -> Int {
        Int(k::shl(&self.0, s))
    }
    /// `⌊self / 2^s⌋`.
    #[inline]
    pub fn shr_floor(&self, s: u64) -> Int {
        Int(k::shr_floor(&self.0, s))
    }
    /// The exponent of the largest power of two dividing `self` (`None` for zero).
    #[inline]
    pub fn trailing_zeros(&self) -> Option<u64> {
        k::trailing_zeros(&self.0)
    }
    /// `k` when `self = 2^k` (`k ≥ 0`), else `None` (zero and negative
    /// numbers included).
    ///
    /// ```
    /// use ccd_arith::Int;
    /// assert_eq!(Int::from(8).exact_log2(), Some(3));
    /// assert_eq!(Int::from(1).exact_log2(), Some(0));
    /// assert_eq!(Int::from(-8).exact_log2(), None);
    /// assert_eq!(Int::from(12).exact_log2(), None);
    /// ```
    #[inline]
    pub fn exact_log2(&self) -> Option<u64> {
        let k = self.trailing_zeros()?;
        (self.signum() > 0 && self.bits() == k + 1).then_some(k)
    }
    /// `self^e`.
    #[inline]
    pub fn pow(&self, e: u32) -> Int {
        Int(k::pow(&self.0, e))
    }
    /// The value as an `i128`, if it fits.
    pub fn to_i128(&self) -> Option<i128> {
        // Most numbers met are short: one conversion instead of three.
        if let Some(v) = self.to_i64() {
            return Some(i128::from(v));
        }
        if self.bits() > 127 {
            return None;
        }
        let digit = |i| k::u64_digit_of_abs(&self.0, i) as u128;
        let m = (digit(1) << 64 | digit(0)) as i128;
        Some(if self.is_negative() { -m } else { m })
    }
    /// The image of an `i128`.
    pub fn from_i128(v: i128) -> Int {
        // Most values met are short: one word, no limb slice.
        if let Ok(v) = i64::try_from(v) {
            return Int::from_i64(v);
        }
        let m = v.unsigned_abs();
        Int(k::from_u64_limbs(v < 0, &[m as u64, (m >> 64) as u64]))
    }
    /// The value as an `i64`, if it fits.
    #[inline]
    pub fn to_i64(&self) -> Option<i64> {
        k::to_i64(&self.0)
    }
    /// The integer as an `f64` when that is exact and below `2^53` in
    /// magnitude (the short numbers of a scene), without big-integer
    /// steps; `None` otherwise.
    pub fn to_f64_exact(&self) -> Option<f64> {
        self.to_i64()
            .filter(|v| v.unsigned_abs() < 1 << 53)
            .map(|v| v as f64)
    }
    /// `self mod p` in `[0, p)`, for `p > 0`.
    #[inline]
    pub fn mod_u64(&self, p: u64) -> u64 {
        k::mod_u64(&self.0, p)
    }
    /// Sign and magnitude as little-endian 64-bit limbs.
    pub fn to_u64_limbs(&self) -> (bool, Vec<u64>) {
        k::to_u64_limbs(&self.0)
    }
    /// Inverse of [`Int::to_u64_limbs`].
    pub fn from_u64_limbs(negative: bool, limbs: &[u64]) -> Int {
        Int(k::from_u64_limbs(negative, limbs))
    }
    /// Parses an optionally signed string of decimal digits.
    pub fn parse_decimal(s: &str) -> Option<Int> {
        let body = s.strip_prefix(['-', '+']).unwrap_or(s);
        if body.is_empty() || !body.bytes().all(|b| b.is_ascii_digit()) {
            return None;
        }
        k::parse_decimal(s.strip_prefix('+').unwrap_or(s)).map(Int)
    }
    /// `10^e`.
    pub fn pow10(e: u32) -> Int {
        Int::from_i64(10).pow(e)
    }
    /// `(m, e)` with `|self| = m · 2^e + r`, `0 <= r < 2^e`, and `m < 2^64`
    /// holding the leading bits of `|self|`; `e = 0` when `|self| < 2^64`.
    pub fn top_bits(&self) -> (u64, u64) {
        let e = self.bits().saturating_sub(64);
        (self.abs_window(e as i64), e)
    }
    /// The 64-bit digits of `|self|`, least significant first, borrowed
    /// where the kernel stores them that way (dashu, GMP).
    #[inline]
    fn abs_digits(&self) -> Cow<'_, [u64]> {
        k::abs_digits(&self.0)
    }
    /// Bits `lo .. lo + 64` of `|self|` as a machine word, `⌊|self|·2^(−lo)⌋
    /// mod 2^64`, read from the (at most two) 64-bit digits holding them
    /// without a shifted copy; bits below position 0 read as zeros.
    ///
    /// ```
    /// use ccd_arith::Int;
    /// let x = Int::from(-0b1011);
    /// assert_eq!(x.abs_window(1), 0b101);
    /// assert_eq!(x.abs_window(-2), 0b101100);
    /// ```
    #[inline]
    pub fn abs_window(&self, lo: i64) -> u64 {
        window(&self.abs_digits(), lo)
    }
    /// `|self|·2^a` against `|o|·2^b`, without shifted copies: a number
    /// `|m| ≠ 0` lies in `[2^(t−1), 2^t)` with `t = bits(m)`, so different
    /// `bits + exponent` decide; otherwise the digits are compared 64 bits
    /// at a time from the leading bit down, aligned there (the shorter
    /// number reads zeros past its end).
    ///
    /// ```
    /// use ccd_arith::Int;
    /// use std::cmp::Ordering;
    /// // 3·2^4 = 48 = 12·2^2 < 13·2^2
    /// assert_eq!(Int::from(3).cmp_abs_scaled(4, &Int::from(-12), 2), Ordering::Equal);
    /// assert_eq!(Int::from(3).cmp_abs_scaled(4, &Int::from(13), 2), Ordering::Less);
    /// ```
    pub fn cmp_abs_scaled(&self, a: i64, o: &Int, b: i64) -> Ordering {
        let (bx, by) = (self.bits() as i64, o.bits() as i64);
        if bx == 0 || by == 0 {
            return bx.cmp(&by);
        }
        let top = (bx + a).cmp(&(by + b));
        if top != Ordering::Equal {
            return top;
        }
        let (x, y) = (self.abs_digits(), o.abs_digits());
        let mut down = 64;
        loop {
            let w = window(&x, bx - down).cmp(&window(&y, by - down));
            if w != Ordering::Equal || down >= bx.max(by) {
                return w;
            }
            down += 64;
        }
    }
    /// The position of the highest bit in which `|self|` and `|o|` differ
    /// (`None` when they are equal): the largest `s` with
    /// `⌊|self|·2^(−s)⌋ ≠ ⌊|o|·2^(−s)⌋`. Read 64 bits at a time from the
    /// longer number's leading bit down, without shifted copies.
    ///
    /// ```
    /// use ccd_arith::Int;
    /// assert_eq!(Int::from(0b1011).highest_differing_bit(&Int::from(0b1001)), Some(1));
    /// assert_eq!(Int::from(8).highest_differing_bit(&Int::from(-8)), None);
    /// ```
    pub fn highest_differing_bit(&self, o: &Int) -> Option<u64> {
        let top = self.bits().max(o.bits()) as i64;
        let (x, y) = (self.abs_digits(), o.abs_digits());
        let mut lo = top - 64;
        while lo > -64 {
            let d = window(&x, lo) ^ window(&y, lo);
            if d != 0 {
                return Some((lo + 63 - d.leading_zeros() as i64) as u64);
            }
            lo -= 64;
        }
        None
    }
    /// `⌊self·2^(−s)⌋` (`up == false`) or `⌈self·2^(−s)⌉`, truncating the
    /// magnitude digit by digit and adding one unit away from zero when a
    /// dropped bit is set and the direction asks for it (down for a
    /// negative number, up for a positive one): no shifted copy, no
    /// negation, one allocation at most (none up to 128 bits with dashu).
    ///
    /// ```
    /// use ccd_arith::Int;
    /// assert_eq!(Int::from(-7).shr_round(1, false), Int::from(-4));
    /// assert_eq!(Int::from(-7).shr_round(1, true), Int::from(-3));
    /// assert_eq!(Int::from(7).shr_round(1, true), Int::from(4));
    /// ```
    pub fn shr_round(&self, s: u64, up: bool) -> Int {
        let Some(zeros) = self.trailing_zeros() else {
            return Int::zero();
        };
        let negative = self.is_negative();
        let n = self.bits().saturating_sub(s).div_ceil(64) as usize;
        let mut stack = [0u64; 10];
        let mut heap = Vec::new();
        let words = if n < stack.len() {
            &mut stack[..=n]
        } else {
            heap.resize(n + 1, 0);
            &mut heap[..]
        };
        let digits = self.abs_digits();
        for (i, w) in words[..n].iter_mut().enumerate() {
            *w = window(&digits, (s + 64 * i as u64) as i64);
        }
        if zeros < s && up != negative {
            for w in words.iter_mut() {
                let (v, carry) = w.overflowing_add(1);
                *w = v;
                if !carry {
                    break;
                }
            }
        }
        Int::from_u64_limbs(negative, words)
    }
    /// A nearest-ish `f64` (not certified; see [`crate::Interval::from_int`]).
    pub fn to_f64(&self) -> f64 {
        let (m, e) = self.top_bits();
        let v = (m as f64) * 2f64.powi(e.min(2000) as i32);
        if self.is_negative() {
            -v
        } else {
            v
        }
    }
}

/// Bits `lo .. lo + 64` of the number with 64-bit digits `d` (least
/// significant first), zeros below position 0 and past the end.
#[inline]
fn window(d: &[u64], lo: i64) -> u64 {
    if lo < 0 {
        return match d.first() {
            Some(&w) if lo > -64 => w << lo.unsigned_abs(),
            _ => 0,
        };
    }
    let (i, off) = ((lo / 64) as usize, lo % 64);
    let digit = |k: usize| d.get(k).copied().unwrap_or(0);
    let mut w = digit(i) >> off;
    if off > 0 {
        w |= digit(i + 1) << (64 - off);
    }
    w
}

impl std::fmt::Display for Int {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        k::fmt(&self.0, f)
    }
}
impl std::fmt::Debug for Int {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        k::fmt(&self.0, f)
    }
}

impl From<i64> for Int {
    fn from(v: i64) -> Int {
        Int::from_i64(v)
    }
}
impl From<i32> for Int {
    fn from(v: i32) -> Int {
        Int::from_i64(v.into())
    }
}
impl From<u64> for Int {
    fn from(v: u64) -> Int {
        Int::from_u64(v)
    }
}

impl PartialEq<i64> for Int {
    fn eq(&self, other: &i64) -> bool {
        self.to_i64() == Some(*other)
    }
}
impl PartialOrd<i64> for Int {
    fn partial_cmp(&self, other: &i64) -> Option<Ordering> {
        Some(self.cmp(&Int::from_i64(*other)))
    }
}

/// Implements a binary operator for all four owned/borrowed combinations
/// through one kernel function.
macro_rules! binop {
    ($tr:ident, $m:ident, $f:path) => {
        impl $tr<&Int> for &Int {
            type Output = Int;
            #[inline]
            fn $m(self, o: &Int) -> Int {
                Int($f(&self.0, &o.0))
            }
        }
        impl $tr<Int> for Int {
            type Output = Int;
            #[inline]
            fn $m(self, o: Int) -> Int {
                Int($f(&self.0, &o.0))
            }
        }
        impl $tr<&Int> for Int {
            type Output = Int;
            #[inline]
            fn $m(self, o: &Int) -> Int {
                Int($f(&self.0, &o.0))
            }
        }
        impl $tr<Int> for &Int {
            type Output = Int;
            #[inline]
            fn $m(self, o: Int) -> Int {
                Int($f(&self.0, &o.0))
            }
        }
    };
}
binop!(Add, add, k::add);
binop!(Sub, sub, k::sub);
binop!(Mul, mul, k::mul);

macro_rules! assignop {
    ($tr:ident, $m:ident, $f:path) => {
        impl $tr<&Int> for Int {
            #[inline]
            fn $m(&mut self, o: &Int) {
                $f(&mut self.0, &o.0)
            }
        }
        impl $tr<Int> for Int {
            #[inline]
            fn $m(&mut self, o: Int) {
                $f(&mut self.0, &o.0)
            }
        }
    };
}
assignop!(AddAssign, add_assign, k::add_assign);
assignop!(SubAssign, sub_assign, k::sub_assign);
assignop!(MulAssign, mul_assign, k::mul_assign);

/// How many word powers [`Int::valuation`] divides out one at a time
/// before it climbs squares: below that a word remainder and a division by
/// a word beat a division by a multi-word power (the ladder alone made
/// mid-size scenes 2–3 % dearer).
const VALUATION_WORD_STEPS: usize = 8;

impl Neg for Int {
    type Output = Int;
    /// In place: every kernel negates an owned number without a copy.
    #[inline]
    fn neg(self) -> Int {
        Int(-self.0)
    }
}
impl Neg for &Int {
    type Output = Int;
    #[inline]
    fn neg(self) -> Int {
        Int(k::neg(&self.0))
    }
}

impl std::iter::Sum for Int {
    fn sum<I: Iterator<Item = Int>>(iter: I) -> Int {
        iter.fold(Int::zero(), |a, b| a + b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn big(s: &str) -> Int {
        Int::parse_decimal(s).unwrap()
    }

    #[test]
    fn limbs_round_trip() {
        for s in [
            "0",
            "1",
            "-1",
            "18446744073709551616",
            "-340282366920938463463374607431768211457",
        ] {
            let v = big(s);
            let (neg, l) = v.to_u64_limbs();
            assert_eq!(Int::from_u64_limbs(neg, &l), v, "{s}");
        }
    }

    #[test]
    fn floor_ops_round_toward_minus_infinity() {
        assert_eq!(Int::from(-7).shr_floor(1), Int::from(-4));
        assert_eq!(Int::from(-7).div_floor(&Int::from(2)), Int::from(-4));
        assert_eq!(Int::from(-7).div_trunc(&Int::from(2)), Int::from(-3));
        assert_eq!(Int::from(-7).mod_u64(5), 3);
    }

    #[test]
    fn parse_rejects_junk() {
        for s in ["", "-", "1.5", "1e3", " 1", "0x10"] {
            assert!(Int::parse_decimal(s).is_none(), "{s}");
        }
        assert_eq!(big("+12"), Int::from(12));
    }

    /// The edges where a kernel could panic or disagree: zeros in gcd
    /// (dashu's own `gcd(0, 0)` panics), signs in the floor operations and
    /// `mod_u64`, `0^0`, numbers past one inline word.
    #[test]
    fn edges_agree_across_kernels() {
        let (z, two) = (Int::zero(), Int::from(2));
        assert_eq!(z.gcd(&z), z);
        assert_eq!(z.gcd(&Int::from(-6)), Int::from(6));
        assert_eq!(Int::from(-6).gcd(&z), Int::from(6));
        assert_eq!(z.pow(0), Int::one());
        assert_eq!(z.signum(), 0);
        assert_eq!(z.trailing_zeros(), None);
        assert_eq!(z.to_u64_limbs(), (false, vec![]));
        assert_eq!(Int::from_u64_limbs(true, &[]), z);
        assert_eq!(z.shr_floor(300), z);
        let big = two.pow(200) + Int::from(7);
        let nbig = -&big;
        assert_eq!(nbig.mod_u64(10), 10 - big.mod_u64(10));
        assert_eq!(nbig.shr_floor(200), Int::from(-2));
        assert_eq!(nbig.div_floor(&two.pow(200)), Int::from(-2));
        assert_eq!(nbig.gcd(&two.pow(150)), Int::one());
        assert_eq!(two.pow(130).gcd(&-two.pow(129)), two.pow(129));
        assert_eq!(nbig.to_string(), format!("-{big}"));
    }

    proptest! {
        /// `valuation` against dividing one factor at a time, on `p^e·c`
        /// (long powers, `c` sometimes a multiple of `p` itself), with and
        /// without a cap.
        #[test]
        fn valuation_matches_repeated_division(
            p in 2u32..120,
            e in 0u32..3000,
            c in -1_000_000i64..1_000_000,
            cap in 0u64..4000,
        ) {
            prop_assume!(c != 0);
            let pi = Int::from(i64::from(p));
            let x = pi.pow(e) * Int::from(c);
            let mut naive = (0u64, x.clone());
            while naive.1.is_divisible_by(&pi) {
                naive = (naive.0 + 1, naive.1.div_exact(&pi));
            }
            prop_assert!(naive.0 >= u64::from(e));
            prop_assert_eq!(x.valuation(p, u64::MAX), naive.0);
            prop_assert_eq!(x.valuation(p, cap), naive.0.min(cap));
        }

        /// Every kernel operation against `i128` arithmetic, on `i64` operands.
        #[test]
        fn kernel_matches_i128(a in any::<i64>(), b in any::<i64>(), s in 0u64..64, p in 1u64..u64::MAX) {
            let (x, y) = (Int::from(a), Int::from(b));
            let (a, b) = (i128::from(a), i128::from(b));
            prop_assert_eq!(x.signum(), a.signum() as i32);
            prop_assert_eq!(x.bits(), u64::from(128 - a.unsigned_abs().leading_zeros()));
            prop_assert_eq!(x.abs().to_i128(), Some(a.abs()));
            prop_assert_eq!(x.shl(s).to_i128(), Some(a << s));
            prop_assert_eq!(x.shr_floor(s).to_i128(), Some(a >> s));
            prop_assert_eq!(x.mod_u64(p), a.rem_euclid(i128::from(p)) as u64);
            prop_assert_eq!(x.trailing_zeros(), (a != 0).then(|| u64::from(a.trailing_zeros())));
            prop_assert_eq!(Int::from_i128(a * b).to_i128(), Some(a * b));
            let g = x.gcd(&y).to_i128().unwrap();
            prop_assert!(g >= 0 && (g == 0) == (a == 0 && b == 0));
            if g != 0 {
                prop_assert!(a % g == 0 && b % g == 0);
                prop_assert_eq!(Int::from_i128(a / g).gcd(&Int::from_i128(b / g)), Int::one());
            }
            if b != 0 {
                let (q, r) = x.div_rem_trunc(&y);
                prop_assert_eq!((q.to_i128(), r.to_i128()), (Some(a / b), Some(a % b)));
                prop_assert_eq!(x.div_trunc(&y).to_i128(), Some(a / b));
                let floor = a.div_euclid(b) - i128::from(b < 0 && a.rem_euclid(b) != 0);
                prop_assert_eq!(x.div_floor(&y).to_i128(), Some(floor));
            }
        }

        #[test]
        fn ring_identities(a in any::<i64>(), b in any::<i64>(), c in any::<i64>()) {
            let (x, y, z) = (Int::from(a), Int::from(b), Int::from(c));
            prop_assert_eq!(&x * &(&y + &z), &x * &y + &x * &z);
            let mut acc = x.clone();
            acc.add_mul(&y, &z);
            prop_assert_eq!(acc, &x + &(&y * &z));
            let p = &x * &y;
            if b != 0 { prop_assert_eq!(p.div_exact(&y), x.clone()); }
            prop_assert_eq!(x.to_string(), a.to_string());
        }

        /// Every window of `|x|` against the shifted copy it avoids.
        #[test]
        fn abs_window_matches_shifts(a in any::<i64>(), s in 0u64..300, lo in -80i64..400) {
            let x = Int::from(a).shl(s);
            let shifted = if lo >= 0 { x.abs().shr_floor(lo as u64) } else { x.abs().shl(lo.unsigned_abs()) };
            let low = shifted.abs_window(0);
            prop_assert_eq!(x.abs_window(lo), low);
            prop_assert_eq!(Int::from_u64(low), &shifted - &shifted.shr_floor(64).shl(64));
        }

        /// Both routines against the shifted copies they avoid.
        #[test]
        fn scaled_comparison_and_rounding_match_shifts(
            a in any::<i64>(), b in any::<i64>(), sa in 0u64..1000, sb in 0u64..300,
            ea in -200i64..200, eb in -200i64..200, s in 0u64..400, up in any::<bool>(),
        ) {
            let (x, y) = (Int::from(a).shl(sa), Int::from(b).shl(sb));
            let e = ea.min(eb);
            let (xs, ys) = (x.abs().shl((ea - e) as u64), y.abs().shl((eb - e) as u64));
            prop_assert_eq!(x.cmp_abs_scaled(ea, &y, eb), xs.cmp(&ys));
            let floor = x.shr_floor(s);
            let exact = floor.shl(s) == x;
            let expected = if up && !exact { floor + Int::one() } else { floor };
            prop_assert_eq!(x.shr_round(s, up), expected);
        }

        #[test]
        fn top_bits_bound(a in any::<i64>(), s in 0u64..300) {
            let x = Int::from(a).shl(s);
            let (m, e) = x.top_bits();
            let lo = Int::from_u64(m).shl(e);
            let hi = Int::from_u64(m).shl(e) + Int::one().shl(e);
            prop_assert!(lo <= x.abs() && x.abs() < hi);
        }
    }
}
