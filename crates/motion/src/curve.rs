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
/// ℤ[u] (no rational arithmetic). In `i128` when every number on the way
/// fits ([`small_poly_curve`]), else over [`Int`] ([`bernstein_to_power`]):
/// the same polynomials.
pub fn to_poly_curve<const N: usize>(curve: &Bezier<[Rat; N]>) -> PolyCurve<N> {
    let one = Rat::one();
    let columns = weighted_columns(curve, &one);
    let count = curve.points.len();
    small_poly_curve::<N>(&columns, count).unwrap_or_else(|| exact_poly_curve(&columns, count))
}

/// The values `wᵢ·Pᵢ[k]` column after column (`k < N`), then the weights
/// `wᵢ` (column `N`), in one buffer; borrowed where no product is needed
/// (no weights).
fn weighted_columns<'a, const N: usize>(
    curve: &'a Bezier<[Rat; N]>,
    one: &'a Rat,
) -> Vec<Cow<'a, Rat>> {
    let count = curve.points.len();
    let mut columns = Vec::with_capacity((N + 1) * count);
    for k in 0..N {
        match &curve.weights {
            Some(w) => columns.extend(
                curve
                    .points
                    .iter()
                    .zip(w)
                    .map(|(p, w)| Cow::Owned(&p[k] * w)),
            ),
            None => columns.extend(curve.points.iter().map(|p| Cow::Borrowed(&p[k]))),
        }
    }
    match &curve.weights {
        Some(w) => columns.extend(w.iter().map(Cow::Borrowed)),
        None => columns.extend(std::iter::repeat_n(Cow::Borrowed(one), count)),
    }
    columns
}

/// [`to_poly_curve`] over [`Int`], from [`weighted_columns`] (`count`
/// points).
fn exact_poly_curve<const N: usize>(columns: &[Cow<Rat>], count: usize) -> PolyCurve<N> {
    let den: Int = common_denominator(columns.iter().map(|x| &**x));
    let power = |column: &[Cow<Rat>]| -> ZPoly {
        let scaled: Vec<Int> = column.iter().map(|x| times_denominator(x, &den)).collect();
        bernstein_to_power(&scaled)
    };
    let column = |k: usize| &columns[k * count..][..count];
    PolyCurve {
        numerators: std::array::from_fn(|k| power(column(k))),
        denominator: power(column(N)),
    }
}

/// Degrees up to which [`small_poly_curve`] tries `i128` (every binomial
/// `C(k, i)`, `k ≤ 60`, fits an `i64`).
const SMALL_CURVE_DEGREE: usize = 60;

/// [`to_poly_curve`] in `i128` from [`weighted_columns`] (`count` points;
/// checked: `None` if a number on the way does not fit): `bᵢ = L·valueᵢ`
/// for the lcm `L` of the denominators ([`SmallInt`]), and per column
/// `Σ bᵢ·Bᵢⁿ(u) = Σ_k C(n, k)·(Σ_(i≤k) (−1)^(k−i)·C(k, i)·bᵢ)·u^k`, the
/// binomials by Pascal's rule (no division).
fn small_poly_curve<const N: usize>(columns: &[Cow<Rat>], count: usize) -> Option<PolyCurve<N>> {
    let n = count.checked_sub(1)?;
    if n > SMALL_CURVE_DEGREE {
        return None;
    }
    let den: SmallInt = common_denominator(columns.iter().map(|x| &**x));
    den.to_i128()?;
    // The binomial rows C(k, ·) for k ≤ n, by Pascal's rule in one flat
    // buffer (row k at offset k(k + 1)/2): additions, no division.
    let mut pascal: Vec<i64> = Vec::with_capacity((n + 1) * (n + 2) / 2);
    for k in 0..=n {
        // Row k − 1 ends where row k begins.
        let previous = pascal.len() - k;
        for i in 0..=k {
            pascal.push(match i {
                0 => 1,
                _ if i == k => 1,
                _ => pascal[previous + i - 1] + pascal[previous + i],
            });
        }
    }
    let row = |k: usize| &pascal[k * (k + 1) / 2..][..=k];
    // One buffer for every column's bᵢ.
    let mut b: Vec<i128> = Vec::with_capacity(count);
    let mut power = |column: &[Cow<Rat>]| -> Option<ZPoly> {
        b.clear();
        for x in column {
            b.push(times_denominator(x, &den).to_i128()?);
        }
        // Σ_(i≤k) C(k, i)·|bᵢ| ≤ 2^k·max|bᵢ| and C(n, k) ≤ 2^n: within
        // 2^125 no sum or product below can overflow, and the checked
        // operations are skipped.
        let bits = b
            .iter()
            .map(|x| 128 - x.unsigned_abs().leading_zeros())
            .max();
        let safe = bits.unwrap_or(0) as usize + 2 * n <= 125;
        let times = |x: i128, y: i128| if safe { Some(x * y) } else { x.checked_mul(y) };
        let plus = |x: i128, y: i128| if safe { Some(x + y) } else { x.checked_add(y) };
        let coeffs = (0..=n)
            .map(|k| {
                let mut sum = 0i128;
                for (i, (&c, &bi)) in row(k).iter().zip(&b).enumerate() {
                    let c = if (k - i) % 2 == 1 { -c } else { c };
                    sum = plus(sum, times(i128::from(c), bi)?)?;
                }
                Some(Int::from_i128(times(sum, i128::from(row(n)[k]))?))
            })
            .collect::<Option<Vec<Int>>>()?;
        Some(ZPoly::new(coeffs))
    };
    let mut columns = columns.chunks_exact(count);
    let mut numerators = Vec::with_capacity(N);
    for column in columns.by_ref().take(N) {
        numerators.push(power(column)?);
    }
    Some(PolyCurve {
        numerators: numerators.try_into().ok()?,
        denominator: power(columns.next()?)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::any;

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
            let curve = Bezier {
                points: (0..count)
                    .map(|i| std::array::from_fn::<_, 3, _>(|k| {
                        let (n, d) = points[3 * i + k];
                        &Rat::from_frac(n, d) * &scale
                    }))
                    .collect(),
                weights: weighted.then(|| (0..count).map(|i| Rat::from_frac(weights[i % 6], 7)).collect()),
            };
            let (small, exact) = routes(&curve);
            if let Some(small) = small {
                proptest::prop_assert_eq!(&small.numerators, &exact.numerators);
                proptest::prop_assert_eq!(&small.denominator, &exact.denominator);
            } else {
                proptest::prop_assert!(long > 0, "short numbers fit");
            }
        }
    }

    /// Both routes on one curve: the `i128` one (`None` where it declines)
    /// and the `Int` one.
    fn routes<const N: usize>(curve: &Bezier<[Rat; N]>) -> (Option<PolyCurve<N>>, PolyCurve<N>) {
        let one = Rat::one();
        let columns = weighted_columns(curve, &one);
        let count = curve.points.len();
        (
            small_poly_curve(&columns, count),
            exact_poly_curve(&columns, count),
        )
    }

    proptest::proptest! {
        /// Past the bound that skips the checks (`bits + 2n > 125`): long
        /// words and degrees up to 60, where sums overflow `i128` or come
        /// close. The `i128` route gives the `Int` route's polynomials or
        /// declines; it never returns wrapped numbers.
        #[test]
        fn checked_route_is_the_exact_route_or_declines(
            numerators in proptest::collection::vec(any::<i64>(), 2..62),
            denominators in proptest::collection::vec(1i64..4, 62),
        ) {
            let curve = Bezier {
                points: numerators
                    .iter()
                    .zip(&denominators)
                    .map(|(&n, &d)| [Rat::from_frac(n, d)])
                    .collect(),
                weights: None,
            };
            let (small, exact) = routes(&curve);
            if let Some(small) = small {
                proptest::prop_assert_eq!(&small.numerators, &exact.numerators);
                proptest::prop_assert_eq!(&small.denominator, &exact.denominator);
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
