//! The CCD timeline against an independent check: at random rational
//! instants, the state the timeline gives must equal the static classifier's
//! answer for the two ellipsoids placed at that instant (placements computed
//! here by de Casteljau over ℚ, not by the engine's polynomial pipeline).

use ccd_arith::Rat;
use ccd_exact::{run, Options, Outcome, Scene, State};
use ccd_motion::{Bezier, Body, Motion};
use ccd_quadric::{classify_pair, Configuration, Ellipsoid};
use proptest::prelude::*;

/// De Casteljau at `u` over ℚ, coordinate-wise, with optional weights.
fn eval_bezier<const N: usize>(c: &Bezier<[Rat; N]>, u: &Rat) -> [Rat; N] {
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

fn placed(body: &Body, u: &Rat) -> Ellipsoid {
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
fn state_at(out: &Outcome, t: &Rat) -> Option<State> {
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

fn small() -> impl Strategy<Value = Rat> {
    (-12i64..=12, 1i64..=4).prop_map(|(p, q)| Rat::from_frac(p, q))
}
fn positive() -> impl Strategy<Value = Rat> {
    (1i64..=8, 1i64..=4).prop_map(|(p, q)| Rat::from_frac(p, q))
}
fn vec3() -> impl Strategy<Value = [Rat; 3]> {
    [small(), small(), small()]
}
fn quat() -> impl Strategy<Value = [Rat; 4]> {
    [small(), small(), small(), small()].prop_filter("nonzero", |q| q.iter().any(|c| !c.is_zero()))
}

fn body() -> impl Strategy<Value = Body> {
    let radii = [positive(), positive(), positive()];
    let motion = prop_oneof![
        (vec3(), quat()).prop_map(|(center, orientation)| Motion::Static {
            center,
            orientation
        }),
        (proptest::collection::vec(vec3(), 1..=3), quat()).prop_map(|(points, orientation)| {
            Motion::Translation {
                center: Bezier {
                    points,
                    weights: None,
                },
                orientation,
            }
        }),
        (
            proptest::collection::vec(quat(), 1..=2),
            proptest::collection::vec(vec3(), 1..=2)
        )
            .prop_map(|(q, c)| Motion::Rigid {
                orientation: Bezier {
                    points: q,
                    weights: None
                },
                center: Bezier {
                    points: c,
                    weights: None
                },
            }),
    ];
    (radii, motion).prop_map(|(radii, motion)| Body { radii, motion })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn timeline_matches_static_classification(a in body(), b in body(), samples in proptest::collection::vec((0i64..=1000, 1i64..=1000), 6)) {
        let scene = Scene { span: [Rat::zero(), Rat::one()], a, b };
        let out = match run(&scene, &Options { digits: 12, ..Options::default() }) {
            Ok(o) => o,
            // A rigid curve through the zero quaternion is a correct refusal.
            Err(ccd_exact::CcdError::Motion { .. }) => return Ok(()),
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        for (p, q) in samples {
            let u = Rat::from_frac(p.min(q), q);
            let Some(state) = state_at(&out, &u) else { continue };
            let expected = match classify_pair(&placed(&scene.a, &u), &placed(&scene.b, &u)) {
                Configuration::Separate => State::Separate,
                Configuration::ExternalTouch => State::Touch,
                Configuration::Overlap => State::Overlap,
            };
            prop_assert_eq!(state, expected, "at u = {}", u);
        }
    }
}
