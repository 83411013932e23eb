//! Motion kinds (Bézier translation, rational rigid, rational affine,
//! helical) and what they give the collision test: moving quadric matrices
//! `A(t)`, `B(t)` and the characteristic polynomial `f(λ; t)` with the
//! lowest degrees the scene allows.

#![warn(missing_docs)]

mod centred;
pub mod characteristic;
mod curve;
mod error;
pub mod kinds;
pub mod matrices;
mod rounded;

pub use characteristic::{char_poly, normalise, normalise_with, CharPoly};
pub use error::MotionError;
pub use kinds::{Bezier, Body, HelicalCenter, Mat34, Motion, Quat, Vec3};
pub use matrices::{characteristic_at, moving_quadric, placed_quadric, PlacedQuadric};
