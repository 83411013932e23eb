//! [`Dual`]: forward-mode dual numbers `v + d·ε` (`ε² = 0`) over any
//! [`RingOps`], so the same generic quadric and subresultant code
//! (`ccd-quadric`, `ccd-subres`) yields a quantity and its derivative in t.
//! Over intervals, `d` encloses the derivative over the whole box the value
//! was evaluated on (the chain rule applied to enclosures).

use crate::trig::Trig;
use ccd_arith::{Rat, RingOps};

/// The dual number `v + d·ε`.
#[derive(Clone, Debug, PartialEq)]
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

impl<T: Trig> Trig for Dual<T> {
    fn constant(q: &Rat, prec: u32) -> Self {
        Dual::constant_of(T::constant(q, prec))
    }
    fn sqrt_rat(q: &Rat, prec: u32) -> Self {
        Dual::constant_of(T::sqrt_rat(q, prec))
    }
    /// `sin(v + dε) = sin v + cos v·d ε`, `cos(v + dε) = cos v − sin v·d ε`.
    fn sin_cos(&self) -> (Self, Self) {
        let (s, c) = self.v.sin_cos();
        let ds = c.times(&self.d);
        let dc = s.times(&self.d).negated();
        (Dual { v: s, d: ds }, Dual { v: c, d: dc })
    }
    fn approx_value(&self) -> f64 {
        self.v.approx_value()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Interval;

    #[test]
    fn derivatives_of_products_and_trig() {
        // f(t) = t³·sin(2t); f'(t) = 3t²·sin 2t + 2t³·cos 2t
        let t = Dual::variable(Interval::point(0.7));
        let two_t = t.times(&Dual::from_i64(2));
        let (s, _) = two_t.sin_cos();
        let f = t.times(&t).times(&t).times(&s);
        let x: f64 = 0.7;
        let want = 3.0 * x * x * (2.0 * x).sin() + 2.0 * x.powi(3) * (2.0 * x).cos();
        assert!(f.d.lo <= want + 1e-14 && want - 1e-14 <= f.d.hi, "{f:?}");
        assert!(f.d.width() < 1e-14);
        // Exact rationals: d/dt (t² − 3t)/2 at t = 5 is (2·5 − 3)/2.
        let r = Dual::variable(Rat::from(5));
        let g = r
            .times(&r)
            .minus(&r.times(&Rat::from(3).into_dual()))
            .div_small(2);
        assert_eq!(g.d, Rat::from_frac(7, 2));
    }

    trait IntoDual: Sized {
        fn into_dual(self) -> Dual<Self>;
    }
    impl IntoDual for Rat {
        fn into_dual(self) -> Dual<Rat> {
            Dual::constant_of(self)
        }
    }
}
