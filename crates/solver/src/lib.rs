//! Exact real root isolation for ccd-exact: Bernstein coefficients on the
//! span, Descartes' rule of signs on them, de Casteljau subdivision; every
//! sign proven, by an `f64`-interval filter where it suffices and by exact
//! integers where it does not.
//!
//! ```
//! use ccd_arith::Rat;
//! use ccd_poly::ZPoly;
//! // (3t − 1)(2t − 1)(t² − 2) on [0, 2]: roots 1/3, 1/2 and √2.
//! let p = &(&ZPoly::from_i64s(&[-1, 3]) * &ZPoly::from_i64s(&[-1, 2])) * &ZPoly::from_i64s(&[-2, 0, 1]);
//! let roots = ccd_solver::isolate(&p, &Rat::zero(), &Rat::from(2)).unwrap();
//! let mut all: Vec<_> = roots.collect();
//! assert_eq!(all.len(), 3);
//! all[2].refine_to(&Rat::from_frac(1, 1_000_000));
//! assert!(all[2].lo().to_f64() <= 2f64.sqrt() && 2f64.sqrt() <= all[2].hi().to_f64());
//! ```

#![warn(missing_docs)]

mod ball;
mod filter_bernstein;
mod isolate;
mod local;
mod model;
mod root;
mod scaled;

pub use ball::JetBall;
pub use isolate::{RootIter, MAX_EXACT_WORK};
pub use local::LOCAL_WORTH;
pub use model::{
    ball_horner, ball_value, ball_view, BallJet, ExactJet, SignModel, SignProbe, BALL_WORTH,
};
pub use root::RealRoot;
pub use scaled::ScaledPoly;

use ccd_arith::Rat;
use ccd_poly::ZPoly;

/// Why a polynomial's roots cannot be listed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum SolverError {
    /// The zero polynomial vanishes everywhere: its roots are not isolated.
    #[error("the polynomial is identically zero")]
    IdenticallyZero,
    /// The interval is empty or a point (`lo >= hi`).
    #[error("empty interval: the lower end is not below the upper end")]
    EmptyInterval,
}

/// All distinct real roots of `p` in the closed interval `[lo, hi]`, lazily
/// and in increasing order. Works on the squarefree part of `p` (so roots of
/// any multiplicity are found once each, and each isolating interval holds
/// a sign change); roots exactly at `lo`, `hi` or at a subdivision point
/// come out as exact rationals.
pub fn isolate(p: &ZPoly, lo: &Rat, hi: &Rat) -> Result<RootIter, SolverError> {
    isolate_with(p, None, lo, hi)
}

/// [`isolate`], given a factor `square` whose square is expected to divide
/// `p` (a hint for the squarefree part, [`ZPoly::squarefree_part_given`]:
/// proven or dropped there, so the roots are the same either way).
pub fn isolate_with(
    p: &ZPoly,
    square: Option<&ZPoly>,
    lo: &Rat,
    hi: &Rat,
) -> Result<RootIter, SolverError> {
    if p.is_zero() {
        return Err(SolverError::IdenticallyZero);
    }
    if lo >= hi {
        return Err(SolverError::EmptyInterval);
    }
    let sf = p.squarefree_part_given(square);
    Ok(RootIter::new(SignProbe::shared(sf), lo, hi))
}

/// `true` when `p` has a root in `[lo, hi]` (exactly decided).
pub fn has_root_in(p: &ZPoly, lo: &Rat, hi: &Rat) -> Result<bool, SolverError> {
    Ok(isolate(p, lo, hi)?.next().is_some())
}

#[cfg(test)]
mod tests;
