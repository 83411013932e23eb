//! [`Real`]: what the generic interval algorithms (sin/cos, interval
//! Newton, sign reading) need from an interval type, implemented for the
//! fast `f64` [`Interval`] and the escalation type [`BigInterval`].

use crate::trig::{half_pi_cody_waite, pi_enclosure};
use ccd_arith::{BigInterval, Dyadic, Int, Interval, Rat, RingOps};
use std::sync::OnceLock;

/// Largest multiple `k` of π/2 for which the `f64` Cody–Waite reduction
/// `x − k·P1 − k·P2 − k·P3` has exact products `k·P1`, `k·P2` (both `P1`
/// and `P2` have 30 significant bits, so `|k| < 2^22` keeps the products
/// within 53 bits).
const CODY_WAITE_MAX_K: i64 = 1 << 22;

/// Extra bits of π beyond the working precision and the size of `k` when
/// reducing in [`BigInterval`].
const REDUCTION_GUARD_BITS: u32 = 16;

/// A closed interval type whose operations enclose exact results (see
/// [`RingOps`]), with the extra operations the generic algorithms use.
pub trait Real: RingOps + PartialEq {
    /// An enclosure of the rational `q`, with `prec` significant bits where
    /// the type has a choice (ignored by `f64` intervals).
    fn constant(q: &Rat, prec: u32) -> Self;
    /// An enclosure of `√q` for a rational `q >= 0`.
    fn sqrt_rat(q: &Rat, prec: u32) -> Self;
    /// Working precision in bits (53 for `f64` intervals).
    fn precision(&self) -> u32;
    /// `[−1, 1]` at precision `prec`.
    fn unit(prec: u32) -> Self;
    /// Both ends are finite.
    fn is_finite(&self) -> bool;
    /// `lo == hi`.
    fn is_point(&self) -> bool;
    /// The lower end as a point.
    fn lower(&self) -> Self;
    /// The upper end as a point.
    fn upper(&self) -> Self;
    /// A point of the interval near its middle (exactly representable).
    fn midpoint(&self) -> Self;
    /// The lower end, exactly (`None` when infinite).
    fn lo_rat(&self) -> Option<Rat>;
    /// The upper end, exactly (`None` when infinite).
    fn hi_rat(&self) -> Option<Rat>;
    /// Smallest interval holding both.
    fn hull(&self, o: &Self) -> Self;
    /// The common part, if any.
    fn intersect(&self, o: &Self) -> Option<Self>;
    /// `self ⊂ interior(o)`.
    fn strictly_inside(&self, o: &Self) -> bool;
    /// Signs of the two ends (−1, 0, 1).
    fn end_signs(&self) -> (i32, i32);
    /// `self / o` when `o` excludes zero.
    fn div(&self, o: &Self) -> Option<Self>;
    /// The point `max(|lo|, |hi|)`.
    fn abs_max(&self) -> Self;
    /// `[−hi, hi]` (for a remainder bound `self >= 0`).
    fn symmetric(&self) -> Self;
    /// Intersection with `[−1, 1]` (for enclosures of sin and cos).
    fn clamp_unit(&self) -> Self;
    /// Midpoint as an `f64` (not certified).
    fn approx(&self) -> f64;
    /// Width as an `f64` (not certified).
    fn width_f64(&self) -> f64;
    /// An integer near `x/(π/2)` for the midpoint `x` (any integer is
    /// correct; a near one keeps the reduced argument small). `None` when
    /// not finite.
    fn quadrant(&self) -> Option<Int>;
    /// An enclosure of `self − k·π/2`.
    fn sub_half_pi_multiple(&self, k: &Int) -> Self;
    /// An enclosure of `k·π/2`.
    fn half_pi_times(k: &Int, prec: u32) -> Self;
    /// An enclosure of `1/j!` (the Taylor coefficients of sin and cos).
    fn inv_factorial(j: usize, prec: u32) -> Self {
        Self::constant(&inv_factorial_rat(j), prec)
    }

    /// The sign of every point (`Some(0)` for the point zero), or `None`.
    fn sign(&self) -> Option<i32> {
        match self.end_signs() {
            (l, _) if l > 0 => Some(1),
            (_, h) if h < 0 => Some(-1),
            (0, 0) => Some(0),
            _ => None,
        }
    }
    /// `0 ∈ self`.
    fn contains_zero(&self) -> bool {
        let (l, h) = self.end_signs();
        l <= 0 && h >= 0
    }
}

/// Numerators and denominators below `2^53` convert exactly to `f64`.
const EXACT_F64_INT: u64 = 1 << 53;

/// `1/j!` exactly (cached for small `j`).
pub fn inv_factorial_rat(j: usize) -> Rat {
    const CACHED: usize = 512;
    static TABLE: OnceLock<Vec<Rat>> = OnceLock::new();
    let table = TABLE.get_or_init(|| {
        let mut t = vec![Rat::one()];
        for i in 1..CACHED {
            let next = &t[i - 1] / &Rat::from(i as i64);
            t.push(next);
        }
        t
    });
    match table.get(j) {
        Some(r) => r.clone(),
        None => (CACHED..=j).fold(table[CACHED - 1].clone(), |acc, i| {
            &acc / &Rat::from(i as i64)
        }),
    }
}

impl Real for Interval {
    fn constant(q: &Rat, _prec: u32) -> Self {
        // Fast path: both parts exact in f64, so one correctly rounded
        // division (widened by an ulp unless exact) encloses the value.
        if let (Some(n), Some(d)) = (q.numer().to_i64(), q.denom().to_i64()) {
            if n.unsigned_abs() < EXACT_F64_INT && d < EXACT_F64_INT as i64 {
                let v = n as f64 / d as f64;
                return if d == 1 {
                    Interval::point(v)
                } else {
                    Interval::new(v.next_down(), v.next_up())
                };
            }
        }
        Interval::from_rat(q)
    }
    fn inv_factorial(j: usize, prec: u32) -> Self {
        static TABLE: OnceLock<Vec<Interval>> = OnceLock::new();
        let table = TABLE.get_or_init(|| {
            (0..64)
                .map(|i| Interval::from_rat(&inv_factorial_rat(i)))
                .collect()
        });
        table
            .get(j)
            .copied()
            .unwrap_or_else(|| <Interval as Real>::constant(&inv_factorial_rat(j), prec))
    }
    fn sqrt_rat(q: &Rat, _prec: u32) -> Self {
        // IEEE square root is correctly rounded, so one ulp outward encloses.
        let i = Interval::from_rat(q);
        Interval::new(
            i.lo.max(0.0).sqrt().next_down().max(0.0),
            i.hi.sqrt().next_up(),
        )
    }
    fn precision(&self) -> u32 {
        53
    }
    fn unit(_prec: u32) -> Self {
        Interval::new(-1.0, 1.0)
    }
    fn is_finite(&self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }
    fn is_point(&self) -> bool {
        self.lo == self.hi
    }
    fn lower(&self) -> Self {
        Interval::point(self.lo)
    }
    fn upper(&self) -> Self {
        Interval::point(self.hi)
    }
    fn midpoint(&self) -> Self {
        let m = self.mid();
        Interval::point(if m.is_finite() {
            m.clamp(self.lo, self.hi)
        } else {
            0.0
        })
    }
    fn lo_rat(&self) -> Option<Rat> {
        Rat::from_f64_exact(self.lo)
    }
    fn hi_rat(&self) -> Option<Rat> {
        Rat::from_f64_exact(self.hi)
    }
    fn hull(&self, o: &Self) -> Self {
        Interval::hull(self, o)
    }
    fn intersect(&self, o: &Self) -> Option<Self> {
        let (lo, hi) = (self.lo.max(o.lo), self.hi.min(o.hi));
        (lo <= hi).then_some(Interval { lo, hi })
    }
    fn strictly_inside(&self, o: &Self) -> bool {
        self.lo > o.lo && self.hi < o.hi
    }
    fn end_signs(&self) -> (i32, i32) {
        let s = |v: f64| {
            if v > 0.0 {
                1
            } else if v < 0.0 {
                -1
            } else {
                0
            }
        };
        (s(self.lo), s(self.hi))
    }
    fn div(&self, o: &Self) -> Option<Self> {
        if o.lo > 0.0 {
            Some(self.div_positive(*o))
        } else if o.hi < 0.0 {
            Some(-self.div_positive(-*o))
        } else {
            None
        }
    }
    fn abs_max(&self) -> Self {
        Interval::point(self.lo.abs().max(self.hi.abs()))
    }
    fn symmetric(&self) -> Self {
        Interval::new(-self.hi, self.hi)
    }
    fn clamp_unit(&self) -> Self {
        Interval::new(self.lo.max(-1.0), self.hi.min(1.0))
    }
    fn approx(&self) -> f64 {
        self.mid()
    }
    fn width_f64(&self) -> f64 {
        self.width()
    }
    fn quadrant(&self) -> Option<Int> {
        let m = self.mid();
        if !m.is_finite() {
            return None;
        }
        if m.abs() < 1e12 {
            return Some(Int::from_i64(
                (m * std::f64::consts::FRAC_2_PI).round() as i64
            ));
        }
        BigInterval::point(Dyadic::from_f64(m)?)
            .with_prec(64)
            .quadrant()
    }
    fn sub_half_pi_multiple(&self, k: &Int) -> Self {
        match k.to_i64() {
            Some(kk) if kk.abs() < CODY_WAITE_MAX_K => {
                let (p1, p2, p3) = half_pi_cody_waite();
                let kf = kk as f64;
                // k·P1 and k·P2 are exact (see CODY_WAITE_MAX_K).
                let r = *self - Interval::point(kf * p1);
                let r = r - Interval::point(kf * p2);
                r - Interval::point(kf) * p3
            }
            _ => {
                // Huge arguments: reduce exactly in multi-precision.
                let (Some(lo), Some(hi)) = (self.lo_rat(), self.hi_rat()) else {
                    return Interval::ENTIRE;
                };
                let big = BigInterval::from_rat(&lo, 64)
                    .hull(&BigInterval::from_rat(&hi, 64))
                    .with_prec(64);
                let r = big.sub_half_pi_multiple(k);
                Interval::new(
                    Interval::from_rat(&r.lo_rat()).lo,
                    Interval::from_rat(&r.hi_rat()).hi,
                )
            }
        }
    }
    fn half_pi_times(k: &Int, _prec: u32) -> Self {
        let (p1, p2, p3) = half_pi_cody_waite();
        let h = Interval::point(p1) + Interval::point(p2) + p3;
        Interval::from_int(k) * h
    }
}

impl Real for BigInterval {
    fn constant(q: &Rat, prec: u32) -> Self {
        BigInterval::from_rat(q, prec)
    }
    fn sqrt_rat(q: &Rat, prec: u32) -> Self {
        BigInterval::sqrt_rat(q, prec)
    }
    fn precision(&self) -> u32 {
        self.prec
    }
    fn unit(prec: u32) -> Self {
        let mut u = BigInterval::from_i64(-1).hull(&BigInterval::from_i64(1));
        u.prec = prec;
        u
    }
    fn is_finite(&self) -> bool {
        true
    }
    fn is_point(&self) -> bool {
        self.lo == self.hi
    }
    fn lower(&self) -> Self {
        let mut p = BigInterval::point(self.lo.clone());
        p.prec = self.prec;
        p
    }
    fn upper(&self) -> Self {
        let mut p = BigInterval::point(self.hi.clone());
        p.prec = self.prec;
        p
    }
    fn midpoint(&self) -> Self {
        BigInterval::midpoint(self)
    }
    fn lo_rat(&self) -> Option<Rat> {
        Some(BigInterval::lo_rat(self))
    }
    fn hi_rat(&self) -> Option<Rat> {
        Some(BigInterval::hi_rat(self))
    }
    fn hull(&self, o: &Self) -> Self {
        BigInterval::hull(self, o)
    }
    fn intersect(&self, o: &Self) -> Option<Self> {
        BigInterval::intersect(self, o)
    }
    fn strictly_inside(&self, o: &Self) -> bool {
        BigInterval::strictly_inside(self, o)
    }
    fn end_signs(&self) -> (i32, i32) {
        (self.lo.m.signum(), self.hi.m.signum())
    }
    fn div(&self, o: &Self) -> Option<Self> {
        BigInterval::div(self, o)
    }
    fn abs_max(&self) -> Self {
        let (a, b) = (self.lo.m.abs(), self.hi.m.abs());
        let lo = Dyadic { m: a, e: self.lo.e };
        let hi = Dyadic { m: b, e: self.hi.e };
        let h = BigInterval::point(lo).hull(&BigInterval::point(hi));
        let mut p = BigInterval::point(h.hi);
        p.prec = self.prec;
        p
    }
    fn symmetric(&self) -> Self {
        BigInterval {
            lo: Dyadic {
                m: -&self.hi.m,
                e: self.hi.e,
            },
            hi: self.hi.clone(),
            prec: self.prec,
        }
    }
    fn clamp_unit(&self) -> Self {
        self.intersect(&Real::unit(self.prec))
            .unwrap_or_else(|| Real::unit(self.prec))
    }
    fn approx(&self) -> f64 {
        BigInterval::approx(self)
    }
    fn width_f64(&self) -> f64 {
        BigInterval::width_f64(self)
    }
    fn quadrant(&self) -> Option<Int> {
        let x = self.midpoint();
        let magnitude = (x.lo.m.bits() as i64 + x.lo.e).max(0) as u32;
        let bits = self.prec.max(64) + magnitude + REDUCTION_GUARD_BITS;
        let (lo, hi) = pi_enclosure(bits);
        let pi = BigInterval::new(lo, hi, bits);
        let q = BigInterval::from_i64(2).with_prec(bits).div(&pi)?;
        let v = x.with_prec(bits).times(&q).midpoint();
        let half = Rat::from_frac(1, 2);
        Some((&v.lo_rat() + &half).floor())
    }
    fn sub_half_pi_multiple(&self, k: &Int) -> Self {
        let bits = self.prec.max(53) + k.bits() as u32 + REDUCTION_GUARD_BITS;
        let kh = <BigInterval as Real>::half_pi_times(k, bits);
        self.with_prec(bits).minus(&kh).with_prec(self.prec.max(53))
    }
    fn half_pi_times(k: &Int, prec: u32) -> Self {
        let bits = prec.max(53) + k.bits() as u32 + REDUCTION_GUARD_BITS;
        let (lo, hi) = pi_enclosure(bits + 1);
        let pi = BigInterval::new(lo, hi, bits);
        let kk = BigInterval::point(Dyadic::from_int(k));
        let h = pi.times(&kk);
        BigInterval::new(
            Dyadic {
                m: h.lo.m,
                e: h.lo.e - 1,
            },
            Dyadic {
                m: h.hi.m,
                e: h.hi.e - 1,
            },
            prec.max(53),
        )
    }
}
