//! What a query asks for.

/// How the roots and signs of a rational scene are computed (scenes with a
/// non-rational motion always take the interval path).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Arithmetic {
    /// Exact and certified: every sign proven (the default).
    #[default]
    Exact,
    /// The paper's Table 3 setting: `f64` Bernstein subdivision after the
    /// exact set-up of `f(λ; t)`. Fast, NOT certified: every instant is
    /// marked `certified: false`.
    Float,
}

/// What a query asks for.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Enclosures of contact instants get `hi − lo <= 10^(−digits)·(t1 − t0)`
    /// (exact arithmetic; the float mode stops at `f64` resolution).
    pub digits: u32,
    /// Stop at the earliest instant at which the bodies are not separate.
    pub first_contact_only: bool,
    /// Exact (certified) or float.
    pub arithmetic: Arithmetic,
    /// Compute the contact point and normal of each contact
    /// (`Outcome::geometry`); `false` leaves it empty (default `true`).
    pub contact_geometry: bool,
    /// Pairs that only translate along straight lines: answer by the
    /// certified ray cast of `ccd-raycast` where it proves everything
    /// asked (instants then have `f64` ends), else by Algorithm 1
    /// (default `false`: every answer from Algorithm 1).
    pub raycast: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            digits: 15,
            first_contact_only: false,
            arithmetic: Arithmetic::Exact,
            contact_geometry: true,
            raycast: false,
        }
    }
}

impl Options {
    /// Largest `digits` accepted (refinement cost grows with it).
    pub const MAX_DIGITS: u32 = 1000;
}
