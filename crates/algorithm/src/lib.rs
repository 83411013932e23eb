//! # ccd-algorithm
//!
//! Algorithm 1 of Jia, Choi, Mourrain & Wang, *An algebraic approach to
//! continuous collision detection for ellipsoids* (CAGD 2011, Section 5),
//! written once, generic over the arithmetic that answers its questions
//! ([`Oracle`]):
//!
//! * exact (`ccd-exact-arith`): every sign proven, instants with exact
//!   rational enclosures refinable to any width;
//! * float (`ccd-float`): the paper's `f64` setting, nothing certified;
//! * interval (`ccd-interval`): helical motions, certified where the
//!   enclosures decide, gaps where the effort budget ends.
//!
//! [`run`] takes the state at `t0`, chooses the branch (Theorems 5.2,
//! 5.4–5.6; typed [`ccd_timeline::Branch`]), walks the candidate roots with
//! the touch test of Theorem 3.10(2) ([`possible_with`]: the decision tree
//! over sets of signs, so one test serves exact signs and enclosures), and
//! lays out the timeline (Theorem 5.1).

#![warn(missing_docs)]

mod assemble;
mod decide;
mod error;
mod options;
mod oracle;
mod run;

pub use assemble::sample_between;
pub use decide::{possible_with, Possible, SignSet, Signs, VarSet};
pub use error::CcdError;
pub use options::{Arithmetic, Options};
pub use oracle::{time_on, At, Candidates, Decided, Found, Item, Oracle, Vanishing};
pub use run::{run, state_at};
