//! Bézier curves over the span, in the power basis of `u ∈ [0, 1]`.

use crate::kinds::Bezier;
use ccd_arith::{Int, Rat};
use ccd_poly::{QPoly, ZPoly};

/// `Σ Bᵢⁿ(u)·vᵢ` in the power basis, for degree `n`: the coefficient of
/// `uʲ` is `C(n, j)·Σ_{i<=j} (−1)^(j−i)·C(j, i)·vᵢ`, computed on the integer
/// vector of [`QPoly::from_rats`] (`vᵢ = s·Pᵢ`; the map is linear, so no
/// rational arithmetic). Pascal's triangle is formed once for all the
/// coordinates of a curve.
struct PowerMap {
    /// Rows `0..=n` of Pascal's triangle.
    binom: Vec<Vec<Int>>,
}

impl PowerMap {
    fn new(n: usize) -> PowerMap {
        let mut binom: Vec<Vec<Int>> = vec![vec![Int::one()]];
        for r in 1..=n {
            let prev = &binom[r - 1];
            let mut row = vec![Int::one(); r + 1];
            for k in 1..r {
                row[k] = &prev[k - 1] + &prev[k];
            }
            binom.push(row);
        }
        PowerMap { binom }
    }

    fn apply(&self, values: &[Rat]) -> QPoly {
        let n = self.binom.len() - 1;
        debug_assert_eq!(values.len(), n + 1);
        let v = QPoly::from_rats(values);
        let coeffs: Vec<Int> = (0..=n)
            .map(|j| {
                let s = self.binom[j]
                    .iter()
                    .enumerate()
                    .fold(Int::zero(), |s, (i, c)| {
                        let term = c * &v.prim().coeff(i);
                        if (j - i) % 2 == 0 {
                            s + term
                        } else {
                            s - term
                        }
                    });
                s * &self.binom[n][j]
            })
            .collect();
        QPoly::from_parts(v.scale().clone(), ZPoly::new(coeffs))
    }
}

/// A (rational) Bézier curve of `N`-vectors as polynomial numerators and
/// one common denominator: the curve is `numerators / denominator`, the
/// denominator `Σ Bᵢⁿ(u)·wᵢ` (1 without weights).
pub struct PolyCurve<const N: usize> {
    /// One numerator polynomial per coordinate.
    pub numerators: [QPoly; N],
    /// The weight curve.
    pub denominator: QPoly,
}

/// Converts a Bézier curve of `N`-vectors (points as `[Rat; N]`).
pub fn to_poly_curve<const N: usize>(curve: &Bezier<[Rat; N]>) -> PolyCurve<N> {
    let weight = |i: usize| curve.weights.as_ref().map_or(Rat::one(), |w| w[i].clone());
    let map = PowerMap::new(curve.points.len().saturating_sub(1));
    let numerators = std::array::from_fn(|k| {
        let vals: Vec<Rat> = curve
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| &p[k] * &weight(i))
            .collect();
        map.apply(&vals)
    });
    let denominator = match &curve.weights {
        Some(w) => map.apply(w),
        None => QPoly::one(),
    };
    PolyCurve {
        numerators,
        denominator,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_form_interpolates_the_ends_and_midpoint() {
        let v = [Rat::from(11), Rat::from(-1)];
        let p = PowerMap::new(1).apply(&v);
        assert_eq!(p.eval_rat(&Rat::zero()), Rat::from(11));
        assert_eq!(p.eval_rat(&Rat::one()), Rat::from(-1));
        // Quadratic: B(1/2) = (v0 + 2 v1 + v2)/4.
        let q = PowerMap::new(2).apply(&[Rat::from(1), Rat::from(5), Rat::from(-3)]);
        assert_eq!(q.eval_rat(&Rat::from_frac(1, 2)), Rat::from(2));
    }
}
