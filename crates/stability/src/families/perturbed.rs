//! The paper's benchmark scenes (`benches/scenes/*.toml`, Tables 3 and 4)
//! with every coordinate perturbed to `d` digits: each number `x` of the
//! bodies (radii, centre and orientation control points, affine matrix
//! entries; not weights or the span) becomes `x + 10⁻ᵈ·rⱼ` with the small
//! rational `rⱼ = (j mod 5 + 1)/(j mod 3 + 2)` (`j` counts the numbers), for
//! `d = 30, 100, 1000` — inputs of about `3.3·d` bits per number.
//!
//! # The truth, and how far it is by construction
//!
//! There is no closed form for these contacts. Every benchmark scene's
//! contacts are simple crossings (the timeline changes between separate
//! and overlap at each), isolated by the certified answer on the short
//! original scene to enclosures `[lo, hi]` of width `w ≤ 10⁻¹⁵` of the
//! span; a perturbation of `10⁻ᵈ` (`d >= 30`) moves a simple root by about
//! `10⁻ᵈ⁺ᶜ` (`c` the condition of the root), far less than `w`. So the
//! truth is: the original's state sequence, and each contact in
//! `[lo − w, hi + w]`. It is **checked independently of the CCD engine**:
//! at both ends of every bracket (and at the span's ends) the exact static
//! classifier (Theorem 3.10) on the *perturbed* scene must give the states
//! on either side, so each bracket provably holds a crossing; a case
//! failing that is an error, not a scene. That one crossing per bracket is
//! all there is rests on the root's simplicity (stability), not on a proof.

use super::unit;
use crate::baseline::state_at;
use crate::truth::{Instant, Truth};
use crate::{Case, Level, StabilityError};
use ccd_arith::Rat;
use ccd_exact::{run, Options, Scene, State};
use ccd_motion::{Body, Motion};

/// The benchmark scenes, by name (embedded at build time).
pub const BENCHES: &[(&str, &str)] = &[
    (
        "rigid-deg2",
        include_str!("../../../../benches/scenes/rigid-deg2.toml"),
    ),
    (
        "affine-deg2",
        include_str!("../../../../benches/scenes/affine-deg2.toml"),
    ),
    (
        "affine-rational-deg2",
        include_str!("../../../../benches/scenes/affine-rational-deg2.toml"),
    ),
    (
        "rigid-288",
        include_str!("../../../../benches/scenes/rigid-288.toml"),
    ),
];

/// `xᵢ + 10⁻ᵈ·rⱼ` for each entry, `j` running on.
fn bump<const N: usize>(xs: &[Rat; N], tiny: &Rat, j: &mut i64) -> [Rat; N] {
    std::array::from_fn(|i| {
        *j += 1;
        &xs[i] + &(tiny * &Rat::from_frac(*j % 5 + 1, *j % 3 + 2))
    })
}

/// `x + 10⁻ᵈ·rⱼ` for every number of `body` (module docs); `j` runs on.
fn perturb_body(body: &Body, d: u32, j: &mut i64) -> Body {
    let tiny = super::pow10(-(d as i32));
    let radii = bump(&body.radii, &tiny, j);
    let motion = match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => Motion::Static {
            center: bump(center, &tiny, j),
            orientation: bump(orientation, &tiny, j),
        },
        Motion::Translation {
            center,
            orientation,
        } => {
            let mut c = center.clone();
            c.points = c.points.iter().map(|p| bump(p, &tiny, j)).collect();
            Motion::Translation {
                center: c,
                orientation: bump(orientation, &tiny, j),
            }
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            let mut o = orientation.clone();
            o.points = o.points.iter().map(|q| bump(q, &tiny, j)).collect();
            let mut c = center.clone();
            c.points = c.points.iter().map(|p| bump(p, &tiny, j)).collect();
            Motion::Rigid {
                orientation: o,
                center: c,
            }
        }
        Motion::Affine { matrix } => {
            let mut m = matrix.clone();
            m.points = m
                .points
                .iter()
                .map(|rows| std::array::from_fn(|r| bump(&rows[r], &tiny, j)))
                .collect();
            Motion::Affine { matrix: m }
        }
        other => other.clone(),
    };
    Body { radii, motion }
}

/// The scene with every body number perturbed at `d` digits.
pub fn perturb(scene: &Scene, d: u32) -> Scene {
    let mut j = 0;
    let a = perturb_body(&scene.a, d, &mut j);
    let b = perturb_body(&scene.b, d, &mut j);
    Scene {
        span: scene.span.clone(),
        a,
        b,
    }
}

/// One perturbed benchmark and its truth (module docs).
fn case(bench: &str, text: &str, d: u32) -> Result<Case, StabilityError> {
    let family = "bench-perturbed";
    let name = format!("{bench}-d{d:04}");
    let scene_err = |source| StabilityError::Scene {
        name: name.clone(),
        source: Box::new(source),
    };
    let original = Scene::from_toml(text).map_err(scene_err)?;
    let out = run(&original, &Options::default()).map_err(|source| StabilityError::Engine {
        name: name.clone(),
        method: "exact",
        source: Box::new(source),
    })?;
    let mut states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
    states.dedup();
    let scene = perturb(&original, d);
    let [t0, t1] = &scene.span;
    let h = t1 - t0;
    let to_u = |t: &Rat| &(t - t0) / &h;
    // Brackets in u, [lo − w, hi + w] ∩ [0, 1].
    let brackets: Vec<(Rat, Rat)> = out
        .contacts
        .iter()
        .map(|c| {
            let w = &c.hi - &c.lo;
            let lo = to_u(&(&c.lo - &w)).max(Rat::zero());
            let hi = to_u(&(&c.hi + &w)).min(Rat::one());
            (lo, hi)
        })
        .collect();
    // Simple crossings only: separate/overlap alternating around each
    // touch, and the static classifier agrees at every bracket end.
    let sides: Vec<State> = states
        .iter()
        .copied()
        .filter(|s| *s != State::Touch)
        .collect();
    let crossing = sides.len() == brackets.len() + 1 && sides.windows(2).all(|w| w[0] != w[1]);
    let mut checks = vec![(Rat::zero(), sides.first().copied())];
    for (i, (lo, hi)) in brackets.iter().enumerate() {
        checks.push((lo.clone(), sides.get(i).copied()));
        checks.push((hi.clone(), sides.get(i + 1).copied()));
    }
    checks.push((Rat::one(), sides.last().copied()));
    for (u, want) in &checks {
        let got = state_at(&scene, u)?;
        if !crossing || Some(got) != *want {
            return Err(StabilityError::Truth(format!(
                "{family}-{name}: the static classifier gives {} at u = {u}, not {:?}",
                got.name(),
                want.map(|s| s.name())
            )));
        }
    }
    let contacts = brackets
        .into_iter()
        .map(|(lo, hi)| Instant::Within(lo, hi))
        .collect();
    let truth = Truth::known(family, name.clone(), Some(d), &unit(), contacts, states)?;
    Ok(Case {
        name: format!("{family}-{name}"),
        scene,
        truth,
    })
}

/// Every benchmark at `d = 30, 100, 1000` (shipped: the quick ones).
pub fn bench_perturbed(level: Level) -> Result<Vec<Case>, StabilityError> {
    let mut out = Vec::new();
    for (bench, text) in BENCHES {
        let ds: &[u32] = match (level, *bench) {
            (Level::Full, _) => &[30, 100, 1000],
            (Level::Shipped, "affine-deg2") => &[30, 100],
            (Level::Shipped, "rigid-288") => &[],
            (Level::Shipped, _) => &[30],
        };
        for &d in ds {
            out.push(case(bench, text, d)?);
        }
    }
    Ok(out)
}
