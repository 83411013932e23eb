//! Algorithm 1 of the paper (Section 5) on the exact path: every contact
//! instant isolated with exact rational bounds and every state decided by
//! exact signs.

use crate::geometry::Bodies;
use crate::signs::Coefficients;
use crate::CcdError;
use ccd_arith::{Int, Rat};
use ccd_classify::{classify_with, Configuration};
use ccd_motion::{placed_quadric, CharPoly, PlacedQuadric};
use ccd_poly::ZPoly;
use ccd_quadric::{characteristic, classify_quartic};
use ccd_scene::Scene;
use ccd_solver::{RealRoot, RootIter, SignModel};
use ccd_subres::{closed_forms, Quantity, QuarticInvariants};
use ccd_timeline::{Findings, Geometry, Instant, Outcome, State, Stats};

/// How the roots and signs are computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Arithmetic {
    /// Exact and certified: every sign proven (the default).
    #[default]
    Exact,
    /// The paper's Table 3 setting: `f64` Bernstein subdivision after the
    /// exact set-up of `f(λ; t)`. Fast, NOT certified: every instant is
    /// marked `certified: false`.
    Float,
}

/// What a query asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Enclosures of contact instants get `hi − lo <= 10^(−digits)·(t1 − t0)`
    /// (exact arithmetic; the float mode stops at `f64` resolution).
    pub digits: u32,
    /// Stop at the earliest instant at which the bodies are not separate.
    pub first_contact_only: bool,
    /// Exact (certified) or float.
    pub arithmetic: Arithmetic,
    /// Compute the contact point and normal of each contact
    /// ([`Outcome::geometry`]); `false` leaves it empty (default `true`).
    pub contact_geometry: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            digits: 15,
            first_contact_only: false,
            arithmetic: Arithmetic::Exact,
            contact_geometry: true,
        }
    }
}

impl Options {
    /// Largest `digits` accepted (refinement cost grows with it).
    pub const MAX_DIGITS: u32 = 1000;
}

/// The largest closed form the exact path forms, in bits (degree times
/// coefficient length, [`exact_bits`]): 2²⁵, a polynomial of 4 MiB, about a
/// second of this machine's time to form and isolate (docs/termination.md).
pub const MAX_EXACT_BITS: u64 = 1 << 25;

/// An upper estimate of the size in bits of `sr0`'s closed form: it is
/// homogeneous of degree 6 in the coefficients `f_k` of `f(λ; u)` (Section
/// 4), so it has degree `≤ 6·deg f` in `u` and coefficients of at most
/// about `6·τ` bits for `f_k` of `τ` bits (plus the binomial growth of the
/// products, a few bits per factor).
pub fn exact_bits(f: &CharPoly) -> u64 {
    let tau = f.coeffs.iter().map(ZPoly::max_bits).max().unwrap_or(0);
    let n = f.degree() as u64;
    (6 * n + 1) * (6 * tau + 8 * n.max(1))
}

/// The configuration at a rational parameter `u`, exactly (Theorem 3.10).
fn state_at(f: &CharPoly, u: &Rat) -> State {
    State::from(classify_quartic(&f.at_scaled(u), Int::signum))
}

/// Is the configuration at the algebraic instant `root` an external touch?
/// Theorem 3.10(2), with the signs decided exactly at the root; `zero` lists
/// quantities known to vanish there (the polynomial the root came from).
fn touches_at<M: SignModel + Clone>(
    root: &mut RealRoot<M>,
    f: &Coefficients,
    zero: &[Quantity],
) -> bool {
    struct NotTouch;
    let answer = classify_with(|q| {
        if zero.contains(&q) {
            return Ok(0);
        }
        match q {
            // Var is read only on the way to "separate": not a touch.
            Quantity::Var => Err(NotTouch),
            other => Ok(root.sign_with(&f.model(other))),
        }
    });
    matches!(answer, Ok(Configuration::ExternalTouch))
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

fn placed(scene: &Scene) -> Result<(PlacedQuadric, PlacedQuadric), CcdError> {
    let a = placed_quadric(&scene.a, &scene.span).map_err(|e| CcdError::motion("a", e))?;
    let b = placed_quadric(&scene.b, &scene.span).map_err(|e| CcdError::motion("b", e))?;
    Ok((a, b))
}

/// The symbolic stage of a rational scene: the normalised `f(λ; u)` and its
/// five `sr` polynomials in `u = (t − t0)/(t1 − t0)`.
pub fn symbolic(scene: &Scene) -> Result<(CharPoly, QuarticInvariants<ZPoly>), CcdError> {
    let (a, b) = placed(scene)?;
    let f = CharPoly::from_placed(&a, &b);
    let inv = closed_forms(&f.coeffs);
    Ok((f, inv))
}

/// The state at `u = 0` straight from the placements (no `f(λ; u)`).
fn state_at_start(a: &PlacedQuadric, b: &PlacedQuadric) -> State {
    let zero = Rat::zero();
    State::from(classify_quartic(
        &characteristic(&a.quadric_at(&zero), &b.quadric_at(&zero)),
        Int::signum,
    ))
}

/// Where the contact candidates come from (Algorithm 1's three branches).
enum Candidates<'a> {
    /// Roots of this polynomial, at which these quantities vanish.
    Roots(&'a ZPoly, &'static [Quantity]),
    /// One state on the whole span.
    Throughout(State),
}

fn candidates<'a>(
    f: &CharPoly,
    sr0: &'a ZPoly,
    coefficients: &'a Coefficients,
    state0: State,
    stats: &mut Stats,
) -> Candidates<'a> {
    if !sr0.is_zero() {
        stats.branch = "sr0";
        return Candidates::Roots(sr0, &[Quantity::Sr0]);
    }
    let sr11 = coefficients.polynomial(Quantity::Sr11);
    if !sr11.is_zero() {
        // Theorem 5.5: touching at one non-root of sr11 means throughout.
        stats.branch = "sr0=0, sr11";
        if state_at(f, &non_root_dyadic(sr11)) == State::Touch {
            Candidates::Throughout(State::Touch)
        } else {
            Candidates::Roots(sr11, &[Quantity::Sr0, Quantity::Sr11])
        }
    } else {
        // Theorem 5.6: the state at t0 holds throughout.
        stats.branch = "sr0=0, sr11=0";
        Candidates::Throughout(state0)
    }
}

/// The contact instants among the roots `roots` yields, in order (up to
/// the first with `first_contact_only`), refined to `width`, each with its
/// contact geometry (crate::geometry); `None` if a filter-only isolation
/// could not prove a sign before that point.
fn contacts_at<M: SignModel + Clone>(
    mut roots: RootIter<M>,
    coefficients: &Coefficients,
    zeros: &[Quantity],
    width: &Rat,
    opts: &Options,
    stats: &mut Stats,
    bodies: &Bodies,
) -> Result<Option<Contacts>, CcdError> {
    let mut contacts = vec![];
    for mut root in roots.by_ref() {
        stats.candidates += 1;
        if touches_at(&mut root, coefficients, zeros) {
            root.refine_to(width);
            let instant = Instant {
                lo: root.lo().clone(),
                hi: root.hi().clone(),
                certified: true,
            };
            let geometry = if opts.contact_geometry {
                bodies.exact(&mut root, coefficients, zeros)
            } else {
                Geometry::Unknown {
                    reason: "not asked for".into(),
                }
            };
            contacts.push((instant, geometry));
            if opts.first_contact_only {
                return Ok(Some(contacts));
            }
        }
    }
    if roots.exhausted() {
        return Err(CcdError::Effort {
            limit: "exact work",
            unit: "word operations of exact root isolation",
            bound: ccd_solver::MAX_EXACT_WORK,
            reached: roots.work(),
        });
    }
    Ok((!roots.undecided()).then_some(contacts))
}

/// Contact instants with their geometry, in order.
type Contacts = Vec<(Instant, Geometry)>;

/// Algorithm 1's `sr0` branch without forming `sr0`: its roots from its
/// certified `f64` Bernstein coefficients, everything else from `f`'s
/// coefficients (crate::signs). `None` (the caller forms `sr0`) when
/// `sr0(1/2) = 0` — mostly `sr0 ≡ 0`, the `sr11` branch, which the filter
/// could not decide — or when the filter cannot prove a sign; otherwise the
/// contacts and the run's statistics.
fn filtered_contacts(
    f: &CharPoly,
    coefficients: &Coefficients,
    width: &Rat,
    opts: &Options,
    stats: &Stats,
    bodies: &Bodies,
) -> Result<Option<(Contacts, Stats)>, CcdError> {
    let sr0 = coefficients.model(Quantity::Sr0);
    if sr0.filtered_sign_at(&Rat::from_frac(1, 2)) == 0 {
        return Ok(None);
    }
    let deg_sr0 = coefficients.sr0_degree();
    let mut stats = Stats {
        branch: "sr0",
        deg_sr0,
        deg_candidates: deg_sr0,
        ..stats.clone()
    };
    let bernstein = ccd_float::certified_bernstein(f, Quantity::Sr0);
    let roots = RootIter::filtered(sr0, &Rat::zero(), &Rat::one(), &bernstein);
    let contacts = contacts_at(
        roots,
        coefficients,
        &[Quantity::Sr0],
        width,
        opts,
        &mut stats,
        bodies,
    )?;
    Ok(contacts.map(|c| (c, stats)))
}

/// Runs Algorithm 1 on a rational scene.
pub fn run(scene: &Scene, opts: &Options) -> Result<Outcome, CcdError> {
    let (a, b) = placed(scene)?;
    if opts.arithmetic == Arithmetic::Float {
        let float = ccd_float::Options {
            first_contact_only: opts.first_contact_only,
        };
        let mut outcome = ccd_float::solve(&CharPoly::from_placed(&a, &b), &scene.span, &float);
        if opts.contact_geometry {
            outcome.geometry = crate::geometry::estimates(scene, &outcome);
        }
        return Ok(outcome);
    }
    let mut stats = Stats::default();
    // First contact only: the state at t0 straight from the placements, so
    // a start that is not separate exits before f(λ; t) is set up.
    let early = opts.first_contact_only.then(|| state_at_start(&a, &b));
    if let Some(state0) = early.filter(|s| *s != State::Separate) {
        // Early exit: not separate at t0, nothing else to compute.
        let found = Findings {
            state0,
            throughout: None,
            contacts: vec![],
            complete: false,
            certified: true,
        };
        return found.into_outcome(&scene.span, stats, |_| Ok(state0));
    }
    let f = CharPoly::from_placed(&a, &b);
    let state0 = early.unwrap_or_else(|| state_at(&f, &Rat::zero()));
    let size = exact_bits(&f);
    if size > MAX_EXACT_BITS {
        return Err(CcdError::Effort {
            limit: "exact size",
            unit: "bits in the closed form of sr0",
            bound: MAX_EXACT_BITS,
            reached: size,
        });
    }
    let coefficients = Coefficients::new(&f);
    stats.deg_f = f.degree();
    let width = Rat::new(Int::one(), Int::pow10(opts.digits)).expect("nonzero denominator");
    let mut found = Findings {
        state0,
        throughout: None,
        contacts: vec![],
        complete: true,
        certified: true,
    };
    let bodies = Bodies::new(scene, &a, &b, opts);
    let contacts = match filtered_contacts(&f, &coefficients, &width, opts, &stats, &bodies)? {
        Some((contacts, filtered_stats)) => {
            stats = filtered_stats;
            Some(contacts)
        }
        None => {
            // sr0 as a polynomial; the other closed forms only as signs at
            // its roots (crate::signs).
            let sr0 = coefficients.polynomial(Quantity::Sr0);
            stats.deg_sr0 = sr0.degree();
            stats.sr0_formed = true;
            match candidates(&f, sr0, &coefficients, state0, &mut stats) {
                Candidates::Throughout(state) => {
                    found.throughout = Some(state);
                    None
                }
                Candidates::Roots(poly, zeros) => {
                    stats.deg_candidates = poly.degree();
                    let roots = ccd_solver::isolate(poly, &Rat::zero(), &Rat::one())
                        .map_err(|e| CcdError::Internal(e.to_string()))?;
                    let exact = contacts_at(
                        roots,
                        &coefficients,
                        zeros,
                        &width,
                        opts,
                        &mut stats,
                        &bodies,
                    )?;
                    Some(exact.expect("exact isolation decides every sign"))
                }
            }
        }
    };
    let mut geometry = vec![];
    if let Some(contacts) = contacts {
        // First contact only: the timeline stops at the one found.
        found.complete = !opts.first_contact_only || contacts.is_empty();
        (found.contacts, geometry) = contacts.into_iter().unzip();
    }
    let mut outcome = found.into_outcome(&scene.span, stats, |u| match state_at(&f, u) {
        State::Touch => Err(CcdError::Internal(format!(
            "touch at sample u = {u} between contacts"
        ))),
        state => Ok(state),
    })?;
    if opts.contact_geometry {
        outcome.geometry = geometry;
    }
    Ok(outcome)
}
