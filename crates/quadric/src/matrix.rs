//! 4×4 matrices over any [`RingOps`] (exact rings, floats, intervals): the congruence `Nᵀ·D·N` that turns
//! a body quadric into a placed one, determinants by 2×2 minors, and the
//! characteristic quartic `det(λA + B)`.

use ccd_arith::RingOps;

/// A 4×4 matrix, row-major.
pub type Mat4<R> = [[R; 4]; 4];
/// A 3×3 matrix, row-major.
pub type Mat3<R> = [[R; 3]; 3];

/// `Nᵀ · diag(d) · N`: the matrix of the quadric `Xᵀ diag(d) X = 0` after the
/// change of coordinates `X ↦ N·X` (so if `N` maps world points to body
/// points, this is the world quadric). Symmetric; the upper triangle is
/// computed once.
pub fn congruence<R: RingOps>(n: &Mat4<R>, d: &[R; 4]) -> Mat4<R> {
    // scaled[k][j] = d_k · N[k][j]
    let scaled: Vec<Vec<R>> = (0..4)
        .map(|k| (0..4).map(|j| d[k].times(&n[k][j])).collect())
        .collect();
    let mut out: Mat4<R> = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    for i in 0..4 {
        for j in i..4 {
            let mut s = R::zero();
            for k in 0..4 {
                if !n[k][i].is_zero() && !scaled[k][j].is_zero() {
                    s = s.plus(&n[k][i].times(&scaled[k][j]));
                }
            }
            out[j][i] = s.clone();
            out[i][j] = s;
        }
    }
    out
}

/// The 2×2 minor of rows `r, r+1` and columns `i, j`.
fn minor2<R: RingOps>(m: &Mat4<R>, r: usize, i: usize, j: usize) -> R {
    m[r][i]
        .times(&m[r + 1][j])
        .minus(&m[r][j].times(&m[r + 1][i]))
}

/// `det(m)` by Laplace expansion along the first two rows (2×2 minors):
/// 30 multiplications.
pub fn det4<R: RingOps>(m: &Mat4<R>) -> R {
    /// Columns `(i, j)` of the top minor, `(k, l)` of the complementary
    /// bottom minor, and whether the permutation `(i j k l)` is even.
    type Pair = ((usize, usize), (usize, usize), bool);
    const PAIRS: [Pair; 6] = [
        ((0, 1), (2, 3), true),
        ((0, 2), (1, 3), false),
        ((0, 3), (1, 2), true),
        ((1, 2), (0, 3), true),
        ((1, 3), (0, 2), false),
        ((2, 3), (0, 1), true),
    ];
    let mut det = R::zero();
    for ((i, j), (k, l), positive) in PAIRS {
        let term = minor2(m, 0, i, j).times(&minor2(m, 2, k, l));
        det = if positive {
            det.plus(&term)
        } else {
            det.minus(&term)
        };
    }
    det
}

/// `det(M)` of a 3×3 matrix.
pub fn det3<R: RingOps>(m: &Mat3<R>) -> R {
    let c0 = m[1][1].times(&m[2][2]).minus(&m[1][2].times(&m[2][1]));
    let c1 = m[1][0].times(&m[2][2]).minus(&m[1][2].times(&m[2][0]));
    let c2 = m[1][0].times(&m[2][1]).minus(&m[1][1].times(&m[2][0]));
    m[0][0]
        .times(&c0)
        .minus(&m[0][1].times(&c1))
        .plus(&m[0][2].times(&c2))
}

/// The adjugate `adj(M)` of a 3×3 matrix (`M·adj(M) = det(M)·I`).
pub fn adj3<R: RingOps>(m: &Mat3<R>) -> Mat3<R> {
    let cof = |r0: usize, r1: usize, c0: usize, c1: usize| {
        m[r0][c0]
            .times(&m[r1][c1])
            .minus(&m[r0][c1].times(&m[r1][c0]))
    };
    // adj[i][j] = (−1)^(i+j) · minor(j, i)
    [
        [cof(1, 2, 1, 2), cof(0, 2, 1, 2).negated(), cof(0, 1, 1, 2)],
        [
            cof(1, 2, 0, 2).negated(),
            cof(0, 2, 0, 2),
            cof(0, 1, 0, 2).negated(),
        ],
        [cof(1, 2, 0, 1), cof(0, 2, 0, 1).negated(), cof(0, 1, 0, 1)],
    ]
}

/// The coefficients `[e, a, b, c, d]` (high → low) of the characteristic
/// quartic `det(λA + B) = e·λ⁴ + a·λ³ + b·λ² + c·λ + d` (Section 2).
///
/// Computed from five determinants at `λ ∈ {0, ±1, ±2}` and exact
/// interpolation (divisions by small integers only): with `T1 = f(1) + f(−1) − 2f(0) = 2(e + b)`,
/// `T2 = f(2) + f(−2) − 2f(0) = 32e + 8b`, `U1 = f(1) − f(−1) = 2(a + c)`,
/// `U2 = f(2) − f(−2) = 16a + 4c`: `e = (T2 − 4T1)/24`, `b = T1/2 − e`,
/// `a = (U2 − 2U1)/12`, `c = U1/2 − a`. In an exact ring every division is
/// exact because the coefficients lie in the ring; over floats or intervals
/// it is an ordinary (enclosing) division.
pub fn characteristic<R: RingOps>(a: &Mat4<R>, b: &Mat4<R>) -> [R; 5] {
    let at = |lambda: i64| -> R {
        let l = R::from_i64(lambda);
        let m: Mat4<R> =
            std::array::from_fn(|i| std::array::from_fn(|j| l.times(&a[i][j]).plus(&b[i][j])));
        det4(&m)
    };
    let (v0, v1, vm1, v2, vm2) = (det4(b), at(1), at(-1), at(2), at(-2));
    let two = R::from_i64(2);
    let two_v0 = two.times(&v0);
    let t1 = v1.plus(&vm1).minus(&two_v0);
    let t2 = v2.plus(&vm2).minus(&two_v0);
    let u1 = v1.minus(&vm1);
    let u2 = v2.minus(&vm2);
    let e = t2.minus(&R::from_i64(4).times(&t1)).div_small(24);
    let bq = t1.div_small(2).minus(&e);
    let aq = u2.minus(&two.times(&u1)).div_small(12);
    let cq = u1.div_small(2).minus(&aq);
    [e, aq, bq, cq, v0]
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Int;
    use proptest::prelude::*;

    fn mat(v: &[i64]) -> Mat4<Int> {
        std::array::from_fn(|i| std::array::from_fn(|j| Int::from(v[4 * i + j])))
    }

    /// Reference determinant by permutations.
    fn det_perm(m: &Mat4<Int>) -> Int {
        let mut total = Int::zero();
        let mut p = [0usize, 1, 2, 3];
        // Heap's algorithm over all 24 permutations, tracking parity.
        fn rec(k: usize, p: &mut [usize; 4], sign: &mut i64, m: &Mat4<Int>, total: &mut Int) {
            if k == 1 {
                let mut prod = Int::from(*sign);
                for (i, &c) in p.iter().enumerate() {
                    prod *= &m[i][c];
                }
                *total += prod;
                return;
            }
            for i in 0..k {
                rec(k - 1, p, sign, m, total);
                let j = if k % 2 == 0 { i } else { 0 };
                if i + 1 < k {
                    p.swap(j, k - 1);
                    *sign = -*sign;
                }
            }
        }
        let mut sign = 1;
        rec(4, &mut p, &mut sign, m, &mut total);
        total
    }

    proptest! {
        #[test]
        fn det4_matches_permutation_expansion(v in proptest::collection::vec(-9i64..10, 16)) {
            let m = mat(&v);
            prop_assert_eq!(det4(&m), det_perm(&m));
        }

        #[test]
        fn characteristic_matches_determinants(va in proptest::collection::vec(-9i64..10, 16), vb in proptest::collection::vec(-9i64..10, 16), l in -20i64..20) {
            let (a, b) = (mat(&va), mat(&vb));
            let f = characteristic(&a, &b);
            let lam = Int::from(l);
            let val = f.iter().fold(Int::zero(), |acc, c| acc * &lam + c);
            let m: Mat4<Int> = std::array::from_fn(|i| std::array::from_fn(|j| &lam * &a[i][j] + &b[i][j]));
            prop_assert_eq!(val, det4(&m));
        }

        #[test]
        fn adjugate_inverts(v in proptest::collection::vec(-9i64..10, 9)) {
            let m: Mat3<Int> = std::array::from_fn(|i| std::array::from_fn(|j| Int::from(v[3 * i + j])));
            let adj = adj3(&m);
            let d = det3(&m);
            for (i, row) in m.iter().enumerate() {
                for j in 0..3 {
                    let s = row.iter().zip(&adj).fold(Int::zero(), |acc, (x, a)| acc + x * &a[j]);
                    prop_assert_eq!(s, if i == j { d.clone() } else { Int::zero() });
                }
            }
        }
    }
}
