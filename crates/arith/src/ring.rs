//! [`Ring`]: the exact commutative rings the generic algorithms (signed
//! subresultants, determinants) run over: integers, rationals, polynomials.

use crate::{Int, Rat};

/// An exact commutative ring with exact division where it divides.
///
/// The methods have their own names (not `add`, `mul`) so that they do not
/// collide with the operator traits the concrete types also implement.
pub trait Ring: Clone + PartialEq + std::fmt::Debug {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The image of a machine integer.
    fn from_i64(v: i64) -> Self;
    /// `self == 0`.
    fn is_zero(&self) -> bool;
    /// `self + o`.
    fn plus(&self, o: &Self) -> Self;
    /// `self − o`.
    fn minus(&self, o: &Self) -> Self;
    /// `self · o`.
    fn times(&self, o: &Self) -> Self;
    /// `−self`.
    fn negated(&self) -> Self;
    /// `self / o` where the caller knows `o` divides `self` exactly
    /// (fraction-free elimination relies on it).
    fn div_exact(&self, o: &Self) -> Self;
}

impl Ring for Int {
    fn zero() -> Self {
        Int::zero()
    }
    fn one() -> Self {
        Int::one()
    }
    fn from_i64(v: i64) -> Self {
        Int::from_i64(v)
    }
    fn is_zero(&self) -> bool {
        Int::is_zero(self)
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn negated(&self) -> Self {
        -self
    }
    fn div_exact(&self, o: &Self) -> Self {
        Int::div_exact(self, o)
    }
}

impl Ring for Rat {
    fn zero() -> Self {
        Rat::zero()
    }
    fn one() -> Self {
        Rat::one()
    }
    fn from_i64(v: i64) -> Self {
        Rat::from(v)
    }
    fn is_zero(&self) -> bool {
        Rat::is_zero(self)
    }
    fn plus(&self, o: &Self) -> Self {
        self + o
    }
    fn minus(&self, o: &Self) -> Self {
        self - o
    }
    fn times(&self, o: &Self) -> Self {
        self * o
    }
    fn negated(&self) -> Self {
        -self
    }
    fn div_exact(&self, o: &Self) -> Self {
        self / o
    }
}
