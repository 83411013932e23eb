//! The exact path's cheapest stage: `sr0`'s Bernstein coefficients in
//! `f64` with proven error bounds, from which its roots are isolated
//! without forming it.

use ccd_arith::Interval;
use ccd_motion::CharPoly;
use ccd_subres::{closed_form, Quantity};

/// Certified enclosures of the Bernstein coefficients on `[0, 1]` of the
/// closed form `q` (not [`Quantity::Var`]) of `f`, times a positive
/// constant: the closed form over the rescaled `f64` inputs of `CharPoly::bernstein_f64`
/// (a positive multiple of `q`, the closed forms being homogeneous and
/// isobaric), with the proven error bounds of [`ccd_poly::BernsteinF64::enclosures`].
/// The exact path isolates the roots of `sr0` from these without forming
/// `sr0`; a coefficient whose sign they leave open sends it back to the
/// exact polynomial.
pub fn certified_bernstein(f: &CharPoly, q: Quantity) -> Vec<Interval> {
    closed_form(&f.bernstein_f64(), q).map_or_else(Vec::new, |p| p.enclosures())
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::{Int, Rat};
    use ccd_poly::ZPoly;

    /// `certified_bernstein` encloses the exact Bernstein coefficients of
    /// `sr0` times `σ = 2^(12j − 6·shift)` (`sr0` is homogeneous of degree
    /// 6 and isobaric of weight 12 in the `c_k`).
    fn assert_encloses_sr0(f: &CharPoly) {
        let enc = certified_bernstein(f, Quantity::Sr0);
        let (j, shift) = f.bernstein_f64_scale();
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
}
