//! The static classifier of two ellipsoids: Theorem 3.10 / Table 2 of
//! Jia, Choi, Mourrain & Wang (CAGD 28, 2011) as one pure decision tree
//! over signs, shared by every caller (exact rationals, polynomials
//! evaluated at algebraic numbers, intervals, floats).
//!
//! It reads the signs of the five quantities `sr22, sr20, sr11, sr10, sr0`
//! of the quartic characteristic polynomial — the Section 4 closed forms of
//! [`ccd_subres::closed_forms`] — and the number of sign variations of the
//! quartic's coefficients:
//!
//! * [`SignData`]: those inputs, stored ([`SignData::from_invariants`]);
//! * [`classify`]: the [`Configuration`] from stored sign data;
//! * [`classify_with`]: the same decision asking for each input lazily;
//! * [`sign_variations`]: `Var(s)` of Proposition 3.1.

#![warn(missing_docs)]

use ccd_subres::{Quantity, QuarticInvariants};

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

/// The signs (−1, 0 or 1) of `sr22, sr20, sr11, sr10, sr0` and the number
/// of sign variations `var = Var(e, a, b, c, d)` of the quartic's
/// coefficients: everything Theorem 3.10 / Table 2 reads.
///
/// Signs of the closed forms ([`ccd_subres::closed_forms`]) are the signs of the
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
    ///
    /// ```
    /// use ccd_arith::Int;
    /// use ccd_classify::{classify, Configuration, SignData};
    /// use ccd_subres::closed_forms;
    /// // −2·(λ+1)(λ+2)(λ−1)(λ−3): two negative and two distinct positive roots,
    /// // scaled by a negative leading coefficient.
    /// let f = [-2, 2, 14, -2, -12].map(Int::from);
    /// let inv = closed_forms(&f);
    /// let s = SignData::from_invariants(&inv, &f, Int::signum);
    /// assert_eq!(classify(&s), Configuration::Separate);
    /// ```
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
/// use ccd_classify::sign_variations;
/// assert_eq!(sign_variations(&[1, -1, 0, 1, 1]), 2);
/// assert_eq!(sign_variations(&[0, 0, 0]), 0);
/// ```
pub fn sign_variations(signs: &[i32]) -> usize {
    ccd_arith::sign_variations(signs.iter().copied())
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
/// use ccd_classify::{classify, Configuration, SignData};
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
/// use ccd_classify::{classify_with, Configuration};
/// use ccd_subres::Quantity;
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
    use ccd_arith::Rat;
    use ccd_subres::closed_forms;
    use ccd_subres::fixtures::{complex_pair, negative, nonzero, positive, quartic, rat, QS};
    use proptest::prelude::*;

    fn signs(f: &[Rat; 5]) -> SignData {
        SignData::from_invariants(&closed_forms(f), f, Rat::signum)
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
