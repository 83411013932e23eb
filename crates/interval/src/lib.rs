//! # ccd-interval
//!
//! The interval arithmetic behind Algorithm 1 (`ccd-algorithm`) for
//! motions that are not rational — the `helical` kind, as in Example 5.2 of
//! Jia, Choi, Mourrain & Wang (CAGD 2011) — and any mix of it with the
//! rational kinds ([`Intervals`], an [`ccd_algorithm::Oracle`]).
//!
//! The algebra is the paper's: `f(λ; t) = det(λA(t) + B(t))`, the five
//! quantities of Theorem 3.10 by the closed forms of Section 4, contact
//! instants among the roots of `sr0(t)` (Theorem 5.2) or, when `sr0 ≡ 0`
//! is proven by structure (module `structure`), of `sr11(t)`. Only the
//! arithmetic differs: every value is an enclosure (`ccd-enclosure`), each
//! sign a set of signs (module `signs`), escalated to multi-precision while
//! undecided; pieces not decided within the effort budget are gaps, filled
//! where sphere certificates prove a state (module `spheres`).
//!
//! What is certified and what is not is spelled out in `docs/helical.md`;
//! in short, an instant is certified only when its root is proven simple
//! and unique in its enclosure and its configuration proven from the signs
//! on that enclosure.
//!
//! ```
//! use ccd_algorithm::Options;
//! use ccd_arith::Rat;
//! use ccd_interval::run;
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

mod oracle;
mod signs;
mod spheres;
mod structure;

pub use oracle::{run, IntervalRoot, Intervals};
pub use structure::without_invisible_spin;
