//! # ccd-enclosure
//!
//! The certified interval path of `ccd-exact` for motions that are not
//! rational — the `helical` kind (constant spin about a fixed axis while
//! the centre follows a line, circle or helix), as in Example 5.2 of Jia,
//! Choi, Mourrain & Wang, *An algebraic approach to continuous collision
//! detection for ellipsoids* (CAGD 2011) — and, on the same footing, any
//! mix of it with the rational kinds.
//!
//! The algebra is the paper's: `f(λ; t) = det(λA(t) + B(t))` (Section 2),
//! the five quantities `sr22, sr20, sr11, sr10, sr0` of Theorem 3.10 by the
//! closed forms of Section 4, contact instants among the roots of `sr0(t)`
//! (Theorem 5.2) or, when `sr0 ≡ 0`, of `sr11(t)` (Theorems 5.4–5.6), and
//! constant states between contacts (Theorem 5.1, Algorithm 1). Only the
//! arithmetic differs: every value is an **enclosure** —
//!
//! * [`trig`]: rigorous sin/cos (Machin's π, Cody–Waite or multi-precision
//!   reduction, Taylor with Lagrange remainder);
//! * [`dyadic`]: [`BigInterval`], intervals with dyadic ends rounded outward
//!   to a chosen number of bits, for escalation when `f64` cannot decide;
//! * [`dual`]: [`Dual`] numbers, so the same generic `ccd-quadric` and
//!   `ccd-subres` code gives each quantity and its derivative in t;
//! * [`placement`]: the bodies' placements over any of these number types;
//! * [`isolate`]: subdivision, mean-value enclosures and interval Newton;
//! * [`signs`]: Theorem 3.10 read off sign *sets*.
//!
//! What is certified and what is not is spelled out in `docs/helical.md`;
//! in short, an instant is certified only when its root is proven simple
//! and unique in its enclosure and its configuration proven from the signs
//! on that enclosure.
//!
//! ```
//! use ccd_arith::Rat;
//! use ccd_enclosure::{run, Options};
//! use ccd_motion::{Body, HelicalCenter, Motion};
//! let r = |x: i64| Rat::from(x);
//! // A sphere of radius 1 spinning about z while its centre moves from
//! // (−4, 1/4, 0) to (4, 1/4, 0) through a static ellipsoid (2, 1, 1/2).
//! let a = Body {
//!     radii: [r(1), r(1), r(1)],
//!     motion: Motion::Helical {
//!         orientation: Motion::identity(),
//!         axis: [r(0), r(0), r(1)],
//!         rate: r(3),
//!         center: HelicalCenter {
//!             base: [r(-4), Rat::from_frac(1, 4), r(0)], velocity: [r(8), r(0), r(0)],
//!             cos: [r(0), r(0), r(0)], sin: [r(0), r(0), r(0)], frequency: r(0),
//!         },
//!     },
//! };
//! let b = Body { radii: [r(2), r(1), Rat::from_frac(1, 2)], motion: Motion::at_origin() };
//! let out = run(&a, &b, &[r(0), r(1)], &Options::default()).unwrap();
//! // They touch twice (t ≈ 0.1276 and t ≈ 0.8724) and overlap in between.
//! assert_eq!(out.contacts.len(), 2);
//! let t1 = &out.contacts[0];
//! assert!(t1.certified && (t1.lo.to_f64() - 0.12761784090026).abs() < 1e-12);
//! assert!(t1.width() <= Rat::from_frac(1, 1_000_000_000_000_000));
//! assert!(!out.collision_free);
//! ```

#![warn(missing_docs)]

pub mod dual;
pub mod dyadic;
mod error;
pub mod isolate;
pub mod placement;
pub mod real;
mod run;
pub mod signs;
pub mod trig;

pub use dual::Dual;
pub use dyadic::{BigInterval, Dyadic};
pub use error::EnclosureError;
pub use placement::{centred_quadrics, invariants_at, quadric_at};
pub use real::Real;
pub use run::{run, without_invisible_spin, Options};
pub use trig::{sin_cos, Trig};
