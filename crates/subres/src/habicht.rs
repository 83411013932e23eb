//! Sylvester–Habicht matrices and signed subresultants (Definition 2.2 of
//! Jia, Choi, Mourrain & Wang 2011, after Basu, Pollack & Roy 2006).
//!
//! Polynomials are coefficient slices LOW→HIGH (index = power of λ). The
//! degrees used are the *formal* degrees `n = f.len() − 1`,
//! `m = g.len() − 1`: leading coefficients are never trimmed, so that over a
//! polynomial ring (coefficients in t) the result specialises correctly at
//! every t, including where the leading coefficient vanishes.

use crate::det::determinant;
use ccd_arith::Ring;

fn check_args<R>(f: &[R], g: &[R], i: usize) -> (usize, usize) {
    assert!(
        !f.is_empty() && !g.is_empty(),
        "signed subresultants: f and g must have at least one coefficient"
    );
    let (n, m) = (f.len() - 1, g.len() - 1);
    assert!(
        m <= n,
        "signed subresultants: need deg f = {n} >= deg g = {m}"
    );
    assert!(
        i <= m && i < n,
        "signed subresultants: index i = {i} out of range (need i <= deg g = {m} and i < deg f = {n})"
    );
    (n, m)
}

/// The i-th Sylvester–Habicht matrix `SyHa_i(f, g)` of Definition 2.2, for
/// `f = Σ p_k λ^k` of (formal) degree `n` and `g = Σ q_k λ^k` of degree
/// `m ≤ n`, coefficients LOW→HIGH.
///
/// It has `n + m − 2i` rows and `n + m − i` columns; column `c` holds the
/// coefficients of `λ^(n+m−i−1−c)` (highest power on the left). The rows
/// are, top to bottom,
///
/// * `m − i` rows of f: `λ^(m−i−1) f, …, λ f, f` (so `p_n` runs down the
///   diagonal from the top-left corner), then
/// * `n − i` rows of g in *increasing* power order: `g, λ g, …,
///   λ^(n−i−1) g` (so `q_m` runs down the anti-diagonal and ends in the
///   bottom-left corner).
///
/// This row order is what makes the determinants *signed* subresultants:
/// with it, [`signed_subresultant`] reproduces the paper's printed eq. (2)
/// exactly, with no extra sign (the g rows of the classical Sylvester
/// matrix run the other way, which multiplies by `(−1)^((n−i)(n−i−1)/2)`).
///
/// # Panics
/// If `f` or `g` is empty, `g.len() > f.len()`, or not `i ≤ m` and `i < n`.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::sylvester_habicht;
/// let z = |v: &[i64]| v.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// // f = λ² + 2λ + 3, g = 4λ + 5, i = 0: one f row, two g rows.
/// let m = sylvester_habicht(&z(&[3, 2, 1]), &z(&[5, 4]), 0);
/// assert_eq!(m, vec![z(&[1, 2, 3]), z(&[0, 4, 5]), z(&[4, 5, 0])]);
/// ```
pub fn sylvester_habicht<R: Ring>(f: &[R], g: &[R], i: usize) -> Vec<Vec<R>> {
    let (n, m) = check_args(f, g, i);
    let cols = n + m - i;
    // Row holding λ^shift · h: the coefficient of λ^k goes to column
    // cols − 1 − (k + shift).
    let shifted = |h: &[R], shift: usize| -> Vec<R> {
        let mut row = vec![R::zero(); cols];
        for (k, c) in h.iter().enumerate() {
            row[cols - 1 - (k + shift)] = c.clone();
        }
        row
    };
    (0..m - i)
        .map(|k| shifted(f, m - i - 1 - k))
        .chain((0..n - i).map(|j| shifted(g, j)))
        .collect()
}

/// The coefficients (LOW→HIGH, length `i + 1`) of the i-th signed
/// subresultant `sr_i(λ)` of f and g (Definition 2.2).
///
/// `sr_i` is the determinant of the square matrix made of the first
/// `n + m − 2i − 1` columns of `SyHa_i(f, g)` and, as last column, the
/// polynomials `λ^(m−i−1) f, …, f, g, …, λ^(n−i−1) g`. Expanding that last
/// column by linearity, the coefficient `sr_{i,j}` of `λ^j` is the
/// determinant of the first `n + m − 2i − 1` columns plus the column of
/// `λ^j`; for `j > i` that column is already among the first ones, so
/// `deg sr_i ≤ i`. `sr_{i,i}` is the i-th principal signed subresultant
/// coefficient, and `sr_0 = sr_{0,0} = (−1)^(n(n−1)/2) Res(f, g)` where
/// `Res` is the classical Sylvester resultant (g rows in decreasing power
/// order); for the quartic (n = 4) the sign is +1, as the paper states.
///
/// Each coefficient is one [`determinant`] of order `n + m − 2i` (the code
/// computes `i + 1` of them).
///
/// # Panics
/// As [`sylvester_habicht`].
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::signed_subresultant;
/// let z = |v: &[i64]| v.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// // f = λ² + bλ + c with f' = 2λ + b: sr_0 = b² − 4c, the discriminant.
/// assert_eq!(signed_subresultant(&z(&[3, 2, 1]), &z(&[2, 2]), 0), z(&[2 * 2 - 4 * 3]));
/// ```
pub fn signed_subresultant<R: Ring>(f: &[R], g: &[R], i: usize) -> Vec<R> {
    let (n, m) = check_args(f, g, i);
    let syha = sylvester_habicht(f, g, i);
    let cols = n + m - i;
    let keep = n + m - 2 * i - 1;
    (0..=i)
        .map(|j| {
            let column = cols - 1 - j;
            let square = syha
                .iter()
                .map(|row| {
                    let mut r = row[..keep].to_vec();
                    r.push(row[column].clone());
                    r
                })
                .collect();
            determinant(square)
        })
        .collect()
}

/// The signed subresultant sequence `sr_0, …, sr_(m−1)` of f and g
/// (index i holds the coefficients of `sr_i`, LOW→HIGH, length `i + 1`);
/// see [`signed_subresultant`]. Empty when `m = 0`.
///
/// # Panics
/// If `f` or `g` is empty or `g.len() > f.len()`.
pub fn signed_subresultants<R: Ring>(f: &[R], g: &[R]) -> Vec<Vec<R>> {
    assert!(
        !g.is_empty(),
        "signed subresultants: g must have at least one coefficient"
    );
    (0..g.len() - 1)
        .map(|i| signed_subresultant(f, g, i))
        .collect()
}

/// The formal derivative `f' = Σ k p_k λ^(k−1)` (LOW→HIGH, length
/// `max(f.len(), 1) − 1`).
pub fn derivative<R: Ring>(f: &[R]) -> Vec<R> {
    f.iter()
        .enumerate()
        .skip(1)
        .map(|(k, c)| R::from_i64(k as i64).times(c))
        .collect()
}

/// The signed subresultant sequence `sr_0, …, sr_(n−2)` of f and its
/// derivative f' (the sequence of the paper's eq. (1), whose coefficients
/// Lemma 2.3 and Theorem 3.10 read). For a quartic it is
/// `[sr_0, sr_1, sr_2]`, equal to eq. (2) when f is monic. Empty when
/// `deg f ≤ 1`.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::subresultants_with_derivative;
/// let z = |v: &[i64]| v.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// // f = λ⁴ + aλ³ + bλ² + cλ + d with (a, b, c, d) = (0, -5, 0, 4) = (λ²−1)(λ²−4):
/// let sr = subresultants_with_derivative(&z(&[4, 0, -5, 0, 1]));
/// // sr_2 = (3a² − 8b)λ² + (2ab − 12c)λ + (ac − 16d), eq. (2).
/// assert_eq!(sr[2], z(&[-64, 0, 40]));
/// ```
pub fn subresultants_with_derivative<R: Ring>(f: &[R]) -> Vec<Vec<R>> {
    if f.len() <= 1 {
        return Vec::new();
    }
    signed_subresultants(f, &derivative(f))
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::RingOps;
    use ccd_arith::{Int, Rat};
    use proptest::prelude::*;

    fn rat() -> impl Strategy<Value = Rat> {
        (-40i64..=40, 1i64..=12).prop_map(|(p, q)| Rat::from_frac(p, q))
    }

    fn r(v: i64) -> Rat {
        Rat::from(v)
    }

    /// The polynomial Σ c_k · monomial_k with integer constants c_k, where
    /// each monomial is a product of powers of (a, b, c, d).
    fn poly(x: &[Rat; 4], terms: &[(i64, [u32; 4])]) -> Rat {
        terms.iter().fold(Rat::zero(), |acc, (k, e)| {
            let mut t = r(*k);
            for (v, &p) in x.iter().zip(e) {
                for _ in 0..p {
                    t = t.times(v);
                }
            }
            acc.plus(&t)
        })
    }

    /// The paper's eq. (2) verbatim, for x = (a, b, c, d):
    /// `[[sr20, sr21, sr22], [sr10, sr11], [sr0]]`.
    fn equation_2(x: &[Rat; 4]) -> [Vec<Rat>; 3] {
        let sr2 = vec![
            poly(x, &[(1, [1, 0, 1, 0]), (-16, [0, 0, 0, 1])]),
            poly(x, &[(2, [1, 1, 0, 0]), (-12, [0, 0, 1, 0])]),
            poly(x, &[(-8, [0, 1, 0, 0]), (3, [2, 0, 0, 0])]),
        ];
        let sr1 = vec![
            // −9a³d + a²bc + 3ac² + 32abd − 4b²c − 48cd
            poly(
                x,
                &[
                    (-9, [3, 0, 0, 1]),
                    (1, [2, 1, 1, 0]),
                    (3, [1, 0, 2, 0]),
                    (32, [1, 1, 0, 1]),
                    (-4, [0, 2, 1, 0]),
                    (-48, [0, 0, 1, 1]),
                ],
            ),
            // −6a³c + 2a²b² − 12a²d + 28abc − 8b³ − 36c² + 32bd
            poly(
                x,
                &[
                    (-6, [3, 0, 1, 0]),
                    (2, [2, 2, 0, 0]),
                    (-12, [2, 0, 0, 1]),
                    (28, [1, 1, 1, 0]),
                    (-8, [0, 3, 0, 0]),
                    (-36, [0, 0, 2, 0]),
                    (32, [0, 1, 0, 1]),
                ],
            ),
        ];
        // −192cd²a + 256d³ + 144c²db + b²a²c² − 6c²da² + 18c³ba + 144ba²d²
        // − 4b³a²d + 16b⁴d − 4c³a³ − 128d²b² − 4b³c² − 27a⁴d² − 80cb²ad
        // + 18cba³d − 27c⁴
        let sr0 = vec![poly(
            x,
            &[
                (-192, [1, 0, 1, 2]),
                (256, [0, 0, 0, 3]),
                (144, [0, 1, 2, 1]),
                (1, [2, 2, 2, 0]),
                (-6, [2, 0, 2, 1]),
                (18, [1, 1, 3, 0]),
                (144, [2, 1, 0, 2]),
                (-4, [2, 3, 0, 1]),
                (16, [0, 4, 0, 1]),
                (-4, [3, 0, 3, 0]),
                (-128, [0, 2, 0, 2]),
                (-4, [0, 3, 2, 0]),
                (-27, [4, 0, 0, 2]),
                (-80, [1, 2, 1, 1]),
                (18, [3, 1, 1, 1]),
                (-27, [0, 0, 4, 0]),
            ],
        )];
        [sr0, sr1, sr2]
    }

    proptest! {
        /// Equation (2): the generic determinants of Definition 2.2 for the
        /// monic quartic and its derivative are exactly the printed formulas.
        #[test]
        fn equation_2_holds_exactly(a in rat(), b in rat(), c in rat(), d in rat()) {
            let x = [a.clone(), b.clone(), c.clone(), d.clone()];
            let f = [d, c, b, a, r(1)];
            let fp = derivative(&f);
            let expected = equation_2(&x);
            for (i, e) in expected.iter().enumerate() {
                prop_assert_eq!(&signed_subresultant(&f, &fp, i), e, "sr_{}", i);
            }
            prop_assert_eq!(subresultants_with_derivative(&f), expected.to_vec());
        }

        /// sr_0(f, g) = (−1)^(n(n−1)/2) Res(f, g): for g of degree 1 with root
        /// β = −q0/q1, Res(f, g) = (−1)^n q1^n f(β), so
        /// sr_0 = (−1)^(n(n+1)/2) q1^n f(β).
        #[test]
        fn sr0_is_the_resultant_for_linear_g(
            f in prop::collection::vec(-9i64..=9, 2..=6),
            q0 in -9i64..=9, q1 in 1i64..=9,
        ) {
            let f: Vec<Int> = f.into_iter().map(Int::from).collect();
            let n = f.len() - 1;
            let g = [Int::from(q0), Int::from(q1)];
            // q1^n f(β) = Σ p_k (−q0)^k q1^(n−k).
            let mut res = Int::zero();
            for (k, p) in f.iter().enumerate() {
                let term = p * &Int::from(-q0).pow(k as u32) * Int::from(q1).pow((n - k) as u32);
                res += term;
            }
            if (n * (n + 1) / 2) % 2 == 1 {
                res = -res;
            }
            prop_assert_eq!(signed_subresultant(&f, &g, 0), vec![res]);
        }
    }

    /// The top of the sequence: sr_(n−1)(f, f') is f' itself (Basu et al.'s
    /// convention sRes_(n−1) = f'), and the matrix shape of Definition 2.2.
    #[test]
    fn shapes_and_top_of_sequence() {
        let z = |v: &[i64]| v.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
        let f = z(&[7, -3, 2, 5, 1]);
        let fp = derivative(&f);
        assert_eq!(fp, z(&[-3, 4, 15, 4]));
        assert_eq!(signed_subresultant(&f, &fp, 3), fp);
        for i in 0..=3 {
            let m = sylvester_habicht(&f, &fp, i);
            assert_eq!(m.len(), 4 + 3 - 2 * i);
            assert!(m.iter().all(|row| row.len() == 4 + 3 - i));
            // p_n on the diagonal of the f block, q_m in the bottom-left corner.
            for (k, row) in m.iter().enumerate().take(3 - i) {
                assert_eq!(row[k], Int::from(1));
            }
            assert_eq!(m.last().unwrap()[0], Int::from(4));
        }
        assert_eq!(signed_subresultants(&f, &fp).len(), 3);
        assert!(subresultants_with_derivative(&z(&[1, 1])).is_empty());
        assert!(subresultants_with_derivative(&z(&[1])).is_empty());
    }

    #[test]
    #[should_panic(expected = "out of range")]
    fn rejects_index_beyond_deg_g() {
        let f = [Int::from(1), Int::from(0), Int::from(1)];
        let g = [Int::from(1), Int::from(1)];
        signed_subresultant(&f, &g, 2);
    }
}
