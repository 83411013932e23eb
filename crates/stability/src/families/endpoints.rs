//! The family `endpoints`: contacts exactly at `t0` and/or `t1` on the
//! span `[1/3, 2]` — touch-and-depart, approach-and-touch, grazes at the
//! ends.

use super::homothetic::Pair;
use super::{int, rat, tilt, v3};
use crate::{Case, Level, StabilityError, Surd};
use ccd_arith::Rat;
use ccd_motion::{Bezier, Vec3};

fn two_point(a: Vec3, b: Vec3) -> Bezier<Vec3> {
    Bezier {
        points: vec![a, b],
        weights: None,
    }
}

pub(super) fn endpoints(_level: Level) -> Result<Vec<Case>, StabilityError> {
    let family = "endpoints";
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: rat(1, 3),
        span: [rat(1, 3), int(2)],
    };
    let g = e.grow();
    let rx = &g * &e.radii[0];
    let ry = &g * &e.radii[1];
    let (zero, one) = (Surd::rational(Rat::zero()), Surd::rational(Rat::one()));
    let on_x = |a: Rat, b: Rat| {
        two_point(
            v3(a, Rat::zero(), Rat::zero()),
            v3(b, Rat::zero(), Rat::zero()),
        )
    };
    let on_y = |a: Rat, b: Rat| {
        two_point(
            v3(a, ry.clone(), Rat::zero()),
            v3(b, ry.clone(), Rat::zero()),
        )
    };
    let r0 = e.radii[0].clone();
    let cases = [
        (
            "touch-at-t0-depart",
            on_x(rx.clone(), &rx + &int(1)),
            vec![zero.clone()],
        ),
        (
            "approach-touch-at-t1",
            on_x(&rx + &int(1), rx.clone()),
            vec![one.clone()],
        ),
        (
            "overlap-until-t1",
            on_x(&rx - &int(1), rx.clone()),
            vec![one.clone()],
        ),
        (
            "touch-at-both-ends",
            on_x(rx.clone(), -&rx),
            vec![zero.clone(), one.clone()],
        ),
        ("graze-at-t0", on_y(Rat::zero(), r0.clone()), vec![zero]),
        ("graze-at-t1", on_y(-&r0, Rat::zero()), vec![one]),
    ];
    cases
        .into_iter()
        .map(|(name, rel, contacts)| e.case(family, name.into(), None, &rel, contacts))
        .collect()
}
