//! The quartic characteristic polynomial: the closed forms of Section 4 for
//! the five subresultant coefficients Theorem 3.10 reads. (The sign logic
//! of Theorem 3.10 / Table 2 that reads them is the crate `ccd-classify`.)
//!
//! Throughout, the quartic is `f(λ) = e·λ⁴ + a·λ³ + b·λ² + c·λ + d`, given
//! HIGH→LOW as `[e, a, b, c, d]` (unlike the LOW→HIGH slices of
//! [`crate::habicht`]). For two ellipsoids, `f = det(λA + B)` and
//! `e = det A < 0`; the paper works with the monic `f / e`.

use ccd_arith::RingOps;

/// The five quantities of Theorem 3.10 for a quartic, as computed by
/// [`closed_forms`]: the coefficients `sr22`, `sr20` of
/// `sr_2(λ) = sr22 λ² + sr21 λ + sr20`, `sr11`, `sr10` of
/// `sr_1(λ) = sr11 λ + sr10`, and `sr0`, of the signed subresultant
/// sequence of f and f' (eq. (1)–(2)), each up to a fixed positive factor
/// (see [`closed_forms`]).
#[derive(Clone, Debug, PartialEq)]
pub struct QuarticInvariants<R> {
    /// `Δ2`, a positive multiple of the leading coefficient of `sr_2`.
    pub sr22: R,
    /// `−W3`, a positive multiple of the constant coefficient of `sr_2`.
    pub sr20: R,
    /// `T`, a positive multiple of the leading coefficient of `sr_1`.
    pub sr11: R,
    /// `T2`, a positive multiple of the constant coefficient of `sr_1`.
    pub sr10: R,
    /// `Δ1`, a positive multiple of `sr_0` (the discriminant).
    pub sr0: R,
}

impl<R> QuarticInvariants<R> {
    /// The value for `q`, or `None` for [`Quantity::Var`] (which depends on
    /// the quartic's coefficients, not on the subresultants).
    pub fn get(&self, q: Quantity) -> Option<&R> {
        match q {
            Quantity::Sr22 => Some(&self.sr22),
            Quantity::Sr20 => Some(&self.sr20),
            Quantity::Sr11 => Some(&self.sr11),
            Quantity::Sr10 => Some(&self.sr10),
            Quantity::Sr0 => Some(&self.sr0),
            Quantity::Var => None,
        }
    }
}

/// The Section 4 closed forms (Emiris & Tsigaridas 2008, from the
/// Bezoutian) for `sr22, sr20, sr11, sr10, sr0` of the quartic
/// `e·λ⁴ + a·λ³ + b·λ² + c·λ + d`, given HIGH→LOW as `[e, a, b, c, d]`;
/// `e` may have either sign. (The forms are polynomials, so nothing breaks
/// where `e` vanishes — e.g. at isolated t over `Z[t]` — but the relations
/// to the monic quartic below need `e ≠ 0`.)
///
/// # Formulas
/// The paper sets `b̄ = −a/4, c̄ = b/6, d̄ = −c/4, ē = d` for the monic
/// quartic. To stay exact over rings without 1/4 and 1/6 (`Int`, `Z[t]`),
/// this uses the *homogeneous* forms with every input scaled by 12:
///
/// ```text
/// ā = 12e, b̄ = −3a, c̄ = 2b, d̄ = −3c, ē = 12d
/// Δ2 = b̄² − ā c̄        Δ3 = c̄² − b̄ d̄
/// W1 = ā d̄ − b̄ c̄       W3 = ā ē − b̄ d̄
/// A  = W3 + 3Δ3         B  = −d̄ W1 − ē Δ2 − c̄ Δ3
/// T  = −9 W1² + 27 Δ2 Δ3 − 3 W3 Δ2 = 3 Δ2 (9Δ3 − W3) − 9 W1²
/// T2 = A W1 − 3 b̄ B     Δ1 = A³ − 27 B²
/// sr22 = Δ2, sr20 = −W3, sr11 = T, sr10 = T2, sr0 = Δ1
/// ```
///
/// With `ā = 1` and the paper's b̄, c̄, d̄, ē these are exactly the Section 4
/// formulas. (The paper also lists `W2 = b̄ ē − c̄ d̄`, which none of the five
/// uses; it is not computed.)
///
/// # Relation to the determinants of Definition 2.2
/// Write `sr_q(f)` for the generic determinants (the coefficients of
/// [`crate::subresultants_with_derivative`]) and `deg = (2, 2, 4, 4, 6)` for
/// the degrees of the five forms, which are homogeneous in `(e, a, b, c, d)`.
/// Then, checked symbolically and asserted by the tests,
///
/// * monic (`e = 1`, the paper's setting): `closed = K · sr_q(f)` with
///   `K = (3, 9, 324, 108, 11664)` for `(sr22, sr20, sr11, sr10, sr0)`
///   (11664 = 108² = 2⁴·3⁶); in particular eq. (2) is recovered up to
///   these positive constants, as the paper's "up to a positive constant
///   multiple" says;
/// * any `e ≠ 0`: `closed(e, a, b, c, d) = K · e^deg · sr_q(f / e)`, an
///   EVEN power of e (2, 2, 4, 4, 6), because homogeneity gives
///   `H(e, a, b, c, d) = e^deg · H(1, a/e, b/e, c/e, d/e)`;
/// * equivalently, against the determinants of the non-monic `f` itself
///   (each of which is homogeneous of degree `deg + 1` and divisible by
///   the leading coefficient): `e · closed = K · sr_q(f)`. Those raw
///   determinants therefore have the sign of `e · closed`, which flips
///   when `e < 0`.
///
/// The ratios the proof of Theorem 3.10 uses survive with small factors:
/// the double root of case (2a) is `λ0 = −sr10/sr11 = −3·T2/T`, and the
/// product of the two double roots in case (2b) is
/// `λ0 λ1 = sr20/sr22 = −W3/(3Δ2)`.
///
/// So the signs returned here are the signs of the paper's `sr_ij` of the
/// monic `f / e`, whatever the sign of `e`: dividing by `e = det A` (which
/// is negative for an ellipsoid) never changes a sign of an even-degree
/// form, which is why the engine never needs to divide by `det A`, and may
/// feed `det(λA + B)` straight in. (Do not feed `det(λA + B)` to
/// [`crate::subresultants_with_derivative`] and read signs off it without
/// correcting by `sign(e)`.)
///
/// # Cost
/// 17 general ring multiplications: `b̄d̄` (shared by Δ3 and W3), `b̄²`,
/// `āc̄`, `c̄²`, `ād̄`, `b̄c̄`, `āē` (7); `d̄W1`, `ēΔ2`, `c̄Δ3` for B (3);
/// `W1²`, `Δ2·(9Δ3 − W3)` for T (2); `AW1`, `b̄B` for T2 (2); `A²`, `A³`,
/// `B²` for Δ1 (3). Not counted: 11 multiplications by the small constants
/// 12, −3, 2, −3, 12 (inputs), 3 (in A), 3, 9, 9 (in T), 3 (in T2) and 27
/// (in Δ1); 11 additions or subtractions and 2 negations. The paper counts
/// 28 multiplications and 12 additions for its (monic, fractional)
/// version, which also computes the unused W2 and neither shares `b̄d̄` nor
/// factors T.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::closed_forms;
/// // −2·(λ+1)(λ+2)(λ−1)(λ−3): two negative and two distinct positive roots,
/// // scaled by a negative leading coefficient; sr22, sr11, sr0 > 0 as for
/// // the monic quartic (Theorem 3.10(1a)).
/// let f = [-2, 2, 14, -2, -12].map(Int::from);
/// let inv = closed_forms(&f);
/// assert_eq!([&inv.sr22, &inv.sr11, &inv.sr0].map(Int::signum), [1, 1, 1]);
/// ```
pub fn closed_forms<R: RingOps>(coeffs: &[R; 5]) -> QuarticInvariants<R> {
    let x = Barred::of(coeffs);
    let bd = x.bb.times(&x.db);
    let (delta2, delta3, w1, w3) = (x.delta2(), x.delta3(&bd), x.w1(), x.w3(&bd));
    let big_a = Barred::big_a(&w3, &delta3);
    let big_b = x.big_b(&w1, &delta2, &delta3);
    QuarticInvariants {
        sr11: Barred::t(&delta2, &delta3, &w1, &w3),
        sr10: x.t2(&big_a, &w1, &big_b),
        sr0: Barred::delta1(&big_a, &big_b),
        sr22: delta2,
        sr20: w3.negated(),
    }
}

/// One closed form of [`closed_forms`] (`None` for [`Quantity::Var`]),
/// with only the products it needs: 2 for `sr22` and `sr20`, 8 for `sr11`,
/// 11 for `sr10`, 13 for `sr0`. For reading one quantity at a point, or as
/// a polynomial when the others are needed only as signs at a few points.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::{closed_form, closed_forms, Quantity};
/// let f = [-2, 2, 14, -2, -12].map(Int::from);
/// assert_eq!(closed_form(&f, Quantity::Sr0), Some(closed_forms(&f).sr0));
/// assert_eq!(closed_form(&f, Quantity::Sr10), Some(closed_forms(&f).sr10));
/// ```
pub fn closed_form<R: RingOps>(coeffs: &[R; 5], q: Quantity) -> Option<R> {
    let x = Barred::of(coeffs);
    if q == Quantity::Sr22 {
        return Some(x.delta2());
    }
    let bd = x.bb.times(&x.db);
    let w3 = x.w3(&bd);
    if q == Quantity::Sr20 {
        return Some(w3.negated());
    }
    let (delta2, delta3, w1) = (x.delta2(), x.delta3(&bd), x.w1());
    match q {
        Quantity::Sr11 => Some(Barred::t(&delta2, &delta3, &w1, &w3)),
        Quantity::Sr10 | Quantity::Sr0 => {
            let big_a = Barred::big_a(&w3, &delta3);
            let big_b = x.big_b(&w1, &delta2, &delta3);
            Some(if q == Quantity::Sr10 {
                x.t2(&big_a, &w1, &big_b)
            } else {
                Barred::delta1(&big_a, &big_b)
            })
        }
        _ => None,
    }
}

/// The isobaric weight of a closed form: with `f = Σ a_k λ^k`, replacing
/// `λ` by `s·λ` (`a_k → s^k·a_k`) multiplies `q` by `s^weight`. The exact
/// path balances the magnitudes of `f`'s coefficients this way (a power of
/// two `s`, so exactly) before evaluating a closed form in floating point.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::{closed_form, isobaric_weight, Quantity};
/// let f = [3, -7, 11, 5, -13].map(Int::from); // a_4 … a_0
/// let g: [Int; 5] = std::array::from_fn(|i| &f[i] * &Int::from(1 << (4 - i)));
/// let q = Quantity::Sr10;
/// let scaled = closed_form(&f, q).unwrap().shl(isobaric_weight(q));
/// assert_eq!(closed_form(&g, q).unwrap(), scaled);
/// ```
pub fn isobaric_weight(q: Quantity) -> u64 {
    match q {
        Quantity::Sr22 => 6,
        Quantity::Sr20 => 4,
        Quantity::Sr11 => 10,
        Quantity::Sr10 => 9,
        Quantity::Sr0 => 12,
        Quantity::Var => 0,
    }
}

/// The degree of a closed form as a homogeneous polynomial in the
/// quartic's five coefficients (`Var`: 0): `closed_form(s·f) =
/// s^degree · closed_form(f)`. Hence `|q| < 2^(degree·bits + slack)` for
/// coefficients of at most `bits` bits, a cheap size estimate.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::{closed_form, homogeneous_degree, Quantity};
/// let f = [3, -7, 11, 5, -13].map(Int::from);
/// let g = f.clone().map(|x| &x * &Int::from(2));
/// let q = Quantity::Sr0;
/// let scaled = closed_form(&f, q).unwrap().shl(homogeneous_degree(q));
/// assert_eq!(closed_form(&g, q).unwrap(), scaled);
/// ```
pub fn homogeneous_degree(q: Quantity) -> u64 {
    match q {
        Quantity::Sr22 | Quantity::Sr20 => 2,
        Quantity::Sr11 | Quantity::Sr10 => 4,
        Quantity::Sr0 => 6,
        Quantity::Var => 0,
    }
}

/// The scaled coefficients `ā = 12e, b̄ = −3a, c̄ = 2b, d̄ = −3c, ē = 12d`
/// and the intermediate quantities of the closed forms built from them.
struct Barred<R> {
    ab: R,
    bb: R,
    cb: R,
    db: R,
    eb: R,
}

impl<R: RingOps> Barred<R> {
    fn of(coeffs: &[R; 5]) -> Barred<R> {
        let [e, a, b, c, d] = coeffs;
        let k = |v: i64| R::from_i64(v);
        Barred {
            ab: k(12).times(e),
            bb: k(-3).times(a),
            cb: k(2).times(b),
            db: k(-3).times(c),
            eb: k(12).times(d),
        }
    }
    /// `Δ2 = b̄² − āc̄`.
    fn delta2(&self) -> R {
        self.bb.times(&self.bb).minus(&self.ab.times(&self.cb))
    }
    /// `Δ3 = c̄² − b̄d̄`.
    fn delta3(&self, bd: &R) -> R {
        self.cb.times(&self.cb).minus(bd)
    }
    /// `W1 = ād̄ − b̄c̄`.
    fn w1(&self) -> R {
        self.ab.times(&self.db).minus(&self.bb.times(&self.cb))
    }
    /// `W3 = āē − b̄d̄`.
    fn w3(&self, bd: &R) -> R {
        self.ab.times(&self.eb).minus(bd)
    }
    /// `A = W3 + 3Δ3`.
    fn big_a(w3: &R, delta3: &R) -> R {
        w3.plus(&R::from_i64(3).times(delta3))
    }
    /// `B = −(d̄W1 + ēΔ2 + c̄Δ3)`.
    fn big_b(&self, w1: &R, delta2: &R, delta3: &R) -> R {
        self.db
            .times(w1)
            .plus(&self.eb.times(delta2))
            .plus(&self.cb.times(delta3))
            .negated()
    }
    /// `T = 3Δ2(9Δ3 − W3) − 9W1²` (`sr11`).
    fn t(delta2: &R, delta3: &R, w1: &R, w3: &R) -> R {
        let k = |v: i64| R::from_i64(v);
        k(3).times(delta2)
            .times(&k(9).times(delta3).minus(w3))
            .minus(&k(9).times(&w1.times(w1)))
    }
    /// `T2 = A·W1 − 3b̄B` (`sr10`).
    fn t2(&self, big_a: &R, w1: &R, big_b: &R) -> R {
        big_a
            .times(w1)
            .minus(&R::from_i64(3).times(&self.bb.times(big_b)))
    }
    /// `Δ1 = A³ − 27B²` (`sr0`).
    fn delta1(big_a: &R, big_b: &R) -> R {
        big_a
            .times(big_a)
            .times(big_a)
            .minus(&R::from_i64(27).times(&big_b.times(big_b)))
    }
}

/// One input of the Theorem 3.10 decision (as asked for by
/// `ccd_classify::classify_with`): one of the five closed forms, or the
/// sign variations of the quartic's coefficients.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// Sign of `sr22`, the leading coefficient of `sr_2`.
    Sr22,
    /// Sign of `sr20`, the constant coefficient of `sr_2`.
    Sr20,
    /// Sign of `sr11`, the leading coefficient of `sr_1`.
    Sr11,
    /// Sign of `sr10`, the constant coefficient of `sr_1`.
    Sr10,
    /// Sign of `sr0` (the discriminant, up to a positive factor).
    Sr0,
    /// The NUMBER of sign variations `Var(e, a, b, c, d)` of the quartic's
    /// coefficients (not a sign).
    Var,
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixtures::{nonzero, positive, quartic, rat, QS};
    use crate::subresultants_with_derivative;
    use ccd_arith::{Int, Rat, Ring};
    use proptest::prelude::*;

    /// closed form = K · generic determinant, for monic quartics.
    const K: [i64; 5] = [3, 9, 324, 108, 11664];

    fn closed<R: Ring>(f: &[R; 5]) -> [R; 5] {
        let inv = closed_forms(f);
        QS.map(|q| inv.get(q).unwrap().clone())
    }

    /// `(sr22, sr20, sr11, sr10, sr0)` from the determinants of
    /// Definition 2.2 for `[e, a, b, c, d]` and its derivative.
    fn generic<R: Ring>(f: &[R; 5]) -> [R; 5] {
        let low: Vec<R> = f.iter().rev().cloned().collect();
        let sr = subresultants_with_derivative(&low);
        [
            sr[2][2].clone(),
            sr[2][0].clone(),
            sr[1][1].clone(),
            sr[1][0].clone(),
            sr[0][0].clone(),
        ]
    }

    fn pow<R: Ring>(x: &R, k: u32) -> R {
        (0..k).fold(R::one(), |acc, _| acc.times(x))
    }

    proptest! {
        /// Isobaric: `λ → s·λ` (`a_k → s^k·a_k`) multiplies each closed
        /// form by `s^isobaric_weight` (integer coefficients, `s` of either
        /// sign; the test fails for any other weight).
        #[test]
        fn closed_forms_are_isobaric(raw in proptest::collection::vec(-99i64..99, 5), s in -7i64..8) {
            let f: [Int; 5] = std::array::from_fn(|i| Int::from(raw[i]));
            let g: [Int; 5] = std::array::from_fn(|i| &f[i] * &Int::from(s).pow(4 - i as u32));
            let (a, b) = (closed(&f), closed(&g));
            for q in 0..5 {
                let w = isobaric_weight(QS[q]) as u32;
                prop_assert_eq!(&b[q], &(&a[q] * &Int::from(s).pow(w)), "{:?}", QS[q]);
            }
        }

        /// Test 3, monic: closed form = K · generic determinant.
        #[test]
        fn closed_forms_are_positive_multiples_monic(a in rat(), b in rat(), c in rat(), d in rat()) {
            let f = [Rat::one(), a, b, c, d];
            let (cl, ge) = (closed(&f), generic(&f));
            for q in 0..5 {
                prop_assert_eq!(&cl[q], &ge[q].times(&Rat::from(K[q])), "{:?}", QS[q]);
            }
        }

        /// Test 3, non-monic: closed(f) = K · e^deg · generic(f / e) (even
        /// powers), and e · closed(f) = K · generic(f).
        #[test]
        fn closed_forms_non_monic(e in nonzero(), a in rat(), b in rat(), c in rat(), d in rat()) {
            let f = [e.clone(), a, b, c, d];
            let monic = f.clone().map(|x| &x / &e);
            let (cl, ge, ge_monic) = (closed(&f), generic(&f), generic(&monic));
            for q in 0..5 {
                let k = Rat::from(K[q]);
                let deg = homogeneous_degree(QS[q]) as u32;
                prop_assert_eq!(&cl[q], &k.times(&pow(&e, deg)).times(&ge_monic[q]));
                prop_assert_eq!(&e.times(&cl[q]), &k.times(&ge[q]));
            }
        }

        /// The same identity over Int, where every division is exact.
        #[test]
        fn closed_forms_non_monic_over_int(f in prop::array::uniform5(-50i64..=50)) {
            prop_assume!(f[0] != 0);
            let f = f.map(Int::from);
            let (cl, ge) = (closed(&f), generic(&f));
            for q in 0..5 {
                prop_assert_eq!(&f[0] * &cl[q], &ge[q] * &Int::from(K[q]));
            }
        }

        /// Test 4, Lemma 2.3 with one double root ρ: sr0 = 0 and
        /// sr1 = sr11 (λ − ρ) with sr11 ≠ 0; for the closed forms,
        /// 3·sr10 = −ρ·sr11.
        #[test]
        fn lemma_2_3_double_root(e in nonzero(), rho in rat(), s in rat(), d1 in positive(), d2 in positive()) {
            prop_assume!(rho != s && rho != &s + &d1 && rho != (&s + &d1) + &d2);
            let t = &s + &d1;
            let f = quartic(&e, &[rho.clone(), rho.clone(), s, t], &[]);
            let ge = generic(&f);
            prop_assert!(ge[4].is_zero());
            prop_assert!(!ge[2].is_zero());
            prop_assert_eq!(&ge[3], &-(&rho * &ge[2]));
            let cl = closed(&f);
            prop_assert!(cl[4].is_zero());
            prop_assert_eq!(&cl[3].times(&Rat::from(3)), &-(&rho * &cl[2]));
        }

        /// Test 4, Lemma 2.3 with two double roots ρ, σ: sr1 ≡ 0, sr0 = 0 and
        /// sr2 = sr22 (λ − ρ)(λ − σ); for the closed forms
        /// sr20 = 3 ρσ · sr22.
        #[test]
        fn lemma_2_3_two_double_roots(e in nonzero(), rho in rat(), gap in positive()) {
            let sigma = &rho + &gap;
            let f = quartic(&e, &[rho.clone(), rho.clone(), sigma.clone(), sigma.clone()], &[]);
            let low: Vec<Rat> = f.iter().rev().cloned().collect();
            let sr = subresultants_with_derivative(&low);
            prop_assert!(sr[0][0].is_zero() && sr[1].iter().all(Rat::is_zero));
            let lead = sr[2][2].clone();
            prop_assert!(!lead.is_zero());
            let expected = [&rho * &sigma, -(&rho + &sigma), Rat::one()].map(|x| x.times(&lead));
            prop_assert_eq!(&sr[2], &expected.to_vec());
            let cl = closed(&f);
            prop_assert!(cl[2].is_zero() && cl[3].is_zero() && cl[4].is_zero());
            prop_assert_eq!(&cl[1], &Rat::from(3).times(&rho).times(&sigma).times(&cl[0]));
        }

        /// Lemma 2.3 with a triple root: gcd(f, f') = (λ − ρ)², again of
        /// degree 2; with a quadruple root sr22 = sr11 = sr0 = 0 (Lemma 3.8(4)).
        #[test]
        fn lemma_2_3_triple_and_quadruple(e in nonzero(), rho in rat(), gap in nonzero()) {
            let sigma = &rho + &gap;
            let f = quartic(&e, &[rho.clone(), rho.clone(), rho.clone(), sigma], &[]);
            let low: Vec<Rat> = f.iter().rev().cloned().collect();
            let sr = subresultants_with_derivative(&low);
            prop_assert!(sr[0][0].is_zero() && sr[1].iter().all(Rat::is_zero));
            let lead = sr[2][2].clone();
            prop_assert!(!lead.is_zero());
            let expected = [&rho * &rho, Rat::from(-2).times(&rho), Rat::one()].map(|x| x.times(&lead));
            prop_assert_eq!(&sr[2], &expected.to_vec());

            let f = quartic(&e, &[rho.clone(), rho.clone(), rho.clone(), rho], &[]);
            let cl = closed(&f);
            prop_assert!(cl[0].is_zero() && cl[2].is_zero() && cl[4].is_zero());
            let ge = generic(&f);
            prop_assert!(ge[0].is_zero() && ge[2].is_zero() && ge[4].is_zero());
        }
    }

    /// Test 3 over `Z[t]`: coefficients are polynomials in t, as for two
    /// moving ellipsoids (Section 5).
    mod over_zpoly {
        use super::*;
        use ccd_poly::ZPoly;

        fn zpoly() -> impl Strategy<Value = ZPoly> {
            prop::collection::vec(-9i64..=9, 0..=5).prop_map(|c| ZPoly::from_i64s(&c))
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(48))]

            /// Monic in λ: closed form = K · generic determinant in Z[t].
            #[test]
            fn monic_in_lambda(a in zpoly(), b in zpoly(), c in zpoly(), d in zpoly()) {
                let f = [ZPoly::one(), a, b, c, d];
                let (cl, ge) = (closed(&f), generic(&f));
                for q in 0..5 {
                    prop_assert_eq!(&cl[q], &ge[q].times(&ZPoly::from_i64(K[q])), "{:?}", QS[q]);
                }
            }

            /// Leading coefficient e(t) = (t − t0)·u(t), vanishing at t0:
            /// e · closed = K · generic in Z[t], and both specialise at
            /// every t — including t0, where the formal degree 4 is kept.
            #[test]
            fn non_monic_and_specialisation(
                t0 in -3i64..=3, u in zpoly(), a in zpoly(), b in zpoly(), c in zpoly(), d in zpoly(),
            ) {
                prop_assume!(!u.is_zero());
                let e = ZPoly::from_i64s(&[-t0, 1]).times(&u);
                let f = [e.clone(), a, b, c, d];
                let (cl, ge) = (closed(&f), generic(&f));
                for q in 0..5 {
                    prop_assert_eq!(&e.times(&cl[q]), &ge[q].times(&ZPoly::from_i64(K[q])));
                }
                for t in [t0, t0 + 1, -5, 7].map(Int::from) {
                    let ft = f.clone().map(|p| p.eval_int(&t));
                    prop_assert_eq!(closed(&ft), cl.clone().map(|p| p.eval_int(&t)));
                    prop_assert_eq!(generic(&ft), ge.clone().map(|p| p.eval_int(&t)));
                }
            }
        }
    }
}
