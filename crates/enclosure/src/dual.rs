//! Sin and cos of [`Dual`] numbers (the type itself lives in `ccd-arith`).

use crate::trig::Trig;
pub use ccd_arith::Dual;
use ccd_arith::Rat;

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
    use ccd_arith::{Interval, RingOps};

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
