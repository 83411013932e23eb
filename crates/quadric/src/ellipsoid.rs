//! Static ellipsoids with exact data and the static classifier
//! (Theorem 3.10 / Table 2).

use crate::matrix::{characteristic, congruence, integral, Mat4};
use crate::placement::{body_diagonal, norm2, rigid_inverse, rotation_numerator};
use ccd_arith::{Int, Rat, RingOps};
use ccd_classify::{classify, Configuration, SignData};
use ccd_subres::closed_forms;

/// An ellipsoid placed in space: semi-axes along its body axes, a centre,
/// and an orientation quaternion `[w, x, y, z]` (any nonzero quaternion).
#[derive(Clone, Debug, PartialEq)]
pub struct Ellipsoid {
    /// Semi-axes `r0, r1, r2 > 0`.
    pub radii: [Rat; 3],
    /// Centre.
    pub center: [Rat; 3],
    /// Orientation (need not be unit; must be nonzero).
    pub orientation: [Rat; 4],
}

impl Ellipsoid {
    /// An axis-aligned ellipsoid.
    pub fn axis_aligned(radii: [Rat; 3], center: [Rat; 3]) -> Ellipsoid {
        Ellipsoid {
            radii,
            center,
            orientation: [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()],
        }
    }

    /// The 4×4 matrix `A` of the ellipsoid, `XᵀAX = 0` on the surface and
    /// `< 0` inside, up to a positive factor: `Nᵀ·D·N` with `N` the inverse
    /// placement and `D` the body quadric.
    pub fn quadric_matrix(&self) -> Mat4<Rat> {
        let m = rotation_numerator(&self.orientation);
        let n = norm2(&self.orientation);
        let inv = rigid_inverse(&m, &n, &self.center, &Rat::one());
        congruence(&inv, &body_diagonal(&self.radii))
    }

    /// [`Ellipsoid::quadric_matrix`] times the positive integer that clears
    /// its denominators: the form the exact tests compute with.
    pub fn quadric_matrix_int(&self) -> Mat4<Int> {
        integral(&self.quadric_matrix())
    }
}

/// Classifies the characteristic quartic `[e, a, b, c, d]` (high → low) of
/// two ellipsoids by Theorem 3.10 from the signs of the closed forms of
/// Section 4. `sign` is the ring's sign function.
pub fn classify_quartic<R: RingOps>(f: &[R; 5], sign: impl Fn(&R) -> i32) -> Configuration {
    classify(&SignData::from_invariants(&closed_forms(f), f, sign))
}

/// Separate, externally touching or overlapping, decided exactly
/// (Theorem 3.10 on `f(λ) = det(λA + B)`; dividing by `det A` is never
/// needed because every quantity read is of even degree in the
/// coefficients).
///
/// ```
/// use ccd_arith::Rat;
/// use ccd_quadric::{classify_pair, Ellipsoid};
/// use ccd_classify::Configuration;
/// let unit = |x: i64| Ellipsoid::axis_aligned([Rat::one(), Rat::one(), Rat::one()], [Rat::from(x), Rat::zero(), Rat::zero()]);
/// assert_eq!(classify_pair(&unit(0), &unit(2)), Configuration::ExternalTouch);
/// assert_eq!(classify_pair(&unit(0), &unit(3)), Configuration::Separate);
/// assert_eq!(classify_pair(&unit(0), &unit(1)), Configuration::Overlap);
/// ```
pub fn classify_pair(a: &Ellipsoid, b: &Ellipsoid) -> Configuration {
    let f = characteristic(&a.quadric_matrix_int(), &b.quadric_matrix_int());
    classify_quartic(&f, Int::signum)
}
