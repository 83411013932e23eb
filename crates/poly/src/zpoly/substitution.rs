//! Substituting into a [`ZPoly`]: Taylor shifts `p(t + c)`, affine
//! substitutions `p(a + b·u)` and the reciprocal `t^n p(1/t)`.

use super::ZPoly;
use ccd_arith::{Int, Rat};

/// Replaces `c` (a coefficient vector, zeros allowed anywhere) by the
/// coefficients of `f(t + s)`: `n(n−1)/2` steps `c_j += s·c_{j+1}`; for
/// `s = ±1` these are additions.
pub(crate) fn taylor_shift_in_place(c: &mut [Int], s: &Int) {
    let n = c.len();
    if n < 2 || s.is_zero() {
        return;
    }
    let sign = if s.is_one() {
        1
    } else if s.abs().is_one() {
        -1
    } else {
        0
    };
    for i in 0..n - 1 {
        for j in (i..n - 1).rev() {
            let (lo, hi) = c.split_at_mut(j + 1);
            match sign {
                1 => lo[j] += &hi[0],
                -1 => lo[j] -= &hi[0],
                _ => lo[j].add_mul(&hi[0], s),
            }
        }
    }
}

impl ZPoly {
    /// `p(t + c)`.
    pub fn taylor_shift(&self, c: &Int) -> ZPoly {
        let mut v = self.c.clone();
        taylor_shift_in_place(&mut v, c);
        ZPoly::new(v)
    }
    /// The primitive integer polynomial `P(u) = κ·p(a + b·u)` for some
    /// rational `κ > 0` (the sign of `p(a + b·u)` is kept; `b ≠ 0` keeps the
    /// degree). With `d = lcm(den a, den b)`, `a = α/d`, `b = β/d`:
    /// `d^n p((α + βu)/d) = Σ_i [shift_α (Σ_j c_j d^(n−j) t^j)]_i β^i u^i`.
    pub fn compose_affine(&self, a: &Rat, b: &Rat) -> ZPoly {
        let p = self.compose_affine_multiple(a, b);
        p.div_exact_int(&p.content())
    }
    /// `d^n·p(a + b·u)` (`d = lcm(den a, den b) > 0`, `n = deg p`): the
    /// positive integer multiple of [`ZPoly::compose_affine`] before its
    /// content is removed, for callers that need only signs.
    pub fn compose_affine_multiple(&self, a: &Rat, b: &Rat) -> ZPoly {
        let Some(n) = self.degree() else {
            return ZPoly::zero();
        };
        let d = a.denom().lcm(b.denom());
        let alpha = a.numer() * &d.div_exact(a.denom());
        let beta = b.numer() * &d.div_exact(b.denom());
        let mut v = self.c.clone();
        // c_j d^(n−j), from the top.
        times_successive_powers(v[..n].iter_mut().rev(), &d);
        taylor_shift_in_place(&mut v, &alpha);
        times_successive_powers(v[1..].iter_mut(), &beta);
        ZPoly::new(v)
    }
    /// `t^n p(1/t)` with `n = deg p`: the coefficients reversed (the degree
    /// drops by the multiplicity of the root `0`).
    pub fn reverse(&self) -> ZPoly {
        ZPoly::new(self.c.iter().rev().cloned().collect())
    }
}

/// Multiplies the entries in turn by `x¹, x², …`: shifts where `x` is a
/// positive power of two (a dyadic substitution's denominators and
/// widths), else products by the running power; nothing for `x = 1`.
fn times_successive_powers<'a>(v: impl Iterator<Item = &'a mut Int>, x: &Int) {
    if x.is_one() {
        return;
    }
    let twos = x.exact_log2();
    let mut power = Int::one();
    for (j, entry) in (1u64..).zip(v) {
        match twos {
            Some(k) => *entry = entry.shl(k * j),
            None => {
                power *= x;
                *entry *= &power;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{rat, zpoly_deg};
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn affine_composition(p in zpoly_deg(0, 9, 150), a in rat(), b in rat(), u in rat()) {
            prop_assume!(!b.is_zero());
            let q = p.compose_affine(&a, &b);
            let n = p.degree().unwrap_or(0);
            prop_assert_eq!(q.degree(), p.degree());
            prop_assert!(q.content().is_one());
            let mut bn = Rat::one();
            for _ in 0..n { bn = &bn * &b; }
            let kappa = &Rat::from_int(q.leading().cloned().unwrap_or_default()) / &(&Rat::from_int(p.leading().cloned().unwrap_or_default()) * &bn);
            prop_assert!(kappa.signum() > 0);
            prop_assert_eq!(q.eval_rat(&u), &kappa * &p.eval_rat(&(&a + &(&b * &u))));
        }

        #[test]
        fn affine_multiple_is_exact(p in zpoly_deg(0, 9, 150), (a, b) in prop_oneof![
            (rat(), rat()),
            // Dyadic ends and widths: the shifts instead of products.
            ((-999i64..999, 0u64..70), (-99i64..99, 0u64..70)).prop_map(|((x, e), (y, f))| {
                let dyadic = |v: i64, k: u64| Rat::new(Int::from(v), Int::one().shl(k)).expect("nonzero");
                (dyadic(x, e), dyadic(y, f))
            }),
        ], u in rat()) {
            prop_assume!(!b.is_zero());
            let d = Rat::from_int(a.denom().lcm(b.denom()));
            let n = p.degree().unwrap_or(0);
            let mut dn = Rat::one();
            for _ in 0..n { dn = &dn * &d; }
            let q = p.compose_affine_multiple(&a, &b);
            prop_assert_eq!(q.eval_rat(&u), &dn * &p.eval_rat(&(&a + &(&b * &u))));
        }

        #[test]
        fn reverse_is_reciprocal(p in zpoly_deg(0, 10, 100), x in rat()) {
            prop_assume!(!x.is_zero() && !p.coeff(0).is_zero());
            let n = p.degree().unwrap_or(0);
            let mut xn = Rat::one();
            for _ in 0..n { xn = &xn * &x; }
            prop_assert_eq!(p.reverse().eval_rat(&x), &xn * &p.eval_rat(&(Rat::one() / &x)));
        }
    }
}
