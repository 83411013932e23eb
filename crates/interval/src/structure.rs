//! What the structure of a scene proves before any enclosure is
//! evaluated: `sr0 ≡ 0` (proportional quadratic parts) and spins that
//! cannot move a body.

use ccd_arith::Rat;
use ccd_motion::{Body, Motion, Quat};
use ccd_quadric::rotation_numerator;

/// The orientation quaternion of a body whose orientation never changes.
fn fixed_orientation(m: &Motion) -> Option<&Quat> {
    match m {
        Motion::Static { orientation, .. } | Motion::Translation { orientation, .. } => {
            Some(orientation)
        }
        Motion::Helical {
            orientation, rate, ..
        } if rate.signum() == 0 => Some(orientation),
        _ => None,
    }
}

/// `sr0 ≡ 0` by structure: the quadratic parts of `A(t)` and `B(t)` (the
/// upper-left 3×3 blocks, `R·diag(r⁻²)·Rᵀ` up to positive factors) are
/// proportional at every t — two spheres under rigid motions (Note 2), or
/// two ellipsoids with proportional radii and the same constant
/// orientation (as in Example 5.1). Then `λA + B` has a 3×3 block that
/// vanishes at one λ, so its rank drops by 2 there and `f` has a double
/// root for every t.
pub(crate) fn sr0_vanishes_by_structure(a: &Body, b: &Body) -> bool {
    let sphere = |x: &Body| {
        x.radii.iter().all(|r| *r == x.radii[0]) && !matches!(x.motion, Motion::Affine { .. })
    };
    if sphere(a) && sphere(b) {
        return true;
    }
    let proportional = |p: &[Rat], q: &[Rat]| {
        (0..p.len()).all(|i| (0..q.len()).all(|j| &p[i] * &q[j] == &p[j] * &q[i]))
    };
    match (fixed_orientation(&a.motion), fixed_orientation(&b.motion)) {
        (Some(qa), Some(qb)) => proportional(qa, qb) && proportional(&a.radii, &b.radii),
        _ => false,
    }
}

/// The body with its spin removed when the spin cannot move it: the helical
/// rotation `Rot(axis, θ)` leaves the quadric invariant for every θ exactly
/// when `Q = R₀·diag(r⁻²)·R₀ᵀ` (`R₀` the initial orientation) commutes with
/// the cross-product matrix `K = [axis]×` (then it commutes with
/// `Rot = I + sin θ·K/|a| + (1 − cos θ)·K²/|a|²`, and `R(t)·Q·R(t)ᵀ = Q`):
/// a sphere, or a spheroid spinning about its axis of symmetry. `A(t)`
/// depends on the rotation only through `R·diag(r⁻²)·Rᵀ`, so setting the
/// rate to 0 is an identity of the motion's symbolic form, checked in exact
/// rational arithmetic, not an approximation — and it takes the spin's
/// `sin`/`cos` out of every enclosure, whatever the rate.
pub fn without_invisible_spin(body: &Body) -> Body {
    let Motion::Helical {
        orientation,
        axis,
        rate,
        center,
    } = &body.motion
    else {
        return body.clone();
    };
    if rate.signum() == 0 {
        return body.clone();
    }
    let m = rotation_numerator(orientation);
    let inv2: [Rat; 3] = std::array::from_fn(|i| {
        let r2 = &body.radii[i] * &body.radii[i];
        r2.recip().unwrap_or_else(Rat::zero)
    });
    // Q = M·diag(r⁻²)·Mᵀ (a positive multiple of R₀·diag·R₀ᵀ).
    let q: [[Rat; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).fold(Rat::zero(), |acc, k| {
                &acc + &(&(&m[i][k] * &inv2[k]) * &m[j][k])
            })
        })
    });
    let z = Rat::zero();
    let k: [[Rat; 3]; 3] = [
        [z.clone(), -&axis[2], axis[1].clone()],
        [axis[2].clone(), z.clone(), -&axis[0]],
        [-&axis[1], axis[0].clone(), z],
    ];
    let mul = |x: &[[Rat; 3]; 3], y: &[[Rat; 3]; 3]| -> [[Rat; 3]; 3] {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..3).fold(Rat::zero(), |acc, l| &acc + &(&x[i][l] * &y[l][j]))
            })
        })
    };
    if mul(&q, &k) != mul(&k, &q) {
        return body.clone();
    }
    Body {
        radii: body.radii.clone(),
        motion: Motion::Helical {
            orientation: orientation.clone(),
            axis: axis.clone(),
            rate: Rat::zero(),
            center: center.clone(),
        },
    }
}
