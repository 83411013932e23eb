//! Motion kinds (Bézier translation, rational rigid, rational affine,
//! helical) and the moving quadric matrices they give.

#![warn(missing_docs)]

pub mod kinds;

pub use kinds::{Bezier, Body, HelicalCenter, Mat34, Motion, Quat, Vec3};
