//! End-to-end tests of the interval path (`ccd-enclosure`) for the
//! non-rational `helical` kind: the paper's Example 5.2, agreement with the
//! exact path where a helical motion is in fact rational, an uncertified
//! tangential graze, and states checked against an independent static
//! classification at sampled instants.

mod common;

use ccd_arith::Rat;
use ccd_exact::{CcdError, Options};
use ccd_exact::{Outcome, Scene, State};
use ccd_interval::run;
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
            ..Options::default()
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
    let field = |r: Result<Outcome, CcdError>| match r {
        Err(CcdError::Scene(e)) => e.field().map(str::to_string),
        other => panic!("{other:?}"),
    };
    let reversed = Scene {
        span: [s.span[1].clone(), s.span[0].clone()],
        ..s.clone()
    };
    assert_eq!(
        field(ccd_exact::run(&reversed, &Options::default())).as_deref(),
        Some("span")
    );
    let too_many = Options {
        digits: Options::MAX_DIGITS + 1,
        ..Options::default()
    };
    assert!(matches!(
        ccd_exact::run(&s, &too_many),
        Err(CcdError::Option {
            option: "--digits",
            ..
        })
    ));
    let mut zero_axis = s.clone();
    if let Motion::Helical { axis, .. } = &mut zero_axis.a.motion {
        *axis = [Rat::zero(), Rat::zero(), Rat::zero()];
    }
    assert_eq!(
        field(ccd_exact::run(&zero_axis, &Options::default())).as_deref(),
        Some("a.motion.axis")
    );
}

// ---------------------------------------------------------------------------
// Issue 18: fast spins and high frequencies. Nothing is assumed, the effort
// is bounded, and every outcome says exactly what it did not prove.
// ---------------------------------------------------------------------------

/// The largest angle `|rate·t|`, `|frequency·t|` of the scene's helical
/// bodies over the span (as `f64`; `inf` when huge).
fn largest_angle(s: &Scene) -> f64 {
    let t = s.span[0].to_f64().abs().max(s.span[1].to_f64().abs());
    [&s.a, &s.b]
        .iter()
        .map(|b| match &b.motion {
            Motion::Helical { rate, center, .. } => {
                (rate.to_f64().abs() * t).max(center.frequency.to_f64().abs() * t)
            }
            _ => 0.0,
        })
        .fold(0.0, f64::max)
}

/// The contract of issue 18 on one outcome: either complete and certified,
/// or it says exactly what is not. States that are claimed proven are
/// checked against an independent `f64` classification where libm's sin and
/// cos of the angle are accurate.
fn assert_honest(s: &Scene, out: &Outcome, first_only: bool) {
    let (t0, t1) = (&out.span[0], &out.span[1]);
    // 1. The segments and gaps follow each other in order without holes.
    enum Piece<'a> {
        Seg(&'a ccd_exact::Segment),
        Gap(&'a ccd_exact::Gap),
    }
    let mut pieces: Vec<(Rat, Piece<'_>)> = out
        .timeline
        .iter()
        .map(|seg| (seg.start.lo.clone(), Piece::Seg(seg)))
        .chain(out.gaps.iter().map(|g| (g.lo.clone(), Piece::Gap(g))))
        .collect();
    pieces.sort_by(|x, y| x.0.cmp(&y.0));
    assert!(!pieces.is_empty(), "{out:?}");
    assert_eq!(&pieces[0].0, t0, "the timeline starts at t0: {out:?}");
    for w in pieces.windows(2) {
        match (&w[0].1, &w[1].1) {
            (Piece::Seg(p), Piece::Seg(n)) => assert_eq!(p.end, n.start, "hole: {out:?}"),
            (Piece::Seg(p), Piece::Gap(g)) => assert_eq!(p.end.hi, g.lo, "hole: {out:?}"),
            (Piece::Gap(g), Piece::Seg(n)) => {
                assert_eq!(
                    n.start,
                    ccd_exact::Instant::exact(g.hi.clone()),
                    "hole: {out:?}"
                )
            }
            (Piece::Gap(_), Piece::Gap(_)) => panic!("adjacent gaps not merged: {out:?}"),
        }
    }
    let reaches_t1 = match &pieces[pieces.len() - 1].1 {
        Piece::Seg(seg) => &seg.end.hi == t1,
        Piece::Gap(g) => &g.hi == t1,
    };
    // 2. `complete` exactly when the timeline alone covers [t0, t1].
    if !first_only {
        assert_eq!(out.complete, out.gaps.is_empty() && reaches_t1, "{out:?}");
        assert!(
            reaches_t1,
            "without --first-contact the span is tiled to t1"
        );
    }
    for g in &out.gaps {
        assert!(g.lo < g.hi && !g.reason.is_empty(), "{g:?}");
        if let Some(w) = &g.witness {
            // Strictly inside, or the gap's start when that is t0 and the
            // state there is proven (the state at t0 is the witness).
            let inside = g.lo < w.t || (w.t == g.lo && g.lo == *t0);
            assert!(inside && w.t < g.hi && w.state != State::Separate, "{g:?}");
        }
    }
    // 3. The verdict is proven, or undecided with a reason.
    let collision = out
        .timeline
        .iter()
        .any(|seg| seg.certified && seg.state != State::Separate)
        || out.gaps.iter().any(|g| g.witness.is_some());
    let separation = out.complete
        && out
            .timeline
            .iter()
            .all(|seg| seg.certified && seg.state == State::Separate);
    assert!(!(collision && separation), "{out:?}");
    assert_eq!(out.collision_free, separation, "{out:?}");
    match &out.undecided {
        Some(why) => {
            assert!(!collision && !separation && !why.is_empty(), "{out:?}");
            assert!(
                !out.gaps.is_empty() || out.timeline.iter().any(|seg| !seg.certified),
                "undecided names something unproven: {out:?}"
            );
        }
        None => assert!(collision || separation, "{out:?}"),
    }
    // 4. Contacts are the zero-length touch segments.
    let touches: Vec<_> = out
        .timeline
        .iter()
        .filter(|seg| seg.start == seg.end && seg.state == State::Touch)
        .map(|seg| &seg.start)
        .collect();
    assert!(out.contacts.iter().all(|c| touches.contains(&c)), "{out:?}");
    assert_eq!(
        out.certified(),
        out.gaps.is_empty()
            && out.undecided.is_none()
            && out
                .timeline
                .iter()
                .all(|seg| seg.certified && seg.start.certified && seg.end.certified)
            && out.contacts.iter().all(|c| c.certified)
            && out.first_contact.as_ref().is_none_or(|c| c.certified)
    );
    // 5. Proven states agree with an independent classification.
    if largest_angle(s) > 1e4 {
        return;
    }
    let check = |t: f64, state: State, what: &str| {
        let independent = State::from(classify_pair(
            &placed_with_libm(&s.a, t),
            &placed_with_libm(&s.b, t),
        ));
        assert_eq!(state, independent, "{what} at t = {t}: {out:?}");
    };
    for seg in out.timeline.iter().filter(|seg| seg.certified) {
        let (lo, hi) = (seg.start.hi.to_f64(), seg.end.lo.to_f64());
        if hi - lo > 1e-5 {
            for k in 1..4 {
                check(
                    lo + (hi - lo) * f64::from(k) / 4.0,
                    seg.state,
                    "certified segment",
                );
            }
        }
    }
    for g in &out.gaps {
        if let Some(w) = &g.witness {
            check(w.t.to_f64(), w.state, "witness");
        }
    }
}

fn issue_scene(rate: &str) -> Scene {
    scene(&format!(
        r#"
        [a]
        radii = [2, 1, "3/2"]
        [a.motion]
        kind = "helical"
        axis = [0, 0, 1]
        rate = "{rate}"
        center = {{ base = [-4, "1/2", 0], velocity = [8, 0, 0] }}
        [b]
        radii = [1, "1/2", "1/3"]
        "#
    ))
}

/// Overlap at t = 1/2 is proven: a certified overlap segment holds it, or a
/// gap's witness is there.
fn overlap_at_half_is_proven(out: &Outcome) -> bool {
    let half = Rat::from_frac(1, 2);
    out.timeline.iter().any(|seg| {
        seg.certified && seg.state == State::Overlap && seg.start.hi < half && half < seg.end.lo
    }) || out
        .gaps
        .iter()
        .any(|g| g.witness.as_ref().is_some_and(|w| w.t == half))
}

#[test]
fn issue_18_scenes_claim_nothing_unproven() {
    for name in ["issue-18-spin-1e300.toml", "issue-18-spin-1e4.toml"] {
        let s = scene_file(name);
        let out = enclosure(&s, &Options::default());
        assert_honest(&s, &out, false);
        // B's centre is inside A at t = 1/2 whatever the orientation.
        assert!(
            !out.collision_free && out.undecided.is_none(),
            "{name}: {out:?}"
        );
        assert!(overlap_at_half_is_proven(&out), "{name}: {out:?}");
        // Both ends are far apart: separate, proven.
        let (first, last) = (&out.timeline[0], &out.timeline[out.timeline.len() - 1]);
        assert!(first.certified && first.state == State::Separate, "{name}");
        assert!(last.certified && last.state == State::Separate && last.end.hi == s.span[1]);
        assert!(
            !out.stats.branch_name().contains("assumed"),
            "{}",
            out.stats.branch_name()
        );
    }
}

#[test]
fn frequency_1e10_stops_at_its_budget_honestly() {
    let s = scene_file("issue-18-frequency-1e10.toml");
    let out = enclosure(&s, &Options::default());
    assert_honest(&s, &out, false);
    assert!(!out.collision_free);
    // The same circle far from B: separate for every orientation and phase.
    let far = scene(
        r#"
        [a]
        radii = [2, 1, "3/2"]
        motion = { kind = "helical", axis = [1, 1, 0], rate = "1e300", center = { base = [20, 0, 0], cos = [3, 0, 0], sin = [0, 3, 0], frequency = 1e10 } }
        [b]
        radii = [1, "1/2", "1/3"]
        "#,
    );
    let out = enclosure(&far, &Options::default());
    assert_honest(&far, &out, false);
    assert!(
        out.collision_free && out.complete && out.certified(),
        "{out:?}"
    );
}

/// A gap from t0 on after an overlap proven at t0 (found by the fuzzer:
/// A's first radius 1e1000 swallows B while the 1e10 frequency exhausts the
/// budget): the full query knows what a first-contact query stopping at t0
/// proves, a certified first contact at t0 and no collision-freedom.
#[test]
fn a_gap_from_t0_keeps_the_state_proven_there() {
    let s = scene(
        r#"
        [a]
        radii = ["1e1000", 1, "3/2"]
        motion = { kind = "helical", axis = [0, 0, 1], rate = 1, center = { cos = [3, 0, 0], sin = [0, 3, 0], frequency = 1e10 } }
        [b]
        radii = [1, "1/2", "1/3"]
        "#,
    );
    let zero = Rat::from_frac(0, 1);
    let at_t0 = |c: &Option<ccd_exact::Instant>| {
        c.as_ref()
            .is_some_and(|c| c.lo == zero && c.hi == zero && c.certified)
    };
    let first = enclosure(
        &s,
        &Options {
            first_contact_only: true,
            ..Options::default()
        },
    );
    assert_honest(&s, &first, true);
    assert!(at_t0(&first.first_contact), "{first:?}");
    let full = enclosure(&s, &Options::default());
    assert_honest(&s, &full, false);
    assert!(!full.gaps.is_empty(), "the budget is reached: {full:?}");
    assert!(at_t0(&full.first_contact), "{full:?}");
    assert!(!full.collision_free && full.undecided.is_none(), "{full:?}");
}

#[test]
fn fast_spin_family_with_answers_known_by_construction() {
    for rate in ["3", "100", "1e300", "1e4000"] {
        // B far from A: separate for every orientation.
        let far = scene(&format!(
            r#"
            [a]
            radii = [2, 1, "3/2"]
            motion = {{ kind = "helical", axis = [1, 2, 3], rate = "{rate}", center = {{ base = [0, 0, 0], velocity = [1, 0, 0] }} }}
            [b]
            radii = [1, "1/2", "1/3"]
            motion = {{ kind = "static", center = [10, 1, 0] }}
            "#
        ));
        let out = enclosure(&far, &Options::default());
        assert_honest(&far, &out, false);
        assert!(
            out.collision_free && out.complete && out.certified(),
            "{rate}: {out:?}"
        );
        assert_eq!(states(&out), [State::Separate]);

        // B's centre inside A at t = 1/2: overlap certain.
        let inside = issue_scene(rate);
        let out = enclosure(&inside, &Options::default());
        assert_honest(&inside, &out, false);
        assert!(
            !out.collision_free && out.undecided.is_none(),
            "{rate}: {out:?}"
        );
        assert!(overlap_at_half_is_proven(&out), "{rate}: {out:?}");

        // A sphere spinning about any axis, and a spheroid spinning about
        // its axis of symmetry (body y turned onto world z by the initial
        // orientation): the spin is invisible, so the answer is the
        // translation's, decided completely and certified.
        for (radii, orientation, axis) in [
            ("[1, 1, 1]", "[1, 0, 0, 0]", "[1, 2, 3]"),
            ("[1, 2, 1]", "[1, 1, 0, 0]", "[0, 0, 5]"),
        ] {
            let helical = format!(
                r#"
                [a]
                radii = {radii}
                motion = {{ kind = "helical", orientation = {orientation}, axis = {axis}, rate = "{rate}", center = {{ base = [-4, "1/4", 0], velocity = [8, 0, 0] }} }}
                [b]
                radii = [2, 1, "1/2"]
                "#
            );
            let translation = format!(
                r#"
                [a]
                radii = {radii}
                motion = {{ kind = "translation", orientation = {orientation}, center = [[-4, "1/4", 0], [4, "1/4", 0]] }}
                [b]
                radii = [2, 1, "1/2"]
                "#
            );
            cross_check(&helical, &translation);
            let out = enclosure(&scene(&helical), &Options::default());
            assert!(out.complete && out.certified(), "{rate} {radii}: {out:?}");
        }
    }
}

#[test]
fn a_visible_spin_is_kept() {
    // An ellipsoid spinning about a non-symmetry axis keeps its rate; a
    // spheroid about its symmetry axis loses it.
    let s = scene(
        r#"
        [a]
        radii = [2, 1, 1]
        motion = { kind = "helical", axis = [0, 0, 1], rate = 5 }
        [b]
        radii = [1, 1, 2]
        motion = { kind = "helical", axis = [0, 0, 1], rate = 5 }
        "#,
    );
    let rate = |b: &Body| match &b.motion {
        Motion::Helical { rate, .. } => rate.clone(),
        _ => panic!("helical"),
    };
    assert_eq!(
        rate(&ccd_interval::without_invisible_spin(&s.a)),
        Rat::from(5)
    );
    assert_eq!(
        rate(&ccd_interval::without_invisible_spin(&s.b)),
        Rat::zero()
    );
}

mod honesty {
    use super::*;
    use proptest::prelude::*;

    fn ratio() -> impl Strategy<Value = String> {
        (1i64..=8, 1i64..=4).prop_map(|(p, q)| format!("\"{p}/{q}\""))
    }

    fn small() -> impl Strategy<Value = i64> {
        -6i64..=6
    }

    /// Spin rates from slow to 1e300, including none.
    fn rate() -> impl Strategy<Value = String> {
        prop_oneof![
            Just("0".to_string()),
            (1i64..=9).prop_map(|r| r.to_string()),
            (1u32..=3).prop_map(|k| format!("1e{k}")),
            (10u32..=300).prop_map(|k| format!("1e{k}")),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 6, ..ProptestConfig::default() })]

        /// Every helical outcome is either complete and certified or says
        /// exactly what is not (gaps with reasons, unproven segments, an
        /// undecided verdict with its reason), and nothing it calls proven
        /// disagrees with an independent classification.
        #[test]
        fn every_helical_outcome_says_what_it_proved(
            ra in [ratio(), ratio(), ratio()],
            rb in [ratio(), ratio(), ratio()],
            axis in (small(), small(), 1i64..=3),
            rate in rate(),
            base in [small(), small(), small()],
            velocity in [small(), small(), small()],
            periodic in (0i64..=3, prop_oneof![Just("0".to_string()), Just("2".to_string()), Just("1e10".to_string())]),
            b_center in [small(), small(), small()],
            first_only in any::<bool>(),
        ) {
            let s = scene(&format!(
                r#"
                [a]
                radii = [{}, {}, {}]
                motion = {{ kind = "helical", axis = [{}, {}, {}], rate = "{rate}", center = {{ base = [{}, {}, {}], velocity = [{}, {}, {}], cos = [{}, 0, 0], sin = [0, {}, 0], frequency = "{}" }} }}
                [b]
                radii = [{}, {}, {}]
                motion = {{ kind = "static", center = [{}, {}, {}] }}
                "#,
                ra[0], ra[1], ra[2], axis.0, axis.1, axis.2,
                base[0], base[1], base[2], velocity[0], velocity[1], velocity[2],
                periodic.0, periodic.0, periodic.1,
                rb[0], rb[1], rb[2], b_center[0], b_center[1], b_center[2],
            ));
            let options = Options { digits: 15, first_contact_only: first_only, ..Options::default() };
            let out = enclosure(&s, &options);
            assert_honest(&s, &out, first_only);
        }
    }
}
