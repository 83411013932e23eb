//! The scene file format (TOML, format 1): exact parsing and validation into
//! typed bodies and motions.
//!
//! A scene names a time span and two ellipsoids `a` and `b`, each with its
//! semi-axes and its motion (see the contract `scene-format.md`). Every number
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

mod error;
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

    /// The default span `[0, 1]`.
    pub fn default_span() -> [Rat; 2] {
        [Rat::zero(), Rat::one()]
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
