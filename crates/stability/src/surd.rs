//! Exact real numbers of the form `a + b·√q` (quadratic surds): the closed
//! form of every true contact instant the generator produces.
//!
//! A grazing pass of a homothetic pair has its contacts at the roots of a
//! quadratic `α u² + β u + γ` with rational coefficients, i.e. at
//! `u = −β/(2α) ± √(β² − 4αγ)/(2α)`; rational instants are the case `b = 0`.
//! Comparisons with rationals are decided exactly by squaring, so "the true
//! instant lies in `[lo, hi]`" is a proof, not a floating-point test.

use crate::StabilityError;
use ccd_arith::{Int, Rat};
use std::cmp::Ordering;

/// The real number `a + b·√q` with rational `a`, `b` and `q >= 0`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Surd {
    /// Rational part.
    pub a: Rat,
    /// Coefficient of the root.
    pub b: Rat,
    /// Radicand, `>= 0`.
    pub q: Rat,
}

impl Surd {
    /// The rational number `a` (`b = 0`).
    pub fn rational(a: Rat) -> Surd {
        Surd {
            a,
            b: Rat::zero(),
            q: Rat::zero(),
        }
    }

    /// `a + b·√q`; [`StabilityError::Truth`] if `q < 0`.
    pub fn new(a: Rat, b: Rat, q: Rat) -> Result<Surd, StabilityError> {
        if q.signum() < 0 {
            return Err(StabilityError::Truth(format!("negative radicand {q}")));
        }
        // A perfect-square radicand makes the value rational: fold it in.
        let (rn, rd) = (isqrt(q.numer()), isqrt(q.denom()));
        if &(&rn * &rn) == q.numer() && &(&rd * &rd) == q.denom() {
            let root = Rat::new(rn, rd).unwrap_or_else(Rat::zero);
            return Ok(Surd::rational(&a + &(&b * &root)));
        }
        Ok(Surd { a, b, q })
    }

    /// `true` when the value is rational by form (`b = 0` or `q = 0`).
    pub fn is_rational(&self) -> bool {
        self.b.is_zero() || self.q.is_zero()
    }

    /// The image `t0 + h·self` under an affine change of variable (from the
    /// normalised `u ∈ [0, 1]` to the time `t = t0 + u·(t1 − t0)`).
    pub fn affine(&self, t0: &Rat, h: &Rat) -> Surd {
        Surd {
            a: t0 + &(h * &self.a),
            b: h * &self.b,
            q: self.q.clone(),
        }
    }

    /// Exact comparison of `self` with a rational `r`: with `x = a − r`, the
    /// sign of `x + b√q` is the common sign of `x` and `b` when they agree,
    /// else the sign of the larger of `x²` and `b²q`.
    pub fn cmp_rat(&self, r: &Rat) -> Ordering {
        let x = &self.a - r;
        let sx = x.signum();
        let sb = if self.is_rational() {
            0
        } else {
            self.b.signum()
        };
        let sign = if sb == 0 || sx == sb {
            if sx == 0 {
                sb
            } else {
                sx
            }
        } else if sx == 0 {
            sb
        } else {
            match (&x * &x).cmp(&(&(&self.b * &self.b) * &self.q)) {
                Ordering::Greater => sx,
                Ordering::Less => sb,
                Ordering::Equal => 0,
            }
        };
        sign.cmp(&0)
    }

    /// `lo <= self <= hi`, decided exactly.
    pub fn within(&self, lo: &Rat, hi: &Rat) -> bool {
        self.cmp_rat(lo) != Ordering::Less && self.cmp_rat(hi) != Ordering::Greater
    }

    /// A rational within `2^-bits · max(1, |b|)` of the value:
    /// `√q = √(n·d)/d` for `q = n/d`, with the integer square root of
    /// `n·d·4^bits` (Newton's method on integers, which gives `⌊√N⌋`).
    pub fn approx(&self, bits: u64) -> Rat {
        if self.is_rational() {
            return self.a.clone();
        }
        let nd = self.q.numer() * self.q.denom();
        let root = isqrt(&nd.shl(2 * bits));
        let sqrt_q = Rat::new(root, self.q.denom().shl(bits)).unwrap_or_else(Rat::zero);
        &self.a + &(&self.b * &sqrt_q)
    }

    /// A nearby `f64`.
    pub fn to_f64(&self) -> f64 {
        self.approx(80).to_f64()
    }

    /// `|x − self|` for a rational `x`, as an `f64` accurate to about
    /// `2^-200` absolute (the value is approximated to 200 bits first, so
    /// errors down to `1e-50` are measured faithfully).
    pub fn distance(&self, x: &Rat) -> f64 {
        (x - &self.approx(200)).abs().to_f64()
    }

    /// The form `a + b*sqrt(q)` (or just `a`), with exact rationals.
    pub fn describe(&self) -> String {
        if self.is_rational() {
            self.a.to_string()
        } else {
            format!("{} + ({})*sqrt({})", self.a, self.b, self.q)
        }
    }
}

/// `⌊√n⌋` for `n >= 0` by Newton's iteration `x ← (x + n/x)/2` from a power
/// of two above the root; it decreases monotonically to `⌊√n⌋`.
fn isqrt(n: &Int) -> Int {
    if n.signum() <= 0 {
        return Int::zero();
    }
    let mut x = Int::one().shl(n.bits() / 2 + 1);
    loop {
        let y = (&x + &n.div_floor(&x)).shr_floor(1);
        if y >= x {
            return x;
        }
        x = y;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn isqrt_is_the_floor() {
        for v in [0i64, 1, 2, 3, 4, 15, 16, 17, 99, 100, 1 << 40] {
            let r = isqrt(&Int::from(v)).to_i64().unwrap_or(-1);
            assert!(r * r <= v && (r + 1) * (r + 1) > v, "{v}");
        }
    }

    #[test]
    fn comparisons_are_exact() {
        // 1 − √2 ≈ −0.41421356.
        let s = Surd::new(Rat::one(), -Rat::one(), Rat::from(2)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(
            s.cmp_rat(&Rat::from_frac(-41421356, 100_000_000)),
            Ordering::Less
        );
        assert_eq!(
            s.cmp_rat(&Rat::from_frac(-41421357, 100_000_000)),
            Ordering::Greater
        );
        assert!((s.to_f64() - (1.0 - 2f64.sqrt())).abs() < 1e-15);
        // 3 + 2·√(9/4) = 6 exactly.
        let t = Surd::new(Rat::from(3), Rat::from(2), Rat::from_frac(9, 4))
            .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(t.cmp_rat(&Rat::from(6)), Ordering::Equal);
        assert!(t.within(&Rat::from(6), &Rat::from(6)));
        assert!(Surd::new(Rat::one(), Rat::one(), -Rat::one()).is_err());
    }
}
