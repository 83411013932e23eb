//! The family `throughout`: states that hold over the whole span —
//! touching throughout (sliding on a rational arc of the boundary, moving
//! together), identical, concentric and nested bodies (overlap), and bodies
//! far apart (separate).

use super::homothetic::Pair;
use super::{identity, int, rat, rotate, tilt, unit, v3};
use crate::truth::Truth;
use crate::{Case, Level, StabilityError};
use ccd_arith::Rat;
use ccd_exact::{Scene, State};
use ccd_motion::{Bezier, Body, Motion, Quat, Vec3};

pub(super) fn throughout(_level: Level) -> Result<Vec<Case>, StabilityError> {
    let family = "throughout";
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: rat(1, 3),
        span: unit(),
    };
    let g = e.grow();
    let mut out = Vec::new();

    // Touching throughout, sliding on a rational arc of ∂((1+s)E): the unit
    // circle arc from angle −θ to θ with cos θ = 3/5 is the rational
    // quadratic Bézier (3/5, −4/5), (5/3, 0), (3/5, 4/5) with weights
    // (1, 3/5, 1); scaled by (1+s)·r it lies on the boundary.
    let sc = |x: Rat, y: Rat| {
        v3(
            &(&g * &e.radii[0]) * &x,
            &(&g * &e.radii[1]) * &y,
            Rat::zero(),
        )
    };
    let arc = Bezier {
        points: vec![
            sc(rat(3, 5), rat(-4, 5)),
            sc(rat(5, 3), Rat::zero()),
            sc(rat(3, 5), rat(4, 5)),
        ],
        weights: Some(vec![int(1), rat(3, 5), int(1)]),
    };
    out.push(e.case(family, "touch-arc".into(), None, &arc, vec![])?);

    // Touching throughout, moving together along a cubic.
    let path = Bezier {
        points: vec![
            v3(int(0), int(0), int(0)),
            v3(int(5), int(-2), int(1)),
            v3(int(-3), int(4), int(2)),
            v3(int(1), int(1), int(-6)),
        ],
        weights: None,
    };
    let offset = rotate(&e.q, &v3(&g * &e.radii[0], Rat::zero(), Rat::zero()));
    let moved = |p: &Vec3| std::array::from_fn(|i| &p[i] + &offset[i]);
    let together = Scene {
        span: unit(),
        a: e.body_a(Motion::Translation {
            center: path.clone(),
            orientation: e.q.clone(),
        }),
        b: e.body_b(Bezier {
            points: path.points.iter().map(moved).collect(),
            weights: None,
        }),
    };
    out.push(Case {
        name: format!("{family}-touch-together"),
        scene: together,
        truth: Truth::throughout(family, "touch-together".into(), State::Touch),
    });

    // Identical bodies on the same path, concentric different bodies,
    // nested bodies: overlap throughout. Far apart: separate throughout.
    let mover = |radii: Vec3, q: Quat, shift: Vec3| Body {
        radii,
        motion: Motion::Translation {
            center: Bezier {
                points: path
                    .points
                    .iter()
                    .map(|p| std::array::from_fn(|i| &p[i] + &shift[i]))
                    .collect(),
                weights: None,
            },
            orientation: q,
        },
    };
    let zero = v3(Rat::zero(), Rat::zero(), Rat::zero());
    let cases = [
        (
            "identical",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            State::Overlap,
        ),
        (
            "concentric",
            mover(v3(int(3), int(1), int(1)), identity(), zero.clone()),
            mover(v3(int(1), int(3), rat(1, 2)), tilt(), zero.clone()),
            State::Overlap,
        ),
        (
            "nested",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(
                e.radii.clone().map(|r| &r * &rat(1, 2)),
                e.q.clone(),
                zero.clone(),
            ),
            State::Overlap,
        ),
        (
            "far-apart",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(e.radii.clone(), tilt(), v3(int(10), int(0), int(0))),
            State::Separate,
        ),
    ];
    for (name, a, b, state) in cases {
        out.push(Case {
            name: format!("{family}-{name}"),
            scene: Scene { span: unit(), a, b },
            truth: Truth::throughout(family, name.into(), state),
        });
    }
    Ok(out)
}
