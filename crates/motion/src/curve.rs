//! Bézier curves over the span, in the power basis of `u ∈ [0, 1]`, with
//! integer coefficients.

use crate::kinds::Bezier;
use ccd_arith::{Int, Rat, Ring, RingOps, SmallInt};
use ccd_poly::{bernstein_to_power, ZPoly};

/// The exact integer types the motion's numbers are brought to: [`Int`],
/// and [`SmallInt`] (an `i128` that overflows) for a route that runs over
/// machine words first and over [`Int`] again when a number does not fit.
pub(crate) trait Integer: Ring {
    /// The image of an [`Int`] (overflowed if it does not fit).
    fn of(x: &Int) -> Self;
    /// The non-negative greatest common divisor.
    fn gcd(&self, o: &Self) -> Self;
    /// `self == 1`.
    fn is_one(&self) -> bool;
}

impl Integer for Int {
    fn of(x: &Int) -> Int {
        x.clone()
    }
    fn gcd(&self, o: &Int) -> Int {
        Int::gcd(self, o)
    }
    fn is_one(&self) -> bool {
        Int::is_one(self)
    }
}

impl Integer for SmallInt {
    fn of(x: &Int) -> SmallInt {
        SmallInt::of(x)
    }
    fn gcd(&self, o: &SmallInt) -> SmallInt {
        SmallInt::gcd(self, o)
    }
    fn is_one(&self) -> bool {
        *self == SmallInt::one()
    }
}

/// The lcm of the denominators of `values` (`1` for none), skipping the
/// usual denominators `1` and those equal to the running lcm.
pub(crate) fn common_denominator<'a, I: Integer>(values: impl IntoIterator<Item = &'a Rat>) -> I {
    values.into_iter().fold(I::one(), |l, v| {
        if v.denom().is_one() {
            return l;
        }
        let d = I::of(v.denom());
        if d == l {
            l
        } else {
            // lcm(l, d) of positive denominators.
            l.div_exact(&l.gcd(&d)).times(&d)
        }
    })
}

/// `x·den` for a multiple `den` of the denominator of `x`: an integer.
pub(crate) fn times_denominator<I: Integer>(x: &Rat, den: &I) -> I {
    let numer = I::of(x.numer());
    if x.denom().is_one() {
        return numer.times(den);
    }
    let d = I::of(x.denom());
    if d == *den {
        numer
    } else {
        numer.times(&den.div_exact(&d))
    }
}

/// A (rational) Bézier curve of `N`-vectors as integer polynomial
/// numerators over one integer polynomial denominator: the curve is
/// `numerators / denominator` exactly, with the denominator a positive
/// multiple of the weight curve `Σ Bᵢⁿ(u)·wᵢ` (of `1` without weights).
pub struct PolyCurve<const N: usize> {
    /// One numerator polynomial per coordinate.
    pub numerators: [ZPoly; N],
    /// The (scaled) weight curve, positive on the span.
    pub denominator: ZPoly,
}

/// Converts a Bézier curve of `N`-vectors (points as `[Rat; N]`): with `L`
/// the lcm of the denominators of every `wᵢ·Pᵢ` and `wᵢ`, numerator `k` is
/// `Σ Bᵢⁿ(u)·(L·wᵢ·Pᵢ[k])` and the denominator `Σ Bᵢⁿ(u)·(L·wᵢ)`, both in
/// ℤ[u] ([`bernstein_to_power`]: additions only, no rational arithmetic).
pub fn to_poly_curve<const N: usize>(curve: &Bezier<[Rat; N]>) -> PolyCurve<N> {
    let weights: Vec<Rat> = match &curve.weights {
        Some(w) => w.clone(),
        None => vec![Rat::one(); curve.points.len()],
    };
    let values: [Vec<Rat>; N] = std::array::from_fn(|k| match &curve.weights {
        Some(w) => curve.points.iter().zip(w).map(|(p, w)| &p[k] * w).collect(),
        None => curve.points.iter().map(|p| p[k].clone()).collect(),
    });
    let den: Int = common_denominator(values.iter().flatten().chain(&weights));
    let scaled = |v: &[Rat]| -> Vec<Int> { v.iter().map(|x| times_denominator(x, &den)).collect() };
    PolyCurve {
        numerators: values.each_ref().map(|v| bernstein_to_power(&scaled(v))),
        denominator: bernstein_to_power(&scaled(&weights)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn power_form_interpolates_the_ends_and_midpoint() {
        let curve = Bezier {
            points: vec![
                [Rat::from(11), Rat::from_frac(1, 3)],
                [Rat::from(-1), Rat::from(2)],
            ],
            weights: None,
        };
        let c = to_poly_curve(&curve);
        let at = |u: Rat| {
            let w = c.denominator.eval_rat(&u);
            c.numerators.each_ref().map(|n| &n.eval_rat(&u) / &w)
        };
        assert_eq!(at(Rat::zero()), [Rat::from(11), Rat::from_frac(1, 3)]);
        assert_eq!(at(Rat::one()), [Rat::from(-1), Rat::from(2)]);
        // Quadratic with weights (1, 2, 1): B(1/2) = Σ Bᵢ wᵢ Pᵢ / Σ Bᵢ wᵢ.
        let curve = Bezier {
            points: vec![[Rat::from(1)], [Rat::from(5)], [Rat::from_frac(-3, 2)]],
            weights: Some(vec![Rat::one(), Rat::from(2), Rat::one()]),
        };
        let c = to_poly_curve(&curve);
        let half = Rat::from_frac(1, 2);
        let value = &c.numerators[0].eval_rat(&half) / &c.denominator.eval_rat(&half);
        // (1/4 + 1/2·2·5 − 1/4·3/2) / (1/4 + 1/2·2 + 1/4) = (39/8) / (3/2).
        assert_eq!(value, Rat::from_frac(13, 4));
    }
}
