//! The certified filter: Bernstein coefficients as outward-rounded `f64`
//! intervals, subdivided by de Casteljau's algorithm in interval arithmetic.
//!
//! The exact integer coefficients are scaled by one common power of two so
//! that the largest fits comfortably in `f64`; a coefficient whose interval
//! contains zero has an undecided sign, and the caller falls back to exact
//! integers for that node. The intervals are enclosures of the exact scaled
//! coefficients, so every sign this module reports is proven.

use ccd_arith::{Int, Interval, Rat};
use ccd_poly::ZPoly;

/// Largest bit length kept in front of the binary point after scaling.
const TARGET_BITS: i64 = 900;

/// A node's Bernstein coefficients as interval enclosures (the exact values
/// times one positive factor).
#[derive(Clone, Debug)]
pub(crate) struct FloatBernstein {
    pub(crate) coeffs: Vec<Interval>,
}

impl FloatBernstein {
    /// Encloses `sign · coeffs` scaled by a common power of two.
    pub(crate) fn from_exact(coeffs: &[Int], sign: i32) -> FloatBernstein {
        let max_bits = coeffs.iter().map(Int::bits).max().unwrap_or(0) as i64;
        let shift = (max_bits - TARGET_BITS).max(0);
        let coeffs = coeffs
            .iter()
            .map(|c| {
                let i = Interval::from_int_scaled(c, shift);
                if sign < 0 {
                    -i
                } else {
                    i
                }
            })
            .collect();
        FloatBernstein { coeffs }
    }

    /// Encloses the Bernstein coefficients of `p` over `[lo, hi]` (times a
    /// positive factor) without a single gcd: with `q(u) = p(lo + (hi − lo)·u)`
    /// (exact, up to a positive factor), the integers
    /// `c_i = C(n, i)·b_i` are the coefficients of `(1 + s)^n q(s/(1 + s))`,
    /// i.e. `reverse(shift₁(reverse(q)))` — additions only — and each `b_i` is
    /// then enclosed as `c_i / C(n, i)` with one rounding (no cancellation).
    /// The signs of the `c_i` are exact. Requires `p(lo) ≠ 0` and `p(hi) ≠ 0`
    /// (so the reversals keep the degree); `None` if a sign is undecided.
    pub(crate) fn from_power(p: &ZPoly, lo: &Rat, hi: &Rat) -> Option<FloatBernstein> {
        let n = p.degree()?;
        let q = if lo.is_zero() && *hi == Rat::one() {
            p.clone()
        } else {
            p.compose_affine(lo, &(hi - lo))
        };
        let c = q.reverse().taylor_shift(&Int::one()).reverse();
        if c.degree() != Some(n) || c.coeff(0).is_zero() {
            return None;
        }
        let max_bits = c.max_bits() as i64;
        let shift = (max_bits - TARGET_BITS).max(0);
        let mut binom = Int::one();
        let mut coeffs = Vec::with_capacity(n + 1);
        for (i, ci) in c.coeffs().iter().enumerate() {
            coeffs.push(
                Interval::from_int_scaled(ci, shift).div_positive(Interval::from_int(&binom)),
            );
            binom = (&binom * &Int::from((n - i) as i64)).div_exact(&Int::from((i + 1) as i64));
        }
        let fb = FloatBernstein { coeffs };
        fb.signs().map(|_| fb)
    }

    /// The certified sign of every coefficient, or `None` if one is undecided.
    pub(crate) fn signs(&self) -> Option<Vec<i32>> {
        self.coeffs.iter().map(Interval::sign).collect()
    }

    /// De Casteljau at `1/2`: the coefficients over the two halves.
    pub(crate) fn split_half(&self) -> (FloatBernstein, FloatBernstein) {
        let n = self.coeffs.len() - 1;
        let mut b = self.coeffs.clone();
        let mut left = Vec::with_capacity(n + 1);
        let mut right = vec![Interval::point(0.0); n + 1];
        left.push(b[0]);
        right[n] = b[n];
        for k in 1..=n {
            for i in 0..=n - k {
                b[i] = b[i].average(b[i + 1]);
            }
            left.push(b[0]);
            right[n - k] = b[n - k];
        }
        (
            FloatBernstein { coeffs: left },
            FloatBernstein { coeffs: right },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_poly::Bernstein;

    #[test]
    fn split_encloses_exact_halves() {
        // p(u) = (u - 1/3)(u - 2/3) in Bernstein form over [0, 1]:
        // b = [2/9, -5/18, 2/9] -> times 18: [4, -5, 4].
        let fb = FloatBernstein::from_exact(&[Int::from(4), Int::from(-5), Int::from(4)], 1);
        assert_eq!(fb.signs(), Some(vec![1, -1, 1]));
        let (l, r) = fb.split_half();
        // Exact halves: left [4, -1/2, -1/4]·..., check signs only.
        assert_eq!(l.signs(), Some(vec![1, -1, -1]));
        assert_eq!(r.signs(), Some(vec![-1, -1, 1]));
    }

    #[test]
    fn interval_conversion_agrees_with_exact_signs() {
        // (3u − 1)(2u − 1)(u² + 1)·(5u + 7) on several intervals.
        let p = ZPoly::from_i64s(&[-1, 3])
            * ZPoly::from_i64s(&[-1, 2])
            * ZPoly::from_i64s(&[1, 0, 1])
            * ZPoly::from_i64s(&[7, 5]);
        for (lo, hi) in [
            (Rat::zero(), Rat::one()),
            (Rat::from_frac(-3, 2), Rat::from_frac(1, 5)),
            (Rat::from_frac(1, 7), Rat::from(4)),
        ] {
            let exact = Bernstein::from_power(&p, &lo, &hi);
            let float = FloatBernstein::from_power(&p, &lo, &hi).expect("well conditioned");
            let signs: Vec<i32> = exact.coeffs().iter().map(|c| c.signum()).collect();
            assert_eq!(float.signs(), Some(signs));
        }
    }

    #[test]
    fn huge_coefficients_keep_their_signs() {
        let big = Int::from(7).pow(1000);
        let fb = FloatBernstein::from_exact(&[big.clone(), -big.clone(), Int::from(1)], -1);
        assert_eq!(fb.coeffs[0].sign(), Some(-1));
        assert_eq!(fb.coeffs[1].sign(), Some(1));
        // 1 vanishes next to 7^1000 after scaling: undecided, never wrong.
        assert_eq!(fb.coeffs[2].sign(), None);
    }
}
