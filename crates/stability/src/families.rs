//! The scene families, each with its ground truth by construction.
//!
//! # The homothetic-pair construction
//!
//! Let `E` be an ellipsoid centred at the origin with semi-axes
//! `r = (r0, r1, r2)` and rotation `R = R(q)`, and let `B = s·E + c` be a
//! scaled copy (`s > 0`, same orientation) centred at `c`. Because `E` is
//! convex and centrally symmetric, `E ∩ B ≠ ∅ ⇔ c ∈ E − s·E = (1 + s)·E`, and
//! the two touch externally exactly when `c` is on the boundary of
//! `(1 + s)·E`. In `E`'s body frame (`c = R·ĉ`) that is the level function
//!
//! ```text
//!   φ(ĉ) = ĉ₀²/r0² + ĉ₁²/r1² + ĉ₂²/r2² − (1 + s)²    (> 0 separate, = 0 touch, < 0 overlap).
//! ```
//!
//! A *grazing pass* moves `ĉ(u) = (x0 + (x1 − x0)·u, d, 0)`, a line along the
//! body `x` axis at offset `d` along body `y`. Its closest approach is at
//! `u* = −x0/(x1 − x0)`, where the supporting planes `ŷ = r1` (of `E`) and
//! `ŷ = d − s·r1` (of `B`) are parallel: the signed Euclidean gap is
//! exactly `g = d − (1 + s)·r1`. The generator picks `d = (1 + s)·r1 + g`
//! with `g ∈ {+10⁻ᵏ, 0, −10⁻ᵏ}`. With `D = (1 + s)² − d²/r1²`, the contact
//! instants are the roots of `φ(ĉ(u)) = 0`:
//!
//! ```text
//!   D < 0: none (a miss);   D = 0: u* (a tangency);   D > 0: u* ± r0·√D/(x1 − x0),
//! ```
//!
//! exact quadratic surds ([`Surd`]), rational when `D` is a square.
//!
//! # The similarity-affine construction
//!
//! For high-degree motions, `B`'s placement is the affine map
//! `X = s(u)·R·Xbody + R·(x(u), 0, 0)` (an `affine` motion: a similarity of
//! degree `n`), i.e. `B = s(u)·E + c(u)` again. With `s(u) > 0` of degree `n`
//! (positive Bernstein coefficients) and `x(u) = r0·(1 + s(u)) + κ·p(u)`,
//! `p(u) = Π (u − ρⱼ)^mⱼ` with chosen rational roots `ρⱼ ∈ (0, 1)` and
//! `0 < κ < r0` (so `x > 0`), the level function is `φ = x/r0 − (1 + s) =
//! κ·p(u)/r0`: the contacts are exactly the `ρⱼ`, crossings for odd `mⱼ`
//! and tangencies (touch and separate again) for even `mⱼ`.

pub mod graze;
pub mod perturbed;
pub mod ratio;

use crate::baseline::eval_curve;
use crate::truth::{Closest, Truth};
use crate::{StabilityError, Surd};
use ccd_arith::{Int, Rat};
use ccd_exact::{Scene, State};
use ccd_motion::{Bezier, Body, Mat34, Motion, Quat, Vec3};
use ccd_quadric::{norm2, rotation_numerator};

/// How many cases to generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// The representative set shipped under `tests/stability/` (fast: the
    /// exact mode runs on all of it in the test suite).
    Shipped,
    /// Every `k` of every family (the report).
    Full,
}

/// One generated scene and its truth.
#[derive(Clone, Debug)]
pub struct Case {
    /// File stem, e.g. `graze-spheres-k07-overlap`.
    pub name: String,
    /// The scene.
    pub scene: Scene,
    /// Its ground truth.
    pub truth: Truth,
}

/// The families, in report order, with a one-line description each.
pub const FAMILIES: &[(&str, &str)] = &[
    ("graze-spheres", "sphere r=1 and sphere r=1/2 on a line; smallest gap +10⁻ᵏ (miss), 0 (tangency at u=3/7), −10⁻ᵏ (two contacts 2·10^(−k/2) apart); sr0 ≡ 0"),
    ("graze-ellipsoids", "rotated ellipsoid (3,2,1) and a 3/4-scaled copy on a line; same gaps"),
    ("ratio-shape", "needle (10ʲ,1,1), j = 0…6 (radii ratio up to 10⁶), and an equal copy; gap +10⁻⁶, 0, −10⁻⁶"),
    ("ratio-size", "unit sphere and a sphere of radius 10⁻ʲ, j = 0…6; gap +10⁻⁶, 0, −10⁻⁶"),
    ("tangency-rational", "crossings at rational instants (Pythagorean offsets), rotated ellipsoids"),
    ("throughout", "touching throughout (moving together; sliding on a rational arc), identical, concentric, nested, far apart"),
    ("endpoints", "contacts exactly at t0 and/or t1 on the span [1/3, 2]: touch-and-depart, approach-and-touch, grazes at the ends"),
    ("affine-degree", "similarity affine motions of degree n = 2…15 with rational crossings and a double (tangential) contact"),
    ("affine-cluster", "degree-3 affine motion, rational crossings at 2/7 and 2/7 + 10⁻ᵏ (overlap for a duration of 10⁻ᵏ)"),
    ("graze-shapes", "different shapes A = (3,2,1), B = (1,1/2,3/4), B's bottom point passing over A's top point; gap +10⁻ᵏ, 0, −10⁻ᵏ, k = 1…100; overlap contacts bracketed by tangent balls"),
    ("graze-turned", "graze-shapes with A and B turned about the contact normal by rational quaternions"),
    ("graze-scene-turned", "graze-turned with the whole scene turned by the rational quaternion (1, 2, −3, 4)"),
    ("graze-spin", "B spinning a quarter turn about the contact normal (rigid motion) in the turned scene; triaxial B for miss/touch, B = (1,1,3/4) for overlaps"),
    ("ratio-needle", "needle (1, 10⁻ᵏ, 10⁻ᵏ), k = 1, 2, 4, …, 4096 (radii ratio up to 10⁴⁰⁹⁶), B = (1,1/2,3/4) passing over it; gap +1/8, 0, −1/8"),
    ("ratio-disc", "disc (1, 1, 10⁻ᵏ), k = 1, 2, 4, …, 4096, same pass"),
    ("bench-perturbed", "the paper's benchmark scenes (benches/scenes) with every coordinate x → x + 10⁻ᵈ·r, d = 30, 100, 1000; contacts bracketed around the unperturbed ones, each bracket checked by the static classifier"),
];

/// The families of issue 12 whose scenes all take the generic path
/// (`sr0 ≢ 0`) with long numbers.
pub const GENERIC: &[&str] = &[
    "graze-shapes",
    "graze-turned",
    "graze-scene-turned",
    "graze-spin",
    "ratio-needle",
    "ratio-disc",
    "bench-perturbed",
];

fn rat(p: i64, q: i64) -> Rat {
    Rat::from_frac(p, q)
}

fn int(v: i64) -> Rat {
    Rat::from(v)
}

/// `10^e` for a signed exponent.
pub fn pow10(e: i32) -> Rat {
    let p = Rat::from(Int::pow10(e.unsigned_abs()));
    if e >= 0 {
        p
    } else {
        p.recip().unwrap_or_else(Rat::one)
    }
}

fn v3(x: Rat, y: Rat, z: Rat) -> Vec3 {
    [x, y, z]
}

fn identity() -> Quat {
    Motion::identity()
}

/// `R(q)·v = M(q)·v / |q|²`.
fn rotate(q: &Quat, v: &Vec3) -> Vec3 {
    let m = rotation_numerator(q);
    let n = norm2(q);
    std::array::from_fn(|i| {
        let s = (0..3).fold(Rat::zero(), |acc, j| &acc + &(&m[i][j] * &v[j]));
        &s / &n
    })
}

/// A homothetic pair (module docs): `A = E` (static at the origin unless
/// moved), `B = s·E + R·ĉ(u)`.
#[derive(Clone, Debug)]
pub struct Pair {
    /// `E`'s semi-axes.
    pub radii: Vec3,
    /// `E`'s (and `B`'s) orientation.
    pub q: Quat,
    /// The scale of `B`.
    pub s: Rat,
    /// The span.
    pub span: [Rat; 2],
}

impl Pair {
    /// `1 + s`.
    fn grow(&self) -> Rat {
        &Rat::one() + &self.s
    }

    /// `φ(ĉ) = Σ ĉᵢ²/rᵢ² − (1 + s)²`.
    pub fn level(&self, c: &Vec3) -> Rat {
        let sum = (0..3).fold(Rat::zero(), |acc, i| {
            let x = &c[i] / &self.radii[i];
            &acc + &(&x * &x)
        });
        let g = self.grow();
        &sum - &(&g * &g)
    }

    fn body_a(&self, center: Motion) -> Body {
        Body {
            radii: self.radii.clone(),
            motion: center,
        }
    }

    fn body_b(&self, center: Bezier<Vec3>) -> Body {
        Body {
            radii: self.radii.clone().map(|r| &r * &self.s),
            motion: Motion::Translation {
                center,
                orientation: self.q.clone(),
            },
        }
    }

    /// `A` static at the origin, `B`'s centre on `R·rel(u)` (`rel` in `E`'s
    /// body frame; a rational Bézier curve maps control point by control
    /// point under the linear map `R`).
    pub fn scene(&self, rel: &Bezier<Vec3>) -> Scene {
        let world = Bezier {
            points: rel.points.iter().map(|p| rotate(&self.q, p)).collect(),
            weights: rel.weights.clone(),
        };
        Scene {
            span: self.span.clone(),
            a: self.body_a(Motion::Static {
                center: v3(Rat::zero(), Rat::zero(), Rat::zero()),
                orientation: self.q.clone(),
            }),
            b: self.body_b(world),
        }
    }

    /// A case whose contacts (in `u`) are `contacts_u`, with the level
    /// function read along `rel`.
    fn case(
        &self,
        family: &str,
        name: String,
        k: Option<u32>,
        rel: &Bezier<Vec3>,
        contacts_u: Vec<Surd>,
    ) -> Result<Case, StabilityError> {
        let phi = |u: &Rat| self.level(&eval_curve(rel, u));
        let truth = Truth::from_level(family, name.clone(), k, &self.span, contacts_u, &phi)?;
        Ok(Case {
            name: format!("{family}-{name}"),
            scene: self.scene(rel),
            truth,
        })
    }

    /// A grazing pass `ĉ(u) = (x0 + (x1 − x0)u, (1 + s)·r1 + gap, 0)`
    /// (module docs), `x0 < 0 < x1`.
    pub fn pass(
        &self,
        family: &str,
        name: String,
        k: Option<u32>,
        x: [Rat; 2],
        gap: Rat,
    ) -> Result<Case, StabilityError> {
        let d = &(&self.grow() * &self.radii[1]) + &gap;
        let rel = Bezier {
            points: vec![
                v3(x[0].clone(), d.clone(), Rat::zero()),
                v3(x[1].clone(), d.clone(), Rat::zero()),
            ],
            weights: None,
        };
        let len = &x[1] - &x[0];
        let ustar = &(-&x[0]) / &len;
        let dr = &d / &self.radii[1];
        let disc = &(&self.grow() * &self.grow()) - &(&dr * &dr);
        let contacts = match disc.signum() {
            -1 => vec![],
            0 => vec![Surd::rational(ustar.clone())],
            _ => {
                let b = &self.radii[0] / &len;
                vec![
                    Surd::new(ustar.clone(), -&b, disc.clone())?,
                    Surd::new(ustar.clone(), b, disc)?,
                ]
            }
        };
        let mut case = self.case(family, name, k, &rel, contacts)?;
        let h = &self.span[1] - &self.span[0];
        case.truth.closest = Some(Closest {
            t: &self.span[0] + &(&h * &ustar),
            gap,
        });
        Ok(case)
    }
}

fn two_point(a: Vec3, b: Vec3) -> Bezier<Vec3> {
    Bezier {
        points: vec![a, b],
        weights: None,
    }
}

/// The gaps of a grazing family at `10⁻ᵏ`: miss, and overlap (the tangency
/// does not depend on `k`).
fn graze_family(
    family: &str,
    pair: &Pair,
    x: [Rat; 2],
    ks: &[u32],
) -> Result<Vec<Case>, StabilityError> {
    let mut out = vec![pair.pass(family, "touch".into(), None, x.clone(), Rat::zero())?];
    for &k in ks {
        let g = pow10(-(k as i32));
        out.push(pair.pass(
            family,
            format!("k{k:02}-miss"),
            Some(k),
            x.clone(),
            g.clone(),
        )?);
        out.push(pair.pass(family, format!("k{k:02}-overlap"), Some(k), x.clone(), -g)?);
    }
    Ok(out)
}

fn ks(level: Level) -> Vec<u32> {
    match level {
        Level::Shipped => vec![1, 3, 8, 15, 30],
        Level::Full => (1..=30).collect(),
    }
}

/// A generic rotation (|q|² = 25/4), so no axis is special in world space.
fn tilt() -> Quat {
    [int(2), int(1), int(-1), rat(1, 2)]
}

fn unit() -> [Rat; 2] {
    [Rat::zero(), Rat::one()]
}

fn graze_spheres(level: Level) -> Result<Vec<Case>, StabilityError> {
    let pair = Pair {
        radii: v3(int(1), int(1), int(1)),
        q: identity(),
        s: rat(1, 2),
        span: unit(),
    };
    graze_family("graze-spheres", &pair, [int(-3), int(4)], &ks(level))
}

fn graze_ellipsoids(level: Level) -> Result<Vec<Case>, StabilityError> {
    let pair = Pair {
        radii: v3(int(3), int(2), int(1)),
        q: tilt(),
        s: rat(3, 4),
        span: unit(),
    };
    graze_family("graze-ellipsoids", &pair, [int(-9), int(12)], &ks(level))
}

fn ratio_js(level: Level) -> Vec<u32> {
    match level {
        Level::Shipped => vec![0, 3, 6],
        Level::Full => (0..=6).collect(),
    }
}

/// Gap ±10⁻⁶ and 0 for each `j`, with a pair built by `pair(j)` and a pass
/// over `[−3w, 4w]`.
fn ratio_family(
    family: &str,
    level: Level,
    pair: impl Fn(u32) -> (Pair, Rat),
) -> Result<Vec<Case>, StabilityError> {
    let mut out = Vec::new();
    for j in ratio_js(level) {
        let (p, w) = pair(j);
        let x = [&int(-3) * &w, &int(4) * &w];
        for (tag, gap) in [
            ("miss", pow10(-6)),
            ("touch", Rat::zero()),
            ("overlap", -pow10(-6)),
        ] {
            out.push(p.pass(family, format!("j{j}-{tag}"), Some(j), x.clone(), gap)?);
        }
    }
    Ok(out)
}

fn ratio_shape(level: Level) -> Result<Vec<Case>, StabilityError> {
    ratio_family("ratio-shape", level, |j| {
        let big = pow10(j as i32);
        let pair = Pair {
            radii: v3(big.clone(), int(1), int(1)),
            q: [int(1), int(1), int(0), int(0)],
            s: int(1),
            span: unit(),
        };
        (pair, big)
    })
}

fn ratio_size(level: Level) -> Result<Vec<Case>, StabilityError> {
    ratio_family("ratio-size", level, |j| {
        let pair = Pair {
            radii: v3(int(1), int(1), int(1)),
            q: identity(),
            s: pow10(-(j as i32)),
            span: unit(),
        };
        (pair, int(1))
    })
}

/// Offsets `d = (1+s)·r1·a/c` with `a² + b² = c²` give `√D = (1+s)·b/c`:
/// rational contact instants.
fn tangency_rational(level: Level) -> Result<Vec<Case>, StabilityError> {
    let triples: &[(i64, i64, i64)] = match level {
        Level::Shipped => &[(3, 4, 5), (20, 21, 29)],
        Level::Full => &[(3, 4, 5), (5, 12, 13), (8, 15, 17), (20, 21, 29)],
    };
    let pair = Pair {
        radii: v3(int(2), int(1), int(3)),
        q: tilt(),
        s: rat(1, 2),
        span: [rat(-1, 2), rat(5, 2)],
    };
    let family = "tangency-rational";
    triples
        .iter()
        .map(|&(a, _, c)| {
            let gap =
                &(&(&pair.grow() * &pair.radii[1]) * &rat(a, c)) - &(&pair.grow() * &pair.radii[1]);
            let x = [int(-4), int(5)];
            pair.pass(family, format!("triple-{a}-{c}"), None, x, gap)
        })
        .collect()
}

fn throughout(_level: Level) -> Result<Vec<Case>, StabilityError> {
    let family = "throughout";
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: rat(1, 3),
        span: unit(),
    };
    let g = e.grow();
    let mut out = Vec::new();

    // Touching throughout, sliding on a rational arc of ∂((1+s)E): the unit
    // circle arc from angle −θ to θ with cos θ = 3/5 is the rational
    // quadratic Bézier (3/5, −4/5), (5/3, 0), (3/5, 4/5) with weights
    // (1, 3/5, 1); scaled by (1+s)·r it lies on the boundary.
    let sc = |x: Rat, y: Rat| {
        v3(
            &(&g * &e.radii[0]) * &x,
            &(&g * &e.radii[1]) * &y,
            Rat::zero(),
        )
    };
    let arc = Bezier {
        points: vec![
            sc(rat(3, 5), rat(-4, 5)),
            sc(rat(5, 3), Rat::zero()),
            sc(rat(3, 5), rat(4, 5)),
        ],
        weights: Some(vec![int(1), rat(3, 5), int(1)]),
    };
    out.push(e.case(family, "touch-arc".into(), None, &arc, vec![])?);

    // Touching throughout, moving together along a cubic.
    let path = Bezier {
        points: vec![
            v3(int(0), int(0), int(0)),
            v3(int(5), int(-2), int(1)),
            v3(int(-3), int(4), int(2)),
            v3(int(1), int(1), int(-6)),
        ],
        weights: None,
    };
    let offset = rotate(&e.q, &v3(&g * &e.radii[0], Rat::zero(), Rat::zero()));
    let moved = |p: &Vec3| std::array::from_fn(|i| &p[i] + &offset[i]);
    let together = Scene {
        span: unit(),
        a: e.body_a(Motion::Translation {
            center: path.clone(),
            orientation: e.q.clone(),
        }),
        b: e.body_b(Bezier {
            points: path.points.iter().map(moved).collect(),
            weights: None,
        }),
    };
    out.push(Case {
        name: format!("{family}-touch-together"),
        scene: together,
        truth: Truth::throughout(family, "touch-together".into(), State::Touch),
    });

    // Identical bodies on the same path, concentric different bodies,
    // nested bodies: overlap throughout. Far apart: separate throughout.
    let mover = |radii: Vec3, q: Quat, shift: Vec3| Body {
        radii,
        motion: Motion::Translation {
            center: Bezier {
                points: path
                    .points
                    .iter()
                    .map(|p| std::array::from_fn(|i| &p[i] + &shift[i]))
                    .collect(),
                weights: None,
            },
            orientation: q,
        },
    };
    let zero = v3(Rat::zero(), Rat::zero(), Rat::zero());
    let cases = [
        (
            "identical",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            State::Overlap,
        ),
        (
            "concentric",
            mover(v3(int(3), int(1), int(1)), identity(), zero.clone()),
            mover(v3(int(1), int(3), rat(1, 2)), tilt(), zero.clone()),
            State::Overlap,
        ),
        (
            "nested",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(
                e.radii.clone().map(|r| &r * &rat(1, 2)),
                e.q.clone(),
                zero.clone(),
            ),
            State::Overlap,
        ),
        (
            "far-apart",
            mover(e.radii.clone(), e.q.clone(), zero.clone()),
            mover(e.radii.clone(), tilt(), v3(int(10), int(0), int(0))),
            State::Separate,
        ),
    ];
    for (name, a, b, state) in cases {
        out.push(Case {
            name: format!("{family}-{name}"),
            scene: Scene { span: unit(), a, b },
            truth: Truth::throughout(family, name.into(), state),
        });
    }
    Ok(out)
}

fn endpoints(_level: Level) -> Result<Vec<Case>, StabilityError> {
    let family = "endpoints";
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: rat(1, 3),
        span: [rat(1, 3), int(2)],
    };
    let g = e.grow();
    let rx = &g * &e.radii[0];
    let ry = &g * &e.radii[1];
    let (zero, one) = (Surd::rational(Rat::zero()), Surd::rational(Rat::one()));
    let on_x = |a: Rat, b: Rat| {
        two_point(
            v3(a, Rat::zero(), Rat::zero()),
            v3(b, Rat::zero(), Rat::zero()),
        )
    };
    let on_y = |a: Rat, b: Rat| {
        two_point(
            v3(a, ry.clone(), Rat::zero()),
            v3(b, ry.clone(), Rat::zero()),
        )
    };
    let r0 = e.radii[0].clone();
    let cases = [
        (
            "touch-at-t0-depart",
            on_x(rx.clone(), &rx + &int(1)),
            vec![zero.clone()],
        ),
        (
            "approach-touch-at-t1",
            on_x(&rx + &int(1), rx.clone()),
            vec![one.clone()],
        ),
        (
            "overlap-until-t1",
            on_x(&rx - &int(1), rx.clone()),
            vec![one.clone()],
        ),
        (
            "touch-at-both-ends",
            on_x(rx.clone(), -&rx),
            vec![zero.clone(), one.clone()],
        ),
        ("graze-at-t0", on_y(Rat::zero(), r0.clone()), vec![zero]),
        ("graze-at-t1", on_y(-&r0, Rat::zero()), vec![one]),
    ];
    cases
        .into_iter()
        .map(|(name, rel, contacts)| e.case(family, name.into(), None, &rel, contacts))
        .collect()
}

/// Power-basis coefficients (low → high) of `Π (u − ρ)^m`.
pub fn poly_from_roots(roots: &[(Rat, u32)]) -> Vec<Rat> {
    let mut p = vec![Rat::one()];
    for (rho, m) in roots {
        for _ in 0..*m {
            let mut next = vec![Rat::zero(); p.len() + 1];
            for (i, c) in p.iter().enumerate() {
                next[i + 1] = &next[i + 1] + c;
                next[i] = &next[i] - &(c * rho);
            }
            p = next;
        }
    }
    p
}

fn binomial(n: usize, k: usize) -> Rat {
    (0..k).fold(Rat::one(), |acc, i| {
        &(&acc * &Rat::from((n - i) as i64)) / &Rat::from((i + 1) as i64)
    })
}

/// Bernstein coefficients of degree `n` of a power-basis polynomial
/// (`deg <= n`): `bᵢ = Σ_{j<=i} C(i, j)/C(n, j)·aⱼ`.
pub fn to_bernstein(a: &[Rat], n: usize) -> Vec<Rat> {
    (0..=n)
        .map(|i| {
            a.iter()
                .enumerate()
                .take(i + 1)
                .fold(Rat::zero(), |acc, (j, aj)| {
                    &acc + &(&(aj * &binomial(i, j)) / &binomial(n, j))
                })
        })
        .collect()
}

/// The similarity-affine construction (module docs) of degree `n` with
/// roots `roots` of `p`.
fn similarity(
    family: &str,
    name: String,
    k: Option<u32>,
    n: usize,
    roots: &[(Rat, u32)],
) -> Result<Case, StabilityError> {
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: Rat::one(),
        span: unit(),
    };
    let p = poly_from_roots(roots);
    if p.len() > n + 1 {
        return Err(StabilityError::Truth(format!("deg p > n = {n}")));
    }
    let kappa = rat(1, 2);
    let pb = to_bernstein(&p, n);
    // s(u): Bernstein coefficients 1/2 + i²/(n+1), all positive.
    let s: Vec<Rat> = (0..=n)
        .map(|i| &rat(1, 2) + &Rat::from_frac((i * i) as i64, (n + 1) as i64))
        .collect();
    let m = rotation_numerator(&e.q);
    let nq = norm2(&e.q);
    let r0 = &e.radii[0];
    let points: Vec<Mat34> = (0..=n)
        .map(|i| {
            let x = &(r0 * &(&Rat::one() + &s[i])) + &(&kappa * &pb[i]);
            std::array::from_fn(|row| {
                let rr = |col: usize| &m[row][col] / &nq;
                [&s[i] * &rr(0), &s[i] * &rr(1), &s[i] * &rr(2), &x * &rr(0)]
            })
        })
        .collect();
    let scene = Scene {
        span: e.span.clone(),
        a: e.body_a(Motion::Static {
            center: v3(Rat::zero(), Rat::zero(), Rat::zero()),
            orientation: e.q.clone(),
        }),
        b: Body {
            radii: e.radii.clone(),
            motion: Motion::Affine {
                matrix: Bezier {
                    points,
                    weights: None,
                },
            },
        },
    };
    // φ = κ·p(u) (sign only matters): Horner.
    let phi = |u: &Rat| {
        let pu = p.iter().rev().fold(Rat::zero(), |acc, c| &(&acc * u) + c);
        &kappa * &pu
    };
    let mut distinct: Vec<Rat> = roots.iter().map(|r| r.0.clone()).collect();
    distinct.sort();
    distinct.dedup();
    let contacts = distinct.into_iter().map(Surd::rational).collect();
    let truth = Truth::from_level(family, name.clone(), k, &e.span, contacts, &phi)?;
    Ok(Case {
        name: format!("{family}-{name}"),
        scene,
        truth,
    })
}

fn affine_degree(level: Level) -> Result<Vec<Case>, StabilityError> {
    let ns: &[usize] = match level {
        Level::Shipped => &[2, 4],
        Level::Full => &[2, 3, 4, 6, 8, 10, 12, 15],
    };
    ns.iter()
        .map(|&n| {
            let roots = match n {
                2 => vec![(rat(2, 7), 1), (rat(5, 7), 1)],
                3 => vec![(rat(1, 4), 1), (rat(3, 5), 2)],
                _ => vec![(rat(1, 5), 1), (rat(1, 2), 2), (rat(4, 5), 1)],
            };
            similarity(
                "affine-degree",
                format!("n{n:02}"),
                Some(n as u32),
                n,
                &roots,
            )
        })
        .collect()
}

fn affine_cluster(level: Level) -> Result<Vec<Case>, StabilityError> {
    let ks: Vec<u32> = match level {
        Level::Shipped => vec![2, 12],
        Level::Full => (1..=30).collect(),
    };
    ks.into_iter()
        .map(|k| {
            let a = rat(2, 7);
            let b = &a + &pow10(-(k as i32));
            similarity(
                "affine-cluster",
                format!("k{k:02}"),
                Some(k),
                3,
                &[(a, 1), (b, 1)],
            )
        })
        .collect()
}

type Family = fn(Level) -> Result<Vec<Case>, StabilityError>;

/// The generators, in the order of [`FAMILIES`].
const GENERATORS: [Family; 16] = [
    graze_spheres,
    graze_ellipsoids,
    ratio_shape,
    ratio_size,
    tangency_rational,
    throughout,
    endpoints,
    affine_degree,
    affine_cluster,
    graze::graze_shapes,
    graze::graze_turned,
    graze::graze_scene_turned,
    graze::graze_spin,
    ratio::ratio_needle,
    ratio::ratio_disc,
    perturbed::bench_perturbed,
];

/// The cases of the families whose name is in `names` (all when `None`)
/// at `level`, in report order.
pub fn generate_only(level: Level, names: Option<&[&str]>) -> Result<Vec<Case>, StabilityError> {
    let mut out = Vec::new();
    for ((name, _), family) in FAMILIES.iter().zip(GENERATORS) {
        if names.is_none_or(|n| n.contains(name)) {
            out.extend(family(level)?);
        }
    }
    Ok(out)
}

/// Every family's cases at `level`, in report order.
pub fn generate(level: Level) -> Result<Vec<Case>, StabilityError> {
    generate_only(level, None)
}
