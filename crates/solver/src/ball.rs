//! [`JetBall`]: the enclosures of `σ·q(m)` and `σ·q′(m)` that
//! [`RealRoot`](crate::RealRoot)'s emulated tests run on — double-word
//! balls ([`DwBall`], about 106 bits in `f64`'s exponent range) and
//! multi-precision intervals ([`BigInterval`], any precision, any
//! exponent). The tests ask only what either can prove: signs, and
//! comparisons of its ends with `f64` bounds.

use ccd_arith::{BigInterval, DwBall, Dyadic, Interval, Rat, RingOps};
use std::cmp::Ordering;

/// A bound `f·2^e` past `f64`'s exponent range (`f` zero or of magnitude
/// in `[2^(−511), 2^511]`, so that a product of two never under- or
/// overflows): the Taylor remainders of values far below that range
/// (`sup|q″|·r²/2` of a closed form of long numbers) keep their size
/// instead of underflowing. Products round to nearest, as in `f64`;
/// callers widen them as they widen `f64` products. In the range of
/// ordinary values `e` stays 0 and each product is one `f64` product.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scaled {
    f: f64,
    e: i64,
}

/// `2^511` and `2^(−511)`: the range `Scaled` keeps its factor in.
const BIG: f64 = 6.703903964971299e153;
const SMALL: f64 = 1.0 / BIG;

impl Scaled {
    /// The finite `x` (NaN and infinities are the caller's to exclude).
    #[inline]
    pub fn new(x: f64) -> Scaled {
        Scaled { f: x, e: 0 }.normal()
    }
    /// The factor brought back into `[2^(−511), 2^511]` (exact: powers
    /// of two, and the factor is normal).
    #[inline]
    fn normal(self) -> Scaled {
        let a = self.f.abs();
        if (SMALL..=BIG).contains(&a) || a == 0.0 || !a.is_finite() {
            return self;
        }
        let (mut f, mut e) = (self.f, self.e);
        if a < f64::MIN_POSITIVE {
            // A subnormal: into the normal range first.
            f *= 2f64.powi(600);
            e -= 600;
        }
        while f.abs() > BIG {
            f *= SMALL;
            e += 511;
        }
        while f.abs() < SMALL {
            f *= BIG;
            e -= 511;
        }
        Scaled { f, e }
    }
    /// `x·2^0` as it is (no product of it may follow: its factor need not
    /// lie in the range products need).
    #[inline]
    pub fn exact(x: f64) -> Scaled {
        Scaled { f: x, e: 0 }
    }
    /// `self · o`, rounded to nearest.
    #[inline]
    pub fn times(self, o: Scaled) -> Scaled {
        Scaled {
            f: self.f * o.f,
            e: self.e + o.e,
        }
        .normal()
    }
    /// `−self`.
    #[inline]
    pub fn neg(self) -> Scaled {
        Scaled {
            f: -self.f,
            e: self.e,
        }
    }
    /// The value in `f64`, rounded toward `−∞` (`up`: toward `+∞`): exact
    /// in the normal range; an underflow gives 0 or `∓MIN_POSITIVE`, an
    /// overflow `±MAX` or `±∞`, whichever is on the safe side.
    #[inline]
    pub fn to_f64(self, up: bool) -> f64 {
        if self.f == 0.0 {
            // Zero at any exponent (products keep `e` on zeros).
            return 0.0;
        }
        let v = if self.e == 0 {
            self.f
        } else if self.e > 2200 {
            f64::INFINITY.copysign(self.f)
        } else if self.e < -2200 {
            0.0
        } else {
            let step = self.e.clamp(-1000, 1000);
            self.f * 2f64.powi(step as i32) * 2f64.powi((self.e - step) as i32)
        };
        if v.is_infinite() && self.f.is_finite() {
            return if up == (v > 0.0) {
                v
            } else {
                f64::MAX.copysign(v)
            };
        }
        if v.abs() < f64::MIN_POSITIVE {
            // Rounded, or flushed to zero.
            return match (up, self.f > 0.0) {
                (true, true) => f64::MIN_POSITIVE,
                (false, false) => -f64::MIN_POSITIVE,
                _ => 0.0,
            };
        }
        v
    }
    /// The exact value (`None` when not finite).
    pub fn to_dyadic(self) -> Option<Dyadic> {
        let d = Dyadic::from_f64(self.f)?;
        Some(Dyadic {
            m: d.m,
            e: d.e + self.e,
        })
    }
}

/// A certified enclosure of one real number, as
/// [`RealRoot`](crate::RealRoot)'s ball round and ball Newton jump use it.
/// Every answer is a proof about every point of the enclosure; `false` or
/// `None` means "not proven".
pub trait JetBall: RingOps {
    /// Whether the ball's values reach past `f64`'s exponent range (its
    /// tests then need remainders past that range too).
    const WIDE: bool;
    /// An enclosure of the rational `x`, at this ball's precision.
    fn enclose_rat(&self, x: &Rat) -> Self;
    /// Upper and lower bounds of `|x|` over the ball (the lower one 0 when
    /// it holds zero).
    fn abs_bounds(&self) -> (f64, f64);
    /// `self + [−r, r]` for `r ≥ 0` (`None` when that says nothing: an
    /// infinite `r`).
    fn widened(&self, r: Scaled) -> Option<Self>;
    /// `self + iv` (`None` when that says nothing: an unbounded `iv`).
    fn plus_interval(&self, iv: Interval) -> Option<Self>;
    /// The sign of every point: `Some(±1)` when the enclosure excludes
    /// zero, `Some(0)` for the exact zero, `None` when undecided.
    fn sign_of(&self) -> Option<i32>;
    /// Every point is at most `x`.
    fn at_most(&self, x: Scaled) -> bool;
    /// Every point is at least `x`.
    fn at_least(&self, x: Scaled) -> bool;
    /// Every point has `|·| ≥ x` (for `x > 0`).
    fn abs_at_least(&self, x: f64) -> bool;
    /// `self / o`, `None` when `o` may vanish or nothing is known.
    fn quotient(&self, o: &Self) -> Option<Self>;
    /// `self · 2^k`.
    fn scaled(&self, k: i64) -> Self;
    /// The ends as exact rationals (`None` when unknown).
    fn end_points(&self) -> Option<(Rat, Rat)>;
}

impl JetBall for DwBall {
    const WIDE: bool = false;
    #[inline]
    fn enclose_rat(&self, x: &Rat) -> Self {
        DwBall::from_rat(x)
    }
    #[inline]
    fn abs_bounds(&self) -> (f64, f64) {
        (self.abs_upper(), self.abs_lower())
    }
    #[inline]
    fn widened(&self, r: Scaled) -> Option<Self> {
        Some(self.plus(&DwBall {
            hi: 0.0,
            lo: 0.0,
            rad: r.to_f64(true),
        }))
    }
    #[inline]
    fn plus_interval(&self, iv: Interval) -> Option<Self> {
        Some(self.plus(&DwBall::from_interval(iv)))
    }
    #[inline]
    fn sign_of(&self) -> Option<i32> {
        self.sign()
    }
    #[inline]
    fn at_most(&self, x: Scaled) -> bool {
        self.upper() <= x.to_f64(false)
    }
    #[inline]
    fn at_least(&self, x: Scaled) -> bool {
        self.lower() >= x.to_f64(true)
    }
    #[inline]
    fn abs_at_least(&self, x: f64) -> bool {
        self.abs_lower() >= x
    }
    #[inline]
    fn quotient(&self, o: &Self) -> Option<Self> {
        let q = self.div(o);
        q.is_known().then_some(q)
    }
    #[inline]
    fn scaled(&self, k: i64) -> Self {
        self.mul_pow2(k)
    }
    #[inline]
    fn end_points(&self) -> Option<(Rat, Rat)> {
        self.ends()
    }
}

/// `|d|` in `f64`, rounded down (`up`: up): `|d| ∈ [t, t + 1]·2^(s + e)`
/// for its leading 64 bits `t` (exactly `t·2^e` when `s = 0`).
fn abs_f64(d: &Dyadic, up: bool) -> f64 {
    let (t, s) = d.m.top_bits();
    let t = t as f64; // within 2^(−53) of the integer
    let f = if up {
        (t + if s == 0 { 0.0 } else { 1.0 }) * (1.0 + f64::EPSILON)
    } else {
        t * (1.0 - f64::EPSILON)
    };
    Scaled {
        f,
        e: s as i64 + d.e,
    }
    .normal()
    .to_f64(up)
}

/// `[lo, hi]` exactly (not rounded), carrying the precision `prec`.
fn exactly(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
    BigInterval { lo, hi, prec }
}

impl JetBall for BigInterval {
    const WIDE: bool = true;
    fn enclose_rat(&self, x: &Rat) -> Self {
        BigInterval::from_rat(x, self.prec)
    }
    fn abs_bounds(&self) -> (f64, f64) {
        let upper = abs_f64(&self.lo, true).max(abs_f64(&self.hi, true));
        let lower = if self.contains_zero() {
            0.0
        } else {
            abs_f64(&self.lo, false).min(abs_f64(&self.hi, false))
        };
        (upper, lower)
    }
    fn widened(&self, r: Scaled) -> Option<Self> {
        let r = r.to_dyadic()?;
        Some(self.plus(&exactly(r.neg(), r, self.prec)))
    }
    fn plus_interval(&self, iv: Interval) -> Option<Self> {
        let (lo, hi) = (Dyadic::from_f64(iv.lo)?, Dyadic::from_f64(iv.hi)?);
        Some(self.plus(&exactly(lo, hi, self.prec)))
    }
    fn sign_of(&self) -> Option<i32> {
        self.sign()
    }
    fn at_most(&self, x: Scaled) -> bool {
        x.to_dyadic()
            .is_some_and(|x| self.hi.cmp_value(&x) != Ordering::Greater)
    }
    fn at_least(&self, x: Scaled) -> bool {
        x.to_dyadic()
            .is_some_and(|x| self.lo.cmp_value(&x) != Ordering::Less)
    }
    fn abs_at_least(&self, x: f64) -> bool {
        let x = Scaled::new(x);
        self.at_least(x) || self.at_most(x.neg())
    }
    fn quotient(&self, o: &Self) -> Option<Self> {
        self.div(o)
    }
    fn scaled(&self, k: i64) -> Self {
        self.mul_pow2(k)
    }
    fn end_points(&self) -> Option<(Rat, Rat)> {
        Some((self.lo_rat(), self.hi_rat()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// `Scaled` keeps the value of products past f64's range, and its
        /// directed conversions bound it.
        #[test]
        fn scaled_products_are_exact_up_to_rounding(
            a in -1e300f64..1e300, b in -1e300f64..1e300,
            ea in -3000i64..3000, eb in -3000i64..3000,
        ) {
            let x = Scaled { f: a, e: ea }.normal();
            let y = Scaled { f: b, e: eb }.normal();
            let p = x.times(y);
            let exact = x.to_dyadic().unwrap().mul(&y.to_dyadic().unwrap()).to_rat();
            let got = p.to_dyadic().unwrap().to_rat();
            // Within one rounding (2^(−53) relatively).
            let err = (&got - &exact).abs();
            prop_assert!(err <= &exact.abs() * &Rat::from_frac(1, 1 << 52));
            let v = got;
            for up in [false, true] {
                let f = p.to_f64(up);
                if f.is_finite() {
                    let f = Rat::from_f64_exact(f).unwrap();
                    let bounds = if up { f >= v } else { f <= v };
                    prop_assert!(bounds);
                } else {
                    prop_assert_eq!(f > 0.0, up);
                }
            }
        }
    }

    /// Zero at any exponent converts to zero, both ways (a product with a
    /// zero factor keeps the other's exponent; found by review).
    #[test]
    fn scaled_zero_is_zero_at_any_exponent() {
        for e in [-5000, -2201, 0, 2201, 5000] {
            for f in [0.0, -0.0] {
                let z = Scaled { f, e };
                assert_eq!(z.to_f64(false), 0.0);
                assert_eq!(z.to_f64(true), 0.0);
                assert_eq!(Scaled::new(0.5).times(z).to_f64(false), 0.0);
            }
        }
        let zero = Dyadic {
            m: ccd_arith::Int::zero(),
            e: 3000,
        };
        assert_eq!((abs_f64(&zero, false), abs_f64(&zero, true)), (0.0, 0.0));
    }

    /// A ball far below f64's range against bounds near it.
    #[test]
    fn big_ball_compares_past_the_f64_range() {
        let tiny = Dyadic {
            m: ccd_arith::Int::from(3),
            e: -4000,
        };
        let b = BigInterval::new(tiny.clone(), tiny, 128);
        let t = Scaled { f: 0.5, e: -3997 }; // 2^(−3998) > 3·2^(−4000)
        assert!(b.at_most(t) && !b.at_least(t));
        assert!(b.at_least(Scaled { f: 0.5, e: -3999 }));
        assert_eq!(b.widened(t).and_then(|w| w.sign_of()), None);
        assert_eq!(
            b.widened(Scaled { f: 0.5, e: -4001 })
                .and_then(|w| w.sign_of()),
            Some(1)
        );
        assert!(b.abs_at_least(0.0) && !b.abs_at_least(f64::MIN_POSITIVE));
    }
}
