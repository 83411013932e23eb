//! Helpers shared by the end-to-end tests: placements at a rational instant
//! computed independently of the engine (de Casteljau over ℚ), and lookups
//! in a timeline.

#![allow(dead_code)]

use ccd_arith::Rat;
use ccd_exact::{Outcome, Scene, State};
use ccd_motion::{Bezier, Body, Motion};
use ccd_quadric::{classify_pair, Configuration, Ellipsoid};

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

/// The static classifier's answer for the scene at parameter `u ∈ [0, 1]`.
pub fn static_state(scene: &Scene, u: &Rat) -> State {
    match classify_pair(&placed(&scene.a, u), &placed(&scene.b, u)) {
        Configuration::Separate => State::Separate,
        Configuration::ExternalTouch => State::Touch,
        Configuration::Overlap => State::Overlap,
    }
}
