//! [`Approx`]: an `f64` value carried with a bound on the magnitude of the
//! terms that produced it, so that "is this zero?" can be asked relative to
//! the rounding noise of the computation rather than to an absolute scale.

use crate::RingOps;

/// An `f64` value with a running magnitude: `magnitude` is what the same
/// computation gives on the absolute values of its inputs with every `−`
/// replaced by `+`. The rounding error of `value` is at most a small multiple
/// (the number of operations along the way) of `f64::EPSILON · magnitude`,
/// which is what [`Approx::sign`] compares against.
///
/// ```
/// use ccd_arith::RingOps;
/// use ccd_arith::Approx;
/// let x = Approx::from_f64(1e4);
/// let y = x.times(&x).minus(&x.times(&x).plus(&Approx::from_f64(1e-3)));
/// // y ≈ −1e-3 against terms of size 1e8: a sign at relative tolerance 1e-14 …
/// assert_eq!(y.sign(1e-14), -1);
/// // … but zero at relative tolerance 1e-10.
/// assert_eq!(y.sign(1e-10), 0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Approx {
    /// The computed value.
    pub value: f64,
    /// The magnitude bound (≥ 0).
    pub magnitude: f64,
}

impl Approx {
    /// An input known to full `f64` precision.
    pub fn from_f64(v: f64) -> Approx {
        Approx {
            value: v,
            magnitude: v.abs(),
        }
    }

    /// The sign of the value, `0` when `|value| <= tol · magnitude` (the
    /// value is indistinguishable from rounding noise at relative tolerance
    /// `tol`). With `tol = 0` this is the plain sign of the `f64`.
    pub fn sign(&self, tol: f64) -> i32 {
        if self.value.abs() <= tol * self.magnitude || self.value.is_nan() {
            0
        } else if self.value > 0.0 {
            1
        } else {
            -1
        }
    }
}

impl RingOps for Approx {
    fn zero() -> Self {
        Approx::from_f64(0.0)
    }
    fn one() -> Self {
        Approx::from_f64(1.0)
    }
    fn from_i64(v: i64) -> Self {
        Approx::from_f64(v as f64)
    }
    fn is_zero(&self) -> bool {
        self.value == 0.0 && self.magnitude == 0.0
    }
    fn plus(&self, o: &Self) -> Self {
        Approx {
            value: self.value + o.value,
            magnitude: self.magnitude + o.magnitude,
        }
    }
    fn minus(&self, o: &Self) -> Self {
        Approx {
            value: self.value - o.value,
            magnitude: self.magnitude + o.magnitude,
        }
    }
    fn times(&self, o: &Self) -> Self {
        Approx {
            value: self.value * o.value,
            magnitude: self.magnitude * o.magnitude,
        }
    }
    fn negated(&self) -> Self {
        Approx {
            value: -self.value,
            magnitude: self.magnitude,
        }
    }
    fn div_small(&self, k: i64) -> Self {
        Approx {
            value: self.value / k as f64,
            magnitude: self.magnitude / (k as f64).abs(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn magnitudes_follow_absolute_values() {
        let a = Approx::from_f64(-3.0);
        let b = Approx::from_f64(2.0);
        let c = a.times(&b).plus(&b).negated().div_small(-2);
        assert_eq!(c.value, -2.0);
        assert_eq!(c.magnitude, 4.0);
        assert_eq!(Approx::zero().sign(0.0), 0);
        assert!(Approx::zero().is_zero());
        assert_eq!(Approx::from_i64(-5).sign(0.1), -1);
    }
}
