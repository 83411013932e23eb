//! # ccd-exact-arith
//!
//! The exact arithmetic behind Algorithm 1 (`ccd-algorithm`): every
//! contact instant isolated with exact rational bounds, every state decided
//! by exact signs ([`Exact`], an [`ccd_algorithm::Oracle`]).
//!
//! * set-up: `f(λ; u)` from the placements (`ccd-motion`), refused above
//!   [`MAX_EXACT_BITS`];
//! * `sr0`'s roots from its certified `f64` Bernstein coefficients
//!   ([`certified_bernstein`], proven error bounds) where that
//!   filter decides, otherwise from the exact isolation of the formed `sr0`
//!   (or `sr11` when `sr0 ≡ 0`);
//! * the signs of `sr22, sr20, sr11, sr10` at a root from `f`'s
//!   coefficients (module `signs`: the closed forms over intervals, dual
//!   numbers and exact dual integers), never forming those polynomials;
//! * the contact point and normal at each contact (module `geometry`).

#![warn(missing_docs)]

mod filter;
mod geometry;
mod oracle;
mod signs;

pub use filter::certified_bernstein;
pub use oracle::{exact_bits, symbolic, Exact, ExactRoot, MAX_EXACT_BITS};
pub use signs::ClosedForm;
