//! [`SceneError`]: why a scene is rejected, naming the offending field.

use ccd_arith::{excerpt, ParseRatError, Rat};
use std::fmt;

use crate::{MAX_BODIES, MAX_CONTROL_POINTS, MAX_INPUT_BYTES};

/// The TOML type of a value, as expected by the format or as found in a file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TomlType {
    /// A number: a TOML integer or float, or (where a number is expected) a
    /// string such as `"1/3"`.
    Number,
    /// A string.
    String,
    /// A boolean.
    Boolean,
    /// A date, time or date-time.
    Datetime,
    /// An array `[…]`.
    Array,
    /// A table: `[header]` or inline `{ … }`.
    Table,
    /// An array of tables `[[header]]`.
    ArrayOfTables,
    /// JSON `null` (scene JSON only).
    Null,
}

impl fmt::Display for TomlType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            TomlType::Number => "a number",
            TomlType::String => "a string",
            TomlType::Boolean => "a boolean",
            TomlType::Datetime => "a date-time",
            TomlType::Array => "an array",
            TomlType::Table => "a table",
            TomlType::ArrayOfTables => "an array of tables",
            TomlType::Null => "null",
        })
    }
}

/// Which size limit a hostile or oversized input ran into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Limit {
    /// The whole input is longer than [`MAX_INPUT_BYTES`].
    InputBytes,
    /// A curve has more than [`MAX_CONTROL_POINTS`] control points.
    ControlPoints,
    /// A number's text is longer than [`Rat::MAX_TEXT`] characters or its
    /// exponent exceeds [`Rat::MAX_EXPONENT`] in magnitude.
    Number,
    /// A world has more than [`MAX_BODIES`] bodies.
    Bodies,
}

impl fmt::Display for Limit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Limit::InputBytes => write!(
                f,
                "at most {MAX_INPUT_BYTES} bytes ({} MiB) of input are read",
                MAX_INPUT_BYTES >> 20
            ),
            Limit::ControlPoints => write!(
                f,
                "at most {MAX_CONTROL_POINTS} control points per curve, i.e. degree <= {}",
                MAX_CONTROL_POINTS - 1
            ),
            Limit::Number => write!(
                f,
                "a number has at most {} characters and an exponent of magnitude <= {}",
                Rat::MAX_TEXT,
                Rat::MAX_EXPONENT
            ),
            Limit::Bodies => write!(f, "at most {MAX_BODIES} bodies in a world"),
        }
    }
}

/// Why a scene was rejected.
///
/// Every variant but [`SceneError::NotToml`] names the offending field as a
/// dotted path with indices, e.g. `b.motion.center[1][2]`, `a.radii[0]`,
/// `span`, `b.motion.kind` (see [`SceneError::field`]), and its message starts
/// with ``field `…`: ``. Keys that are not bare TOML keys are quoted in paths.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SceneError {
    /// The text is not valid TOML (1-based line and column, in characters).
    #[error("not TOML (line {line}, column {column}): {message}")]
    NotToml {
        /// Line of the syntax error.
        line: usize,
        /// Column of the syntax error.
        column: usize,
        /// The TOML parser's description.
        message: String,
    },
    /// The text is not valid JSON (a scene written as JSON, e.g. one line
    /// of `ccd-exact batch`; 1-based line and column).
    #[error("not JSON (line {line}, column {column}): {message}")]
    NotJson {
        /// Line of the syntax error.
        line: usize,
        /// Column of the syntax error.
        column: usize,
        /// The JSON parser's description.
        message: String,
    },
    /// A JSON number that is not an integer: JSON numbers with a fraction
    /// or an exponent are binary floating point once parsed, so a scene
    /// writes them as strings (`"0.1"`, `"1/3"`, `"1e-20"`).
    #[error("field `{field}`: a JSON number that is not an integer is not exact; write it as a string, e.g. \"0.1\" or \"1/3\"")]
    JsonFloat {
        /// Path of the number.
        field: String,
    },
    /// A JSON `null` inside an array (a key whose value is `null` is read
    /// as absent).
    #[error("field `{field}`: null is not a value of the scene format")]
    JsonNull {
        /// Path of the null.
        field: String,
    },
    /// Two bodies of a world with the same name, or a body with an empty
    /// name.
    #[error("field `{field}`: {}", match .first { Some(i) => format!("the name is already that of body[{i}]"), None => "a name must not be empty".to_string() })]
    Name {
        /// Path of the second body's `name`.
        field: String,
        /// The index of the first body with that name (`None`: the name
        /// is empty).
        first: Option<usize>,
    },
    /// A required field is absent. A `motion` table that is present needs a
    /// `kind`: its absence is reported here as `….motion.kind`.
    #[error("field `{field}`: required but missing")]
    Missing {
        /// Path of the missing field.
        field: String,
    },
    /// A field that scene format 1 does not have (at this place, or for this
    /// motion kind).
    #[error("field `{field}`: unknown field (not part of scene format 1 here)")]
    Unknown {
        /// Path of the unexpected field.
        field: String,
    },
    /// A value of the wrong TOML type.
    #[error("field `{field}`: expected {expected}, found {found}")]
    WrongType {
        /// Path of the value.
        field: String,
        /// What the format wants there.
        expected: TomlType,
        /// What the file has.
        found: TomlType,
    },
    /// A number that is not a finite exact rational (`inf`, `nan`, `1/0`,
    /// `abc`, an empty string, …).
    #[error("field `{field}`: {source}")]
    Number {
        /// Path of the number.
        field: String,
        /// Why its text is not a number.
        source: ParseRatError,
    },
    /// An array of the wrong length (a 3-vector, a quaternion, a matrix row,
    /// the span, or weights that do not match the control points).
    #[error("field `{field}`: expected {expected} entries, found {found}")]
    Length {
        /// Path of the array.
        field: String,
        /// Required number of entries.
        expected: usize,
        /// Number of entries present.
        found: usize,
    },
    /// A Bézier curve without control points.
    #[error("field `{field}`: a curve needs at least one control point")]
    Empty {
        /// Path of the control-point list.
        field: String,
    },
    /// A radius or weight that is not `> 0`.
    #[error("field `{field}`: must be > 0, found {}", shown(.value))]
    NonPositive {
        /// Path of the number.
        field: String,
        /// Its value.
        value: Rat,
    },
    /// `span = [t0, t1]` with `t0 >= t1`.
    #[error("field `span`: t0 = {} must be less than t1 = {}", shown(.t0), shown(.t1))]
    Span {
        /// Start of the span (boxed to keep the error small).
        t0: Box<Rat>,
        /// End of the span.
        t1: Box<Rat>,
    },
    /// A motion `kind` that format 1 does not define.
    #[error(
        "field `{field}`: unknown motion kind `{kind}` (expected static, translation, rigid, affine or helical)"
    )]
    UnknownKind {
        /// Path of the `kind` field.
        field: String,
        /// The kind as written (cut to at most [`Rat::QUOTED_TEXT`]
        /// characters, see [`excerpt`]).
        kind: String,
    },
    /// An orientation quaternion that is exactly zero (no rotation).
    #[error("field `{field}`: the zero quaternion is not a rotation")]
    ZeroQuaternion {
        /// Path of the quaternion.
        field: String,
    },
    /// A helical spin axis that is the zero vector.
    #[error("field `{field}`: the spin axis must not be the zero vector")]
    ZeroAxis {
        /// Path of the axis.
        field: String,
    },
    /// An input beyond a size limit; `field` is `<file>` for the whole input.
    #[error("field `{field}`: too large ({limit})")]
    TooLarge {
        /// Path of the oversized item, or `<file>`.
        field: String,
        /// The limit exceeded.
        limit: Limit,
    },
    /// `format` is not 1.
    #[error("field `format`: unsupported format {} (only format 1 exists)", shown(.found))]
    UnsupportedFormat {
        /// The format number found.
        found: Rat,
    },
}

impl SceneError {
    /// The dotted path of the offending field (`None` only for
    /// [`SceneError::NotToml`] and [`SceneError::NotJson`]; `<file>` for an oversized input).
    pub fn field(&self) -> Option<&str> {
        match self {
            SceneError::NotToml { .. } | SceneError::NotJson { .. } => None,
            SceneError::Span { .. } => Some("span"),
            SceneError::UnsupportedFormat { .. } => Some("format"),
            SceneError::Missing { field }
            | SceneError::Unknown { field }
            | SceneError::WrongType { field, .. }
            | SceneError::Number { field, .. }
            | SceneError::Length { field, .. }
            | SceneError::Empty { field }
            | SceneError::NonPositive { field, .. }
            | SceneError::UnknownKind { field, .. }
            | SceneError::ZeroQuaternion { field }
            | SceneError::ZeroAxis { field }
            | SceneError::JsonFloat { field }
            | SceneError::JsonNull { field }
            | SceneError::Name { field, .. }
            | SceneError::TooLarge { field, .. } => Some(field),
        }
    }
}

/// A dotted field path under construction, e.g. `b.motion.center[1][2]`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub(crate) struct FieldPath(String);

impl FieldPath {
    /// The path of a top-level key.
    pub(crate) fn root(key: &str) -> FieldPath {
        FieldPath::default().key(key)
    }
    /// `self.key`; keys that are not bare TOML keys are quoted, and a key
    /// from the file longer than [`Rat::QUOTED_TEXT`] characters is cut (see
    /// [`excerpt`]), so an error never echoes a huge key in full.
    pub(crate) fn key(&self, key: &str) -> FieldPath {
        let bare = !key.is_empty()
            && key
                .bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-');
        let cut = excerpt(key);
        let key = if bare && cut == key {
            cut
        } else {
            format!("{cut:?}")
        };
        if self.0.is_empty() {
            FieldPath(key)
        } else {
            FieldPath(format!("{}.{key}", self.0))
        }
    }
    /// The path of body `i` of a world, named `name`: `body[3] "arm-2"`
    /// (the name cut as [`FieldPath::key`] cuts keys).
    pub(crate) fn body(i: usize, name: &str) -> FieldPath {
        FieldPath(format!("body[{i}] {:?}", excerpt(name)))
    }
    /// `self[i]`.
    pub(crate) fn index(&self, i: usize) -> FieldPath {
        FieldPath(format!("{}[{i}]", self.0))
    }
    /// The path as text, for an error.
    pub(crate) fn to_field(&self) -> String {
        self.0.clone()
    }
}

/// A value from the file as a message shows it: cut by [`excerpt`] (a
/// number may have thousands of digits).
fn shown(value: &Rat) -> String {
    excerpt(&value.to_string())
}
