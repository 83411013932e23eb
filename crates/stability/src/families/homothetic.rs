//! The families built on a homothetic pair: `graze-spheres`,
//! `graze-ellipsoids`, `ratio-shape`, `ratio-size` and
//! `tangency-rational` (grazing passes at a chosen gap), and the [`Pair`]
//! that [`super::throughout`], [`super::endpoints`] and [`super::affine`]
//! build on too.
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

use super::{identity, int, pow10, rat, rotate, tilt, unit, v3};
use crate::baseline::eval_curve;
use crate::truth::{Closest, Truth};
use crate::{Case, Level, StabilityError, Surd};
use ccd_arith::Rat;
use ccd_exact::Scene;
use ccd_motion::{Bezier, Body, Motion, Quat, Vec3};

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
    pub(super) fn grow(&self) -> Rat {
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

    pub(super) fn body_a(&self, center: Motion) -> Body {
        Body {
            radii: self.radii.clone(),
            motion: center,
        }
    }

    pub(super) fn body_b(&self, center: Bezier<Vec3>) -> Body {
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
    pub(super) fn case(
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

pub(super) fn graze_spheres(level: Level) -> Result<Vec<Case>, StabilityError> {
    let pair = Pair {
        radii: v3(int(1), int(1), int(1)),
        q: identity(),
        s: rat(1, 2),
        span: unit(),
    };
    graze_family("graze-spheres", &pair, [int(-3), int(4)], &ks(level))
}

pub(super) fn graze_ellipsoids(level: Level) -> Result<Vec<Case>, StabilityError> {
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

pub(super) fn ratio_shape(level: Level) -> Result<Vec<Case>, StabilityError> {
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

pub(super) fn ratio_size(level: Level) -> Result<Vec<Case>, StabilityError> {
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
pub(super) fn tangency_rational(level: Level) -> Result<Vec<Case>, StabilityError> {
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
