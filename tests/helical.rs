//! End-to-end tests of the interval path (`ccd-enclosure`) for the
//! non-rational `helical` kind: the paper's Example 5.2, agreement with the
//! exact path where a helical motion is in fact rational, an uncertified
//! tangential graze, and states checked against an independent static
//! classification at sampled instants.

mod common;

use ccd_arith::Rat;
use ccd_enclosure::{run, EnclosureError, Options};
use ccd_exact::{Outcome, Scene, State};
use ccd_motion::{Body, Motion};
use ccd_quadric::{classify_pair, Ellipsoid};

fn scene_file(name: &str) -> Scene {
    let path = format!("{}/tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn scene(text: &str) -> Scene {
    Scene::from_toml(text).unwrap_or_else(|e| panic!("{e}"))
}

fn enclosure(s: &Scene, options: &Options) -> Outcome {
    run(&s.a, &s.b, &s.span, options).unwrap_or_else(|e| panic!("{e}"))
}

fn states(out: &Outcome) -> Vec<State> {
    out.timeline.iter().map(|s| s.state).collect()
}

fn holds(lo: &Rat, hi: &Rat, t: f64, slack: f64) -> bool {
    lo.to_f64() - slack <= t && t <= hi.to_f64() + slack
}

/// The timeline is in order, without gaps, from t0 to t1.
fn assert_covers(out: &Outcome) {
    let tl = &out.timeline;
    assert_eq!(tl[0].start.lo, out.span[0]);
    for w in tl.windows(2) {
        assert_eq!(w[0].end, w[1].start, "gap in {tl:?}");
    }
    if out.complete {
        assert_eq!(tl[tl.len() - 1].end.hi, out.span[1]);
    }
}

#[test]
fn paper_example_5_2() {
    let s = scene_file("paper-example-5-2.toml");
    let out = enclosure(&s, &Options::default());
    assert_eq!(states(&out), common::PASS_THROUGH);
    assert_covers(&out);
    let max_width = Rat::from_frac(1, 1_000_000_000_000_000); // 1e-15 · (t1 − t0)
    assert_eq!(out.contacts.len(), 2);
    for (c, t) in out.contacts.iter().zip([0.0749830692, 0.8913371204]) {
        assert!(c.certified, "{c:?}");
        assert!(holds(&c.lo, &c.hi, t, 1e-10), "{c:?} vs {t}");
        assert!(c.width() <= max_width, "{}", c.width());
        assert!(c.lo <= c.hi);
    }
    assert!(out
        .timeline
        .iter()
        .all(|s| s.start.certified && s.end.certified));
    assert!(!out.collision_free && out.complete);
    assert_eq!(out.first_contact.as_ref(), Some(&out.contacts[0]));
}

#[test]
fn paper_example_5_2_first_contact_and_digits() {
    let s = scene_file("paper-example-5-2.toml");
    let first = enclosure(
        &s,
        &Options {
            digits: 30,
            first_contact_only: true,
        },
    );
    assert!(!first.complete);
    assert_eq!(first.contacts.len(), 1);
    let c = &first.contacts[0];
    assert!(c.certified && holds(&c.lo, &c.hi, 0.0749830692, 1e-10));
    assert!(c.width() <= Rat::from_frac(1, 1_000_000_000_000_000).mul_pow2(-50));
    assert_eq!(states(&first), [State::Separate, State::Touch]);
}

/// A helical motion with no spin and no periodic part is a translation: the
/// interval path must agree with the exact path on the same scene written
/// as a `translation`.
fn cross_check(helical: &str, translation: &str) {
    let (h, t) = (scene(helical), scene(translation));
    let interval = enclosure(&h, &Options::default());
    let exact = ccd_exact::run(&t, &ccd_exact::Options::default()).expect("exact path runs");
    assert_eq!(states(&interval), states(&exact));
    assert_eq!(interval.contacts.len(), exact.contacts.len());
    for (i, e) in interval.contacts.iter().zip(&exact.contacts) {
        assert!(i.certified);
        assert!(i.lo <= e.hi && e.lo <= i.hi, "{i:?} vs {e:?}");
        assert!(i.width() <= Rat::from_frac(1, 1_000_000_000_000_000));
    }
    assert_eq!(interval.collision_free, exact.collision_free);
    assert_covers(&interval);
}

#[test]
fn pure_translation_agrees_with_the_exact_path() {
    // Generic shapes: the sr0 branch.
    cross_check(
        r#"
        [a]
        radii = [2, 1, 1]
        motion = { kind = "helical", axis = [0, 0, 1], rate = 0, center = { base = [11, 0, 0], velocity = [-12, 0, 0] } }
        [b]
        radii = [1, 1.5, 0.5]
        motion = { kind = "translation", center = [[3, -2, -4], [3, 2, 0]] }
        "#,
        r#"
        [a]
        radii = [2, 1, 1]
        motion = { kind = "translation", center = [[11, 0, 0], [-1, 0, 0]] }
        [b]
        radii = [1, 1.5, 0.5]
        motion = { kind = "translation", center = [[3, -2, -4], [3, 2, 0]] }
        "#,
    );
    // Example 5.1 (equal shapes, equal orientations): sr0 ≡ 0 by structure,
    // the sr11 branch (Theorems 5.4–5.5).
    cross_check(
        r#"
        [a]
        radii = [2, 1, 1]
        motion = { kind = "helical", axis = [1, 0, 0], rate = 0, center = { base = [11, 0, 0], velocity = [-12, 0, 0] } }
        [b]
        radii = [2, 1, 1]
        motion = { kind = "translation", center = [[3, -2, -4], [3, 2, 0]] }
        "#,
        &std::fs::read_to_string(format!(
            "{}/tests/scenes/paper-example-5-1.toml",
            env!("CARGO_MANIFEST_DIR")
        ))
        .expect("scene file"),
    );
}

#[test]
fn tangential_graze_is_reported_uncertified() {
    // Unit sphere a on the circle of radius 3 about the origin; unit sphere
    // b at (3, 4, 0), at distance 5 from the origin. The centres' distance
    // is √(34 − 30·cos(t − φ)), φ = atan2(4, 3): its minimum 2 = r_a + r_b
    // is reached at t = φ only, so the spheres touch there and separate
    // again without overlapping — a double root, which interval Newton
    // cannot prove.
    let s = scene(
        r#"
        span = [0, 2]
        [a]
        radii = [1, 1, 1]
        motion = { kind = "helical", axis = [0, 0, 1], rate = 1, center = { cos = [3, 0, 0], sin = [0, 3, 0], frequency = 1 } }
        [b]
        radii = [1, 1, 1]
        motion = { kind = "static", center = [3, 4, 0] }
        "#,
    );
    let out = enclosure(&s, &Options::default());
    let phi = 4f64.atan2(3.0);
    assert_eq!(out.contacts.len(), 1, "{out:?}");
    let c = &out.contacts[0];
    assert!(!c.certified);
    assert!(holds(&c.lo, &c.hi, phi, 1e-15), "{c:?} vs {phi}");
    assert!(c.width().to_f64() < 1e-6, "{}", c.width().to_f64());
    assert_eq!(
        states(&out),
        [State::Separate, State::Touch, State::Separate]
    );
    assert_covers(&out);
    assert!(!out.collision_free);
}

/// The body placed at time `t` with the rotation and centre computed in
/// `f64` from libm's sin and cos, rounded to rationals: independent of the
/// engine (helical and static bodies only).
fn placed_with_libm(body: &Body, t: f64) -> Ellipsoid {
    let f = |r: &Rat| r.to_f64();
    let exact = |x: f64| Rat::from_f64_exact(x).expect("finite");
    match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => Ellipsoid {
            radii: body.radii.clone(),
            center: center.clone(),
            orientation: orientation.clone(),
        },
        Motion::Helical {
            orientation,
            axis,
            rate,
            center,
        } => {
            let half = f(rate) * t / 2.0;
            let n = axis.iter().map(|x| f(x) * f(x)).sum::<f64>().sqrt();
            let p = [
                half.cos(),
                half.sin() * f(&axis[0]) / n,
                half.sin() * f(&axis[1]) / n,
                half.sin() * f(&axis[2]) / n,
            ];
            let q = orientation.each_ref().map(f);
            let prod = [
                p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3],
                p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2],
                p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1],
                p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0],
            ];
            let w = f(&center.frequency) * t;
            let c: [f64; 3] = std::array::from_fn(|i| {
                f(&center.base[i])
                    + f(&center.velocity[i]) * t
                    + f(&center.cos[i]) * w.cos()
                    + f(&center.sin[i]) * w.sin()
            });
            Ellipsoid {
                radii: body.radii.clone(),
                center: c.map(exact),
                orientation: prod.map(exact),
            }
        }
        other => panic!("not used here: {other:?}"),
    }
}

/// The timeline's state at `t` (`None` within `margin` of a breakpoint).
fn state_in(out: &Outcome, t: f64, margin: f64) -> Option<State> {
    out.timeline
        .iter()
        .find(|s| s.start.hi.to_f64() + margin < t && t < s.end.lo.to_f64() - margin)
        .map(|s| s.state)
}

#[test]
fn sampled_states_match_an_independent_classification() {
    for name in ["paper-example-5-2.toml", "screw-step.toml"] {
        let s = scene_file(name);
        let out = enclosure(&s, &Options::default());
        let (t0, t1) = (s.span[0].to_f64(), s.span[1].to_f64());
        let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut checked = 0;
        for _ in 0..60 {
            seed = seed
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            let t = t0 + (t1 - t0) * ((seed >> 11) as f64 / (1u64 << 53) as f64);
            let Some(state) = state_in(&out, t, 1e-6) else {
                continue;
            };
            let independent = State::from(classify_pair(
                &placed_with_libm(&s.a, t),
                &placed_with_libm(&s.b, t),
            ));
            assert_eq!(state, independent, "{name} at t = {t}");
            checked += 1;
        }
        assert!(checked >= 50, "{name}: {checked}");
    }
}

#[test]
fn screw_step_has_certified_contacts() {
    let s = scene_file("screw-step.toml");
    let out = enclosure(&s, &Options::default());
    assert!(!out.contacts.is_empty());
    assert!(out.contacts.iter().all(|c| c.certified));
    assert_covers(&out);
}

#[test]
fn invalid_queries_are_typed_errors() {
    let s = scene_file("paper-example-5-2.toml");
    let reversed = [s.span[1].clone(), s.span[0].clone()];
    assert_eq!(
        run(&s.a, &s.b, &reversed, &Options::default()),
        Err(EnclosureError::Span)
    );
    let too_many = Options {
        digits: Options::MAX_DIGITS + 1,
        first_contact_only: false,
    };
    assert!(matches!(
        run(&s.a, &s.b, &s.span, &too_many),
        Err(EnclosureError::Digits { .. })
    ));
    let mut a = s.a.clone();
    if let Motion::Helical { axis, .. } = &mut a.motion {
        *axis = [Rat::zero(), Rat::zero(), Rat::zero()];
    }
    assert_eq!(
        run(&a, &s.b, &s.span, &Options::default()),
        Err(EnclosureError::Zero {
            body: "a",
            field: "axis"
        })
    );
}
