//! Sign models: a quantity `q(t)` as [`RealRoot`](crate::RealRoot) needs
//! it, both as the function whose root it is and as a quantity whose sign
//! is asked for at a root ([`SignModel`]); [`SignProbe`], the model of an
//! explicit polynomial; [`ExactJet`], exact values at a dyadic point.

use crate::scaled::ScaledPoly;
use ccd_arith::{Int, Interval, Rat};
use ccd_poly::ZPoly;
use std::sync::Arc;

/// A polynomial `q` prepared for exact sign decisions at many roots
/// ([`RealRoot::sign_with`](crate::RealRoot::sign_with)): with its `f64` view (one conversion of every
/// coefficient), formed once; a caller that asks for the sign of the same
/// `q` at several roots should build it once. The roots themselves keep
/// their squarefree polynomial this way too, shared by every root one
/// isolation yields.
#[derive(Clone, Debug)]
pub struct SignProbe {
    q: ZPoly,
    sq: ScaledPoly,
}

impl SignProbe {
    /// Prepares `q`.
    pub fn new(q: &ZPoly) -> SignProbe {
        SignProbe::of(q.clone())
    }

    fn of(q: ZPoly) -> SignProbe {
        SignProbe {
            sq: ScaledPoly::new(&q),
            q,
        }
    }

    /// A root family's polynomial.
    pub(crate) fn shared(q: ZPoly) -> Arc<SignProbe> {
        Arc::new(SignProbe::of(q))
    }
}

/// Exact values of `σ·q` and `σ·q′` at a dyadic point `m`, as integers
/// over powers of two: `σ·q(m) = value·2^(−value_exp)` and
/// `σ·q′(m) = slope·2^(−slope_exp)` ([`SignModel::exact_jet_at`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ExactJet {
    /// `σ·q(m)·2^value_exp`.
    pub value: Int,
    /// `σ·q′(m)·2^slope_exp`.
    pub slope: Int,
    /// The power of two under `value`.
    pub value_exp: i64,
    /// The power of two under `slope`.
    pub slope_exp: i64,
}

impl ExactJet {
    /// `(σ·q(m), σ·q′(m))` enclosed (one rounding each).
    pub fn enclose(&self) -> (Interval, Interval) {
        (
            Interval::from_int_scaled(&self.value, self.value_exp),
            Interval::from_int_scaled(&self.slope, self.slope_exp),
        )
    }
}

/// A quantity `q(t)` as [`RealRoot`](crate::RealRoot) needs it, both as the function whose
/// root it is (refinement) and as a quantity whose sign is asked for at a
/// root ([`RealRoot::sign_with`](crate::RealRoot::sign_with)): for a constant `σ > 0` of the model's
/// choosing, certified enclosures of `σ·q` and `σ·q″` over intervals,
/// exact values of `σ·q(m)` and `σ·q′(m)` at dyadic points, `f64` guesses
/// for Newton steps, the exact sign at a rational point, and `q` itself
/// for deciding `q(α) = 0` (which may be formed only when first asked
/// for).
///
/// [`SignProbe`] is the model of an explicit polynomial; a caller that has
/// `q` as a function of other polynomials (the closed forms of Section 4
/// of `f`'s coefficients) can supply the same from those, far more cheaply
/// than forming `q`.
pub trait SignModel {
    /// `σ·q(X)` enclosed.
    fn enclose(&self, x: Interval) -> Interval;
    /// `σ·q″(X)` enclosed.
    fn enclose_second(&self, x: Interval) -> Interval;
    /// `σ·q(m)` and `σ·q′(m)` exactly, for a dyadic `m`.
    fn exact_jet_at(&self, m: &Rat) -> ExactJet;
    /// `(σ·q(m), σ·q′(m))` enclosed, for a dyadic `m`.
    fn value_and_slope_at(&self, m: &Rat) -> (Interval, Interval) {
        self.exact_jet_at(m).enclose()
    }
    /// `(σ·q(x), σ·q′(x))` approximately (Newton guesses; no guarantee).
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64);
    /// The exact sign of `q(x)`.
    fn sign_at(&self, x: &Rat) -> i32;
    /// The sign of `q(x)` when the enclosure at `x` excludes zero.
    fn float_sign_at(&self, x: &Rat) -> Option<i32> {
        self.enclose(Interval::from_rat(x))
            .sign()
            .filter(|s| *s != 0)
    }
    /// The exact sign of `q(x)`: [`SignModel::float_sign_at`] when it
    /// decides, [`SignModel::sign_at`] otherwise.
    fn filtered_sign_at(&self, x: &Rat) -> i32 {
        self.float_sign_at(x).unwrap_or_else(|| self.sign_at(x))
    }
    /// `false` only if `q(x) ≠ 0` is certain from a cheap test (the
    /// rational root theorem); `true` is always a safe answer.
    fn admits_root_at(&self, _x: &Rat) -> bool {
        true
    }
    /// `q` exactly.
    fn exact(&self) -> &ZPoly;
}

impl<T: SignModel> SignModel for Arc<T> {
    fn enclose(&self, x: Interval) -> Interval {
        (**self).enclose(x)
    }
    fn enclose_second(&self, x: Interval) -> Interval {
        (**self).enclose_second(x)
    }
    fn exact_jet_at(&self, m: &Rat) -> ExactJet {
        (**self).exact_jet_at(m)
    }
    fn value_and_slope_at(&self, m: &Rat) -> (Interval, Interval) {
        (**self).value_and_slope_at(m)
    }
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64) {
        (**self).approx_value_and_slope(x)
    }
    fn sign_at(&self, x: &Rat) -> i32 {
        (**self).sign_at(x)
    }
    fn admits_root_at(&self, x: &Rat) -> bool {
        (**self).admits_root_at(x)
    }
    fn exact(&self) -> &ZPoly {
        (**self).exact()
    }
}

impl SignModel for SignProbe {
    fn enclose(&self, x: Interval) -> Interval {
        self.sq.enclose(x)
    }
    fn enclose_second(&self, x: Interval) -> Interval {
        self.sq.enclose_derivative(2, x)
    }
    /// `H = 2^(k·n)·q(m)` and `H′ = 2^(k·(n−1))·q′(m)` at `m = a/2^k` from
    /// one homogeneous Horner pass, on the `f64` view's scale.
    fn exact_jet_at(&self, m: &Rat) -> ExactJet {
        let k = m.dyadic_exponent().expect("a dyadic point") as i64;
        let (value, slope) = self.q.eval_homogeneous_with_derivative(m);
        let n = self.q.degree().unwrap_or(0) as i64;
        let shift = self.sq.shift();
        ExactJet {
            value,
            slope,
            value_exp: shift + k * n,
            slope_exp: shift + k * (n - 1).max(0),
        }
    }
    /// `q(m) = H/b^n` and `q′(m) = H′/b^(n−1)` for `m = a/b`, both exact
    /// from one Horner pass, then scaled like the `f64` view: by shifts at
    /// a dyadic `m` (the solver's case), by an enclosed division otherwise.
    fn value_and_slope_at(&self, m: &Rat) -> (Interval, Interval) {
        if m.dyadic_exponent().is_some() {
            return self.exact_jet_at(m).enclose();
        }
        let (qm, dqm) = self.q.eval_homogeneous_with_derivative(m);
        let n = self.q.degree().unwrap_or(0) as u32;
        let b = m.denom();
        let over = |h: &Int, e: u32| {
            Interval::from_int_scaled(h, self.sq.shift())
                .div_positive(Interval::from_int(&b.pow(e)))
        };
        (over(&qm, n), over(&dqm, n.saturating_sub(1)))
    }
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64) {
        self.sq.value_and_slope(x)
    }
    fn sign_at(&self, x: &Rat) -> i32 {
        self.q.sign_at(x)
    }
    fn admits_root_at(&self, x: &Rat) -> bool {
        self.q.admits_rational_root(x)
    }
    fn exact(&self) -> &ZPoly {
        &self.q
    }
}
