//! Floating-point views of an exact integer polynomial: interval
//! coefficients for certified enclosures, plain `f64` for Newton guesses.
//! Both are scaled by one power of two so huge coefficients fit.

use ccd_arith::{Int, Interval};
use ccd_poly::ZPoly;
use std::sync::OnceLock;

/// Bit length kept for the largest coefficient after scaling.
const TARGET_BITS: i64 = 600;

/// `p · 2^(-shift)` with interval coefficients (low → high): certified
/// `f64` enclosures of an exact polynomial and its derivatives over
/// intervals, and plain `f64` values for Newton guesses.
#[derive(Clone, Debug)]
pub struct ScaledPoly {
    coeffs: Vec<Interval>,
    approx: Vec<f64>,
    shift: i64,
    /// `[i·cᵢ, i(i−1)·cᵢ]` enclosed (the coefficients of `p′` and `p″`,
    /// each one rounding of the product), formed on first need.
    derived: OnceLock<Vec<[Interval; 2]>>,
}

impl ScaledPoly {
    /// `p` scaled so its largest coefficient has about 600 bits.
    pub fn new(p: &ZPoly) -> ScaledPoly {
        ScaledPoly::with_shift(p, (p.max_bits() as i64 - TARGET_BITS).max(0))
    }

    /// `p · 2^(-shift)` for a given shift (several polynomials on one scale).
    pub fn with_shift(p: &ZPoly, shift: i64) -> ScaledPoly {
        let coeffs: Vec<Interval> = p
            .coeffs()
            .iter()
            .map(|c: &Int| Interval::from_int_scaled(c, shift))
            .collect();
        let approx = coeffs.iter().map(Interval::mid).collect();
        ScaledPoly {
            coeffs,
            approx,
            shift,
            derived: OnceLock::new(),
        }
    }

    /// `[i·cᵢ, i(i−1)·cᵢ]` for every `i` (the falling factorials of
    /// [`ScaledPoly::enclose_derivative`] for orders 1 and 2).
    fn derived(&self) -> &[[Interval; 2]] {
        self.derived.get_or_init(|| {
            let times = |c: Interval, f: usize| c * Interval::point(f as f64);
            self.coeffs
                .iter()
                .enumerate()
                .map(|(i, &c)| [times(c, i), times(c, i * i.saturating_sub(1))])
                .collect()
        })
    }

    /// The power of two the coefficients were scaled by.
    pub fn shift(&self) -> i64 {
        self.shift
    }

    /// A certified enclosure of `{ p(x)·2^(-shift) : x ∈ X }` (interval Horner).
    pub fn enclose(&self, x: Interval) -> Interval {
        let [v] = ScaledPoly::enclose_each([self], x);
        v
    }

    /// [`ScaledPoly::enclose`] of each polynomial over one `x`, bit for
    /// bit, their Horner steps taken in lockstep (see `lockstep`: the
    /// steps of independent polynomials alternate).
    pub fn enclose_each<const N: usize>(polys: [&ScaledPoly; N], x: Interval) -> [Interval; N] {
        horner_passes(
            polys.map(|p| &p.coeffs[..]),
            0,
            Interval::point(0.0),
            x,
            Interval::is_finite,
            |acc, _, c, mul_add| mul_add(acc, *c),
        )
    }

    /// A certified enclosure of `{ p⁽ʳ⁾(x)·2^(-shift) : x ∈ X }` for
    /// `r = order ≥ 1`, from the interval coefficients
    /// (`Σ i(i−1)…(i−r+1)·cᵢ·X^(i−r)`, interval Horner; the falling
    /// factorials are exact in `f64` for the degrees here), with no exact
    /// derivative.
    pub fn enclose_derivative(&self, order: usize, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        if (1..=2).contains(&order) {
            // The same products, formed once ([`ScaledPoly::derived`]).
            for d in self.derived().iter().skip(order).rev() {
                acc = acc * x + d[order - 1];
            }
            return acc;
        }
        for (i, c) in self.coeffs.iter().enumerate().skip(order).rev() {
            let factor: usize = (i + 1 - order..=i).product();
            acc = acc * x + *c * Interval::point(factor as f64);
        }
        acc
    }

    /// `(enclose_derivative(1, x), enclose_derivative(2, x))`, bit for
    /// bit, from one pass over the coefficients (each Horner sum keeps
    /// its own order of operations).
    pub fn enclose_derivatives(&self, x: Interval) -> (Interval, Interval) {
        let [d] = ScaledPoly::enclose_derivatives_each([self], x);
        d
    }

    /// [`ScaledPoly::enclose_derivatives`] of each polynomial over one
    /// `x`, bit for bit, in lockstep (as [`ScaledPoly::enclose_each`]).
    pub fn enclose_derivatives_each<const N: usize>(
        polys: [&ScaledPoly; N],
        x: Interval,
    ) -> [(Interval, Interval); N] {
        let zero = Interval::point(0.0);
        horner_passes(
            polys.map(|p| p.derived()),
            1,
            (zero, zero),
            x,
            |(d1, d2)| d1.is_finite() && d2.is_finite(),
            |(d1, d2), i, d, mul_add| {
                let d1 = mul_add(d1, d[0]);
                (d1, if i >= 2 { mul_add(d2, d[1]) } else { d2 })
            },
        )
    }

    /// The first derivatives of [`ScaledPoly::enclose_derivatives_each`]
    /// alone, bit for bit (the same Horner sums, without the second's).
    pub fn enclose_slopes_each<const N: usize>(
        polys: [&ScaledPoly; N],
        x: Interval,
    ) -> [Interval; N] {
        horner_passes(
            polys.map(|p| p.derived()),
            1,
            Interval::point(0.0),
            x,
            Interval::is_finite,
            |d1, _, d, mul_add| mul_add(d1, d[0]),
        )
    }

    /// `(p(x), p'(x))` approximately, scaled.
    pub fn value_and_slope(&self, x: f64) -> (f64, f64) {
        let [vd] = ScaledPoly::value_and_slope_each([self], x);
        vd
    }

    /// [`ScaledPoly::value_and_slope`] of each polynomial at one `x`, bit
    /// for bit, in lockstep (as [`ScaledPoly::enclose_each`]).
    pub fn value_and_slope_each<const N: usize>(
        polys: [&ScaledPoly; N],
        x: f64,
    ) -> [(f64, f64); N] {
        lockstep(
            polys.map(|p| &p.approx[..]),
            0,
            (0.0, 0.0),
            |(v, d), _, &c| (v * x + c, d * x + v),
        )
    }
}

/// Interval Horner passes over `x` in [`lockstep`], each step
/// `step(acc, index, coefficient, mul_add)` with `mul_add(a, c) = a·x + c`.
/// Where `0 ≤ x.lo ≤ x.hi < ∞` the pass first takes
/// [`Interval::mul_add_nonneg_unchecked`] and tests only its results
/// (`finite`): a pass whose every step is finite is `mul_fast` and `+` bit
/// for bit, and one that is not ends non-finite. Otherwise, or then, the
/// pass is taken with `mul_fast` and `+`.
fn horner_passes<const N: usize, C, A: Copy>(
    lists: [&[C]; N],
    skip: usize,
    start: A,
    x: Interval,
    finite: impl Fn(&A) -> bool,
    step: impl Fn(A, usize, &C, &dyn Fn(Interval, Interval) -> Interval) -> A,
) -> [A; N] {
    if x.lo >= 0.0 && x.lo <= x.hi && x.hi < f64::INFINITY {
        let unchecked = |a: Interval, c: Interval| a.mul_add_nonneg_unchecked(x, c);
        let out = lockstep(lists, skip, start, |a, i, c| step(a, i, c, &unchecked));
        if out.iter().all(&finite) {
            return out;
        }
    }
    let checked = |a: Interval, c: Interval| a.mul_fast(x) + c;
    lockstep(lists, skip, start, |a, i, c| step(a, i, c, &checked))
}

/// Horner's rule on `N` coefficient lists (low → high) at once: the
/// accumulators start at `start`, and from the top index down to `skip`
/// each list with a coefficient there takes `step(acc, index, coefficient)`.
/// Each list sees exactly the steps it would alone (so the same bits), but
/// the steps of the `N` lists alternate: within one list each step waits
/// for the one before (an interval step is a product, its widening, a sum
/// and its widening, one after the other), so independent chains side by
/// side keep the floating-point units busy where one alone would stall.
#[inline]
fn lockstep<const N: usize, C, A: Copy>(
    lists: [&[C]; N],
    skip: usize,
    start: A,
    step: impl Fn(A, usize, &C) -> A,
) -> [A; N] {
    let mut acc = [start; N];
    let top = lists.iter().map(|l| l.len()).max().unwrap_or(0);
    if lists.iter().all(|l| l.len() == top) {
        // The usual case (the five views of f share their degree): every
        // list at every row, with no test of its length.
        let lists = lists.map(|l| &l[..top]);
        for i in (skip..top).rev() {
            for (a, list) in acc.iter_mut().zip(lists) {
                *a = step(*a, i, &list[i]);
            }
        }
        return acc;
    }
    for i in (skip..top).rev() {
        for (a, list) in acc.iter_mut().zip(lists) {
            if let Some(c) = list.get(i) {
                *a = step(*a, i, c);
            }
        }
    }
    acc
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// The enclosure of `p⁽ʳ⁾` as it was before the derived coefficients
    /// were kept: each `cᵢ·i(i−1)…` formed inside the Horner pass.
    fn reference(p: &ScaledPoly, order: usize, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        for (i, c) in p.coeffs.iter().enumerate().skip(order).rev() {
            let factor: usize = (i + 1 - order..=i).product();
            acc = acc * x + *c * Interval::point(factor as f64);
        }
        acc
    }

    /// Interval Horner on one polynomial, step by step: what
    /// [`ScaledPoly::enclose`] was before the lockstep.
    fn horner(p: &ScaledPoly, x: Interval) -> Interval {
        p.coeffs
            .iter()
            .rev()
            .fold(Interval::point(0.0), |acc, c| acc * x + *c)
    }

    fn bits(iv: Interval) -> (u64, u64) {
        (iv.lo.to_bits(), iv.hi.to_bits())
    }

    /// A pass that overflows takes the fallback, and gives the checked
    /// pass's bits: lists of one length (`lockstep`'s fast branch) whose
    /// unchecked pass ends non-finite.
    #[test]
    fn overflowing_passes_fall_back() {
        let p = ZPoly::new((1..8).map(|c| Int::from(c).shl(1000)).collect());
        let polys = [0, 1, 2].map(|_| ScaledPoly::with_shift(&p, 0));
        let each = [&polys[0], &polys[1], &polys[2]];
        let x = Interval::new(0.0, 1e50);
        let unchecked = polys[0]
            .coeffs
            .iter()
            .rev()
            .fold(Interval::point(0.0), |acc, c| {
                acc.mul_add_nonneg_unchecked(x, *c)
            });
        assert!(!unchecked.is_finite());
        let values = ScaledPoly::enclose_each(each, x);
        let (d1, d2) = ScaledPoly::enclose_derivatives_each(each, x)[0];
        assert_eq!(bits(values[0]), bits(horner(&polys[0], x)));
        assert_eq!(bits(d1), bits(reference(&polys[0], 1, x)));
        assert_eq!(bits(d2), bits(reference(&polys[0], 2, x)));
    }

    proptest! {
        /// The derivatives from the kept products, alone or both in one
        /// pass, are the reference's bit for bit (long coefficients, so
        /// that the scaled ones are inexact, over intervals of either sign).
        #[test]
        fn derivatives_are_the_reference(
            raw in proptest::collection::vec(any::<i64>(), 0..12),
            wide in 0u64..700, lo in -4.0f64..4.0, w in 0.0f64..1.0,
        ) {
            let p = ZPoly::new(raw.iter().map(|&c| Int::from(c).shl(wide) + Int::from(c)).collect());
            let sp = ScaledPoly::new(&p);
            let x = Interval::new(lo, lo + w);
            for order in 1..=3 {
                prop_assert_eq!(bits(sp.enclose_derivative(order, x)), bits(reference(&sp, order, x)));
            }
            let (d1, d2) = sp.enclose_derivatives(x);
            prop_assert_eq!(bits(d1), bits(reference(&sp, 1, x)));
            prop_assert_eq!(bits(d2), bits(reference(&sp, 2, x)));
        }

        /// The enclosures over `x ≥ 0` are the checked passes' bit for
        /// bit, also where a step overflows (the unchecked pass ends
        /// non-finite and is redone with the tests): coefficients scaled up
        /// to about `2^1062`, so some are infinite, `x` up to `10^12`, zero,
        /// or unbounded (which the unchecked pass leaves to the checked
        /// one).
        #[test]
        fn unchecked_passes_are_the_checked_ones(
            raw in proptest::collection::vec(proptest::collection::vec(any::<i64>(), 0..15), 3),
            up in 0i64..400,
            lo in prop_oneof![Just(0.0), Just(-0.0), 0.0f64..4.0, 1.0f64..1e12],
            w in prop_oneof![Just(0.0), Just(f64::INFINITY), 0.0f64..1e3],
        ) {
            let polys: Vec<ScaledPoly> = raw
                .iter()
                .map(|r| ScaledPoly::with_shift(&ZPoly::new(r.iter().map(|&c| Int::from(c).shl(600)).collect()), -up))
                .collect();
            let each = [&polys[0], &polys[1], &polys[2]];
            let x = Interval::new(lo, lo + w);
            let (values, derivatives) = (ScaledPoly::enclose_each(each, x), ScaledPoly::enclose_derivatives_each(each, x));
            for (k, p) in polys.iter().enumerate() {
                let checked = p.coeffs.iter().rev().fold(Interval::point(0.0), |acc, c| acc.mul_fast(x) + *c);
                prop_assert_eq!(bits(values[k]), bits(checked));
                prop_assert_eq!(bits(values[k]), bits(horner(p, x)));
                prop_assert_eq!(bits(derivatives[k].0), bits(reference(p, 1, x)));
                prop_assert_eq!(bits(derivatives[k].1), bits(reference(p, 2, x)));
            }
        }

        /// Three polynomials of different lengths or of one (none, a
        /// constant, up to degree 13) in lockstep give each one's own
        /// values bit for bit:
        /// enclosures, derivatives (the first alone too) and the plain
        /// `f64` value and slope.
        #[test]
        fn lockstep_is_each_alone(
            mut raw in proptest::collection::vec(proptest::collection::vec(any::<i64>(), 0..15), 3),
            equal in any::<bool>(),
            wide in 0u64..700, lo in -4.0f64..4.0, w in 0.0f64..1.0,
        ) {
            if equal {
                // Lists of one length (the usual case, without length tests).
                let n = raw.iter().map(Vec::len).min().unwrap_or(0);
                raw.iter_mut().for_each(|r| r.truncate(n));
            }
            let polys: Vec<ScaledPoly> = raw
                .iter()
                .map(|r| ScaledPoly::new(&ZPoly::new(r.iter().map(|&c| Int::from(c).shl(wide) + Int::from(c)).collect())))
                .collect();
            let each = [&polys[0], &polys[1], &polys[2]];
            let x = Interval::new(lo, lo + w);
            let (values, derivatives) = (ScaledPoly::enclose_each(each, x), ScaledPoly::enclose_derivatives_each(each, x));
            let approx = ScaledPoly::value_and_slope_each(each, lo);
            let slopes = ScaledPoly::enclose_slopes_each(each, x);
            for (k, p) in polys.iter().enumerate() {
                prop_assert_eq!(bits(values[k]), bits(horner(p, x)));
                prop_assert_eq!(bits(derivatives[k].0), bits(reference(p, 1, x)));
                prop_assert_eq!(bits(slopes[k]), bits(derivatives[k].0));
                prop_assert_eq!(bits(derivatives[k].1), bits(reference(p, 2, x)));
                // The value and slope pass as it was, one polynomial alone.
                let (mut value, mut slope) = (0.0, 0.0);
                for &c in p.approx.iter().rev() {
                    slope = slope * lo + value;
                    value = value * lo + c;
                }
                prop_assert_eq!((approx[k].0.to_bits(), approx[k].1.to_bits()), (value.to_bits(), slope.to_bits()));
            }
        }
    }
}
