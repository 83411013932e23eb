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
                truth.agrees(&got.lo, &got.hi),
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
        // Pieces run from one contact's upper end to the next one's lower
        // end: a bracketed contact's interval is not sampled.
        let mut ends = vec![(span[0].clone(), span[0].clone())];
        ends.extend(case.truth.contacts.iter().map(|c| c.bounds(200)));
        ends.push((span[1].clone(), span[1].clone()));
        let at = |t: &Rat| state_at(&case.scene, &to_u(&case, t)).unwrap_or_else(|e| panic!("{e}"));
        // The span's ends themselves (a bracket may reach them).
        let mut seen = vec![at(&span[0])];
        for (i, w) in ends.windows(2).enumerate() {
            let (from, to) = (&w[0].1, &w[1].0);
            if from < to {
                for q in [
                    Rat::from_frac(1, 3),
                    Rat::from_frac(1, 2),
                    Rat::from_frac(2, 3),
                ] {
                    seen.push(at(&(from + &(&(to - from) * &q))));
                }
            }
            // Contact i sits at ends[i + 1]; an irrational or bracketed
            // one cannot be evaluated exactly, and is a Touch by
            // construction.
            if let Some(c) = case.truth.contacts.get(i) {
                seen.push(match c.exact() {
                    Some(s) if s.is_rational() => at(&s.a),
                    _ => State::Touch,
                });
            }
        }
        seen.push(at(&span[1]));
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

/// The families built for issue 12 must reach the generic path (the
/// homothetic grazes all have `sr0 ≡ 0`), with long numbers: a gap of
/// `10⁻¹⁰⁰`, a radius of `10⁻⁶⁴`, 100-digit benchmark coordinates.
#[test]
fn new_families_take_the_generic_path_with_long_numbers() {
    let cases = shipped();
    for &family in ccd_stability::families::GENERIC {
        let fam: Vec<&Case> = cases.iter().filter(|c| c.truth.family == family).collect();
        assert!(fam.len() >= 3, "{family}");
        for case in fam {
            let out = run(&case.scene, &Options::default())
                .unwrap_or_else(|e| panic!("{}: {e}", case.name));
            assert!(
                out.stats.deg_sr0.is_some(),
                "{}: sr0 ≡ 0 (a homothetic construction?)",
                case.name
            );
        }
    }
    for (name, digits) in [
        ("graze-scene-turned-k100-miss", 100),
        ("ratio-needle-k0064-overlap", 64),
        ("bench-perturbed-affine-deg2-d0100", 100),
    ] {
        let text = to_toml(&find(&cases, name).scene, &[]).unwrap_or_else(|e| panic!("{e}"));
        let longest = text
            .split('"')
            .skip(1)
            .step_by(2)
            .map(str::len)
            .max()
            .unwrap_or(0);
        assert!(longest > digits, "{name}: longest number {longest} chars");
    }
}

/// Turning the whole scene by a rational quaternion changes no answer:
/// the exact timelines of `graze-turned-*` and `graze-scene-turned-*`
/// agree state for state, and their contact enclosures overlap.
#[test]
fn turning_the_whole_scene_changes_nothing() {
    let cases = shipped();
    let mut pairs = 0;
    for case in cases.iter().filter(|c| c.truth.family == "graze-turned") {
        let twin = case.name.replace("graze-turned", "graze-scene-turned");
        let run_of =
            |c: &Case| run(&c.scene, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        let (a, b) = (run_of(case), run_of(find(&cases, &twin)));
        let states = |o: &ccd_exact::Outcome| {
            let mut s: Vec<State> = o.timeline.iter().map(|x| x.state).collect();
            s.dedup();
            s
        };
        assert_eq!(states(&a), states(&b), "{}", case.name);
        assert_eq!(a.contacts.len(), b.contacts.len(), "{}", case.name);
        for (x, y) in a.contacts.iter().zip(&b.contacts) {
            assert!(
                x.lo <= y.hi && y.lo <= x.hi,
                "{}: {x:?} vs {y:?}",
                case.name
            );
        }
        pairs += 1;
    }
    assert!(pairs >= 5);
}

/// A perturbation of `10⁻ᵈ` keeps the benchmark's contacts: the exact
/// answer on the perturbed scene has the original's count, each contact
/// within the original's enclosure widened by its width.
#[test]
fn perturbed_benchmarks_keep_their_contacts() {
    let cases = shipped();
    let mut checked = 0;
    for (bench, text) in ccd_stability::families::perturbed::BENCHES {
        let original = ccd_exact::Scene::from_toml(text).unwrap_or_else(|e| panic!("{e}"));
        let want = run(&original, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
        let prefix = format!("bench-perturbed-{bench}-d");
        for case in cases.iter().filter(|c| c.name.starts_with(&prefix)) {
            let got = run(&case.scene, &Options::default()).unwrap_or_else(|e| panic!("{e}"));
            assert!(got.complete, "{}", case.name);
            assert_eq!(got.contacts.len(), want.contacts.len(), "{}", case.name);
            for (g, w) in got.contacts.iter().zip(&want.contacts) {
                let width = &w.hi - &w.lo;
                assert!(g.certified, "{}", case.name);
                assert!(
                    g.lo >= &w.lo - &width && g.hi <= &w.hi + &width,
                    "{}: [{}, {}] moved from [{}, {}]",
                    case.name,
                    g.lo,
                    g.hi,
                    w.lo,
                    w.hi
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 4);
}
