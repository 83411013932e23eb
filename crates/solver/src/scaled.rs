//! Floating-point views of an exact integer polynomial: interval
//! coefficients for certified enclosures, plain `f64` for Newton guesses.
//! Both are scaled by one power of two so huge coefficients fit.

use ccd_arith::{Int, Interval};
use ccd_poly::ZPoly;

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
        }
    }

    /// The power of two the coefficients were scaled by.
    pub fn shift(&self) -> i64 {
        self.shift
    }

    /// A certified enclosure of `{ p(x)·2^(-shift) : x ∈ X }` (interval Horner).
    pub fn enclose(&self, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        for c in self.coeffs.iter().rev() {
            acc = acc * x + *c;
        }
        acc
    }

    /// A certified enclosure of `{ p⁽ʳ⁾(x)·2^(-shift) : x ∈ X }` for
    /// `r = order ≥ 1`, from the interval coefficients
    /// (`Σ i(i−1)…(i−r+1)·cᵢ·X^(i−r)`, interval Horner; the falling
    /// factorials are exact in `f64` for the degrees here), with no exact
    /// derivative.
    pub fn enclose_derivative(&self, order: usize, x: Interval) -> Interval {
        let mut acc = Interval::point(0.0);
        for (i, c) in self.coeffs.iter().enumerate().skip(order).rev() {
            let factor: usize = (i + 1 - order..=i).product();
            acc = acc * x + *c * Interval::point(factor as f64);
        }
        acc
    }

    /// `(p(x), p'(x))` approximately, scaled.
    pub fn value_and_slope(&self, x: f64) -> (f64, f64) {
        let mut v = 0.0;
        let mut d = 0.0;
        for &c in self.approx.iter().rev() {
            d = d * x + v;
            v = v * x + c;
        }
        (v, d)
    }
}
