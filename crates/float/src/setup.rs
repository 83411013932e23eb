//! The set-up stage of float mode: the exact characteristic polynomial
//! `f(λ; u)` (a [`CharPoly`] over ℤ[u]) converted to `f64` Bernstein form,
//! and the five `sr` polynomials of Theorem 3.10 computed from it in `f64`
//! by the Section 4 closed forms ([`ccd_subres::closed_forms`], the same
//! function the exact path runs over ℤ[u]).

use ccd_arith::Approx;
use ccd_motion::CharPoly;
use ccd_poly::BernsteinF64;
use ccd_subres::{closed_forms, QuarticInvariants};

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
    let coeffs = f.bernstein_f64();
    let inv = closed_forms(&coeffs);
    Prepared {
        f: coeffs,
        inv,
        deg_f: f.degree(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::{Int, Rat};
    use ccd_poly::ZPoly;

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
}
