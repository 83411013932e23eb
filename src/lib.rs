//! # ccd-exact
//!
//! Exact, certified continuous collision detection for two moving
//! ellipsoids, after Jia, Choi, Mourrain & Wang, *An algebraic approach to
//! continuous collision detection for ellipsoids* (CAGD 2011).
//!
//! Data flows one way: scene ([`Scene`]) → motion (`ccd-motion`) → quadric
//! matrices `A(t)`, `B(t)` → characteristic polynomial `f(λ; t)` →
//! subresultants `sr_ij(t)` (`ccd-subres`) → roots (`ccd-solver`) →
//! timeline ([`Outcome`]). Scenes with a non-rational (helical) motion go
//! through certified interval enclosures instead (`ccd-enclosure`), where
//! an instant that cannot be certified is reported with `certified: false`.
//!
//! ```
//! use ccd_exact::{run, Options, Scene, State};
//! let scene = Scene::from_toml(r#"
//!     [a]
//!     radii = [2, 1, 1]
//!     motion = { kind = "translation", center = [[11, 0, 0], [-1, 0, 0]] }
//!     [b]
//!     radii = [2, 1, 1]
//!     motion = { kind = "translation", center = [[3, -2, -4], [3, 2, 0]] }
//! "#).unwrap();
//! let out = run(&scene, &Options::default()).unwrap();
//! let states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
//! assert_eq!(states, [State::Separate, State::Touch, State::Overlap, State::Touch, State::Separate]);
//! // The first contact t1 ≈ 0.5395042868, enclosed to 1e-15 with exact ends.
//! let t1 = &out.contacts[0];
//! assert!(t1.lo.to_f64() <= 0.5395042869 && t1.hi.to_f64() >= 0.5395042867);
//! assert!(t1.width() <= ccd_arith::Rat::from_frac(1, 1_000_000_000_000_000));
//! ```

#![warn(missing_docs)]

mod algorithm;
mod batch;
mod error;
mod geometry;
mod json;
mod signs;
mod world;

pub use algorithm::{symbolic, Arithmetic, Options};
pub use batch::{batch_line, run_batch, BatchError, BatchOptions, BatchSummary};
pub use ccd_scene::{Scene, SceneError, SceneFile, World};
pub use ccd_timeline::{Box3, Gap, Geometry, Instant, Outcome, Segment, State, Stats, Witness};
pub use error::CcdError;
pub use json::{to_json, world_to_json};
pub use world::{
    run_world, BroadStats, PairResult, WorldContact, WorldOutcome, MAX_CANDIDATE_PAIRS,
};

/// Runs continuous collision detection on a scene (Algorithm 1).
pub fn run(scene: &Scene, options: &Options) -> Result<Outcome, CcdError> {
    if options.digits > Options::MAX_DIGITS {
        return Err(CcdError::Option {
            option: "--digits",
            reason: format!("at most {}", Options::MAX_DIGITS),
        });
    }
    scene.validate()?;
    let helical = [&scene.a, &scene.b].iter().any(|b| !b.motion.is_rational());
    if !helical {
        return algorithm::run(scene, options);
    }
    if options.arithmetic == Arithmetic::Float {
        return Err(CcdError::Option { option: "--arithmetic", reason: "float arithmetic needs rational motions; helical scenes use certified interval enclosures".into() });
    }
    // Non-rational motions: certified interval enclosures (not exact algebra).
    let opts = ccd_enclosure::Options {
        digits: options.digits,
        first_contact_only: options.first_contact_only,
    };
    let mut outcome =
        ccd_enclosure::run(&scene.a, &scene.b, &scene.span, &opts).map_err(CcdError::from)?;
    if options.contact_geometry {
        outcome.geometry = geometry::helical(scene, &outcome, options);
    }
    Ok(outcome)
}

/// Parses a scene from TOML text and runs it.
pub fn run_toml(text: &str, options: &Options) -> Result<Outcome, CcdError> {
    run(&Scene::from_toml(text)?, options)
}
