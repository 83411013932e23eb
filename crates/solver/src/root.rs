//! [`RealRoot`]: a real algebraic number given by a squarefree integer
//! polynomial and an isolating interval with exact rational ends; refinable
//! to any width, and able to decide the exact sign of any polynomial at it.

use crate::scaled::ScaledPoly;
use ccd_arith::{Interval, Rat};
use ccd_poly::{Bernstein, ZPoly};
use std::sync::{Arc, OnceLock};

/// A real root `α` of a squarefree `p ∈ ℤ[t]`: either known exactly
/// (`lo = hi = α`, a rational root) or the only root of `p` in the open
/// interval `(lo, hi)`, where `p(lo)` and `p(hi)` are nonzero with opposite
/// signs.
#[derive(Clone, Debug)]
pub struct RealRoot {
    poly: Arc<ZPoly>,
    lo: Rat,
    hi: Rat,
    /// Sign of `p(lo)`; 0 when the root is exact.
    sign_lo: i32,
    approx: Arc<OnceLock<ScaledPoly>>,
}

impl RealRoot {
    pub(crate) fn exact(poly: Arc<ZPoly>, at: Rat) -> RealRoot {
        RealRoot {
            poly,
            lo: at.clone(),
            hi: at,
            sign_lo: 0,
            approx: Arc::default(),
        }
    }

    pub(crate) fn isolated(poly: Arc<ZPoly>, lo: Rat, hi: Rat, sign_lo: i32) -> RealRoot {
        debug_assert!(sign_lo != 0 && lo < hi);
        RealRoot {
            poly,
            lo,
            hi,
            sign_lo,
            approx: Arc::default(),
        }
    }

    /// Lower end of the enclosure.
    pub fn lo(&self) -> &Rat {
        &self.lo
    }
    /// Upper end of the enclosure.
    pub fn hi(&self) -> &Rat {
        &self.hi
    }
    /// The squarefree polynomial this is a root of.
    pub fn poly(&self) -> &ZPoly {
        &self.poly
    }
    /// The rational value when the root is known exactly.
    pub fn exact_value(&self) -> Option<&Rat> {
        (self.sign_lo == 0).then_some(&self.lo)
    }
    /// `hi − lo`.
    pub fn width(&self) -> Rat {
        &self.hi - &self.lo
    }
    /// The midpoint of the enclosure.
    pub fn midpoint(&self) -> Rat {
        Rat::midpoint(&self.lo, &self.hi)
    }

    fn scaled(&self) -> &ScaledPoly {
        self.approx.get_or_init(|| ScaledPoly::new(&self.poly))
    }

    /// Moves one end to `x` (strictly inside) according to the exact sign of
    /// `p(x)`; a zero makes the root exact.
    fn cut(&mut self, x: Rat) {
        let s = self.sign_of_p_at(&x);
        if s == 0 {
            self.lo = x.clone();
            self.hi = x;
            self.sign_lo = 0;
        } else if s == self.sign_lo {
            self.lo = x;
        } else {
            self.hi = x;
        }
    }

    /// The sign of `p(x)`: the interval enclosure when it excludes zero,
    /// exact evaluation otherwise.
    fn sign_of_p_at(&self, x: &Rat) -> i32 {
        match self.scaled().enclose(Interval::from_rat(x)).sign() {
            Some(s) if s != 0 => s,
            _ => self.poly.sign_at(x),
        }
    }

    /// Halves the enclosure (one sign evaluation).
    pub fn bisect(&mut self) {
        if self.sign_lo != 0 {
            self.cut(self.midpoint());
        }
    }

    /// Tries to jump to an enclosure of width about `target` around a float
    /// Newton estimate, proven by the exact signs at its two ends.
    fn newton_jump(&mut self, target: &Rat) -> bool {
        let (lo_f, hi_f) = (self.lo.to_f64(), self.hi.to_f64());
        let sp = self.scaled();
        let mut x = 0.5 * (lo_f + hi_f);
        for _ in 0..12 {
            let (v, d) = sp.value_and_slope(x);
            if d == 0.0 || !v.is_finite() || !d.is_finite() {
                return false;
            }
            let nx = (x - v / d).clamp(lo_f, hi_f);
            if nx == x {
                break;
            }
            x = nx;
        }
        let eps = (target.to_f64() * 0.25).max(4.0 * f64::EPSILON * x.abs().max(f64::MIN_POSITIVE));
        let (Some(a), Some(b)) = (Rat::from_f64_exact(x - eps), Rat::from_f64_exact(x + eps))
        else {
            return false;
        };
        let old = self.width();
        if a > self.lo && a < self.hi {
            self.cut(a);
        }
        if b > self.lo && b < self.hi {
            self.cut(b);
        }
        self.sign_lo == 0 || self.width() * Rat::from(2) <= old
    }

    /// Shrinks the enclosure until `hi − lo <= max_width` (or the root turns
    /// out rational). Each step is proven by exact signs of `p`.
    ///
    /// At the end the simplest rational in the enclosure is tried: a root
    /// `a/b` with `b² < 1/(hi − lo)` is that rational, and is then reported
    /// exactly (one exact evaluation).
    pub fn refine_to(&mut self, max_width: &Rat) {
        let mut newton_ok = true;
        while self.sign_lo != 0 && self.width() > *max_width {
            if newton_ok {
                newton_ok = self.newton_jump(max_width);
                if newton_ok {
                    continue;
                }
            }
            self.bisect();
        }
        if self.sign_lo != 0 {
            let s = Rat::simplest_in(&self.lo, &self.hi);
            if s != self.lo && s != self.hi && self.poly.sign_at(&s) == 0 {
                self.lo = s.clone();
                self.hi = s;
                self.sign_lo = 0;
            }
        }
    }

    fn enclosure(&self) -> Interval {
        Interval::from_rat(&self.lo).hull(&Interval::from_rat(&self.hi))
    }

    /// The exact sign (−1, 0, 1) of `q(α)`.
    ///
    /// First the certified filter: an interval enclosure of `q` over the
    /// isolating interval, refined a few times. If it cannot exclude zero,
    /// zero is decided exactly: `q(α) = 0` iff `g = gcd(p, q)` has a root in
    /// the interval, and since `g | p` has at most the one root `α` there,
    /// that is a sign change of `g` between the ends. If `q(α) ≠ 0`, the
    /// interval is refined until `q`'s exact Bernstein coefficients over it
    /// share one strict sign, which must happen since `q` has no root near `α`.
    pub fn sign_of(&mut self, q: &ZPoly) -> i32 {
        if q.is_zero() {
            return 0;
        }
        if self.sign_lo == 0 {
            return q.sign_at(&self.lo);
        }
        let sq = ScaledPoly::new(q);
        for _ in 0..4 {
            if let Some(s) = sq.enclose(self.enclosure()).sign() {
                if s != 0 {
                    return s;
                }
            }
            let w = self.width().mul_pow2(-12);
            self.refine_to(&w);
            if self.sign_lo == 0 {
                return q.sign_at(&self.lo);
            }
        }
        let g = self.poly.gcd(q);
        if g.degree().unwrap_or(0) >= 1 && g.sign_at(&self.lo) * g.sign_at(&self.hi) < 0 {
            return 0;
        }
        loop {
            if let Some(s) = sq.enclose(self.enclosure()).sign() {
                if s != 0 {
                    return s;
                }
            }
            let b = Bernstein::from_power(q, &self.lo, &self.hi);
            let s = b.scale().signum();
            let first = b.coeffs()[0].signum();
            if first != 0 && b.coeffs().iter().all(|c| c.signum() == first) {
                return first * s;
            }
            let w = self.width().mul_pow2(-8);
            self.refine_to(&w);
            if self.sign_lo == 0 {
                return q.sign_at(&self.lo);
            }
        }
    }
}
