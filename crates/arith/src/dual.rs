//! [`Dual`]: forward-mode dual numbers `v + d·ε` (`ε² = 0`) over any
//! [`RingOps`], so the same generic quadric and subresultant code
//! (`ccd-quadric`, `ccd-subres`) yields a quantity and its derivative in t.
//! Over intervals, `d` encloses the derivative over the whole box the value
//! was evaluated on (the chain rule applied to enclosures); nested,
//! `Dual<Dual<T>>` carries second derivatives in `d.d` ([`crate::Jet2`] is
//! the same with 6 instead of 9 products).

use crate::RingOps;

/// The dual number `v + d·ε`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dual<T> {
    /// Value.
    pub v: T,
    /// Derivative.
    pub d: T,
}

impl<T: RingOps> Dual<T> {
    /// The independent variable at `v` (derivative 1).
    pub fn variable(v: T) -> Dual<T> {
        Dual { v, d: T::one() }
    }
    /// A constant (derivative 0).
    pub fn constant_of(v: T) -> Dual<T> {
        Dual { v, d: T::zero() }
    }
}

impl<T: RingOps> RingOps for Dual<T> {
    fn zero() -> Self {
        Dual::constant_of(T::zero())
    }
    fn one() -> Self {
        Dual::constant_of(T::one())
    }
    fn from_i64(v: i64) -> Self {
        Dual::constant_of(T::from_i64(v))
    }
    fn is_zero(&self) -> bool {
        self.v.is_zero() && self.d.is_zero()
    }
    fn plus(&self, o: &Self) -> Self {
        Dual {
            v: self.v.plus(&o.v),
            d: self.d.plus(&o.d),
        }
    }
    fn minus(&self, o: &Self) -> Self {
        Dual {
            v: self.v.minus(&o.v),
            d: self.d.minus(&o.d),
        }
    }
    fn times(&self, o: &Self) -> Self {
        let d = if self.d.is_zero() {
            self.v.times(&o.d)
        } else if o.d.is_zero() {
            self.d.times(&o.v)
        } else {
            self.v.times(&o.d).plus(&self.d.times(&o.v))
        };
        Dual {
            v: self.v.times(&o.v),
            d,
        }
    }
    fn negated(&self) -> Self {
        Dual {
            v: self.v.negated(),
            d: self.d.negated(),
        }
    }
    fn div_small(&self, k: i64) -> Self {
        Dual {
            v: self.v.div_small(k),
            d: self.d.div_small(k),
        }
    }
}
