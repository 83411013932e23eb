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
    /// positive power of two) straight from the power basis, in interval
    /// arithmetic: `q(u) = p(lo + (hi − lo)·u)` by a Taylor shift and scaling,
    /// then `b_i = Σ_j C(i, j)/C(n, j)·q_j` as `q_j/C(n, j)` accumulated
    /// through Pascal's triangle (additions only). `None` when a coefficient's
    /// sign is left undecided (cancellation): the caller converts exactly.
    pub(crate) fn from_power(p: &ZPoly, lo: &Rat, hi: &Rat) -> Option<FloatBernstein> {
        let n = p.degree()?;
        let max_bits = p.max_bits() as i64;
        let shift = (max_bits - TARGET_BITS).max(0);
        let mut a: Vec<Interval> = p
            .coeffs()
            .iter()
            .map(|c| Interval::from_int_scaled(c, shift))
            .collect();
        if !lo.is_zero() {
            let l = Interval::from_rat(lo);
            for i in 0..n {
                for j in (i..n).rev() {
                    a[j] = a[j] + l * a[j + 1];
                }
            }
        }
        let w = hi - lo;
        if w != Rat::one() {
            let wi = Interval::from_rat(&w);
            let mut pw = Interval::point(1.0);
            for c in a.iter_mut().skip(1) {
                pw = pw * wi;
                *c = *c * pw;
            }
        }
        // q_j / C(n, j), then b_i = Σ_j C(i, j)·(q_j / C(n, j)).
        let mut binom = Int::one();
        for (j, c) in a.iter_mut().enumerate() {
            *c = c.div_positive(Interval::from_int(&binom));
            binom = (&binom * &Int::from((n - j) as i64)).div_exact(&Int::from((j + 1) as i64));
        }
        for k in 1..=n {
            for i in (k..=n).rev() {
                a[i] = a[i] + a[i - 1];
            }
        }
        let fb = FloatBernstein { coeffs: a };
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
