//! Algorithm 1 of the paper (Section 5) in `f64`: the structure of the exact
//! path (`ccd_exact`'s `algorithm::run`) with every sign read from floats.

use crate::approx::Approx;
use crate::bernstein::BernsteinF64;
use crate::roots::Roots;
use crate::setup::{prepare, Prepared};
use ccd_arith::Rat;
use ccd_classify::{classify_with, sign_variations, Configuration};
use ccd_motion::CharPoly;
use ccd_subres::{closed_forms, Quantity};
use ccd_timeline::{Findings, Instant, Outcome, State, Stats};

/// What a float query asks for.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Options {
    /// Stop at the earliest instant at which the bodies are not separate
    /// (later roots of the candidate polynomial are never looked for).
    pub first_contact_only: bool,
}

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
/// ([`Approx::sign`]), which also absorbs the error of evaluating at a root
/// known only to its bracket.
pub const TOL_SIGN: f64 = 1e-10;

/// Why a lazy Theorem 3.10 decision stopped: it needed `Var`, which is read
/// only on the way to "separate", so the instant is not a touch.
struct NotTouch;

/// Theorem 3.10 at `u`, with the signs of `f`'s coefficients and of the
/// closed forms evaluated in `f64` there; `zero` lists quantities known to
/// vanish at `u` (identically, or because `u` is a root of them), whose
/// float values are noise. With `var = false` the decision stops (as not a
/// touch) where it would need the sign variations.
fn configuration_at(
    p: &Prepared,
    u: f64,
    zero: &[Quantity],
    tol: f64,
    var: bool,
) -> Result<Configuration, NotTouch> {
    let fu: [Approx; 5] = p.f_at(u);
    let inv = closed_forms(&fu);
    classify_with(|q| {
        if zero.contains(&q) {
            return Ok(0);
        }
        match q {
            Quantity::Var if var => Ok(sign_variations(&fu.map(|c| c.sign(tol))) as i32),
            Quantity::Var => Err(NotTouch),
            other => Ok(inv.get(other).map_or(0, |x| x.sign(tol))),
        }
    })
}

/// The configuration at `u` (Theorem 3.10), `identically` listing the
/// quantities known to vanish on the whole span.
fn state_at(p: &Prepared, u: f64, identically: &[Quantity], tol: f64) -> State {
    match configuration_at(p, u, identically, tol, true) {
        Ok(c) => State::from(c),
        Err(NotTouch) => unreachable!("Var is allowed"),
    }
}

/// Is the configuration at the candidate `u` an external touch?
/// Theorem 3.10(2) with `zero` the quantities the candidate is a root of.
fn touches_at(p: &Prepared, u: f64, zero: &[Quantity]) -> bool {
    matches!(
        configuration_at(p, u, zero, TOL_SIGN, false),
        Ok(Configuration::ExternalTouch)
    )
}

/// The state on a piece between contacts (Theorem 5.1), at its sample
/// `u`. A piece between contacts cannot be a touch; if floats say so (a
/// value within [`TOL_SIGN`] of zero, e.g. next to a contact they missed),
/// the plain `f64` signs decide.
fn state_on(p: &Prepared, u: f64, identically: &[Quantity]) -> State {
    match state_at(p, u, identically, TOL_SIGN) {
        State::Touch => state_at(p, u, identically, 0.0),
        state => state,
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

/// Float Algorithm 1 on an exact characteristic polynomial: [`prepare`]
/// then [`solve_prepared`]. Not certified: every instant of the outcome has
/// `certified: false`.
///
/// ```
/// use ccd_arith::Rat;
/// use ccd_float::{solve, Options};
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
/// separately from the set-up [`prepare`]).
///
/// * `sr0 ≢ 0` (to [`TOL_IDENTICALLY_ZERO`]): the candidates are the roots
///   of `sr0` (Theorem 5.2);
/// * `sr0 ≡ 0`, `sr11 ≢ 0`: touching at one non-root δ of `sr11` means
///   touching throughout (Theorem 5.5), otherwise the candidates are the
///   roots of `sr11` (Theorem 5.4);
/// * `sr0 ≡ sr11 ≡ 0`: the state at `t0` holds throughout (Theorem 5.6).
///
/// Each candidate is kept when Theorem 3.10(2) says "touch" in `f64` at its
/// float estimate ([`TOL_SIGN`]); with `first_contact_only`, the walk stops
/// at the first kept one (and does not start when the bodies are not
/// separate at `t0`). The states between contacts are sampled (Theorem
/// 5.1). The outcome is laid out by the exact path's rules
/// ([`ccd_timeline::Findings::into_outcome`]); instants are the candidates'
/// float brackets converted exactly to rationals and mapped to `t`, and
/// every instant has `certified: false`.
pub fn solve_prepared(p: &Prepared, span: &[Rat; 2], options: &Options) -> Outcome {
    let first_only = options.first_contact_only;
    let sr0_zero = p.inv.sr0.is_negligible(TOL_IDENTICALLY_ZERO);
    let sr11_zero = sr0_zero && p.inv.sr11.is_negligible(TOL_IDENTICALLY_ZERO);
    let identically: &[Quantity] = match (sr0_zero, sr11_zero) {
        (false, _) => &[],
        (true, false) => &[Quantity::Sr0],
        (true, true) => &[Quantity::Sr0, Quantity::Sr11],
    };
    let mut stats = Stats {
        deg_f: p.deg_f,
        deg_sr0: (!sr0_zero).then(|| p.inv.sr0.degree()),
        ..Stats::default()
    };
    let state0 = state_at(p, 0.0, identically, TOL_SIGN);
    let stop_early = first_only && state0 != State::Separate;

    let mut throughout: Option<State> = None;
    let candidates: Option<(&BernsteinF64, &[Quantity])> = if !sr0_zero {
        stats.branch = "sr0";
        Some((&p.inv.sr0, &[Quantity::Sr0]))
    } else if !sr11_zero {
        stats.branch = "sr0=0, sr11";
        let delta = non_root_dyadic(&p.inv.sr11);
        if state_at(p, delta, identically, TOL_SIGN) == State::Touch {
            throughout = Some(State::Touch);
            None
        } else {
            Some((&p.inv.sr11, &[Quantity::Sr0, Quantity::Sr11]))
        }
    } else {
        stats.branch = "sr0=0, sr11=0";
        throughout = Some(state0);
        None
    };

    let mut found = Findings {
        state0,
        // Stopped at t0 (not separate there): the answer is t0 itself.
        throughout: throughout.filter(|_| !stop_early),
        contacts: Vec::new(),
        complete: !stop_early,
        certified: false,
    };
    if let (Some((poly, zeros)), false) = (candidates, stop_early) {
        stats.deg_candidates = Some(poly.degree());
        for c in Roots::new(poly, TOL_ROOT_NOISE) {
            stats.candidates += 1;
            if touches_at(p, c.estimate(), zeros) {
                found.contacts.push(Instant {
                    lo: rat(c.lo),
                    hi: rat(c.hi),
                    certified: false,
                });
                if first_only {
                    found.complete = false;
                    break;
                }
            }
        }
    }
    let laid_out = found.into_outcome(span, stats, |u| {
        Ok::<State, std::convert::Infallible>(state_on(p, u.to_f64(), identically))
    });
    match laid_out {
        Ok(out) => out,
        Err(never) => match never {},
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
        assert_eq!(out.stats.branch, "sr0=0, sr11");
        assert_eq!(out.stats.deg_sr0, None);
        let got: Vec<f64> = out.contacts.iter().map(|c| c.midpoint().to_f64()).collect();
        assert!((got[0] - 1.0 / 6.0).abs() < 1e-15 && (got[1] - 5.0 / 6.0).abs() < 1e-15);
        assert!(out.complete && !out.collision_free);

        let first = solve(
            &f,
            &unit(),
            &Options {
                first_contact_only: true,
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
        assert_eq!(out.stats.branch, "sr0=0, sr11=0");
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
