//! The set-up stage of float mode: the exact characteristic polynomial
//! `f(λ; u)` (a [`CharPoly`] over ℤ[u]) converted to `f64` Bernstein form,
//! and the five `sr` polynomials of Theorem 3.10 computed from it in `f64`
//! by the Section 4 closed forms ([`ccd_subres::closed_forms`], the same
//! function the exact path runs over ℤ[u]).

use crate::approx::Approx;
use crate::bernstein::BernsteinF64;
use ccd_arith::{Int, Interval};
use ccd_motion::CharPoly;
use ccd_poly::ZPoly;
use ccd_subres::{closed_form, closed_forms, Quantity, QuarticInvariants};

/// `f(λ; u)` and its `sr` polynomials in `f64` Bernstein form on `[0, 1]`:
/// everything [`crate::solve_prepared`] reads.
#[derive(Clone, Debug)]
pub struct Prepared {
    /// `[c_4, c_3, c_2, c_1, c_0]` (high → low in λ), each scaled by a
    /// positive power of two (see [`prepare`]).
    pub f: [BernsteinF64; 5],
    /// `sr22, sr20, sr11, sr10, sr0` of `f`, in `f64`.
    pub inv: QuarticInvariants<BernsteinF64>,
    /// `deg_t f` of the exact characteristic polynomial.
    pub deg_f: usize,
}

impl Prepared {
    /// The coefficients of `f(λ; u)` at `u`, with magnitudes.
    pub fn f_at(&self, u: f64) -> [Approx; 5] {
        self.f.each_ref().map(|c| c.eval(u))
    }
}

/// `m · 2^e` without spurious overflow or underflow in the power.
fn ldexp(m: f64, e: i64) -> f64 {
    let mut v = m;
    let mut e = e;
    while e != 0 && v != 0.0 && v.is_finite() {
        let step = e.clamp(-1000, 1000);
        v *= 2f64.powi(step as i32);
        e -= step;
    }
    v
}

/// `x · 2^(−shift)` as the nearest-ish `f64` (from its top 64 bits).
fn int_to_f64_scaled(x: &Int, shift: i64) -> f64 {
    let (m, e) = x.top_bits();
    let v = ldexp(m as f64, e as i64 - shift);
    if x.is_negative() {
        -v
    } else {
        v
    }
}

/// Converts the exact `f(λ; u)` to `f64` and computes its `sr` polynomials.
///
/// The Bernstein coefficients of `f`'s coefficients are computed exactly
/// (integers) and rounded once: converting the power form in `f64` instead
/// would lose up to `2^n` to cancellation on `[0, 1]`. So the inputs of the
/// closed forms carry one rounding each, and their magnitudes are their
/// absolute values.
///
/// The integer coefficients can be far outside the range of `f64` (and the
/// closed forms are of degree 6 in them), so before conversion `f` is
/// rescaled by the two changes the exact normalisation also uses, neither
/// of which changes a sign Theorem 3.10 reads: `λ ↦ 2^j·λ` (so `c_k` gets
/// `2^(jk)`), with `j` balancing the sizes of `c_4 = det A` and
/// `c_0 = det B`, and division of all coefficients by one power of two that
/// brings the largest to about 1.
///
/// ```
/// use ccd_float::prepare;
/// use ccd_motion::CharPoly;
/// use ccd_poly::ZPoly;
/// // Example 5.1: −(λ + 1)²(−λ² + (68u² − 96u + 34)λ − 1), so sr0 ≡ 0.
/// let f = CharPoly { coeffs: [
///     ZPoly::from_i64s(&[1]), ZPoly::from_i64s(&[-32, 96, -68]),
///     ZPoly::from_i64s(&[-66, 192, -136]), ZPoly::from_i64s(&[-32, 96, -68]),
///     ZPoly::from_i64s(&[1]),
/// ] };
/// let p = prepare(&f);
/// assert!(p.inv.sr0.is_negligible(1e-10));
/// assert!(!p.inv.sr11.is_negligible(1e-10));
/// ```
pub fn prepare(f: &CharPoly) -> Prepared {
    let coeffs = inputs(f);
    let inv = closed_forms(&coeffs);
    Prepared {
        f: coeffs,
        inv,
        deg_f: f.degree(),
    }
}

/// The rescaling of [`prepare`] for the scaled Bernstein coefficients of
/// `f`'s coefficients (`scaled[i]` of `λ^(4 − i)`): `c_k` (the coefficient
/// of `λ^k`) becomes `c_k·2^(j·k − shift)`; returns `(j, shift)`.
fn scaling(scaled: &[Vec<Int>; 5]) -> (i64, i64) {
    let bits = |c: &Vec<Int>| c.iter().map(Int::bits).max().unwrap_or(0) as i64;
    let b: [i64; 5] = scaled.each_ref().map(bits);
    // b = 0 exactly for a zero coefficient.
    let j = if b[0] == 0 || b[4] == 0 {
        0
    } else {
        (b[4] - b[0]).div_euclid(4)
    };
    let exp = |i: usize| (4 - i as i64) * j;
    let shift = (0..5)
        .filter(|&i| b[i] != 0)
        .map(|i| b[i] + exp(i))
        .max()
        .unwrap_or(0);
    (j, shift)
}

/// `f`'s coefficients, rescaled ([`scaling`]) and rounded.
fn inputs(f: &CharPoly) -> [BernsteinF64; 5] {
    let scaled: [Vec<Int>; 5] = f.coeffs.each_ref().map(ZPoly::scaled_bernstein);
    let (j, shift) = scaling(&scaled);
    std::array::from_fn(|i| {
        let exp = (4 - i as i64) * j;
        BernsteinF64::from_scaled(
            scaled[i]
                .iter()
                .map(|c| int_to_f64_scaled(c, shift - exp))
                .collect(),
        )
    })
}

/// Certified enclosures of the Bernstein coefficients on `[0, 1]` of the
/// closed form `q` (not [`Quantity::Var`]) of `f`, times a positive
/// constant: the closed form over the rescaled `f64` inputs of [`prepare`]
/// (a positive multiple of `q`, the closed forms being homogeneous and
/// isobaric), with the proven error bounds of [`BernsteinF64::enclosures`].
/// The exact path isolates the roots of `sr0` from these without forming
/// `sr0`; a coefficient whose sign they leave open sends it back to the
/// exact polynomial.
pub fn certified_bernstein(f: &CharPoly, q: Quantity) -> Vec<Interval> {
    closed_form(&inputs(f), q).map_or_else(Vec::new, |p| p.enclosures())
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Rat;

    #[test]
    fn huge_coefficients_are_rescaled_not_overflowed() {
        let big = Int::from(3).pow(400);
        let small = Int::from(5);
        // λ ↦ big·λ applied to a tame quartic, then everything times big.
        let tame = [[-3, 1], [5, -2], [-4, 7], [2, 9], [6, -1]];
        let f = CharPoly {
            coeffs: std::array::from_fn(|i| {
                let scale = big.pow(5 - i as u32) * &small;
                ZPoly::new(tame[i].iter().map(|&c| &scale * &Int::from(c)).collect())
            }),
        };
        let p = prepare(&f);
        for q in [
            &p.inv.sr22,
            &p.inv.sr20,
            &p.inv.sr11,
            &p.inv.sr10,
            &p.inv.sr0,
        ] {
            assert!(q.coefficients().iter().all(|c| c.is_finite()));
        }
        // Signs agree with the exact closed forms at u = 1/3.
        let exact = closed_forms(&f.at(&Rat::from_frac(1, 3)));
        let float = closed_forms(&p.f_at(1.0 / 3.0));
        assert_eq!(exact.sr22.signum(), float.sr22.sign(1e-9));
        assert_eq!(exact.sr11.signum(), float.sr11.sign(1e-9));
        assert_eq!(exact.sr0.signum(), float.sr0.sign(1e-9));
    }

    #[test]
    fn exact_bernstein_conversion() {
        // (1 − u)^3 = Σ C(3,i) b_i …: scaled coefficients [1, 0, 0, 0].
        let p = ZPoly::from_i64s(&[1, -3, 3, -1]);
        assert_eq!(p.scaled_bernstein(), [1, 0, 0, 0].map(Int::from));
        // u² (a_0 = 0, the reversal drops it): [0, 0, 1].
        assert_eq!(
            ZPoly::from_i64s(&[0, 0, 1]).scaled_bernstein(),
            [0, 0, 1].map(Int::from)
        );
        assert_eq!(ZPoly::zero().scaled_bernstein(), [Int::zero()]);
        // 2 + u: [2, 3].
        assert_eq!(
            ZPoly::from_i64s(&[2, 1]).scaled_bernstein(),
            [2, 3].map(Int::from)
        );
    }

    /// `certified_bernstein` encloses the exact Bernstein coefficients of
    /// `sr0` times `σ = 2^(12j − 6·shift)` (`sr0` is homogeneous of degree
    /// 6 and isobaric of weight 12 in the `c_k`).
    fn assert_encloses_sr0(f: &CharPoly) {
        let enc = certified_bernstein(f, Quantity::Sr0);
        let (j, shift) = scaling(&f.coeffs.each_ref().map(ZPoly::scaled_bernstein));
        let sr0 = closed_form(&f.coeffs, Quantity::Sr0).expect("sr0");
        let n = enc.len() - 1;
        // sr0 in degree n on [0, 1], exactly.
        let exact: Vec<Rat> = if sr0.is_zero() {
            vec![Rat::zero(); n + 1]
        } else {
            let b = ccd_poly::Bernstein::from_power(&sr0, &Rat::zero(), &Rat::one());
            let e = b.elevate(n - b.degree());
            e.coeffs()
                .iter()
                .map(|c| e.scale() * &Rat::from(c.clone()))
                .collect()
        };
        for (iv, b) in enc.iter().zip(&exact) {
            let b = b.mul_pow2(12 * j - 6 * shift);
            let (lo, hi) = (Rat::from_f64_exact(iv.lo), Rat::from_f64_exact(iv.hi));
            assert!(
                lo.is_none_or(|lo| lo <= b) && hi.is_none_or(|hi| b <= hi),
                "{iv:?} misses {}",
                b.to_f64()
            );
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Random coefficients, and sr0 with cancellation: f with a double
        /// root in λ on a random factor, so that sr0 is small or zero.
        #[test]
        fn certified_bernstein_encloses_the_exact_coefficients(
            raw in proptest::collection::vec(proptest::collection::vec(-99i64..99, 1..6), 5),
            root in proptest::collection::vec(-9i64..9, 1..3),
            big in 0u32..200,
        ) {
            let scale = Int::from(3).pow(big);
            let f = CharPoly { coeffs: std::array::from_fn(|k| ZPoly::new(raw[k].iter().map(|&c| &scale * &Int::from(c)).collect())) };
            if f.coeffs.iter().all(ZPoly::is_zero) { return Ok(()); }
            assert_encloses_sr0(&f);
            // (λ − r(u))²·(λ² + raw0·λ + raw1): sr0 ≡ 0.
            let r = ZPoly::from_i64s(&root);
            let (p, q) = (ZPoly::new(raw[0].iter().map(|&c| Int::from(c)).collect()), ZPoly::new(raw[1].iter().map(|&c| Int::from(c)).collect()));
            let sq = [ZPoly::one(), -&(&r * &ZPoly::from_i64s(&[2])), &r * &r];
            let other = [ZPoly::one(), p, q];
            let coeffs: [ZPoly; 5] = std::array::from_fn(|d| {
                (0..3).filter(|&a| d >= a && d - a < 3).fold(ZPoly::zero(), |acc, a| &acc + &(&sq[a] * &other[d - a]))
            });
            assert_encloses_sr0(&CharPoly { coeffs });
        }
    }

    #[test]
    fn scaled_conversion_keeps_ratios() {
        assert_eq!(int_to_f64_scaled(&Int::from(-12), 2), -3.0);
        let x = Int::from(7).pow(700);
        let v = int_to_f64_scaled(&x, x.bits() as i64);
        assert!((0.5..1.0).contains(&v));
        assert_eq!(ldexp(1.0, -1100), 0.0);
        assert_eq!(ldexp(1.0, -1074), f64::from_bits(1));
    }
}
