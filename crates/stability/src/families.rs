//! The scene families, each with its ground truth by construction, one
//! file per construction: [`homothetic`] (grazing passes of a homothetic
//! pair: `graze-spheres`, `graze-ellipsoids`, `ratio-shape`, `ratio-size`,
//! `tangency-rational`), [`throughout`], [`endpoints`], [`affine`]
//! (similarity-affine motions of high degree: `affine-degree`,
//! `affine-cluster`), [`graze`] (non-homothetic grazing passes:
//! `graze-shapes`, `graze-turned`, `graze-scene-turned`, `graze-spin`),
//! [`ratio`] (extreme radius ratios: `ratio-needle`, `ratio-disc`) and
//! [`perturbed`] (`bench-perturbed`). This file holds the list
//! ([`FAMILIES`], [`GENERIC`]), the generators' order and the small
//! helpers they share.

pub mod affine;
pub mod endpoints;
pub mod graze;
pub mod homothetic;
pub mod perturbed;
pub mod ratio;
pub mod throughout;

use crate::truth::Truth;
use crate::StabilityError;
use ccd_arith::{Int, Rat};
use ccd_exact::Scene;
use ccd_motion::{Motion, Quat, Vec3};
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

/// A generic rotation (|q|² = 25/4), so no axis is special in world space.
fn tilt() -> Quat {
    [int(2), int(1), int(-1), rat(1, 2)]
}

fn unit() -> [Rat; 2] {
    [Rat::zero(), Rat::one()]
}

type Family = fn(Level) -> Result<Vec<Case>, StabilityError>;

/// The generators, in the order of [`FAMILIES`].
const GENERATORS: [Family; 16] = [
    homothetic::graze_spheres,
    homothetic::graze_ellipsoids,
    homothetic::ratio_shape,
    homothetic::ratio_size,
    homothetic::tangency_rational,
    throughout::throughout,
    endpoints::endpoints,
    affine::affine_degree,
    affine::affine_cluster,
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
