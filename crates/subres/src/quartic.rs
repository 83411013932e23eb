//! The quartic characteristic polynomial: the closed forms of Section 4 for
//! the five subresultant coefficients Theorem 3.10 reads, and the sign logic
//! of Theorem 3.10 / Table 2 as one pure decision tree over signs.
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
/// use ccd_subres::{classify, closed_forms, Configuration, SignData};
/// // −2·(λ+1)(λ+2)(λ−1)(λ−3): two negative and two distinct positive roots,
/// // scaled by a negative leading coefficient.
/// let f = [-2, 2, 14, -2, -12].map(Int::from);
/// let inv = closed_forms(&f);
/// let s = SignData::from_invariants(&inv, &f, Int::signum);
/// assert_eq!(classify(&s), Configuration::Separate);
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

/// The configuration of two ellipsoids (Theorem 2.1): separate, touching
/// externally (boundaries meet, interiors disjoint), or overlapping
/// (interiors meet).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Configuration {
    /// No common point: f has two distinct positive roots.
    Separate,
    /// Common boundary points only: f has a positive double root.
    ExternalTouch,
    /// Common interior points: f has no positive root.
    Overlap,
}

/// One input of the Theorem 3.10 decision, as asked for by
/// [`classify_with`].
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

/// The signs (−1, 0 or 1) of `sr22, sr20, sr11, sr10, sr0` and the number
/// of sign variations `var = Var(e, a, b, c, d)` of the quartic's
/// coefficients: everything Theorem 3.10 / Table 2 reads.
///
/// Signs of the closed forms ([`closed_forms`]) are the signs of the
/// paper's quantities of the monic `f / e` for any `e`, and
/// `Var(e, a, b, c, d) = Var(1, a/e, b/e, c/e, d/e)` because negating a
/// whole sequence does not change its sign variations — so the data can be
/// taken straight from the non-monic `det(λA + B)`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignData {
    /// Sign of `sr22`.
    pub sr22: i32,
    /// Sign of `sr20`.
    pub sr20: i32,
    /// Sign of `sr11`.
    pub sr11: i32,
    /// Sign of `sr10`.
    pub sr10: i32,
    /// Sign of `sr0`.
    pub sr0: i32,
    /// `Var(e, a, b, c, d)`, see [`sign_variations`].
    pub var: usize,
}

impl SignData {
    /// The sign data of a quartic `[e, a, b, c, d]` (HIGH→LOW) and its
    /// invariants (normally `closed_forms(coeffs)`), with `sign` the sign
    /// function of the ring (−1, 0, 1).
    pub fn from_invariants<R>(
        inv: &QuarticInvariants<R>,
        coeffs: &[R; 5],
        mut sign: impl FnMut(&R) -> i32,
    ) -> SignData {
        let coefficient_signs = coeffs.each_ref().map(&mut sign);
        SignData {
            sr22: sign(&inv.sr22),
            sr20: sign(&inv.sr20),
            sr11: sign(&inv.sr11),
            sr10: sign(&inv.sr10),
            sr0: sign(&inv.sr0),
            var: sign_variations(&coefficient_signs),
        }
    }

    /// The value [`classify_with`] expects for `q`: a sign, or the count
    /// `var` for [`Quantity::Var`].
    pub fn get(&self, q: Quantity) -> i32 {
        match q {
            Quantity::Sr22 => self.sr22,
            Quantity::Sr20 => self.sr20,
            Quantity::Sr11 => self.sr11,
            Quantity::Sr10 => self.sr10,
            Quantity::Sr0 => self.sr0,
            Quantity::Var => i32::try_from(self.var).unwrap_or(i32::MAX),
        }
    }
}

/// `Var(s)`: the number of sign changes in the sequence of signs `s`
/// (any negative value counts as −, any positive as +), zeros skipped —
/// Descartes' rule of signs (Proposition 3.1) and Table 1.
///
/// ```
/// use ccd_subres::sign_variations;
/// assert_eq!(sign_variations(&[1, -1, 0, 1, 1]), 2);
/// assert_eq!(sign_variations(&[0, 0, 0]), 0);
/// ```
pub fn sign_variations(signs: &[i32]) -> usize {
    let mut nonzero = signs.iter().filter(|s| **s != 0).map(|s| s.signum());
    let Some(mut last) = nonzero.next() else {
        return 0;
    };
    let mut count = 0;
    for s in nonzero {
        if s != last {
            count += 1;
            last = s;
        }
    }
    count
}

/// Theorem 3.10 / Table 2: the configuration from the sign data.
///
/// Exactly the rows of Table 2, everything else Overlap:
///
/// | Var | sr22 | sr20 | sr11 | sr10 | sr0 | configuration |
/// |-----|------|------|------|------|-----|---------------|
/// | 2   | > 0  |      | > 0  |      | > 0 | Separate (3.10(1a)) |
/// | 2   | > 0  |      | > 0  | > 0  | = 0 | Separate (3.10(1b)) |
/// |     | > 0  |      | > 0  | < 0  | = 0 | ExternalTouch (3.10(2a)) |
/// |     | > 0  | < 0  | = 0  |      | = 0 | ExternalTouch (3.10(2b)) |
///
/// The touch rows do not read Var (Theorem 3.10(2)). This is
/// [`classify_with`] over stored data, so the two cannot disagree.
///
/// ```
/// use ccd_subres::{classify, Configuration, SignData};
/// let s = SignData { sr22: 1, sr20: -1, sr11: 0, sr10: 0, sr0: 0, var: 0 };
/// assert_eq!(classify(&s), Configuration::ExternalTouch);
/// ```
pub fn classify(s: &SignData) -> Configuration {
    match classify_with(|q| Ok::<i32, std::convert::Infallible>(s.get(q))) {
        Ok(c) => c,
        Err(never) => match never {},
    }
}

/// Theorem 3.10 / Table 2 with lazily computed inputs: `sign(q)` is called
/// only for the quantities the decision needs, each at most once, and its
/// first error is returned as is (e.g. an interval evaluation that cannot
/// decide a sign).
///
/// `sign(q)` must return the sign (−1, 0, 1; only the sign of the value is
/// used) of `q`, or for [`Quantity::Var`] the number of sign variations
/// `Var(e, a, b, c, d)`.
///
/// Order of the questions (each step only if the previous ones have not
/// decided):
/// 1. `Sr22` — `≤ 0` is Overlap (Lemma 3.9);
/// 2. `Sr11` — `< 0` is Overlap;
/// 3. `Sr0`;
/// 4. if `sr11 > 0, sr0 = 0`: `Sr10` — `< 0` is ExternalTouch (3.10(2a)),
///    `= 0` Overlap (a double root at λ = 0, impossible for ellipsoids),
///    `> 0` a separate candidate (3.10(1b));
///    if `sr11 = 0, sr0 = 0`: `Sr20` — `< 0` is ExternalTouch (3.10(2b)),
///    otherwise Overlap;
///    if `sr11 > 0, sr0 > 0`: a separate candidate (3.10(1a));
///    otherwise (`sr0 < 0`, or `sr11 = 0` and `sr0 ≠ 0`) Overlap;
/// 5. for a separate candidate only: `Var` — `= 2` is Separate, otherwise
///    Overlap.
///
/// So `Sr20` is asked only when `sr11 = sr0 = 0`, `Sr10` only when
/// `sr11 > 0` and `sr0 = 0`, and `Var` only for the two separate rows.
///
/// ```
/// use ccd_subres::{classify_with, Configuration, Quantity};
/// let mut asked = Vec::new();
/// let c = classify_with(|q| {
///     asked.push(q);
///     Ok::<_, ()>(match q { Quantity::Sr22 | Quantity::Sr11 | Quantity::Sr0 => 1, _ => 2 })
/// });
/// assert_eq!(c, Ok(Configuration::Separate));
/// assert_eq!(asked, [Quantity::Sr22, Quantity::Sr11, Quantity::Sr0, Quantity::Var]);
/// ```
pub fn classify_with<E>(
    mut sign: impl FnMut(Quantity) -> Result<i32, E>,
) -> Result<Configuration, E> {
    use Configuration::{ExternalTouch, Overlap, Separate};
    if sign(Quantity::Sr22)? <= 0 {
        return Ok(Overlap);
    }
    let sr11 = sign(Quantity::Sr11)?;
    if sr11 < 0 {
        return Ok(Overlap);
    }
    let sr0 = sign(Quantity::Sr0)?;
    let separate_candidate = match (sr11 > 0, sr0.signum()) {
        (true, 1) => true,
        (true, 0) => match sign(Quantity::Sr10)?.signum() {
            1 => true,
            -1 => return Ok(ExternalTouch),
            _ => return Ok(Overlap),
        },
        (false, 0) => {
            return Ok(if sign(Quantity::Sr20)? < 0 {
                ExternalTouch
            } else {
                Overlap
            })
        }
        _ => false,
    };
    if separate_candidate && sign(Quantity::Var)? == 2 {
        Ok(Separate)
    } else {
        Ok(Overlap)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::subresultants_with_derivative;
    use ccd_arith::{Int, Rat, Ring};
    use proptest::prelude::*;

    /// The five quantities in the order of [`QuarticInvariants`].
    const QS: [Quantity; 5] = [
        Quantity::Sr22,
        Quantity::Sr20,
        Quantity::Sr11,
        Quantity::Sr10,
        Quantity::Sr0,
    ];
    /// closed form = K · generic determinant, for monic quartics.
    const K: [i64; 5] = [3, 9, 324, 108, 11664];
    /// Homogeneous degree of each closed form in (e, a, b, c, d).
    const DEG: [u32; 5] = [2, 2, 4, 4, 6];

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

    fn r(p: i64, q: i64) -> Rat {
        Rat::from_frac(p, q)
    }

    fn rat() -> impl Strategy<Value = Rat> {
        (-30i64..=30, 1i64..=9).prop_map(|(p, q)| r(p, q))
    }
    fn positive() -> impl Strategy<Value = Rat> {
        (1i64..=40, 1i64..=8).prop_map(|(p, q)| r(p, q))
    }
    fn negative() -> impl Strategy<Value = Rat> {
        positive().prop_map(|x| -x)
    }
    fn nonzero() -> impl Strategy<Value = Rat> {
        (positive(), any::<bool>()).prop_map(|(x, neg)| if neg { -x } else { x })
    }

    /// `e · Π (λ − ρ)` over the given real roots times the given monic
    /// quadratic factors `λ² + sλ + p` (as `(s, p)`), HIGH→LOW.
    fn quartic(e: &Rat, roots: &[Rat], quadratics: &[(Rat, Rat)]) -> [Rat; 5] {
        let mut low = vec![e.clone()];
        let mut mul = |factor: &[Rat]| {
            let mut out = vec![Rat::zero(); low.len() + factor.len() - 1];
            for (i, x) in low.iter().enumerate() {
                for (j, y) in factor.iter().enumerate() {
                    out[i + j] = out[i + j].plus(&x.times(y));
                }
            }
            low = out;
        };
        for root in roots {
            mul(&[-root.clone(), Rat::one()]);
        }
        for (s, p) in quadratics {
            mul(&[p.clone(), s.clone(), Rat::one()]);
        }
        assert_eq!(low.len(), 5, "not a quartic");
        std::array::from_fn(|k| low[4 - k].clone())
    }

    /// `λ² − 2uλ + u² + v²`, roots `u ± iv`.
    fn complex_pair(u: &Rat, v: &Rat) -> (Rat, Rat) {
        (Rat::from(-2).times(u), u.times(u).plus(&v.times(v)))
    }

    fn signs(f: &[Rat; 5]) -> SignData {
        SignData::from_invariants(&closed_forms(f), f, Rat::signum)
    }

    proptest! {
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
                prop_assert_eq!(&cl[q], &k.times(&pow(&e, DEG[q])).times(&ge_monic[q]));
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

    /// The root patterns of Theorem 2.1 (two negative roots plus …), with
    /// the configuration they imply and, for the degenerate patterns of
    /// Lemma 3.8, the row of Table 2 that must decide them.
    #[derive(Debug, Clone)]
    enum Pattern {
        /// Distinct negatives + two distinct positives.
        Separate,
        /// Negative double root + two distinct positives (via sr10 > 0).
        SeparateNegativeDouble,
        /// Distinct negatives + positive double root (via sr10 < 0).
        Touch,
        /// Negative double + positive double root (via sr20 < 0).
        TouchTwoDoubles,
        /// Two negatives + a complex pair (real part of either sign).
        ComplexPair,
        /// Four negative roots, some possibly equal.
        FourNegative,
        /// Negative triple + negative simple root (sr11 = sr0 = 0, sr20 > 0).
        TripleSimple,
        /// Negative quadruple root (sr22 = sr11 = sr0 = 0).
        Quadruple,
    }

    fn pattern() -> impl Strategy<Value = Pattern> {
        prop_oneof![
            Just(Pattern::Separate),
            Just(Pattern::SeparateNegativeDouble),
            Just(Pattern::Touch),
            Just(Pattern::TouchTwoDoubles),
            Just(Pattern::ComplexPair),
            Just(Pattern::FourNegative),
            Just(Pattern::TripleSimple),
            Just(Pattern::Quadruple),
        ]
    }

    proptest! {
        /// Test 5: classify(closed-form signs) agrees with the root pattern
        /// (Theorem 2.1) for any nonzero leading coefficient.
        #[test]
        fn classify_matches_root_patterns(
            pat in pattern(),
            e in nonzero(),
            n in negative(), m in negative(), dn in positive(),
            p in positive(), dp in positive(),
            u in rat(), v in nonzero(),
        ) {
            let n2 = &n - &dn; // distinct from n, negative
            let p2 = &p + &dp; // distinct from p, positive
            let simple_distinct = m != n;
            let (roots, quads, expected) = match pat {
                Pattern::Separate => (vec![n, n2, p, p2], vec![], Configuration::Separate),
                Pattern::SeparateNegativeDouble => (vec![n.clone(), n, p, p2], vec![], Configuration::Separate),
                Pattern::Touch => (vec![n, n2, p.clone(), p], vec![], Configuration::ExternalTouch),
                Pattern::TouchTwoDoubles => (vec![n.clone(), n, p.clone(), p], vec![], Configuration::ExternalTouch),
                Pattern::ComplexPair => (vec![n, m], vec![complex_pair(&u, &v)], Configuration::Overlap),
                Pattern::FourNegative => (vec![n.clone(), m.clone(), n2, if dp > dn { n } else { m }], vec![], Configuration::Overlap),
                Pattern::TripleSimple => (vec![n.clone(), n.clone(), n, m], vec![], Configuration::Overlap),
                Pattern::Quadruple => (vec![n.clone(), n.clone(), n.clone(), n], vec![], Configuration::Overlap),
            };
            let f = quartic(&e, &roots, &quads);
            let s = signs(&f);
            prop_assert_eq!(classify(&s), expected, "{:?} {:?} {:?}", pat, f, s);
            match pat {
                Pattern::SeparateNegativeDouble => prop_assert!(s.sr0 == 0 && s.sr11 > 0 && s.sr10 > 0),
                Pattern::Touch => prop_assert!(s.sr0 == 0 && s.sr11 > 0 && s.sr10 < 0),
                Pattern::TouchTwoDoubles => prop_assert!(s.sr0 == 0 && s.sr11 == 0 && s.sr20 < 0),
                Pattern::TripleSimple if simple_distinct => prop_assert!(s.sr0 == 0 && s.sr11 == 0 && s.sr22 > 0 && s.sr20 > 0),
                Pattern::Quadruple => prop_assert!(s.sr0 == 0 && s.sr11 == 0 && s.sr22 == 0),
                Pattern::ComplexPair if simple_distinct => prop_assert!(s.sr0 < 0),
                Pattern::Separate => prop_assert!(s.sr0 > 0),
                _ => {}
            }
            if matches!(expected, Configuration::Separate | Configuration::ExternalTouch) {
                prop_assert_eq!(s.var, 2);
            }
        }
    }

    /// `(e, real roots, quadratic factors (s, p) = λ² + sλ + p, expected)`.
    type Example = (i64, Vec<i64>, Vec<(i64, i64)>, Configuration);

    /// Fixed instances, one per Table 2 row plus degenerate overlaps.
    #[test]
    fn fixed_examples() {
        let z = |v: i64| Rat::from(v);
        let cases: [Example; 7] = [
            (1, vec![-1, -2, 1, 3], vec![], Configuration::Separate),
            (-2, vec![-1, -1, 1, 3], vec![], Configuration::Separate),
            (3, vec![-1, -2, 2, 2], vec![], Configuration::ExternalTouch),
            (-1, vec![-1, -1, 2, 2], vec![], Configuration::ExternalTouch),
            // A negative double root and the complex pair ±i: sr0 = 0 but
            // sr11 < 0.
            (1, vec![-9, -9], vec![(0, 1)], Configuration::Overlap),
            // Complex pair 1 ± i with positive real part: Var = 2, sr0 < 0.
            (-1, vec![-1, -2], vec![(-2, 2)], Configuration::Overlap),
            (5, vec![-1, -1, -1, -1], vec![], Configuration::Overlap),
        ];
        for (e, roots, quads, expected) in cases {
            let roots: Vec<Rat> = roots.into_iter().map(z).collect();
            let quads: Vec<(Rat, Rat)> = quads.into_iter().map(|(s, p)| (z(s), z(p))).collect();
            let f = quartic(&z(e), &roots, &quads);
            assert_eq!(classify(&signs(&f)), expected, "{f:?}");
        }
    }

    /// Table 2 written out as data (None = the column is blank), the
    /// reference for the decision tree.
    type Row = (Option<usize>, [Option<i32>; 5], Configuration);
    const TABLE_2: [Row; 4] = [
        (
            Some(2),
            [Some(1), None, Some(1), None, Some(1)],
            Configuration::Separate,
        ),
        (
            Some(2),
            [Some(1), None, Some(1), Some(1), Some(0)],
            Configuration::Separate,
        ),
        (
            None,
            [Some(1), None, Some(1), Some(-1), Some(0)],
            Configuration::ExternalTouch,
        ),
        (
            None,
            [Some(1), Some(-1), Some(0), None, Some(0)],
            Configuration::ExternalTouch,
        ),
    ];

    /// Exhaustive: every combination of signs and Var ∈ {0, …, 4} gets the
    /// configuration of the matching Table 2 row (Overlap when none), and
    /// `classify_with` asks only what it documents, each at most once.
    #[test]
    fn decision_tree_is_table_2() {
        let mut combos = 0;
        for code in 0..3usize.pow(5) * 5 {
            let sign = |k: u32| (code / 3usize.pow(k) % 3) as i32 - 1;
            let s = SignData {
                sr22: sign(0),
                sr20: sign(1),
                sr11: sign(2),
                sr10: sign(3),
                sr0: sign(4),
                var: code / 3usize.pow(5),
            };
            let values = [s.sr22, s.sr20, s.sr11, s.sr10, s.sr0];
            let expected = TABLE_2
                .iter()
                .find(|(var, row, _)| {
                    var.is_none_or(|v| v == s.var)
                        && row
                            .iter()
                            .zip(values)
                            .all(|(c, v)| c.is_none_or(|c| c == v))
                })
                .map_or(Configuration::Overlap, |row| row.2);
            let mut asked = Vec::new();
            let got = classify_with(|q| {
                asked.push(q);
                Ok::<_, ()>(s.get(q))
            });
            assert_eq!(got, Ok(expected), "{s:?}");
            assert_eq!(classify(&s), expected);
            let count = |q| asked.iter().filter(|&&a| a == q).count();
            for q in QS.into_iter().chain([Quantity::Var]) {
                assert!(count(q) <= 1, "{q:?} asked twice for {s:?}");
            }
            if count(Quantity::Sr20) == 1 {
                assert!(s.sr22 > 0 && s.sr11 == 0 && s.sr0 == 0);
            }
            if count(Quantity::Sr10) == 1 {
                assert!(s.sr22 > 0 && s.sr11 > 0 && s.sr0 == 0);
            }
            if count(Quantity::Var) == 1 {
                assert!(s.sr22 > 0 && s.sr11 > 0 && (s.sr0 > 0 || (s.sr0 == 0 && s.sr10 > 0)));
            }
            combos += 1;
        }
        assert_eq!(combos, 1215);
    }

    /// Errors from the sign oracle stop the decision at once.
    #[test]
    fn classify_with_propagates_errors() {
        let mut asked = Vec::new();
        let got = classify_with(|q| {
            asked.push(q);
            match q {
                Quantity::Sr22 => Ok(1),
                _ => Err("undecided"),
            }
        });
        assert_eq!(got, Err("undecided"));
        assert_eq!(asked, [Quantity::Sr22, Quantity::Sr11]);
    }

    #[test]
    fn sign_variations_skip_zeros() {
        assert_eq!(sign_variations(&[]), 0);
        assert_eq!(sign_variations(&[1, 0, 0, 1]), 0);
        assert_eq!(sign_variations(&[-1, 0, 5, 0, -3, 2]), 3);
        assert_eq!(sign_variations(&[-1, -2, 3, 0, 7]), 1);
    }
}
