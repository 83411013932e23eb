//! Ellipsoids as quadric matrices, the characteristic quartic
//! `det(λA + B)` and the static classifier of Theorem 3.10 (Jia, Choi,
//! Mourrain & Wang 2011): separate, externally touching or overlapping,
//! decided exactly.

#![warn(missing_docs)]

mod ellipsoid;
mod matrix;
mod placement;
mod relative;

pub use ccd_classify::Configuration;
pub use ellipsoid::{classify_pair, classify_quartic, Ellipsoid};
pub use matrix::{
    adj3, adj4, adj4_column, characteristic, congruence, det3, det4, integral, is_affine_placement,
    placed_characteristic, subset_products, Mat3, Mat4,
};
pub use placement::{
    affine_inverse, affine_placement, body_diagonal, norm2, quat_mul, rigid_inverse,
    rigid_placement, rotation_numerator,
};
pub use relative::{
    rigid_characteristic, rigid_characteristic_degree, rigid_values, RigidFrame, ScaledSum,
};
