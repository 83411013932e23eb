//! The stability families (`crates/stability`, shipped under
//! `tests/stability/`): the exact mode is right on every shipped scene —
//! verdict, contact count, every true instant inside its certified
//! enclosure, the state sequence — and the generator's ground truth is
//! itself checked against the exact static classifier (Theorem 3.10),
//! independently of the CCD engine.

use ccd_arith::Rat;
use ccd_exact::{run, Arithmetic, Options, State};
use ccd_stability::baseline::{sample, state_at};
use ccd_stability::families::{generate, Level};
use ccd_stability::harness::{answer, score, Method};
use ccd_stability::scene_io::to_toml;
use ccd_stability::{read_cases, Case, Truth};
use std::path::Path;

fn shipped() -> Vec<Case> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/stability");
    read_cases(&dir).unwrap_or_else(|e| panic!("{e}"))
}

fn find<'a>(cases: &'a [Case], name: &str) -> &'a Case {
    cases
        .iter()
        .find(|c| c.name == name)
        .unwrap_or_else(|| panic!("no shipped scene {name}"))
}

/// `u = (t − t0)/(t1 − t0)`.
fn to_u(case: &Case, t: &Rat) -> Rat {
    let [t0, t1] = &case.scene.span;
    &(t - t0) / &(t1 - t0)
}

#[test]
fn shipped_files_are_what_the_generator_makes() {
    let files = shipped();
    let mut made = generate(Level::Shipped).unwrap_or_else(|e| panic!("{e}"));
    made.sort_by(|a, b| a.name.cmp(&b.name));
    assert_eq!(
        files.len(),
        made.len(),
        "regenerate with `stability generate tests/stability`"
    );
    for (f, m) in files.iter().zip(&made) {
        assert_eq!(f.name, m.name);
        assert_eq!(f.scene, m.scene, "{}", f.name);
        assert_eq!(f.truth, m.truth, "{}", f.name);
    }
    // Every family is represented, with misses, touches and overlaps.
    for (family, _) in ccd_stability::families::FAMILIES {
        assert!(files.iter().any(|c| c.truth.family == *family), "{family}");
    }
}

#[test]
fn scene_text_and_truth_json_round_trip() {
    for case in generate(Level::Shipped).unwrap_or_else(|e| panic!("{e}")) {
        let text = to_toml(&case.scene, &[]).unwrap_or_else(|e| panic!("{e}"));
        let back =
            ccd_exact::Scene::from_toml(&text).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        assert_eq!(back, case.scene, "{}", case.name);
        let json = case.truth.to_json().to_string();
        assert_eq!(
            Truth::from_json(&case.name, &json).unwrap_or_else(|e| panic!("{e}")),
            case.truth
        );
    }
}

#[test]
fn exact_mode_is_right_on_every_shipped_scene() {
    let cases = shipped();
    assert!(cases.len() >= 50);
    for case in &cases {
        let out =
            run(&case.scene, &Options::default()).unwrap_or_else(|e| panic!("{}: {e}", case.name));
        let t = &case.truth;
        assert_eq!(
            out.collision_free, t.collision_free,
            "{}: verdict",
            case.name
        );
        assert_eq!(
            out.contacts.len(),
            t.contacts.len(),
            "{}: contacts",
            case.name
        );
        for (truth, got) in t.contacts.iter().zip(&out.contacts) {
            assert!(got.certified, "{}", case.name);
            assert!(
                truth.within(&got.lo, &got.hi),
                "{}: {} not in [{}, {}]",
                case.name,
                truth.describe(),
                got.lo,
                got.hi
            );
            assert!(
                got.width()
                    <= Rat::from_frac(1, 1_000_000_000_000_000) * (&out.span[1] - &out.span[0])
            );
        }
        let mut states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
        states.dedup();
        assert_eq!(states, t.states, "{}: timeline", case.name);
        assert_eq!(
            out.first_contact.is_none(),
            t.collision_free,
            "{}",
            case.name
        );
        // The scoring harness agrees (it is what the report uses).
        let ans = answer(case, Method::Exact).unwrap_or_else(|e| panic!("{e}"));
        let s = score(case, Method::Exact, &ans, 0.0);
        assert!(
            !s.wrong() && s.enclosed && s.states_ok,
            "{}: {s:?}",
            case.name
        );
    }
}

#[test]
fn exact_mode_on_touching_throughout_and_span_ends() {
    let cases = shipped();
    for name in ["throughout-touch-arc", "throughout-touch-together"] {
        let out =
            run(&find(&cases, name).scene, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(out.timeline.len(), 1, "{name}");
        assert_eq!(out.timeline[0].state, State::Touch, "{name}");
        assert!(out.contacts.is_empty() && !out.collision_free, "{name}");
    }
    for name in [
        "throughout-identical",
        "throughout-concentric",
        "throughout-nested",
    ] {
        let out =
            run(&find(&cases, name).scene, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(out.timeline.len(), 1, "{name}");
        assert_eq!(out.timeline[0].state, State::Overlap, "{name}");
    }
    // Contacts exactly at t0 = 1/3 and t1 = 2 are reported exactly.
    let (t0, t1) = (Rat::from_frac(1, 3), Rat::from(2));
    for (name, at) in [
        ("endpoints-touch-at-t0-depart", vec![&t0]),
        ("endpoints-graze-at-t0", vec![&t0]),
        ("endpoints-approach-touch-at-t1", vec![&t1]),
        ("endpoints-overlap-until-t1", vec![&t1]),
        ("endpoints-graze-at-t1", vec![&t1]),
        ("endpoints-touch-at-both-ends", vec![&t0, &t1]),
    ] {
        let out =
            run(&find(&cases, name).scene, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        let got: Vec<(&Rat, &Rat)> = out.contacts.iter().map(|c| (&c.lo, &c.hi)).collect();
        let want: Vec<(&Rat, &Rat)> = at.iter().map(|t| (*t, *t)).collect();
        assert_eq!(got, want, "{name}");
    }
}

#[test]
fn closest_approach_agrees_with_the_static_classifier() {
    let mut checked = 0;
    for case in generate(Level::Shipped).unwrap_or_else(|e| panic!("{e}")) {
        let Some(c) = &case.truth.closest else {
            continue;
        };
        let got = state_at(&case.scene, &to_u(&case, &c.t)).unwrap_or_else(|e| panic!("{e}"));
        let want = match c.gap.signum() {
            1 => State::Separate,
            0 => State::Touch,
            _ => State::Overlap,
        };
        assert_eq!(got, want, "{} at t = {} (gap {})", case.name, c.t, c.gap);
        checked += 1;
    }
    assert!(checked >= 30);
}

#[test]
fn truth_states_agree_with_the_static_classifier() {
    // Between consecutive true contacts (and the ends) the static classifier
    // at a rational inside each piece must give the truth's state; at a
    // rational contact it must give Touch.
    for case in generate(Level::Shipped).unwrap_or_else(|e| panic!("{e}")) {
        let span = &case.scene.span;
        let mut bounds = vec![span[0].clone()];
        bounds.extend(case.truth.contacts.iter().map(|c| c.approx(200)));
        bounds.push(span[1].clone());
        let at = |t: &Rat| state_at(&case.scene, &to_u(&case, t)).unwrap_or_else(|e| panic!("{e}"));
        let mut seen = Vec::new();
        for (i, w) in bounds.windows(2).enumerate() {
            if w[0] < w[1] {
                for q in [
                    Rat::from_frac(1, 3),
                    Rat::from_frac(1, 2),
                    Rat::from_frac(2, 3),
                ] {
                    seen.push(at(&(&w[0] + &(&(&w[1] - &w[0]) * &q))));
                }
            }
            // Contact i sits at bounds[i + 1]; an irrational one cannot be
            // evaluated exactly, and is a Touch by construction.
            if let Some(c) = case.truth.contacts.get(i) {
                seen.push(if c.is_rational() {
                    at(&c.a)
                } else {
                    State::Touch
                });
            }
        }
        seen.dedup();
        assert_eq!(seen, case.truth.states, "{}", case.name);
    }
}

#[test]
fn sampling_misses_short_events_and_floats_are_uncertified() {
    let cases = shipped();
    // A tangency at t = 3/7 falls between samples i/99.
    let touch =
        sample(&find(&cases, "graze-spheres-touch").scene, 100).unwrap_or_else(|e| panic!("{e}"));
    assert!(touch.collision_free, "the sampler should miss the tangency");
    // An overlap lasting ~2·10⁻⁴ (k = 8) is missed; one lasting ~0.3 (k = 1) is seen.
    let k8 = sample(&find(&cases, "graze-spheres-k08-overlap").scene, 100)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(k8.collision_free);
    let k1 = sample(&find(&cases, "graze-spheres-k01-overlap").scene, 100)
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((k1.collision_free, k1.contacts.len()), (false, 2));
    assert_eq!(
        k1.states,
        [State::Separate, State::Overlap, State::Separate]
    );
    // Float mode answers but never claims certification.
    let opts = Options {
        arithmetic: Arithmetic::Float,
        ..Options::default()
    };
    let out = run(&find(&cases, "graze-spheres-k01-overlap").scene, &opts)
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(!out.contacts.is_empty() && out.contacts.iter().all(|c| !c.certified));
}
