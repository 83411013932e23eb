//! A certified broad phase for worlds of moving ellipsoids.
//!
//! For each body and each of `S = 2^depth` equal sub-intervals ("slices")
//! `[t_k, t_{k+1}]` of the span, [`sweep`] gives an axis-aligned box that
//! **provably** holds the body at every instant of the slice, and (but for
//! affine motions) its centre's box and its shape around it; [`broad_phase`]
//! then sweeps and prunes: a pair is a candidate when in some slice neither
//! disjoint boxes nor a separating plane ([`Swept::apart`]) prove it apart,
//! and every other pair is **proven separate** over the whole span.
//!
//! The boxes are outward-rounded `f64` ([`ccd_arith::Interval`]): every
//! operation rounds away from the true value, so a box is never smaller
//! than the exact one; a number beyond `f64`'s range gives an infinite box,
//! which overlaps everything and prunes nothing. The math (see [`sweep`]):
//!
//! * a Bézier curve with positive weights lies in the convex hull of its
//!   control points, and de Casteljau halving gives the control points of
//!   each slice (on homogeneous coordinates `[wᵢPᵢ, wᵢ]` for a rational
//!   curve, whose weights stay positive);
//! * an ellipsoid `X = R·diag(r)·Y + c`, `|Y| <= 1`, has `|X_k − c_k| <=
//!   ‖row_k(R)·diag(r)‖ <= max r` for any rotation `R`;
//! * an affine placement `X = (L(t)·diag(r)·Y + d(t)) / w(t)` is, for fixed
//!   `Y`, a rational Bézier curve with control points `Lᵢ·diag(r)·Y + dᵢ`,
//!   so `X_k` lies between `minᵢ (d_ik − ‖row_k(Lᵢ)·diag(r)‖)` and
//!   `maxᵢ (d_ik + ‖row_k(Lᵢ)·diag(r)‖)`.
//!
//! ```
//! use ccd_arith::Rat;
//! use ccd_broad::{broad_phase, slice_start, sweep, DEFAULT_DEPTH};
//! use ccd_motion::{Bezier, Body, Motion};
//! let ball = |from: [i64; 3], to: [i64; 3]| Body {
//!     radii: [1, 1, 1].map(Rat::from),
//!     motion: Motion::Translation {
//!         center: Bezier { points: vec![from.map(Rat::from), to.map(Rat::from)], weights: None },
//!         orientation: Motion::identity(),
//!     },
//! };
//! let span = [Rat::zero(), Rat::one()];
//! // Balls 0 and 1 pass the origin at t = 1/2; ball 2 passes it at t = 3/4,
//! // when the others have left (their boxes over the whole span overlap, in
//! // no slice do they); ball 3 is far away.
//! let bodies = [
//!     ball([-10, 0, 0], [10, 0, 0]),
//!     ball([0, -10, 0], [0, 10, 0]),
//!     ball([0, 0, -30], [0, 0, 10]),
//!     ball([0, 0, 50], [0, 0, 60]),
//! ];
//! let boxes: Vec<_> = bodies.iter().map(|b| sweep(b, &span, DEFAULT_DEPTH)).collect();
//! let found = broad_phase(&boxes, 1000).unwrap();
//! assert_eq!(found.candidates.len(), 1);
//! let c = &found.candidates[0];
//! assert_eq!((c.a, c.b), (0, 1));
//! // They cannot touch before the first slice in which they are not proven
//! // apart. (They touch at t = 1/2 − 1/(10√2) ≈ 0.429; the bound is 13/32.)
//! assert_eq!(slice_start(&span, DEFAULT_DEPTH, c.first_slice), Rat::from_frac(13, 32));
//! assert_eq!(found.pruned, 5);
//! ```

#![warn(missing_docs)]

mod boxes;
mod sweep;

pub use boxes::{sweep, Aabb, Swept};
pub use sweep::{broad_phase, slice_start, BroadError, BroadPhase, Candidate};

/// The default number of halvings of the span: `2^5 = 32` slices.
pub const DEFAULT_DEPTH: u32 = 5;

/// Most halvings [`sweep`] does (`2^10 = 1024` slices); a larger depth is
/// clamped to it.
pub const MAX_DEPTH: u32 = 10;
