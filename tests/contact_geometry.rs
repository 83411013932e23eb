//! Contact points and normals (issue 14): on both surfaces at the contact
//! instant, the normal along both gradients (A's outward, B's inward), and
//! an independent float cross-check against the Perram–Wertheim contact
//! point on every shipped scene with contacts.

use ccd_arith::{Interval, Rat};
use ccd_enclosure::{quadric_at, BigInterval};
use ccd_exact::{run, to_json, Arithmetic, Box3, Geometry, Instant, Options, Outcome, Scene};
use ccd_motion::{placed_quadric, Body};
use ccd_quadric::Mat4;

fn load(path: &str) -> Scene {
    let full = format!("{}/{path}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{full}: {e}"))
}

/// The largest radius over the smallest.
fn radius_ratio(s: &Scene) -> f64 {
    let radii: Vec<f64> =
        s.a.radii
            .iter()
            .chain(&s.b.radii)
            .map(Rat::to_f64)
            .collect();
    let (lo, hi) = radii
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), r| (l.min(*r), h.max(*r)));
    hi / lo
}

/// Radius ratios above this get the exact reference (`f64` overflows in
/// the Perram–Wertheim solve: a 10⁻⁶⁴ radius puts 10¹²⁸ in the quadric).
const EXTREME_RATIO: f64 = 1e12;

/// The shipped scenes whose radii span at most twelve orders of magnitude:
/// where the float path's estimates are compared with the exact points.
fn shipped() -> Vec<(String, Scene)> {
    all_shipped()
        .into_iter()
        .filter(|(_, s)| radius_ratio(s) <= EXTREME_RATIO)
        .collect()
}

fn all_shipped() -> Vec<(String, Scene)> {
    let mut out = vec![];
    for dir in ["tests/scenes", "benches/scenes", "tests/stability"] {
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

/// The arithmetic of the test's references: `f64`, or exact rationals
/// for extreme radius ratios.
trait Num: Clone + PartialOrd {
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    fn div(&self, o: &Self) -> Self;
    fn int(v: i64) -> Self;
    fn half(&self) -> Self;
    fn abs(&self) -> Self;
    fn f64(&self) -> f64;
    /// Bisection steps for the Perram–Wertheim maximum.
    const STEPS: usize;
}

/// `add`, `sub`, `mul`, `div` of [`Num`] by the type's operators on
/// references.
macro_rules! arithmetic_by_operators {
    () => {
        fn add(&self, o: &Self) -> Self {
            self + o
        }
        fn sub(&self, o: &Self) -> Self {
            self - o
        }
        fn mul(&self, o: &Self) -> Self {
            self * o
        }
        fn div(&self, o: &Self) -> Self {
            self / o
        }
    };
}

impl Num for f64 {
    arithmetic_by_operators!();
    fn int(v: i64) -> Self {
        v as f64
    }
    fn half(&self) -> Self {
        0.5 * self
    }
    fn abs(&self) -> Self {
        f64::abs(*self)
    }
    fn f64(&self) -> f64 {
        *self
    }
    const STEPS: usize = 200;
}

impl Num for Rat {
    arithmetic_by_operators!();
    fn int(v: i64) -> Self {
        Rat::from(v)
    }
    fn half(&self) -> Self {
        self.mul_pow2(-1)
    }
    fn abs(&self) -> Self {
        Rat::abs(self)
    }
    fn f64(&self) -> f64 {
        self.to_f64()
    }
    const STEPS: usize = 120;
}

/// The first three components of `Q·X`, `X = (x, 1)` (half the gradient).
fn gradient<N: Num>(q: &[[N; 4]; 4], x: &[N; 3]) -> [N; 3] {
    std::array::from_fn(|r| (0..3).fold(q[r][3].clone(), |acc, c| acc.add(&q[r][c].mul(&x[c]))))
}

/// `v` as a unit `f64` vector (scaled by its largest component first, so
/// that nothing overflows).
fn direction<N: Num>(v: &[N; 3]) -> [f64; 3] {
    let m = v
        .iter()
        .map(N::abs)
        .fold(N::int(0), |a, b| if b > a { b } else { a });
    unit(std::array::from_fn(|i| v[i].div(&m).f64()))
}

fn unit(v: [f64; 3]) -> [f64; 3] {
    let n = v.iter().map(|x| x * x).sum::<f64>().sqrt();
    v.map(|x| x / n)
}

fn dist(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

fn det3<N: Num>(m: &[[N; 3]; 3]) -> N {
    let minor =
        |i: usize, j: usize, k: usize, l: usize| m[1][i].mul(&m[2][j]).sub(&m[1][k].mul(&m[2][l]));
    m[0][0]
        .mul(&minor(1, 2, 2, 1))
        .sub(&m[0][1].mul(&minor(0, 2, 2, 0)))
        .add(&m[0][2].mul(&minor(0, 1, 1, 0)))
}

/// 3×3 solve by Cramer's rule (test reference).
fn solve3<N: Num>(m: &[[N; 3]; 3], v: &[N; 3]) -> [N; 3] {
    let d = det3(m);
    std::array::from_fn(|k| {
        let mut mk = m.clone();
        for (row, vi) in mk.iter_mut().zip(v) {
            row[k] = vi.clone();
        }
        det3(&mk).div(&d)
    })
}

fn mat_vec<N: Num>(m: &[[N; 3]; 3], v: &[N; 3]) -> [N; 3] {
    std::array::from_fn(|r| (0..3).fold(N::int(0), |acc, c| acc.add(&m[r][c].mul(&v[c]))))
}

fn dot<N: Num>(x: &[N; 3], y: &[N; 3]) -> N {
    (0..3).fold(N::int(0), |acc, i| acc.add(&x[i].mul(&y[i])))
}

/// Centre `c` and shape `Σ` (the body is `(x − c)ᵀΣ⁻¹(x − c) <= 1`) of the
/// ellipsoid `XᵀQX <= 0`: `Q = [[P, q], [qᵀ, r]]`, `c = −P⁻¹q`,
/// `Σ = (qᵀP⁻¹q − r)·P⁻¹`.
fn centre_shape<N: Num>(q: &[[N; 4]; 4]) -> ([N; 3], [[N; 3]; 3]) {
    let p: [[N; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| q[i][j].clone()));
    let qv: [N; 3] = std::array::from_fn(|i| q[i][3].clone());
    let pinv_q = solve3(&p, &qv);
    let c = pinv_q.clone().map(|x| N::int(0).sub(&x));
    let k = dot(&qv, &pinv_q).sub(&q[3][3]);
    let cols: [[N; 3]; 3] = std::array::from_fn(|j| {
        let e: [N; 3] = std::array::from_fn(|i| N::int((i == j) as i64));
        solve3(&p, &e)
    });
    let sigma = std::array::from_fn(|i| std::array::from_fn(|j| k.mul(&cols[j][i])));
    (c, sigma)
}

/// The Perram–Wertheim contact point (independent of the engine's kernel
/// computation): `x = cA + (1−s)·ΣA·C⁻¹·d`, `C = (1−s)ΣA + sΣB`,
/// `d = cB − cA`, at the `s` maximising `F(s) = s(1−s)·dᵀC⁻¹d` (F is
/// concave; its derivative is bisected, to machine precision in `f64`, to
/// `2^−120` in rationals). Also `F(s)`, which is 1 at touching.
fn perram_wertheim<N: Num>(qa: &[[N; 4]; 4], qb: &[[N; 4]; 4]) -> ([f64; 3], f64) {
    let (ca, sa) = centre_shape(qa);
    let (cb, sb) = centre_shape(qb);
    let one = N::int(1);
    let d: [N; 3] = std::array::from_fn(|i| cb[i].sub(&ca[i]));
    let c = |s: &N| -> [[N; 3]; 3] {
        let r = one.sub(s);
        std::array::from_fn(|i| std::array::from_fn(|j| r.mul(&sa[i][j]).add(&s.mul(&sb[i][j]))))
    };
    let diff: [[N; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| sb[i][j].sub(&sa[i][j])));
    let slope = |s: &N| {
        let y = solve3(&c(s), &d);
        let a = one.sub(&N::int(2).mul(s)).mul(&dot(&d, &y));
        a.sub(&s.mul(&one.sub(s)).mul(&dot(&y, &mat_vec(&diff, &y))))
    };
    let (mut lo, mut hi) = (N::int(0), one.clone());
    for _ in 0..N::STEPS {
        let m = lo.add(&hi).half();
        if m <= lo || m >= hi {
            break;
        }
        if slope(&m) > N::int(0) {
            lo = m;
        } else {
            hi = m;
        }
    }
    let s = lo.add(&hi).half();
    let y = solve3(&c(&s), &d);
    let step = mat_vec(&sa, &y);
    let r = one.sub(&s);
    let x = std::array::from_fn(|i| ca[i].add(&r.mul(&step[i])).f64());
    (x, s.mul(&r).mul(&dot(&d, &y)).f64())
}

/// The quadrics at the time `t`, and the test's reference at the point
/// `x`: the unit directions of `A·X` and `B·X` (gradients), `|∇A|`, `|∇B|`,
/// the Perram–Wertheim point and `F`. In `f64`, or exactly (rational
/// motions) for radius ratios above [`EXTREME_RATIO`].
struct Reference {
    ga: [f64; 3],
    gb: [f64; 3],
    norms: [f64; 2],
    /// How much each gradient's direction can turn over a box of width 1
    /// around `x`: the largest entry of `Q`'s 3×3 block over `|Q·X|∞`.
    turn: [f64; 2],
    pw: [f64; 3],
    f: f64,
}

fn reference(s: &Scene, t: &Rat, x: &[Rat; 3]) -> Reference {
    fn of<N: Num>(qa: &[[N; 4]; 4], qb: &[[N; 4]; 4], x: &[N; 3]) -> Reference {
        let (ga, gb) = (gradient(qa, x), gradient(qb, x));
        // |∇(XᵀQX)| = 2·|Q·X|, scaled by the largest component first.
        let norm = |g: &[N; 3]| {
            let m = g
                .iter()
                .map(N::abs)
                .fold(N::int(0), |a, b| if b > a { b } else { a });
            let scaled: [f64; 3] = std::array::from_fn(|i| g[i].div(&m).f64());
            2.0 * m.f64() * dist(&scaled, &[0.0; 3])
        };
        let turn = |q: &[[N; 4]; 4], g: &[N; 3]| {
            let big = |v: &mut dyn Iterator<Item = &N>| {
                v.map(N::abs)
                    .fold(N::int(0), |a, b| if b > a { b } else { a })
            };
            let block = big(&mut q[..3].iter().flat_map(|row| row[..3].iter()));
            block.div(&big(&mut g.iter())).f64()
        };
        let (pw, f) = perram_wertheim(qa, qb);
        Reference {
            ga: direction(&ga),
            gb: direction(&gb),
            norms: [norm(&ga), norm(&gb)],
            turn: [turn(qa, &ga), turn(qb, &gb)],
            pw,
            f,
        }
    }
    let rational = s.a.motion.is_rational() && s.b.motion.is_rational();
    if rational && radius_ratio(s) > EXTREME_RATIO {
        let [t0, t1] = &s.span;
        let u = &(t - t0) / &(t1 - t0);
        let q = |body: &Body| -> [[Rat; 4]; 4] {
            let m = placed_quadric(body, &s.span).unwrap().quadric_at(&u);
            m.map(|row| row.map(Rat::from_int))
        };
        of(&q(&s.a), &q(&s.b), x)
    } else {
        let x = x.clone().map(|v| v.to_f64());
        of(
            &quadric_f64(&s.a, &s.span, t),
            &quadric_f64(&s.b, &s.span, t),
            &x,
        )
    }
}

/// Every check of one contact: [`check_point`] at the contact's instant.
fn check_contact(name: &str, s: &Scene, out: &Outcome, k: usize) -> f64 {
    let c = &out.contacts[k];
    let (_, _, certified) = point_of(&out.geometry[k]);
    assert_eq!(certified, c.certified, "{name}: contact {k}");
    check_point(name, s, c, &out.geometry[k])
}

/// Every check of the geometry `g` at the touch instant `c`: point on both
/// surfaces (exactly at a rational instant with an exact point, by
/// enclosure otherwise), the default width goal where certified, normal
/// along A's outward and against B's outward gradient, Perram–Wertheim
/// within `1e-9` of the scene size. Returns the Perram–Wertheim deviation
/// relative to the size.
fn check_point(name: &str, s: &Scene, c: &Instant, g: &Geometry) -> f64 {
    let (point, normal, certified) = point_of(g);
    let size = size(s);
    let rmin =
        s.a.radii
            .iter()
            .chain(&s.b.radii)
            .map(Rat::to_f64)
            .fold(f64::INFINITY, f64::min);
    let rational_scene = s.a.motion.is_rational() && s.b.motion.is_rational();
    if certified {
        // The exact path meets the default goal (ccd_contact::Goal); the
        // helical path does not narrow the time enclosure, so its boxes
        // are only as narrow as that allows.
        let slack = if rational_scene { 1.0 } else { 1e3 };
        let w = point.width().to_f64();
        assert!(w <= slack * 1e-12 * size, "{name}: {point:?}");
        let w = normal.width().to_f64();
        assert!(w <= slack * 1e-12 * size / rmin, "{name}: {normal:?}");
    }
    let t = c.midpoint();
    let r = reference(s, &t, &point.midpoint());
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
    } else if certified {
        for (body, g) in [(&s.a, r.norms[0]), (&s.b, r.norms[1])] {
            let v = form_on_box(body, &s.span, &c.lo, &c.hi, point);
            assert!(v.contains_zero(), "{name}: XᵀQX ∈ {v:?} excludes 0");
            // Narrow enough that a point off the surface by 1e-8 of the
            // size would fail: |XᵀQX| grows like |∇Q|·distance (Q has an
            // arbitrary positive scale, so compare with its gradient).
            assert!(v.width_f64() < 1e-8 * g * size, "{name}: {v:?}, |∇Q| = {g}");
        }
    }
    let x = mid(point);
    // The normal along ∇A and −∇B at the point box's midpoint, wherever
    // that gradient's direction is determined by the box (a disc A of
    // thickness 10⁻⁶⁴ turns its gradient completely within a box 10⁻²⁶
    // wide: there only −∇B is compared, which the other must then be).
    let n = direction(&mid(normal));
    let w = point.width().to_f64();
    let mut compared = 0;
    for (g, turn, what) in [
        (r.ga, r.turn[0], "∇A"),
        (r.gb.map(|v| -v), r.turn[1], "−∇B"),
    ] {
        if turn * w < 1e-6 {
            assert!(dist(&n, &g) < 1e-9, "{name}: normal {n:?} vs {what} {g:?}");
            compared += 1;
        }
    }
    assert!(
        compared >= 1,
        "{name}: neither gradient is determined by the box"
    );
    assert!(
        (r.f - 1.0).abs() < 1e-8,
        "{name}: Perram–Wertheim F = {} at a touch",
        r.f
    );
    let deviation = dist(&r.pw, &x) / size;
    assert!(
        deviation <= 1e-9,
        "{name}: Perram–Wertheim {:?} vs {x:?}",
        r.pw
    );
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
    let (mut checked, mut scenes) = (0, 0);
    for (name, s) in all_shipped() {
        let out = match run(&s, &Options::default()) {
            Ok(o) => o,
            Err(e) => panic!("{name}: {e}"),
        };
        assert_eq!(out.geometry.len(), out.contacts.len(), "{name}");
        for k in 0..out.contacts.len() {
            worst = worst.max(check_contact(&name, &s, &out, k));
            checked += 1;
        }
        scenes += usize::from(!out.contacts.is_empty());
    }
    eprintln!(
        "{scenes} scenes, {checked} contacts, Perram–Wertheim max deviation {worst:e} of the scene size"
    );
    assert!(
        scenes >= 71 && checked >= 120,
        "only {scenes} scenes, {checked} contacts"
    );
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
        for seg in stripped["timeline"].as_array_mut().unwrap() {
            if let Some(o) = seg.as_object_mut() {
                for end in ["start", "end"] {
                    for key in ["point", "normal", "point_note"] {
                        o.remove(&format!("{end}_{key}"));
                    }
                }
            }
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

/// The touch segments of `out` that are not isolated contacts, with the
/// geometry at their two ends.
fn touch_segments(out: &Outcome) -> Vec<(&ccd_exact::Segment, &[Geometry; 2])> {
    assert_eq!(out.segment_geometry.len(), out.timeline.len());
    out.timeline
        .iter()
        .zip(&out.segment_geometry)
        .filter_map(|(s, g)| g.as_ref().map(|g| (s, g)))
        .collect()
}

#[test]
fn touching_throughout_segments_carry_the_point_at_both_ends() {
    let names = [
        "tests/scenes/static-touching-spheres.toml",
        "tests/stability/throughout-touch-arc.toml",
        "tests/stability/throughout-touch-together.toml",
    ];
    for name in names {
        let s = load(name);
        let out = run(&s, &Options::default()).unwrap();
        let segments = touch_segments(&out);
        assert_eq!(segments.len(), 1, "{name}");
        let (seg, [start, end]) = segments[0];
        assert_eq!(
            (seg.start.lo.clone(), seg.end.hi.clone()),
            (s.span[0].clone(), s.span[1].clone())
        );
        for (at, g) in [(&seg.start, start), (&seg.end, end)] {
            // Exact rational ends: the point is exact (on both surfaces
            // exactly) and certified.
            let (p, n, certified) = point_of(g);
            assert!(certified && p.lo == p.hi && n.lo == n.hi, "{name}: {g:?}");
            check_point(name, &s, at, g);
        }
        // Every other segment gets none; the first contact is the start.
        assert!(out.contacts.is_empty(), "{name}");
        assert_eq!(out.first_contact_geometry(), Some(start), "{name}");
        let j = to_json(&out);
        let k = out.timeline.iter().position(|t| t == seg).unwrap();
        let entry = &j["timeline"][k];
        for key in ["start_point", "start_normal", "end_point", "end_normal"] {
            assert!(entry[key]["lo"].is_array(), "{name}: {key}");
        }
        assert_eq!(j["first_contact"]["point"], entry["start_point"], "{name}");
        assert_eq!(
            j["first_contact"]["normal"], entry["start_normal"],
            "{name}"
        );
        // A first-contact query stops at t0 with the same point.
        let first = Options {
            first_contact_only: true,
            ..Options::default()
        };
        let fc = run(&s, &first).unwrap();
        assert_eq!(fc.first_contact_geometry(), Some(start), "{name}");
        // Float mode: estimates, near the exact points.
        let float = Options {
            arithmetic: Arithmetic::Float,
            ..Options::default()
        };
        let fl = run(&s, &float).unwrap();
        let fsegs = touch_segments(&fl);
        assert_eq!(fsegs.len(), 1, "{name}");
        for (g, e) in fsegs[0].1.iter().zip([start, end]) {
            let (p, _, certified) = point_of(g);
            assert!(!certified, "{name}");
            let (ep, _, _) = point_of(e);
            assert!(dist(&mid(p), &mid(ep)) < 1e-9 * size(&s), "{name}");
        }
    }
    // Known by construction: unit spheres at the origin and at (2, 0, 0)
    // touch at (1, 0, 0), A's normal +x.
    let out = run(&load(names[0]), &Options::default()).unwrap();
    let one = [Rat::one(), Rat::zero(), Rat::zero()];
    for g in touch_segments(&out)[0].1 {
        assert_eq!(
            g,
            &Geometry::Point {
                point: Box3::point(one.clone()),
                normal: Box3::point(one.clone()),
                certified: true,
            }
        );
    }
}

#[test]
fn no_touch_segment_no_segment_geometry() {
    for name in [
        "tests/scenes/paper-example-5-1.toml",
        "tests/stability/throughout-nested.toml",
    ] {
        let out = run(&load(name), &Options::default()).unwrap();
        assert!(touch_segments(&out).is_empty(), "{name}");
        let j = to_json(&out);
        for seg in j["timeline"].as_array().unwrap() {
            assert!(seg.get("start_point").is_none() && seg.get("start_point_note").is_none());
        }
    }
    let without = Options {
        contact_geometry: false,
        ..Options::default()
    };
    let out = run(&load("tests/scenes/static-touching-spheres.toml"), &without).unwrap();
    assert!(out.segment_geometry.is_empty() && out.first_contact_geometry().is_none());
}

#[test]
fn a_first_contact_query_stopping_at_a_touch_at_t0_carries_its_point() {
    // Touching at t0, then apart: the default query reports the contact at
    // t0; the first-contact query stops at t0 with the same point.
    let name = "tests/stability/endpoints-touch-at-t0-depart.toml";
    let s = load(name);
    let full = run(&s, &Options::default()).unwrap();
    let first = Options {
        first_contact_only: true,
        ..Options::default()
    };
    let fc = run(&s, &first).unwrap();
    assert!(fc.contacts.is_empty());
    let g = fc.first_contact_geometry().expect("a point at t0");
    check_point(name, &s, fc.first_contact.as_ref().unwrap(), g);
    let (p, _, _) = point_of(g);
    let (q, _, _) = point_of(&full.geometry[0]);
    for i in 0..3 {
        assert!(q.lo[i] <= p.lo[i] && p.hi[i] <= q.hi[i], "{p:?} vs {q:?}");
    }
    assert!(to_json(&fc)["first_contact"]["point"]["lo"].is_array());
}

/// The normal's normalisation at scales where its components' `f64`
/// estimates underflow (1e-60) or overflow (1e100): its largest component
/// is exactly ±1 and the others lie in [−1, 1] (the contract), on the
/// exact path.
#[test]
fn the_normal_is_scaled_by_its_largest_component_at_any_scale() {
    for (ra, rb, scale) in [("1e-60", "2e-60", "e-60"), ("1e100", "2e100", "e100")] {
        let text = format!(
            "format = 1\nspan = [\"0\", \"1\"]\n[a]\nradii = [\"{ra}\", \"{ra}\", \"{ra}\"]\n\
             [b]\nradii = [\"{rb}\", \"{rb}\", \"{rb}\"]\n[b.motion]\nkind = \"translation\"\n\
             center = [[\"-10{scale}\", \"1{scale}\", \"0.5{scale}\"], [\"10{scale}\", \"1{scale}\", \"0.5{scale}\"]]\n"
        );
        let out = run(
            &Scene::from_toml(&text).expect("valid"),
            &Options::default(),
        )
        .expect("runs");
        assert_eq!(out.geometry.len(), 2, "{scale}");
        for g in &out.geometry {
            let (_, normal, certified) = point_of(g);
            assert!(certified);
            let one = Rat::one();
            let k = (0..3)
                .find(|&k| normal.lo[k] == normal.hi[k] && normal.lo[k].abs() == one)
                .unwrap_or_else(|| panic!("{scale}: no component ±1 in {normal:?}"));
            for j in (0..3).filter(|&j| j != k) {
                assert!(
                    normal.lo[j].abs() <= one && normal.hi[j].abs() <= one,
                    "{scale}: {normal:?}"
                );
            }
        }
    }
}
