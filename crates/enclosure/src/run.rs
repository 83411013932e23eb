//! Algorithm 1 of the paper (Section 5) on the interval path: candidate
//! instants from the certified isolation of `sr0(t)` (or of `sr11(t)` when
//! `sr0 ≡ 0`, Theorems 5.4–5.6), each decided by Theorem 3.10(2) on its
//! enclosure, and the state of every piece between contacts read at a
//! rational sample (Theorem 5.1).

use crate::dyadic::BigInterval;
use crate::error::EnclosureError;
use crate::isolate::{isolate, refine, width_rat, Found, Limits, Problem};
use crate::placement::invariants_at;
use crate::real::Real;
use crate::signs::{Possible, Readings};
use crate::trig::Trig;
use ccd_arith::{Int, Interval, Rat};
use ccd_motion::{Body, Motion, Quat};
use ccd_subres::{classify, Configuration, Quantity, SignData};
use ccd_timeline::{Instant, Outcome, Segment, State, Stats};

/// What a query asks for (the same fields as the exact path's options).
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
    /// Largest `digits` accepted.
    pub const MAX_DIGITS: u32 = 1000;
}

/// Precisions (bits) tried, in order, when an `f64` enclosure cannot decide
/// a configuration at a point or on a box.
const DECISION_PRECISIONS: [u32; 2] = [128, 512];
/// Evenly spaced samples used to test whether a quantity vanishes
/// identically.
const ZERO_TEST_SAMPLES: usize = 17;
/// Bits used to confirm that a quantity vanishes identically.
const ZERO_TEST_BITS: u32 = 256;
/// Minimal box width of the subdivision, relative to the span: `2^−36`.
const MIN_WIDTH_LOG2: i32 = -36;
/// The isolation domain extends the span by `2^−20` of its length on each
/// side, so that roots at the ends are strictly inside some box.
const MARGIN_LOG2: i32 = -20;
/// At most this many boxes are examined in one isolation.
const MAX_BOXES: usize = 50_000;
/// Bits of the multi-precision subdivision of an `f64` cluster.
const CLUSTER_BITS: u32 = 128;
/// At most this many boxes are examined when subdividing a cluster again.
const MAX_CLUSTER_BOXES: usize = 400;
/// Largest precision tried when refining a certified root.
const MAX_REFINEMENT_BITS: u32 = 1 << 15;

/// What is known about `sr0 ≡ 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sr0 {
    /// `sr0` is not identically zero (proven at a sample).
    NotZero,
    /// `sr0 ≡ 0` by the structure of the scene (Note 2 of the paper, and its
    /// generalisation: the quadratic parts of `A(t)` and `B(t)` are
    /// proportional for all t, so `λA + B` drops rank by 2 at one λ).
    Proven,
    /// `sr0` encloses zero at every sample, even in multi-precision: taken
    /// as identically zero, but not proven, so nothing that relies on it is
    /// reported as certified.
    Assumed,
}

/// A contact candidate with its decision.
#[derive(Clone, Debug)]
struct Contact {
    lo: Rat,
    hi: Rat,
    certified: bool,
}

/// The configuration at one instant and whether it is proven.
#[derive(Clone, Copy, Debug)]
struct Decided {
    state: State,
    certified: bool,
}

/// One CCD query: bodies, span, the knowledge about `sr0`, the options.
struct Query<'a> {
    a: &'a Body,
    b: &'a Body,
    span: &'a [Rat; 2],
    sr0: Sr0,
    options: &'a Options,
}

fn validate(a: &Body, b: &Body, span: &[Rat; 2], options: &Options) -> Result<(), EnclosureError> {
    if options.digits > Options::MAX_DIGITS {
        return Err(EnclosureError::Digits {
            max: Options::MAX_DIGITS,
            got: options.digits,
        });
    }
    if span[0] >= span[1] {
        return Err(EnclosureError::Span);
    }
    for (name, body) in [("a", a), ("b", b)] {
        if body.radii.iter().any(|r| r.signum() <= 0) {
            return Err(EnclosureError::Radius { body: name });
        }
        let zero_quat = |q: &Quat| q.iter().all(|x| x.signum() == 0);
        match &body.motion {
            Motion::Helical {
                orientation, axis, ..
            } => {
                if zero_quat(orientation) {
                    return Err(EnclosureError::Zero {
                        body: name,
                        field: "orientation",
                    });
                }
                if axis.iter().all(|x| x.signum() == 0) {
                    return Err(EnclosureError::Zero {
                        body: name,
                        field: "axis",
                    });
                }
            }
            Motion::Static { orientation, .. } | Motion::Translation { orientation, .. }
                if zero_quat(orientation) =>
            {
                return Err(EnclosureError::Zero {
                    body: name,
                    field: "orientation",
                });
            }
            other => {
                // The rational kinds are checked exactly (vanishing weights
                // or quaternion curves, singular affine maps).
                // (placing a body validates it; no matrix is formed).
                if !matches!(other, Motion::Static { .. }) {
                    ccd_motion::placed_quadric(body, span)
                        .map_err(|source| EnclosureError::Motion { body: name, source })?;
                }
            }
        }
    }
    Ok(())
}

/// The orientation quaternion of a body whose orientation never changes.
fn fixed_orientation(m: &Motion) -> Option<&Quat> {
    match m {
        Motion::Static { orientation, .. } | Motion::Translation { orientation, .. } => {
            Some(orientation)
        }
        Motion::Helical {
            orientation, rate, ..
        } if rate.signum() == 0 => Some(orientation),
        _ => None,
    }
}

/// `sr0 ≡ 0` by structure: the quadratic parts of `A(t)` and `B(t)` (the
/// upper-left 3×3 blocks, `R·diag(r⁻²)·Rᵀ` up to positive factors) are
/// proportional at every t — two spheres under rigid motions (Note 2), or
/// two ellipsoids with proportional radii and the same constant
/// orientation (as in Example 5.1). Then `λA + B` has a 3×3 block that
/// vanishes at one λ, so its rank drops by 2 there and `f` has a double
/// root for every t.
fn sr0_vanishes_by_structure(a: &Body, b: &Body) -> bool {
    let sphere = |x: &Body| {
        x.radii.iter().all(|r| *r == x.radii[0]) && !matches!(x.motion, Motion::Affine { .. })
    };
    if sphere(a) && sphere(b) {
        return true;
    }
    let proportional = |p: &[Rat], q: &[Rat]| {
        (0..p.len()).all(|i| (0..q.len()).all(|j| &p[i] * &q[j] == &p[j] * &q[i]))
    };
    match (fixed_orientation(&a.motion), fixed_orientation(&b.motion)) {
        (Some(qa), Some(qb)) => proportional(qa, qb) && proportional(&a.radii, &b.radii),
        _ => false,
    }
}

/// Evenly spaced dyadic samples strictly inside the span.
fn samples(span: &[Rat; 2], n: usize) -> Vec<Rat> {
    let dt = &span[1] - &span[0];
    (0..n)
        .map(|i| &span[0] + &(&dt * &Rat::from_frac(2 * i as i64 + 1, 2 * n as i64)))
        .collect()
}

/// Whether `q` is proven nonzero at some sample (f64, then multi-precision).
fn nonzero_somewhere(p: &Problem<'_>, span: &[Rat; 2]) -> Option<Rat> {
    let pts = samples(span, ZERO_TEST_SAMPLES);
    for t in &pts {
        if p.value(&Interval::from_rat(t), 53)
            .sign()
            .is_some_and(|s| s != 0)
        {
            return Some(t.clone());
        }
    }
    for t in pts.iter().step_by(4) {
        let v = p.value(&BigInterval::from_rat(t, ZERO_TEST_BITS), ZERO_TEST_BITS);
        if v.sign().is_some_and(|s| s != 0) {
            return Some(t.clone());
        }
    }
    None
}

impl Query<'_> {
    fn problem(&self, target: Quantity) -> Problem<'_> {
        Problem {
            a: self.a,
            b: self.b,
            span: self.span,
            target,
        }
    }

    /// The readings of Theorem 3.10 over `t` (a point or a box), with the
    /// quantities in `zero` known to vanish there.
    fn readings<R: Real + Trig>(&self, t: &R, zero: &[Quantity]) -> Readings {
        let (f, inv) = invariants_at(self.a, self.b, self.span, t, t.precision());
        let mut r = Readings::of(&f, &inv);
        if self.sr0 != Sr0::NotZero {
            r = r.with_zero(Quantity::Sr0);
        }
        for q in zero {
            r = r.with_zero(*q);
        }
        r
    }

    /// The possible configurations over `[lo, hi]`: `f64` first, then
    /// multi-precision while undecided.
    fn possible(&self, lo: &Rat, hi: &Rat, zero: &[Quantity]) -> Possible {
        let box64 = Interval::from_rat(lo).hull(&Interval::from_rat(hi));
        let mut p = self.readings(&box64, zero).possible();
        for bits in DECISION_PRECISIONS {
            if p.single().is_some() {
                break;
            }
            let bx = BigInterval::from_rat(lo, bits).hull(&BigInterval::from_rat(hi, bits));
            p = self.readings(&bx, zero).possible();
        }
        p
    }

    /// The configuration at the rational instant `t`.
    fn state_at(&self, t: &Rat) -> Decided {
        if let Some(c) = self.possible(t, t, &[]).single() {
            return Decided {
                state: State::from(c),
                certified: self.sr0 != Sr0::Assumed,
            };
        }
        // Undecided even in multi-precision: a best guess from the
        // midpoints, reported uncertified.
        let bits = DECISION_PRECISIONS[DECISION_PRECISIONS.len() - 1];
        let tt = BigInterval::from_rat(t, bits);
        let (f, inv) = invariants_at(self.a, self.b, self.span, &tt, bits);
        let sign = |x: &BigInterval| {
            let v = x.approx();
            if v > 0.0 {
                1
            } else if v < 0.0 {
                -1
            } else {
                0
            }
        };
        let mut s = SignData::from_invariants(&inv, &f, sign);
        if self.sr0 != Sr0::NotZero {
            s.sr0 = 0;
        }
        Decided {
            state: State::from(classify(&s)),
            certified: false,
        }
    }

    /// Bits for refining an enclosure to `target` on this span.
    fn refinement_bits(&self) -> u32 {
        let dt = (&self.span[1] - &self.span[0]).to_f64();
        let scale = self.span[0]
            .to_f64()
            .abs()
            .max(self.span[1].to_f64().abs())
            .max(dt);
        let ratio = (scale / dt).log2().max(0.0);
        (self.options.digits as f64 * std::f64::consts::LOG2_10 + ratio + 96.0).ceil() as u32
    }

    /// A certified simple root of `target` in the box `x`: decided (touch
    /// or not) and, when it may be a touch, refined to `width` (escalating
    /// to multi-precision when `x`'s arithmetic cannot get there).
    fn root_contact<R: Real + Trig>(&self, target: Quantity, x: R, width: &Rat) -> Option<Contact> {
        let zero = [target];
        let (lo, hi) = (x.lo_rat()?, x.hi_rat()?);
        if !self.possible(&lo, &hi, &zero).touch {
            return None;
        }
        let p = self.problem(target);
        let fine = refine(&p, x, width);
        let (mut lo, mut hi) = (fine.lo_rat()?, fine.hi_rat()?);
        let mut bits = self.refinement_bits().max(fine.precision());
        while &(&hi - &lo) > width && bits <= MAX_REFINEMENT_BITS {
            let start = BigInterval::from_rat(&lo, bits).hull(&BigInterval::from_rat(&hi, bits));
            let big = refine(&p, start, width);
            let w = width_rat(&big).unwrap_or_else(|| &hi - &lo);
            if w < &hi - &lo {
                (lo, hi) = (big.lo_rat(), big.hi_rat());
            }
            bits *= 2;
        }
        let decided = self.possible(&lo, &hi, &zero);
        decided.touch.then(|| Contact {
            certified: decided.single() == Some(Configuration::ExternalTouch)
                && self.sr0 != Sr0::Assumed,
            lo,
            hi,
        })
    }

    /// The contacts among what subdivision found: certified roots are
    /// decided and refined; a cluster that is consistent with a touch is
    /// subdivided again in multi-precision (when `escalate`), and what still
    /// cannot be proven is reported uncertified.
    fn examine<R: Real + Trig>(
        &self,
        target: Quantity,
        found: Found<R>,
        width: &Rat,
        escalate: bool,
        out: &mut Vec<Contact>,
    ) {
        match found {
            Found::Root(x) => out.extend(self.root_contact(target, x, width)),
            Found::Cluster(x) => {
                let (Some(lo), Some(hi)) = (x.lo_rat(), x.hi_rat()) else {
                    return;
                };
                if !self.possible(&lo, &hi, &[target]).touch {
                    return;
                }
                if !escalate {
                    out.push(Contact {
                        lo,
                        hi,
                        certified: false,
                    });
                    return;
                }
                let bx = BigInterval::from_rat(&lo, CLUSTER_BITS)
                    .hull(&BigInterval::from_rat(&hi, CLUSTER_BITS));
                let dt = (&self.span[1] - &self.span[0]).to_f64();
                let limits = Limits {
                    min_width: dt * 2f64.powi(-(CLUSTER_BITS as i32) + 24),
                    max_boxes: MAX_CLUSTER_BOXES,
                    pieces: 2,
                };
                for f in isolate(&self.problem(target), &bx, &limits) {
                    self.examine(target, f, width, false, out);
                }
            }
        }
    }

    /// Contacts from the roots of `target` in the span, in order.
    fn contacts(&self, target: Quantity, stats: &mut Stats) -> Vec<Contact> {
        let (t0, t1) = (&self.span[0], &self.span[1]);
        let dt = (t1 - t0).to_f64();
        let margin = dt * 2f64.powi(MARGIN_LOG2);
        let domain = Interval::new(
            Interval::from_rat(t0).lo - margin,
            Interval::from_rat(t1).hi + margin,
        );
        let limits = Limits {
            min_width: dt * 2f64.powi(MIN_WIDTH_LOG2),
            max_boxes: MAX_BOXES,
            pieces: 32,
        };
        let width = &(t1 - t0) / &Rat::from_int(Int::pow10(self.options.digits));
        let mut out: Vec<Contact> = Vec::new();
        let all = isolate(&self.problem(target), &domain, &limits);
        for found in all {
            stats.candidates += 1;
            let mut here = Vec::new();
            self.examine(target, found, &width, true, &mut here);
            for mut c in here {
                // Clip to the span; an enclosure reaching past an end may
                // hold a root outside the span, so it is no longer certified.
                if &c.hi < t0 || &c.lo > t1 {
                    continue;
                }
                if &c.lo < t0 {
                    c.lo = t0.clone();
                    c.certified = false;
                }
                if &c.hi > t1 {
                    c.hi = t1.clone();
                    c.certified = false;
                }
                out.push(c);
            }
            if self.options.first_contact_only && !out.is_empty() {
                out.truncate(1);
                break;
            }
        }
        out
    }
}

/// A rational strictly inside `(lo, hi)` with a small denominator.
fn sample_between(lo: &Rat, hi: &Rat) -> Rat {
    let quarter = (hi - lo).mul_pow2(-2);
    Rat::simplest_in(&(lo + &quarter), &(hi - &quarter))
}

fn instant(lo: Rat, hi: Rat, certified: bool) -> Instant {
    Instant { lo, hi, certified }
}

/// Runs continuous collision detection for two bodies over `span` on the
/// interval path (any motion kinds, in particular `helical`).
///
/// Contact instants come with exact rational enclosures, certified when
/// the root of `sr0` (or `sr11`) is proven simple and unique in its
/// enclosure by interval Newton and Theorem 3.10(2) is decided on the
/// enclosure; otherwise they are reported with `certified: false` (see
/// `docs/helical.md` for the exact rules).
pub fn run(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    options: &Options,
) -> Result<Outcome, EnclosureError> {
    validate(a, b, span, options)?;
    let (t0, t1) = (span[0].clone(), span[1].clone());
    let mut stats = Stats::default();
    let sr0 = if sr0_vanishes_by_structure(a, b) {
        Sr0::Proven
    } else {
        let p = Problem {
            a,
            b,
            span,
            target: Quantity::Sr0,
        };
        match nonzero_somewhere(&p, span) {
            Some(_) => Sr0::NotZero,
            None => Sr0::Assumed,
        }
    };
    let q = Query {
        a,
        b,
        span,
        sr0,
        options,
    };
    let first_only = options.first_contact_only;
    let start0 = q.state_at(&t0);

    // The whole span in one state (Theorems 5.5 and 5.6), or the contacts.
    let mut throughout: Option<Decided> = None;
    let mut contacts: Vec<Contact> = Vec::new();
    let stop_early = first_only && start0.state != State::Separate;
    match sr0 {
        Sr0::NotZero => {
            stats.branch = "interval: sr0";
            if !stop_early {
                contacts = q.contacts(Quantity::Sr0, &mut stats);
            }
        }
        Sr0::Proven | Sr0::Assumed => {
            stats.branch = if sr0 == Sr0::Proven {
                "interval: sr0 = 0 (structure), sr11"
            } else {
                "interval: sr0 = 0 (assumed), sr11"
            };
            match nonzero_somewhere(&q.problem(Quantity::Sr11), span) {
                Some(delta) => {
                    // Theorem 5.5: touching at one non-root of sr11 means
                    // touching throughout.
                    let at = q.state_at(&delta);
                    if at.state == State::Touch {
                        throughout = Some(at);
                    } else if !stop_early {
                        contacts = q.contacts(Quantity::Sr11, &mut stats);
                    }
                }
                None => {
                    // Theorem 5.6: the state at t0 holds throughout; sr11 ≡ 0
                    // is only observed, not proven.
                    stats.branch = "interval: sr0 = 0, sr11 = 0 (assumed)";
                    throughout = Some(Decided {
                        certified: false,
                        ..start0
                    });
                }
            }
        }
    }

    let start = instant(t0.clone(), t0.clone(), start0.certified);
    let end = Instant::exact(t1.clone());
    let mut timeline: Vec<Segment> = Vec::new();
    let mut contact_instants: Vec<Instant> = Vec::new();
    let complete;
    if let Some(d) = throughout {
        let e = instant(t1.clone(), t1.clone(), d.certified);
        let s = instant(t0.clone(), t0.clone(), d.certified);
        timeline.push(Segment {
            state: d.state,
            start: s,
            end: e,
        });
        complete = true;
    } else if stop_early {
        timeline.push(Segment {
            state: start0.state,
            start: start.clone(),
            end: start.clone(),
        });
        complete = false;
    } else {
        // Breakpoints: t0, the contacts, t1 (a contact reaching an end
        // replaces it).
        let mut points: Vec<(Instant, bool)> = Vec::new();
        if contacts.first().is_none_or(|c| c.lo != t0) {
            points.push((start.clone(), false));
        }
        points.extend(
            contacts
                .iter()
                .map(|c| (instant(c.lo.clone(), c.hi.clone(), c.certified), true)),
        );
        let reached_end = !first_only || contacts.is_empty();
        if contacts.last().is_none_or(|c| c.hi != t1) && reached_end {
            points.push((end.clone(), false));
        }
        // States of the open pieces; an undecided piece makes its bounding
        // instants uncertified.
        let mut pieces: Vec<Option<State>> = Vec::new();
        for k in 0..points.len().saturating_sub(1) {
            let (lo, hi) = (&points[k].0.hi, &points[k + 1].0.lo);
            if lo >= hi {
                pieces.push(None);
                continue;
            }
            let d = q.state_at(&sample_between(lo, hi));
            if !d.certified {
                points[k].0.certified = false;
                points[k + 1].0.certified = false;
            }
            pieces.push(Some(d.state));
        }
        for (k, (p, is_contact)) in points.iter().enumerate() {
            if *is_contact {
                timeline.push(Segment {
                    state: State::Touch,
                    start: p.clone(),
                    end: p.clone(),
                });
                contact_instants.push(p.clone());
            }
            if let (Some(Some(state)), Some((next, _))) = (pieces.get(k), points.get(k + 1)) {
                timeline.push(Segment {
                    state: *state,
                    start: p.clone(),
                    end: next.clone(),
                });
            }
        }
        complete = reached_end;
    }

    let first_contact = if start0.state != State::Separate {
        Some(start)
    } else {
        timeline
            .iter()
            .find(|s| s.state != State::Separate)
            .map(|s| s.start.clone())
    };
    Ok(Outcome {
        span: span.clone(),
        collision_free: first_contact.is_none() && complete,
        first_contact,
        contacts: contact_instants,
        timeline,
        complete,
        stats,
        geometry: Vec::new(),
    })
}
