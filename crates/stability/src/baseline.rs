//! The naive baseline: the exact STATIC test (Theorem 3.10,
//! [`ccd_quadric::classify_pair`]) at `N` evenly spaced instants — what
//! discrete-time collision checking (FCL's default CCD, game engines' fixed
//! sub-steps) does.
//!
//! Each sample is decided exactly, so every error of the baseline is a
//! sampling error, never a rounding error: an event that begins and ends
//! between two samples is not seen at all, and an event that is seen is
//! dated to the first sample after it.

use crate::StabilityError;
use ccd_arith::{Int, Rat};
use ccd_exact::{Scene, State};
use ccd_motion::{Bezier, Body, Motion};
use ccd_quadric::{
    affine_inverse, body_diagonal, characteristic, classify_pair, classify_quartic, congruence,
    integral, Ellipsoid, Mat4,
};

/// De Casteljau at `u` over ℚ, coordinate-wise, with optional weights:
/// `Σ Bᵢⁿ(u)·wᵢ·Pᵢ / Σ Bᵢⁿ(u)·wᵢ` by repeated linear interpolation of the
/// homogeneous points `(wᵢPᵢ, wᵢ)`.
pub fn eval_curve<const N: usize>(c: &Bezier<[Rat; N]>, u: &Rat) -> [Rat; N] {
    let w = |i: usize| c.weights.as_ref().map_or(Rat::one(), |w| w[i].clone());
    let v = &Rat::one() - u;
    let reduce = |mut p: Vec<Rat>| {
        while p.len() > 1 {
            p = p.windows(2).map(|x| &(&v * &x[0]) + &(u * &x[1])).collect();
        }
        p.pop().unwrap_or_else(Rat::zero)
    };
    let den = reduce((0..c.points.len()).map(w).collect());
    std::array::from_fn(|k| {
        let num = reduce(
            c.points
                .iter()
                .enumerate()
                .map(|(i, p)| &p[k] * &w(i))
                .collect(),
        );
        &num / &den
    })
}

/// A body frozen at one instant: an [`Ellipsoid`] for the rigid kinds, or
/// the quadric matrix of its affine image.
enum Placed {
    Rigid(Box<Ellipsoid>),
    Quadric(Box<Mat4<Rat>>),
}

impl Placed {
    fn matrix(&self) -> Mat4<Rat> {
        match self {
            Placed::Rigid(e) => e.quadric_matrix(),
            Placed::Quadric(m) => (**m).clone(),
        }
    }
}

/// The body at parameter `u ∈ [0, 1]` (placement evaluated exactly).
fn place(body: &Body, u: &Rat) -> Result<Placed, StabilityError> {
    let rigid = |center, orientation| {
        Placed::Rigid(Box::new(Ellipsoid {
            radii: body.radii.clone(),
            center,
            orientation,
        }))
    };
    Ok(match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => rigid(center.clone(), orientation.clone()),
        Motion::Translation {
            center,
            orientation,
        } => rigid(eval_curve(center, u), orientation.clone()),
        Motion::Rigid {
            orientation,
            center,
        } => rigid(eval_curve(center, u), eval_curve(orientation, u)),
        Motion::Affine { matrix } => {
            // [L | d]/w at u: interpolate the 12 entries as one curve.
            let flat = matrix.flattened();
            let e = eval_curve(&flat, u);
            let l = std::array::from_fn(|i| std::array::from_fn(|j| e[4 * i + j].clone()));
            let d = std::array::from_fn(|i| e[4 * i + 3].clone());
            let inv = affine_inverse(&l, &d, &Rat::one());
            Placed::Quadric(Box::new(congruence(&inv, &body_diagonal(&body.radii))))
        }
        Motion::Helical { .. } => return Err(StabilityError::Unsupported("helical")),
    })
}

/// The exact static state of the scene at `u ∈ [0, 1]` (`t = t0 + u·(t1 − t0)`).
pub fn state_at(scene: &Scene, u: &Rat) -> Result<State, StabilityError> {
    let (a, b) = (place(&scene.a, u)?, place(&scene.b, u)?);
    Ok(State::from(match (&a, &b) {
        (Placed::Rigid(ea), Placed::Rigid(eb)) => classify_pair(ea, eb),
        _ => classify_quartic(
            &characteristic(&integral(&a.matrix()), &integral(&b.matrix())),
            Int::signum,
        ),
    }))
}

/// What the sampling baseline reports.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sampled {
    /// No sample found the bodies not separate.
    pub collision_free: bool,
    /// Reported contact instants (times): a lone `Touch` sample, or the
    /// first sample after a change between separate and overlap.
    pub contacts: Vec<Rat>,
    /// The sampled states with repeats collapsed.
    pub states: Vec<State>,
}

/// Samples the scene at `n >= 2` evenly spaced instants `uᵢ = i/(n − 1)`
/// (both ends included) and reads contacts off the state changes.
pub fn sample(scene: &Scene, n: usize) -> Result<Sampled, StabilityError> {
    let n = n.max(2);
    let last =
        i64::try_from(n - 1).map_err(|_| StabilityError::Usage("too many samples".into()))?;
    let us: Vec<Rat> = (0..=last).map(|i| Rat::from_frac(i, last)).collect();
    let states = us
        .iter()
        .map(|u| state_at(scene, u))
        .collect::<Result<Vec<_>, _>>()?;
    // Runs of equal states: (state, first index, length).
    let mut runs: Vec<(State, usize, usize)> = Vec::new();
    for (i, s) in states.iter().enumerate() {
        match runs.last_mut() {
            Some(r) if r.0 == *s => r.2 += 1,
            _ => runs.push((*s, i, 1)),
        }
    }
    let h = &scene.span[1] - &scene.span[0];
    let time = |i: usize| &scene.span[0] + &(&h * &us[i]);
    let mut contacts = Vec::new();
    for (j, &(state, first, len)) in runs.iter().enumerate() {
        let crossing = j > 0 && state != State::Touch && runs[j - 1].0 != State::Touch;
        if (state == State::Touch && len == 1) || crossing {
            contacts.push(time(first));
        }
    }
    Ok(Sampled {
        collision_free: states.iter().all(|s| *s == State::Separate),
        contacts,
        states: runs.iter().map(|r| r.0).collect(),
    })
}
