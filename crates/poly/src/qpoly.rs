//! [`QPoly`]: polynomials over `Q` as one rational times a primitive
//! integer polynomial.

use crate::zpoly::forward_binops;
use crate::ZPoly;
use ccd_arith::{Int, Rat, Ring};
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A polynomial over `Q` held as `scale · prim`: `prim` primitive in `Z[t]`
/// with positive leading coefficient, `scale ∈ Q` (both zero for the zero
/// polynomial). The representation is canonical, so `==` is equality of
/// polynomials.
///
/// ```
/// use ccd_arith::Rat;
/// use ccd_poly::QPoly;
/// let p = QPoly::from_rats(&[Rat::from_frac(1, 2), Rat::from_frac(-3, 4)]); // 1/2 − 3/4 t
/// assert_eq!(p.scale(), &Rat::from_frac(-1, 4)); //                          = −1/4 (3t − 2)
/// assert_eq!(p.eval_rat(&Rat::from(2)), Rat::from(-1));
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct QPoly {
    scale: Rat,
    prim: ZPoly,
}

impl Default for QPoly {
    /// The zero polynomial.
    fn default() -> QPoly {
        QPoly::zero()
    }
}

impl QPoly {
    /// `scale · p`, normalised: the signed content of `p` moves into the scale.
    pub fn from_parts(scale: Rat, p: ZPoly) -> QPoly {
        let Some(lc) = p.leading() else {
            return QPoly::zero();
        };
        if scale.is_zero() {
            return QPoly::zero();
        }
        let c = p.content();
        let c = if lc.is_negative() { -c } else { c };
        let prim = p.div_exact_int(&c);
        QPoly {
            scale: &scale * &Rat::from_int(c),
            prim,
        }
    }
    /// The integer polynomial `p` over `Q`.
    pub fn from_zpoly(p: &ZPoly) -> QPoly {
        QPoly::from_parts(Rat::one(), p.clone())
    }
    /// From rational coefficients, constant term first: over the common
    /// denominator `L = lcm(den c_i)`, `Σ c_i t^i = (1/L)·Σ (c_i L) t^i`.
    pub fn from_rats(c: &[Rat]) -> QPoly {
        let l = c.iter().fold(Int::one(), |l, x| l.lcm(x.denom()));
        let ints = c
            .iter()
            .map(|x| x.numer() * &l.div_exact(x.denom()))
            .collect();
        let inv_l = Rat::new(Int::one(), l).expect("lcm of positive denominators is positive");
        QPoly::from_parts(inv_l, ZPoly::new(ints))
    }
    /// `0`.
    pub fn zero() -> QPoly {
        QPoly {
            scale: Rat::zero(),
            prim: ZPoly::zero(),
        }
    }
    /// `1`.
    pub fn one() -> QPoly {
        QPoly {
            scale: Rat::one(),
            prim: ZPoly::one(),
        }
    }
    /// The constant `c`.
    pub fn constant(c: Rat) -> QPoly {
        QPoly::from_parts(c, ZPoly::one())
    }
    /// The variable `t`.
    pub fn x() -> QPoly {
        QPoly {
            scale: Rat::one(),
            prim: ZPoly::x(),
        }
    }
    /// The rational factor (zero only for the zero polynomial).
    pub fn scale(&self) -> &Rat {
        &self.scale
    }
    /// The primitive integer part (positive leading coefficient).
    pub fn prim(&self) -> &ZPoly {
        &self.prim
    }
    /// The rational coefficients `scale·prim_i`, constant term first.
    pub fn coeffs(&self) -> Vec<Rat> {
        self.prim
            .coeffs()
            .iter()
            .map(|x| &self.scale * &Rat::from_int(x.clone()))
            .collect()
    }
    /// The coefficient of `t^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> Rat {
        &self.scale * &Rat::from_int(self.prim.coeff(i))
    }
    /// The degree; `None` for zero.
    pub fn degree(&self) -> Option<usize> {
        self.prim.degree()
    }
    /// `self == 0`.
    pub fn is_zero(&self) -> bool {
        self.prim.is_zero()
    }
    /// `c·p`.
    pub fn mul_rat(&self, c: &Rat) -> QPoly {
        if c.is_zero() || self.is_zero() {
            return QPoly::zero();
        }
        QPoly {
            scale: &self.scale * c,
            prim: self.prim.clone(),
        }
    }
    /// The derivative.
    pub fn derivative(&self) -> QPoly {
        QPoly::from_parts(self.scale.clone(), self.prim.derivative())
    }
    /// `p(x)`, exactly.
    pub fn eval_rat(&self, x: &Rat) -> Rat {
        &self.scale * &self.prim.eval_rat(x)
    }
    /// The exact sign of `p(x)`: `sign(scale)·sign(prim(x))`, no rationals.
    pub fn sign_at(&self, x: &Rat) -> i32 {
        self.scale.signum() * self.prim.sign_at(x)
    }
    /// The exact quotient in `Q[t]`, or `None` if `d` does not divide `self`
    /// (or `d = 0`). `prim_d` is primitive, so `prim_d | prim_self` in `Q[t]`
    /// iff it does in `Z[t]` (Gauss), and the quotient is primitive again.
    pub fn div_exact(&self, d: &QPoly) -> Option<QPoly> {
        if d.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(QPoly::zero());
        }
        let q = self.prim.div_exact(&d.prim)?;
        Some(QPoly {
            scale: &self.scale / &d.scale,
            prim: q,
        })
    }
    /// Euclidean division in `Q[t]`: `(q, r)` with `self = q·d + r`,
    /// `deg r < deg d`. From the pseudo-division
    /// `lc^k·prim = q̃·prim_d + r̃`: `q = s/(lc^k s_d)·q̃`, `r = s/lc^k·r̃`.
    /// Panics if `d = 0`.
    pub fn div_rem(&self, d: &QPoly) -> (QPoly, QPoly) {
        assert!(
            !d.is_zero(),
            "QPoly::div_rem: division by the zero polynomial"
        );
        let (dd, n) = (d.prim.degree().unwrap_or(0), self.prim.degree());
        if n.is_none_or(|n| n < dd) {
            return (QPoly::zero(), self.clone());
        }
        let k = (n.unwrap_or(0) - dd + 1) as u32;
        let (q, r) = self.prim.pseudo_div_rem(&d.prim);
        let lck = Rat::from_int(d.prim.leading().expect("nonzero divisor").pow(k));
        let rs = &self.scale / &lck;
        (
            QPoly::from_parts(&rs / &d.scale, q),
            QPoly::from_parts(rs, r),
        )
    }
    /// The monic gcd over `Q[t]` (`gcd(0, 0) = 0`).
    pub fn gcd(&self, o: &QPoly) -> QPoly {
        QPoly::monic(self.prim.gcd(&o.prim))
    }
    /// The monic squarefree part `p / gcd(p, p')` (zero stays zero).
    pub fn squarefree_part(&self) -> QPoly {
        QPoly::monic(self.prim.squarefree_part())
    }
    /// `g / lc(g)` for a primitive `g` with positive leading coefficient.
    fn monic(g: ZPoly) -> QPoly {
        let Some(lc) = g.leading() else {
            return QPoly::zero();
        };
        let scale = Rat::new(Int::one(), lc.clone()).expect("nonzero leading coefficient");
        QPoly { scale, prim: g }
    }
    /// `p(a + b·u)`, exactly. From `P = prim.compose_affine(a, b) = κ·prim(a + bu)`
    /// and the leading coefficient `lc(prim(a + bu)) = lc(prim)·b^n`:
    /// `κ = lc(P)/(lc(prim)·b^n)`.
    pub fn compose_affine(&self, a: &Rat, b: &Rat) -> QPoly {
        let Some(n) = self.degree() else {
            return QPoly::zero();
        };
        if b.is_zero() {
            return QPoly::constant(self.eval_rat(a));
        }
        let p = self.prim.compose_affine(a, b);
        let mut bn = Rat::one();
        for _ in 0..n {
            bn = &bn * b;
        }
        let lc_exact = &Rat::from_int(self.prim.leading().expect("nonzero").clone()) * &bn;
        let lc_p = Rat::from_int(p.leading().expect("degree kept for b ≠ 0").clone());
        QPoly::from_parts(&self.scale * &(&lc_exact / &lc_p), p)
    }
}

impl Add<&QPoly> for &QPoly {
    type Output = QPoly;
    /// `s_a P_a + s_b P_b = (g/D)·((n_a/g)(D/d_a) P_a + (n_b/g)(D/d_b) P_b)`
    /// with `D = lcm(d_a, d_b)`, `g = gcd(n_a, n_b)`.
    fn add(self, o: &QPoly) -> QPoly {
        if self.is_zero() {
            return o.clone();
        }
        if o.is_zero() {
            return self.clone();
        }
        let (na, da, nb, db) = (
            self.scale.numer(),
            self.scale.denom(),
            o.scale.numer(),
            o.scale.denom(),
        );
        let g = na.gcd(nb);
        let d = da.lcm(db);
        let fa = na.div_exact(&g) * d.div_exact(da);
        let fb = nb.div_exact(&g) * d.div_exact(db);
        let sum = &self.prim.mul_int(&fa) + &o.prim.mul_int(&fb);
        QPoly::from_parts(Rat::new(g, d).expect("positive lcm"), sum)
    }
}
impl Sub<&QPoly> for &QPoly {
    type Output = QPoly;
    fn sub(self, o: &QPoly) -> QPoly {
        self + &(-o)
    }
}
impl Mul<&QPoly> for &QPoly {
    type Output = QPoly;
    /// `(s_a s_b)·(P_a P_b)`: a product of primitive polynomials is
    /// primitive (Gauss), with positive leading coefficient.
    fn mul(self, o: &QPoly) -> QPoly {
        if self.is_zero() || o.is_zero() {
            return QPoly::zero();
        }
        QPoly {
            scale: &self.scale * &o.scale,
            prim: &self.prim * &o.prim,
        }
    }
}
impl Neg for &QPoly {
    type Output = QPoly;
    fn neg(self) -> QPoly {
        QPoly {
            scale: -&self.scale,
            prim: self.prim.clone(),
        }
    }
}
impl Neg for QPoly {
    type Output = QPoly;
    fn neg(self) -> QPoly {
        QPoly {
            scale: -self.scale,
            prim: self.prim,
        }
    }
}
forward_binops!(QPoly);

ccd_arith::ring_ops_via_operators!(QPoly, zero: QPoly::zero(), one: QPoly::one(), from_i64: |v| QPoly::constant(Rat::from(v)), is_zero: |x| QPoly::is_zero(x), div_small: |a, k| a.mul_rat(&Rat::from_frac(1, k)));

impl Ring for QPoly {
    /// The exact quotient in `Q[t]`; panics if `o` does not divide `self`.
    fn div_exact(&self, o: &Self) -> Self {
        QPoly::div_exact(self, o)
            .expect("Ring::div_exact for QPoly: the divisor does not divide exactly")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{rat, zpoly};
    use ccd_arith::RingOps;
    use proptest::prelude::*;

    fn qpoly() -> impl Strategy<Value = QPoly> {
        prop::collection::vec(rat(), 0..8).prop_map(|c| QPoly::from_rats(&c))
    }

    #[test]
    fn canonical_representation() {
        let p = QPoly::from_rats(&[Rat::from_frac(1, 2), Rat::from_frac(-3, 4), Rat::zero()]);
        assert_eq!(p.prim(), &ZPoly::from_i64s(&[-2, 3]));
        assert_eq!(p.scale(), &Rat::from_frac(-1, 4));
        assert_eq!(
            p.coeffs(),
            vec![Rat::from_frac(1, 2), Rat::from_frac(-3, 4)]
        );
        assert_eq!(p.coeff(5), Rat::zero());
        assert_eq!(QPoly::default(), QPoly::zero());
        assert_eq!(QPoly::from_rats(&[Rat::zero()]), QPoly::zero());
        assert_eq!(QPoly::constant(Rat::from(3)).degree(), Some(0));
        assert_eq!(
            QPoly::x().mul_rat(&Rat::from(2)),
            QPoly::from_zpoly(&ZPoly::from_i64s(&[0, 2]))
        );
        assert_eq!(
            QPoly::from_zpoly(&ZPoly::from_i64s(&[0, 0, 3])).derivative(),
            QPoly::from_zpoly(&ZPoly::from_i64s(&[0, 6]))
        );
        assert_eq!(
            <QPoly as ccd_arith::RingOps>::from_i64(5),
            QPoly::constant(Rat::from(5))
        );
        assert!(QPoly::one().mul_rat(&Rat::zero()).is_zero());
    }

    #[test]
    fn gcd_and_squarefree_are_monic() {
        let z = |c: &[i64]| QPoly::from_zpoly(&ZPoly::from_i64s(c));
        let p = (z(&[-1, 2]) * z(&[-1, 2])).mul_rat(&Rat::from_frac(5, 3)) * z(&[1, 0, 1]);
        assert_eq!(
            p.squarefree_part(),
            z(&[-1, 2]).mul_rat(&Rat::from_frac(1, 2)) * z(&[1, 0, 1])
        );
        assert_eq!(
            p.gcd(&z(&[-3, 6])),
            QPoly::from_rats(&[Rat::from_frac(-1, 2), Rat::one()])
        );
        assert!(QPoly::zero().gcd(&QPoly::zero()).is_zero());
        assert_eq!(p.div_exact(&QPoly::zero()), None);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn field_operations(a in qpoly(), b in qpoly(), c in qpoly(), x in rat()) {
            prop_assert_eq!(QPoly::from_rats(&a.coeffs()), a.clone());
            prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
            prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
            prop_assert!((&a - &a).is_zero());
            prop_assert_eq!((&a * &b).eval_rat(&x), &a.eval_rat(&x) * &b.eval_rat(&x));
            prop_assert_eq!((&a - &b).eval_rat(&x), &a.eval_rat(&x) - &b.eval_rat(&x));
            prop_assert_eq!(a.sign_at(&x), a.eval_rat(&x).signum());
            let mut s = a.clone();
            s += &b;
            s -= &b;
            prop_assert_eq!(s, a.clone());
            prop_assert_eq!(a.plus(&b).minus(&c).times(&b).negated(), -((&a + &b - &c) * b.clone()));
            if !b.is_zero() {
                let (q, r) = a.div_rem(&b);
                prop_assert_eq!(&(&q * &b) + &r, a.clone());
                prop_assert!(r.is_zero() || r.degree() < b.degree());
                prop_assert_eq!((&a * &b).div_exact(&b), Some(a.clone()));
                prop_assert_eq!(<QPoly as Ring>::div_exact(&(&a * &b), &b), a.clone());
                if r.is_zero() {
                    prop_assert_eq!(a.div_exact(&b), Some(q));
                } else {
                    prop_assert_eq!(a.div_exact(&b), None);
                }
            }
        }

        #[test]
        fn affine_composition_is_exact(a in qpoly(), s in rat(), t in rat(), u in rat()) {
            prop_assert_eq!(a.compose_affine(&s, &t).eval_rat(&u), a.eval_rat(&(&s + &(&t * &u))));
        }

        #[test]
        fn gcd_matches_integer_gcd(p in zpoly(6, 80), q in zpoly(6, 80), g in zpoly(4, 80)) {
            let (a, b) = (QPoly::from_zpoly(&(&p * &g)), QPoly::from_zpoly(&(&q * &g)));
            let h = a.gcd(&b);
            if !h.is_zero() {
                prop_assert_eq!(h.coeff(h.degree().unwrap_or(0)), Rat::one());
                prop_assert!(a.div_exact(&h).is_some() && b.div_exact(&h).is_some());
            }
            prop_assert_eq!(h.prim(), &(&p * &g).gcd(&(&q * &g)));
        }
    }
}
