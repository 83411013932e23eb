//! Sphere certificates: separation or overlap proven from the centres
//! alone, used to fill the gaps the isolation leaves (`docs/helical.md`).

use crate::oracle::{Intervals, MAX_SPHERE_BOXES, MAX_WITNESS_PROBES, SPHERE_MIN_WIDTH_LOG2};
use ccd_algorithm::{sample_between, state_at, Item};
use ccd_arith::{Interval, Rat, RingOps};
use ccd_enclosure::placement::center_at;
use ccd_motion::Body;
use ccd_timeline::{Gap, Instant, Segment, State, Witness};

/// Separation or overlap proven from the centres alone, whatever the
/// orientations: each body lies in the ball of radius `max rᵢ` about its
/// centre and contains the ball of radius `min rᵢ`, so
/// `|c_a − c_b| > max r(a) + max r(b)` proves *separate* and
/// `|c_a − c_b| < max(min r(a), min r(b))` (one centre inside the other
/// body) proves *overlap*. The distance is enclosed over a box of times
/// (`f64` intervals, outward rounded); `None` when neither is proven (or a
/// body is affine).
fn sphere_state(a: &Body, b: &Body, span: &[Rat; 2], lo: &Rat, hi: &Rat) -> Option<State> {
    let t = Interval::from_rat(lo).hull(&Interval::from_rat(hi));
    let (ca, cb) = (center_at(a, span, &t)?, center_at(b, span, &t)?);
    let d2 = (0..3).fold(Interval::point(0.0), |acc, i| {
        acc.plus(&ca[i].minus(&cb[i]).square())
    });
    let max = |b: &Body| b.radii.iter().max().cloned().unwrap_or_else(Rat::zero);
    let min = |b: &Body| b.radii.iter().min().cloned().unwrap_or_else(Rat::zero);
    let outer = &max(a) + &max(b);
    let inner = min(a).max(min(b));
    if d2.lo > Interval::from_rat(&(&outer * &outer)).hi {
        Some(State::Separate)
    } else if d2.hi < Interval::from_rat(&(&inner * &inner)).lo {
        Some(State::Overlap)
    } else {
        None
    }
}

/// A gap cut into pieces proven by [`sphere_state`] (by bisection within
/// the budget) and the pieces left undecided, in order, adjacent pieces of
/// one kind merged.
fn sphere_pieces(
    q: &Intervals<'_>,
    lo: &Rat,
    hi: &Rat,
    budget: &mut usize,
) -> Vec<(Rat, Rat, Option<State>)> {
    let min_width = (hi - lo).mul_pow2(SPHERE_MIN_WIDTH_LOG2);
    let mut out: Vec<(Rat, Rat, Option<State>)> = Vec::new();
    let mut stack = vec![(lo.clone(), hi.clone())];
    let point = |t: &Rat| sphere_state(&q.a, &q.b, &q.span, t, t).is_some();
    while let Some((l, h)) = stack.pop() {
        let state = if *budget > 0 {
            *budget -= 1;
            sphere_state(&q.a, &q.b, &q.span, &l, &h)
        } else {
            None
        };
        // Bisect only where something is provable at a point of the box
        // (an end or the midpoint): the effort goes to the boundaries of
        // the provable pieces, not into stretches where nothing is.
        let m = Rat::midpoint(&l, &h);
        let promising = || point(&l) || point(&m) || point(&h);
        if state.is_none() && *budget > 0 && &h - &l > min_width && promising() {
            stack.push((m.clone(), h));
            stack.push((l, m));
            continue;
        }
        match out.last_mut() {
            Some((_, end, s)) if *s == state && *end == l => *end = h,
            _ => out.push((l, h, state)),
        }
    }
    out
}

/// Fills the gaps with what the sphere certificates prove and probes the
/// remaining gaps for a proven non-separate instant (a witness); the
/// algorithm merges neighbouring segments of one state afterwards.
pub(crate) fn settle_gaps(q: &Intervals<'_>, items: Vec<Item>) -> Vec<Item> {
    let mut sphere_budget = MAX_SPHERE_BOXES;
    let mut probes = MAX_WITNESS_PROBES;
    let mut out: Vec<Item> = Vec::new();
    let push = |out: &mut Vec<Item>, item: Item| out.push(item);
    for item in items {
        let Item::Gap(g) = item else {
            push(&mut out, item);
            continue;
        };
        for (lo, hi, state) in sphere_pieces(q, &g.lo, &g.hi, &mut sphere_budget) {
            match state {
                Some(state) => push(
                    &mut out,
                    Item::Segment(Segment {
                        state,
                        start: Instant::exact(lo),
                        end: Instant::exact(hi),
                        certified: true,
                    }),
                ),
                None => {
                    let mut witness = None;
                    if probes > 0 {
                        probes -= 1;
                        let t = sample_between(&lo, &hi);
                        let d = state_at(q, &t);
                        if d.certified && d.state != State::Separate {
                            witness = Some(Witness { t, state: d.state });
                        }
                    }
                    push(
                        &mut out,
                        Item::Gap(Gap {
                            lo,
                            hi,
                            reason: g.reason.clone(),
                            witness,
                        }),
                    );
                }
            }
        }
    }
    out
}
