//! Signed subresultant sequences (Sylvester–Habicht) over any exact ring,
//! and the closed forms for the quartic characteristic polynomial of two
//! ellipsoids.
//!
//! This implements Sections 2–4 of Jia, Choi, Mourrain & Wang, "An
//! algebraic approach to continuous collision detection for ellipsoids"
//! (CAGD 28, 2011):
//!
//! * [`determinant`] (module `det`): fraction-free Bareiss determinants over
//!   any [`ccd_arith::Ring`] — integers, rationals, polynomials in t;
//! * [`sylvester_habicht`], [`signed_subresultant`],
//!   [`signed_subresultants`], [`subresultants_with_derivative`] (module
//!   `habicht`): Definition 2.2, reproducing eq. (2) exactly, and the
//!   gcd property of Lemma 2.3;
//! * [`closed_forms`], [`closed_form`] (module `closed_forms`): the
//!   Section 4 formulas for the five quantities `sr22, sr20, sr11, sr10,
//!   sr0` of Theorem 3.10, in a homogeneous division-free form valid for
//!   any leading coefficient.
//!
//! The decision of Theorem 3.10 / Table 2 over their signs is the crate
//! `ccd-classify`.
//!
//! Everything here depends only on `ccd-arith`.

#![warn(missing_docs)]

mod closed_forms;
mod det;
#[cfg(any(test, feature = "fixtures"))]
#[doc(hidden)]
pub mod fixtures;
mod habicht;

pub use closed_forms::{
    closed_form, closed_forms, homogeneous_degree, isobaric_weight, Quantity, QuarticInvariants,
};
pub use det::determinant;
pub use habicht::{
    derivative, signed_subresultant, signed_subresultants, subresultants_with_derivative,
    sylvester_habicht,
};
