//! [`BigInterval`]: closed intervals with dyadic endpoints `m·2^e` rounded
//! outward to a chosen number of significant bits — the escalation type
//! used when an `f64` [`Interval`](ccd_arith::Interval) is too wide to
//! decide a sign or to reach the requested width of an enclosure.
//!
//! Every operation computes the exact dyadic result of the endpoint
//! formulas (sums and products of dyadics are dyadic) and then rounds the
//! lower end down and the upper end up to `prec` significant bits, so the
//! result contains the exact result for any points of the operands.
//! Divisions (by small integers, or by an interval excluding zero) round
//! the quotients of the endpoints outward in the same way. `prec == 0`
//! marks an exact value (small constants): no rounding at all; a binary
//! operation works at the larger precision of its operands.

use ccd_arith::{Int, Rat, RingOps};
use std::cmp::Ordering;

/// Precision used for divisions of exact (`prec == 0`) operands.
const DEFAULT_DIVISION_BITS: u32 = 64;

/// The dyadic rational `m · 2^e`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dyadic {
    /// Mantissa.
    pub m: Int,
    /// Binary exponent.
    pub e: i64,
}

impl Dyadic {
    /// Zero.
    pub fn zero() -> Dyadic {
        Dyadic {
            m: Int::zero(),
            e: 0,
        }
    }
    /// The integer `k`.
    pub fn from_int(k: &Int) -> Dyadic {
        Dyadic { m: k.clone(), e: 0 }
    }
    /// The exact rational value.
    pub fn to_rat(&self) -> Rat {
        Rat::from_int(self.m.clone()).mul_pow2(self.e)
    }
    /// The exact value of a finite `f64`, `None` otherwise.
    pub fn from_f64(x: f64) -> Option<Dyadic> {
        let r = Rat::from_f64_exact(x)?;
        Dyadic::from_rat_exact(&r)
    }
    /// The value of a rational with a power-of-two denominator.
    pub fn from_rat_exact(r: &Rat) -> Option<Dyadic> {
        let den = r.denom();
        let tz = den.trailing_zeros()?;
        if den.bits() != tz + 1 {
            return None;
        }
        Some(Dyadic {
            m: r.numer().clone(),
            e: -(tz as i64),
        })
    }
    /// A nearby `f64` (not certified).
    pub fn to_f64(&self) -> f64 {
        let (mm, ee) = self.m.top_bits();
        let scale = self.e + ee as i64;
        let v = (mm as f64) * 2f64.powi(scale.clamp(-1100, 1100) as i32);
        if self.m.is_negative() {
            -v
        } else {
            v
        }
    }
    fn signum(&self) -> i32 {
        self.m.signum()
    }
    /// Both mantissas over the common exponent `min(e)`.
    fn aligned(&self, o: &Dyadic) -> (Int, Int, i64) {
        if self.m.is_zero() {
            return (Int::zero(), o.m.clone(), o.e);
        }
        if o.m.is_zero() {
            return (self.m.clone(), Int::zero(), self.e);
        }
        let e = self.e.min(o.e);
        (
            self.m.shl((self.e - e) as u64),
            o.m.shl((o.e - e) as u64),
            e,
        )
    }
    fn add(&self, o: &Dyadic) -> Dyadic {
        let (a, b, e) = self.aligned(o);
        Dyadic { m: a + b, e }
    }
    fn sub(&self, o: &Dyadic) -> Dyadic {
        let (a, b, e) = self.aligned(o);
        Dyadic { m: a - b, e }
    }
    fn mul(&self, o: &Dyadic) -> Dyadic {
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }
    fn neg(&self) -> Dyadic {
        Dyadic {
            m: -&self.m,
            e: self.e,
        }
    }
    fn cmp(&self, o: &Dyadic) -> Ordering {
        let (a, b, _) = self.aligned(o);
        a.cmp(&b)
    }
    /// Rounded to `prec` significant bits, down (`up == false`) or up.
    fn round(self, prec: u32, up: bool) -> Dyadic {
        if prec == 0 {
            return self;
        }
        let bits = self.m.bits();
        if bits <= prec as u64 {
            return self;
        }
        let s = bits - prec as u64;
        let m = if up {
            -(-&self.m).shr_floor(s)
        } else {
            self.m.shr_floor(s)
        };
        Dyadic {
            m,
            e: self.e + s as i64,
        }
    }
    /// `⌊n·2^s / d⌋·2^(−s)` (down) or with `⌈⌉` (up), for `d > 0`.
    fn quotient(n: &Int, d: &Int, s: i64, up: bool) -> Dyadic {
        let (num, den) = if s >= 0 {
            (n.shl(s as u64), d.clone())
        } else {
            (n.clone(), d.shl(s.unsigned_abs()))
        };
        let m = if up {
            -(-&num).div_floor(&den)
        } else {
            num.div_floor(&den)
        };
        Dyadic { m, e: -s }
    }
    /// An outward rounding of `a / b` (`b ≠ 0`) to about `prec` bits.
    fn div(a: &Dyadic, b: &Dyadic, prec: u32, up: bool) -> Dyadic {
        let (bm, am) = if b.m.is_negative() {
            (-&b.m, -&a.m)
        } else {
            (b.m.clone(), a.m.clone())
        };
        let s = prec as i64 + 2 + bm.bits() as i64 - am.bits() as i64;
        let q = Dyadic::quotient(&am, &bm, s, up);
        Dyadic {
            m: q.m,
            e: q.e + a.e - b.e,
        }
        .round(prec, up)
    }
}

/// A closed interval `[lo, hi]` with dyadic ends kept to `prec` significant
/// bits by outward rounding (`prec == 0`: exact, never rounded).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BigInterval {
    /// Lower end.
    pub lo: Dyadic,
    /// Upper end.
    pub hi: Dyadic,
    /// Significant bits kept (0: exact).
    pub prec: u32,
}

fn min_d(a: Dyadic, b: Dyadic) -> Dyadic {
    if a.cmp(&b) == Ordering::Greater {
        b
    } else {
        a
    }
}
fn max_d(a: Dyadic, b: Dyadic) -> Dyadic {
    if a.cmp(&b) == Ordering::Less {
        b
    } else {
        a
    }
}

impl BigInterval {
    /// The exact point `x` (never rounded).
    pub fn point(x: Dyadic) -> BigInterval {
        BigInterval {
            lo: x.clone(),
            hi: x,
            prec: 0,
        }
    }
    /// `[lo, hi]` rounded outward to `prec` bits.
    pub fn new(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
        BigInterval {
            lo: lo.round(prec, false),
            hi: hi.round(prec, true),
            prec,
        }
    }
    /// The same interval, kept from now on to `prec` bits (rounded outward).
    pub fn with_prec(&self, prec: u32) -> BigInterval {
        BigInterval::new(self.lo.clone(), self.hi.clone(), prec)
    }
    /// An enclosure of the rational `q` with `prec` bits (exact when `q` is
    /// dyadic).
    pub fn from_rat(q: &Rat, prec: u32) -> BigInterval {
        if let Some(d) = Dyadic::from_rat_exact(q) {
            let mut p = BigInterval::point(d);
            p.prec = prec;
            return p;
        }
        let bits = prec.max(DEFAULT_DIVISION_BITS);
        let s = bits as i64 + 2 + q.denom().bits() as i64 - q.numer().bits() as i64;
        BigInterval {
            lo: Dyadic::quotient(q.numer(), q.denom(), s, false),
            hi: Dyadic::quotient(q.numer(), q.denom(), s, true),
            prec,
        }
    }
    /// An enclosure of `√q` for a rational `q >= 0`, to about `prec` bits.
    pub fn sqrt_rat(q: &Rat, prec: u32) -> BigInterval {
        let bits = prec.max(DEFAULT_DIVISION_BITS) as i64 + 4;
        // √q = √(n·d)/d; with N = ⌊n·d·4^k⌋, √q ∈ [isqrt(N), isqrt(N) + 1] / (d·2^k).
        let nd = q.numer() * q.denom();
        let k = (bits - nd.bits() as i64 / 2 + q.denom().bits() as i64).max(0);
        let big = nd.shl(2 * k as u64);
        let s = isqrt(&big);
        let exact = &s * &s == big;
        let den = q.denom().shl(k as u64);
        let lo = Dyadic::div(
            &Dyadic::from_int(&s),
            &Dyadic::from_int(&den),
            bits as u32,
            false,
        );
        let top = if exact { s } else { s + Int::one() };
        let hi = Dyadic::div(
            &Dyadic::from_int(&top),
            &Dyadic::from_int(&den),
            bits as u32,
            true,
        );
        BigInterval::new(lo, hi, prec)
    }
    /// Lower end as a rational.
    pub fn lo_rat(&self) -> Rat {
        self.lo.to_rat()
    }
    /// Upper end as a rational.
    pub fn hi_rat(&self) -> Rat {
        self.hi.to_rat()
    }
    /// Sign of every point: `Some(±1)`, `Some(0)` for the point zero, `None`
    /// when undecided.
    pub fn sign(&self) -> Option<i32> {
        if self.lo.signum() > 0 {
            Some(1)
        } else if self.hi.signum() < 0 {
            Some(-1)
        } else if self.lo.signum() == 0 && self.hi.signum() == 0 {
            Some(0)
        } else {
            None
        }
    }
    /// `lo <= 0 <= hi`.
    pub fn contains_zero(&self) -> bool {
        self.lo.signum() <= 0 && self.hi.signum() >= 0
    }
    /// Smallest interval holding both.
    pub fn hull(&self, o: &BigInterval) -> BigInterval {
        BigInterval {
            lo: min_d(self.lo.clone(), o.lo.clone()),
            hi: max_d(self.hi.clone(), o.hi.clone()),
            prec: self.prec.max(o.prec),
        }
    }
    /// The common part, if any.
    pub fn intersect(&self, o: &BigInterval) -> Option<BigInterval> {
        let lo = max_d(self.lo.clone(), o.lo.clone());
        let hi = min_d(self.hi.clone(), o.hi.clone());
        (lo.cmp(&hi) != Ordering::Greater).then(|| BigInterval {
            lo,
            hi,
            prec: self.prec.max(o.prec),
        })
    }
    /// `self ⊂ interior(o)`.
    pub fn strictly_inside(&self, o: &BigInterval) -> bool {
        self.lo.cmp(&o.lo) == Ordering::Greater && self.hi.cmp(&o.hi) == Ordering::Less
    }
    /// The exact midpoint (never rounded, so it always lies in the
    /// interval, as interval Newton requires), as a point carrying this
    /// precision.
    pub fn midpoint(&self) -> BigInterval {
        let s = self.lo.add(&self.hi);
        let mut p = BigInterval::point(Dyadic { m: s.m, e: s.e - 1 });
        p.prec = self.prec;
        p
    }
    /// `self / o` for an interval `o` that excludes zero (`None` otherwise).
    pub fn div(&self, o: &BigInterval) -> Option<BigInterval> {
        if o.contains_zero() {
            return None;
        }
        let prec = self.prec.max(o.prec).max(DEFAULT_DIVISION_BITS);
        let ends = [
            (&self.lo, &o.lo),
            (&self.lo, &o.hi),
            (&self.hi, &o.lo),
            (&self.hi, &o.hi),
        ];
        let lo = ends
            .iter()
            .map(|(a, b)| Dyadic::div(a, b, prec, false))
            .reduce(min_d)?;
        let hi = ends
            .iter()
            .map(|(a, b)| Dyadic::div(a, b, prec, true))
            .reduce(max_d)?;
        Some(BigInterval {
            lo,
            hi,
            prec: self.prec.max(o.prec),
        })
    }
    /// A nearby `f64` of the midpoint (not certified).
    pub fn approx(&self) -> f64 {
        0.5 * (self.lo.to_f64() + self.hi.to_f64())
    }
    /// `hi − lo`, approximately.
    pub fn width_f64(&self) -> f64 {
        self.hi.sub(&self.lo).to_f64()
    }
    fn from_ends(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
        BigInterval::new(lo, hi, prec)
    }
}

/// `⌊√n⌋` for `n >= 0` (Newton's iteration on integers).
fn isqrt(n: &Int) -> Int {
    if n.signum() <= 0 {
        return Int::zero();
    }
    let mut x = Int::one().shl(n.bits().div_ceil(2));
    loop {
        let y = (&x + &n.div_floor(&x)).shr_floor(1);
        if y >= x {
            return x;
        }
        x = y;
    }
}

impl RingOps for BigInterval {
    fn zero() -> Self {
        BigInterval::point(Dyadic::zero())
    }
    fn one() -> Self {
        BigInterval::point(Dyadic::from_int(&Int::one()))
    }
    fn from_i64(v: i64) -> Self {
        BigInterval::point(Dyadic::from_int(&Int::from_i64(v)))
    }
    fn is_zero(&self) -> bool {
        self.lo.signum() == 0 && self.hi.signum() == 0
    }
    fn plus(&self, o: &Self) -> Self {
        BigInterval::from_ends(
            self.lo.add(&o.lo),
            self.hi.add(&o.hi),
            self.prec.max(o.prec),
        )
    }
    fn minus(&self, o: &Self) -> Self {
        BigInterval::from_ends(
            self.lo.sub(&o.hi),
            self.hi.sub(&o.lo),
            self.prec.max(o.prec),
        )
    }
    fn times(&self, o: &Self) -> Self {
        let prec = self.prec.max(o.prec);
        let c = [
            self.lo.mul(&o.lo),
            self.lo.mul(&o.hi),
            self.hi.mul(&o.lo),
            self.hi.mul(&o.hi),
        ];
        let lo = c.iter().cloned().reduce(min_d).unwrap_or_else(Dyadic::zero);
        let hi = c.into_iter().reduce(max_d).unwrap_or_else(Dyadic::zero);
        BigInterval::from_ends(lo, hi, prec)
    }
    fn negated(&self) -> Self {
        BigInterval {
            lo: self.hi.neg(),
            hi: self.lo.neg(),
            prec: self.prec,
        }
    }
    fn div_small(&self, k: i64) -> Self {
        // `k ≠ 0` is the trait's contract, so the division always exists.
        let d = BigInterval::from_i64(k);
        self.div(&d).unwrap_or_else(|| self.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn contains(i: &BigInterval, x: &Rat) -> bool {
        &i.lo_rat() <= x && x <= &i.hi_rat()
    }

    #[test]
    fn sqrt_encloses() {
        for (n, d) in [(2i64, 1i64), (1, 3), (49, 4), (10_000_000_019, 7)] {
            let q = Rat::from_frac(n, d);
            let s = BigInterval::sqrt_rat(&q, 100);
            let (lo, hi) = (s.lo_rat(), s.hi_rat());
            assert!(&lo * &lo <= q && q <= &hi * &hi, "{n}/{d}");
            assert!(s.width_f64() < 1e-25 * (n as f64 / d as f64).sqrt().max(1.0));
        }
        let exact = BigInterval::sqrt_rat(&Rat::from_frac(9, 4), 80);
        assert_eq!(exact.lo_rat(), Rat::from_frac(3, 2));
        assert_eq!(exact.hi_rat(), Rat::from_frac(3, 2));
    }

    proptest! {
        #[test]
        fn operations_enclose_exact_results(a in -10_000i64..10_000, b in 1i64..1000, c in -10_000i64..10_000, d in 1i64..1000, prec in 8u32..80) {
            let (x, y) = (Rat::from_frac(a, b), Rat::from_frac(c, d));
            let (ix, iy) = (BigInterval::from_rat(&x, prec), BigInterval::from_rat(&y, prec));
            prop_assert!(contains(&ix, &x) && contains(&iy, &y));
            prop_assert!(contains(&ix.plus(&iy), &(&x + &y)));
            prop_assert!(contains(&ix.minus(&iy), &(&x - &y)));
            prop_assert!(contains(&ix.times(&iy), &(&x * &y)));
            prop_assert!(contains(&ix.div_small(7), &(&x / &Rat::from(7))));
            prop_assert!(contains(&ix.div_small(-3), &(&x / &Rat::from(-3))));
            if c != 0 {
                let q = ix.div(&iy).expect("excludes zero");
                prop_assert!(contains(&q, &(&x / &y)));
            }
            let m = ix.hull(&iy).midpoint();
            prop_assert!(contains(&ix.hull(&iy), &m.lo_rat()));
        }
    }
}
