//! The CCD timeline against an independent check: at random rational
//! instants, the state the timeline gives must equal the static classifier's
//! answer for the two ellipsoids placed at that instant (placements computed
//! here by de Casteljau over ℚ, not by the engine's polynomial pipeline).

mod common;

use ccd_arith::Rat;
use ccd_exact::{run, Options, Scene};
use ccd_motion::{Bezier, Body, Motion};
use common::{state_at, static_state};
use proptest::prelude::*;

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
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn timeline_matches_static_classification(a in body(), b in body(), samples in proptest::collection::vec((0i64..=1000, 1i64..=1000), 6)) {
        let scene = Scene { span: [Rat::zero(), Rat::one()], a, b };
        let out = match run(&scene, &Options { digits: 12, ..Options::default() }) {
            Ok(o) => o,
            // A rigid curve through the zero quaternion is a correct refusal.
            Err(ccd_exact::CcdError::Motion { .. }) => {
                prop_assume!(false);
                unreachable!()
            }
            Err(e) => return Err(TestCaseError::fail(e.to_string())),
        };
        let mut compared = 0;
        for (p, q) in samples {
            // Strictly inside the span.
            let u = Rat::from_frac(1 + p % (q + 1), q + 2);
            let Some(state) = state_at(&out, &u) else { continue };
            compared += 1;
            prop_assert_eq!(state, static_state(&scene, &u), "at u = {}", u);
        }
        prop_assert!(compared > 0, "no sample fell inside a segment");
    }
}
