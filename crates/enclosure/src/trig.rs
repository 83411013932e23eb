//! Rigorous enclosures of sin and cos over intervals, for `f64`
//! [`Interval`]s and multi-precision [`BigInterval`]s, by one generic code
//! path.
//!
//! # Method
//! * **π** is enclosed by Machin's formula `π = 16·atan(1/5) − 4·atan(1/239)`
//!   in fixed point: `atan(1/m)·2^N` is the alternating series
//!   `Σ (−1)^k ⌊2^N / ((2k+1)·m^(2k+1))⌋`, each floored term off by less
//!   than 1 and the tail (after the first zero term) by less than 1, so
//!   with `K` terms the sum is within `K + 1` of `atan(1/m)·2^N`
//!   ([`pi_enclosure`], cached).
//! * **Argument reduction** of a point `x`: `k ≈ x/(π/2)` (any integer is
//!   correct, a near one keeps `r` small) and `r = x − k·π/2` enclosed —
//!   in `f64` by the Cody–Waite split `π/2 = P1 + P2 + P3` (P1, P2 with 30
//!   significant bits so `k·P1`, `k·P2` are exact for `|k| < 2^22`, P3 an
//!   interval), beyond that and in multi-precision with π to
//!   `prec + bits(k) + 16` bits; then `sin x`, `cos x` are `±sin r`,
//!   `±cos r` by `k mod 4`.
//! * **Taylor** polynomials in `r` with the Lagrange remainder: every
//!   derivative of sin and cos is bounded by 1, so
//!   `|sin r − Σ_{j odd < J} (−1)^((j−1)/2) r^j/j!| <= |r|^J/J!` for the
//!   first odd `J` left out (likewise for cos with even `J`); `J` is chosen
//!   so the bound is below `2^−(prec+8)`.
//! * **Intervals** `X = [a, b]`: sin and cos are enclosed by the hull of
//!   their enclosures at `a` and `b` and of the extreme values ±1 at every
//!   `j·π/2` whose enclosure meets `X` (j even: cos = ±1, j odd: sin = ±1),
//!   since between consecutive such points both are monotone. Intervals
//!   longer than about 2π get `[−1, 1]`.

use crate::real::Real;
use ccd_arith::{BigInterval, Dyadic, Int, Interval, Rat, RingOps};
use std::sync::{Mutex, OnceLock};

/// Guard bits of the Machin sums beyond the bits asked for.
const PI_GUARD_BITS: u32 = 32;

/// `(Σ, K)`: `Σ_{k<K} (−1)^k ⌊2^N/((2k+1)·m^(2k+1))⌋` over the nonzero
/// terms; `atan(1/m)·2^N ∈ [Σ − K − 1, Σ + K + 1]`.
fn atan_inv_fixed(m: u64, n: u64) -> (Int, i64) {
    let one = Int::one().shl(n);
    let m_int = Int::from_u64(m);
    let m2 = &m_int * &m_int;
    let mut power = m_int; // m^(2k+1)
    let mut sum = Int::zero();
    let mut k: i64 = 0;
    loop {
        let den = &power * &Int::from_i64(2 * k + 1);
        let term = one.div_floor(&den);
        if term.is_zero() {
            return (sum, k);
        }
        sum = if k % 2 == 0 { sum + term } else { sum - term };
        power = &power * &m2;
        k += 1;
    }
}

/// An enclosure `[lo, hi]` of π with at least `bits` correct bits, as
/// dyadics (cached; recomputed only when more bits are asked for).
pub fn pi_enclosure(bits: u32) -> (Dyadic, Dyadic) {
    static CACHE: OnceLock<Mutex<Option<(u32, Dyadic, Dyadic)>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(None));
    let mut guard = match cache.lock() {
        Ok(g) => g,
        Err(poisoned) => poisoned.into_inner(),
    };
    if let Some((have, lo, hi)) = guard.as_ref() {
        if *have >= bits {
            return (lo.clone(), hi.clone());
        }
    }
    let n = (bits + PI_GUARD_BITS) as u64;
    let (s5, k5) = atan_inv_fixed(5, n);
    let (s239, k239) = atan_inv_fixed(239, n);
    let centre = s5.mul_i64(16) - s239.mul_i64(4);
    let err = Int::from_i64(16 * (k5 + 1) + 4 * (k239 + 1));
    let e = -(n as i64);
    let lo = Dyadic {
        m: &centre - &err,
        e,
    };
    let hi = Dyadic {
        m: &centre + &err,
        e,
    };
    *guard = Some((bits, lo.clone(), hi.clone()));
    (lo, hi)
}

/// The Cody–Waite split of π/2: `(P1, P2, P3)` with `P1`, `P2` exact `f64`s
/// of at most 30 significant bits and `P3` an interval, so that
/// `π/2 ∈ P1 + P2 + P3`.
pub fn half_pi_cody_waite() -> (f64, f64, Interval) {
    static SPLIT: OnceLock<(f64, f64, Interval)> = OnceLock::new();
    *SPLIT.get_or_init(|| {
        let (lo, hi) = pi_enclosure(200);
        let (lo, hi) = (lo.to_rat().mul_pow2(-1), hi.to_rat().mul_pow2(-1));
        let p1 = Rat::from_int(lo.mul_pow2(29).floor()).mul_pow2(-29);
        let rest = &lo - &p1;
        let p2 = Rat::from_int(rest.mul_pow2(59).floor()).mul_pow2(-59);
        let (r_lo, r_hi) = (&(&lo - &p1) - &p2, &(&hi - &p1) - &p2);
        let p3 = Interval::new(Interval::from_rat(&r_lo).lo, Interval::from_rat(&r_hi).hi);
        (p1.to_f64(), p2.to_f64(), p3)
    })
}

/// Taylor enclosures `(sin r, cos r)` for a (small) reduced argument.
fn taylor<R: Real>(r: &R) -> (R, R) {
    let prec = r.precision();
    let rho = r.abs_max();
    let rho_f = rho.approx();
    if !rho_f.is_finite() || rho_f > 64.0 {
        return (R::unit(prec), R::unit(prec));
    }
    // Smallest J with rho^J/J! < 2^−(prec+8) (and J >= 4); J! grows past
    // rho^J quickly for rho <= 64.
    let target = -(prec as f64 + 8.0);
    let mut log_term = 0.0f64; // log2(rho^j / j!)
    let mut j_max = 0u32;
    let lr = rho_f.max(f64::MIN_POSITIVE).log2();
    while j_max < 4 || log_term >= target {
        j_max += 1;
        log_term += lr - (j_max as f64).log2();
        if j_max > 20_000 {
            break;
        }
    }
    let mut sin = R::zero();
    let mut cos = R::zero();
    let mut power = R::one(); // r^j
    for j in 0..j_max {
        if j > 0 {
            power = power.times(r);
        }
        let term = power.times(&R::inv_factorial(j as usize, prec));
        let negative = (j / 2) % 2 == 1;
        let acc = if j % 2 == 0 { &mut cos } else { &mut sin };
        *acc = if negative {
            acc.minus(&term)
        } else {
            acc.plus(&term)
        };
    }
    // Remainders: the first omitted odd (sin) and even (cos) powers.
    let remainder = |j: u32| -> R {
        let mut p = R::one();
        for _ in 0..j {
            p = p.times(&rho);
        }
        p.times(&R::inv_factorial(j as usize, prec)).symmetric()
    };
    let (js, jc) = if j_max % 2 == 1 {
        (j_max, j_max + 1)
    } else {
        (j_max + 1, j_max)
    };
    (
        sin.plus(&remainder(js)).clamp_unit(),
        cos.plus(&remainder(jc)).clamp_unit(),
    )
}

/// `(sin x, cos x)` enclosed for a point (or very narrow) `x`.
fn sin_cos_point<R: Real>(x: &R) -> (R, R) {
    let Some(k) = x.quadrant() else {
        let u = R::unit(x.precision());
        return (u.clone(), u);
    };
    let r = x.sub_half_pi_multiple(&k);
    let (s, c) = taylor(&r);
    match k.mod_u64(4) {
        0 => (s, c),
        1 => (c, s.negated()),
        2 => (s.negated(), c.negated()),
        _ => (c.negated(), s),
    }
}

/// Rigorous enclosures `(sin X, cos X)` of an interval `X` (see the module
/// documentation for the method).
pub fn sin_cos<R: Real>(x: &R) -> (R, R) {
    let prec = x.precision();
    let unit = R::unit(prec);
    if !x.is_finite() {
        return (unit.clone(), unit);
    }
    if x.is_point() {
        return sin_cos_point(x);
    }
    let (a, b) = (x.lower(), x.upper());
    let (Some(ka), Some(kb)) = (a.quadrant(), b.quadrant()) else {
        return (unit.clone(), unit);
    };
    if &kb - &ka > Int::from_i64(6) {
        return (unit.clone(), unit);
    }
    let (sa, ca) = sin_cos_point(&a);
    let (sb, cb) = sin_cos_point(&b);
    let (mut s, mut c) = (sa.hull(&sb), ca.hull(&cb));
    let mut j = &ka - &Int::one();
    let last = &kb + &Int::one();
    while j <= last {
        if R::half_pi_times(&j, prec).intersect(x).is_some() {
            let extreme = |v: &R, at: i64| v.hull(&R::constant(&Rat::from(at), prec));
            match j.mod_u64(4) {
                0 => c = extreme(&c, 1),
                1 => s = extreme(&s, 1),
                2 => c = extreme(&c, -1),
                _ => s = extreme(&s, -1),
            }
        }
        j = &j + &Int::one();
    }
    (s.clamp_unit(), c.clamp_unit())
}

/// The number types the placement code runs over: enclosing ring
/// operations plus rational constants, square roots of rational constants
/// and sin/cos. Implemented by [`Interval`], [`BigInterval`] and
/// [`crate::Dual`] of either (forward-mode derivatives).
pub trait Trig: RingOps {
    /// An enclosure of the rational constant `q`.
    fn constant(q: &Rat, prec: u32) -> Self;
    /// An enclosure of `√q` for a rational constant `q >= 0`.
    fn sqrt_rat(q: &Rat, prec: u32) -> Self;
    /// Enclosures of `(sin self, cos self)`.
    fn sin_cos(&self) -> (Self, Self);
    /// The midpoint of the value as an `f64` (not certified; for choosing
    /// exact constants such as a frame origin).
    fn approx_value(&self) -> f64;
}

impl Trig for Interval {
    fn constant(q: &Rat, prec: u32) -> Self {
        <Interval as Real>::constant(q, prec)
    }
    fn sqrt_rat(q: &Rat, prec: u32) -> Self {
        <Interval as Real>::sqrt_rat(q, prec)
    }
    fn sin_cos(&self) -> (Self, Self) {
        sin_cos(self)
    }
    fn approx_value(&self) -> f64 {
        self.mid()
    }
}

impl Trig for BigInterval {
    fn constant(q: &Rat, prec: u32) -> Self {
        <BigInterval as Real>::constant(q, prec)
    }
    fn sqrt_rat(q: &Rat, prec: u32) -> Self {
        <BigInterval as Real>::sqrt_rat(q, prec)
    }
    fn sin_cos(&self) -> (Self, Self) {
        sin_cos(self)
    }
    fn approx_value(&self) -> f64 {
        self.approx()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn holds(i: &Interval, v: f64, slack: f64) -> bool {
        i.lo <= v + slack && v - slack <= i.hi
    }

    #[test]
    fn pi_is_enclosed_tightly() {
        let (lo, hi) = pi_enclosure(300);
        let (l, h) = (lo.to_rat(), hi.to_rat());
        assert!(l.to_f64() <= std::f64::consts::PI && std::f64::consts::PI <= h.to_f64());
        assert!((&h - &l).to_f64() < 1e-85);
        // Known digits: π = 3.14159265358979323846264338327950288419716939937510…
        let digits: Rat = "3.14159265358979323846264338327950288419716939937510"
            .parse()
            .unwrap();
        let tail = Rat::from_frac(1, 10).mul_pow2(-160);
        assert!(&l - &tail <= digits && digits <= &h + &Rat::from_frac(1, 1_000_000_000_000_000));
        let (p1, p2, p3) = half_pi_cody_waite();
        let h = Interval::point(p1) + Interval::point(p2) + p3;
        assert!(h.lo <= std::f64::consts::FRAC_PI_2 && std::f64::consts::FRAC_PI_2 <= h.hi);
    }

    #[test]
    fn exact_multiples_of_half_pi_and_neighbours() {
        for k in -40i64..40 {
            let x = k as f64 * std::f64::consts::FRAC_PI_2;
            for d in [-2i32, -1, 0, 1, 2] {
                let mut y = x;
                for _ in 0..d.abs() {
                    y = if d > 0 { y.next_up() } else { y.next_down() };
                }
                let (s, c) = sin_cos(&Interval::point(y));
                // f64 libm is accurate to < 1 ulp; the enclosure must hold
                // the true value, which is within 1e-15 of libm here.
                assert!(holds(&s, y.sin(), 2e-16), "sin {y}: {s:?} vs {}", y.sin());
                assert!(holds(&c, y.cos(), 2e-16), "cos {y}: {c:?} vs {}", y.cos());
                assert!(s.width() < 1e-15 && c.width() < 1e-15, "{s:?} {c:?}");
                assert!(s.lo >= -1.0 && s.hi <= 1.0);
            }
        }
    }

    #[test]
    fn huge_arguments_agree_with_multi_precision() {
        for x in [
            1e7,
            12345678.9,
            1e15,
            -3.3e22,
            1e300,
            f64::MAX,
            2f64.powi(60),
        ] {
            let (s, c) = sin_cos(&Interval::point(x));
            let big = BigInterval::point(Dyadic::from_f64(x).unwrap()).with_prec(200);
            let (bs, bc) = sin_cos(&big);
            assert!(bs.width_f64() < 1e-50 && bc.width_f64() < 1e-50);
            assert!(
                holds(&s, bs.approx(), 0.0) && holds(&c, bc.approx(), 0.0),
                "{x}"
            );
            assert!(s.width() < 1e-14 && c.width() < 1e-14, "{x}: {s:?}");
            // sin² + cos² = 1 to the precision
            let one = bs.times(&bs).plus(&bc.times(&bc));
            assert!((one.approx() - 1.0).abs() < 1e-50);
        }
        // libm agrees for moderately large arguments
        let (s, _) = sin_cos(&Interval::point(1e7));
        assert!(holds(&s, 1e7f64.sin(), 1e-15));
    }

    #[test]
    fn known_values_in_high_precision() {
        // sin(1) = 0.84147098480789650665250232163029899962256306079837…
        let one = BigInterval::from_i64(1).with_prec(256);
        let (s, c) = sin_cos(&one);
        let sin1: Rat = "0.84147098480789650665250232163029899962256306079837"
            .parse()
            .unwrap();
        let cos1: Rat = "0.54030230586813971740093660744297660373231042061792"
            .parse()
            .unwrap();
        let eps = Rat::from_frac(1, 1).mul_pow2(-160);
        assert!(&s.lo_rat() - &eps <= sin1 && sin1 <= &s.hi_rat() + &eps);
        assert!(&c.lo_rat() - &eps <= cos1 && cos1 <= &c.hi_rat() + &eps);
        assert!(s.width_f64() < 1e-70);
    }

    #[test]
    fn intervals_over_extrema_reach_one() {
        let (s, c) = sin_cos(&Interval::new(1.5, 1.6));
        assert_eq!(s.hi, 1.0);
        assert!(c.lo < 0.0 && c.hi > 0.0);
        let (s, c) = sin_cos(&Interval::new(-0.1, 0.1));
        assert_eq!(c.hi, 1.0);
        assert!(s.lo <= -0.0998 && s.hi >= 0.0998);
        let (s, c) = sin_cos(&Interval::new(0.0, 100.0));
        assert_eq!((s.lo, s.hi, c.lo, c.hi), (-1.0, 1.0, -1.0, 1.0));
        let (s, _) = sin_cos(
            &BigInterval::from_i64(3)
                .hull(&BigInterval::from_i64(5))
                .with_prec(100),
        );
        assert_eq!(s.lo_rat(), Rat::from(-1));
    }

    proptest! {
        #[test]
        fn point_enclosures_hold_libm(x in -1000.0f64..1000.0) {
            let (s, c) = sin_cos(&Interval::point(x));
            prop_assert!(holds(&s, x.sin(), 3e-16 * x.abs().max(1.0)));
            prop_assert!(holds(&c, x.cos(), 3e-16 * x.abs().max(1.0)));
            // The widest enclosures come at reduced arguments |r| near π/4,
            // where the Taylor terms are largest: 4.2e-15 at x = 0.82125…
            // (the saved regression case), about 19 ulps of 1.
            prop_assert!(s.width() < 6e-15 * x.abs().max(1.0));
        }

        #[test]
        fn interval_enclosures_contain_inner_points(a in -50.0f64..50.0, w in 0.0f64..8.0, f in 0.0f64..1.0) {
            let x = Interval::new(a, a + w);
            let (s, c) = sin_cos(&x);
            let p = a + f * w;
            let (ps, pc) = sin_cos(&Interval::point(p));
            prop_assert!(s.lo <= ps.hi && ps.lo <= s.hi && s.lo <= ps.lo + 1e-15 && ps.hi <= s.hi + 1e-15);
            prop_assert!(c.lo <= pc.lo + 1e-15 && pc.hi <= c.hi + 1e-15);
            // monotone: a sub-interval's enclosure is inside (up to rounding)
            let sub = Interval::new(a + f * w * 0.5, a + f * w);
            let (ss, sc) = sin_cos(&sub);
            prop_assert!(s.lo <= ss.lo + 1e-15 && ss.hi <= s.hi + 1e-15);
            prop_assert!(c.lo <= sc.lo + 1e-15 && sc.hi <= c.hi + 1e-15);
        }

        #[test]
        fn multi_precision_agrees_with_f64(x in -100.0f64..100.0) {
            let big = BigInterval::point(Dyadic::from_f64(x).unwrap()).with_prec(120);
            let (bs, bc) = sin_cos(&big);
            let (s, c) = sin_cos(&Interval::point(x));
            prop_assert!(s.lo <= bs.approx() && bs.approx() <= s.hi);
            prop_assert!(c.lo <= bc.approx() && bc.approx() <= c.hi);
            prop_assert!(bs.width_f64() < 1e-30);
        }
    }
}
