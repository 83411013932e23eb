//! # ccd-enclosure
//!
//! Rigorous enclosures for motions that are not rational — the `helical`
//! kind (constant spin about a fixed axis while the centre follows a line,
//! circle or helix), as in Example 5.2 of Jia, Choi, Mourrain & Wang (CAGD
//! 2011) — and, on the same footing, any mix of it with the rational
//! kinds: the arithmetic that the interval path (`ccd-interval`) and the
//! contact geometry (`ccd-contact`) evaluate `f(λ; t)` and the five
//! quantities of Theorem 3.10 in.
//!
//! * [`trig`]: rigorous sin/cos (Machin's π, Cody–Waite or multi-precision
//!   reduction, Taylor with Lagrange remainder);
//! * [`BigInterval`] (from `ccd-arith`, where the solver's sign tiers use
//!   it too): intervals with dyadic ends rounded outward to a chosen
//!   number of bits, for escalation when `f64` cannot decide;
//! * [`dual`]: [`Dual`] numbers, so the same generic `ccd-quadric` and
//!   `ccd-subres` code gives each quantity and its derivative in t;
//! * [`placement`]: the bodies' placements over any of these number types;
//! * [`isolate`]: subdivision, mean-value enclosures and interval Newton.

#![warn(missing_docs)]

pub mod dual;
pub mod isolate;
pub mod placement;
pub mod real;
pub mod trig;

pub use ccd_arith::{BigInterval, Dyadic};
pub use dual::Dual;
pub use placement::{centred_quadrics, invariants_at, quadric_at, unit_frame, UnitFrame};
pub use real::Real;
pub use trig::{sin_cos, Trig};
