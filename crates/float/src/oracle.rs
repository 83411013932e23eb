//! The float arithmetic's answers to Algorithm 1 (`ccd-algorithm`): every
//! sign read from `f64` values of the closed forms, with tolerances.

use crate::roots::{Candidate, Roots};
use crate::setup::{prepare, Prepared};
use ccd_algorithm::{
    possible_with, At, Candidates, CcdError, Decided, Found, Options, Oracle, SignSet, Signs,
    Vanishing, VarSet,
};
use ccd_arith::Rat;
use ccd_classify::sign_variations;
use ccd_motion::{Body, CharPoly};
use ccd_poly::BernsteinF64;
use ccd_subres::{closed_forms, Quantity, QuarticInvariants};
use ccd_timeline::{Geometry, Instant, Outcome, Path, State, Stats};

/// Relative tolerance under which an `sr` polynomial counts as identically
/// zero: every Bernstein coefficient within `1e-10` of its magnitude
/// ([`BernsteinF64::is_negligible`]). This decides the branches of
/// Algorithm 1 (`sr0 ≡ 0`: Theorems 5.4–5.6), and it is exactly where floats
/// guess: the rounding noise of the closed forms is about `1e-13` of the
/// magnitude for degree 288, so an `sr0` that is not zero but cancels to
/// ten digits is taken for zero.
pub const TOL_IDENTICALLY_ZERO: f64 = 1e-10;

/// Relative tolerance under which the candidate polynomial's value at
/// `u = 0` or `u = 1` is snapped to zero (see [`crate::Roots`]), so that a
/// contact exactly at an end of the span is found there: about the
/// rounding level `n·ε` of the closed forms for `n` in the hundreds.
pub const TOL_ROOT_NOISE: f64 = 1e-13;

/// Relative tolerance under which a value of `sr22, sr20, sr11, sr10, sr0`
/// or of a coefficient of `f` at one instant counts as zero (Theorem 3.10
/// reads zero signs, e.g. `sr11 = 0` in case (2b)): `1e-10` of its magnitude
/// ([`ccd_arith::Approx::sign`]), which also absorbs the error of evaluating at a root
/// known only to its bracket.
pub const TOL_SIGN: f64 = 1e-10;

/// `f64` signs at `u`: the closed forms of `f`'s coefficients there, each
/// zero within `tol` of its magnitude; `identically` read as 0.
struct FloatSigns<'a> {
    inv: QuarticInvariants<ccd_arith::Approx>,
    f: [ccd_arith::Approx; 5],
    tol: f64,
    identically: &'a [Quantity],
}

impl<'a> FloatSigns<'a> {
    fn at(p: &Prepared, u: f64, tol: f64, identically: &'a [Quantity]) -> FloatSigns<'a> {
        let f = p.f_at(u);
        FloatSigns {
            inv: closed_forms(&f),
            f,
            tol,
            identically,
        }
    }
}

impl Signs for FloatSigns<'_> {
    fn sign(&mut self, q: Quantity) -> SignSet {
        if self.identically.contains(&q) {
            return SignSet::exactly(0);
        }
        SignSet::exactly(self.inv.get(q).map_or(0, |x| x.sign(self.tol)))
    }
    fn variations(&mut self) -> VarSet {
        VarSet::exactly(sign_variations(&self.f.map(|c| c.sign(self.tol))))
    }
}

/// The first of 1/2, 1/4, 3/4, 1/8, 3/8, … (down to 2^-12) at which `p` is
/// not zero to [`TOL_SIGN`]: the δ of Theorem 5.5.
fn non_root_dyadic(p: &BernsteinF64) -> f64 {
    (1..=12)
        .flat_map(|k| {
            (1..(1u32 << k))
                .step_by(2)
                .map(move |m| m as f64 / (1u32 << k) as f64)
        })
        .find(|&d| p.eval(d).sign(TOL_SIGN) != 0)
        .unwrap_or(0.5)
}

/// The exact value of a float in `[0, 1]` as a rational.
fn rat(u: f64) -> Rat {
    Rat::from_f64_exact(u).expect("a finite float")
}

/// The float arithmetic over a prepared `f(λ; u)`, in `u ∈ [0, 1]`.
/// Nothing it answers is certified.
pub struct Float<'p> {
    p: &'p Prepared,
    span: [Rat; 2],
    unit: [Rat; 2],
    /// The quantities that vanish identically to [`TOL_IDENTICALLY_ZERO`].
    identically: Vec<Quantity>,
    /// The bodies, for the contact point estimates.
    bodies: Option<(&'p Body, &'p Body)>,
}

impl<'p> Float<'p> {
    /// The float arithmetic of `p` on `span`; with `bodies`, contacts get
    /// `f64` estimates of their point and normal.
    pub fn new(
        p: &'p Prepared,
        span: &[Rat; 2],
        bodies: Option<(&'p Body, &'p Body)>,
    ) -> Float<'p> {
        let sr0_zero = p.inv.sr0.is_negligible(TOL_IDENTICALLY_ZERO);
        let sr11_zero = sr0_zero && p.inv.sr11.is_negligible(TOL_IDENTICALLY_ZERO);
        let identically = match (sr0_zero, sr11_zero) {
            (false, _) => vec![],
            (true, false) => vec![Quantity::Sr0],
            (true, true) => vec![Quantity::Sr0, Quantity::Sr11],
        };
        Float {
            p,
            span: span.clone(),
            unit: [Rat::zero(), Rat::one()],
            identically,
            bodies,
        }
    }
}

impl Oracle for Float<'_> {
    type Root = Candidate;
    const PATH: Path = Path::Float;
    const SAMPLE_AT_ENDS: bool = true;

    fn domain(&self) -> &[Rat; 2] {
        &self.unit
    }

    fn time(&self, u: &Rat) -> Rat {
        ccd_algorithm::time_on(&self.span, u)
    }

    /// Signs within [`TOL_SIGN`] of zero read as zero.
    fn signs<'a>(&'a self, at: At<'a, Candidate>, _level: usize) -> Box<dyn Signs + 'a> {
        let u = match at {
            At::Sample(x) => x.to_f64(),
            At::Root(c) => c.estimate(),
        };
        Box::new(FloatSigns::at(self.p, u, TOL_SIGN, &self.identically))
    }

    fn guess(&self, _u: &Rat) -> State {
        unreachable!("float signs are always single")
    }

    fn vanishes(&mut self, q: Quantity) -> Vanishing {
        if self.identically.contains(&q) {
            Vanishing::Identically
        } else if q == Quantity::Sr11 {
            Vanishing::Not(Some(rat(non_root_dyadic(&self.p.inv.sr11))))
        } else {
            Vanishing::Not(None)
        }
    }

    fn candidates(&self, q: Quantity, attempt: usize) -> Option<Candidates<'_, Candidate>> {
        let poly = match (q, attempt) {
            (Quantity::Sr0, 0) => &self.p.inv.sr0,
            (Quantity::Sr11, 0) => &self.p.inv.sr11,
            _ => return None,
        };
        Some(Candidates {
            degree: Some(poly.degree()),
            roots: Box::new(Roots::new(poly, TOL_ROOT_NOISE).map(Found::Root)),
        })
    }

    fn ends(&self, c: &Candidate) -> (Rat, Rat) {
        (rat(c.lo), rat(c.hi))
    }

    /// The float bracket as it stands (already at `f64` resolution).
    fn refine(&self, c: &mut Candidate, _q: Quantity) -> Instant {
        let (lo, hi) = self.ends(c);
        Instant {
            lo,
            hi,
            certified: false,
        }
    }

    /// An `f64` estimate at the contact's midpoint (case (2b) for the roots
    /// of `sr11`).
    fn geometry(&self, _c: &mut Candidate, zeros: &[Quantity], instant: &Instant) -> Geometry {
        self.geometry_at(&instant.midpoint(), zeros)
    }

    /// An `f64` estimate at `u` (case (2b) where `sr11` vanishes
    /// identically).
    fn geometry_at(&self, u: &Rat, zeros: &[Quantity]) -> Geometry {
        let Some((a, b)) = self.bodies else {
            return Geometry::Unknown {
                reason: "no bodies given".into(),
            };
        };
        let t = self.time(u);
        ccd_contact::estimate(a, b, &self.span, &t, zeros.contains(&Quantity::Sr11))
    }

    /// A piece between contacts cannot be a touch; if floats say so (a
    /// value within [`TOL_SIGN`] of zero, e.g. next to a contact they
    /// missed), the plain `f64` signs decide.
    fn touch_between_contacts(&self, u: &Rat, d: Decided) -> Result<Decided, CcdError> {
        let mut plain = FloatSigns::at(self.p, u.to_f64(), 0.0, &self.identically);
        Ok(possible_with(&mut plain, &[], false)
            .single()
            .map_or(d, |c| Decided {
                state: State::from(c),
                certified: true,
            }))
    }

    fn stats(&self, stats: &mut Stats) {
        stats.deg_f = self.p.deg_f;
        stats.deg_sr0 =
            (!self.identically.contains(&Quantity::Sr0)).then(|| self.p.inv.sr0.degree());
    }
}

/// Float Algorithm 1 on an exact characteristic polynomial: [`prepare`]
/// then [`solve_prepared`]. Not certified: every instant of the outcome has
/// `certified: false`.
///
/// ```
/// use ccd_algorithm::Options;
/// use ccd_arith::Rat;
/// use ccd_float::solve;
/// use ccd_motion::CharPoly;
/// use ccd_poly::ZPoly;
/// use ccd_timeline::State;
/// // Example 5.1 (Section 5.2): f = λ⁴ + a λ³ + b λ² + a λ + 1.
/// let a = ZPoly::from_i64s(&[-32, 96, -68]);
/// let f = CharPoly { coeffs: [
///     ZPoly::from_i64s(&[1]), a.clone(), ZPoly::from_i64s(&[-66, 192, -136]), a,
///     ZPoly::from_i64s(&[1]),
/// ] };
/// let out = solve(&f, &[Rat::zero(), Rat::one()], &Options::default());
/// let states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
/// assert_eq!(states, [State::Separate, State::Touch, State::Overlap, State::Touch, State::Separate]);
/// assert!((out.contacts[0].midpoint().to_f64() - 0.5395042868).abs() < 1e-10);
/// assert!(!out.contacts[0].certified);
/// ```
pub fn solve(f: &CharPoly, span: &[Rat; 2], options: &Options) -> Outcome {
    solve_prepared(&prepare(f), span, options)
}

/// Float Algorithm 1 on a prepared `f(λ; u)` (the solve stage, timed
/// separately from the set-up [`prepare`]), without contact geometry: the
/// generic `ccd_algorithm::run` over [`Float`]. Not certified: every
/// instant has `certified: false`.
pub fn solve_prepared(p: &Prepared, span: &[Rat; 2], options: &Options) -> Outcome {
    let options = Options {
        contact_geometry: false,
        ..options.clone()
    };
    match ccd_algorithm::run(Float::new(p, span, None), &options) {
        Ok(out) => out,
        Err(e) => unreachable!("the float arithmetic raises no error: {e}"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_poly::ZPoly;
    use State::{Overlap, Separate, Touch};

    /// Two unit spheres `d(u)` apart (`d²` given):
    /// `f = −(λ + 1)²(λ² + mλ + 1)`, `m = 2 − d²` (Note 2: `sr0 ≡ 0`).
    fn spheres(d2: &[i64]) -> CharPoly {
        let k = |v: i64| ZPoly::from_i64s(&[v]);
        let m = &k(2) - &ZPoly::from_i64s(d2);
        let c3 = -(&m + &k(2));
        CharPoly {
            coeffs: [k(-1), c3.clone(), -(&(&k(2) * &m) + &k(2)), c3, k(-1)],
        }
    }

    fn unit() -> [Rat; 2] {
        [Rat::zero(), Rat::one()]
    }

    fn states(out: &Outcome) -> Vec<State> {
        out.timeline.iter().map(|s| s.state).collect()
    }

    #[test]
    fn passing_through_and_first_contact_only() {
        // d = 3 − 6u: touch at 1/6, overlap, touch at 5/6.
        let f = spheres(&[9, -36, 36]);
        let out = solve(&f, &unit(), &Options::default());
        assert_eq!(states(&out), [Separate, Touch, Overlap, Touch, Separate]);
        assert_eq!(out.stats.branch, Some(ccd_timeline::Branch::Sr11));
        assert_eq!(out.stats.deg_sr0, None);
        let got: Vec<f64> = out.contacts.iter().map(|c| c.midpoint().to_f64()).collect();
        assert!((got[0] - 1.0 / 6.0).abs() < 1e-15 && (got[1] - 5.0 / 6.0).abs() < 1e-15);
        assert!(out.complete && !out.collision_free);

        let first = solve(
            &f,
            &unit(),
            &Options {
                first_contact_only: true,
                ..Options::default()
            },
        );
        assert_eq!(states(&first), [Separate, Touch]);
        assert_eq!(first.contacts.len(), 1);
        assert!(first.stats.candidates < out.stats.candidates);
        assert!(!first.complete && !first.collision_free);
        assert_eq!(first.first_contact, Some(out.contacts[0].clone()));
    }

    #[test]
    fn touching_throughout_is_theorem_5_6() {
        let out = solve(&spheres(&[4]), &unit(), &Options::default());
        assert_eq!(out.stats.branch, Some(ccd_timeline::Branch::Throughout));
        assert_eq!(states(&out), [Touch]);
        assert_eq!(
            out.first_contact.as_ref().map(|i| i.lo.clone()),
            Some(Rat::zero())
        );
        assert!(out
            .timeline
            .iter()
            .all(|s| !s.start.certified && !s.end.certified));
    }

    #[test]
    fn contact_at_the_start_is_found_exactly_there() {
        // d = 2 + 2u: touching at u = 0, then apart.
        let out = solve(&spheres(&[4, 8, 4]), &unit(), &Options::default());
        assert_eq!(states(&out), [Touch, Separate]);
        assert_eq!(
            (&out.contacts[0].lo, &out.contacts[0].hi),
            (&Rat::zero(), &Rat::zero())
        );
        let first = solve(
            &spheres(&[4, 8, 4]),
            &unit(),
            &Options {
                first_contact_only: true,
                ..Options::default()
            },
        );
        assert_eq!(states(&first), [Touch]);
        assert!(!first.complete);
    }

    #[test]
    fn instants_are_mapped_to_the_span() {
        // d = 3 − 2u touches at u = 1/2, i.e. t = 2 + 4·(1/2) = 4 on [2, 6].
        let span = [Rat::from(2), Rat::from(6)];
        let out = solve(&spheres(&[9, -12, 4]), &span, &Options::default());
        assert_eq!(states(&out), [Separate, Touch, Overlap]);
        assert!((out.contacts[0].midpoint().to_f64() - 4.0).abs() < 1e-14);
        assert_eq!(out.timeline.last().unwrap().end.hi, Rat::from(6));
        assert_eq!(out.span, span);
    }
}
