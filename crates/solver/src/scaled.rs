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
        ScaledPoly::with_shift(p, (p.max_bits() as i64 - TARGET_BITS).max(0))
    }

    /// `p · 2^(-shift)` for a given shift (to compare with another scaled
    /// polynomial, e.g. a derivative).
    pub(crate) fn with_shift(p: &ZPoly, shift: i64) -> ScaledPoly {
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
