//! Evaluating a [`ZPoly`]: at integers and rationals (exactly, or
//! homogeneously without a gcd, with or without the derivative), its exact
//! sign at a rational point, the rational root theorem filter, and a
//! certified interval enclosure.

use super::ZPoly;
use ccd_arith::{Int, Interval, Rat};

/// `Σ_i c_i x^i y^(n−i)` with `n = len − 1`: the homogenized Horner scheme
/// (`0` for an empty slice). With `y = q > 0` and `x = p` it is
/// `q^n·f(p/q)` for `f = Σ c_i t^i`, so it carries the exact sign of `f(p/q)`.
pub(crate) fn hom_horner(c: &[Int], x: &Int, y: &Int) -> Int {
    hom_horner_impl::<false>(c, x, y).0
}

/// [`hom_horner`] together with the homogeneous derivative
/// `Σ_{i≥1} i·c_i x^(i−1) y^(n−i) = y^(n−1)·f′(x/y)`, in one pass and
/// without forming `f′`: the Horner partial sums `A_i = y^(n−i)·B_i`
/// (`B_i = Σ_{l≥i} c_l (x/y)^(l−i)`) give `y^(n−1)·f′(x/y) = Σ_{i≥1} A_i x^(i−1)`,
/// a second Horner run in `x` over them.
pub(crate) fn hom_horner_with_derivative(c: &[Int], x: &Int, y: &Int) -> (Int, Int) {
    hom_horner_impl::<true>(c, x, y)
}

fn hom_horner_impl<const DERIVATIVE: bool>(c: &[Int], x: &Int, y: &Int) -> (Int, Int) {
    let Some((last, rest)) = c.split_last() else {
        return (Int::zero(), Int::zero());
    };
    if x.is_zero() {
        // At 0 (the start of the span): `c_0·y^n` and `c_1·y^(n−1)`, the
        // only terms without a factor `x`, with no Horner pass.
        let n = rest.len() as u32;
        let power = |e: u32| if y.is_one() { Int::one() } else { y.pow(e) };
        let value = &c[0] * &power(n);
        let slope = match (DERIVATIVE, c.get(1)) {
            (true, Some(c1)) => c1 * &power(n - 1),
            _ => Int::zero(),
        };
        return (value, slope);
    }
    let mut acc = last.clone();
    let mut dacc = Int::zero();
    // acc ← acc·x + term, with `add` adding the term in place (and the
    // derivative's Horner run on the old acc first).
    let mut step = |acc: &mut Int, add: &dyn Fn(&mut Int)| {
        if DERIVATIVE {
            dacc = &dacc * x + &*acc;
        }
        *acc = &*acc * x;
        add(acc);
    };
    let k = y.trailing_zeros().unwrap_or(0);
    if y.is_one() {
        for ci in rest.iter().rev() {
            step(&mut acc, &|a| *a += ci);
        }
    } else if y.bits() == k + 1 {
        // y = 2^k (every dyadic point): c_i·y^(n−i) is a shift, so each
        // step costs time linear in the size of the numbers, not a product.
        for (j, ci) in rest.iter().rev().enumerate() {
            step(&mut acc, &|a| *a += ci.shl(k * (j as u64 + 1)));
        }
    } else {
        let mut ypow = Int::one();
        for ci in rest.iter().rev() {
            ypow *= y;
            let yp = &ypow;
            step(&mut acc, &|a| a.add_mul(ci, yp));
        }
    }
    (acc, dacc)
}

impl ZPoly {
    /// `p(x)` by Horner's scheme.
    pub fn eval_int(&self, x: &Int) -> Int {
        hom_horner(&self.c, x, &Int::one())
    }
    /// `p(x)` exactly: `Σ c_i a^i b^(n−i) / b^n` for `x = a/b`.
    pub fn eval_rat(&self, x: &Rat) -> Rat {
        let n = self.c.len().saturating_sub(1) as u32;
        let num = hom_horner(&self.c, x.numer(), x.denom());
        Rat::new(num, x.denom().pow(n)).expect("a power of a positive denominator is nonzero")
    }
    /// `p(x)·b^n` for `x = a/b` (`b > 0`, `n` the degree) as the integer
    /// `Σ c_i a^i b^(n−i)`: the exact value without a gcd; for a dyadic
    /// `x = a/2^k` it is `p(x)·2^(k·n)`.
    pub fn eval_homogeneous(&self, x: &Rat) -> Int {
        hom_horner(&self.c, x.numer(), x.denom())
    }
    /// `(bⁿ·p(x), bⁿ⁻¹·p′(x))` for `x = a/b`, `n = deg p`: the homogeneous
    /// value and derivative in one Horner pass, without forming `p′`.
    ///
    /// ```
    /// use ccd_arith::{Int, Rat};
    /// use ccd_poly::ZPoly;
    /// let p = ZPoly::from_i64s(&[1, 0, 3]); // 3t² + 1
    /// let x = Rat::from_frac(1, 2);
    /// // 4·p(1/2) = 7, 2·p′(1/2) = 2·3 = 6
    /// assert_eq!(p.eval_homogeneous_with_derivative(&x), (Int::from(7), Int::from(6)));
    /// ```
    pub fn eval_homogeneous_with_derivative(&self, x: &Rat) -> (Int, Int) {
        hom_horner_with_derivative(&self.c, x.numer(), x.denom())
    }
    /// Whether `x` passes the rational root theorem for `p = Σ cᵢ tⁱ`: a
    /// root `a/b` in lowest terms has `b | c_n` and `a | c_0`. `false` proves
    /// `p(x) ≠ 0` with two divisibility tests instead of an evaluation.
    ///
    /// ```
    /// use ccd_arith::Rat;
    /// use ccd_poly::ZPoly;
    /// let p = ZPoly::from_i64s(&[-2, 3]); // 3t − 2
    /// assert!(p.admits_rational_root(&Rat::from_frac(2, 3)));
    /// assert!(!p.admits_rational_root(&Rat::from_frac(1, 2)));
    /// assert!(!p.admits_rational_root(&Rat::zero()));
    /// ```
    pub fn admits_rational_root(&self, x: &Rat) -> bool {
        let (Some(first), Some(last)) = (self.c.first(), self.c.last()) else {
            return true;
        };
        if x.numer().is_zero() {
            return first.is_zero();
        }
        last.is_divisible_by(x.denom()) && (first.is_zero() || first.is_divisible_by(x.numer()))
    }
    /// The exact sign of `p(x)`: the sign of the integer `Σ c_i a^i b^(n−i)`
    /// for `x = a/b`, `b > 0` (no gcds, no rationals).
    pub fn sign_at(&self, x: &Rat) -> i32 {
        hom_horner(&self.c, x.numer(), x.denom()).signum()
    }
    /// A certified enclosure of `p(x)` for every `x` in the interval: Horner's
    /// scheme in outward-rounded interval arithmetic. Coefficients wider than
    /// `f64` are first scaled by a common `2^(−s)` and the result scaled back
    /// (an overflowing bound is kept finite on the side that must stay finite,
    /// so the sign survives); it may be wide.
    pub fn eval_interval(&self, x: Interval) -> Interval {
        if self.c.is_empty() {
            return Interval::point(0.0);
        }
        let s = self.max_bits().saturating_sub(900);
        let mut acc = Interval::point(0.0);
        for ci in self.c.iter().rev() {
            acc = acc * x + Interval::from_int_scaled(ci, s as i64);
        }
        scale_up(acc, s)
    }
}

/// `x·2^s` as a certified enclosure: a bound that overflows is replaced by
/// `±f64::MAX` on the side where it must stay a valid bound, and `±∞` on
/// the other.
fn scale_up(x: Interval, s: u64) -> Interval {
    if s == 0 {
        return x;
    }
    let f = |v: f64| {
        let mut r = v;
        let mut k = s;
        while k > 0 && r.is_finite() {
            let step = k.min(1000);
            r *= 2f64.powi(step as i32);
            k -= step;
        }
        r
    };
    let (lo, hi) = (f(x.lo), f(x.hi));
    // A finite lower bound that overflowed to +∞ stays a valid bound as MAX.
    let lo = if lo == f64::INFINITY { f64::MAX } else { lo };
    let hi = if hi == f64::NEG_INFINITY {
        f64::MIN
    } else {
        hi
    };
    Interval::new(lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{f64_to_rat, rat, zpoly};
    use proptest::prelude::*;

    #[test]
    fn interval_evaluation_of_huge_coefficients_keeps_the_sign() {
        let big = Int::one().shl(3000);
        let p = ZPoly::new(vec![-&big, Int::zero(), big.clone()]); // 2^3000 (t² − 1)
        let at = |x: f64| p.eval_interval(Interval::point(x));
        assert_eq!(at(2.0).sign(), Some(1));
        assert_eq!(at(0.5).sign(), Some(-1));
        assert!(at(1.0).contains_zero());
        assert_eq!(
            ZPoly::zero().eval_interval(Interval::point(3.0)).sign(),
            Some(0)
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn evaluation_is_consistent(p in zpoly(10, 200), q in zpoly(6, 100), x in rat(), n in any::<i32>()) {
            let v = p.eval_rat(&x);
            prop_assert_eq!(p.sign_at(&x), v.signum());
            prop_assert_eq!(Rat::from_int(p.eval_int(&Int::from(n))), p.eval_rat(&Rat::from(n as i64)));
            prop_assert_eq!((&p * &q).eval_rat(&x), &v * &q.eval_rat(&x));
            // Product rule and the Taylor coefficient: [p(t + c)]_1 = p'(c).
            prop_assert_eq!((&p * &q).derivative(), &(&p.derivative() * &q) + &(&p * &q.derivative()));
            let c = Int::from(n % 1000);
            prop_assert_eq!(p.taylor_shift(&c).coeff(1), p.derivative().eval_int(&c));
            prop_assert_eq!(p.taylor_shift(&c).eval_rat(&x), p.eval_rat(&(&x + &Rat::from_int(c))));
            let iv = p.eval_interval(ccd_arith::Interval::from_rat(&x));
            if iv.lo.is_finite() { prop_assert!(f64_to_rat(iv.lo) <= v); }
            if iv.hi.is_finite() { prop_assert!(v <= f64_to_rat(iv.hi)); }
            let f = p.to_f64();
            prop_assert_eq!(f.len(), p.coeffs().len());
        }

        /// The rational root theorem filter never rejects a root, and a
        /// rejection always means a nonzero value.
        #[test]
        fn rational_root_filter_is_sound(q in zpoly(6, 40), a in -50i64..50, b in 1i64..50) {
            let x = Rat::from_frac(a, b);
            let root = ZPoly::from_i64s(&[-a, b]) * q.clone();
            prop_assert!(q.is_zero() || root.admits_rational_root(&x));
            if !q.admits_rational_root(&x) {
                prop_assert!(q.sign_at(&x) != 0);
            }
        }

        /// At 0 (no Horner pass): the sums `Σ c_i·0^i·y^(n−i)` and
        /// `Σ i·c_i·0^(i−1)·y^(n−i)` term by term, for any `y` (reduced
        /// `0/y` or not).
        #[test]
        fn homogeneous_values_at_zero(p in zpoly(9, 60), y in 1i64..300) {
            let (zero, y) = (Int::zero(), Int::from(y));
            let n = p.coeffs().len().saturating_sub(1) as u32;
            let term = |i: u32, e: u32, c: &Int| c * &zero.pow(e) * y.pow(n - i);
            let value: Int = p.coeffs().iter().enumerate().map(|(i, c)| term(i as u32, i as u32, c)).fold(Int::zero(), |a, b| &a + &b);
            let slope: Int = p.coeffs().iter().enumerate().skip(1)
                .map(|(i, c)| term(i as u32, i as u32 - 1, &(c * &Int::from(i as i64))))
                .fold(Int::zero(), |a, b| &a + &b);
            prop_assert_eq!(hom_horner_with_derivative(p.coeffs(), &zero, &y), (value.clone(), slope));
            prop_assert_eq!(hom_horner(p.coeffs(), &zero, &y), value);
        }

        /// One pass gives the homogeneous value and the homogeneous value of
        /// the derivative, at integer, dyadic and general rational points.
        #[test]
        fn value_with_derivative_matches_separate_passes(p in zpoly(9, 60), a in -300i64..300, b in 1i64..300, dyadic in proptest::bool::ANY) {
            let x = if dyadic { Rat::dyadic(Int::from(a), (b % 40) as u64) } else { Rat::from_frac(a, b) };
            prop_assert_eq!(
                p.eval_homogeneous_with_derivative(&x),
                (p.eval_homogeneous(&x), p.derivative().eval_homogeneous(&x))
            );
        }
    }
}
