//! Why a query on the interval path cannot run.

use ccd_motion::MotionError;

/// An invalid query: bad options, span or bodies.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EnclosureError {
    /// `digits` above [`crate::Options::MAX_DIGITS`].
    #[error("--digits: at most {max} (got {got})")]
    Digits {
        /// The largest accepted value.
        max: u32,
        /// The value asked for.
        got: u32,
    },
    /// `t0 >= t1`.
    #[error("span: t0 < t1 is required")]
    Span,
    /// A radius `<= 0`.
    #[error("{body}.radii: every radius must be > 0")]
    Radius {
        /// `a` or `b`.
        body: &'static str,
    },
    /// A quaternion or axis that must not be zero is zero.
    #[error("{body}.motion.{field}: must not be zero")]
    Zero {
        /// `a` or `b`.
        body: &'static str,
        /// The field.
        field: &'static str,
    },
    /// A rational motion that degenerates on the span (decided exactly by
    /// `ccd-motion`).
    #[error("{body}.motion: {source}")]
    Motion {
        /// `a` or `b`.
        body: &'static str,
        /// What degenerates.
        #[source]
        source: MotionError,
    },
}
