//! The characteristic quartic of two rigid placements from their relative
//! placement, at the degree the pair needs.
//!
//! For rigid placements `X = R_A·Y + c_A` and `X = R_B·Y + c_B` (`R` a
//! rotation) with body quadrics `D_A`, `D_B` (diagonal), the world quadrics
//! are `A = N_AᵀD_AN_A`, `N_A = [[R_Aᵀ, −R_Aᵀc_A], [0, 1]]`, and
//! `det(λA + B) = det(λD_A + GᵀD_BG)` for the relative placement
//! `G = N_B·N_A⁻¹ = [[R, d], [0, 1]]`, `R = R_BᵀR_A`, `d = R_Bᵀ(c_A − c_B)`
//! (`det N_A = 1`). Cauchy–Binet then sums squared minors of `G` against
//! the diagonals, and every minor of a rotation block with one translation
//! column is one of a few short quantities (below), so `det(λA + B)` is
//! formed from 25 squares of short polynomials instead of the quadrics'
//! products, whose rational rotations `R = M(q)/|q|²` leave powers of
//! `|q|²` (up to the eighth) that the normalisation divides out again.

use crate::matrix::{subset_products, Mat3};
use ccd_arith::{Int, RingOps, SmallInt};
use ccd_poly::{SmallPoly, ZPoly};

/// A rigid placement `X = (M/n)·Y + C/w` with `M/n` a rotation
/// (`M·Mᵀ = n²·I`, `det M = n³`: `M = M(q)`, `n = |q|²` for a quaternion
/// `q`) and `w ≠ 0`: the numbers of `ccd-motion`'s integer frames.
#[derive(Clone, Debug, PartialEq)]
pub struct RigidFrame<R> {
    /// The rotation numerator `M`.
    pub m: Mat3<R>,
    /// The rotation denominator `n`.
    pub n: R,
    /// The centre numerator `C`.
    pub center: [R; 3],
    /// The centre denominator `w`.
    pub w: R,
}

impl<R> RigidFrame<R> {
    /// Every number mapped by `f`.
    pub fn map<Q>(&self, f: impl Fn(&R) -> Q) -> RigidFrame<Q> {
        RigidFrame {
            m: self.m.each_ref().map(|row| row.each_ref().map(&f)),
            n: f(&self.n),
            center: self.center.each_ref().map(&f),
            w: f(&self.w),
        }
    }
}

/// An upper bound on the degrees of [`rigid_characteristic`]'s
/// coefficients from those of the frames' numbers (`a`, `b`: each
/// number's degree): twice the largest degree of the quantities it
/// squares, from `deg(xy) <= deg x + deg y` and `deg(x ± y) <= max`.
pub fn rigid_characteristic_degree(a: &RigidFrame<usize>, b: &RigidFrame<usize>) -> usize {
    let largest = |v: &[usize]| v.iter().copied().max().unwrap_or(0);
    let (ma, mb) = (largest(a.m.as_flattened()), largest(b.m.as_flattened()));
    let delta = (b.w + largest(&a.center)).max(a.w + largest(&b.center));
    let quantities = [
        a.w + b.w + ma + mb,
        a.n + mb + delta,
        b.n + ma + delta,
        ma + mb + delta,
        a.n + b.n + a.w + b.w,
    ];
    2 * largest(&quantities)
}

/// [`rigid_characteristic`] of frames given by their values at several
/// `u` (`a[i]`, `b[i]` at the `i`-th point) and diagonals, in `i128`: plain
/// machine arithmetic once a bound shows that no number on the way
/// reaches `2^126`, the weights formed once; `None` when the bound does
/// not hold at some point. With every frame number below `2^F` in
/// magnitude, `δ < 2^(2F+1)` and the five quantities are below
/// `2^(4F+4)` (`x̃`, a sum of three products of `M` with a cross product
/// of two products, is the longest), every partial sum included. With the
/// quantities then below `2^Q` and the diagonal entries below `2^G`, a
/// weight (at most two products of four diagonal entries) is below
/// `2^(4G+1)` and each coefficient a sum of at most 32 terms
/// weight·square: below `2^(2Q+4G+6)`, every partial sum included.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_quadric::{rigid_characteristic, rigid_values, RigidFrame};
/// let frame = |q: [i64; 4], c: [i64; 3], w: i64| RigidFrame {
///     m: ccd_quadric::rotation_numerator(&q.map(Int::from)),
///     n: ccd_quadric::norm2(&q.map(Int::from)),
///     center: c.map(Int::from),
///     w: Int::from(w),
/// };
/// let (a, b) = (frame([1, 2, 0, 1], [1, 0, 2], 3), frame([2, 0, 1, 1], [4, 1, 0], 1));
/// let (da, db) = ([1, 4, 9, -36], [4, 1, 1, -4]);
/// let word = |f: &RigidFrame<Int>| f.map(|x| x.to_i128().unwrap());
/// let int = |d: [i64; 4]| d.map(Int::from);
/// let exact = rigid_characteristic(&a, &b, &int(da), &int(db));
/// let fast = rigid_values(&[word(&a)], &[word(&b)], &da.map(i128::from), &db.map(i128::from));
/// assert_eq!(fast, Some(vec![exact.map(|x| x.to_i128().unwrap())]));
/// ```
pub fn rigid_values(
    a: &[RigidFrame<i128>],
    b: &[RigidFrame<i128>],
    da: &[i128; 4],
    db: &[i128; 4],
) -> Option<Vec<[i128; 5]>> {
    let bits = |x: &i128| 128 - x.unsigned_abs().leading_zeros();
    let frame_bits = |f: &RigidFrame<i128>| {
        f.m.iter()
            .flatten()
            .chain(&f.center)
            .chain([&f.n, &f.w])
            .map(bits)
            .max()
            .unwrap_or(0)
    };
    // The weights (below 2^(4G+1)) first, before any product.
    let g = da.iter().chain(db).map(bits).max().unwrap_or(0);
    if 4 * g + 6 > 126 {
        return None;
    }
    let weights = Weights::of(&da.map(Word), &db.map(Word));
    let word = |x: &i128| Word(*x);
    a.iter()
        .zip(b)
        .map(|(a, b)| {
            // The quantities first (below 2^(4F+4)), then their actual size.
            if 4 * (frame_bits(a).max(frame_bits(b))) + 4 > 126 {
                return None;
            }
            let minors = RelativeMinors::of(&a.map(word), &b.map(word));
            let q = minors.all().map(|w| bits(&w.0)).max().unwrap_or(0);
            (2 * q + 4 * g + 6 <= 126).then(|| minors.weighted(&weights).map(|w| w.0))
        })
        .collect()
}

/// An `i128` in plain machine arithmetic, for [`rigid_values`] only,
/// whose bound keeps every number on the way below `2^126`.
#[derive(Clone, Copy, Debug)]
struct Word(i128);

impl RingOps for Word {
    fn zero() -> Self {
        Word(0)
    }
    fn one() -> Self {
        Word(1)
    }
    fn from_i64(v: i64) -> Self {
        Word(i128::from(v))
    }
    fn is_zero(&self) -> bool {
        self.0 == 0
    }
    fn plus(&self, o: &Self) -> Self {
        Word(self.0 + o.0)
    }
    fn minus(&self, o: &Self) -> Self {
        Word(self.0 - o.0)
    }
    fn times(&self, o: &Self) -> Self {
        Word(self.0 * o.0)
    }
    fn negated(&self) -> Self {
        Word(-self.0)
    }
    fn div_small(&self, k: i64) -> Self {
        Word(self.0 / i128::from(k))
    }
}

impl ScaledSum for Word {
    type Scalar = Word;
    fn add_scaled(&mut self, s: &Word, q: &Word) {
        self.0 += s.0 * q.0;
    }
}

/// A ring of integer polynomials with its integer scalars, for the
/// weighted sums of squares of [`rigid_characteristic`] (a product by a
/// constant costs far less than one by a constant polynomial).
pub trait ScaledSum: RingOps {
    /// The constants.
    type Scalar: RingOps;
    /// `self ← self + s·q`.
    fn add_scaled(&mut self, s: &Self::Scalar, q: &Self);
}

impl ScaledSum for Int {
    type Scalar = Int;
    fn add_scaled(&mut self, s: &Int, q: &Int) {
        self.add_product(s, q, false);
    }
}

impl ScaledSum for ZPoly {
    type Scalar = Int;
    fn add_scaled(&mut self, s: &Int, q: &ZPoly) {
        *self = &*self + &q.mul_int(s);
    }
}

impl ScaledSum for SmallPoly {
    type Scalar = SmallInt;
    fn add_scaled(&mut self, s: &SmallInt, q: &SmallPoly) {
        SmallPoly::add_scaled(self, s, q);
    }
}

/// Column `j` of `m`.
fn column<R>(m: &Mat3<R>, j: usize) -> [&R; 3] {
    [&m[0][j], &m[1][j], &m[2][j]]
}

/// `s²·det(λ·D_A + Gᵀ·D_B·G)` as `[c_4, …, c_0]` (high → low in λ) for two
/// rigid placements (module docs) with body quadrics `diag(da)`,
/// `diag(db)`, where `s = n_A·n_B·w_A·w_B` clears every denominator.
///
/// With `T, U ⊆ {0, 1, 2, 3}` (columns and rows of `G`, index 3 the
/// homogeneous one), `det(λD_A + GᵀD_BG) = Σ λ^(4−|T|)·D_A(Tᶜ)·D_B(U)·det(G_(U,T))²`
/// over `|U| = |T|` ([`subset_products`] for `D(S)`). A minor with row 3
/// but not column 3 vanishes; one with both is a minor of `R`; and since
/// `R` is a rotation (`adj R = Rᵀ`, columns `Re_j × Re_k = ±Re_l`) the
/// squared minors are, times `s²`, the squares of
/// * `s` (sizes 0 and 3 of `R`);
/// * `R̃ = w_Aw_B·M_BᵀM_A = s·R` (size 1, and size 2 as the complementary
///   entry);
/// * `d̃ = n_A·M_Bᵀδ = s·d` (rows `{i}`, columns `{3}`), `δ = w_B·C_A − w_A·C_B`;
/// * `x̃_(·j) = M_Bᵀ((M_Ae_j) × δ) = s·(Re_j × d)` (rows `{i, i′}`,
///   columns `{j, 3}`: entry `i″` of the cross product);
/// * `d̃′ = n_B·M_Aᵀδ = s·Rᵀd` (rows `{0, 1, 2}`, columns `{j, j′, 3}`:
///   entry `j″`).
///
/// For the quadrics `A = N_AᵀD_AN_A` of the integer inverse placements
/// `N_A = n_Aw_A·[[R_Aᵀ, −R_Aᵀc_A], [0, 1]]` (`rigid_inverse`), `s²` times
/// coefficient `k` of their [`crate::characteristic`] is
/// `(n_Aw_A)^(2k)·(n_Bw_B)^(8−2k)` times coefficient `k` here: the same
/// quartic up to a rescaling of λ and a positive factor, which keep every
/// sign Theorem 3.10 reads. 90 products for the short quantities, 25
/// squares and 46 products by constants, against degree `8·deg(n_Aw_A)`
/// more in every coefficient through the quadrics.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_quadric::{characteristic, congruence, rigid_characteristic, rigid_inverse, RigidFrame};
/// let i = |v: i64| Int::from(v);
/// let frame = |q: [i64; 4], c: [i64; 3], w: i64| {
///     let q = q.map(i);
///     RigidFrame {
///         m: ccd_quadric::rotation_numerator(&q),
///         n: ccd_quadric::norm2(&q),
///         center: c.map(i),
///         w: i(w),
///     }
/// };
/// let (a, b) = (frame([1, 2, 0, 1], [1, 0, 2], 3), frame([2, 0, 1, 1], [4, 1, 0], 1));
/// let (da, db) = ([1, 4, 9, -36].map(i), [4, 1, 1, -4].map(i));
/// let quadric = |f: &RigidFrame<Int>, d: &[Int; 4]| {
///     congruence(&rigid_inverse(&f.m, &f.n, &f.center, &f.w), d)
/// };
/// let old = characteristic(&quadric(&a, &da), &quadric(&b, &db));
/// let new = rigid_characteristic(&a, &b, &da, &db);
/// let (pa, pb) = (&a.n * &a.w, &b.n * &b.w);
/// let s = &pa * &pb;
/// for (k, (o, n)) in old.iter().rev().zip(new.iter().rev()).enumerate() {
///     assert_eq!(o * &s * &s, n * &pa.pow(2 * k as u32) * &pb.pow(8 - 2 * k as u32));
/// }
/// ```
pub fn rigid_characteristic<R: ScaledSum>(
    a: &RigidFrame<R>,
    b: &RigidFrame<R>,
    da: &[R::Scalar; 4],
    db: &[R::Scalar; 4],
) -> [R; 5] {
    RelativeMinors::of(a, b).weighted(&Weights::of(da, db))
}

/// The quantities whose squares make up [`rigid_characteristic`]: `s`,
/// `R̃`, `d̃`, `d̃′` and `x̃`, each `s` times a minor of the relative
/// placement `G`.
struct RelativeMinors<R> {
    s: R,
    r: Mat3<R>,
    d: [R; 3],
    dp: [R; 3],
    x: Mat3<R>,
}

impl<R: ScaledSum> RelativeMinors<R> {
    /// The quantities of two rigid frames: 90 products.
    fn of(a: &RigidFrame<R>, b: &RigidFrame<R>) -> RelativeMinors<R> {
        // Σ_k x[k]·y[k].
        let dot = |x: [&R; 3], y: [&R; 3]| {
            let mut e = R::zero();
            for (p, q) in x.into_iter().zip(y) {
                if !p.is_zero() && !q.is_zero() {
                    e.add_product(p, q, false);
                }
            }
            e
        };
        let times = |x: &R, y: R| {
            let mut e = R::zero();
            e.set_product(x, &y);
            e
        };
        let delta: [R; 3] = std::array::from_fn(|k| {
            let mut e = R::zero();
            e.set_product(&b.w, &a.center[k]);
            e.add_product(&a.w, &b.center[k], true);
            e
        });
        let delta_ref = [&delta[0], &delta[1], &delta[2]];
        let wab = a.w.times(&b.w);
        let s = a.n.times(&b.n).times(&wab);
        let r: Mat3<R> = std::array::from_fn(|i| {
            std::array::from_fn(|j| times(&wab, dot(column(&b.m, i), column(&a.m, j))))
        });
        let d: [R; 3] = std::array::from_fn(|i| times(&a.n, dot(column(&b.m, i), delta_ref)));
        let dp: [R; 3] = std::array::from_fn(|j| times(&b.n, dot(column(&a.m, j), delta_ref)));
        // x̃[i][j] = (M_Bᵀ·((M_A e_j) × δ))_i.
        let cross: [[R; 3]; 3] = std::array::from_fn(|j| {
            let u = column(&a.m, j);
            std::array::from_fn(|k| {
                let (p, q) = ((k + 1) % 3, (k + 2) % 3);
                let mut e = R::zero();
                e.add_product(u[p], &delta[q], false);
                e.add_product(u[q], &delta[p], true);
                e
            })
        });
        let x = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                dot(column(&b.m, i), [&cross[j][0], &cross[j][1], &cross[j][2]])
            })
        });
        RelativeMinors { s, r, d, dp, x }
    }

    /// Every quantity.
    fn all(&self) -> impl Iterator<Item = &R> {
        std::iter::once(&self.s)
            .chain(self.r.iter().flatten())
            .chain(&self.d)
            .chain(&self.dp)
            .chain(self.x.iter().flatten())
    }

    /// `Σ λ^k·Σ weight·square` (see [`rigid_characteristic`]): 25 squares
    /// and 46 products by constants.
    fn weighted(&self, w: &Weights<R::Scalar>) -> [R; 5] {
        // Coefficient of λ^k at f[4 − k], each square formed once.
        let mut f: [R; 5] = std::array::from_fn(|_| R::zero());
        let mut add = |q: &R, terms: &[(usize, &R::Scalar)]| {
            if q.is_zero() {
                return;
            }
            let square = q.squared();
            for &(k, weight) in terms {
                f[4 - k].add_scaled(weight, &square);
            }
        };
        add(
            &self.s,
            &[(4, &w.s[0]), (3, &w.s[1]), (1, &w.s[2]), (0, &w.s[3])],
        );
        for i in 0..3 {
            add(&self.d[i], &[(3, &w.d[i])]);
            add(&self.dp[i], &[(1, &w.dp[i])]);
            for j in 0..3 {
                let r = &w.r[i][j];
                add(&self.r[i][j], &[(3, &r[0]), (2, &r[1]), (1, &r[2])]);
                add(&self.x[i][j], &[(2, &w.x[i][j])]);
            }
        }
        f
    }
}

/// The constant weights of [`RelativeMinors::weighted`]: for each
/// quantity and power of λ, `Σ D_A(Tᶜ)·D_B(U)` over the minors `(U, T)`
/// it stands for ([`rigid_characteristic`]).
struct Weights<S> {
    /// `s²` at λ⁴, λ³, λ¹, λ⁰.
    s: [S; 4],
    /// `d̃_i²` at λ³.
    d: [S; 3],
    /// `d̃′_j²` at λ¹.
    dp: [S; 3],
    /// `R̃_ij²` at λ³, λ², λ¹.
    r: [[[S; 3]; 3]; 3],
    /// `x̃_ij²` at λ².
    x: [[S; 3]; 3],
}

impl<S: RingOps> Weights<S> {
    /// From the diagonals (bit `c` of a table index: entry `c`).
    fn of(da: &[S; 4], db: &[S; 4]) -> Weights<S> {
        let (ta, tb) = (subset_products(da), subset_products(db));
        let w = |pairs: &[(usize, usize)]| {
            pairs
                .iter()
                .fold(S::zero(), |w, &(sa, sb)| w.plus(&ta[sa].times(&tb[sb])))
        };
        let bit = |i: usize| 1usize << i;
        Weights {
            // The full minors (sizes 0 and 3 of R, with and without row
            // and column 3).
            s: [w(&[(15, 0)]), w(&[(7, 8)]), w(&[(8, 7)]), w(&[(0, 15)])],
            // Rows {i}, columns {3}.
            d: std::array::from_fn(|i| w(&[(7, bit(i))])),
            // Rows {0,1,2}, columns {0,1,2,3}∖{j}.
            dp: std::array::from_fn(|j| w(&[(bit(j), 7)])),
            // Size 1 (rows {i}, columns {j}; with 3 in both), and the
            // complementary size 2 (rows {0,1,2}∖{i}, columns {0,1,2}∖{j};
            // with 3 in both).
            r: std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    let (ri, cj) = (bit(i), bit(j));
                    [
                        w(&[(15 ^ cj, ri)]),
                        w(&[(7 ^ cj, 8 | ri), (8 | cj, 7 ^ ri)]),
                        w(&[(cj, 15 ^ ri)]),
                    ]
                })
            }),
            // Rows {0,1,2}∖{i}, columns {j, 3}.
            x: std::array::from_fn(|i| std::array::from_fn(|j| w(&[(7 ^ bit(j), 7 ^ bit(i))]))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// `rigid_values` is the exact quartic wherever it answers, and its
        /// bound keeps every machine operation in range (an overflow
        /// panics in this debug build) for numbers of every size up to
        /// far past where it declines: frame numbers and diagonal entries
        /// of up to 60 bits.
        #[test]
        fn rigid_values_are_exact_or_declined(
            raw in proptest::collection::vec(any::<i64>(), 38),
            frame_bits in 1u32..61,
            diagonal_bits in 1u32..61,
        ) {
            let cut = |x: i64, bits: u32| x >> (64 - bits);
            let frame = |o: usize| RigidFrame {
                m: std::array::from_fn(|i| std::array::from_fn(|j| i128::from(cut(raw[o + 3 * i + j], frame_bits)))),
                n: i128::from(cut(raw[o + 9], frame_bits)),
                center: std::array::from_fn(|k| i128::from(cut(raw[o + 10 + k], frame_bits))),
                w: i128::from(cut(raw[o + 13], frame_bits)),
            };
            let (a, b) = (frame(0), frame(14));
            let diagonal = |o: usize| -> [i128; 4] { std::array::from_fn(|k| i128::from(cut(raw[o + k], diagonal_bits))) };
            let (da, db) = (diagonal(28), diagonal(32));
            let int = |x: &i128| Int::from_i128(*x);
            let exact = rigid_characteristic(&a.map(int), &b.map(int), &da.each_ref().map(int), &db.each_ref().map(int));
            if let Some(values) = rigid_values(&[a], &[b], &da, &db) {
                prop_assert_eq!(values[0].map(Int::from_i128), exact);
            } else {
                // Declined only past the bound's guarantee (8F + 4G <= 112
                // with the quantities at their largest).
                prop_assert!(8 * frame_bits + 4 * diagonal_bits > 112);
            }
        }
    }
}
