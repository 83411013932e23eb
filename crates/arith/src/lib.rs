//! Exact arithmetic for ccd-exact: big integers ([`Int`]), rationals
//! ([`Rat`]), outward-rounded `f64` intervals ([`Interval`]) and the [`Ring`]
//! trait the generic algorithms are written against.
//!
//! The big-integer kernel is dashu (pure Rust, numbers up to 128 bits
//! inline: 11–23 % fewer instructions per query than num-bigint, see
//! docs/table4.md) by default, num-bigint (pure Rust) with the `num-kernel`
//! feature (or without the default features), and GMP (through rug) with
//! the `gmp` feature, which wins over both; nothing above this crate can
//! tell the difference except by speed.

#![warn(missing_docs)]

mod approx;
#[cfg(any(feature = "gmp", all(feature = "dashu", not(feature = "num-kernel"))))]
mod backend_dashu;
#[cfg(feature = "gmp")]
mod backend_gmp;
#[cfg(all(
    not(feature = "gmp"),
    any(not(feature = "dashu"), feature = "num-kernel")
))]
mod backend_num;
mod backend_refops;
mod big_interval;
mod convert;
mod descartes;
mod dual;
mod dwball;
mod dyadic;
mod int;
mod interval;
mod jet2;
mod rat;
mod ring;
mod small;

pub use approx::Approx;
pub use big_interval::BigInterval;
pub use convert::NotFinite;
pub use descartes::sign_variations;
pub use dual::Dual;
pub use dwball::DwBall;
pub use dyadic::Dyadic;
pub use int::Int;
pub use interval::Interval;
pub use jet2::Jet2;
pub use rat::text::{excerpt, ParseRatError};
pub use rat::Rat;
pub use ring::{Ring, RingOps};
pub use small::{gcd_u128, SmallInt};

// The big-integer kernel of this build, whose functions `Int` wraps.
#[cfg(any(feature = "gmp", all(feature = "dashu", not(feature = "num-kernel"))))]
use backend_dashu as kernel;
#[cfg(all(
    not(feature = "gmp"),
    any(not(feature = "dashu"), feature = "num-kernel")
))]
use backend_num as kernel;

/// The name of the big-integer kernel in this build: `"num-bigint"`,
/// `"dashu"` or `"gmp"` (dashu, with long products, gcds and divisions in
/// GMP).
pub const BACKEND: &str = if cfg!(feature = "gmp") {
    "gmp"
} else if cfg!(feature = "dashu") && !cfg!(feature = "num-kernel") {
    "dashu"
} else {
    "num-bigint"
};
