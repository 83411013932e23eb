//! 4×4 matrices over any [`RingOps`] (exact rings, floats, intervals): the congruence `Nᵀ·D·N` that turns
//! a body quadric into a placed one, determinants by 2×2 minors, and the
//! characteristic quartic `det(λA + B)`.

use ccd_arith::{Int, Rat, RingOps};

/// A 4×4 matrix, row-major.
pub type Mat4<R> = [[R; 4]; 4];
/// A 3×3 matrix, row-major.
pub type Mat3<R> = [[R; 3]; 3];

/// `Nᵀ · diag(d) · N`: the matrix of the quadric `Xᵀ diag(d) X = 0` after the
/// change of coordinates `X ↦ N·X` (so if `N` maps world points to body
/// points, this is the world quadric). Symmetric; the upper triangle is
/// computed once. Any size: 4×4 for quadrics, 3×3 for a body's shape
/// matrix `R·diag(r²)·Rᵀ` (`N = Rᵀ`).
pub fn congruence<R: RingOps, const N: usize>(n: &[[R; N]; N], d: &[R; N]) -> [[R; N]; N] {
    // scaled[k][j] = d_k · N[k][j]
    // Built in place: entries may be large values (polynomials).
    let mut scaled: [[R; N]; N] = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    for (k, row) in scaled.iter_mut().enumerate() {
        for (j, e) in row.iter_mut().enumerate() {
            e.set_product(&d[k], &n[k][j]);
        }
    }
    let mut out: [[R; N]; N] = std::array::from_fn(|_| std::array::from_fn(|_| R::zero()));
    for i in 0..N {
        for j in i..N {
            for k in 0..N {
                if !n[k][i].is_zero() && !scaled[k][j].is_zero() {
                    out[i][j].add_product(&n[k][i], &scaled[k][j], false);
                }
            }
            if j > i {
                out[j][i] = out[i][j].clone();
            }
        }
    }
    out
}

/// The 2×2 minor of rows `r, r+1` and columns `i, j`.
fn minor2<R: RingOps>(m: &Mat4<R>, r: usize, i: usize, j: usize) -> R {
    mixed_minor2(m, m, r, i, j)
}

/// `x[r][i]·y[r+1][j] − x[r][j]·y[r+1][i]`: the 2×2 minor with its top row
/// from `x` and its bottom row from `y`.
fn mixed_minor2<R: RingOps>(x: &Mat4<R>, y: &Mat4<R>, r: usize, i: usize, j: usize) -> R {
    let mut m = R::zero();
    set_mixed_minor2(&mut m, x, y, r, i, j);
    m
}

/// [`mixed_minor2`] into `out` (built where it lives).
fn set_mixed_minor2<R: RingOps>(
    out: &mut R,
    x: &Mat4<R>,
    y: &Mat4<R>,
    r: usize,
    i: usize,
    j: usize,
) {
    out.set_product(&x[r][i], &y[r + 1][j]);
    out.add_product(&x[r][j], &y[r + 1][i], true);
}

/// `m` times the lcm of its entries' denominators: the same quadric (a
/// positive multiple), in integers, which `det(λA + B)` computes with far
/// more cheaply than with rationals.
///
/// ```
/// use ccd_arith::{Int, Rat};
/// use ccd_quadric::integral;
/// let mut m: [[Rat; 4]; 4] = std::array::from_fn(|_| std::array::from_fn(|_| Rat::zero()));
/// m[0][0] = Rat::from_frac(1, 4);
/// m[3][3] = Rat::from_frac(-1, 6);
/// let n = integral(&m);
/// assert_eq!((n[0][0].clone(), n[3][3].clone()), (Int::from(3), Int::from(-2)));
/// ```
pub fn integral(m: &Mat4<Rat>) -> Mat4<Int> {
    let den = m.iter().flatten().fold(Int::one(), |l, x| l.lcm(x.denom()));
    m.each_ref().map(|row| {
        row.each_ref()
            .map(|x| x.numer() * &den.div_exact(x.denom()))
    })
}

/// Columns `(i, j)` of a top 2×2 minor, `(k, l)` of the complementary
/// bottom minor, and whether the permutation `(i j k l)` is even.
type LaplacePair = ((usize, usize), (usize, usize), bool);

/// Laplace expansion of a 4×4 determinant along its first two rows.
const LAPLACE_PAIRS: [LaplacePair; 6] = [
    ((0, 1), (2, 3), true),
    ((0, 2), (1, 3), false),
    ((0, 3), (1, 2), true),
    ((1, 2), (0, 3), true),
    ((1, 3), (0, 2), false),
    ((2, 3), (0, 1), true),
];

/// `det(m)` by Laplace expansion along the first two rows (2×2 minors):
/// 30 multiplications.
pub fn det4<R: RingOps>(m: &Mat4<R>) -> R {
    let mut det = R::zero();
    for ((i, j), (k, l), positive) in LAPLACE_PAIRS {
        det.add_product(&minor2(m, 0, i, j), &minor2(m, 2, k, l), !positive);
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

/// Column `j` of the adjugate of a 4×4 matrix: `adj(M)[i][j] =
/// (−1)^(i+j)·minor(j, i)`, so `M·adj(M) = det(M)·I`. When `M` has rank 3
/// every column is a multiple of the kernel vector (the contact point of
/// Wang et al. 2001 for `M = λ*A + B`).
pub fn adj4_column<R: RingOps>(m: &Mat4<R>, j: usize) -> [R; 4] {
    std::array::from_fn(|i| {
        // minor(j, i): delete row j and column i.
        let rows: [usize; 3] = std::array::from_fn(|r| if r < j { r } else { r + 1 });
        let cols: [usize; 3] = std::array::from_fn(|c| if c < i { c } else { c + 1 });
        let sub: Mat3<R> =
            std::array::from_fn(|r| std::array::from_fn(|c| m[rows[r]][cols[c]].clone()));
        let minor = det3(&sub);
        if (i + j).is_multiple_of(2) {
            minor
        } else {
            minor.negated()
        }
    })
}

/// The adjugate of a 4×4 matrix (`M·adj(M) = det(M)·I`), by columns
/// ([`adj4_column`]).
pub fn adj4<R: RingOps>(m: &Mat4<R>) -> Mat4<R> {
    let cols: [[R; 4]; 4] = std::array::from_fn(|j| adj4_column(m, j));
    std::array::from_fn(|i| std::array::from_fn(|j| cols[j][i].clone()))
}

/// The coefficients `[e, a, b, c, d]` (high → low) of the characteristic
/// quartic `det(λA + B) = e·λ⁴ + a·λ³ + b·λ² + c·λ + d` (Section 2).
///
/// Laplace expansion along the first two rows with `λ` kept symbolic: each
/// 2×2 minor of `λA + B` is a quadratic in `λ`,
/// `λ²·|a a| + λ·(|a b| + |b a|) + |b b|` (eight products), and the
/// determinant is `Σ ± top(λ)·bottom(λ)` over the six complementary pairs
/// (nine products each): 150 products, like five determinants at fixed
/// `λ`, but each product pairs entries of `A` and `B` themselves. When one
/// body is static its entries are constants, and two thirds of the
/// products become scalings (O(n) instead of O(n²) for polynomial entries
/// of length n). No division, so the same code serves every ring.
pub fn characteristic<R: RingOps>(a: &Mat4<R>, b: &Mat4<R>) -> [R; 5] {
    // The 2×2 minor of rows (r, r + 1), columns (i, j) of λA + B as
    // [λ², λ, 1] coefficients.
    // Built in place: minors of polynomial entries are large values.
    let minor = |m: &mut [R; 3], scratch: &mut R, r: usize, i: usize, j: usize| {
        set_mixed_minor2(&mut m[0], a, a, r, i, j);
        set_mixed_minor2(&mut m[1], a, b, r, i, j);
        set_mixed_minor2(scratch, b, a, r, i, j);
        m[1].plus_assign(scratch);
        set_mixed_minor2(&mut m[2], b, b, r, i, j);
    };
    let mut f: [R; 5] = std::array::from_fn(|_| R::zero());
    let mut top: [R; 3] = std::array::from_fn(|_| R::zero());
    let mut bottom: [R; 3] = std::array::from_fn(|_| R::zero());
    let mut scratch = R::zero();
    for ((i, j), (k, l), positive) in LAPLACE_PAIRS {
        minor(&mut top, &mut scratch, 0, i, j);
        minor(&mut bottom, &mut scratch, 2, k, l);
        for (p, t) in top.iter().enumerate() {
            for (q, u) in bottom.iter().enumerate() {
                f[p + q].add_product(t, u, !positive);
            }
        }
    }
    f
}

/// `D(S) = Π_(c ∈ S) d_c` for every subset `S` of a diagonal's four
/// indices (bit `c` of the table's index: entry `c`), the products
/// [`placed_characteristic`] reads.
///
/// ```
/// use ccd_quadric::subset_products;
/// let p = subset_products(&[2i64, 3, 5, 7].map(ccd_arith::Int::from));
/// assert_eq!(p[0b0101], ccd_arith::Int::from(10));
/// assert_eq!(p[0b1111], ccd_arith::Int::from(210));
/// ```
pub fn subset_products<R: RingOps>(d: &[R; 4]) -> [R; 16] {
    let mut p: [R; 16] = std::array::from_fn(|_| R::one());
    for (c, dc) in d.iter().enumerate() {
        for s in 0..1 << c {
            p[s | 1 << c] = p[s].times(dc);
        }
    }
    p
}

/// The characteristic quartic of two placed bodies from their placements,
/// without forming either quadric: for `A = M_A^(−T)·D_A·M_A^(−1)` and
/// `B = M_B^(−T)·D_B·M_B^(−1)` (`M` maps body to world coordinates,
/// homogeneous; `D` diagonal), returns `[e, a, b, c, d]` (high → low) of
///
/// `det(M_A)²·det(M_B)²·det(λA + B) = Σ_T λ^(4 − |T∩A|) · D_A(A∖T) · D_B(B∖T) · P_T²`,
///
/// the sum over the 70 four-column subsets `T` of the 4×8 matrix
/// `[M_A | M_B]`, with `P_T` its Plücker coordinates (4×4 minors) and
/// `D(S)` the product of the diagonal entries indexed by `S`, given as the
/// tables `pa`, `pb` of [`subset_products`].
///
/// Tables `D'(S) = α·β^|S|·D(S)` (`α, β > 0`, rational, the table still
/// integral) give coefficient `k` of the sum (`λ^k`, `|A∖T| = k`) times
/// `α·β^k` for A, `α·β^(4−k)` for B: `λA + B` with `A` and `B` scaled,
/// which rescales λ and keeps every sign Theorem 3.10 reads. Integer
/// diagonals `D = s·D̃` of long rational `D̃` carry `s^|S|` in `D(S)`, a
/// factor the products need not carry.
///
/// Proof: `λA + B = Gᵀ·diag(λD_A, D_B)·G` with `G = [M_A^(−1); M_B^(−1)]`
/// (8×4), so Cauchy–Binet sums `det(G_S)²` times the diagonal over row sets
/// `S`; the columns of `[M_A^(−1); −M_B^(−1)]` span the kernel of
/// `[M_A | M_B]`, so `det(G_S) = ±det(M_A)^(−1)·det(M_B)^(−1)·P_(S^c)`.
///
/// `both`, when given, multiplies the terms whose `T` holds both
/// homogeneous columns (3 and 7): with affine placements
/// ([`is_affine_placement`]) the terms without either vanish, so tables
/// reduced by `c^(number of A's or B's axes in S)` and `both = c` give
/// every term the same factor (`PlacedQuadric::diagonal_products` in
/// `ccd-motion`).
///
/// The factor `det(M_A)²·det(M_B)²` is positive wherever both placements
/// are invertible, and each `P_T` has degree at most four times that of
/// the placements: for motions of degree 2 this is `deg_t ≤ 16`, against
/// 48 for `det(λA + B)` with `A` formed through adjugates. 56 products for
/// the 2×2 minors, 420 for the Plücker coordinates, 70 squarings.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_quadric::{characteristic, congruence, placed_characteristic, subset_products, Mat4};
/// let i = |v: i64| Int::from(v);
/// // Unit sphere at the origin; sphere of radius 1 (D = diag(1,1,1,−1)) at x = 3.
/// let id: Mat4<Int> = std::array::from_fn(|r| std::array::from_fn(|c| i((r == c) as i64)));
/// let mut shifted = id.clone();
/// shifted[0][3] = i(3);
/// let d = [i(1), i(1), i(1), i(-1)];
/// let f = placed_characteristic(&id, &subset_products(&d), &shifted, &subset_products(&d), None);
/// // Inverse placements give the quadrics directly: same quartic (det M = 1).
/// let mut back = id.clone();
/// back[0][3] = i(-3);
/// assert_eq!(f, characteristic(&congruence(&id, &d), &congruence(&back, &d)));
/// ```
pub fn placed_characteristic<R: RingOps + PartialEq>(
    ma: &Mat4<R>,
    pa: &[R; 16],
    mb: &Mat4<R>,
    pb: &[R; 16],
    both: Option<&R>,
) -> [R; 5] {
    // Column c of [M_A | M_B] (c < 4 from A).
    let entry = |r: usize, c: usize| if c < 4 { &ma[r][c] } else { &mb[r][c - 4] };
    // 2×2 minors of rows (0, 1) and (2, 3) for every column pair i < j,
    // built in place at their triangular index (`pair_index`).
    // Each formed in its slot (entries may be large values: polynomials):
    // `x·y − z·w` with zero products skipped, by the same ring operations
    // as `x.times(y).minus(&z.times(w))` wherever `add_product` is its
    // default or `Interval`'s. (`SmallPoly` accumulates `z·w` term by term,
    // the same value whenever it is exact; near `2^126` its overflow marker
    // may fall otherwise, which only sends the set-up to `ZPoly`, and the
    // set-up's size test keeps these minors far below that.)
    let minor = |m: &mut R, r: usize, k: usize| {
        let (i, j) = COLUMN_PAIRS[k];
        let nonzero = |x: &R, y: &R| !x.is_zero() && !y.is_zero();
        let (x, y) = (entry(r, i), entry(r + 1, j));
        let (z, w) = (entry(r, j), entry(r + 1, i));
        match (nonzero(x, y), nonzero(z, w)) {
            (true, true) => {
                m.set_product(x, y);
                m.add_product(z, w, true);
            }
            (true, false) => m.set_product(x, y),
            (false, true) => {
                m.set_product(z, w);
                *m = m.negated();
            }
            (false, false) => {}
        }
    };
    let mut top: [R; 28] = std::array::from_fn(|_| R::zero());
    let mut bottom: [R; 28] = std::array::from_fn(|_| R::zero());
    for k in 0..28 {
        minor(&mut top[k], 0, k);
        minor(&mut bottom[k], 2, k);
    }
    let mut coeffs: [R; 5] = std::array::from_fn(|_| R::zero());
    // Grouped by A's columns outside T (`outside_a`, whose product `pa`
    // multiplies the inner sum once): 70 products by `pb` and 16 by `pa`
    // instead of 70 products `pa·pb` and 70 by those (long products where
    // `D` has long entries).
    // Both placements' last rows `(0, 0, 0, w)` with the same `w` (rigid
    // and affine motions): a `T` with one homogeneous column `h` (3 or 7)
    // has `P_T = ±w·det(rows 0–2 of T ∖ {h})` (Laplace along row 3), so
    // `T` and `T △ {3, 7}` have the same `P_T²`: 20 of the 70 Laplace
    // expansions and squarings are each one's partner's (`partners` holds
    // the first square of a pair until the second takes it).
    let shared_w = homogeneous(ma)
        .zip(homogeneous(mb))
        .is_some_and(|(x, y)| x == y);
    let mut partners: Vec<(u32, R)> = Vec::new();
    // Moreover, when `pb` changes sign with the homogeneous index
    // (`D_B`'s homogeneous entry −1: an ellipsoid's), a partner's term
    // (before `pa`) is the other's negated: the group `outside_a ∪ {3}`
    // (A's homogeneous column outside `T`) holds only terms whose `T`
    // lacks column 3, so holds column 7 (else `P_T = 0`), and these are
    // exactly the partners of the one-homogeneous terms of the group
    // `outside_a`. Its inner sum is theirs negated (`partner_sums`): 20 of
    // the 50 long products by `pb` are not formed.
    let negated_partners = shared_w && (0..8).all(|s| pb[s | 8] == pb[s].negated());
    let mut partner_sums: [Option<R>; 8] = std::array::from_fn(|_| None);
    for outside_a in 0u32..16 {
        let in_a = !outside_a & 0xf;
        if negated_partners && outside_a & 8 != 0 {
            // Only partners here (no term holds both homogeneous columns).
            if let Some(sum) = partner_sums[(outside_a & 7) as usize].take() {
                let index = in_a.count_ones() as usize;
                coeffs[index].add_product(&pa[outside_a as usize], &sum.negated(), false);
            }
            continue;
        }
        // |T ∩ B| = 4 − |T ∩ A| = |A ∖ T|.
        let mut inner = R::zero();
        // The terms whose `T` holds both homogeneous columns, times `both`
        // once.
        let mut inner_both = R::zero();
        // The terms with one homogeneous column, when `negated_partners`.
        let mut one = R::zero();
        for in_b in (0u32..16).filter(|b| b.count_ones() == outside_a.count_ones()) {
            let t = in_a | in_b << 4;
            // A partner's square (see `shared_w`) instead of P_T's Laplace
            // expansion and square.
            let paired = shared_w && (t & HOMOGENEOUS).count_ones() == 1;
            let key = t & !HOMOGENEOUS;
            if let Some(i) = paired
                .then(|| partners.iter().position(|(k, _)| *k == key))
                .flatten()
            {
                let (_, square) = partners.swap_remove(i);
                inner.add_product(&pb[(!in_b & 0xf) as usize], &square, false);
                continue;
            }
            let mut cols = [0usize; 4];
            for (slot, c) in cols.iter_mut().zip((0..8).filter(|c| t >> c & 1 == 1)) {
                *slot = c;
            }
            // Laplace along rows (0, 1): positions (p, q) of the top minor in
            // T, the complementary positions (r, s) for the bottom one.
            let mut plucker = R::zero();
            for ((p, q), (r, s), positive) in LAPLACE_PAIRS {
                let (upper, lower) = (
                    &top[pair_index(cols[p], cols[q])],
                    &bottom[pair_index(cols[r], cols[s])],
                );
                if upper.is_zero() || lower.is_zero() {
                    continue;
                }
                plucker.add_product(upper, lower, !positive);
            }
            if plucker.is_zero() {
                continue;
            }
            let square = plucker.squared();
            let sum = if both.is_some() && t & HOMOGENEOUS == HOMOGENEOUS {
                &mut inner_both
            } else if negated_partners && paired {
                &mut one
            } else {
                &mut inner
            };
            sum.add_product(&pb[(!in_b & 0xf) as usize], &square, false);
            if paired && !negated_partners {
                partners.push((key, square));
            }
        }
        if !one.is_zero() {
            inner.plus_assign(&one);
            partner_sums[outside_a as usize] = Some(one);
        }
        if let Some(factor) = both.filter(|_| !inner_both.is_zero()) {
            inner.add_product(factor, &inner_both, false);
        }
        if inner.is_zero() {
            continue;
        }
        // λ^(4 − |T∩A|) is coefficient index |T∩A| (high → low).
        coeffs[in_a.count_ones() as usize].add_product(&pa[outside_a as usize], &inner, false);
    }
    coeffs
}

/// The column pairs `i < j` of `[M_A | M_B]` in lexicographic order: the
/// `k`-th is at [`pair_index`] `k`.
const COLUMN_PAIRS: [(usize, usize); 28] = {
    let mut pairs = [(0, 0); 28];
    let (mut i, mut k) = (0, 0);
    while i < 8 {
        let mut j = i + 1;
        while j < 8 {
            pairs[k] = (i, j);
            k += 1;
            j += 1;
        }
        i += 1;
    }
    pairs
};

/// The index of the column pair `i < j` in [`COLUMN_PAIRS`]: the `7 + 6 +
/// … ` pairs of the rows before `i`, then `j − i − 1`.
const fn pair_index(i: usize, j: usize) -> usize {
    i * (15 - i) / 2 + j - i - 1
}

/// The homogeneous columns of `[M_A | M_B]`: the last of each placement.
const HOMOGENEOUS: u32 = 1 << 3 | 1 << 7;

/// `w` when the last row of `m` is `(0, 0, 0, w)` (an affine placement).
fn homogeneous<R: RingOps>(m: &Mat4<R>) -> Option<&R> {
    m[3][..3].iter().all(R::is_zero).then_some(&m[3][3])
}

/// Whether the last row of `m` is `(0, 0, 0, w)`: the placements of
/// rigid and affine motions, whose Cauchy–Binet terms in
/// [`placed_characteristic`] vanish unless `T` holds a homogeneous
/// column (row 3 of `[M_A | M_B]` is zero on the others).
pub fn is_affine_placement<R: RingOps>(m: &Mat4<R>) -> bool {
    homogeneous(m).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Int;
    use proptest::prelude::*;

    #[test]
    fn pair_index_finds_each_column_pair() {
        for (k, &(i, j)) in COLUMN_PAIRS.iter().enumerate() {
            assert!(i < j && j < 8);
            assert_eq!(pair_index(i, j), k);
        }
    }

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
                let j = if k.is_multiple_of(2) { i } else { 0 };
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

        /// Interval quadric algebra over axis-aligned ellipsoids (structural
        /// zeros, and centres with zero coordinates): `congruence` and
        /// `characteristic` enclose the exact rational results, and no
        /// bound is subnormal (a zero stays exact, as the ring operations
        /// of `Interval` keep it; `±2^−1074` would make every later
        /// product with it a microcode assist).
        #[test]
        fn interval_quadrics_enclose_and_keep_zeros(
            axes in proptest::array::uniform6(1i64..20),
            centres in proptest::array::uniform6(prop_oneof![Just(0i64), -5i64..6]),
        ) {
            use ccd_arith::{Interval, Rat};
            let quadric = |r: &[i64], c: &[i64]| -> (Mat4<Rat>, Mat4<Interval>) {
                let n: Mat4<Rat> = std::array::from_fn(|i| std::array::from_fn(|j| {
                    if i == j { Rat::one() } else if j == 3 && i < 3 { Rat::from(-c[i]) } else { Rat::zero() }
                }));
                let d: [Rat; 4] = std::array::from_fn(|k| if k < 3 { Rat::from_frac(1, r[k] * r[k]) } else { -Rat::one() });
                let iv = |m: &Mat4<Rat>| m.clone().map(|row| row.map(|x| Interval::from_rat(&x)));
                (congruence(&n, &d), congruence(&iv(&n), &d.clone().map(|x| Interval::from_rat(&x))))
            };
            let (ea, ia) = quadric(&axes[..3], &centres[..3]);
            let (eb, ib) = quadric(&axes[3..], &centres[3..]);
            let holds = |iv: &Interval, x: &Rat| {
                iv.lo.is_finite() && iv.hi.is_finite()
                    && Rat::from_f64_exact(iv.lo).unwrap() <= *x && *x <= Rat::from_f64_exact(iv.hi).unwrap()
            };
            let normal = |iv: &Interval| [iv.lo, iv.hi].iter().all(|&v| v == 0.0 || v.abs() >= f64::MIN_POSITIVE);
            for (e, i) in [(&ea, &ia), (&eb, &ib)] {
                for (er, ir) in e.iter().zip(i) {
                    for (x, iv) in er.iter().zip(ir) {
                        prop_assert!(holds(iv, x) && normal(iv), "{:?} against {}", iv, x);
                    }
                }
            }
            // The 2×2 minors `characteristic` forms, and the sums of the
            // mixed ones (most of them exactly zero here).
            for r in 0..3 {
                for (i, j) in COLUMN_PAIRS.iter().filter(|&&(_, j)| j < 4).copied() {
                    let minor = |x: &Mat4<Rat>, y: &Mat4<Rat>| mixed_minor2(x, y, r, i, j);
                    let iminor = |x: &Mat4<Interval>, y: &Mat4<Interval>| mixed_minor2(x, y, r, i, j);
                    let exact = [minor(&ea, &eb), minor(&eb, &ea), minor(&ea, &eb).plus(&minor(&eb, &ea))];
                    let enclosed = [iminor(&ia, &ib), iminor(&ib, &ia), iminor(&ia, &ib).plus(&iminor(&ib, &ia))];
                    for (x, iv) in exact.iter().zip(&enclosed) {
                        prop_assert!(holds(iv, x) && normal(iv), "{:?} against {}", iv, x);
                    }
                }
            }
            for (x, iv) in characteristic(&ea, &eb).iter().zip(&characteristic(&ia, &ib)) {
                prop_assert!(holds(iv, x) && normal(iv), "{:?} against {}", iv, x);
            }
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
        fn placed_characteristic_is_det_squared_times_quartic(va in proptest::collection::vec(-9i64..10, 16), vb in proptest::collection::vec(-9i64..10, 16), da in proptest::collection::vec(-9i64..10, 4), db in proptest::collection::vec(-9i64..10, 4), shape in 0u8..4) {
            // Against the quadrics through adjugates: adj(M) = det(M)·M⁻¹, so
            // det(λ·adj(M_A)ᵀD_A·adj(M_A) + adj(M_B)ᵀD_B·adj(M_B)) is
            // det(M_B)^8·det(μA + B) at μ = λ·det(M_A)²/det(M_B)², and the
            // Plücker form is det(M_A)²det(M_B)²·det(μA + B). Shapes: any
            // placements; affine ones, last rows (0, 0, 0, w), the two `w`
            // independent; affine with one `w` (the partners' squares);
            // and with the homogeneous diagonal entries −1 of ellipsoids
            // (the partners' products by the tables).
            let (mut ma, mut mb) = (mat(&va), mat(&vb));
            let (mut da, mut db) = (da, db);
            if shape == 3 {
                (da[3], db[3]) = (-1, -1);
            }
            if shape > 0 {
                for m in [&mut ma, &mut mb] {
                    m[3][..3].iter_mut().for_each(|x| *x = Int::zero());
                }
                prop_assert!(is_affine_placement(&ma) && is_affine_placement(&mb));
            }
            if shape >= 2 {
                mb[3][3] = ma[3][3].clone();
            }
            let (sa, sb) = (det4(&ma), det4(&mb));
            prop_assume!(!sa.is_zero() && !sb.is_zero());
            let d = |v: &[i64]| -> [Int; 4] { std::array::from_fn(|k| Int::from(v[k])) };
            let plucker = placed_characteristic(&ma, &subset_products(&d(&da)), &mb, &subset_products(&d(&db)), None);
            let adjugate = characteristic(&congruence(&adj4(&ma), &d(&da)), &congruence(&adj4(&mb), &d(&db)));
            // Coefficient of λ^k: adjugate = det(M_B)^8·(sa²/sb²)^k·plucker_k/(sa²sb²),
            // i.e. adjugate_k·sa²·sb^(2k+2) = sb^8·sa^(2k)·plucker_k.
            for k in 0..5u32 {
                let (x, y) = (&adjugate[4 - k as usize], &plucker[4 - k as usize]);
                prop_assert_eq!(x * &sa.pow(2) * &sb.pow(2 * k + 2), y * &sb.pow(8) * &sa.pow(2 * k));
            }
        }

        #[test]
        fn adj4_inverts(v in proptest::collection::vec(-9i64..10, 16)) {
            let m = mat(&v);
            let (adj, d) = (adj4(&m), det4(&m));
            for (i, row) in m.iter().enumerate() {
                for j in 0..4 {
                    let s = row.iter().zip(&adj).fold(Int::zero(), |acc, (x, a)| acc + x * &a[j]);
                    prop_assert_eq!(s, if i == j { d.clone() } else { Int::zero() });
                }
            }
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
