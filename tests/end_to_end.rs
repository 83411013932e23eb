//! End-to-end scenes through the library: the paper's Example 5.1, the
//! shipped scenes, and constructed degenerate scenes whose answers are known
//! by construction.

mod common;

use ccd_arith::{Int, Rat};
use ccd_exact::{run_toml, Options, Outcome, State};

fn scene(name: &str) -> String {
    let path = format!("{}/tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn run(text: &str) -> Outcome {
    run_toml(text, &Options::default()).unwrap_or_else(|e| panic!("{e}"))
}

fn run_first_contact(text: &str) -> Outcome {
    let options = Options {
        first_contact_only: true,
        ..Options::default()
    };
    run_toml(text, &options).unwrap_or_else(|e| panic!("{e}"))
}

fn states(out: &Outcome) -> Vec<State> {
    out.timeline.iter().map(|s| s.state).collect()
}

fn eps(digits: u32) -> Rat {
    Rat::new(Int::one(), Int::pow10(digits)).unwrap()
}

/// Checks the timeline covers the span in order without gaps.
fn assert_well_formed(out: &Outcome) {
    let first = out.timeline.first().expect("nonempty timeline");
    assert_eq!(
        (first.start.lo.clone(), first.start.hi.clone()),
        (out.span[0].clone(), out.span[0].clone())
    );
    let last = out.timeline.last().unwrap();
    if out.complete {
        assert_eq!(
            (last.end.lo.clone(), last.end.hi.clone()),
            (out.span[1].clone(), out.span[1].clone())
        );
    }
    for w in out.timeline.windows(2) {
        assert_eq!(w[0].end, w[1].start, "gap or overlap between segments");
        assert!(
            w[0].state != w[1].state || w[0].state == State::Touch,
            "adjacent segments share a state: {w:?}"
        );
    }
    for seg in &out.timeline {
        assert!(seg.start.lo <= seg.start.hi && seg.start.hi <= seg.end.hi);
    }
}

fn assert_encloses(i: &ccd_exact::Instant, t: f64, tol: f64) {
    assert!(
        i.lo.to_f64() - tol <= t && t <= i.hi.to_f64() + tol,
        "{t} not in [{}, {}]",
        i.lo.to_f64(),
        i.hi.to_f64()
    );
}

#[test]
fn paper_example_5_1() {
    let out = run(&scene("paper-example-5-1.toml"));
    assert_well_formed(&out);
    assert_eq!(states(&out), common::PASS_THROUGH);
    assert_eq!(out.contacts.len(), 2);
    assert_encloses(&out.contacts[0], 0.5395042868, 1e-10);
    assert_encloses(&out.contacts[1], 0.8722604191, 1e-10);
    for c in &out.contacts {
        assert!(c.width() <= eps(15), "width {}", c.width().to_f64());
        assert!(c.lo < c.hi, "irrational instants cannot be exact");
    }
    assert_eq!(out.first_contact.as_ref(), Some(&out.contacts[0]));
    assert!(!out.collision_free && out.complete);
}

#[test]
fn paper_example_5_1_sr11_matches_the_printed_one() {
    // The paper prints sr11(t) (sr0 ≡ 0 here); ours must be a constant multiple.
    let text = scene("paper-example-5-1.toml");
    let s = ccd_exact::Scene::from_toml(&text).unwrap();
    let (f, inv) = ccd_exact::symbolic(&s).unwrap();
    assert!(inv.sr0.is_zero(), "Example 5.1 has sr0 ≡ 0");
    assert_eq!(f.degree(), 2, "the paper's f has degree 2 in t");
    let printed = ccd_poly::ZPoly::from_i64s(&[
        2985984, -32845824, 158630400, -439492608, 764204544, -854175744, 599418368, -241483776,
        42762752,
    ]);
    let ours = &inv.sr11;
    assert_eq!(ours.primitive_part(), printed.primitive_part());
}

#[test]
fn rigid_tumbling_runs_and_is_consistent() {
    let text = scene("rigid-tumbling.toml");
    let out = run(&text);
    assert_well_formed(&out);
    // One body turns by a linear quaternion and translates linearly: 6 / 36.
    assert_eq!((out.stats.deg_f, out.stats.deg_sr0), (6, Some(36)));
    let parsed = ccd_exact::Scene::from_toml(&text).unwrap();
    for k in 1..64 {
        let u = Rat::from_frac(k, 64);
        if let Some(state) = common::state_at(&out, &u) {
            assert_eq!(state, common::static_state(&parsed, &u), "u = {u}");
        }
    }
    for c in &out.contacts {
        assert!(c.width() <= eps(15));
    }
}

#[test]
fn static_touching_spheres_touch_throughout() {
    let out = run(&scene("static-touching-spheres.toml"));
    assert_eq!(states(&out), [State::Touch]);
    assert!(out.contacts.is_empty());
    assert_eq!(
        out.first_contact.as_ref().map(|i| i.lo.clone()),
        Some(Rat::zero())
    );
    assert!(!out.collision_free);
}

const SPHERE_PASS: &str = r#"
[a]
radii = [1, 1, 1]
[b]
radii = [1, 1, 1]
[b.motion]
kind = "translation"
center = [[3, 0, 0], [-3, 0, 0]]
"#;

#[test]
fn two_spheres_take_the_sr0_zero_branch() {
    // |x(u)| = |3 − 6u| = 2 at u = 1/6 and 5/6: rational instants, found exactly or enclosed.
    let out = run(SPHERE_PASS);
    assert_well_formed(&out);
    assert_eq!(out.stats.deg_sr0, None, "spheres have sr0 ≡ 0");
    assert_eq!(states(&out), common::PASS_THROUGH);
    for (c, r) in out
        .contacts
        .iter()
        .zip([Rat::from_frac(1, 6), Rat::from_frac(5, 6)])
    {
        assert!(c.lo <= r && r <= c.hi);
    }
}

#[test]
fn identical_ellipsoids_moving_together_overlap_throughout() {
    let body = r#"radii = [3, 1, "1/2"]
motion = { kind = "rigid", orientation = [[1, 0, 0, 0], [1, 1, 2, 0]], center = [[0, 0, 0], [1, 2, 3]] }"#;
    let out = run(&format!("[a]\n{body}\n[b]\n{body}\n"));
    assert_eq!(states(&out), [State::Overlap]);
    assert_eq!(
        out.first_contact.as_ref().map(|i| i.lo.clone()),
        Some(Rat::zero())
    );
}

#[test]
fn ellipsoids_touching_throughout_the_span() {
    // Copies shifted along the principal x axis by twice that semi-axis, moving together.
    let out = run(r#"
[a]
radii = [2, 1, 1]
motion = { kind = "translation", center = [[0, 0, 0], [0, 5, 1]] }
[b]
radii = [2, 1, 1]
motion = { kind = "translation", center = [[4, 0, 0], [4, 5, 1]] }
"#);
    assert_eq!(states(&out), [State::Touch]);
    assert!(out.contacts.is_empty() && !out.collision_free);
}

fn sliding(from: &str, to: &str) -> String {
    format!("[a]\nradii = [2, 1, 1]\n[b]\nradii = [2, 1, 1]\nmotion = {{ kind = \"translation\", center = [[{from}, 0, 0], [{to}, 0, 0]] }}\n")
}

#[test]
fn contact_exactly_at_t0() {
    let out = run(&sliding("4", "6"));
    assert_well_formed(&out);
    assert_eq!(states(&out), [State::Touch, State::Separate]);
    assert_eq!(out.contacts[0].lo, Rat::zero());
    assert_eq!(out.contacts[0].hi, Rat::zero());
    assert_eq!(
        out.first_contact.as_ref().map(|i| i.lo.clone()),
        Some(Rat::zero())
    );
}

#[test]
fn contact_exactly_at_t1() {
    let out = run(&sliding("6", "4"));
    assert_well_formed(&out);
    assert_eq!(states(&out), [State::Separate, State::Touch]);
    assert_eq!(
        (out.contacts[0].lo.clone(), out.contacts[0].hi.clone()),
        (Rat::one(), Rat::one())
    );
}

#[test]
fn contact_at_a_rational_interior_instant() {
    // x(u) = 6 − 6u = 4 at u = 1/3; and the span is [2, 5], so t = 3.
    let text = format!("span = [2, 5]\n{}", sliding("6", "0"));
    let out = run(&text);
    assert_well_formed(&out);
    assert_eq!(
        states(&out),
        [State::Separate, State::Touch, State::Overlap]
    );
    let c = &out.contacts[0];
    assert!(c.lo <= Rat::from(3) && Rat::from(3) <= c.hi && c.width() <= &eps(15) * &Rat::from(3));
    // At a dyadic instant the root is found exactly: x = 4 at u = 1/2.
    let out = run(&sliding("6", "2"));
    assert_eq!(out.contacts[0].lo, Rat::from_frac(1, 2));
    assert_eq!(out.contacts[0].hi, Rat::from_frac(1, 2));
}

#[test]
fn tangential_graze_is_a_contact_between_separate_pieces() {
    // A unit sphere slides along y = 2 over the ellipsoid x²/4 + y² + z² = 1,
    // touching its top (0, 1, 0) at u = 1/2 only (the ellipse's radius of
    // curvature there, 4, exceeds the sphere's 1).
    let out = run(r#"
[a]
radii = [2, 1, 1]
[b]
radii = [1, "1", "1.0"]
motion = { kind = "translation", center = [[-3, 2, 0], [3, 2, 0]] }
"#);
    assert_well_formed(&out);
    assert_eq!(
        states(&out),
        [State::Separate, State::Touch, State::Separate]
    );
    assert_eq!(out.contacts[0].lo, Rat::from_frac(1, 2));
    assert!(!out.collision_free);
}

#[test]
fn first_contact_only_stops_at_the_first() {
    let text = scene("paper-example-5-1.toml");
    let out = run_first_contact(&text);
    assert!(!out.complete);
    assert_eq!(out.contacts.len(), 1);
    assert_encloses(&out.contacts[0], 0.5395042868, 1e-10);
    assert_eq!(states(&out), [State::Separate, State::Touch]);
    assert!(!out.collision_free);
}

#[test]
fn motion_degeneracies_are_errors_naming_the_field() {
    let q = "[a]\nradii = [1, 2, 3]\nmotion = { kind = \"rigid\", orientation = [[1, 0, 0, 0], [-1, 0, 0, 0]], center = [[0, 0, 0]] }\n[b]\nradii = [1, 1, 1]\n";
    let e = run_toml(q, &Options::default()).unwrap_err();
    assert!(e.to_string().contains("a.motion.orientation"), "{e}");
    let l = "[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\nmotion = { kind = \"affine\", matrix = [[[1, 0, 0, 5], [0, 1, 0, 0], [0, 0, 1, 0]], [[-1, 0, 0, 5], [0, -1, 0, 0], [0, 0, -1, 0]]] }\n";
    let e = run_toml(l, &Options::default()).unwrap_err();
    assert!(e.to_string().contains("b.motion.matrix"), "{e}");
}

#[test]
fn first_contact_at_t0_exits_before_the_symbolic_stage() {
    // Overlapping at t0: the answer is t0, and f(λ; t) is never built.
    let text = format!("span = [3, 4]\n{}", sliding("3", "8"));
    let out = run_first_contact(&text);
    assert_eq!(
        out.first_contact
            .as_ref()
            .map(|i| (i.lo.clone(), i.hi.clone())),
        Some((Rat::from(3), Rat::from(3)))
    );
    assert_eq!(states(&out), [State::Overlap]);
    assert!(!out.complete && !out.collision_free);
    assert_eq!(
        out.stats.deg_f, 0,
        "no characteristic polynomial was needed"
    );
    // The full query agrees on the first contact.
    let full = run(&text);
    assert_eq!(full.first_contact, out.first_contact);
}
