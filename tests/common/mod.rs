//! Helpers shared by the end-to-end tests: placements at a rational instant
//! computed independently of the engine (de Casteljau over ℚ), and lookups
//! in a timeline.

#![allow(dead_code)]

use ccd_arith::{Int, Rat};
use ccd_exact::{Outcome, Scene, State};
use ccd_motion::{Bezier, Body, Motion};
use ccd_quadric::{
    affine_inverse, body_diagonal, characteristic, classify_quartic, congruence, integral,
    Ellipsoid, Mat4,
};

/// De Casteljau at `u` over ℚ, coordinate-wise, with optional weights.
pub fn eval_bezier<const N: usize>(c: &Bezier<[Rat; N]>, u: &Rat) -> [Rat; N] {
    let w = |i: usize| c.weights.as_ref().map_or(Rat::one(), |w| w[i].clone());
    let lerp = |a: &Rat, b: &Rat| &(&(&Rat::one() - u) * a) + &(u * b);
    let reduce = |mut v: Vec<Rat>| {
        while v.len() > 1 {
            v = v.windows(2).map(|p| lerp(&p[0], &p[1])).collect();
        }
        v.remove(0)
    };
    let den = reduce((0..c.points.len()).map(w).collect());
    std::array::from_fn(|k| {
        &reduce(
            c.points
                .iter()
                .enumerate()
                .map(|(i, p)| &p[k] * &w(i))
                .collect(),
        ) / &den
    })
}

pub fn placed(body: &Body, u: &Rat) -> Ellipsoid {
    let (center, orientation) = match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => (center.clone(), orientation.clone()),
        Motion::Translation {
            center,
            orientation,
        } => (eval_bezier(center, u), orientation.clone()),
        Motion::Rigid {
            orientation,
            center,
        } => (eval_bezier(center, u), eval_bezier(orientation, u)),
        other => panic!("not covered here: {other:?}"),
    };
    Ellipsoid {
        radii: body.radii.clone(),
        center,
        orientation,
    }
}

/// The timeline's state at `t`, or `None` if `t` lies in a contact's enclosure.
pub fn state_at(out: &Outcome, t: &Rat) -> Option<State> {
    for seg in &out.timeline {
        if seg.start.lo <= *t && *t <= seg.start.hi || seg.end.lo <= *t && *t <= seg.end.hi {
            if seg.start == seg.end {
                return None;
            }
            continue;
        }
        if seg.start.hi < *t && *t < seg.end.lo {
            return Some(seg.state);
        }
    }
    None
}

/// The states of a pass-through: separate, touch, overlap, touch, separate.
pub const PASS_THROUGH: [State; 5] = [
    State::Separate,
    State::Touch,
    State::Overlap,
    State::Touch,
    State::Separate,
];

/// The quadric matrix of `body` placed at parameter `u` (up to a positive
/// factor), for every rational kind: through [`placed`] for the rigid kinds,
/// through the inverse of `[L | d]` evaluated by de Casteljau for affine.
pub fn quadric_at(body: &Body, u: &Rat) -> Mat4<Rat> {
    match &body.motion {
        Motion::Affine { matrix } => {
            let flat = matrix.flattened();
            let e = eval_bezier(&flat, u);
            let l: [[Rat; 3]; 3] =
                std::array::from_fn(|r| std::array::from_fn(|k| e[4 * r + k].clone()));
            let d: [Rat; 3] = std::array::from_fn(|r| e[4 * r + 3].clone());
            congruence(
                &affine_inverse(&l, &d, &Rat::one()),
                &body_diagonal(&body.radii),
            )
        }
        _ => placed(body, u).quadric_matrix(),
    }
}

/// The static classifier's answer for the scene at parameter `u ∈ [0, 1]`
/// (rational kinds only).
pub fn static_state(scene: &Scene, u: &Rat) -> State {
    let f = characteristic(
        &integral(&quadric_at(&scene.a, u)),
        &integral(&quadric_at(&scene.b, u)),
    );
    State::from(classify_quartic(&f, Int::signum))
}
