//! What can make a motion unusable over the span, decided exactly.

/// A motion that does not define a valid moving ellipsoid over the span.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MotionError {
    /// The quaternion curve is zero at some instant, so `R(q)` is undefined.
    #[error("the quaternion curve vanishes at t ≈ {at}")]
    QuaternionVanishes {
        /// Approximate instant (span-relative parameter mapped to t).
        at: f64,
    },
    /// `L(t)` is singular at some instant: the ellipsoid degenerates.
    #[error("the affine matrix L(t) is singular at t ≈ {at}")]
    SingularAffine {
        /// Approximate instant.
        at: f64,
    },
    /// The weight curve has a zero on the span.
    #[error("the weight curve vanishes at t ≈ {at}")]
    WeightVanishes {
        /// Approximate instant.
        at: f64,
    },
    /// A Bézier curve without control points, or whose weights are not one
    /// per control point (a validated scene never has one; a `Body` built
    /// through the API can).
    #[error("a Bézier curve has {points} control points and {weights} weights (needs at least one point and one weight per point)")]
    MalformedCurve {
        /// Number of control points.
        points: usize,
        /// Number of weights.
        weights: usize,
    },
    /// A kind that has no exact rational form (helical) in the exact path.
    #[error("the {kind} motion is not rational; it needs the interval path")]
    NotRational {
        /// The kind's name.
        kind: &'static str,
    },
}

impl MotionError {
    /// The field of a body's table the error is about, e.g.
    /// `motion.orientation`.
    pub fn field(&self) -> &'static str {
        match self {
            MotionError::QuaternionVanishes { .. } => "motion.orientation",
            MotionError::SingularAffine { .. } => "motion.matrix",
            MotionError::WeightVanishes { .. } | MotionError::MalformedCurve { .. } => {
                "motion.weights"
            }
            MotionError::NotRational { .. } => "motion.kind",
        }
    }
}
