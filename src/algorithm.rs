//! Algorithm 1 of the paper (Section 5) on the exact path: every contact
//! instant isolated with exact rational bounds and every state decided by
//! exact signs.

use crate::CcdError;
use ccd_arith::Rat;
use ccd_motion::{placed_quadric, CharPoly};
use ccd_poly::ZPoly;
use ccd_quadric::classify_quartic;
use ccd_scene::Scene;
use ccd_solver::RealRoot;
use ccd_subres::{classify_with, closed_forms, Configuration, Quantity, QuarticInvariants};
use ccd_timeline::{Instant, Outcome, Segment, State, Stats};

/// What a query asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Enclosures of contact instants get `hi − lo <= 10^(−digits)·(t1 − t0)`.
    pub digits: u32,
    /// Stop at the earliest instant at which the bodies are not separate.
    pub first_contact_only: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            digits: 15,
            first_contact_only: false,
        }
    }
}

impl Options {
    /// Largest `digits` accepted (refinement cost grows with it).
    pub const MAX_DIGITS: u32 = 1000;
}

/// The configuration at a rational parameter `u`, exactly (Theorem 3.10).
fn state_at(f: &CharPoly, u: &Rat) -> State {
    State::from(classify_quartic(&f.at_scaled(u), ccd_arith::Int::signum))
}

/// The sr polynomials of `f(λ; u)` (Section 4 closed forms over ℤ[u]).
fn invariants(f: &CharPoly) -> QuarticInvariants<ZPoly> {
    closed_forms(&f.coeffs)
}

/// Is the configuration at the algebraic instant `root` an external touch?
/// Theorem 3.10(2), with the signs decided exactly at the root; `zero` lists
/// quantities known to vanish there (the polynomial the root came from).
fn touches_at(root: &mut RealRoot, inv: &QuarticInvariants<ZPoly>, zero: &[Quantity]) -> bool {
    struct NotTouch;
    let answer = classify_with(|q| {
        if zero.contains(&q) {
            return Ok(0);
        }
        match q {
            // Var is read only on the way to "separate": not a touch.
            Quantity::Var => Err(NotTouch),
            other => Ok(inv.get(other).map_or(0, |p| root.sign_of(p))),
        }
    });
    matches!(answer, Ok(Configuration::ExternalTouch))
}

/// A simple rational strictly inside `(lo, hi)`, or `lo`/`hi` themselves
/// where they may be taken (`*_incl`): the sample for a piece of the span.
fn sample_between(lo: &Rat, lo_incl: bool, hi: &Rat, hi_incl: bool) -> Rat {
    let s = Rat::simplest_in(lo, hi);
    if (s != *lo || lo_incl) && (s != *hi || hi_incl) && lo != hi {
        return s;
    }
    let quarter = (hi - lo).mul_pow2(-2);
    Rat::simplest_in(&(lo + &quarter), &(hi - &quarter))
}

/// The first of 1/2, 1/4, 3/4, 1/8, 3/8, … that is not a root of `p ≠ 0`.
fn non_root_dyadic(p: &ZPoly) -> Rat {
    (1u64..)
        .flat_map(|k| {
            (1..(1u64 << k.min(62)))
                .step_by(2)
                .map(move |m| Rat::dyadic(ccd_arith::Int::from_u64(m), k))
        })
        .find(|d| p.sign_at(d) != 0)
        .expect("a nonzero polynomial has finitely many roots")
}

/// A candidate contact: the instant and whether it is a touch.
struct Contact {
    root: RealRoot,
}

/// The symbolic stage of a rational scene: the normalised `f(λ; u)` and its
/// five `sr` polynomials in `u = (t − t0)/(t1 − t0)`.
pub fn symbolic(scene: &Scene) -> Result<(CharPoly, QuarticInvariants<ZPoly>), CcdError> {
    let ma = placed_quadric(&scene.a, &scene.span).map_err(|e| CcdError::motion("a", e))?;
    let mb = placed_quadric(&scene.b, &scene.span).map_err(|e| CcdError::motion("b", e))?;
    let f = CharPoly::from_placed(&ma, &mb);
    let inv = invariants(&f);
    Ok((f, inv))
}

/// Runs Algorithm 1 on a rational scene.
pub fn run(scene: &Scene, opts: &Options) -> Result<Outcome, CcdError> {
    let span = scene.span.clone();
    let (f, inv) = symbolic(scene)?;
    let mut stats = Stats {
        deg_f: f.degree(),
        deg_sr0: inv.sr0.degree(),
        ..Stats::default()
    };
    let (zero, one) = (Rat::zero(), Rat::one());
    let state0 = state_at(&f, &zero);

    let mut contacts: Vec<Contact> = Vec::new();
    let mut throughout: Option<State> = None;
    let first_only = opts.first_contact_only;
    let stop_early = first_only && state0 != State::Separate;

    let candidates: Option<(&ZPoly, Vec<Quantity>)> = if !inv.sr0.is_zero() {
        stats.branch = "sr0";
        Some((&inv.sr0, vec![Quantity::Sr0]))
    } else if !inv.sr11.is_zero() {
        // Theorem 5.5: touching at one non-root of sr11 means throughout.
        stats.branch = "sr0=0, sr11";
        let delta = non_root_dyadic(&inv.sr11);
        if state_at(&f, &delta) == State::Touch {
            throughout = Some(State::Touch);
            None
        } else {
            Some((&inv.sr11, vec![Quantity::Sr0, Quantity::Sr11]))
        }
    } else {
        // Theorem 5.6: the state at t0 holds throughout.
        stats.branch = "sr0=0, sr11=0";
        throughout = Some(state0);
        None
    };

    if let (Some((poly, zeros)), false) = (candidates, stop_early) {
        stats.deg_candidates = poly.degree();
        let roots = ccd_solver::isolate(poly, &zero, &one)
            .map_err(|e| CcdError::Internal(e.to_string()))?;
        for mut root in roots {
            stats.candidates += 1;
            if touches_at(&mut root, &inv, &zeros) {
                contacts.push(Contact { root });
                if first_only {
                    break;
                }
            }
        }
    }

    // Enclosures to the requested width, then mapped from u to t.
    let width = Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(opts.digits))
        .expect("nonzero denominator");
    let dt = &span[1] - &span[0];
    let to_t = |u: &Rat| &span[0] + &(u * &dt);
    let instant_u = |r: &RealRoot| Instant {
        lo: r.lo().clone(),
        hi: r.hi().clone(),
        certified: true,
    };
    let map = |i: &Instant| Instant {
        lo: to_t(&i.lo),
        hi: to_t(&i.hi),
        certified: i.certified,
    };
    let mut contact_u: Vec<Instant> = Vec::with_capacity(contacts.len());
    for c in contacts.iter_mut() {
        c.root.refine_to(&width);
        contact_u.push(instant_u(&c.root));
    }

    let start = Instant::exact(zero.clone());
    let end = Instant::exact(one.clone());
    let mut timeline: Vec<Segment> = Vec::new();
    let complete;
    if let Some(state) = throughout {
        timeline.push(Segment {
            state,
            start: start.clone(),
            end: end.clone(),
        });
        complete = true;
    } else if stop_early {
        timeline.push(Segment {
            state: state0,
            start: start.clone(),
            end: start.clone(),
        });
        complete = false;
    } else {
        // Breakpoints: t0, the contacts, t1 (contacts at the ends coincide).
        let mut points: Vec<Instant> = Vec::new();
        if contact_u
            .first()
            .is_none_or(|c| c.lo != zero || c.hi != zero)
        {
            points.push(start.clone());
        }
        points.extend(contact_u.iter().cloned());
        let ends_at_one = contact_u.last().is_some_and(|c| c.lo == one && c.hi == one);
        let reached_end = !first_only || contact_u.is_empty();
        if !ends_at_one && reached_end {
            points.push(end.clone());
        }
        let is_contact = |i: &Instant| contact_u.contains(i);
        for (k, p) in points.iter().enumerate() {
            if is_contact(p) {
                timeline.push(Segment {
                    state: State::Touch,
                    start: p.clone(),
                    end: p.clone(),
                });
            }
            if let Some(next) = points.get(k + 1) {
                let exact_lo = p.lo == p.hi && is_contact(p);
                let exact_hi = next.lo == next.hi && is_contact(next);
                let sample = sample_between(&p.hi, !exact_lo, &next.lo, !exact_hi);
                let state = state_at(&f, &sample);
                if state == State::Touch {
                    return Err(CcdError::Internal(format!(
                        "touch at sample u = {sample} between contacts"
                    )));
                }
                timeline.push(Segment {
                    state,
                    start: p.clone(),
                    end: next.clone(),
                });
            }
        }
        complete = reached_end;
    }

    let first_contact = match (state0, throughout) {
        (State::Separate, Some(State::Separate)) => None,
        (State::Separate, None) => timeline
            .iter()
            .find(|s| s.state != State::Separate)
            .map(|s| s.start.clone()),
        _ => Some(start.clone()),
    };
    Ok(Outcome {
        collision_free: first_contact.is_none() && complete,
        first_contact: first_contact.map(|i| map(&i)),
        contacts: contact_u.iter().map(map).collect(),
        timeline: timeline
            .iter()
            .map(|s| Segment {
                state: s.state,
                start: map(&s.start),
                end: map(&s.end),
            })
            .collect(),
        complete,
        span,
        stats,
    })
}
