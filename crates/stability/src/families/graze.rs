//! Non-homothetic grazing passes: two *different* ellipsoids whose
//! closest points keep horizontal tangent planes, so the minimum gap is the
//! chosen offset exactly, whatever the shapes, however `B` turns about the
//! vertical, and however the whole scene is turned.
//!
//! # The construction
//!
//! `A` (semi-axes `a = (a0, a1, a2)`) is centred at `(0, 0, −a2)`, so its
//! top point is the origin, turned about the vertical `z` axis only
//! (orientation `(w, 0, 0, z)`); `B` (semi-axes `b = (b0, b1, b2)`)
//! translates horizontally,
//!
//! ```text
//!   c(u) = ((u − u*)·v0, (u − u*)·v1, g + b2),
//! ```
//!
//! and turns, if at all, about the vertical axis through its centre (every
//! orientation control point of the form `(w, 0, 0, z)`; a rigid *spin* when
//! there are several). Both bodies' body `z` axes stay vertical, so `A` lies
//! in the half-space `z ≤ 0` and meets the plane `z = 0` only in its top
//! point, the origin, and `B(u)` lies in `z ≥ g` and meets `z = g` only in
//! its bottom point `(c0(u), c1(u), g)`. Hence:
//!
//! * `g > 0`: the slab `0 < z < g` separates them — **separate
//!   throughout** (the gap at `u*` is exactly `g`);
//! * `g = 0`: a common point lies in the plane `z = 0`, so it is both the
//!   top and the bottom point, i.e. `c0 = c1 = 0`: **one tangential touch at
//!   `u = u*`**, separate elsewhere;
//! * `g < 0`: at `u*` both contain the origin (it is on `B`'s vertical axis
//!   between its bottom point and its centre): overlap. With `B` translating
//!   (or spinning while rotation-symmetric about its vertical axis, `b0 =
//!   b1`, so that its *set* does not change), `A ∩ B(u) ≠ ∅ ⇔ c(u) ∈ A − B`,
//!   a strictly convex body, which the line `c(u)` enters once and leaves
//!   once: with both ends separate, **exactly two contacts**, one on each side
//!   of `u*`. A spinning triaxial `B` is used for `g ≥ 0` only (its overlap
//!   set need not be an interval).
//!
//! The ends are separate by the bounding spheres: the horizontal distance
//! `|u − u*|·|v|` at `u = 0, 1` exceeds `max a + max b` (checked).
//!
//! # Brackets for the two contacts (`g = −ε`)
//!
//! For an ellipsoid with vertical semi-axis `c` and smallest (largest)
//! semi-axis `m` (`M`), the ball of radius `m²/c` (`M²/c`) tangent at the top
//! point from inside lies inside (contains) the ellipsoid: along the
//! boundary, the squared distance to the ball's centre `(0, 0, c − R)` is
//! bounded below (above) by `m²(1 − z²/c²) + (z − c + R)²`, a convex
//! (concave) function of `z` stationary at `z = c` with value `R²`. The same
//! holds at `B`'s bottom point, and the balls stay put when a body turns
//! about its vertical axis. Two such balls with radii summing to `S` and
//! centres `S − ε` apart vertically meet exactly when the horizontal
//! distance `h` satisfies `h² ≤ 2εS − ε²`. So the bodies overlap while
//! `h² < 2ε·S_in − ε²` and are separate while `h² > 2ε·S_out − ε²`, and each
//! contact lies in `u* ± [h_in, h_out]/|v|` (clipped to the span) — exact
//! quadratic surds, rounded outward to rationals.
//!
//! # The whole scene turned
//!
//! A rational quaternion `Q` applied to everything (`A`'s orientation `Q·qA`,
//! `B`'s `Q·qB(u)` control point by control point, `B`'s centre `R(Q)·c(u)`
//! likewise: both are linear in the control points) is a rigid motion of
//! space, so the truth does not change.
//!
//! Placing `A`'s top point (not its centre) at the origin keeps every
//! number short: `B`'s height `g + b2` does not carry `a2`, so a needle of
//! radius `10⁻⁴⁰⁹⁶` ([`super::ratio`]) is written `"1e-4096"` and nothing
//! in the scene exceeds the format's 4096 characters a number.

use super::{int, pow10, rat, rotate, v3};
use crate::truth::{Closest, Instant, Truth};
use crate::{Case, Level, StabilityError, Surd};
use ccd_arith::{Int, Rat};
use ccd_exact::{Scene, State};
use ccd_motion::{Bezier, Body, Motion, Quat, Vec3};

pub use ccd_quadric::quat_mul;

/// A turn about the vertical axis, `(w, 0, 0, z)`.
pub fn about_z(w: Rat, z: Rat) -> Quat {
    [w, Rat::zero(), Rat::zero(), z]
}

fn is_about_z(q: &Quat) -> bool {
    q[1].is_zero() && q[2].is_zero() && !(q[0].is_zero() && q[3].is_zero())
}

fn max3(r: &Vec3) -> Rat {
    r.iter().max().cloned().unwrap_or_else(Rat::zero)
}

fn min3(r: &Vec3) -> Rat {
    r.iter().min().cloned().unwrap_or_else(Rat::zero)
}

/// A short rational `<= s` (`below`) or `>= s`, within about `2^-bits`:
/// the simplest one between one and two error bounds of
/// [`Surd::approx`] away.
fn round_out(s: &Surd, bits: u64, below: bool) -> Rat {
    let slack = &Rat::dyadic(Int::one(), bits) * &(&Rat::one() + &s.b.abs());
    let x = s.approx(bits);
    let near = if below { &x - &slack } else { &x + &slack };
    let far = if below {
        &near - &slack
    } else {
        &near + &slack
    };
    let (lo, hi) = if below { (far, near) } else { (near, far) };
    Rat::simplest_in(&lo, &hi)
}

/// A non-homothetic grazing pass (module docs).
#[derive(Clone, Debug)]
pub struct Graze {
    /// `A`'s semi-axes (`[2]` vertical).
    pub a_radii: Vec3,
    /// `A`'s turn about the vertical.
    pub a_turn: Quat,
    /// `B`'s semi-axes (`[2]` vertical).
    pub b_radii: Vec3,
    /// `B`'s orientation control points, each a turn about the vertical:
    /// one for a translation, several for a rigid spin.
    pub b_turn: Vec<Quat>,
    /// The rotation applied to the whole scene.
    pub scene_turn: Quat,
    /// `B`'s horizontal velocity `(v0, v1)` over the span in `u`.
    pub velocity: [Rat; 2],
    /// `|v|`, rational (the generator checks `speed² = v0² + v1²`).
    pub speed: Rat,
    /// The instant of closest approach, in `(0, 1)`.
    pub ustar: Rat,
}

impl Graze {
    /// The standard pass for bodies `a_radii`, `b_radii`: velocity along
    /// `(3, 4)` fast enough that both ends are outside the bounding spheres
    /// (`u*·|v| > 2·(max a + max b)`), closest at `u* = 3/7`.
    pub fn new(a_radii: Vec3, b_radii: Vec3) -> Graze {
        let ustar = rat(3, 7);
        let reach = &(&max3(&a_radii) + &max3(&b_radii)) * &int(2);
        // |v| = 5w with w the least integer above reach / (5·u*).
        let w = Rat::from((&reach / &(&int(5) * &ustar)).floor().to_i64().unwrap_or(1) + 1);
        Graze {
            a_radii,
            a_turn: about_z(int(1), int(0)),
            b_radii,
            b_turn: vec![about_z(int(1), int(0))],
            scene_turn: about_z(int(1), int(0)),
            velocity: [&int(3) * &w, &int(4) * &w],
            speed: &int(5) * &w,
            ustar,
        }
    }

    fn check(&self) -> Result<(), StabilityError> {
        let [v0, v1] = &self.velocity;
        let ok = is_about_z(&self.a_turn)
            && self.b_turn.iter().all(is_about_z)
            && !self.b_turn.is_empty()
            && &(v0 * v0) + &(v1 * v1) == &self.speed * &self.speed
            && self.speed.signum() > 0
            && self.ustar > Rat::zero()
            && self.ustar < Rat::one();
        if ok {
            Ok(())
        } else {
            Err(StabilityError::Truth(
                "graze: turns must be about z, |v| rational, 0 < u* < 1".into(),
            ))
        }
    }

    /// The scene with gap `gap`, on the span `[0, 1]`.
    pub fn scene(&self, gap: &Rat) -> Scene {
        let z = gap + &self.b_radii[2];
        let at = |u: Rat| {
            let s = &u - &self.ustar;
            rotate(
                &self.scene_turn,
                &v3(&s * &self.velocity[0], &s * &self.velocity[1], z.clone()),
            )
        };
        let center = Bezier {
            points: vec![at(Rat::zero()), at(Rat::one())],
            weights: None,
        };
        let turned: Vec<Quat> = self
            .b_turn
            .iter()
            .map(|q| quat_mul(&self.scene_turn, q))
            .collect();
        let b_motion = match turned.as_slice() {
            [q] => Motion::Translation {
                center,
                orientation: q.clone(),
            },
            _ => Motion::Rigid {
                orientation: Bezier {
                    points: turned,
                    weights: None,
                },
                center,
            },
        };
        Scene {
            span: [Rat::zero(), Rat::one()],
            a: Body {
                radii: self.a_radii.clone(),
                motion: Motion::Static {
                    center: rotate(
                        &self.scene_turn,
                        &v3(Rat::zero(), Rat::zero(), -&self.a_radii[2]),
                    ),
                    orientation: quat_mul(&self.scene_turn, &self.a_turn),
                },
            },
            b: Body {
                radii: self.b_radii.clone(),
                motion: b_motion,
            },
        }
    }

    /// `R²` for the balls tangent at `A`'s top and `B`'s bottom point:
    /// inside (`m²/c`) or around (`M²/c`); returns the sum `S`.
    fn ball_sum(&self, outer: bool) -> Rat {
        let ball = |r: &Vec3| {
            let m = if outer { max3(r) } else { min3(r) };
            &(&m * &m) / &r[2]
        };
        &ball(&self.a_radii) + &ball(&self.b_radii)
    }

    /// The two contacts' brackets for the gap `−eps` (module docs).
    fn brackets(&self, eps: &Rat) -> Result<Vec<Instant>, StabilityError> {
        let reach = &max3(&self.a_radii) + &max3(&self.b_radii);
        let ends_apart =
            &self.ustar * &self.speed > reach && &(&Rat::one() - &self.ustar) * &self.speed > reach;
        let spins = self.b_turn.len() > 1;
        if !ends_apart || (spins && self.b_radii[0] != self.b_radii[1]) {
            return Err(StabilityError::Truth(
                "graze overlap: ends within the bounding spheres, or a triaxial spin".into(),
            ));
        }
        // h² = 2εS − ε² (≤ 0: no information from that side).
        let h2 = |outer: bool| {
            let v = &(&(&int(2) * eps) * &self.ball_sum(outer)) - &(eps * eps);
            if v.signum() > 0 {
                v
            } else {
                Rat::zero()
            }
        };
        let off = |outer: bool, sign: i64| {
            Surd::new(self.ustar.clone(), &int(sign) / &self.speed, h2(outer))
        };
        let bits = 64 + eps.denom().bits().max(eps.numer().bits());
        let (zero, one) = (Rat::zero(), Rat::one());
        let clip = |x: Rat| x.max(zero.clone()).min(one.clone());
        let left = (
            clip(round_out(&off(true, -1)?, bits, true)),
            clip(round_out(&off(false, -1)?, bits, false)).min(self.ustar.clone()),
        );
        let right = (
            clip(round_out(&off(false, 1)?, bits, true)).max(self.ustar.clone()),
            clip(round_out(&off(true, 1)?, bits, false)),
        );
        Ok(vec![
            Instant::Within(left.0, left.1),
            Instant::Within(right.0, right.1),
        ])
    }

    /// The case with gap `gap` (module docs for the truth).
    pub fn pass(
        &self,
        family: &str,
        name: String,
        k: Option<u32>,
        gap: Rat,
    ) -> Result<Case, StabilityError> {
        self.check()?;
        let (contacts, states) = match gap.signum() {
            1 => (vec![], vec![State::Separate]),
            0 => (
                vec![Instant::At(Surd::rational(self.ustar.clone()))],
                vec![State::Separate, State::Touch, State::Separate],
            ),
            _ => (
                self.brackets(&-&gap)?,
                vec![
                    State::Separate,
                    State::Touch,
                    State::Overlap,
                    State::Touch,
                    State::Separate,
                ],
            ),
        };
        let scene = self.scene(&gap);
        let mut truth = Truth::known(family, name.clone(), k, &scene.span, contacts, states)?;
        truth.closest = Some(Closest {
            t: self.ustar.clone(),
            gap: gap.clone(),
        });
        Ok(Case {
            name: format!("{family}-{name}"),
            scene,
            truth,
        })
    }

    /// The pass with gap `+10⁻ᵏ`, `0` and `−10⁻ᵏ` for every `k` (the
    /// touch once).
    pub fn family(&self, family: &str, ks: &[u32]) -> Result<Vec<Case>, StabilityError> {
        let mut out = vec![self.pass(family, "touch".into(), None, Rat::zero())?];
        for &k in ks {
            let g = pow10(-(k as i32));
            out.push(self.pass(family, format!("k{k:03}-miss"), Some(k), g.clone())?);
            out.push(self.pass(family, format!("k{k:03}-overlap"), Some(k), -g)?);
        }
        Ok(out)
    }
}

/// The gap exponents: up to `10⁻¹⁰⁰`.
fn graze_ks(level: Level) -> Vec<u32> {
    match level {
        Level::Shipped => vec![1, 24, 100],
        Level::Full => vec![
            1, 2, 3, 4, 6, 8, 10, 12, 16, 20, 22, 24, 30, 40, 50, 60, 70, 80, 90, 100,
        ],
    }
}

/// Triaxial `A = (3, 2, 1)` and `B = (1, 1/2, 3/4)`.
fn shapes() -> Graze {
    Graze::new(v3(int(3), int(2), int(1)), v3(int(1), rat(1, 2), rat(3, 4)))
}

/// Turns about the vertical: `A` by `(2, 0, 0, 1)`, `B` by `(1, 0, 0, 3)`.
fn turned() -> Graze {
    Graze {
        a_turn: about_z(int(2), int(1)),
        b_turn: vec![about_z(int(1), int(3))],
        ..shapes()
    }
}

/// A generic rational rotation of the whole scene (`|Q|² = 30`).
fn scene_quat() -> Quat {
    [int(1), int(2), int(-3), int(4)]
}

/// Different shapes, axis-aligned: `B` translates.
pub fn graze_shapes(level: Level) -> Result<Vec<Case>, StabilityError> {
    shapes().family("graze-shapes", &graze_ks(level))
}

/// `A` and `B` turned about the contact normal by fixed rational angles.
pub fn graze_turned(level: Level) -> Result<Vec<Case>, StabilityError> {
    turned().family("graze-turned", &graze_ks(level))
}

/// [`graze_turned`] with the whole scene turned by `Q = (1, 2, −3, 4)`.
pub fn graze_scene_turned(level: Level) -> Result<Vec<Case>, StabilityError> {
    let g = Graze {
        scene_turn: scene_quat(),
        ..turned()
    };
    g.family("graze-scene-turned", &graze_ks(level))
}

/// `B` spinning about the contact normal under a rigid motion (orientation
/// `(1, 0, 0, 0) → (1, 0, 0, 1)`, a quarter turn), the whole scene turned by
/// `Q`: a triaxial `B` for the misses and the touch, `B = (1, 1, 3/4)`
/// (symmetric about its spin axis) for the overlaps (module docs).
pub fn graze_spin(level: Level) -> Result<Vec<Case>, StabilityError> {
    let family = "graze-spin";
    let spin = vec![about_z(int(1), int(0)), about_z(int(1), int(1))];
    let tri = Graze {
        b_turn: spin.clone(),
        scene_turn: scene_quat(),
        ..turned()
    };
    let sym = Graze {
        b_radii: v3(int(1), int(1), rat(3, 4)),
        ..tri.clone()
    };
    let mut out = vec![tri.pass(family, "touch".into(), None, Rat::zero())?];
    for k in graze_ks(level) {
        let g = pow10(-(k as i32));
        out.push(tri.pass(family, format!("k{k:03}-miss"), Some(k), g.clone())?);
        out.push(sym.pass(family, format!("k{k:03}-overlap"), Some(k), -g)?);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternion_product_composes_rotations() {
        let p = scene_quat();
        let q: Quat = [rat(1, 2), int(3), int(0), int(-1)];
        let v = v3(int(1), rat(-2, 3), int(5));
        assert_eq!(rotate(&quat_mul(&p, &q), &v), rotate(&p, &rotate(&q, &v)));
    }

    #[test]
    fn brackets_straddle_nothing_and_shrink_with_the_gap() {
        let g = shapes();
        let wide = g.brackets(&pow10(-2)).unwrap_or_else(|e| panic!("{e}"));
        let narrow = g.brackets(&pow10(-40)).unwrap_or_else(|e| panic!("{e}"));
        for b in [&wide, &narrow] {
            let (l, r) = (b[0].bounds(0), b[1].bounds(0));
            assert!(l.0 <= l.1 && l.1 <= g.ustar && g.ustar <= r.0 && r.0 <= r.1);
        }
        let width = |b: &[Instant]| {
            let (lo, hi) = b[1].bounds(0);
            &hi - &lo
        };
        assert!(width(&narrow) < &width(&wide) * &pow10(-15));
    }

    #[test]
    fn a_triaxial_spin_has_no_overlap_truth() {
        let g = Graze {
            b_turn: vec![about_z(int(1), int(0)), about_z(int(1), int(1))],
            ..shapes()
        };
        assert!(g.pass("x", "y".into(), None, -pow10(-3)).is_err());
        assert!(g.pass("x", "y".into(), None, pow10(-3)).is_ok());
    }
}
