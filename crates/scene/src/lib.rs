//! The scene file format (TOML, format 1): exact parsing and validation into
//! typed bodies and motions.
//!
//! A scene names a time span and two ellipsoids `a` and `b`, each with its
//! semi-axes and its motion (see the contract `scene-format.md`); a world
//! file ([`World`], [`SceneFile`]) names any number of bodies as `[[body]]`
//! tables, each with a `name`. A scene may also be written as JSON with the
//! same structure ([`Scene::from_json`], one line of `ccd-exact batch`). Every number
//! is read exactly as a rational: TOML integers as themselves, TOML floats
//! from their decimal text as written (`0.1` is exactly 1/10), strings such
//! as `"1/3"` or `"1e-20"` through [`Rat::parse_exact`].
//!
//! ```
//! use ccd_scene::{Motion, Rat, Scene};
//! let scene = Scene::from_toml(r#"
//!     [a]
//!     radii = [1, "1/2", 0.25]
//!     [b]
//!     radii = [1, 1, 1]
//!     [b.motion]
//!     kind = "translation"
//!     center = [[3, 0, 0], [-3, 0, 0]]
//! "#).unwrap();
//! assert_eq!(scene.a.radii[2], Rat::from_frac(1, 4));
//! assert_eq!(scene.a.motion, Motion::at_origin());
//! let err = Scene::from_toml("[a]\nradii = [1, 1]\n[b]\nradii = [1, 1, 1]").unwrap_err();
//! assert_eq!(err.field(), Some("a.radii"));
//! ```
//!
//! Rejected scenes give a [`SceneError`] naming the offending field as a
//! dotted path with indices. The parser does every check that is local to a
//! value; whether a weight curve or quaternion curve vanishes somewhere on the
//! span, or an affine `L(t)` is singular somewhere on it, needs exact root
//! isolation and is left to `ccd-motion`.

#![warn(missing_docs)]

pub(crate) mod error;
mod json;
mod number;
mod parse;
mod validate;

pub use ccd_arith::Rat;
pub use ccd_motion::{Bezier, Body, HelicalCenter, Mat34, Motion, Quat, Vec3};
pub use error::{Limit, SceneError, TomlType};

/// Most control points one Bézier curve may have (so its degree is at most
/// 15); more is refused with [`SceneError::TooLarge`] rather than computed.
pub const MAX_CONTROL_POINTS: usize = 16;

/// Longest input text, in bytes (4 MiB), that [`Scene::from_toml`] reads
/// (and the `ccd-exact` binary reads of a file); longer input is refused
/// with [`SceneError::TooLarge`] on field `<file>` before any parsing.
///
/// It is above the largest scene the other limits allow: two affine curves of
/// [`MAX_CONTROL_POINTS`] matrices and weights, 13 numbers of at most
/// [`Rat::MAX_TEXT`] characters each per point, come to about 1.7 MB.
pub const MAX_INPUT_BYTES: usize = 4 << 20;

/// Most bodies a world file may have; more is refused with
/// [`SceneError::TooLarge`] on field `body` (limit [`Limit::Bodies`]).
///
/// A minimal `[[body]]` table is about 35 bytes, so the 4 MiB input limit
/// alone would allow about 120 000; the number of pairs a world may send to
/// the exact query is capped separately (by `ccd-exact`, after its broad
/// phase).
pub const MAX_BODIES: usize = 100_000;

/// A parsed, validated scene (format 1).
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The time interval `[t0, t1]`, `t0 < t1`.
    pub span: [Rat; 2],
    /// The first ellipsoid.
    pub a: Body,
    /// The second ellipsoid.
    pub b: Body,
}

impl Scene {
    /// Parse and validate TOML text.
    ///
    /// Besides the TOML syntax this checks the structure (no unknown keys,
    /// required keys present, a `motion` table that is present has a `kind`),
    /// the types and lengths of all values, every number's exactness, and
    /// then everything [`Scene::validate`] checks. Input longer than
    /// [`MAX_INPUT_BYTES`] is refused unread. Never panics.
    ///
    /// # Errors
    ///
    /// A [`SceneError`] naming the offending field ([`SceneError::field`]).
    pub fn from_toml(text: &str) -> Result<Scene, SceneError> {
        parse::parse_scene(text)
    }

    /// Validate a scene built in code (the same local checks as the parser),
    /// for library users: `t0 < t1`; radii `> 0`; every curve has 1 to
    /// [`MAX_CONTROL_POINTS`] control points and, when weighted, one weight
    /// `> 0` per point (a rigid orientation curve has no weights); static,
    /// translation and helical orientations and the helical axis are not
    /// zero. Field paths are those of the file format.
    ///
    /// Not checked here (it needs root isolation on the span, see
    /// `ccd-motion`): a rigid quaternion curve or an affine `L(t)` that
    /// vanishes or is singular somewhere on the span. A single zero control
    /// quaternion of a rigid curve is accepted.
    ///
    /// # Errors
    ///
    /// A [`SceneError`] naming the first offending field.
    pub fn validate(&self) -> Result<(), SceneError> {
        validate::validate(self)
    }

    /// Parse and validate a scene written as JSON with the TOML scene's
    /// structure: `{"span": [0, 1], "a": {"radii": [2, 1, 1], "motion":
    /// {"kind": "translation", "center": [[11, 0, 0], [-1, 0, 0]]}}, "b":
    /// …}`. Numbers are JSON integers or strings (`"0.1"`, `"1/3"`,
    /// `"1e-20"`); a JSON number with a fraction or exponent is refused
    /// ([`SceneError::JsonFloat`]), a key whose value is `null` is absent.
    /// Errors and field paths are those of [`Scene::from_toml`]; a syntax
    /// error is [`SceneError::NotJson`]. Input longer than
    /// [`MAX_INPUT_BYTES`] is refused unread. Never panics.
    ///
    /// ```
    /// use ccd_scene::{Rat, Scene};
    /// let s = Scene::from_json(r#"{"a": {"radii": [1, "1/2", "0.25"]}, "b": {"radii": [1, 1, 1]}}"#).unwrap();
    /// assert_eq!(s.a.radii[1], Rat::from_frac(1, 2));
    /// let e = Scene::from_json(r#"{"a": {"radii": [1, 0.5, 1]}, "b": {"radii": [1, 1, 1]}}"#).unwrap_err();
    /// assert_eq!(e.field(), Some("a.radii[1]"));
    /// ```
    pub fn from_json(text: &str) -> Result<Scene, SceneError> {
        parse::parse_json_scene(text)
    }

    /// The default span `[0, 1]`.
    pub fn default_span() -> [Rat; 2] {
        [Rat::zero(), Rat::one()]
    }
}

/// One body of a world: its name and the body.
#[derive(Clone, Debug, PartialEq)]
pub struct NamedBody {
    /// The body's name (non-empty, unique in its world).
    pub name: String,
    /// Radii and motion, as in a pair scene.
    pub body: Body,
}

/// A world: any number of named bodies over one span (a world file's
/// `[[body]]` tables). Every pair of bodies is a pair [`Scene`]
/// ([`World::pair`]).
///
/// ```
/// use ccd_scene::{SceneFile, World};
/// let file = SceneFile::from_toml(r#"
///     span = [0, 2]
///     [[body]]
///     name = "ball"
///     radii = [1, 1, 1]
///     [[body]]
///     name = "arm-2"
///     radii = [2, 1, 1]
///     motion = { kind = "translation", center = [[5, 0, 0], [0, 0, 0]] }
/// "#).unwrap();
/// let SceneFile::World(world) = file else { panic!("a world file") };
/// assert_eq!(world.bodies[1].name, "arm-2");
/// assert_eq!(world.pair(0, 1).b, world.bodies[1].body);
/// let err = SceneFile::from_toml("[[body]]\nname = \"x\"\nradii = [1, 0, 1]").unwrap_err();
/// assert_eq!(err.field(), Some("body[0] \"x\".radii[1]"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct World {
    /// The time interval `[t0, t1]`, `t0 < t1`.
    pub span: [Rat; 2],
    /// The bodies, in file order.
    pub bodies: Vec<NamedBody>,
}

impl World {
    /// Validate a world built in code: the checks of [`Scene::validate`]
    /// on every body (field paths `body[i] "name".…`), every name
    /// non-empty and unique, at most [`MAX_BODIES`] bodies.
    pub fn validate(&self) -> Result<(), SceneError> {
        validate::world(self)
    }

    /// The pair scene of bodies `i` and `j` (`a` = body `i`), over the
    /// world's span. Panics when an index is out of range.
    pub fn pair(&self, i: usize, j: usize) -> Scene {
        Scene {
            span: self.span.clone(),
            a: self.bodies[i].body.clone(),
            b: self.bodies[j].body.clone(),
        }
    }

    /// The field path of body `i`, `body[i] "name"`, that errors about it
    /// start with. Panics when `i` is out of range.
    pub fn body_field(&self, i: usize) -> String {
        error::FieldPath::body(i, &self.bodies[i].name).to_field()
    }
}

/// What a scene file holds: a pair (`[a]`, `[b]`) or a world (`[[body]]`).
/// A file is a world file exactly when it has a `body` key; every pair
/// file keeps its format-1 meaning.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneFile {
    /// Two bodies `a` and `b` (boxed: a scene is large beside a world's
    /// vector).
    Pair(Box<Scene>),
    /// Any number of named bodies.
    World(World),
}

impl SceneFile {
    /// Parse and validate a pair or world file (TOML); the checks and
    /// errors of [`Scene::from_toml`], and for a world [`World::validate`]'s.
    pub fn from_toml(text: &str) -> Result<SceneFile, SceneError> {
        parse::parse_file(text)
    }
}

impl std::str::FromStr for Scene {
    type Err = SceneError;
    /// Same as [`Scene::from_toml`].
    fn from_str(text: &str) -> Result<Scene, SceneError> {
        Scene::from_toml(text)
    }
}

#[cfg(test)]
mod tests;
