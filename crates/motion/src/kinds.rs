//! The motion kinds of the scene contract (`scene-format.md`, format 1), as
//! exact data. Turning them into moving quadric matrices is [`crate::matrices`].

use ccd_arith::Rat;

/// A point or vector of ℝ³ with exact coordinates.
pub type Vec3 = [Rat; 3];
/// A quaternion `[w, x, y, z]`, not necessarily unit; it stands for the
/// rotation `R(q) = M(q) / |q|²` of the contract.
pub type Quat = [Rat; 4];
/// An affine placement `[L | d]` as 3 rows of 4.
pub type Mat34 = [[Rat; 4]; 3];

/// A Bézier curve over the span: with `u = (t − t0)/(t1 − t0)` and control
/// points `P0..Pn` it is `Σ Bᵢⁿ(u)·Pᵢ`, or with weights
/// `Σ Bᵢⁿ(u)·wᵢ·Pᵢ / Σ Bᵢⁿ(u)·wᵢ` (each `wᵢ > 0`).
#[derive(Clone, Debug, PartialEq)]
pub struct Bezier<P> {
    /// Control points `P0..Pn` (at least one).
    pub points: Vec<P>,
    /// One positive weight per control point, or `None` (all ones).
    pub weights: Option<Vec<Rat>>,
}

impl<P> Bezier<P> {
    /// A curve that stays at one point.
    pub fn constant(p: P) -> Self {
        Bezier {
            points: vec![p],
            weights: None,
        }
    }
    /// Degree `n` (control points − 1).
    pub fn degree(&self) -> usize {
        self.points.len().saturating_sub(1)
    }
    /// The polynomial Bézier curve with these control points (no weights).
    pub fn polynomial(points: Vec<P>) -> Self {
        Bezier {
            points,
            weights: None,
        }
    }
}

impl Bezier<Mat34> {
    /// The twelve entries of `[L | d]` as one curve in ℚ¹² (same weights):
    /// an affine motion's matrix curve evaluated or bounded entrywise.
    pub fn flattened(&self) -> Bezier<[Rat; 12]> {
        Bezier {
            points: self
                .points
                .iter()
                .map(|m| std::array::from_fn(|i| m[i / 4][i % 4].clone()))
                .collect(),
            weights: self.weights.clone(),
        }
    }
}

/// The centre curve of a helical motion:
/// `c(t) = base + velocity·t + cos·cos(frequency·t) + sin·sin(frequency·t)`,
/// with `t` the time itself.
#[derive(Clone, Debug, PartialEq)]
pub struct HelicalCenter {
    /// `base`.
    pub base: Vec3,
    /// `velocity`.
    pub velocity: Vec3,
    /// `cos` amplitude vector.
    pub cos: Vec3,
    /// `sin` amplitude vector.
    pub sin: Vec3,
    /// `frequency` (radians per unit of t).
    pub frequency: Rat,
}

/// How one ellipsoid is placed over the span. Body points `Xbody` map to the
/// world by `X = R(t)·Xbody + c(t)` (rigid kinds) or
/// `X = (L(t)·Xbody + d(t)) / w(t)` (affine).
// A scene holds two motions, built once: boxing the large helical variant
// would only complicate constructing it.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq)]
pub enum Motion {
    /// Fixed placement: `R = R(orientation)`, `c = center`.
    Static {
        /// Centre.
        center: Vec3,
        /// Orientation quaternion.
        orientation: Quat,
    },
    /// Fixed orientation, centre on a (rational) Bézier curve.
    Translation {
        /// Centre curve.
        center: Bezier<Vec3>,
        /// Orientation quaternion.
        orientation: Quat,
    },
    /// `R(t) = R(q(t))` for a polynomial Bézier quaternion curve (a rational
    /// rotation of degree 2m) and a (rational) Bézier centre; the body turns
    /// about its own centre.
    Rigid {
        /// Orientation curve (weights are not part of the contract here).
        orientation: Bezier<Quat>,
        /// Centre curve.
        center: Bezier<Vec3>,
    },
    /// `X = (L(t)·Xbody + d(t)) / w(t)` with `[L | d]` a Bézier curve of 3×4
    /// matrices and `w` the weight curve (1 without weights).
    Affine {
        /// `[L | d]` control matrices and their weights.
        matrix: Bezier<Mat34>,
    },
    /// Spin at a constant `rate` about `axis` (through the body's centre)
    /// after `orientation`, centre on a line, circle or helix. Not rational.
    Helical {
        /// Initial orientation quaternion.
        orientation: Quat,
        /// Spin axis (nonzero).
        axis: Vec3,
        /// Radians per unit of t.
        rate: Rat,
        /// Centre curve.
        center: HelicalCenter,
    },
}

impl Motion {
    /// The identity quaternion `[1, 0, 0, 0]`.
    pub fn identity() -> Quat {
        [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()]
    }
    /// Static at the origin, unrotated: what an omitted `motion` table means.
    pub fn at_origin() -> Motion {
        Motion::Static {
            center: [Rat::zero(), Rat::zero(), Rat::zero()],
            orientation: Motion::identity(),
        }
    }
    /// A translation along `center` with the identity orientation.
    pub fn translation(center: Bezier<Vec3>) -> Motion {
        Motion::Translation {
            center,
            orientation: Motion::identity(),
        }
    }
    /// `true` for the kinds whose placement is a rational function of t.
    pub fn is_rational(&self) -> bool {
        !matches!(self, Motion::Helical { .. })
    }
    /// `(control points, weights)` of each Bézier curve of the motion.
    pub(crate) fn curve_shapes(&self) -> Vec<(usize, Option<usize>)> {
        fn shape<P>(c: &Bezier<P>) -> (usize, Option<usize>) {
            (c.points.len(), c.weights.as_ref().map(Vec::len))
        }
        match self {
            Motion::Static { .. } | Motion::Helical { .. } => vec![],
            Motion::Translation { center, .. } => vec![shape(center)],
            Motion::Rigid {
                orientation,
                center,
            } => vec![shape(orientation), shape(center)],
            Motion::Affine { matrix } => vec![shape(matrix)],
        }
    }
}

/// One ellipsoid of a scene: semi-axes along its body axes and its motion.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Semi-axes `r0, r1, r2 > 0`; the body is `x²/r0² + y²/r1² + z²/r2² <= 1`.
    pub radii: Vec3,
    /// Placement over the span.
    pub motion: Motion,
}
