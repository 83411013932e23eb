//! Sign models: a quantity `q(t)` as [`RealRoot`](crate::RealRoot) needs
//! it, both as the function whose root it is and as a quantity whose sign
//! is asked for at a root ([`SignModel`]); [`SignProbe`], the model of an
//! explicit polynomial; [`ExactJet`], exact values at a dyadic point.

use crate::local::{Cost, Local};
use crate::scaled::ScaledPoly;
use ccd_arith::{BigInterval, Dual, DwBall, Int, Interval, Rat, RingOps};
use ccd_poly::{Residues, ZPoly};
use std::sync::{Arc, Mutex, OnceLock};

/// A polynomial `q` prepared for exact sign decisions at many roots
/// ([`RealRoot::sign_with`](crate::RealRoot::sign_with)): with its `f64` view (one conversion of every
/// coefficient), formed once; a caller that asks for the sign of the same
/// `q` at several roots should build it once. The roots themselves keep
/// their squarefree polynomial this way too, shared by every root one
/// isolation yields.
#[derive(Debug)]
pub struct SignProbe {
    q: ZPoly,
    sq: ScaledPoly,
    /// `q·2^(−shift)` in double-word balls (low → high), on first need.
    balls: OnceLock<Vec<DwBall>>,
    /// The size of an exact evaluation of `q`.
    cost: Cost,
    /// `q` re-centred next to the points of its costly exact evaluations
    /// ([`Local`]), on first need.
    local: OnceLock<Mutex<Recentred>>,
}

/// A clone starts without a re-centred model (a cache).
impl Clone for SignProbe {
    fn clone(&self) -> SignProbe {
        SignProbe {
            q: self.q.clone(),
            sq: self.sq.clone(),
            balls: self.balls.clone(),
            cost: self.cost,
            local: OnceLock::new(),
        }
    }
}

/// [`SignProbe`]'s re-centred model, the costly points it did not decide
/// since it was built, and those it did (for tests).
#[derive(Debug, Default)]
struct Recentred {
    model: Option<Arc<Local>>,
    misses: u32,
    hits: u64,
}

/// The costly points in a row that the re-centred model does not decide
/// (or that come before there is one) at which it is re-centred, at the
/// last of them: the first such point alone may be a stray, and a Taylor
/// shift costs several exact evaluations.
const LOCAL_MISSES: u32 = 2;

impl SignProbe {
    /// Prepares `q`.
    pub fn new(q: &ZPoly) -> SignProbe {
        SignProbe::of(q.clone())
    }

    fn of(q: ZPoly) -> SignProbe {
        SignProbe {
            sq: ScaledPoly::new(&q),
            cost: Cost::of(&q),
            q,
            balls: OnceLock::new(),
            local: OnceLock::new(),
        }
    }

    /// The balls of `q·2^(−shift)` (formed on first need); `None` for a
    /// short `q` (below [`BALL_WORTH`]), whose exact Horner pass costs
    /// less than the balls' bookkeeping.
    fn ball_coefficients(&self) -> Option<&[DwBall]> {
        let n = self.q.degree().unwrap_or(0) as u64;
        if (n + 1) * self.q.max_bits() < BALL_WORTH {
            return None;
        }
        Some(
            self.balls
                .get_or_init(|| ball_view(&self.q, self.sq.shift())),
        )
    }

    /// `read` on the re-centred model at a costly point `x`: the model kept,
    /// or, at the [`LOCAL_MISSES`]th costly point in a row it did not
    /// decide, a new one next to `x = a/2^k` ([`Local::near`]). `None` for
    /// a cheap or non-dyadic point, when there is no model yet, or when
    /// `read` does not decide. The lock is held only to read or
    /// replace the model, not while it is evaluated or built.
    fn recentred<T>(&self, x: &Rat, read: impl Fn(&Local) -> Option<T>) -> Option<T> {
        if !self.cost.costly(x) {
            return None;
        }
        let k = x.dyadic_exponent()?;
        let lock = || {
            let state = self.local.get_or_init(Mutex::default);
            state.lock().unwrap_or_else(|e| e.into_inner())
        };
        let model = lock().model.clone();
        if let Some(t) = model.as_deref().and_then(&read) {
            lock().hits += 1;
            return Some(t);
        }
        {
            let mut state = lock();
            state.misses += 1;
            if state.misses < LOCAL_MISSES {
                return None;
            }
            state.misses = 0;
        }
        let model = Arc::new(Local::near(&self.q, x, x, k)?);
        let t = read(&model);
        let mut state = lock();
        state.model = Some(model);
        state.hits += u64::from(t.is_some());
        t
    }

    /// How many costly points the re-centred model decided.
    #[cfg(test)]
    pub(crate) fn recentred_hits(&self) -> u64 {
        self.local
            .get()
            .and_then(|s| s.lock().ok())
            .map_or(0, |s| s.hits)
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

/// The size (coefficients times bits) from which an explicit polynomial's
/// jet is taken in balls first ([`SignProbe`]'s [`SignModel::ball_jet_at`]):
/// below it, one exact Horner pass is cheaper than the balls' bookkeeping
/// (Example 5.1's `sr11` squarefree part, of degree 4 with 10-bit
/// coefficients, size 50, is 1.8 % slower with balls). It was 4,096 until
/// a root stopped trying balls after one failed
/// ([`RealRoot`](crate::RealRoot)'s Newton steps): the `sr0 ≡ 0` branch's
/// `sr11` of the grazing stability scenes (sizes 966–1,296) then gains 2–4 %
/// from them, and where they fail (next to tight clusters) a root's Newton
/// steps pay for one failed attempt instead of one per step (its cut and
/// sign tests still try balls each time: one evaluation, no step).
pub const BALL_WORTH: u64 = 512;

/// `(p(x), p′(x))` by Horner's rule over balls (double-word, or any ring
/// of enclosures), for coefficients low → high (zero for none).
pub fn ball_horner<B: RingOps>(coeffs: &[B], x: &B) -> Dual<B> {
    let mut it = coeffs.iter().rev();
    let mut v = it.next().cloned().unwrap_or_else(B::zero);
    let mut d = B::zero();
    for c in it {
        d = d.times(x).plus(&v);
        v = v.times(x).plus(c);
    }
    Dual { v, d }
}

/// `p(x)` by Horner's rule over balls (or any ring of enclosures), for
/// coefficients low → high (zero for none): [`ball_horner`]'s value alone.
pub fn ball_value<B: RingOps>(coeffs: &[B], x: &B) -> B {
    let mut it = coeffs.iter().rev();
    let mut v = it.next().cloned().unwrap_or_else(B::zero);
    for c in it {
        v = v.times(x).plus(c);
    }
    v
}

/// The coefficients of `p·2^(−shift)` as balls (low → high).
pub fn ball_view(p: &ZPoly, shift: i64) -> Vec<DwBall> {
    p.coeffs()
        .iter()
        .map(|c| DwBall::from_int_scaled(c, shift))
        .collect()
}

/// Enclosures of `σ·q(m)` and `σ·q′(m)` at a dyadic point: the scale `σ`
/// of [`ExactJet`], so that `value` holds `ExactJet::value·2^(−value_exp)`
/// and `slope` holds `ExactJet::slope·2^(−slope_exp)`. In double-word
/// balls ([`SignModel::ball_jet_at`], the default `B`) or in
/// multi-precision intervals ([`SignModel::big_jet_at`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallJet<B = DwBall> {
    /// Encloses `σ·q(m)`.
    pub value: B,
    /// Encloses `σ·q′(m)`.
    pub slope: B,
    /// [`ExactJet::value_exp`]: `σ·q(m)·2^value_exp` is an integer.
    pub value_exp: i64,
    /// [`ExactJet::slope_exp`]: `σ·q′(m)·2^slope_exp` is an integer (these
    /// let [`RealRoot`](crate::RealRoot) tell when the ball pins down the
    /// exact jet's `f64` enclosures).
    pub slope_exp: i64,
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
    /// `σ·q(m)` and `σ·q′(m)` in double-word balls, for a dyadic `m`:
    /// what [`RealRoot`](crate::RealRoot) tries before
    /// [`SignModel::exact_jet_at`], which it needs only when these do not
    /// decide. `None` (the default) when the model has no such view.
    fn ball_jet_at(&self, _m: &Rat) -> Option<BallJet> {
        None
    }
    /// A cheaper jet for a Newton step past the float resolution at the
    /// dyadic `m ∈ x`: `σ·q(m)` in a double-word ball, as
    /// [`SignModel::ball_jet_at`]'s value, and the `f64` enclosure of
    /// `σ·q′` over the whole interval `x`, which holds `σ·q′(m)` and, by
    /// the mean value theorem, signs `q(c) ∈ q(m) + q′(x)·(c − m)` at
    /// every `c ∈ x` with no evaluation there. The caller guarantees
    /// `m ∈ x`: the mean value form rests on it. Exponents as
    /// [`SignModel::ball_jet_at`]'s. `None` (the default) when the model
    /// has no such view, or its slope is not cheaper than the jet's.
    fn ball_value_and_slope_over(&self, _m: &Rat, _x: Interval) -> Option<BallJet> {
        None
    }
    /// The sign of `q(x)` at a dyadic `x` when a double-word ball of it
    /// excludes zero; `None` otherwise. The default reads the value of
    /// [`SignModel::ball_jet_at`].
    fn ball_sign_at(&self, x: &Rat) -> Option<i32> {
        self.ball_jet_at(x)
            .and_then(|jet| jet.value.sign())
            .filter(|s| *s != 0)
    }
    /// `σ·q(m)` and `σ·q′(m)` in multi-precision intervals of about `prec`
    /// bits or more, for a dyadic `m`: what [`RealRoot`](crate::RealRoot)
    /// tries when the double-word balls do not decide (values out of
    /// `f64`'s range, or cancelling below its 106 bits) and before the
    /// exact jet. `None` (the default) when the model has no such view or
    /// it would cost about as much as the exact jet.
    fn big_jet_at(&self, _m: &Rat, _prec: u32) -> Option<BallJet<BigInterval>> {
        None
    }
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
    /// A positive integer `L` that the denominator of every rational root
    /// of `q` (in lowest terms) divides: `|lc(q)|` by the rational root
    /// theorem. `None` (the default, always safe) when unknown cheaply.
    fn root_denominators(&self) -> Option<Int> {
        None
    }
    /// A lower bound on the bits of [`SignModel::root_denominators`]' `L`
    /// when `L ≠ 0`, where it costs less than `L`: enough for
    /// [`RealRoot`](crate::RealRoot)'s early answer that an integer lies
    /// inside `(lo·L, hi·L)`. `None` (the default, always safe): `L`
    /// itself is read.
    fn root_denominator_bits(&self) -> Option<u64> {
        None
    }
    /// `q` exactly.
    fn exact(&self) -> &ZPoly;
    /// `q` modulo the fixed word prime of [`Residues`], and whether its
    /// degree is proven to be `q`'s (the prime does not divide `lc(q)`).
    /// The default reduces [`SignModel::exact`]; a model that has `q` as a
    /// function of other polynomials may form the image from theirs, so
    /// that a coprimality proof ([`Residues::proves_coprime`]) needs no `q`.
    fn residues(&self) -> (Residues, bool) {
        Residues::image(self.exact())
    }
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
    fn ball_jet_at(&self, m: &Rat) -> Option<BallJet> {
        (**self).ball_jet_at(m)
    }
    fn ball_sign_at(&self, x: &Rat) -> Option<i32> {
        (**self).ball_sign_at(x)
    }
    fn big_jet_at(&self, m: &Rat, prec: u32) -> Option<BallJet<BigInterval>> {
        (**self).big_jet_at(m, prec)
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
    fn root_denominators(&self) -> Option<Int> {
        (**self).root_denominators()
    }
    fn root_denominator_bits(&self) -> Option<u64> {
        (**self).root_denominator_bits()
    }
    fn exact(&self) -> &ZPoly {
        (**self).exact()
    }
    fn residues(&self) -> (Residues, bool) {
        (**self).residues()
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
    /// Horner over the balls of `q·2^(−shift)` at an exact ball of `m`;
    /// `None` for a short `q` (below [`BALL_WORTH`]).
    fn ball_jet_at(&self, m: &Rat) -> Option<BallJet> {
        let balls = self.ball_coefficients()?;
        let n = self.q.degree().unwrap_or(0) as i64;
        let k = m.dyadic_exponent()? as i64;
        let x = DwBall::exactly(m)?;
        let shift = self.sq.shift();
        let jet = ball_horner(balls, &x);
        (jet.v.is_known() && jet.d.is_known()).then_some(BallJet {
            value: jet.v,
            slope: jet.d,
            value_exp: shift + k * n,
            slope_exp: shift + k * (n - 1).max(0),
        })
    }
    /// Horner over the same balls, the value alone.
    fn ball_sign_at(&self, x: &Rat) -> Option<i32> {
        let balls = self.ball_coefficients()?;
        ball_value(balls, &DwBall::exactly(x)?)
            .sign()
            .filter(|s| *s != 0)
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
    /// On the re-centred model first when the exact evaluation is costly
    /// ([`LOCAL_WORTH`](crate::LOCAL_WORTH)) and the model decides; exactly otherwise.
    fn sign_at(&self, x: &Rat) -> i32 {
        self.recentred(x, |l| l.sign(x, self.cost.sign_ladder(x)))
            .unwrap_or_else(|| self.q.sign_at(x))
    }
    /// From the re-centred model, for a costly point ([`LOCAL_WORTH`](crate::LOCAL_WORTH)),
    /// at `prec` bits or, while its value holds zero (a step it could not
    /// pin down), at four times as many, up to the ladder's cap (an eighth
    /// of the exact pass's numbers' bits); `None` otherwise, and for a
    /// `prec` past the cap, where the exact jet costs less.
    fn big_jet_at(&self, m: &Rat, prec: u32) -> Option<BallJet<BigInterval>> {
        let k = m.dyadic_exponent()? as i64;
        let mut precisions = self.cost.ladder(m, prec).peekable();
        precisions.peek().filter(|&&first| first == prec)?;
        let (value, slope) = self.recentred(m, |l| {
            precisions
                .clone()
                .map(|p| l.jet(m, p))
                .find(|(v, _)| !v.contains_zero())
        })?;
        let n = self.q.degree().unwrap_or(0) as i64;
        let shift = self.sq.shift();
        Some(BallJet {
            value: value.mul_pow2(-shift),
            slope: slope.mul_pow2(-shift),
            value_exp: shift + k * n,
            slope_exp: shift + k * (n - 1).max(0),
        })
    }
    fn admits_root_at(&self, x: &Rat) -> bool {
        self.q.admits_rational_root(x)
    }
    fn root_denominators(&self) -> Option<Int> {
        self.q.leading().map(Int::abs)
    }
    fn exact(&self) -> &ZPoly {
        &self.q
    }
}
