//! Bézier curves over the span, in the power basis of `u ∈ [0, 1]`.

use crate::kinds::Bezier;
use ccd_arith::{Int, Rat};
use ccd_poly::{Bernstein, QPoly};

/// `Σ Bᵢⁿ(u)·vᵢ` in the power basis: [`Bernstein::to_power`] on the
/// integer vector of the values over their common denominator (additions
/// only, no rational arithmetic).
fn bernstein_to_power(values: &[Rat]) -> QPoly {
    let den = values.iter().fold(Int::one(), |l, v| l.lcm(v.denom()));
    let ints = values
        .iter()
        .map(|v| v.numer() * &den.div_exact(v.denom()))
        .collect();
    let scale = Rat::new(Int::one(), den).expect("lcm of positive denominators is positive");
    Bernstein::from_parts(Rat::zero(), Rat::one(), scale, ints).to_power()
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
    let numerators = std::array::from_fn(|k| {
        let vals: Vec<Rat> = curve
            .points
            .iter()
            .enumerate()
            .map(|(i, p)| &p[k] * &weight(i))
            .collect();
        bernstein_to_power(&vals)
    });
    let denominator = match &curve.weights {
        Some(w) => bernstein_to_power(w),
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
        let p = bernstein_to_power(&v);
        assert_eq!(p.eval_rat(&Rat::zero()), Rat::from(11));
        assert_eq!(p.eval_rat(&Rat::one()), Rat::from(-1));
        // Quadratic: B(1/2) = (v0 + 2 v1 + v2)/4.
        let q = bernstein_to_power(&[Rat::from(1), Rat::from(5), Rat::from(-3)]);
        assert_eq!(q.eval_rat(&Rat::from_frac(1, 2)), Rat::from(2));
    }
}
