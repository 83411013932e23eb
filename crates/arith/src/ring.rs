//! The algebra the generic algorithms run over.
//!
//! [`RingOps`]: addition, multiplication and division by small integers:
//! enough for the closed forms of Section 4, quadric matrices and
//! `det(λA + B)`. Exact rings, floating-point numbers, intervals (where
//! every operation encloses the exact result) and dual numbers all have it,
//! so one routine serves the exact, float and interval paths.
//!
//! [`Ring`]: an exact [`RingOps`] with exact division where it divides, for
//! fraction-free elimination (subresultant determinants).

use crate::{Int, Rat};

/// Ring operations. The method names differ from `add`, `mul` so that they
/// do not collide with the operator traits the types also implement.
pub trait RingOps: Clone + std::fmt::Debug {
    /// The additive identity.
    fn zero() -> Self;
    /// The multiplicative identity.
    fn one() -> Self;
    /// The image of a machine integer.
    fn from_i64(v: i64) -> Self;
    /// `self` is known to be exactly zero (lets sparse products skip work;
    /// `false` is always a safe answer for approximate types).
    fn is_zero(&self) -> bool;
    /// `self + o`.
    fn plus(&self, o: &Self) -> Self;
    /// `self − o`.
    fn minus(&self, o: &Self) -> Self;
    /// `self · o`.
    fn times(&self, o: &Self) -> Self;
    /// `−self`.
    fn negated(&self) -> Self;
    /// `self / k` for a small nonzero integer `k`; in an exact ring the
    /// caller guarantees that `k` divides `self`.
    fn div_small(&self, k: i64) -> Self;
    /// `self ← self + x·y`, or `self ← self − x·y` when `negate`: the
    /// multiply-accumulate of dot products and determinant expansions.
    /// The default is exactly `self.plus(&x.times(y))` (resp. `minus`), so
    /// approximate types round as before; an exact type with fixed storage
    /// may override it to accumulate in place (same value: exactness), and
    /// an approximate one to skip work that changes no bit (`Interval`
    /// skips a zero factor, whose product its `plus` adds as the identity).
    fn add_product(&mut self, x: &Self, y: &Self, negate: bool) {
        let term = x.times(y);
        *self = if negate {
            self.minus(&term)
        } else {
            self.plus(&term)
        };
    }
    /// `self ← x·y`, over what `self` held. The default is exactly
    /// `*self = x.times(y)`; a type with large fixed storage may override it
    /// to build the product where `self` lives (same value: exactness),
    /// which a product returned by value cannot always do (the compiler
    /// builds it in a temporary and copies it over).
    fn set_product(&mut self, x: &Self, y: &Self) {
        *self = x.times(y);
    }
    /// `self ← self + o`. The default is exactly `*self = self.plus(o)`;
    /// overridden like [`RingOps::set_product`].
    fn plus_assign(&mut self, o: &Self) {
        *self = self.plus(o);
    }
    /// `self · self`. The default is exactly `self.times(self)`; an exact
    /// type may override it with a cheaper squaring (same value:
    /// exactness).
    fn squared(&self) -> Self {
        self.times(self)
    }
}

/// An exact commutative ring with exact division where it divides.
pub trait Ring: RingOps + PartialEq {
    /// `self / o` where the caller knows `o` divides `self` exactly
    /// (fraction-free elimination relies on it).
    fn div_exact(&self, o: &Self) -> Self;
}

/// Implements [`RingOps`] for a type whose references have the `+ − ×`
/// and unary `−` operators, given its constants and its small division.
#[macro_export]
macro_rules! ring_ops_via_operators {
    ($t:ty, zero: $zero:expr, one: $one:expr, from_i64: |$v:ident| $from:expr, is_zero: |$z:ident| $isz:expr, div_small: |$a:ident, $k:ident| $div:expr $(, squared: |$s:ident| $sq:expr)? $(, add_product: |$acc:ident, $x:ident, $y:ident, $neg:ident| $ap:expr)?) => {
        impl $crate::RingOps for $t {
            fn zero() -> Self {
                $zero
            }
            fn one() -> Self {
                $one
            }
            fn from_i64($v: i64) -> Self {
                $from
            }
            fn is_zero(&self) -> bool {
                let $z = self;
                $isz
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
            fn div_small(&self, $k: i64) -> Self {
                let $a = self;
                $div
            }
            $(
                fn squared(&self) -> Self {
                    let $s = self;
                    $sq
                }
            )?
            $(
                fn add_product(&mut self, $x: &Self, $y: &Self, $neg: bool) {
                    let $acc = self;
                    $ap
                }
            )?
        }
    };
}

ring_ops_via_operators!(Int, zero: Int::zero(), one: Int::one(), from_i64: |v| Int::from_i64(v), is_zero: |x| Int::is_zero(x), div_small: |a, k| a.div_exact(&Int::from_i64(k)), squared: |x| x.pow(2));
ring_ops_via_operators!(Rat, zero: Rat::zero(), one: Rat::one(), from_i64: |v| Rat::from(v), is_zero: |x| Rat::is_zero(x), div_small: |a, k| a / &Rat::from(k));
ring_ops_via_operators!(f64, zero: 0.0, one: 1.0, from_i64: |v| v as f64, is_zero: |x| *x == 0.0, div_small: |a, k| a / k as f64);

impl Ring for Int {
    fn div_exact(&self, o: &Self) -> Self {
        Int::div_exact(self, o)
    }
}

impl Ring for Rat {
    fn div_exact(&self, o: &Self) -> Self {
        self / o
    }
}
