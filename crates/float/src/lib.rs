//! # ccd-float
//!
//! The FLOAT MODE of ccd-exact: Algorithm 1 of Jia, Choi, Mourrain & Wang,
//! *An algebraic approach to continuous collision detection for ellipsoids*
//! (CAGD 2011), run in `f64` as in the paper's own comparison (Section 5.3,
//! Table 3): "Double precision floating-point arithmetic is used for all
//! computations … Polynomials are represented in the Bernstein form …
//! Root solving of polynomials are then done by subdivision using the de
//! Casteljau algorithm."
//!
//! **Nothing here is certified**, and every [`Instant`] it returns says so
//! (`certified: false`). Floats decide signs that may be rounding noise —
//! whether `sr0 ≡ 0` ([`TOL_IDENTICALLY_ZERO`]), whether a polynomial has a
//! root where it only grazes zero ([`Roots`]'s stopping rule), whether a
//! value at a root is zero ([`TOL_SIGN`]) — so grazing contacts, tangencies
//! and near misses can be missed or invented. It exists as a fast option
//! and as the baseline the exact mode is measured against.
//!
//! Pipeline (mirroring the exact path):
//! 1. set-up ([`prepare`], module `setup`): the exact characteristic
//!    polynomial `f(λ; u)` ([`CharPoly`], shared with the exact path) is
//!    rescaled and converted to `f64` Bernstein form ([`BernsteinF64`],
//!    module `bernstein`), and the five `sr` polynomials of Theorem 3.10 are
//!    computed from it by the Section 4 closed forms
//!    ([`ccd_subres::closed_forms`], unchanged, over [`BernsteinF64`]);
//! 2. solve ([`solve_prepared`], module `algorithm`): Algorithm 1's branches
//!    (Theorems 5.2, 5.4–5.6), candidate roots on `[0, 1]` in increasing
//!    order by de Casteljau subdivision and Descartes' rule of signs
//!    ([`Roots`], module `roots`), the touch test of Theorem 3.10(2) at each
//!    ([`ccd_classify::classify_with`] on [`Approx`] signs, module `approx`),
//!    the states between contacts (Theorem 5.1), and the [`Outcome`] laid
//!    out by the exact path's own rules
//!    ([`ccd_timeline::Findings::into_outcome`]), with `certified: false`, so every instant is marked
//!    uncertified.
//!
//! ```
//! use ccd_arith::Rat;
//! use ccd_float::{solve, Options};
//! use ccd_motion::CharPoly;
//! use ccd_poly::ZPoly;
//! // Two unit spheres, centres d = 3 − 2u apart: they touch at u = 1/2.
//! // f(λ; u) = −(λ + 1)²(λ² + mλ + 1) with m = 2 − d² (Note 2: sr0 ≡ 0).
//! let m = ZPoly::from_i64s(&[-7, 12, -4]);
//! let k = |v: i64| ZPoly::from_i64s(&[v]);
//! let c3 = -(&m + &k(2));
//! let f = CharPoly { coeffs: [k(-1), c3.clone(), -(&(&k(2) * &m) + &k(2)), c3, k(-1)] };
//! let out = solve(&f, &[Rat::zero(), Rat::one()], &Options { first_contact_only: true });
//! let first = out.first_contact.unwrap();
//! assert!((first.midpoint().to_f64() - 0.5).abs() < 1e-12 && !first.certified);
//! assert!(!out.complete);
//! ```

#![warn(missing_docs)]

mod algorithm;
mod approx;
mod bernstein;
mod roots;
mod setup;

pub use algorithm::{
    solve, solve_prepared, Options, TOL_IDENTICALLY_ZERO, TOL_ROOT_NOISE, TOL_SIGN,
};
pub use approx::Approx;
pub use bernstein::BernsteinF64;
pub use ccd_motion::CharPoly;
pub use ccd_timeline::{Instant, Outcome, Segment, State, Stats};
pub use roots::{Candidate, RootKind, Roots, CLUSTER_WIDTH, ROOT_WIDTH};
pub use setup::{certified_bernstein, prepare, Prepared};
