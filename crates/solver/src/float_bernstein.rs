//! The certified filter: Bernstein coefficients as outward-rounded `f64`
//! intervals, subdivided by de Casteljau's algorithm in interval arithmetic.
//!
//! The exact integer coefficients are scaled by one common power of two so
//! that the largest fits comfortably in `f64`; a coefficient whose interval
//! contains zero has an undecided sign, and the caller falls back to exact
//! integers for that node. The intervals are enclosures of the exact scaled
//! coefficients, so every sign this module reports is proven.

use ccd_arith::{Int, Interval};

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
    fn huge_coefficients_keep_their_signs() {
        let big = Int::from(7).pow(1000);
        let fb = FloatBernstein::from_exact(&[big.clone(), -big.clone(), Int::from(1)], -1);
        assert_eq!(fb.coeffs[0].sign(), Some(-1));
        assert_eq!(fb.coeffs[1].sign(), Some(1));
        // 1 vanishes next to 7^1000 after scaling: undecided, never wrong.
        assert_eq!(fb.coeffs[2].sign(), None);
    }
}
