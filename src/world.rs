//! Worlds of many bodies: the certified broad phase (`ccd-broad`), then the
//! exact pair query on every candidate pair, in parallel (rayon), in a
//! deterministic order; or, in first-contact mode, only as many pair
//! queries as the earliest contact in the world needs.

use ccd_arith::Rat;
use ccd_broad::{broad_phase, slice_start, sweep, BroadPhase, Candidate, DEFAULT_DEPTH};
use ccd_scene::World;
use ccd_timeline::{Instant, Outcome};
use rayon::prelude::*;
use std::time::Instant as Clock;

use crate::{run, CcdError, Options};

/// Most candidate pairs (pairs the broad phase cannot prove separate) a
/// world may send to the exact query; more is refused with
/// [`ccd_broad::BroadError::TooManyCandidates`] before any query runs
/// (a world whose bodies crowd together, e.g. many bodies at one place).
/// Each candidate's result is kept for the answer, and its JSON: up to
/// about 10 kB a pair, so the cap keeps a world's answer to a few GB.
pub const MAX_CANDIDATE_PAIRS: usize = 500_000;

/// The exact query's answer for one candidate pair.
#[derive(Clone, Debug)]
pub struct PairResult {
    /// Index of the first body (`a < b`, file order).
    pub a: usize,
    /// Index of the second body.
    pub b: usize,
    /// The two cannot touch before this instant (the start of the first
    /// slice in which their certified boxes overlap).
    pub not_before: Rat,
    /// The pair's outcome, or why it has none (e.g. an effort bound).
    pub result: Result<Outcome, CcdError>,
}

impl PairResult {
    /// Proven to touch or overlap somewhere on the span.
    pub fn colliding(&self) -> bool {
        matches!(&self.result, Ok(o) if !o.collision_free && o.undecided.is_none())
    }
    /// Neither proven separate throughout nor proven to collide (an error,
    /// or `collision_free: null`).
    pub fn undecided(&self) -> bool {
        !matches!(&self.result, Ok(o) if o.undecided.is_none())
    }
}

/// The earliest contact in the world.
#[derive(Clone, Debug, PartialEq)]
pub struct WorldContact {
    /// Its instant: the earliest first contact among the pairs (smallest
    /// `lo`, then file order). `certified` is `false` when the pair's
    /// instant is not certified, or when a pair that might touch earlier
    /// (its `not_before` below `hi`) is undecided.
    pub instant: Instant,
    /// The pair `(a, b)`, `a < b`.
    pub pair: (usize, usize),
}

/// What the broad phase did.
#[derive(Clone, Debug, PartialEq)]
pub struct BroadStats {
    /// Pairs sent to the exact query (or, in first-contact mode, that
    /// might have been).
    pub candidates: usize,
    /// Pairs **proven separate** throughout: in every slice disjoint
    /// certified boxes or a separating plane; never queried.
    pub pruned: u64,
    /// Pairs whose boxes overlap in some slice (what boxes alone would
    /// have sent to the exact query).
    pub box_overlaps: usize,
    /// The number of slices of the span the boxes are over.
    pub slices: usize,
    /// Wall time of the boxes and the sweep, in seconds.
    pub seconds: f64,
}

/// The answer for a world.
#[derive(Clone, Debug)]
pub struct WorldOutcome {
    /// `[t0, t1]`.
    pub span: [Rat; 2],
    /// The bodies' names, in file order.
    pub bodies: Vec<String>,
    /// The queried candidate pairs, ordered by `(a, b)`: every candidate,
    /// or in first-contact mode those the search needed.
    pub pairs: Vec<PairResult>,
    /// The earliest contact in the world; `None` when no queried pair
    /// touches or overlaps.
    pub first_contact: Option<WorldContact>,
    /// The broad phase's counts.
    pub broad_phase: BroadStats,
    /// `true` when every candidate pair was queried over the whole span
    /// (not in first-contact mode).
    pub complete: bool,
}

impl WorldOutcome {
    /// The pairs proven to touch or overlap, ordered by `(a, b)`.
    pub fn colliding(&self) -> Vec<(usize, usize)> {
        self.pairs
            .iter()
            .filter(|p| p.colliding())
            .map(|p| (p.a, p.b))
            .collect()
    }
    /// The queried pairs neither proven separate nor proven colliding.
    pub fn undecided(&self) -> Vec<(usize, usize)> {
        self.pairs
            .iter()
            .filter(|p| p.undecided())
            .map(|p| (p.a, p.b))
            .collect()
    }
    /// Everything reported is proven: every pair's outcome certified, no
    /// pair undecided, the first contact certified.
    pub fn certified(&self) -> bool {
        self.pairs
            .iter()
            .all(|p| matches!(&p.result, Ok(o) if o.certified()))
            && self
                .first_contact
                .as_ref()
                .is_none_or(|c| c.instant.certified)
    }
}

/// Runs a world: each body's motion is checked (an invalid one is an error
/// naming it, `body[3] "arm-2".motion.orientation`), the certified broad
/// phase proves most pairs separate, and [`run`] answers the candidate
/// pairs in parallel on rayon's pool.
///
/// With `options.first_contact_only` it finds the world's earliest contact
/// without the later ones: candidates go in the order of their
/// `not_before` bound, a few per worker at a time, each a first-contact
/// query, and the search stops once the earliest contact found ends
/// (`hi`) no later than the next candidate's bound: no remaining pair can
/// touch strictly earlier.
pub fn run_world(world: &World, options: &Options) -> Result<WorldOutcome, CcdError> {
    world.validate()?;
    check_motions(world)?;
    let clock = Clock::now();
    let boxes: Vec<_> = world
        .bodies
        .par_iter()
        .map(|b| sweep(&b.body, &world.span, DEFAULT_DEPTH))
        .collect();
    let BroadPhase {
        candidates,
        pruned,
        box_overlaps,
    } = broad_phase(&boxes, MAX_CANDIDATE_PAIRS)?;
    let broad = BroadStats {
        candidates: candidates.len(),
        pruned,
        box_overlaps,
        slices: 1 << DEFAULT_DEPTH,
        seconds: clock.elapsed().as_secs_f64(),
    };
    let candidates: Vec<(Candidate, Rat)> = candidates
        .into_iter()
        .map(|c| (c, slice_start(&world.span, DEFAULT_DEPTH, c.first_slice)))
        .collect();
    let query = |(c, not_before): &(Candidate, Rat)| PairResult {
        a: c.a,
        b: c.b,
        not_before: not_before.clone(),
        result: run(&world.pair(c.a, c.b), options).map_err(|e| rename(e, world, c)),
    };
    let mut pairs: Vec<PairResult> = if options.first_contact_only {
        earliest(candidates, &query)
    } else {
        candidates.par_iter().map(query).collect()
    };
    // An option the pair query refuses (e.g. float arithmetic on a helical
    // body) is the caller's error, not the pair's.
    if let Some(e) = pairs.iter().find_map(|p| match &p.result {
        Err(e @ CcdError::Option { .. }) => Some(e.clone()),
        _ => None,
    }) {
        return Err(e);
    }
    pairs.sort_by_key(|p| (p.a, p.b));
    let first_contact = first_contact(&pairs);
    Ok(WorldOutcome {
        span: world.span.clone(),
        bodies: world.bodies.iter().map(|b| b.name.clone()).collect(),
        complete: !options.first_contact_only,
        pairs,
        first_contact,
        broad_phase: broad,
    })
}

/// Every rational body's motion is valid over the span (a quaternion curve
/// that vanishes, a singular `L(t)`, a weight curve with a root), decided
/// exactly once per body; the first invalid body in file order is the
/// error.
fn check_motions(world: &World) -> Result<(), CcdError> {
    let checks: Vec<Result<(), CcdError>> = world
        .bodies
        .par_iter()
        .enumerate()
        .map(|(i, b)| {
            if !b.body.motion.is_rational() {
                return Ok(());
            }
            ccd_motion::placed_quadric(&b.body, &world.span)
                .map(|_| ())
                .map_err(|e| CcdError::motion(&world.body_field(i), e))
        })
        .collect();
    checks.into_iter().collect()
}

/// A pair's error about its body `a` or `b` names the world's body.
fn rename(e: CcdError, world: &World, c: &Candidate) -> CcdError {
    match e {
        CcdError::Motion { field, source } => {
            let (body, rest) = field.split_once('.').unwrap_or(("", &field));
            let i = if body == "a" { c.a } else { c.b };
            CcdError::Motion {
                field: format!("{}.{rest}", world.body_field(i)),
                source,
            }
        }
        e => e,
    }
}

/// The first-contact search (see [`run_world`]): `candidates` with their
/// `not_before` bounds.
fn earliest(
    mut candidates: Vec<(Candidate, Rat)>,
    query: &(impl Fn(&(Candidate, Rat)) -> PairResult + Sync),
) -> Vec<PairResult> {
    candidates.sort_by(|(c, t), (d, u)| t.cmp(u).then((c.a, c.b).cmp(&(d.a, d.b))));
    let batch = 4 * rayon::current_num_threads().max(1);
    let mut done: Vec<PairResult> = Vec::new();
    // The smallest `hi` of a first contact found so far.
    let mut best: Option<Rat> = None;
    for chunk in candidates.chunks(batch) {
        if best.as_ref().is_some_and(|hi| chunk[0].1 >= *hi) {
            break;
        }
        let results: Vec<PairResult> = chunk.par_iter().map(query).collect();
        for fc in results
            .iter()
            .filter_map(|r| r.result.as_ref().ok()?.first_contact.as_ref())
        {
            if best.as_ref().is_none_or(|hi| fc.hi < *hi) {
                best = Some(fc.hi.clone());
            }
        }
        done.extend(results);
    }
    done
}

/// The earliest first contact among the pairs (smallest `lo`, then file
/// order), certified only when its instant is and no undecided pair could
/// touch before its `hi`.
fn first_contact(pairs: &[PairResult]) -> Option<WorldContact> {
    let (p, fc) = pairs
        .iter()
        .filter_map(|p| Some((p, p.result.as_ref().ok()?.first_contact.as_ref()?)))
        .min_by(|(p, x), (q, y)| x.lo.cmp(&y.lo).then((p.a, p.b).cmp(&(q.a, q.b))))?;
    let unsure = pairs.iter().any(|q| q.undecided() && q.not_before < fc.hi);
    let mut instant = fc.clone();
    instant.certified &= !unsure;
    Some(WorldContact {
        instant,
        pair: (p.a, p.b),
    })
}
