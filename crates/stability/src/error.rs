//! The crate's typed errors.

/// Everything that can go wrong while generating, reading, running or
/// reporting the stability families.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum StabilityError {
    /// Reading or writing a file.
    #[error("{path}: {source}")]
    Io {
        /// The file or directory.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
    /// A scene file the engine's parser refused.
    #[error("scene `{name}`: {source}")]
    Scene {
        /// The scene's name.
        name: String,
        /// The parser's error.
        source: Box<ccd_exact::SceneError>,
    },
    /// The engine refused or failed on a scene.
    #[error("scene `{name}`, {method}: {source}")]
    Engine {
        /// The scene's name.
        name: String,
        /// Which method.
        method: &'static str,
        /// The engine's error.
        source: Box<ccd_exact::CcdError>,
    },
    /// A ground-truth sidecar that cannot be read.
    #[error("truth file `{name}`: {reason}")]
    TruthFile {
        /// The sidecar's name.
        name: String,
        /// What is wrong.
        reason: String,
    },
    /// A method gave no answer within the report's budget (its process
    /// was killed; the report counts it as wrong).
    #[error("scene `{name}`, {method}: no answer within {seconds} s")]
    NoAnswer {
        /// The case.
        name: String,
        /// The method's label.
        method: String,
        /// The budget.
        seconds: u64,
    },
    /// A guarded query's child process failed.
    #[error("scene `{name}`, {method}: child process failed: {message}")]
    Child {
        /// The case.
        name: String,
        /// The method's label.
        method: String,
        /// Its standard error.
        message: String,
    },
    /// A construction whose ground truth is inconsistent (a generator bug).
    #[error("ground truth: {0}")]
    Truth(String),
    /// A motion kind the sampling baseline does not place (helical).
    #[error("the sampling baseline does not place {0} motions")]
    Unsupported(&'static str),
    /// Drawing the chart.
    #[error("chart: {0}")]
    Chart(String),
    /// Bad command line.
    #[error("usage: {0}")]
    Usage(String),
}

impl StabilityError {
    /// An I/O error on `path`.
    pub fn io(path: &std::path::Path, source: std::io::Error) -> StabilityError {
        StabilityError::Io {
            path: path.display().to_string(),
            source,
        }
    }
}
