//! Sweep-and-prune over the bodies' boxes, then the per-slice test.

use ccd_arith::{Int, Rat};

use crate::{Aabb, Swept};

/// A pair that the broad phase could not prove separate: in some slice
/// neither their boxes nor a plane separate them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Candidate {
    /// The first body (index in the world, `a < b`).
    pub a: usize,
    /// The second body.
    pub b: usize,
    /// The first slice in which they are not proven apart: the two cannot
    /// touch before [`slice_start`] of it.
    pub first_slice: usize,
}

/// What the broad phase found.
#[derive(Clone, Debug, PartialEq)]
pub struct BroadPhase {
    /// The candidate pairs, ordered by `(a, b)`.
    pub candidates: Vec<Candidate>,
    /// How many pairs are **proven separate** over the whole span: in
    /// every slice disjoint boxes or a plane separate them.
    pub pruned: u64,
    /// How many pairs have overlapping boxes in some slice (the candidates
    /// of boxes alone; the separating planes prove the rest of them apart).
    pub box_overlaps: usize,
}

/// Why the broad phase gave no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BroadError {
    /// More candidate pairs than allowed (the bodies crowd together or
    /// sweep through most of the world), refused before the exact queries
    /// rather than run.
    #[error("limit `candidate pairs`: more than {limit} pairs of bodies could not be proven separate by the broad phase")]
    TooManyCandidates {
        /// The limit.
        limit: usize,
    },
    /// The bodies' box lists do not all have the same number of slices.
    #[error("the bodies' boxes are over different numbers of slices")]
    Slices,
}

/// The start `t_k = t0 + k·(t1 − t0)/2^depth` of slice `k` (exact).
pub fn slice_start(span: &[Rat; 2], depth: u32, k: usize) -> Rat {
    let width = &span[1] - &span[0];
    let frac = Rat::dyadic(Int::from_u64(k as u64), u64::from(depth));
    &span[0] + &(&width * &frac)
}

/// The candidate pairs: pairs of bodies (all swept over the same slices)
/// not proven apart in some slice.
///
/// Sweep-and-prune on the bodies' whole-span boxes (the hull of their
/// slices) along the axis where the boxes' middles spread most, then the
/// per-slice test [`Swept::apart`] (disjoint boxes, or a separating plane)
/// on each pair whose whole-span boxes overlap. A pair is pruned only when
/// it is proven apart in every slice, so every pruned pair is separate
/// throughout. Fails rather than collect more than `max_candidates` pairs.
pub fn broad_phase(bodies: &[Swept], max_candidates: usize) -> Result<BroadPhase, BroadError> {
    let slices = bodies.first().map_or(0, Swept::slices);
    if bodies.iter().any(|b| b.slices() != slices) {
        return Err(BroadError::Slices);
    }
    let whole: Vec<Aabb> = bodies
        .iter()
        .map(|b| {
            let first = b.boxes.first().copied().unwrap_or(Aabb::ENTIRE);
            b.boxes.iter().fold(first, |h, x| h.hull(x))
        })
        .collect();
    let axis = sweep_axis(&whole);
    let mut order: Vec<usize> = (0..whole.len()).collect();
    order.sort_by(|&i, &j| {
        whole[i].lo[axis]
            .total_cmp(&whole[j].lo[axis])
            .then(i.cmp(&j))
    });
    let mut active: Vec<usize> = Vec::new();
    let mut candidates = Vec::new();
    let mut box_overlaps = 0;
    for &i in &order {
        let lo = whole[i].lo[axis];
        active.retain(|&j| whole[j].hi[axis] >= lo);
        for &j in &active {
            if !whole[i].overlaps(&whole[j]) {
                continue;
            }
            let (a, b) = (i.min(j), i.max(j));
            let (sa, sb) = (&bodies[a], &bodies[b]);
            let Some(first_box) = (0..slices).find(|&k| sa.boxes[k].overlaps(&sb.boxes[k])) else {
                continue;
            };
            box_overlaps += 1;
            if sa.apart_throughout(sb) {
                continue;
            }
            if let Some(first_slice) = (first_box..slices).find(|&k| !sa.apart(sb, k)) {
                if candidates.len() == max_candidates {
                    return Err(BroadError::TooManyCandidates {
                        limit: max_candidates,
                    });
                }
                candidates.push(Candidate { a, b, first_slice });
            }
        }
        active.push(i);
    }
    candidates.sort_by_key(|c| (c.a, c.b));
    let n = bodies.len() as u64;
    let pairs = n * n.saturating_sub(1) / 2;
    Ok(BroadPhase {
        box_overlaps,
        pruned: pairs - candidates.len() as u64,
        candidates,
    })
}

/// The axis along which the finite box middles have the largest variance
/// (fewest boxes overlap in projection, for typical worlds).
fn sweep_axis(boxes: &[Aabb]) -> usize {
    let spread = |axis: usize| {
        let mids: Vec<f64> = boxes
            .iter()
            .map(|b| b.mid(axis))
            .filter(|m| m.is_finite())
            .collect();
        let n = mids.len().max(1) as f64;
        let mean = mids.iter().sum::<f64>() / n;
        mids.iter().map(|m| (m - mean) * (m - mean)).sum::<f64>() / n
    };
    let s = [spread(0), spread(1), spread(2)];
    (0..3).fold(0, |best, k| if s[k] > s[best] { k } else { best })
}
