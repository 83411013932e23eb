//! `f(λ; u)` rounded to `f64` Bernstein form on `[0, 1]`, with the proven
//! error bounds of [`BernsteinF64`]: the inputs of the float path's closed
//! forms and of the exact path's certified filter for `sr0`.

use crate::CharPoly;
use ccd_arith::Int;
use ccd_poly::{BernsteinF64, ZPoly};

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

/// The rescaling of [`CharPoly::bernstein_f64`] for the scaled Bernstein coefficients of
/// `f`'s coefficients (`scaled[i]` of `λ^(4 − i)`): `c_k` (the coefficient
/// of `λ^k`) becomes `c_k·2^(j·k − shift)`; returns `(j, shift)`.
pub(crate) fn scaling(scaled: &[Vec<Int>; 5]) -> (i64, i64) {
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

impl CharPoly {
    /// The coefficients of `f(λ; u)` (high → low in λ) in `f64` Bernstein
    /// form on `[0, 1]`, rescaled so that no sign Theorem 3.10 reads
    /// changes.
    ///
    /// The Bernstein coefficients of `f`'s coefficients are computed exactly
    /// (integers) and rounded once: converting the power form in `f64`
    /// instead would lose up to `2^n` to cancellation on `[0, 1]`. The
    /// integer coefficients can be far outside the range of `f64` (and the
    /// closed forms are of degree 6 in them), so before conversion `f` is
    /// rescaled by the two changes the exact normalisation also uses:
    /// `λ ↦ 2^j·λ` (so `c_k` gets `2^(jk)`), with `j` balancing the sizes of
    /// `c_4 = det A` and `c_0 = det B`, and division of all coefficients by
    /// one power of two that brings the largest to about 1.
    pub fn bernstein_f64(&self) -> [BernsteinF64; 5] {
        let scaled: [Vec<Int>; 5] = self.coeffs.each_ref().map(ZPoly::scaled_bernstein);
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

    /// The rescaling `(j, shift)` of [`CharPoly::bernstein_f64`]: `c_k`
    /// (the coefficient of `λ^k`) is multiplied by `2^(j·k − shift)`.
    pub fn bernstein_f64_scale(&self) -> (i64, i64) {
        scaling(&self.coeffs.each_ref().map(ZPoly::scaled_bernstein))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
