//! Worlds (issue 15): on random worlds the world answer equals the pairwise
//! answer for every pair, no touching pair is ever pruned (pairs built to
//! touch exactly, and shifted by 1e-30 either way), and the world's
//! first-contact mode finds the earliest contact of the full run.

use ccd_arith::Rat;
use ccd_exact::{run, run_world, to_json, world_to_json, Options, World};
use ccd_motion::{Bezier, Body, Motion, Quat, Vec3};
use ccd_scene::NamedBody;
use proptest::prelude::*;

fn rat(lo: i64, hi: i64, den: i64) -> impl Strategy<Value = Rat> + Clone {
    (lo..=hi).prop_map(move |p| Rat::from_frac(p, den))
}
fn vec3(half: i64) -> impl Strategy<Value = Vec3> + Clone {
    [
        rat(-half * 4, half * 4, 4),
        rat(-half * 4, half * 4, 4),
        rat(-half * 4, half * 4, 4),
    ]
}
fn quat() -> impl Strategy<Value = Quat> + Clone {
    [rat(-3, 3, 1), rat(-3, 3, 1), rat(-3, 3, 1), rat(-3, 3, 1)]
        .prop_filter("nonzero", |q| q.iter().any(|x| !x.is_zero()))
}

/// Small motions that keep each exact query quick: static, linear or
/// quadratic (possibly weighted) translation, and rigid with a linear
/// quaternion curve.
fn body() -> impl Strategy<Value = Body> {
    let radii = [rat(1, 8, 4), rat(1, 8, 4), rat(1, 8, 4)];
    let motion = prop_oneof![
        (vec3(4), quat()).prop_map(|(center, orientation)| Motion::Static {
            center,
            orientation
        }),
        (
            prop::collection::vec(vec3(4), 2..=3),
            quat(),
            prop::option::of(rat(1, 3, 1))
        )
            .prop_map(|(points, orientation, w)| {
                let weights = w
                    .filter(|_| points.len() == 3)
                    .map(|w| vec![Rat::one(), w, Rat::one()]);
                Motion::Translation {
                    center: Bezier { points, weights },
                    orientation,
                }
            }),
        (quat(), quat(), vec3(4), vec3(4))
            // q1 = −c·q0 (c > 0) makes the curve pass through 0 on the span:
            // no rotation there, an invalid body (QuaternionVanishes).
            .prop_filter("a quaternion curve through zero", |(q0, q1, _, _)| {
                let parallel = (0..4).all(|i| (0..4).all(|j| &q0[i] * &q1[j] == &q0[j] * &q1[i]));
                let dot = (0..4).fold(Rat::zero(), |s, i| s + &q0[i] * &q1[i]);
                !(parallel && dot.signum() < 0)
            })
            .prop_map(|(q0, q1, c0, c1)| Motion::Rigid {
                orientation: Bezier {
                    points: vec![q0, q1],
                    weights: None
                },
                center: Bezier {
                    points: vec![c0, c1],
                    weights: None
                },
            }),
    ];
    (radii, motion).prop_map(|(radii, motion)| Body { radii, motion })
}

fn world(bodies: Vec<Body>) -> World {
    World {
        span: [Rat::zero(), Rat::one()],
        bodies: bodies
            .into_iter()
            .enumerate()
            .map(|(i, body)| NamedBody {
                name: format!("b{i}"),
                body,
            })
            .collect(),
    }
}

fn options() -> Options {
    Options {
        contact_geometry: false,
        ..Options::default()
    }
}

/// The world's answers against each pair's own: candidates' results are the
/// pair results, pruned pairs are separate throughout, `colliding` and the
/// first contact follow. A rigid quaternion curve through zero makes the
/// world an error exactly when some pair is one too.
fn check_world(w: &World) -> Result<(), TestCaseError> {
    let opts = options();
    let got = match run_world(w, &opts) {
        Ok(g) => g,
        Err(e) => {
            let any_pair_fails = (0..w.bodies.len())
                .any(|i| (0..w.bodies.len()).any(|j| i != j && run(&w.pair(i, j), &opts).is_err()));
            prop_assert!(
                any_pair_fails || w.bodies.len() < 2,
                "world error {e} but no pair fails"
            );
            return Ok(());
        }
    };
    let n = w.bodies.len();
    let mut colliding = Vec::new();
    let mut earliest: Option<(Rat, (usize, usize))> = None;
    let mut cands = got.pairs.iter().peekable();
    for i in 0..n {
        for j in i + 1..n {
            let alone = run(&w.pair(i, j), &opts).expect("valid pair");
            match cands.next_if(|p| (p.a, p.b) == (i, j)) {
                Some(p) => {
                    let mine = p.result.as_ref().expect("the pair ran");
                    prop_assert_eq!(to_json(mine), to_json(&alone), "pair ({}, {})", i, j);
                    if let Some(fc) = &alone.first_contact {
                        prop_assert!(
                            p.not_before <= fc.hi,
                            "({i}, {j}) bound {} after {}",
                            p.not_before,
                            fc.hi
                        );
                    }
                }
                None => prop_assert!(
                    alone.collision_free,
                    "pair ({i}, {j}) pruned but not separate: {:?}",
                    alone.timeline
                ),
            }
            if !alone.collision_free {
                colliding.push((i, j));
            }
            if let Some(fc) = &alone.first_contact {
                if earliest.as_ref().is_none_or(|(lo, _)| fc.lo < *lo) {
                    earliest = Some((fc.lo.clone(), (i, j)));
                }
            }
        }
    }
    prop_assert!(cands.next().is_none(), "pairs out of order");
    prop_assert_eq!(got.colliding(), colliding.clone());
    let json = world_to_json(&got);
    prop_assert_eq!(
        json["colliding"].as_array().map(Vec::len),
        Some(colliding.len())
    );
    prop_assert_eq!(
        json["broad_phase"]["pruned"].as_u64(),
        Some((n * (n - 1) / 2 - got.pairs.len()) as u64)
    );
    prop_assert_eq!(
        got.first_contact
            .as_ref()
            .map(|c| (c.instant.lo.clone(), c.pair)),
        earliest.clone()
    );

    // First-contact mode: the same earliest instant (enclosures of one
    // instant overlap), without isolating later roots.
    let fast = run_world(
        w,
        &Options {
            first_contact_only: true,
            ..opts
        },
    )
    .expect("ran in full");
    match (&fast.first_contact, &got.first_contact) {
        (None, None) => {}
        (Some(f), Some(g)) => {
            prop_assert!(
                f.instant.lo <= g.instant.hi && g.instant.lo <= f.instant.hi,
                "{f:?} vs {g:?}"
            );
            prop_assert!(fast
                .pairs
                .iter()
                .all(|p| p.result.as_ref().is_ok_and(|o| o.contacts.len() <= 1)));
        }
        (f, g) => prop_assert!(false, "first-contact mode {f:?}, full {g:?}"),
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn world_answer_is_the_pairwise_answer(bodies in prop::collection::vec(body(), 2..=6)) {
        check_world(&world(bodies))?;
    }

    /// Pairs built to touch: A and B share an orientation R(q); in that
    /// frame B moves along x at height d over A, so at the instant its
    /// centre passes x = 0 they touch when d = ra1 + rb1 (separated by the
    /// plane y = ra1 otherwise). d is shifted by -1e-30 (a brief overlap), 0
    /// (an exact touch) or +1e-30 (a graze that misses). A touching pair is
    /// never pruned; the graze gets the pairwise answer.
    #[test]
    fn no_touching_pair_is_pruned(
        ra in [rat(1, 8, 4), rat(1, 8, 4), rat(1, 8, 4)],
        rb in [rat(1, 8, 4), rat(1, 8, 4), rat(1, 8, 4)],
        q in quat(),
        from in rat(1, 40, 4),
        to in rat(1, 40, 4),
        offset in vec3(4),
        shift in -1i64..=1,
        others in prop::collection::vec(body(), 0..=3),
    ) {
        let eps = Rat::parse_exact("1e-30").unwrap();
        let d = &(&ra[1] + &rb[1]) + &(&eps * &Rat::from(shift));
        let rotate = |v: [Rat; 3]| -> Vec3 {
            let [w, x, y, z] = &q;
            let two = Rat::from(2);
            let m = [
                [w * w + x * x - y * y - z * z, &two * &(x * y - w * z), &two * &(x * z + w * y)],
                [&two * &(x * y + w * z), w * w - x * x + y * y - z * z, &two * &(y * z - w * x)],
                [&two * &(x * z - w * y), &two * &(y * z + w * x), w * w - x * x - y * y + z * z],
            ];
            let n = w * w + x * x + y * y + z * z;
            std::array::from_fn(|k| (0..3).fold(offset[k].clone(), |s, j| s + &m[k][j] * &v[j] / &n))
        };
        let a = Body { radii: ra.clone(), motion: Motion::Static { center: rotate([Rat::zero(), Rat::zero(), Rat::zero()]), orientation: q.clone() } };
        let b = Body {
            radii: rb.clone(),
            motion: Motion::Translation {
                center: Bezier { points: vec![rotate([-from.clone(), d.clone(), Rat::zero()]), rotate([to.clone(), d.clone(), Rat::zero()])], weights: None },
                orientation: q.clone(),
            },
        };
        let mut bodies = others;
        bodies.insert(0, a);
        bodies.push(b);
        let w = world(bodies);
        let last = w.bodies.len() - 1;
        let got = run_world(&w, &options()).expect("valid world");
        let pair = got.pairs.iter().find(|p| (p.a, p.b) == (0, last));
        let alone = run(&w.pair(0, last), &options()).unwrap();
        if shift <= 0 {
            let p = pair.expect("a touching pair is a candidate");
            prop_assert!(p.colliding(), "touching pair not colliding: {:?}", p.result);
            prop_assert!(!alone.collision_free);
            // Touch at u* = from / (from + to): within the enclosure.
            let u = &from / &(&from + &to);
            let fc = alone.first_contact.as_ref().unwrap();
            if shift == 0 {
                prop_assert!(fc.lo <= u && u <= fc.hi, "{fc:?} vs {u}");
            }
            prop_assert!(p.not_before <= fc.hi);
        } else {
            prop_assert!(alone.collision_free, "the graze misses by 1e-30");
            prop_assert!(pair.is_none_or(|p| !p.colliding()));
        }
        check_world(&w)?;
    }
}

#[test]
fn world_errors_name_the_body() {
    // A quaternion curve through zero at t = 1/2: an error naming the body,
    // even though the broad phase would prune its pairs.
    let text = r#"
        [[body]]
        name = "ball"
        radii = [1, 1, 1]
        [[body]]
        name = "arm-2"
        radii = [1, 1, 1]
        motion = { kind = "rigid", orientation = [[1, 0, 0, 0], [-1, 0, 0, 0]], center = [[100, 0, 0]] }
    "#;
    let ccd_scene::SceneFile::World(w) = ccd_scene::SceneFile::from_toml(text).unwrap() else {
        panic!()
    };
    let e = run_world(&w, &Options::default()).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("field `body[1] \"arm-2\".motion.orientation`"),
        "{e}"
    );
}

#[test]
fn the_shipped_world_agrees_with_its_pairs() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/scenes/world-crossing.toml"
    ))
    .unwrap();
    let ccd_scene::SceneFile::World(w) = ccd_scene::SceneFile::from_toml(&text).unwrap() else {
        panic!()
    };
    check_world(&w).unwrap();
    let got = run_world(&w, &options()).unwrap();
    let names = |(a, b): (usize, usize)| (got.bodies[a].as_str(), got.bodies[b].as_str());
    let colliding: Vec<_> = got.colliding().into_iter().map(names).collect();
    assert_eq!(
        colliding,
        [("left", "right"), ("rod", "tumbler"), ("coil", "post")]
    );
    let fc = got.first_contact.unwrap();
    assert_eq!(names(fc.pair), ("coil", "post"));
    assert!(got.broad_phase.pruned >= 20, "{:?}", got.broad_phase);
}

#[test]
fn a_crowded_world_stops_at_the_candidate_cap() {
    // 1001 balls at one place: 500500 pairs, none provably separate.
    let ball = Body {
        radii: [1, 1, 1].map(Rat::from),
        motion: Motion::at_origin(),
    };
    let w = world(vec![ball; 1001]);
    let e = run_world(&w, &options()).unwrap_err();
    assert!(
        e.to_string()
            .starts_with("limit `candidate pairs`: more than 500000"),
        "{e}"
    );
}
