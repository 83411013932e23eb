//! [`Interval`]: closed `f64` intervals with outward rounding, the cheap
//! certified filter in front of exact arithmetic.
//!
//! Every operation returns an interval that contains the exact result of the
//! operation applied to any points of the operands: the float result
//! (rounded to nearest) is widened by one ulp on each side, which is enough
//! since round-to-nearest is off by at most half an ulp. The ring
//! operations ([`RingOps`](crate::RingOps)) leave exact results unwidened:
//! a sum with the exact zero or below `2^−1022`, a product or quotient of
//! the exact zero ([`Interval::sum_keeping_zeros`]); so does
//! [`Interval::from_rat`] for an integer of `f64`.

use crate::{Int, Rat};
use std::ops::{Add, Div, Mul, Neg, Sub};

/// A closed interval `[lo, hi]` of reals, `lo <= hi`, possibly unbounded.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower bound.
    pub lo: f64,
    /// Upper bound.
    pub hi: f64,
}

/// `x.next_up()`, bit for bit, in a few integer operations instead of the
/// standard library's chain of tests: `−0` is first made `+0` (adding
/// `+0` changes nothing else), and NaN and `+∞` are returned as they are;
/// otherwise the next float up is one step of the bit pattern, away from
/// zero for `+0` and positive floats, towards it for negative ones (from
/// `−∞` to `−MAX` too).
#[inline]
fn up(x: f64) -> f64 {
    let y = x + 0.0;
    if y < f64::INFINITY {
        step_away(y)
    } else {
        x
    }
}

/// The bit pattern of `y` plus one step, `+1` for a clear sign bit and
/// `−1` for a set one: on x86_64 in the vector registers the float is
/// already in (the sign spread across the lane by shifts, then one integer
/// addition), not through a general-purpose register and back, whose
/// transfers are most of an interval step's latency.
#[inline(always)]
fn step_away(y: f64) -> f64 {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::x86_64::*;
        // SAFETY: SSE2 is part of the x86_64 baseline; these are register
        // operations on the one lane.
        unsafe {
            let v = _mm_castpd_si128(_mm_set_sd(y));
            // The high half's sign copied to all 64 bits: all ones or zero.
            let sign = _mm_shuffle_epi32::<0b01_01_01_01>(_mm_srai_epi32::<31>(v));
            let step = _mm_or_si128(sign, _mm_set_epi64x(0, 1));
            _mm_cvtsd_f64(_mm_castsi128_pd(_mm_add_epi64(v, step)))
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        let bits = y.to_bits();
        f64::from_bits(bits.wrapping_add(((bits as i64 >> 63) | 1) as u64))
    }
}

/// [`up`] on both lanes of an SSE2 register, bit for bit: `+0` for `−0`
/// first, NaN and `+∞` kept as they are, every other float one step of
/// its bit pattern up (as [`step_away`], on two lanes).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn up2(x: std::arch::x86_64::__m128d) -> std::arch::x86_64::__m128d {
    use std::arch::x86_64::*;
    let y = _mm_add_pd(x, _mm_setzero_pd());
    let v = _mm_castpd_si128(y);
    // Each lane's high-half sign spread to its 64 bits: all ones or zero.
    let sign = _mm_shuffle_epi32::<0b11_11_01_01>(_mm_srai_epi32::<31>(v));
    let step = _mm_or_si128(sign, _mm_set1_epi64x(1));
    let stepped = _mm_castsi128_pd(_mm_add_epi64(v, step));
    let finite = _mm_cmplt_pd(y, _mm_set1_pd(f64::INFINITY));
    _mm_or_pd(_mm_and_pd(finite, stepped), _mm_andnot_pd(finite, x))
}

/// `x.next_down()`, bit for bit: `−(−x).next_up()` (negation only flips
/// the sign bit, NaN included).
#[inline]
fn down(x: f64) -> f64 {
    -up(-x)
}

/// An upper bound of the exact sum whose rounding is `s`: `s` itself when
/// `|s| < 2^−1022`, else [`up`]`(s)`. A sum of floats is a multiple of
/// `2^−1074`, so one below `2^−1022` in magnitude is a float (subnormal or
/// zero) and its rounding is exact; rounding is monotone, so a rounded
/// sum below `2^−1022` comes from an exact one below it (Hauser, *Handling
/// floating-point exceptions in numeric programs*, TOPLAS 1996).
#[inline]
fn up_sum(s: f64) -> f64 {
    if s.abs() < f64::MIN_POSITIVE {
        s
    } else {
        up(s)
    }
}

/// A lower bound of the exact sum whose rounding is `s`; see [`up_sum`].
#[inline]
fn down_sum(s: f64) -> f64 {
    -up_sum(-s)
}

/// Scales `x` by `2^k` and widens outward when the result may be inexact.
fn scale2(x: f64, k: i64) -> (f64, f64) {
    if x == 0.0 {
        return (0.0, 0.0);
    }
    let mut v = x;
    let mut rest = k;
    while rest != 0 {
        let step = rest.clamp(-1000, 1000);
        v *= 2f64.powi(step as i32);
        rest -= step;
    }
    let exact = v.is_finite() && v != 0.0 && v.abs() >= f64::MIN_POSITIVE;
    if exact {
        (v, v)
    } else {
        (down(v), up(v))
    }
}

impl Interval {
    /// The whole real line.
    pub const ENTIRE: Interval = Interval {
        lo: f64::NEG_INFINITY,
        hi: f64::INFINITY,
    };

    /// `self · x`, bit for bit what `*` gives, from two products instead of
    /// four when `x ≥ 0` (interval Horner over `t ≥ 0`, the solver's
    /// innermost loop). With `x.lo ≥ 0` the least of the four
    /// corner products is `lo·x.lo` when `lo ≥ 0` and `lo·x.hi` otherwise,
    /// the greatest `hi·x.hi` when `hi ≥ 0` and `hi·x.lo` otherwise; that
    /// holds for the exact products, and rounding to nearest is monotone,
    /// so for the rounded ones too (a zero's sign is lost in the widening
    /// either way). No corner is NaN while both factors are finite; any
    /// other factor goes through `*`.
    #[inline]
    pub fn mul_fast(self, x: Interval) -> Interval {
        let finite = |v: &Interval| v.lo > f64::NEG_INFINITY && v.hi < f64::INFINITY;
        if !(x.lo >= 0.0 && finite(&x) && finite(&self)) {
            return self * x;
        }
        let (lo, hi) = self.nonneg_corners(x);
        Interval {
            lo: down(lo),
            hi: up(hi),
        }
    }

    /// The least and greatest corner products of `self·x` for `x ≥ 0`,
    /// rounded to nearest: `lo·x.lo` or `lo·x.hi` by the sign of `lo`, and
    /// likewise for `hi` ([`Interval::mul_fast`]).
    #[inline]
    fn nonneg_corners(self, x: Interval) -> (f64, f64) {
        (
            self.lo * if self.lo >= 0.0 { x.lo } else { x.hi },
            self.hi * if self.hi >= 0.0 { x.hi } else { x.lo },
        )
    }

    /// `self·x + c` for a Horner step over `x ≥ 0`, for a caller that has
    /// checked `0 ≤ x.lo ≤ x.hi < ∞`: bit for bit `self.mul_fast(x) + c`
    /// while `self` and `c` are finite too, without `mul_fast`'s tests of
    /// them. Where `self` or `c` has an infinite or NaN end, the result has
    /// one, and so do the steps after it: `ScaledPoly`'s Horner passes take
    /// this step, test only their results, and redo a pass whose result is
    /// not finite with `mul_fast` and `+`. (For `x` outside that range the
    /// result may be finite and wrong.)
    ///
    /// On x86_64 both ends go through one SSE2 register as `(−lo, hi)`,
    /// where every widening is upward: `down(v) = −up(−v)` and IEEE
    /// negation and rounding to nearest commute, so the lanes give the
    /// scalar formula's bits (the tests `unchecked_step_is_mul_fast_and_sum`
    /// and `unchecked_step_keeps_the_scalar_bits`).
    #[inline]
    pub fn mul_add_nonneg_unchecked(self, x: Interval, c: Interval) -> Interval {
        debug_assert!(0.0 <= x.lo && x.lo <= x.hi && x.hi < f64::INFINITY);
        #[cfg(target_arch = "x86_64")]
        {
            // SAFETY: SSE2 is part of the x86_64 baseline; register
            // operations only.
            unsafe { self.mul_add_nonneg_sse2(x, c) }
        }
        #[cfg(not(target_arch = "x86_64"))]
        self.mul_add_nonneg_scalar(x, c)
    }

    /// The step's definition, end by end: `down(down(lo·f) + c.lo)` and
    /// `up(up(hi·f) + c.hi)` with the corners of `nonneg_corners`. What
    /// the SSE2 lanes reproduce bit for bit (the test
    /// `unchecked_step_keeps_the_scalar_bits`), and the step off x86_64.
    #[cfg_attr(all(target_arch = "x86_64", not(test)), allow(dead_code))]
    #[inline]
    fn mul_add_nonneg_scalar(self, x: Interval, c: Interval) -> Interval {
        let (lo, hi) = self.nonneg_corners(x);
        Interval {
            lo: down(down(lo) + c.lo),
            hi: up(up(hi) + c.hi),
        }
    }

    /// [`Interval::mul_add_nonneg_unchecked`] with both ends in one
    /// register: lane 0 holds `−lo`, lane 1 `hi`. The corner factor of
    /// each end is picked by that end's sign (as in `nonneg_corners`), the
    /// product of `−lo` is `−(lo·f)` exactly, and [`up`] on both lanes is
    /// `down` on `lo` and `up` on `hi`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    unsafe fn mul_add_nonneg_sse2(self, x: Interval, c: Interval) -> Interval {
        use std::arch::x86_64::*;
        // The sign bit of lane 0 only.
        let flip = _mm_set_pd(0.0, -0.0);
        let ends = _mm_set_pd(self.hi, self.lo);
        // Lane 0: lo ≥ 0 picks x.lo, else x.hi; lane 1: hi ≥ 0 picks
        // x.hi, else x.lo (a NaN end picks the second, as `>=` does).
        let straight = _mm_set_pd(x.hi, x.lo);
        let crossed = _mm_set_pd(x.lo, x.hi);
        let keep = _mm_cmpge_pd(ends, _mm_setzero_pd());
        let factor = _mm_or_pd(_mm_and_pd(keep, straight), _mm_andnot_pd(keep, crossed));
        let product = up2(_mm_mul_pd(_mm_xor_pd(ends, flip), factor));
        let sum = up2(_mm_add_pd(
            product,
            _mm_xor_pd(_mm_set_pd(c.hi, c.lo), flip),
        ));
        Interval {
            lo: -_mm_cvtsd_f64(sum),
            hi: _mm_cvtsd_f64(_mm_unpackhi_pd(sum, sum)),
        }
    }

    /// The exact point `[0, 0]` (of either zero's sign).
    #[inline]
    fn is_zero_point(&self) -> bool {
        self.lo == 0.0 && self.hi == 0.0
    }

    /// `self + o`, or `self − o` with `negate`, widened only where the
    /// rounded sum may be inexact: not where an operand is the exact zero,
    /// nor where the sum is below `2^−1022` (a float sum that small is
    /// exact: Hauser, TOPLAS 1996). A sum that cancels to zero stays the
    /// exact point zero.
    ///
    /// The ring operations ([`RingOps`](crate::RingOps)) keep exact zeros
    /// this way (and give the exact zero for a product with one): they
    /// serve the generic matrix algebra of quadrics, whose structural
    /// zeros (axis-aligned shapes, spheres, still coordinates) would
    /// otherwise become `±2^−1074`, making every later product with them a
    /// subnormal one, a microcode assist of about 80 cycles on x86_64
    /// against one. The operators `+ − ×` widen every bound by one step:
    /// they serve the solver's Horner and de Casteljau loops, where exact
    /// zeros seldom arise and the extra comparisons cost a degree-2 affine
    /// query 4–6 % in instructions and 3–4 % in time (session 33).
    #[inline]
    pub fn sum_keeping_zeros(self, o: Interval, negate: bool) -> Interval {
        // Adding the exact zero is exact (and keeps `add_product` with a
        // zero factor the sum of the zero product, bit for bit).
        if o.is_zero_point() {
            return self;
        }
        if self.is_zero_point() {
            return if negate { -o } else { o };
        }
        let (lo, hi) = if negate {
            (self.lo - o.hi, self.hi - o.lo)
        } else {
            (self.lo + o.lo, self.hi + o.hi)
        };
        Interval::new(down_sum(lo), up_sum(hi))
    }

    /// The point `[x, x]`.
    pub fn point(x: f64) -> Interval {
        Interval { lo: x, hi: x }
    }
    /// `[lo, hi]`; NaN bounds give [`Interval::ENTIRE`].
    pub fn new(lo: f64, hi: f64) -> Interval {
        if lo.is_nan() || hi.is_nan() {
            Interval::ENTIRE
        } else {
            Interval { lo, hi }
        }
    }
    /// A certified enclosure of `x · 2^(-shift)`.
    pub fn from_int_scaled(x: &Int, shift: i64) -> Interval {
        let (m, e) = x.top_bits();
        let (lo, hi) = if e == 0 && m < (1u64 << 53) {
            let (a, b) = scale2(m as f64, -shift);
            (a, b)
        } else {
            // |x| in [m, m + 1] · 2^e.
            let (a, _) = scale2(down(m as f64), e as i64 - shift);
            let (_, b) = scale2(up((m as f64) + 1.0), e as i64 - shift);
            (down(a).max(0.0), up(b))
        };
        if x.is_negative() {
            Interval { lo: -hi, hi: -lo }
        } else {
            Interval { lo, hi }
        }
    }
    /// A certified enclosure of a machine integer (the point itself when
    /// it is exact in `f64`).
    pub fn from_i64(v: i64) -> Interval {
        if v.unsigned_abs() <= 1 << 53 {
            return Interval::point(v as f64);
        }
        Interval::from_int(&Int::from_i64(v))
    }
    /// A certified enclosure of a machine integer: the point itself when it
    /// is exact in `f64`, else the two neighbours of its rounding.
    pub fn from_i128(v: i128) -> Interval {
        if v.unsigned_abs() < 1 << 53 {
            // Exact (a machine conversion, not i128's library call).
            return Interval::point(v as i64 as f64);
        }
        let x = v as f64;
        // `as i128` saturates: the bracket also covers |v| near 2^127.
        if v.unsigned_abs() < 1 << 100 && x as i128 == v {
            Interval::point(x)
        } else {
            Interval::new(x.next_down(), x.next_up())
        }
    }
    /// A certified enclosure of an integer.
    pub fn from_int(x: &Int) -> Interval {
        Interval::from_int_scaled(x, 0)
    }
    /// A certified enclosure of a rational.
    pub fn from_rat(x: &Rat) -> Interval {
        // Numerator and denominator below 2^53 (decimal scene numbers) are
        // the exact points `from_int` gives them, without its big-integer
        // steps.
        let (n, d) = match (x.numer().to_f64_exact(), x.denom().to_f64_exact()) {
            // An integer of `f64` (zero among them) is its own point.
            (Some(n), Some(1.0)) => return Interval::point(n),
            (Some(n), Some(d)) => (Interval::point(n), Interval::point(d)),
            _ => (Interval::from_int(x.numer()), Interval::from_int(x.denom())),
        };
        n.div_positive(d)
    }
    /// `self / d` for an interval `d` of positive numbers.
    pub fn div_positive(self, d: Interval) -> Interval {
        debug_assert!(d.lo > 0.0);
        let c = [
            self.lo / d.lo,
            self.lo / d.hi,
            self.hi / d.lo,
            self.hi / d.hi,
        ];
        Interval::hull_widened(c)
    }
    #[inline]
    fn hull_widened(c: [f64; 4]) -> Interval {
        if c.iter().any(|v| v.is_nan()) {
            return Interval::ENTIRE;
        }
        let lo = c.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = c.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval {
            lo: down(lo),
            hi: up(hi),
        }
    }
    /// `√x` over the nonnegative part of the interval, for a quantity known
    /// to be `>= 0` whose enclosure rounding may have pushed below zero
    /// (`f64::sqrt` is correctly rounded, so one step out on each side
    /// holds the exact root); [`Interval::ENTIRE`] when `hi < 0` or NaN.
    pub fn sqrt(self) -> Interval {
        if self.hi.is_nan() || self.hi < 0.0 {
            return Interval::ENTIRE;
        }
        let lo = if self.lo > 0.0 {
            down(self.lo.sqrt()).max(0.0)
        } else {
            0.0
        };
        Interval::new(lo, up(self.hi.sqrt()))
    }
    /// Midpoint (not certified).
    pub fn mid(&self) -> f64 {
        0.5 * self.lo + 0.5 * self.hi
    }
    /// Width `hi − lo` (rounded up).
    pub fn width(&self) -> f64 {
        up(self.hi - self.lo)
    }
    /// Both ends finite (no overflow, no NaN turned into the whole line).
    pub fn is_finite(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }
    /// `0 ∈ self`.
    pub fn contains_zero(&self) -> bool {
        self.lo <= 0.0 && self.hi >= 0.0
    }
    /// The sign of every point of the interval: `Some(±1)` when it excludes
    /// zero, `Some(0)` for the exact point zero, `None` when undecided.
    pub fn sign(&self) -> Option<i32> {
        if self.lo > 0.0 {
            Some(1)
        } else if self.hi < 0.0 {
            Some(-1)
        } else if self.lo == 0.0 && self.hi == 0.0 {
            Some(0)
        } else {
            None
        }
    }
    /// Smallest interval holding both.
    pub fn hull(&self, o: &Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
    /// `self²` (tighter than `self · self` when the interval holds zero).
    pub fn square(self) -> Interval {
        let m = self * self;
        if self.contains_zero() {
            Interval { lo: 0.0, hi: m.hi }
        } else {
            Interval {
                lo: m.lo.max(0.0),
                hi: m.hi,
            }
        }
    }
    /// `(self + o) / 2`: the de Casteljau step.
    pub fn average(self, o: Interval) -> Interval {
        let s = self + o;
        Interval {
            lo: s.lo * 0.5,
            hi: s.hi * 0.5,
        }
        .widen_if_tiny()
    }
    fn widen_if_tiny(self) -> Interval {
        // Halving is exact except in the subnormal range.
        let lo = if self.lo != 0.0 && self.lo.abs() < f64::MIN_POSITIVE {
            down(self.lo)
        } else {
            self.lo
        };
        let hi = if self.hi != 0.0 && self.hi.abs() < f64::MIN_POSITIVE {
            up(self.hi)
        } else {
            self.hi
        };
        Interval { lo, hi }
    }
}

impl Add for Interval {
    type Output = Interval;
    #[inline]
    fn add(self, o: Interval) -> Interval {
        Interval::new(down(self.lo + o.lo), up(self.hi + o.hi))
    }
}
impl Sub for Interval {
    type Output = Interval;
    #[inline]
    fn sub(self, o: Interval) -> Interval {
        Interval::new(down(self.lo - o.hi), up(self.hi - o.lo))
    }
}
/// `self / d`: the hull of the quotients when `d` excludes zero,
/// [`Interval::ENTIRE`] otherwise.
impl Div for Interval {
    type Output = Interval;
    fn div(self, d: Interval) -> Interval {
        if d.contains_zero() {
            return Interval::ENTIRE;
        }
        Interval::hull_widened([
            self.lo / d.lo,
            self.lo / d.hi,
            self.hi / d.lo,
            self.hi / d.hi,
        ])
    }
}
impl Neg for Interval {
    type Output = Interval;
    #[inline]
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}
impl Mul for Interval {
    type Output = Interval;
    #[inline]
    fn mul(self, o: Interval) -> Interval {
        let c = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if c.iter().any(|v| v.is_nan()) {
            // 0 · ∞: the operands' product set is still bounded by what we
            // can say; be safe.
            return Interval::ENTIRE;
        }
        Interval::hull_widened(c)
    }
}

impl crate::RingOps for Interval {
    fn zero() -> Self {
        Interval::point(0.0)
    }
    fn one() -> Self {
        Interval::point(1.0)
    }
    fn from_i64(v: i64) -> Self {
        Interval::from_i64(v)
    }
    fn is_zero(&self) -> bool {
        self.is_zero_point()
    }
    #[inline]
    fn plus(&self, o: &Self) -> Self {
        self.sum_keeping_zeros(*o, false)
    }
    #[inline]
    fn minus(&self, o: &Self) -> Self {
        self.sum_keeping_zeros(*o, true)
    }
    /// `self · o`; the exact zero when a factor is the exact zero (the
    /// other is a real number, even where its enclosure is unbounded).
    #[inline]
    fn times(&self, o: &Self) -> Self {
        if self.is_zero_point() || o.is_zero_point() {
            return Interval::point(0.0);
        }
        *self * *o
    }
    /// `self ± x·y`, nothing when a factor is the exact zero.
    #[inline]
    fn add_product(&mut self, x: &Self, y: &Self, negate: bool) {
        if x.is_zero_point() || y.is_zero_point() {
            return;
        }
        *self = self.sum_keeping_zeros(*x * *y, negate);
    }
    #[inline]
    fn negated(&self) -> Self {
        -*self
    }
    fn div_small(&self, k: i64) -> Self {
        if self.is_zero_point() {
            return *self; // exact
        }
        let d = Interval::from_i64(k.abs());
        let q = self.div_positive(d);
        if k < 0 {
            -q
        } else {
            q
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The ring operations keep the exact zero exact: sums that cancel,
    /// products with a zero factor (even an unbounded other one) and
    /// multiply-accumulates of them, where `+`, `−` and `×` widen a zero
    /// to `±2^−1074`.
    #[test]
    fn ring_operations_keep_exact_zeros() {
        use crate::RingOps;
        let zero = Interval::point(0.0);
        let x = Interval::new(-1.5, 2.5);
        assert_eq!(zero.plus(&zero), zero);
        assert_eq!(x.minus(&x).lo, (-4f64).next_down()); // a normal sum widens
        let p = Interval::point(0.75);
        assert_eq!(p.minus(&p), zero);
        for other in [x, p, Interval::ENTIRE, zero] {
            // Adding the exact zero is exact; `add_product` with a zero
            // factor is the sum of the zero product.
            assert_eq!((other.plus(&zero), zero.plus(&other)), (other, other));
            assert_eq!(other.minus(&zero), other);
            assert_eq!(zero.minus(&other), -other);
            assert_eq!(zero.times(&other), zero);
            assert_eq!(other.times(&zero), zero);
            let mut acc = p;
            acc.add_product(&other, &zero, true);
            assert_eq!(acc, p);
        }
        let minus_zero = Interval::point(-0.0);
        assert_eq!(minus_zero.plus(&p), p);
        assert_eq!(x.times(&minus_zero), zero);
        assert_eq!(zero.div_small(-3), zero);
        // The operators widen by one step, as before.
        assert_eq!((zero + zero).hi, f64::from_bits(1));
        assert_eq!((zero * x).lo, -f64::from_bits(1));
        // And both agree away from zero.
        assert_eq!(x.times(&p), x * p);
    }

    /// The unchecked Horner step is `mul_fast` and `+` bit for bit on
    /// finite operands at their edges (signed zeros, `MAX`, subnormals, a
    /// product that overflows), and keeps a non-finite end non-finite.
    #[test]
    fn unchecked_step_is_mul_fast_and_sum() {
        let ends = [
            0.0,
            -0.0,
            5e-324,
            -5e-324,
            1.5,
            -2.5,
            1e300,
            -1e300,
            f64::MAX,
            -f64::MAX,
        ];
        let intervals: Vec<Interval> = ends
            .iter()
            .flat_map(|&a| ends.iter().map(move |&b| Interval::new(a.min(b), a.max(b))))
            .collect();
        let xs = [
            (0.0, 0.0),
            (-0.0, 0.0),
            (0.0, 2.0),
            (1.0, 3.0),
            (0.5, 1e300),
        ];
        let bits = |i: Interval| (i.lo.to_bits(), i.hi.to_bits());
        for &(lo, hi) in &xs {
            let x = Interval::new(lo, hi);
            for &acc in &intervals {
                for &c in intervals.iter().step_by(7) {
                    let fast = acc.mul_add_nonneg_unchecked(x, c);
                    assert_eq!(
                        bits(fast),
                        bits(acc.mul_fast(x) + c),
                        "{acc:?}·{x:?} + {c:?}"
                    );
                }
                for bad in [
                    Interval::new(f64::NEG_INFINITY, 1.0),
                    Interval::new(-1.0, f64::INFINITY),
                ] {
                    assert!(!bad.mul_add_nonneg_unchecked(x, acc).is_finite());
                    assert!(!acc.mul_add_nonneg_unchecked(x, bad).is_finite());
                }
            }
        }
    }

    #[test]
    fn huge_integers_are_enclosed() {
        let x = Int::from(3).pow(700); // about 2^1109: beyond f64
        let i = Interval::from_int_scaled(&x, 1100);
        let approx = (700.0 * 3f64.log2() - 1100.0).exp2();
        assert!(
            i.lo <= approx * (1.0 + 1e-9) && i.hi >= approx * (1.0 - 1e-9),
            "{i:?} {approx}"
        );
        assert!(Interval::from_int(&x).hi.is_infinite());
        assert_eq!(Interval::from_int(&-x).sign(), Some(-1));
    }

    proptest! {
        #[test]
        fn arithmetic_encloses_exact_results(a in -1_000_000i64..1_000_000, b in -1_000_000i64..1_000_000, c in 1i64..1000) {
            let (x, y) = (Rat::from_frac(a, c), Rat::from_frac(b, 7));
            let (ix, iy) = (Interval::from_rat(&x), Interval::from_rat(&y));
            for (iv, exact) in [(ix + iy, &x + &y), (ix - iy, &x - &y), (ix * iy, &x * &y), (ix.square(), &x * &x)] {
                let e = Interval::from_rat(&exact);
                prop_assert!(iv.lo <= e.hi && e.lo <= iv.hi);
                prop_assert!(iv.lo <= exact.to_f64() + 1e-300 && exact.to_f64() - 1e-300 <= iv.hi);
            }
        }

        /// `mul_fast` is `*` bit for bit, for every factor: signs mixed,
        /// zeros of either sign, tiny and huge magnitudes (products that
        /// underflow or overflow), infinite ends.
        #[test]
        fn mul_fast_is_mul(
            ends in proptest::array::uniform4(prop_oneof![
                Just(0.0), Just(-0.0), Just(f64::INFINITY), Just(f64::NEG_INFINITY),
                Just(f64::MAX), Just(f64::MIN_POSITIVE), Just(5e-324),
                -1e3f64..1e3, -1e300f64..1e300, -1e-300f64..1e-300,
            ]),
        ) {
            let interval = |a: f64, b: f64| Interval::new(a.min(b), a.max(b));
            let (a, x) = (interval(ends[0], ends[1]), interval(ends[2], ends[3]));
            for (p, q) in [(a, x), (x, a), (a, a), (a, Interval::new(0.0, x.hi.abs()))] {
                let (fast, slow) = (p.mul_fast(q), p * q);
                prop_assert_eq!((fast.lo.to_bits(), fast.hi.to_bits()), (slow.lo.to_bits(), slow.hi.to_bits()), "{:?} · {:?}", p, q);
            }
        }

        /// A rounded sum below `2^−1022` in magnitude is the exact sum
        /// (what `up_sum` leaves unwidened), and `sum_keeping_zeros`
        /// encloses the exact sums and differences of the ends, for ends
        /// around the subnormal range, ordinary ones and infinities.
        #[test]
        fn small_sums_are_exact_and_kept_sums_enclose(
            ends in proptest::array::uniform4(prop_oneof![
                Just(0.0), Just(-0.0), Just(f64::INFINITY), Just(f64::NEG_INFINITY),
                Just(f64::MIN_POSITIVE), Just(-f64::MIN_POSITIVE), Just(5e-324), Just(-5e-324),
                Just(f64::MAX), Just(-f64::MAX),
                (1u64..1 << 54).prop_map(f64::from_bits),
                (1u64..1 << 54).prop_map(|b| -f64::from_bits(b)),
                -1e-300f64..1e-300, -1e3f64..1e3,
            ]),
        ) {
            let exact = |v: f64| Rat::from_f64_exact(v);
            for (a, b) in [(ends[0], ends[1]), (ends[2], ends[3]), (ends[0], -ends[0])] {
                let s = a + b;
                if s.abs() < f64::MIN_POSITIVE {
                    prop_assert_eq!(exact(s), Some(&exact(a).unwrap() + &exact(b).unwrap()), "{} + {}", a, b);
                }
            }
            let interval = |a: f64, b: f64| Interval::new(a.min(b), a.max(b));
            let (x, y) = (interval(ends[0], ends[1]), interval(ends[2], ends[3]));
            for negate in [false, true] {
                let kept = x.sum_keeping_zeros(y, negate);
                let (lo, hi) = if negate { (x.lo - y.hi, x.hi - y.lo) } else { (x.lo + y.lo, x.hi + y.hi) };
                let corner = |u: f64, v: f64| Some(&exact(u)? + &exact(if negate { -v } else { v })?);
                if let (Some(l), Some(true_lo)) = (exact(kept.lo), corner(x.lo, if negate { y.hi } else { y.lo })) {
                    prop_assert!(l <= true_lo, "{:?} ± {:?}: {:?}", x, y, kept);
                }
                if let (Some(h), Some(true_hi)) = (exact(kept.hi), corner(x.hi, if negate { y.lo } else { y.hi })) {
                    prop_assert!(true_hi <= h, "{:?} ± {:?}: {:?}", x, y, kept);
                }
                // Never wider than the one-step widening of `+` and `−`.
                let plain = if negate { x - y } else { x + y };
                prop_assert!(plain.lo <= kept.lo && kept.hi <= plain.hi);
                // An exact zero sum stays the exact zero.
                if lo == 0.0 && hi == 0.0 {
                    prop_assert_eq!((kept.lo, kept.hi), (0.0, 0.0));
                }
            }
        }

        /// `add_product` is `plus`/`minus` of `times`, bit for bit, for
        /// every kind of factor: zero points of both signs, intervals with
        /// a zero end, subnormal, huge and unbounded ends.
        #[test]
        fn add_product_is_the_sum_of_the_product(
            ends in proptest::array::uniform6(prop_oneof![
                Just(0.0), Just(-0.0), Just(f64::INFINITY), Just(f64::NEG_INFINITY),
                Just(f64::MAX), Just(5e-324), Just(-5e-324),
                -1e3f64..1e3, -1e-300f64..1e-300,
            ]),
            negate in any::<bool>(),
        ) {
            use crate::RingOps;
            let interval = |a: f64, b: f64| Interval::new(a.min(b), a.max(b));
            let (acc, x, y) = (interval(ends[0], ends[1]), interval(ends[2], ends[3]), interval(ends[4], ends[5]));
            let bits = |i: Interval| (i.lo.to_bits(), i.hi.to_bits());
            let mut fused = acc;
            fused.add_product(&x, &y, negate);
            let product = x.times(&y);
            let plain = if negate { acc.minus(&product) } else { acc.plus(&product) };
            prop_assert_eq!(bits(fused), bits(plain));
        }

        #[test]
        fn int_enclosure_holds(a in any::<i64>(), s in 0u64..200, sh in -50i64..1200) {
            let x = Int::from(a).shl(s) + Int::from(a);
            let i = Interval::from_int_scaled(&x, sh);
            // Compare exactly: lo·2^sh <= x <= hi·2^sh, using rationals.
            let to_rat = |v: f64| -> Option<Rat> {
                if !v.is_finite() { return None; }
                let (m, e) = decompose(v);
                Some(Rat::from(m).mul_pow2(e + sh))
            };
            let xr = Rat::from(x.clone());
            if let Some(l) = to_rat(i.lo) { prop_assert!(l <= xr); }
            if let Some(h) = to_rat(i.hi) { prop_assert!(xr <= h); }
        }
    }

    proptest! {
        /// Quotients and square roots enclose the exact values: `q·d`
        /// and `r²` bracket the operands (checked in rationals).
        #[test]
        fn division_and_roots_enclose(a in -1_000_000i64..1_000_000, b in 1i64..1_000_000, c in 1i64..1000, neg in any::<bool>()) {
            let x = Rat::from_frac(a, c);
            let y = Rat::from_frac(if neg { -b } else { b }, 7);
            let q = Interval::from_rat(&x) / Interval::from_rat(&y);
            let exact = &x / &y;
            let r = |v: f64| Rat::from_f64_exact(v).expect("finite");
            prop_assert!(r(q.lo) <= exact && exact <= r(q.hi), "{:?} {}", q, exact);
            let s = Interval::from_rat(&x.abs()).sqrt();
            let (lo, hi) = (r(s.lo), r(s.hi));
            prop_assert!(&lo * &lo <= x.abs() && x.abs() <= &hi * &hi, "{:?}", s);
        }
    }

    proptest! {
        /// Machine integers of every length are enclosed, as points when
        /// exact in `f64` and at most two ulps wide otherwise.
        #[test]
        fn machine_integers_are_enclosed(x in any::<i128>(), shift in 0u32..127) {
            let x = x >> shift;
            let i = Interval::from_i128(x);
            let r = |v: f64| Rat::from_f64_exact(v).expect("finite");
            let exact = Rat::from_int(Int::from_i128(x));
            prop_assert!(r(i.lo) <= exact && exact <= r(i.hi), "{:?} {}", i, x);
            if x.unsigned_abs() < 1 << 53 {
                prop_assert_eq!(i.lo, i.hi);
            }
            prop_assert!(i.hi <= i.lo.next_up().next_up());
        }
    }

    proptest! {
        /// The short path of `from_rat` gives the general path's interval,
        /// bit for bit, on both sides of 2^53; an integer below 2^53 is
        /// its point.
        #[test]
        fn short_rationals_are_enclosed_as_before(n in any::<i64>(), d in 1i64..i64::MAX, shift in 0u32..12) {
            let (n, d) = (n >> shift, d >> shift.min(8));
            let x = Rat::from_frac(n, d.max(1));
            let general = Interval::from_int(x.numer()).div_positive(Interval::from_int(x.denom()));
            let short = Interval::from_rat(&x);
            match (x.numer().to_f64_exact(), x.denom().is_one()) {
                // An integer of `f64` is its own point (the general path
                // widens the quotient by `1`).
                (Some(n), true) => prop_assert_eq!((short.lo, short.hi), (n, n)),
                _ => prop_assert_eq!((short.lo.to_bits(), short.hi.to_bits()), (general.lo.to_bits(), general.hi.to_bits())),
            }
        }
    }

    #[test]
    fn division_by_zero_and_roots_of_negatives_are_refused() {
        let one = Interval::point(1.0);
        assert_eq!(one / Interval::new(-1.0, 1.0), Interval::ENTIRE);
        assert_eq!(Interval::point(-1.0).sqrt(), Interval::ENTIRE);
        assert_eq!(Interval::new(-1e-300, 4.0).sqrt().lo, 0.0);
        assert!(Interval::point(4.0).sqrt().lo < 2.0 && Interval::point(4.0).sqrt().hi > 2.0);
    }

    /// Ordinary floats of any size and the special values.
    fn special_f64() -> impl Strategy<Value = f64> {
        prop_oneof![
            any::<f64>(),
            -1e6f64..1e6,
            Just(0.0),
            Just(-0.0),
            Just(f64::INFINITY),
            Just(f64::NEG_INFINITY),
            Just(f64::NAN),
            Just(-f64::NAN),
            Just(f64::MAX),
            Just(-f64::MAX),
            Just(f64::MIN_POSITIVE),
            Just(-f64::MIN_POSITIVE),
            Just(f64::from_bits(1)),
            Just(-f64::from_bits(1)),
        ]
    }

    proptest! {
        /// The SSE2 step is the scalar formula, bit for bit (a NaN end, of
        /// either sign, where the formula's is NaN: the callers only test
        /// that a result is finite).
        #[test]
        fn unchecked_step_keeps_the_scalar_bits(
            a in special_f64(), b in special_f64(), c0 in special_f64(), c1 in special_f64(),
            x0 in prop_oneof![0f64..1e300, 0f64..1e-300, Just(0.0), Just(-0.0), Just(f64::from_bits(1)), Just(f64::MIN_POSITIVE)],
            w in prop_oneof![0f64..1e300, 0f64..1e-300, Just(0.0), Just(f64::from_bits(1))],
        ) {
            let (acc, c) = (Interval::new(a.min(b), a.max(b)), Interval::new(c0.min(c1), c0.max(c1)));
            let x = Interval::new(x0, (x0 + w).min(f64::MAX));
            let want = acc.mul_add_nonneg_scalar(x, c);
            let got = acc.mul_add_nonneg_unchecked(x, c);
            let same = |g: f64, w: f64| g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan());
            prop_assert!(same(got.lo, want.lo) && same(got.hi, want.hi), "{:?}·{:?} + {:?}: {:?}, not {:?}", acc, x, c, got, want);
        }

        /// The widening steps are the standard library's, bit for bit.
        #[test]
        fn widening_steps_are_next_up_and_down(x in special_f64()) {
            prop_assert_eq!(up(x).to_bits(), x.next_up().to_bits(), "{}", x);
            prop_assert_eq!(down(x).to_bits(), x.next_down().to_bits(), "{}", x);
        }
    }

    /// `v = m · 2^e` exactly.
    fn decompose(v: f64) -> (i64, i64) {
        if v == 0.0 {
            return (0, 0);
        }
        let bits = v.to_bits();
        let sign = if bits >> 63 == 1 { -1 } else { 1 };
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = (bits & ((1u64 << 52) - 1)) as i64;
        if exp == 0 {
            (sign * frac, -1074)
        } else {
            (sign * (frac | (1i64 << 52)), exp - 1075)
        }
    }
}
