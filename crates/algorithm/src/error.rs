//! Why a query has no answer: every error names what was wrong and where.

use ccd_motion::MotionError;
use ccd_scene::SceneError;

/// Why a query has no answer.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
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
    /// The exact path reached one of its documented bounds (see
    /// docs/termination.md): the scene's numbers are too long for its
    /// degrees to be answered exactly in about a second. Every query below
    /// the bounds runs to the end.
    #[error(
        "limit `{limit}`: the exact query needs more than {bound} {unit} (reached {reached}): \
         the scene's numbers are too long for its degrees; see docs/termination.md"
    )]
    Effort {
        /// Which bound: `exact work` (word operations of root isolation,
        /// `ccd_solver::MAX_EXACT_WORK`) or `exact size` (bits of the
        /// closed forms, `ccd_exact_arith::MAX_EXACT_BITS`).
        limit: &'static str,
        /// The unit of `bound` and `reached`.
        unit: &'static str,
        /// The bound.
        bound: u64,
        /// What the query reached (or would need) when it stopped.
        reached: u64,
    },
    /// The broad phase of a world refused it (too many candidate pairs).
    #[error(transparent)]
    Broad(#[from] ccd_broad::BroadError),
    /// A broken invariant inside the engine (a bug: please report it).
    #[error("internal error: {0}")]
    Internal(String),
}

impl CcdError {
    /// Attaches the body (`a` or `b`, or a world's `body[3] "arm-2"`) and
    /// the field that a motion error is about.
    pub fn motion(body: &str, source: MotionError) -> CcdError {
        let field = source.field();
        CcdError::Motion {
            field: format!("{body}.{field}"),
            source,
        }
    }
}
