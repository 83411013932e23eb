//! Fraction-free determinants (Bareiss elimination) over any exact [`Ring`].
//!
//! The signed subresultants of Definition 2.2 are determinants of
//! (modified) Sylvester–Habicht matrices; [`determinant`] is the one routine
//! that evaluates all of them, over integers, rationals or polynomials in t.

use ccd_arith::Ring;

/// The determinant of the square matrix `m` (given as rows), by Bareiss'
/// fraction-free Gaussian elimination.
///
/// Step k (0-based) replaces every entry of the trailing block by
/// `m[i][j] ← (m[i][j]·m[k][k] − m[i][k]·m[k][j]) / p`, where `p` is the
/// previous pivot (1 at the first step). By Sylvester's identity each new
/// entry is a minor of the input, so the division is exact
/// ([`Ring::div_exact`]) and intermediate sizes stay bounded by Hadamard's
/// bound — no fractions are created, which is what makes the routine usable
/// over `Int` and over polynomial rings, not just fields. The last pivot is
/// the determinant.
///
/// When the pivot `m[k][k]` is zero, the first row below it with a nonzero
/// entry in column k is swapped in (flipping the sign); when there is none
/// the column is dependent and the determinant is zero. The ring must be an
/// integral domain (`Int`, `Rat`, polynomials over them) for the exactness
/// argument to hold.
///
/// The empty (0 × 0) matrix has determinant 1.
///
/// Cost: O(n³) ring multiplications and O(n²) exact divisions.
///
/// # Panics
/// If `m` is not square.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_subres::determinant;
/// let m = |rows: &[[i64; 3]]| -> Vec<Vec<Int>> {
///     rows.iter().map(|r| r.iter().map(|&v| Int::from(v)).collect()).collect()
/// };
/// // A zero pivot forces a row swap.
/// assert_eq!(determinant(m(&[[0, 2, 1], [3, 0, 4], [1, 1, 1]])), Int::from(5));
/// assert_eq!(determinant(m(&[[1, 2, 3], [2, 4, 6], [7, 8, 9]])), Int::from(0));
/// ```
pub fn determinant<R: Ring>(mut m: Vec<Vec<R>>) -> R {
    let n = m.len();
    assert!(
        m.iter().all(|row| row.len() == n),
        "determinant: the matrix is not square"
    );
    if n == 0 {
        return R::one();
    }
    let mut negate = false;
    let mut prev = R::one();
    for k in 0..n - 1 {
        if m[k][k].is_zero() {
            match (k + 1..n).find(|&r| !m[r][k].is_zero()) {
                Some(r) => {
                    m.swap(k, r);
                    negate = !negate;
                }
                None => return R::zero(),
            }
        }
        let (top, bottom) = m.split_at_mut(k + 1);
        let pivot_row = &top[k];
        let pivot = &pivot_row[k];
        for row in bottom.iter_mut() {
            let lead = row[k].clone();
            for j in k + 1..n {
                let v = row[j].times(pivot).minus(&lead.times(&pivot_row[j]));
                row[j] = v.div_exact(&prev);
            }
            row[k] = R::zero();
        }
        prev = m[k][k].clone();
    }
    let d = m[n - 1][n - 1].clone();
    if negate {
        d.negated()
    } else {
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::RingOps;
    use ccd_arith::{Int, Rat};
    use proptest::prelude::*;

    /// Laplace expansion along the first row: the reference.
    fn cofactor<R: Ring>(m: &[Vec<R>]) -> R {
        let n = m.len();
        if n == 0 {
            return R::one();
        }
        let mut acc = R::zero();
        for (c, entry) in m[0].iter().enumerate() {
            if entry.is_zero() {
                continue;
            }
            let minor: Vec<Vec<R>> = m[1..]
                .iter()
                .map(|row| {
                    row.iter()
                        .enumerate()
                        .filter(|&(j, _)| j != c)
                        .map(|(_, v)| v.clone())
                        .collect()
                })
                .collect();
            let term = entry.times(&cofactor(&minor));
            acc = if c % 2 == 0 {
                acc.plus(&term)
            } else {
                acc.minus(&term)
            };
        }
        acc
    }

    fn to_ring<R: Ring>(rows: &[Vec<i64>]) -> Vec<Vec<R>> {
        rows.iter()
            .map(|r| r.iter().map(|&v| R::from_i64(v)).collect())
            .collect()
    }

    /// Square integer matrices of size 0..=6 with many zeros (so that zero
    /// pivots and singular matrices are frequent).
    fn matrix() -> impl Strategy<Value = Vec<Vec<i64>>> {
        (0usize..=6).prop_flat_map(|n| {
            prop::collection::vec(
                prop::collection::vec(prop_oneof![3 => Just(0i64), 4 => -9i64..=9], n),
                n,
            )
        })
    }

    /// A matrix with a repeated (or scaled) row or a zero column: singular.
    fn singular() -> impl Strategy<Value = Vec<Vec<i64>>> {
        (
            matrix().prop_filter("needs 2 rows", |m| m.len() >= 2),
            any::<prop::sample::Index>(),
            any::<prop::sample::Index>(),
            -3i64..=3,
            any::<bool>(),
        )
            .prop_map(|(mut m, a, b, s, zero_column)| {
                let n = m.len();
                let (i, j) = (a.index(n), b.index(n));
                if zero_column {
                    m.iter_mut().for_each(|row| row[j] = 0);
                } else {
                    let j = if i == j { (j + 1) % n } else { j };
                    m[j] = m[i].iter().map(|v| v * s).collect();
                }
                m
            })
    }

    proptest! {
        #[test]
        fn bareiss_matches_cofactor_over_int(m in matrix()) {
            let a: Vec<Vec<Int>> = to_ring(&m);
            prop_assert_eq!(determinant(a.clone()), cofactor(&a));
        }

        #[test]
        fn bareiss_matches_cofactor_over_rat(m in matrix(), den in 1i64..=7) {
            let a: Vec<Vec<Rat>> = to_ring::<Rat>(&m)
                .into_iter()
                .map(|r| r.into_iter().map(|v| v.times(&Rat::from_frac(1, den))).collect())
                .collect();
            prop_assert_eq!(determinant(a.clone()), cofactor(&a));
        }

        #[test]
        fn singular_matrices_have_zero_determinant(m in singular()) {
            let a: Vec<Vec<Int>> = to_ring(&m);
            prop_assert_eq!(determinant(a), Int::zero());
        }
    }

    #[test]
    fn zero_pivots_need_swaps() {
        // Anti-diagonal permutation of size 4: two swaps, determinant +1;
        // size 3: one swap, determinant −1.
        let anti = |n: usize| -> Vec<Vec<Int>> {
            (0..n)
                .map(|i| (0..n).map(|j| Int::from((i + j == n - 1) as i64)).collect())
                .collect()
        };
        assert_eq!(determinant(anti(3)), Int::from(-1));
        assert_eq!(determinant(anti(4)), Int::from(1));
        // A pivot that becomes zero only after elimination.
        let m: Vec<Vec<Int>> = to_ring(&[vec![1, 2, 3], vec![2, 4, 5], vec![3, 7, 1]]);
        assert_eq!(determinant(m.clone()), cofactor(&m));
        assert_eq!(determinant(Vec::<Vec<Int>>::new()), Int::one());
    }

    #[test]
    #[should_panic(expected = "not square")]
    fn rejects_non_square() {
        determinant(vec![vec![Int::one(), Int::zero()]]);
    }
}
