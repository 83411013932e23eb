//! [`Residues`]: polynomials over the prime field `F_p` of one fixed word
//! prime `p` (the first table prime, `p < 2^62`), as a [`RingOps`] type:
//! a generic exact computation over `ℤ[t]` (a closed form of the
//! subresultants) runs over `Residues` unchanged and gives the image
//! modulo `p` of its exact result, since reduction modulo `p` is a ring
//! homomorphism `ℤ[t] → F_p[t]` (an exact division by a small `k`, `p ∤ k`,
//! maps to the product with `k^{-1}`).
//!
//! What one image proves ([`Residues::proves_coprime`]): for `P, Q ∈ ℤ[t]`
//! with `p ∤ lc(P)` and `Q mod p ≠ 0`, if `gcd(P mod p, Q mod p) = 1` then
//! `gcd(P, Q) = 1` over `ℚ`. Proof: let `n = deg P`, `d = deg Q` and
//! `e = deg(Q mod p) ≤ d`. Reduction commutes with the Sylvester
//! determinant, so `Res_{n,d}(P, Q) mod p = Res_{n,d}(P̄, Q̄) =
//! ±lc(P̄)^(d−e)·Res(P̄, Q̄)`, nonzero since `lc(P̄) ≠ 0` and `P̄, Q̄` are
//! coprime over the field `F_p`. So `Res(P, Q) ≠ 0`: `P` and `Q` have no
//! common root. No condition on `Q`'s leading coefficient is needed.

use crate::modular::gcd_mod_p;
use crate::prime::{ntt_prime, Fp};
use crate::ZPoly;
use ccd_arith::{Int, RingOps};
use std::sync::LazyLock;

/// The field: Montgomery arithmetic modulo the first table prime.
static FIELD: LazyLock<Fp> = LazyLock::new(|| Fp::new(ntt_prime(0).p));

/// A polynomial over `F_p` (module docs), coefficients low → high in
/// Montgomery form, without trailing zeros.
///
/// ```
/// use ccd_arith::RingOps;
/// use ccd_poly::{Residues, ZPoly};
/// // (t − 1)(t + 2) and (t − 1)(t − 3) share t − 1; (t + 2) and (t − 3) do not.
/// let a = ZPoly::from_i64s(&[-2, 1, 1]);
/// let b = ZPoly::from_i64s(&[3, -4, 1]);
/// assert!(!Residues::of(&a).proves_coprime(&Residues::of(&b)));
/// let (c, d) = (ZPoly::from_i64s(&[2, 1]), ZPoly::from_i64s(&[-3, 1]));
/// assert!(Residues::of(&c).proves_coprime(&Residues::of(&d)));
/// // The image of a product is the product of the images.
/// assert_eq!(Residues::of(&c).times(&Residues::of(&d)), Residues::of(&(&c * &d)));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Residues(Vec<u64>);

impl Residues {
    /// `p` modulo the field's prime.
    pub fn of(p: &ZPoly) -> Residues {
        let f = &*FIELD;
        Residues::trimmed(p.coeffs().iter().map(|c| f.enter(c.mod_u64(f.p))).collect())
    }

    /// `p` modulo the field's prime, and whether the image keeps `p`'s
    /// degree (the prime does not divide `lc(p)`).
    pub fn image(p: &ZPoly) -> (Residues, bool) {
        let r = Residues::of(p);
        let kept = r.degree() == p.degree();
        (r, kept)
    }

    fn trimmed(mut c: Vec<u64>) -> Residues {
        while c.last() == Some(&0) {
            c.pop();
        }
        Residues(c)
    }

    /// The image of the integer `k`.
    fn constant(k: &Int) -> Residues {
        let f = &*FIELD;
        Residues::trimmed(vec![f.enter(k.mod_u64(f.p))])
    }

    /// The field's prime `p` (the first table prime).
    pub fn modulus() -> u64 {
        FIELD.p
    }

    /// The degree (`None` for zero).
    pub fn degree(&self) -> Option<usize> {
        self.0.len().checked_sub(1)
    }

    /// Whether `self = P mod p` and `other = Q mod p` prove `gcd(P, Q) = 1`
    /// (module docs), given that `self`'s degree is that of `P` (the
    /// caller's check that `p ∤ lc(P)`): `other ≠ 0` and the gcd over `F_p`
    /// is a nonzero constant. `false` means "not proven".
    pub fn proves_coprime(&self, other: &Residues) -> bool {
        !self.0.is_empty()
            && !other.0.is_empty()
            && gcd_mod_p(self.0.clone(), other.0.clone(), &FIELD).len() == 1
    }

    /// The monic gcd over `F_p` (zero when both are zero). For images it
    /// proves little by itself: a common factor `h` of `P, Q` over `ℚ`
    /// shows in the images' gcd only when `p ∤ lc(h)`, so a gcd without
    /// `h̄` rules `h` out only as a filter whose "no" may be wrong.
    ///
    /// ```
    /// use ccd_poly::{Residues, ZPoly};
    /// // (t − 1)²(t + 2) and (t − 1)²(t − 3): the gcd's image is (t − 1)².
    /// let a = ZPoly::from_i64s(&[2, -3, 0, 1]);
    /// let b = ZPoly::from_i64s(&[-3, 7, -5, 1]);
    /// let g = Residues::of(&a).gcd(&Residues::of(&b));
    /// assert_eq!(g, Residues::of(&ZPoly::from_i64s(&[1, -2, 1])));
    /// ```
    pub fn gcd(&self, other: &Residues) -> Residues {
        Residues(gcd_mod_p(self.0.clone(), other.0.clone(), &FIELD))
    }

    /// For an image of degree 1, `c·(t − r)`: the primitive `d·t − n` with
    /// `n/d ≡ r (mod p)`, `|n|, d ≤ 2^26` (Wang's rational reconstruction in
    /// machine integers, unique since `2·(2^26)² < p`), or `None` (also for
    /// other degrees): a candidate only, for the caller to prove (a short
    /// root seen modulo `p`). The bound is well below `√p`, so that the
    /// residue of a long root passes for a short one only with odds of
    /// about `2^53/p` (a wrong candidate costs the caller its proof; at
    /// `2^30`, eleven scenes of the stability families paid it).
    ///
    /// ```
    /// use ccd_poly::{Residues, ZPoly};
    /// // 3t − 2 modulo p: back to 3t − 2 (from its root 2/3).
    /// let g = Residues::of(&ZPoly::from_i64s(&[-2, 3]));
    /// assert_eq!(g.linear_candidate(), Some(ZPoly::from_i64s(&[-2, 3])));
    /// ```
    pub fn linear_candidate(&self) -> Option<ZPoly> {
        let f = &*FIELD;
        let [c0, c1] = self.0[..] else {
            return None;
        };
        // The root −c0/c1, in [0, p).
        let root = f.leave(f.mul(f.neg(c0), f.inv(c1)));
        const BOUND: i128 = 1 << 26;
        // Extended Euclid on (p, root), stopped at the first remainder ≤ B.
        let (mut r0, mut r1) = (i128::from(f.p), i128::from(root));
        let (mut t0, mut t1) = (0i128, 1i128);
        while r1 > BOUND {
            let q = r0 / r1;
            (r0, r1) = (r1, r0 - q * r1);
            (t0, t1) = (t1, t0 - q * t1);
        }
        if t1 == 0 || t1.abs() > BOUND {
            return None;
        }
        let (n, d) = if t1 < 0 { (-r1, -t1) } else { (r1, t1) };
        let (n, d) = (i64::try_from(n).ok()?, i64::try_from(d).ok()?);
        Some(ZPoly::from_i64s(&[-n, d]).primitive_part())
    }

    /// The derivative: the image of `P′` (reduction commutes with it).
    pub fn derivative(&self) -> Residues {
        let f = &*FIELD;
        let c = self.0.iter().enumerate().skip(1);
        Residues::trimmed(c.map(|(i, &x)| f.mul(x, f.enter(i as u64 % f.p))).collect())
    }

    /// Whether `self = P mod p`, of `P`'s degree (the caller's check that
    /// `p ∤ lc(P)`), proves `P` squarefree: `gcd(P, P′) = 1` over `ℚ` by
    /// [`Residues::proves_coprime`] (a constant `P` is not proven). `false`
    /// means "not proven".
    pub fn proves_squarefree(&self) -> bool {
        self.proves_coprime(&self.derivative())
    }

    /// Coefficientwise `op`.
    fn zip(&self, o: &Residues, op: impl Fn(&Fp, u64, u64) -> u64) -> Residues {
        let f = &*FIELD;
        let n = self.0.len().max(o.0.len());
        let at = |v: &[u64], i: usize| v.get(i).copied().unwrap_or(0);
        Residues::trimmed((0..n).map(|i| op(f, at(&self.0, i), at(&o.0, i))).collect())
    }
}

impl RingOps for Residues {
    fn zero() -> Self {
        Residues(Vec::new())
    }
    fn one() -> Self {
        Residues::from_i64(1)
    }
    fn from_i64(v: i64) -> Self {
        Residues::constant(&Int::from_i64(v))
    }
    fn is_zero(&self) -> bool {
        self.0.is_empty()
    }
    fn plus(&self, o: &Self) -> Self {
        self.zip(o, Fp::add)
    }
    fn minus(&self, o: &Self) -> Self {
        self.zip(o, Fp::sub)
    }
    fn times(&self, o: &Self) -> Self {
        if self.0.is_empty() || o.0.is_empty() {
            return Residues::zero();
        }
        let f = &*FIELD;
        let mut c = vec![0u64; self.0.len() + o.0.len() - 1];
        for (i, &x) in self.0.iter().enumerate() {
            if x == 0 {
                continue;
            }
            for (slot, &y) in c[i..].iter_mut().zip(&o.0) {
                *slot = f.add(*slot, f.mul(x, y));
            }
        }
        // A field has no zero divisors: the top coefficient is nonzero.
        Residues(c)
    }
    fn negated(&self) -> Self {
        Residues(self.0.iter().map(|&x| FIELD.neg(x)).collect())
    }
    /// The product with `k^{-1}` (`k` small and nonzero, so `p ∤ k`): the
    /// image of the exact quotient whenever `k` divides the integer value.
    fn div_small(&self, k: i64) -> Self {
        let f = &*FIELD;
        let k = Residues::constant(&Int::from_i64(k));
        let inv = f.inv(k.0[0]);
        Residues(self.0.iter().map(|&x| f.mul(x, inv)).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn poly(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    /// Short roots come back exactly (the root 0, negative ones, the
    /// bound `±2^26` itself), a long one (`1/2^30`) does not, and only
    /// degree-1 images are read.
    #[test]
    fn linear_candidates_at_the_bounds() {
        let b = 1i64 << 26;
        for (n, d) in [
            (0, 1),
            (1, 1),
            (-1, 1),
            (-7, 3),
            (b, 1),
            (-b, b - 1),
            (5, b),
        ] {
            let root = ZPoly::from_i64s(&[-n, d]).primitive_part();
            // Any multiple of d·t − n has the same monic image.
            let image = Residues::of(&root.mul_int(&Int::from(-12_345)));
            assert_eq!(image.linear_candidate(), Some(root), "{n}/{d}");
        }
        let long = ZPoly::new(vec![Int::from(-1), Int::one().shl(30)]);
        assert_eq!(Residues::of(&long).linear_candidate(), None);
        assert_eq!(Residues::of(&poly(&[1, 0, 1])).linear_candidate(), None);
        assert_eq!(Residues::of(&poly(&[3])).linear_candidate(), None);
    }

    proptest! {
        /// Roots modulo `p` of every kind: a short root `n/d` itself (it
        /// comes back, primitive), one just beside it (`n/d + k`, `k ≠ 0`
        /// small: a residue that is not short, as a uniform one): a
        /// candidate `d·t − n`, whenever given, has `0 < d ≤ 2^26`,
        /// `|n| ≤ 2^26`, is primitive and has that root (`n ≡ r·d`).
        #[test]
        fn linear_candidates_are_short_roots_of_the_residue(
            n in -(1i64 << 26)..=(1 << 26), d in 1i64..=(1 << 26), k in -3i64..=3,
            uniform in proptest::option::of(0..Residues::modulus()),
        ) {
            let f = &*FIELD;
            let reduce = |x: &Int| f.enter(x.mod_u64(f.p));
            let short = f.mul(reduce(&Int::from(n)), f.inv(reduce(&Int::from(d))));
            let r = match uniform {
                Some(u) => f.enter(u),
                None => f.add(short, reduce(&Int::from(k))),
            };
            let image = Residues::trimmed(vec![f.neg(r), f.one]);
            let bound = Int::from(1i64 << 26);
            match image.linear_candidate() {
                Some(h) => {
                    let (hn, hd) = (-h.coeff(0), h.coeff(1));
                    prop_assert!(hd.is_positive() && hd <= bound && hn.abs() <= bound);
                    prop_assert_eq!(h.primitive_part(), h.clone());
                    prop_assert_eq!(f.mul(reduce(&hn), f.inv(reduce(&hd))), r);
                }
                None => prop_assert!(uniform.is_some() || k != 0, "{}/{}", n, d),
            }
            if uniform.is_none() && k == 0 {
                let root = ZPoly::from_i64s(&[-n, d]).primitive_part();
                prop_assert_eq!(image.linear_candidate(), Some(root));
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        /// The image of the derivative is the derivative of the image, and
        /// a squarefree proof only for a squarefree polynomial (a square
        /// factor is never proven; a product of distinct linear factors
        /// whose leading coefficient the prime does not divide always is).
        #[test]
        fn derivative_and_squarefree_proofs(
            c in proptest::collection::vec(-10_000i64..10_000, 1..9),
            roots in proptest::collection::btree_set(-50i64..50, 1..6),
            twice in any::<bool>(),
        ) {
            let p = poly(&c);
            prop_assert_eq!(Residues::of(&p).derivative(), Residues::of(&p.derivative()));
            let q = roots.iter().fold(ZPoly::one(), |acc, &r| &acc * &poly(&[-r, 1]));
            let q = if twice { &q * &poly(&[-*roots.iter().next().unwrap(), 1]) } else { q };
            let (image, kept) = Residues::image(&q);
            prop_assert!(kept);
            prop_assert_eq!(image.proves_squarefree(), !twice);
        }
    }

    proptest! {
        /// Reduction is a ring homomorphism on the operations closed forms use.
        #[test]
        fn reduction_commutes_with_ring_operations(
            a in proptest::collection::vec(any::<i64>(), 0..8),
            b in proptest::collection::vec(any::<i64>(), 0..8),
            k in prop_oneof![-12i64..=-1, 1i64..=12],
        ) {
            let (a, b) = (poly(&a), poly(&b));
            let (ra, rb) = (Residues::of(&a), Residues::of(&b));
            prop_assert_eq!(ra.plus(&rb), Residues::of(&(&a + &b)));
            prop_assert_eq!(ra.minus(&rb), Residues::of(&(&a - &b)));
            prop_assert_eq!(ra.times(&rb), Residues::of(&(&a * &b)));
            prop_assert_eq!(ra.negated(), Residues::of(&(-&a)));
            let ak = &a * &poly(&[k]);
            prop_assert_eq!(Residues::of(&ak).div_small(k), ra);
        }

        /// A proof of coprimality is never wrong: a common factor `c` of
        /// positive degree is never proven away, and coprime pairs (by the
        /// exact gcd) are proven whenever the image keeps `P`'s degree and
        /// the images are coprime.
        #[test]
        fn coprime_proofs_agree_with_the_exact_gcd(
            a in proptest::collection::vec(-9i64..=9, 1..6),
            b in proptest::collection::vec(-9i64..=9, 1..6),
            c in proptest::collection::vec(-9i64..=9, 2..4),
        ) {
            let (a, b, c) = (poly(&a), poly(&b), poly(&c));
            prop_assume!(c.degree().unwrap_or(0) >= 1 && !a.is_zero());
            let (p, q) = (&a * &c, &b * &c);
            prop_assert!(!Residues::of(&p).proves_coprime(&Residues::of(&q)));
            let proven = Residues::of(&a).proves_coprime(&Residues::of(&b));
            let exact = !b.is_zero() && a.gcd(&b).degree() == Some(0);
            // Small coefficients: p divides no leading coefficient nor the
            // resultant of a and b (below (9·√6)^10 < 2^45 < p by Hadamard's
            // bound), so the images keep the gcd's degree: proofs and
            // truth agree.
            prop_assert_eq!(proven, exact);
        }
    }
}
