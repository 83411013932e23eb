//! Bézier curves over the span, in the power basis of `u ∈ [0, 1]`, with
//! integer coefficients.

use crate::kinds::Bezier;
use ccd_arith::{Int, Rat, Ring, RingOps, SmallInt};
use ccd_poly::{bernstein_to_power, ZPoly};
use std::borrow::Cow;

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

/// The gcd of `values` (`≥ 0`; `0` when all vanish), stopping as soon as
/// it is `1`.
pub(crate) fn content<'a, I: Integer + 'a>(values: impl IntoIterator<Item = &'a I>) -> I {
    values
        .into_iter()
        .fold(I::zero(), |g, e| if g.is_one() { g } else { g.gcd(e) })
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
/// ℤ[u] (no rational arithmetic). In `i128` ([`SmallInt`]) when every
/// number on the way fits, else over [`Int`] ([`bernstein_to_power`]):
/// the same polynomials.
pub fn to_poly_curve<const N: usize>(curve: &Bezier<[Rat; N]>) -> PolyCurve<N> {
    // Borrowed where no product is needed (no weights).
    let one = Rat::one();
    let weights: Vec<Cow<Rat>> = match &curve.weights {
        Some(w) => w.iter().map(Cow::Borrowed).collect(),
        None => vec![Cow::Borrowed(&one); curve.points.len()],
    };
    let values: [Vec<Cow<Rat>>; N] = std::array::from_fn(|k| match &curve.weights {
        Some(w) => curve
            .points
            .iter()
            .zip(w)
            .map(|(p, w)| Cow::Owned(&p[k] * w))
            .collect(),
        None => curve.points.iter().map(|p| Cow::Borrowed(&p[k])).collect(),
    });
    small_poly_curve(&values, &weights).unwrap_or_else(|| exact_poly_curve(&values, &weights))
}

/// [`to_poly_curve`] of the values `wᵢ·Pᵢ[k]` and weights `wᵢ` over [`Int`].
fn exact_poly_curve<const N: usize>(
    values: &[Vec<Cow<Rat>>; N],
    weights: &[Cow<Rat>],
) -> PolyCurve<N> {
    let den: Int = common_denominator(values.iter().flatten().chain(weights).map(|x| &**x));
    let scaled =
        |v: &[Cow<Rat>]| -> Vec<Int> { v.iter().map(|x| times_denominator(x, &den)).collect() };
    PolyCurve {
        numerators: values.each_ref().map(|v| bernstein_to_power(&scaled(v))),
        denominator: bernstein_to_power(&scaled(weights)),
    }
}

/// [`to_poly_curve`] over [`SmallInt`]: `None` if a number does not fit
/// (or the degree is beyond the binomials' `i64` range).
fn small_poly_curve<const N: usize>(
    values: &[Vec<Cow<Rat>>; N],
    weights: &[Cow<Rat>],
) -> Option<PolyCurve<N>> {
    let n = weights.len().checked_sub(1)?;
    if n > 60 {
        return None;
    }
    let den: SmallInt = common_denominator(values.iter().flatten().chain(weights).map(|x| &**x));
    den.to_i128()?;
    // C(k, i) for k ≤ n, a row at a time (Pascal), as SmallInts.
    let mut pascal: Vec<Vec<SmallInt>> = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let row = (0..=k)
            .map(|i| match i {
                0 => SmallInt::one(),
                _ if i == k => SmallInt::one(),
                _ => pascal[k - 1][i - 1].plus(&pascal[k - 1][i]),
            })
            .collect();
        pascal.push(row);
    }
    // Σ bᵢ·Bᵢⁿ(u) = Σ_k C(n, k)·(Σ_(i≤k) (−1)^(k−i)·C(k, i)·bᵢ)·u^k.
    let power = |v: &[Cow<Rat>]| -> Option<ZPoly> {
        let b: Vec<SmallInt> = v.iter().map(|x| times_denominator(x, &den)).collect();
        let coeffs: Option<Vec<Int>> = (0..=n)
            .map(|k| {
                let mut s = SmallInt::zero();
                for (i, bi) in b.iter().enumerate().take(k + 1) {
                    s.add_product(&pascal[k][i], bi, (k - i) % 2 == 1);
                }
                s.times(&pascal[n][k]).to_int()
            })
            .collect();
        Some(ZPoly::new(coeffs?))
    };
    let numerators: Vec<ZPoly> = values.iter().map(|v| power(v)).collect::<Option<_>>()?;
    Some(PolyCurve {
        numerators: numerators.try_into().ok()?,
        denominator: power(weights)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    proptest::proptest! {
        /// The `i128` route gives the `Int` route's polynomials, and
        /// declines (rather than overflowing) on long numbers.
        #[test]
        fn small_route_is_the_exact_route(
            points in proptest::collection::vec((-1_000_000_000i64..1_000_000_000, 1i64..20), 3..18),
            weights in proptest::collection::vec(1i64..1000, 6),
            weighted in proptest::bool::ANY,
            long in 0u32..4,
        ) {
            let scale = Rat::from_int(Int::from(10).pow(13 * long));
            let count = points.len() / 3;
            let values: [Vec<Cow<Rat>>; 3] = std::array::from_fn(|k| {
                (0..count).map(|i| {
                    let (n, d) = points[3 * i + k];
                    let w = if weighted { Rat::from_frac(weights[i % 6], 7) } else { Rat::one() };
                    Cow::Owned(&(&Rat::from_frac(n, d) * &scale) * &w)
                }).collect()
            });
            let w: Vec<Cow<Rat>> = (0..count)
                .map(|i| Cow::Owned(if weighted { Rat::from_frac(weights[i % 6], 7) } else { Rat::one() }))
                .collect();
            let exact = exact_poly_curve(&values, &w);
            if let Some(small) = small_poly_curve(&values, &w) {
                proptest::prop_assert_eq!(&small.numerators, &exact.numerators);
                proptest::prop_assert_eq!(&small.denominator, &exact.denominator);
            } else {
                proptest::prop_assert!(long > 0, "short numbers fit");
            }
        }
    }

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
