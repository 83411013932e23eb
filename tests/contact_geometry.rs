//! Contact points and normals (issue 14): on both surfaces at the contact
//! instant, the normal along both gradients (A's outward, B's inward), and
//! an independent float cross-check against the Perram–Wertheim contact
//! point on every shipped scene with contacts.

use ccd_arith::{Interval, Rat};
use ccd_enclosure::{quadric_at, BigInterval};
use ccd_exact::{run, to_json, Arithmetic, Box3, Geometry, Options, Outcome, Scene};
use ccd_motion::{placed_quadric, Body};
use ccd_quadric::Mat4;

fn load(path: &str) -> Scene {
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{full}: {e}"))
}

/// The shipped scenes whose radii span at most twelve orders of magnitude
/// (the widths of docs/scene-format.md's goal are promised there; the
/// stability report's `ratio-*` families go to `10⁻⁴⁰⁹⁶`, where the
/// normal's box is only as narrow as 512-bit intervals allow, or there is
/// no point box at all, `point_note` saying why).
fn shipped() -> Vec<(String, Scene)> {
    all_shipped()
        .into_iter()
        .filter(|(_, s)| {
            let radii: Vec<f64> =
                s.a.radii
                    .iter()
                    .chain(&s.b.radii)
                    .map(Rat::to_f64)
                    .collect();
            let (lo, hi) = radii
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(l, h), r| (l.min(*r), h.max(*r)));
            hi <= 1e12 * lo
        })
        .collect()
}

fn all_shipped() -> Vec<(String, Scene)> {
    let mut out = vec![];
    for dir in ["tests/scenes", "tests/stability"] {
        let full = format!("{}/{dir}", env!("CARGO_MANIFEST_DIR"));
        let mut names: Vec<String> = std::fs::read_dir(&full)
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            // World files (many bodies) are tests/world.rs's.
            .filter(|n| n.ends_with(".toml") && !n.starts_with("world-"))
            .collect();
        names.sort();
        for n in names {
            let path = format!("{dir}/{n}");
            out.push((path.clone(), load(&path)));
        }
    }
    out
}

fn size(s: &Scene) -> f64 {
    s.a.radii
        .iter()
        .chain(&s.b.radii)
        .map(Rat::to_f64)
        .fold(0.0, f64::max)
}

fn point_of(g: &Geometry) -> (&Box3, &Box3, bool) {
    match g {
        Geometry::Point {
            point,
            normal,
            certified,
        } => (point, normal, *certified),
        other => panic!("no point: {other:?}"),
    }
}

fn mid(b: &Box3) -> [f64; 3] {
    b.midpoint().map(|x| x.to_f64())
}

/// `A(t)` in `f64` at the time `t` (entries' midpoints).
fn quadric_f64(body: &Body, span: &[Rat; 2], t: &Rat) -> [[f64; 4]; 4] {
    quadric_at(body, span, &Interval::from_rat(t), 53).map(|row| row.map(|x| x.mid()))
}

/// `XᵀQX` enclosed for `X = (box, 1)`, `Q` enclosed at the time enclosure
/// `[lo, hi]`, in 256-bit intervals, by the mean value form around the
/// box's midpoint `m`: `v(m) + ∇v(box)·(box − m)` (the plain interval form
/// loses `|Q|·|X|²` to the dependency problem far from the origin).
fn form_on_box(body: &Body, span: &[Rat; 2], lo: &Rat, hi: &Rat, b: &Box3) -> BigInterval {
    use ccd_arith::RingOps;
    let prec = 256;
    let k = |q: &Rat| BigInterval::from_rat(q, prec);
    let t = k(lo).hull(&k(hi));
    let q: Mat4<BigInterval> = quadric_at(body, span, &t, prec);
    let m = b.midpoint();
    let xm: [BigInterval; 4] =
        std::array::from_fn(|i| if i == 3 { k(&Rat::one()) } else { k(&m[i]) });
    let xb: [BigInterval; 4] = std::array::from_fn(|i| {
        if i == 3 {
            k(&Rat::one())
        } else {
            k(&b.lo[i]).hull(&k(&b.hi[i]))
        }
    });
    let mut v = k(&Rat::zero());
    for i in 0..4 {
        for j in 0..4 {
            v = v.plus(&xm[i].times(&q[i][j].times(&xm[j])));
        }
    }
    for i in 0..3 {
        let g = (0..4).fold(k(&Rat::zero()), |acc, j| acc.plus(&q[i][j].times(&xb[j])));
        v = v.plus(
            &g.times(&xb[i].minus(&xm[i]))
                .times(&BigInterval::from_i64(2)),
        );
    }
    v
}

fn gradient(q: &[[f64; 4]; 4], x: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|r| 2.0 * ((0..3).map(|c| q[r][c] * x[c]).sum::<f64>() + q[r][3]))
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    v.map(|x| x / n)
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

/// 3×3 solve by Cramer's rule (test reference, `f64`).
fn solve3(m: &[[f64; 3]; 3], v: &[f64; 3]) -> [f64; 3] {
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(m);
    std::array::from_fn(|k| {
        let mut mk = *m;
        for (row, vi) in mk.iter_mut().zip(v) {
            row[k] = *vi;
        }
        det(&mk) / d
    })
}

fn mat_vec(m: &[[f64; 3]; 3], v: &[f64; 3]) -> [f64; 3] {
    std::array::from_fn(|r| (0..3).map(|c| m[r][c] * v[c]).sum())
}

/// Centre `c` and shape `Σ` (the body is `(x − c)ᵀΣ⁻¹(x − c) <= 1`) of the
/// ellipsoid `XᵀQX <= 0`: `Q = [[P, q], [qᵀ, r]]`, `c = −P⁻¹q`,
/// `Σ = (qᵀP⁻¹q − r)·P⁻¹`.
fn centre_shape(q: &[[f64; 4]; 4]) -> ([f64; 3], [[f64; 3]; 3]) {
    let p: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| q[i][j]));
    let qv: [f64; 3] = std::array::from_fn(|i| q[i][3]);
    let pinv_q = solve3(&p, &qv);
    let c = pinv_q.map(|x| -x);
    let k = (0..3).map(|i| qv[i] * pinv_q[i]).sum::<f64>() - q[3][3];
    let cols: [[f64; 3]; 3] = std::array::from_fn(|j| {
        let e: [f64; 3] = std::array::from_fn(|i| (i == j) as i64 as f64);
        solve3(&p, &e)
    });
    let sigma = std::array::from_fn(|i| std::array::from_fn(|j| k * cols[j][i]));
    (c, sigma)
}

/// The Perram–Wertheim contact point (floats; independent of the engine's
/// kernel computation): `x = cA + (1−s)·ΣA·C⁻¹·d`, `C = (1−s)ΣA + sΣB`,
/// `d = cB − cA`, at the `s` maximising `F(s) = s(1−s)·dᵀC⁻¹d` (F is
/// concave; its derivative is bisected to machine precision). Also `F(s)`,
/// which is 1 at touching.
fn perram_wertheim(qa: &[[f64; 4]; 4], qb: &[[f64; 4]; 4]) -> ([f64; 3], f64) {
    let (ca, sa) = centre_shape(qa);
    let (cb, sb) = centre_shape(qb);
    let d: [f64; 3] = std::array::from_fn(|i| cb[i] - ca[i]);
    let c = |s: f64| -> [[f64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| (1.0 - s) * sa[i][j] + s * sb[i][j]))
    };
    let dot = |x: &[f64; 3], y: &[f64; 3]| (0..3).map(|i| x[i] * y[i]).sum::<f64>();
    let diff: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| sb[i][j] - sa[i][j]));
    let slope = |s: f64| {
        let y = solve3(&c(s), &d);
        (1.0 - 2.0 * s) * dot(&d, &y) - s * (1.0 - s) * dot(&y, &mat_vec(&diff, &y))
    };
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..200 {
        let m = 0.5 * (lo + hi);
        if m <= lo || m >= hi {
            break;
        }
        if slope(m) > 0.0 {
            lo = m;
        } else {
            hi = m;
        }
    }
    let s = 0.5 * (lo + hi);
    let y = solve3(&c(s), &d);
    let step = mat_vec(&sa, &y);
    let x = std::array::from_fn(|i| ca[i] + (1.0 - s) * step[i]);
    (x, s * (1.0 - s) * dot(&d, &y))
}

/// Every check of one contact: point on both surfaces (exactly at a
/// rational instant with an exact point, by enclosure otherwise), normal
/// along A's outward and against B's outward gradient, Perram–Wertheim
/// within `1e-9` of the scene size. Returns the Perram–Wertheim deviation
/// relative to the size.
fn check_contact(name: &str, s: &Scene, out: &Outcome, k: usize) -> f64 {
    let c = &out.contacts[k];
    let (point, normal, certified) = point_of(&out.geometry[k]);
    assert_eq!(certified, c.certified, "{name}: contact {k}");
    let size = size(s);
    let rmin =
        s.a.radii
            .iter()
            .chain(&s.b.radii)
            .map(Rat::to_f64)
            .fold(f64::INFINITY, f64::min);
    let rational_scene = s.a.motion.is_rational() && s.b.motion.is_rational();
    if c.certified {
        // The exact path meets the default goal (ccd_contact::Goal); the
        // helical path does not narrow the time enclosure, so its boxes
        // are only as narrow as that allows.
        let slack = if rational_scene { 1.0 } else { 1e3 };
        let w = point.width().to_f64();
        assert!(w <= slack * 1e-12 * size, "{name}: {point:?}");
        let w = normal.width().to_f64();
        assert!(w <= slack * 1e-12 * size / rmin, "{name}: {normal:?}");
    }
    let exact_instant = c.lo == c.hi && point.lo == point.hi;
    if exact_instant && rational_scene {
        // Exactly on both surfaces: XᵀQX = 0 with Q exact at u.
        let [t0, t1] = &s.span;
        let u = &(&c.lo - t0) / &(t1 - t0);
        for body in [&s.a, &s.b] {
            let q = placed_quadric(body, &s.span).unwrap().quadric_at(&u);
            let x: Vec<Rat> = point.lo.iter().cloned().chain([Rat::one()]).collect();
            let mut v = Rat::zero();
            for i in 0..4 {
                for j in 0..4 {
                    v = &v + &(&(&x[i] * &Rat::from_int(q[i][j].clone())) * &x[j]);
                }
            }
            assert!(v.is_zero(), "{name}: XᵀQX = {v} at the exact point");
        }
    } else if c.certified {
        for body in [&s.a, &s.b] {
            let v = form_on_box(body, &s.span, &c.lo, &c.hi, point);
            assert!(v.contains_zero(), "{name}: XᵀQX ∈ {v:?} excludes 0");
            // Narrow enough that a point off the surface by 1e-8 of the
            // size would fail: |XᵀQX| grows like |∇Q|·distance (Q has an
            // arbitrary positive scale, so compare with its gradient).
            let q = quadric_f64(body, &s.span, &c.midpoint());
            let g = gradient(&q, &mid(point));
            let g = g.iter().map(|x| x * x).sum::<f64>().sqrt();
            assert!(v.width_f64() < 1e-8 * g * size, "{name}: {v:?}, |∇Q| = {g}");
        }
    }
    let t = c.midpoint();
    let (qa, qb) = (
        quadric_f64(&s.a, &s.span, &t),
        quadric_f64(&s.b, &s.span, &t),
    );
    let x = mid(point);
    let n = unit(mid(normal));
    let (ga, gb) = (unit(gradient(&qa, &x)), unit(gradient(&qb, &x)));
    assert!(dist(&n, &ga) < 1e-9, "{name}: normal {n:?} vs ∇A {ga:?}");
    assert!(
        dist(&n, &gb.map(|v| -v)) < 1e-9,
        "{name}: normal {n:?} vs −∇B {gb:?}"
    );
    let (pw, f) = perram_wertheim(&qa, &qb);
    assert!(
        (f - 1.0).abs() < 1e-8,
        "{name}: Perram–Wertheim F = {f} at a touch"
    );
    let deviation = dist(&pw, &x) / size;
    assert!(deviation <= 1e-9, "{name}: Perram–Wertheim {pw:?} vs {x:?}");
    deviation
}

#[test]
fn example_5_1_contacts_are_on_both_surfaces() {
    let s = load("tests/scenes/paper-example-5-1.toml");
    let out = run(&s, &Options::default()).unwrap();
    assert_eq!(out.contacts.len(), 2);
    assert_eq!(out.geometry.len(), 2);
    for k in 0..2 {
        check_contact("example 5.1", &s, &out, k);
    }
    // The paper's figure: the first touch is near (3.763, 0.079, −0.921).
    let (p, _, _) = point_of(&out.geometry[0]);
    assert!(dist(&mid(p), &[3.762974279322, 0.079008573559, -0.920991426441]) < 1e-11);
}

#[test]
fn every_shipped_scene_with_contacts_passes_perram_wertheim() {
    let mut worst: f64 = 0.0;
    let mut checked = 0;
    for (name, s) in shipped() {
        let out = match run(&s, &Options::default()) {
            Ok(o) => o,
            Err(e) => panic!("{name}: {e}"),
        };
        assert_eq!(out.geometry.len(), out.contacts.len(), "{name}");
        for k in 0..out.contacts.len() {
            worst = worst.max(check_contact(&name, &s, &out, k));
            checked += 1;
        }
    }
    eprintln!("{checked} contacts, Perram–Wertheim max deviation {worst:e} of the scene size");
    assert!(checked >= 40, "only {checked} contacts checked");
}

#[test]
fn float_mode_points_are_estimates_near_the_exact_ones() {
    let mut checked = 0;
    for (name, s) in shipped() {
        if !(s.a.motion.is_rational() && s.b.motion.is_rational()) {
            continue;
        }
        let exact = run(&s, &Options::default()).unwrap();
        let float = Options {
            arithmetic: Arithmetic::Float,
            ..Options::default()
        };
        let out = run(&s, &float).unwrap();
        assert_eq!(out.geometry.len(), out.contacts.len(), "{name}");
        // The float path's failures are documented elsewhere
        // (docs/stability.md): its points are compared where its instants
        // are right.
        let instants_agree = out.contacts.len() == exact.contacts.len()
            && out
                .contacts
                .iter()
                .zip(&exact.contacts)
                .all(|(f, e)| (f.midpoint().to_f64() - e.midpoint().to_f64()).abs() < 1e-9);
        if !instants_agree {
            continue;
        }
        for (g, e) in out.geometry.iter().zip(&exact.geometry) {
            let (p, n, certified) = point_of(g);
            assert!(!certified && p.lo == p.hi && n.lo == n.hi, "{name}");
            let (ep, _, _) = point_of(e);
            assert!(
                dist(&mid(p), &mid(ep)) < 1e-6 * size(&s),
                "{name}: {p:?} vs {ep:?}"
            );
            checked += 1;
        }
    }
    assert!(checked >= 20, "only {checked}");
}

/// A scene whose contact point and normal are known by construction.
fn tangency(b_radii: &str, c0: &str, c1: &str) -> Scene {
    Scene::from_toml(&format!(
        r#"
        [a]
        radii = [2, 1, 1]
        [b]
        radii = {b_radii}
        motion = {{ kind = "translation", center = [{c0}, {c1}] }}
        "#
    ))
    .unwrap()
}

#[test]
fn rational_tangency_known_by_construction() {
    // B, with radii (1, 3/2, 1/2), passes (3, 0, 0) at u = 1/2 moving along
    // −(1, 1, 1): tangent to x = 2 there, so A and B touch at (2, 0, 0)
    // with A's normal +x, then overlap.
    let s = tangency(r#"[1, "3/2", "1/2"]"#, "[4, 1, 1]", "[2, -1, -1]");
    let out = run(&s, &Options::default()).unwrap();
    let half = Rat::from_frac(1, 2);
    assert!(out.contacts[0].lo <= half && half <= out.contacts[0].hi);
    let (p, n, certified) = point_of(&out.geometry[0]);
    assert!(certified);
    for i in 0..3 {
        let want = Rat::from([2, 0, 0][i]);
        assert!(p.lo[i] <= want && want <= p.hi[i], "{p:?}");
        let want = Rat::from([1, 0, 0][i]);
        assert!(n.lo[i] <= want && want <= n.hi[i], "{n:?}");
    }
    check_contact("tangency (2a)", &s, &out, 0);
    // B = A reflected through p = (8/5, 3/5, 0) on A (x²/4 + y² = 1), moving
    // along A's normal (2, 3, 0) at p: touch at u = 1/2 at p, normal
    // (2/3, 1, 0) (largest component 1). A translate of A: case (2b).
    let s = tangency(
        "[2, 1, 1]",
        r#"["18/5", "9/5", 0]"#,
        r#"["14/5", "3/5", 0]"#,
    );
    let out = run(&s, &Options::default()).unwrap();
    assert_eq!(out.contacts[0].lo, half);
    assert_eq!(out.contacts[0].hi, half);
    let (p, n, certified) = point_of(&out.geometry[0]);
    assert!(certified);
    let (want_p, want_n) = (
        [Rat::from_frac(8, 5), Rat::from_frac(3, 5), Rat::zero()],
        [Rat::from_frac(2, 3), Rat::one(), Rat::zero()],
    );
    for i in 0..3 {
        assert!(p.lo[i] <= want_p[i] && want_p[i] <= p.hi[i], "{p:?}");
        assert!(n.lo[i] <= want_n[i] && want_n[i] <= n.hi[i], "{n:?}");
    }
    check_contact("tangency (2b)", &s, &out, 0);
    // At this rational instant the rational point itself is also found
    // exactly (what the exact path falls back to when f64 intervals are
    // too wide).
    let rat = |m: [[ccd_arith::Int; 4]; 4]| m.map(|row| row.map(Rat::from_int));
    let u = Rat::from_frac(1, 2);
    let qa = rat(placed_quadric(&s.a, &s.span).unwrap().quadric_at(&u));
    let qb = rat(placed_quadric(&s.b, &s.span).unwrap().quadric_at(&u));
    let e = ccd_contact::from_quadrics(&qa, &qb, ccd_contact::Case::TwoDouble).unwrap();
    assert_eq!((e.point, e.normal), (want_p, want_n));
}

#[test]
fn first_contact_only_carries_the_same_geometry() {
    let s = load("tests/scenes/paper-example-5-1.toml");
    let full = run(&s, &Options::default()).unwrap();
    let first = run(
        &s,
        &Options {
            first_contact_only: true,
            ..Options::default()
        },
    )
    .unwrap();
    assert_eq!(first.geometry, full.geometry[..1]);
    let j = to_json(&first);
    assert_eq!(j["first_contact"]["point"], j["contacts"][0]["point"]);
    assert!(j["first_contact"]["normal"]["lo"].is_array());
}

#[test]
fn json_adds_only_point_and_normal() {
    for (name, s) in shipped() {
        let with = to_json(&run(&s, &Options::default()).unwrap());
        let without = Options {
            contact_geometry: false,
            ..Options::default()
        };
        let mut stripped = with.clone();
        let without = to_json(&run(&s, &without).unwrap());
        let strip = |v: &mut serde_json::Value| {
            if let Some(o) = v.as_object_mut() {
                for key in ["point", "normal", "point_note"] {
                    o.remove(key);
                }
            }
        };
        for c in stripped["contacts"].as_array_mut().unwrap() {
            strip(c);
        }
        strip(&mut stripped["first_contact"]);
        assert_eq!(stripped, without, "{name}");
        for c in with["contacts"].as_array().unwrap() {
            for key in ["point", "normal"] {
                let b = &c[key];
                for end in ["lo", "hi", "approx"] {
                    let v = b[end]
                        .as_array()
                        .unwrap_or_else(|| panic!("{name}: {key}.{end}"));
                    assert_eq!(v.len(), 3);
                    for x in v {
                        let text = x.as_str().unwrap();
                        if end != "approx" {
                            // Exact rationals in lowest terms.
                            let q: Rat = text.parse().unwrap();
                            assert_eq!(q.to_string(), text);
                        } else {
                            assert!(text.parse::<f64>().is_ok());
                        }
                    }
                }
            }
        }
    }
}
