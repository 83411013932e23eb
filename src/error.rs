//! Errors of the front door: every one names what was wrong and where.

use ccd_motion::MotionError;
use ccd_scene::SceneError;

/// Why a query has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CcdError {
    /// The scene is not valid (the message starts with the field).
    #[error(transparent)]
    Scene(#[from] SceneError),
    /// A motion degenerates somewhere on the span, found exactly.
    #[error("field `{field}`: {source}")]
    Motion {
        /// The offending field, e.g. `b.motion.orientation`.
        field: String,
        /// What degenerates.
        source: MotionError,
    },
    /// An option is out of range.
    #[error("option `{option}`: {reason}")]
    Option {
        /// The option, e.g. `--digits`.
        option: &'static str,
        /// Why.
        reason: String,
    },
    /// The interval path for non-rational motions refused the scene.
    #[error(transparent)]
    Enclosure(#[from] ccd_enclosure::EnclosureError),
    /// The exact isolation reached its documented bound on work (see
    /// docs/termination.md): the scene's numbers are too long for its
    /// degree to be answered in about a second. Every query below the
    /// bound runs to the end.
    #[error(
        "the exact query needs more than its bound of {limit} word operations of exact \
         root isolation (did {work}): the scene's numbers are too long for its degrees; \
         see docs/termination.md"
    )]
    Effort {
        /// Word operations done when the isolation stopped.
        work: u64,
        /// The bound, [`ccd_solver::MAX_EXACT_WORK`].
        limit: u64,
    },
    /// A broken invariant inside the engine (a bug: please report it).
    #[error("internal error: {0}")]
    Internal(String),
}

impl CcdError {
    /// Attaches the body (`a` or `b`) and the field that a motion error is about.
    pub(crate) fn motion(body: &str, source: MotionError) -> CcdError {
        let field = match source {
            MotionError::QuaternionVanishes { .. } => "motion.orientation",
            MotionError::SingularAffine { .. } => "motion.matrix",
            MotionError::WeightVanishes { .. } | MotionError::MalformedCurve { .. } => {
                "motion.weights"
            }
            MotionError::NotRational { .. } => "motion.kind",
        };
        CcdError::Motion {
            field: format!("{body}.{field}"),
            source,
        }
    }
}
