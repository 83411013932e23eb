//! Exact arithmetic for ccd-exact: big integers ([`Int`]), rationals
//! ([`Rat`]), outward-rounded `f64` intervals ([`Interval`]) and the [`Ring`]
//! trait the generic algorithms are written against.
//!
//! The big-integer kernel is num-bigint (pure Rust) by default and GMP
//! (through rug) with the `gmp` feature; nothing above this crate can tell
//! the difference except by speed.

#![warn(missing_docs)]

mod approx;
#[cfg(feature = "gmp")]
mod backend_gmp;
#[cfg(not(feature = "gmp"))]
mod backend_num;
mod convert;
mod dual;
mod int;
mod interval;
mod rat;
mod ring;

pub use approx::Approx;
pub use convert::NotFinite;
pub use dual::Dual;
pub use int::Int;
pub use interval::Interval;
pub use rat::text::{excerpt, ParseRatError};
pub use rat::Rat;
pub use ring::{Ring, RingOps};

/// The name of the big-integer kernel in this build: `"num-bigint"` or `"gmp"`.
pub const BACKEND: &str = if cfg!(feature = "gmp") {
    "gmp"
} else {
    "num-bigint"
};
