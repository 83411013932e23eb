//! # ccd-exact
//!
//! Exact, certified continuous collision detection for two moving
//! ellipsoids, after Jia, Choi, Mourrain & Wang, *An algebraic approach to
//! continuous collision detection for ellipsoids* (CAGD 2011).
//!
//! Data flows one way: scene ([`Scene`]) → motion ([`Motion`]) → quadric
//! matrices `A(t)`, `B(t)` → characteristic polynomial `f(λ; t)` →
//! subresultants `sr_ij(t)` → roots → timeline ([`Outcome`]). Algorithm 1
//! exists once (`ccd-algorithm`), over three arithmetics: exact (certified,
//! the default for rational motions), float (`--arithmetic float`, not
//! certified) and interval (non-rational, helical motions: certified where
//! the enclosures decide, an instant that cannot be certified reported with
//! `certified: false`). This crate is the front door: [`run`] dispatches,
//! [`to_json`] writes the contract's JSON, and everything needed to build a
//! scene in code and read the result is re-exported here ([`prelude`]).
//!
//! A scene built in code, its first contact read back:
//!
//! ```
//! use ccd_exact::prelude::*;
//! let r = |x: i64| Rat::from(x);
//! let a = Body {
//!     radii: [r(2), r(1), r(1)],
//!     motion: Motion::translation(Bezier::polynomial(vec![[r(11), r(0), r(0)], [r(-1), r(0), r(0)]])),
//! };
//! let b = Body {
//!     radii: [r(2), r(1), r(1)],
//!     motion: Motion::translation(Bezier::polynomial(vec![[r(3), r(-2), r(-4)], [r(3), r(2), r(0)]])),
//! };
//! let scene = Scene { span: [r(0), r(1)], a, b };
//! let options = Options { first_contact_only: true, ..Options::default() };
//! let out = run(&scene, &options)?;
//! let t1 = out.first_contact.expect("they touch");
//! // t1 ≈ 0.5395042868, enclosed to 1e-15 with exact rational ends.
//! assert!(t1.certified && t1.lo.to_f64() <= 0.5395042869 && t1.hi.to_f64() >= 0.5395042867);
//! assert!(t1.width() <= Rat::from_frac(1, 1_000_000_000_000_000));
//! # Ok::<(), CcdError>(())
//! ```
//!
//! The same scene from TOML, the whole timeline:
//!
//! ```
//! use ccd_exact::{run_toml, Options, State};
//! let out = run_toml(r#"
//!     [a]
//!     radii = [2, 1, 1]
//!     motion = { kind = "translation", center = [[11, 0, 0], [-1, 0, 0]] }
//!     [b]
//!     radii = [2, 1, 1]
//!     motion = { kind = "translation", center = [[3, -2, -4], [3, 2, 0]] }
//! "#, &Options::default()).unwrap();
//! let states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
//! assert_eq!(states, [State::Separate, State::Touch, State::Overlap, State::Touch, State::Separate]);
//! ```

#![warn(missing_docs)]

mod batch;
mod json;
mod world;

pub use batch::{batch_line, run_batch, BatchError, BatchOptions, BatchSummary};
pub use ccd_algorithm::{Arithmetic, CcdError, Options};
pub use ccd_arith::{Int, Rat};
pub use ccd_exact_arith::{symbolic, MAX_EXACT_BITS};
pub use ccd_motion::{Bezier, Body, HelicalCenter, Mat34, Motion, Quat, Vec3};
pub use ccd_scene::{Scene, SceneError, SceneFile, World};
pub use ccd_timeline::{
    Box3, Branch, Gap, Geometry, Instant, Outcome, Path, Segment, State, Stats, Witness,
};
pub use json::{to_json, to_json_pretty, world_to_json, world_to_json_pretty};
pub use world::{
    run_world, BroadStats, PairResult, WorldContact, WorldOutcome, MAX_CANDIDATE_PAIRS,
};

/// Everything needed to build a scene in code, run it and read the result.
pub mod prelude {
    pub use crate::{
        run, run_toml, Arithmetic, Bezier, Body, Box3, CcdError, Geometry, HelicalCenter, Instant,
        Motion, Options, Outcome, Rat, Scene, Segment, State,
    };
}

/// Runs continuous collision detection on a scene (Algorithm 1), on the
/// exact arithmetic (or the float one, as `options` asks) for rational
/// motions and on the interval arithmetic when a motion is helical.
///
/// # Errors
///
/// [`CcdError::Scene`] for a scene that fails [`Scene::validate`],
/// [`CcdError::Motion`] for a motion that degenerates on the span,
/// [`CcdError::Option`] for an option out of range (`digits` above
/// [`Options::MAX_DIGITS`], float arithmetic on a helical scene), and
/// [`CcdError::Effort`] when an exact query reaches a documented bound.
pub fn run(scene: &Scene, options: &Options) -> Result<Outcome, CcdError> {
    if options.digits > Options::MAX_DIGITS {
        return Err(CcdError::Option {
            option: "--digits",
            reason: format!("at most {}", Options::MAX_DIGITS),
        });
    }
    scene.validate()?;
    let (a, b, span) = (&scene.a, &scene.b, &scene.span);
    if !(a.motion.is_rational() && b.motion.is_rational()) {
        if options.arithmetic == Arithmetic::Float {
            return Err(CcdError::Option { option: "--arithmetic", reason: "float arithmetic needs rational motions; helical scenes use certified interval enclosures".into() });
        }
        return ccd_algorithm::run(ccd_interval::Intervals::new(a, b, span, options)?, options);
    }
    match options.arithmetic {
        Arithmetic::Exact => {
            if options.raycast {
                if let Some(outcome) = ccd_raycast::run(scene, options) {
                    return Ok(outcome);
                }
            }
            ccd_algorithm::run(ccd_exact_arith::Exact::new(scene, options.digits)?, options)
        }
        Arithmetic::Float => {
            // A static pair's f straight from the scene (the same polynomial).
            let f = match ccd_motion::CharPoly::of_static(a, b) {
                Some(f) => f,
                None => ccd_motion::CharPoly::from_placed(
                    &ccd_motion::placed_quadric(a, span).map_err(|e| CcdError::motion("a", e))?,
                    &ccd_motion::placed_quadric(b, span).map_err(|e| CcdError::motion("b", e))?,
                ),
            };
            let p = ccd_float::prepare(&f);
            ccd_algorithm::run(ccd_float::Float::new(&p, span, Some((a, b))), options)
        }
    }
}

/// Parses a scene from TOML text and runs it.
///
/// # Errors
///
/// [`CcdError::Scene`] naming the field for text that is not a valid
/// scene, otherwise those of [`run`].
pub fn run_toml(text: &str, options: &Options) -> Result<Outcome, CcdError> {
    run(&Scene::from_toml(text)?, options)
}
