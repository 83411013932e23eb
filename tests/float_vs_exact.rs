//! Float mode (`ccd-float`, the paper's Table 3 setting) against the exact
//! mode (`ccd_exact::run`): on the shipped scenes and on seeded random
//! translation and rigid scenes they agree on the states and, to ~1e-9, on
//! the contact times wherever the exact contacts are well-conditioned
//! (each contact a transversal crossing between different states, apart
//! from the others and from the span's ends, and a small forward error
//! estimate for f64). One documented case shows where floats go wrong: a
//! tangential graze.

use ccd_arith::Rat;
use ccd_exact::{run, Options, Outcome, Scene, State};

fn scene_file(name: &str) -> Scene {
    let path = format!("{}/tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn exact(scene: &Scene, first_contact_only: bool) -> Outcome {
    let opts = Options {
        first_contact_only,
        ..Options::default()
    };
    run(scene, &opts).unwrap_or_else(|e| panic!("{e}"))
}

/// The exact, normalised `f(λ; u)` the exact path also starts from.
fn char_poly(scene: &Scene) -> ccd_motion::CharPoly {
    ccd_motion::char_poly(&scene.a, &scene.b, &scene.span).expect("a valid rational scene")
}

fn float(scene: &Scene, first_contact_only: bool) -> Outcome {
    ccd_float::solve(
        &char_poly(scene),
        &scene.span,
        &Options {
            first_contact_only,
            ..Options::default()
        },
    )
}

fn states(out: &Outcome) -> Vec<State> {
    out.timeline.iter().map(|s| s.state).collect()
}

fn mid(i: &ccd_exact::Instant) -> f64 {
    i.midpoint().to_f64()
}

/// A forward error estimate for the float contact times: at each exact
/// contact `u*` (in `u = (t − t0)/(t1 − t0)`), the rounding level of the
/// float candidate polynomial `p` (`sr0`, or `sr11` when `sr0 ≡ 0`) —
/// `ε·n·m(u*)` with `m` its magnitude bound (see `ccd_float::BernsteinF64`)
/// — over its slope `|p'(u*)|`: how far rounding can move the root.
fn float_error_estimate(scene: &Scene, out: &Outcome) -> f64 {
    let prep = ccd_float::prepare(&char_poly(scene));
    let p = if prep.inv.sr0.is_negligible(ccd_float::TOL_IDENTICALLY_ZERO) {
        &prep.inv.sr11
    } else {
        &prep.inv.sr0
    };
    let dt = (&out.span[1] - &out.span[0]).to_f64();
    let h = 1e-7;
    out.contacts
        .iter()
        .map(|c| {
            let u = ((&c.midpoint() - &out.span[0]).to_f64() / dt).clamp(h, 1.0 - h);
            let slope = (p.eval(u + h).value - p.eval(u - h).value) / (2.0 * h);
            f64::EPSILON * p.degree() as f64 * p.eval(u).magnitude / slope.abs() * dt
        })
        .fold(0.0, f64::max)
}

/// Every exact contact changes the state (a crossing: a simple root of the
/// candidate polynomial, not a graze), and contacts are at least `gap`
/// apart from each other and from the span's ends.
fn well_separated_crossings(out: &Outcome, gap: f64) -> bool {
    let (t0, t1) = (out.span[0].to_f64(), out.span[1].to_f64());
    let crossing = out
        .timeline
        .windows(3)
        .all(|w| w[1].state != State::Touch || w[1].start != w[1].end || w[0].state != w[2].state);
    let mut ts: Vec<f64> = vec![t0];
    ts.extend(out.contacts.iter().map(mid));
    ts.push(t1);
    crossing && ts.windows(2).all(|w| w[1] - w[0] > gap)
}

/// Float and exact agree: same states, same contacts to `tol`, every float
/// instant uncertified, same completeness.
fn assert_agree(name: &str, e: &Outcome, f: &Outcome, tol: f64) {
    assert_eq!(states(e), states(f), "{name}: states");
    assert_eq!(e.contacts.len(), f.contacts.len(), "{name}: contacts");
    for (ce, cf) in e.contacts.iter().zip(&f.contacts) {
        assert!(
            (mid(ce) - mid(cf)).abs() <= tol,
            "{name}: {} vs {}",
            mid(ce),
            mid(cf)
        );
        assert!(ce.certified && !cf.certified);
    }
    assert_eq!(
        e.first_contact.is_some(),
        f.first_contact.is_some(),
        "{name}"
    );
    if let (Some(a), Some(b)) = (&e.first_contact, &f.first_contact) {
        assert!((mid(a) - mid(b)).abs() <= tol, "{name}: first contact");
    }
    assert_eq!(
        (e.complete, e.collision_free),
        (f.complete, f.collision_free),
        "{name}"
    );
    // (A first-contact exact query that stops at t0 skips the symbolic stage.)
    if e.stats.branch.is_some() && f.stats.branch.is_some() {
        assert_eq!(e.stats.branch, f.stats.branch, "{name}: branch");
    }
    for seg in &f.timeline {
        assert!(!seg.start.certified && !seg.end.certified, "{name}");
    }
}

#[test]
fn shipped_scenes_agree() {
    // Example 5.1 takes the sr0 ≡ 0 branch (Theorem 5.5), the touching
    // spheres sr0 ≡ sr11 ≡ 0 (Theorem 5.6), rigid-tumbling the sr0 branch.
    for name in [
        "paper-example-5-1.toml",
        "rigid-tumbling.toml",
        "static-touching-spheres.toml",
    ] {
        let s = scene_file(name);
        for first in [false, true] {
            let (e, f) = (exact(&s, first), float(&s, first));
            assert!(well_separated_crossings(&exact(&s, false), 1e-6), "{name}");
            assert!(float_error_estimate(&s, &e) <= 1e-7, "{name}");
            assert_agree(name, &e, &f, 1e-9);
        }
    }
}

/// Two tumbling bodies, quaternion curves of degrees 5 and 6: deg_t f = 48,
/// deg sr0 = 288 (the degrees of the paper's Table 3 "degree 4 affine"
/// row; also in `benches/float.rs`).
const RIGID_288: &str = r#"
[a]
radii = [3, "0.5", "0.5"]
[a.motion]
kind = "rigid"
orientation = [[1, 0, 0, 0], [1, 1, 0, 1], [2, 0, 1, 0], [1, 0, 1, 1], [1, 1, 1, 0], [2, 0, 0, 1]]
center = [[-1, 0, 0], [0, 1, 0], [1, 0, 0]]
[b]
radii = [2, "1.5", "0.25"]
[b.motion]
kind = "rigid"
orientation = [[1, 0, 0, 0], [1, 0, 1, 1], [1, 1, 0, 0], [2, 1, 0, 1], [1, 0, 0, 1], [1, 1, 0, 1], [2, 0, 1, 0]]
center = [[-9, "1.2", 0], [0, "-1", "0.5"], [9, "0.9", "0.1"]]
"#;

#[test]
fn degree_288_scene_agrees() {
    let s = Scene::from_toml(RIGID_288).expect("a valid scene");
    let e = exact(&s, false);
    let f = float(&s, false);
    assert_eq!((e.stats.deg_f, e.stats.deg_sr0), (48, Some(288)));
    assert_eq!((f.stats.deg_f, f.stats.deg_sr0), (48, Some(288)));
    assert!(well_separated_crossings(&e, 1e-6));
    assert!(float_error_estimate(&s, &e) <= 1e-7);
    assert_agree("rigid 288", &e, &f, 1e-9);
    assert_agree("rigid 288 first", &exact(&s, true), &float(&s, true), 1e-9);
}

/// Xorshift64*: a small seeded generator, so the scenes are reproducible.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// An integer in `[lo, hi]`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
    /// `p/q` as TOML text, `p ∈ [lo, hi]`, `q ∈ {1, 2, 4}`.
    fn rat(&mut self, lo: i64, hi: i64) -> String {
        let q = [1, 2, 4][self.int(0, 2) as usize];
        format!("\"{}/{}\"", self.int(lo * q, hi * q), q)
    }
    fn vec3(&mut self, lo: i64, hi: i64) -> String {
        format!(
            "[{}, {}, {}]",
            self.rat(lo, hi),
            self.rat(lo, hi),
            self.rat(lo, hi)
        )
    }
    fn radii(&mut self, sphere: bool) -> String {
        let r = |g: &mut Rng| format!("\"{}/4\"", g.int(2, 10));
        if sphere {
            let r = r(self);
            return format!("[{r}, {r}, {r}]");
        }
        format!("[{}, {}, {}]", r(self), r(self), r(self))
    }
    fn quat(&mut self) -> String {
        format!(
            "[{}, {}, {}, {}]",
            self.int(1, 3),
            self.int(-2, 2),
            self.int(-2, 2),
            self.int(-2, 2)
        )
    }
}

/// A random scene: `a` static, translating or tumbling near the origin; `b`
/// sweeping across it (from x ≈ −6 to x ≈ 6), translating or tumbling; one
/// in six are two spheres (sr0 ≡ 0, Note 2: the sr11 branch).
fn random_scene(g: &mut Rng) -> String {
    let spheres = g.int(0, 5) == 0;
    let rigid = |g: &mut Rng, centers: String| {
        format!(
            "kind = \"rigid\"\norientation = [{}, {}]\ncenter = {centers}",
            g.quat(),
            g.quat()
        )
    };
    let a_centers = format!("[{}, {}]", g.vec3(-1, 1), g.vec3(-1, 1));
    let a_motion = match g.int(0, 2) {
        0 => format!("kind = \"static\"\ncenter = {}", g.vec3(-1, 1)),
        1 => format!("kind = \"translation\"\ncenter = {a_centers}"),
        _ => rigid(g, a_centers),
    };
    let (y0, z0, y1, z1) = (g.rat(-2, 2), g.rat(-2, 2), g.rat(-2, 2), g.rat(-2, 2));
    let b_centers = if g.int(0, 1) == 0 {
        format!("[[-6, {y0}, {z0}], [6, {y1}, {z1}]]")
    } else {
        format!("[[-6, {y0}, {z0}], {}, [6, {y1}, {z1}]]", g.vec3(-3, 3))
    };
    let b_motion = if g.int(0, 1) == 0 {
        format!("kind = \"translation\"\ncenter = {b_centers}")
    } else {
        rigid(g, b_centers)
    };
    format!(
        "[a]\nradii = {}\n[a.motion]\n{a_motion}\n[b]\nradii = {}\n[b.motion]\n{b_motion}\n",
        g.radii(spheres),
        g.radii(spheres)
    )
}

/// Seeded random scenes whose contacts cross between states and are apart
/// from each other and the span's ends: float agrees with exact on states,
/// contact counts and branch everywhere, and on contact times to within the
/// float error estimate (or 1e-9); where that estimate is at most 1e-7 (it
/// is pessimistic by two to three orders of magnitude), to 1e-9. First
/// contact queries agree the same way.
#[test]
fn random_translation_and_rigid_scenes_agree() {
    let mut g = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut compared, mut well, mut contacts, mut sr11_branch) = (0, 0, 0, 0);
    for k in 0..150 {
        let text = random_scene(&mut g);
        let s = Scene::from_toml(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
        let e = exact(&s, false);
        if !well_separated_crossings(&e, 1e-6) {
            continue;
        }
        let estimate = float_error_estimate(&s, &e);
        let tol = if estimate <= 1e-7 {
            1e-9
        } else {
            estimate.max(1e-9)
        };
        let name = format!("scene {k} (error estimate {estimate:e}):\n{text}");
        assert_agree(&name, &e, &float(&s, false), tol);
        assert_agree(&name, &exact(&s, true), &float(&s, true), tol);
        compared += 1;
        sr11_branch += usize::from(e.stats.branch == Some(ccd_exact::Branch::Sr11));
        if estimate <= 1e-7 {
            well += 1;
            contacts += e.contacts.len();
        }
    }
    eprintln!(
        "{compared} compared, {well} well-conditioned, {contacts} contacts, {sr11_branch} sr11"
    );
    assert!(
        compared >= 140 && well >= 130 && contacts >= 230 && sr11_branch >= 20,
        "{compared} scenes, {well} well-conditioned with {contacts} contacts, {sr11_branch} sr11"
    );
}

/// A unit sphere sliding over the top of the ellipsoid x²/4 + y² + z² = 1
/// with its centre on the line y = Y, z = 0, x from −4 to 4. For Y = 2 it
/// grazes the ellipsoid at u = 1/2: the ellipsoid's top is flatter than the
/// sphere, so they touch at the one point (0, 1, 0) and separate again.
const GRAZE: &str = r#"
    [a]
    radii = [2, 1, 1]
    [b]
    radii = [1, 1, 1]
    [b.motion]
    kind = "translation"
    center = [[-4, Y, 0], [4, Y, 0]]
"#;

fn graze(y: &str) -> Scene {
    Scene::from_toml(&GRAZE.replace('Y', y)).expect("a valid scene")
}

/// WHERE FLOAT MODE IS WRONG. The tangential graze is one external touch
/// at exactly u = 1/2 (sr0 has a double root there), which exact mode
/// reports as Separate, Touch, Separate. In f64 the double root of sr0 is
/// perturbed by rounding (~1e-18 relative) into two simple roots about
/// √1e-18 ≈ 1e-9 either side of 1/2, and each passes the touch test. So
/// float mode reports TWO contacts straddling the graze, and for the piece
/// between them — sampled, by the shared timeline rules, at its simplest
/// rational, which is 1/2, the graze itself — a touch: a Touch segment of
/// positive length, which exact mode never produces (the bodies are in
/// fact separate on that piece except at 1/2). Had the rounding gone the
/// other way, the double root would have vanished and float mode would
/// have missed the touch altogether: near a double root floats can only
/// guess. The first contact is still right to ~1e-9.
///
/// For comparison, the neighbouring scenes that are not tangential are
/// answered correctly by float mode: a near miss (gap 1e-12) is collision
/// free and a shallow pass (depth 1e-12) overlaps between two contacts
/// ~4e-7 either side of 1/2.
#[test]
fn documented_failure_tangential_graze() {
    use State::{Overlap, Separate, Touch};
    let s = graze("2");
    let e = exact(&s, false);
    assert_eq!(states(&e), [Separate, Touch, Separate]);
    assert_eq!(e.contacts.len(), 1);
    assert_eq!(e.contacts[0].lo, Rat::from_frac(1, 2));
    assert_eq!(e.contacts[0].hi, Rat::from_frac(1, 2));

    let f = float(&s, false);
    assert_eq!(states(&f), [Separate, Touch, Touch, Touch, Separate]);
    let between = &f.timeline[2];
    assert!(between.start.hi < between.end.lo, "a touch on an interval");
    assert!(!f.collision_free);
    let (c0, c1) = (mid(&f.contacts[0]), mid(&f.contacts[1]));
    assert!(c0 < 0.5 && 0.5 < c1, "{c0} {c1}");
    assert!(0.5 - c0 > 1e-10 && c1 - 0.5 > 1e-10, "{c0} {c1}");
    assert!(0.5 - c0 < 1e-8 && c1 - 0.5 < 1e-8, "{c0} {c1}");
    // The first contact is right to ~1e-9; what follows it is not.
    assert!((mid(f.first_contact.as_ref().unwrap()) - 0.5).abs() < 1e-8);

    // Near miss (gap 1e-12): both modes say collision free.
    let s = graze("\"2.000000000001\"");
    assert!(exact(&s, false).collision_free);
    assert!(float(&s, false).collision_free);
    // Shallow pass (depth 1e-12): both see the overlap between two contacts.
    let s = graze("\"1.999999999999\"");
    let (e, f) = (exact(&s, false), float(&s, false));
    assert_eq!(states(&e), [Separate, Touch, Overlap, Touch, Separate]);
    assert_agree("shallow pass", &e, &f, 1e-9);
}
