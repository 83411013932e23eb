//! Floating-point views of an exact integer polynomial: interval
//! coefficients for certified enclosures, plain `f64` for Newton guesses.
//! Both are scaled by one power of two so huge coefficients fit.

use ccd_arith::{Int, Interval};
use ccd_poly::ZPoly;

/// Bit length kept for the largest coefficient after scaling.
const TARGET_BITS: i64 = 600;

/// `p · 2^(-shift)` with interval coefficients (low → high).
#[derive(Clone, Debug)]
pub(crate) struct ScaledPoly {
    coeffs: Vec<Interval>,
    approx: Vec<f64>,
    shift: i64,
}

impl ScaledPoly {
    pub(crate) fn new(p: &ZPoly) -> ScaledPoly {
        let shift = (p.max_bits() as i64 - TARGET_BITS).max(0);
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
        }
    }

    /// The power of two the coefficients were scaled by.
    pub(crate) fn shift(&self) -> i64 {
        self.shift
    }

    /// A certified enclosure of `{ p(x)·2^(-shift) : x ∈ X }` (interval Horner).
    pub(crate) fn enclose(&self, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        for c in self.coeffs.iter().rev() {
            acc = acc * x + *c;
        }
        acc
    }

    /// A certified enclosure of `{ p″(x)·2^(-shift) : x ∈ X }`, from the
    /// interval coefficients (`Σ i(i−1)·cᵢ·X^(i−2)`, interval Horner; the
    /// factors `i(i−1)` are exact in `f64`), with no exact derivative.
    pub(crate) fn enclose_second_derivative(&self, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        for (i, c) in self.coeffs.iter().enumerate().skip(2).rev() {
            acc = acc * x + *c * Interval::point((i * (i - 1)) as f64);
        }
        acc
    }

    /// `(p(x), p'(x))` approximately, scaled.
    pub(crate) fn value_and_slope(&self, x: f64) -> (f64, f64) {
        let mut v = 0.0;
        let mut d = 0.0;
        for &c in self.approx.iter().rev() {
            d = d * x + v;
            v = v * x + c;
        }
        (v, d)
    }
}
