//! `f(λ; u)` of two bodies that never turn (static or translating along
//! polynomial curves), set up in the frame of A's centre: a handful of
//! products of constant 3×3 integer matrices and short polynomials in `u`
//! instead of two moving 4×4 quadrics and their determinant.
//!
//! # The formula
//!
//! A placed body's integer quadric is `A = Nᵀ·D·N` with `N` its inverse
//! placement `[[X, y(u)], [0, z]]` scaled to a primitive integer matrix
//! ([`crate::matrices`]); for a body that does not turn and moves along a
//! polynomial curve, `X` and `z` are constants and its centre is
//! `c(u) = −X⁻¹·y(u)`. The translation
//! `T = [[I, c_A], [0, 1]]` has determinant 1, so
//! `det(λA + B) = det(Tᵀ(λA + B)T)`, and in that frame
//!
//! `TᵀAT = [[K_A, 0], [0, −κ_A]]`, `TᵀBT = [[K_B, −K_B·d], [−dᵀK_B, dᵀK_B·d − κ_B]]`
//!
//! with `K = XᵀD₃X`, `κ = −d₄·z² > 0` and `d(u) = c_B(u) − c_A(u)` (the
//! scales of the integer quadrics, and so λ's, are kept exactly). With
//! `P(λ) = λK_A + K_B` and `d = e/δ` (`e` integer, `δ > 0`), the Schur
//! complement of `P` gives
//!
//! `δ²·det(λA + B) = det P·(eᵀK_B·e − δ²(κ_B + λκ_A)) − (K_B·e)ᵀ·adj P·(K_B·e)`,
//!
//! where `det P = λ³ det K_A + λ² p₂ + λ p₁ + det K_B` with
//! `p₂ = tr(adj K_A·K_B)`, `p₁ = tr(K_A·adj K_B)`, and
//! `adj P = λ² adj K_A + λ·(adj(K_A + K_B) − adj K_A − adj K_B) + adj K_B`.
//! Translating by `d` once more (`[[I, d], [0, 1]]`, the frame of B's
//! centre) gives the same determinant as
//! `det P·(λ·eᵀK_A·e − δ²(κ_B + λκ_A)) − λ²(K_A·e)ᵀ·adj P·(K_A·e)`;
//! comparing the two in the powers of λ, the part `g(λ)` without `κ` is
//!
//! `g(λ) = λ³·det K_A·eᵀK_B·e + λ²·(p₂·eᵀK_B·e − (K_B·e)ᵀ·adj K_A·(K_B·e)) + λ·det K_B·eᵀK_A·e`
//!
//! (the `λ`-coefficient read from the second form, the others from the
//! first; `g(0) = 0` as `bᵀ·adj K·b = det K·eᵀK·e` for `b = K·e`), so
//!
//! `δ²·det(λA + B) = g(λ) − δ²(κ_B + λκ_A)·det P`
//!
//! needs one quadratic form with an adjugate, not two. The factor `δ²` is
//! a positive constant, which the normalisation's content removal takes
//! out: the normalised `f` is the very polynomial of the general route
//! (checked against it by a property test below).
//!
//! # Machine words
//!
//! The routine is written once over [`CentredInteger`] and runs over
//! `i128` ([`SmallInt`], [`SmallPoly`]) when the numbers are short (one-
//! or two-digit radii and centres: `f` has at most about 120 bits), over
//! [`Int`] otherwise: three-decimal radii already give `K` entries of
//! about 60 bits and an `f` of about 250 bits. The bodies themselves
//! ([`Centred`]) and the short numbers of the set-up ([`Offset`]: the
//! centre offset, `K·e`, `eᵀK·e`, `adj K_A`) fit `i128` far more often,
//! and are lifted to [`Int`] from there ([`Centred::lifted`],
//! [`Offset::lifted`]).

use crate::curve::Integer;
use ccd_arith::{Int, RingOps, SmallInt};
use ccd_poly::{SmallPoly, ZPoly};
use ccd_quadric::{adj3, det3, Mat3};

/// The exact integers the set-up runs over, with their polynomials in `u`:
/// [`Int`] with [`ZPoly`], and [`SmallInt`] with [`SmallPoly`] (`i128`
/// numbers that mark an overflow, which every later operation keeps). The
/// routine [`centred_characteristic`] is written once over this trait; a
/// caller runs it over `SmallInt` first and over `Int` when a result is
/// overflowed (the same polynomials when none is: every operation is
/// exact or overflows).
pub(crate) trait CentredInteger: Integer {
    /// Polynomials in `u` with coefficients of this type.
    type Poly: RingOps;
    /// `|self|`.
    fn abs(&self) -> Self;
    /// The image of a [`ZPoly`] (overflowed if it does not fit).
    fn poly(p: &ZPoly) -> Self::Poly;
    /// The constant polynomial `x`.
    fn constant(x: &Self) -> Self::Poly;
    /// `Σ cᵢ·pᵢ`, accumulated in one coefficient vector.
    fn combination<'a>(terms: impl IntoIterator<Item = (&'a Self, &'a Self::Poly)>) -> Self::Poly
    where
        Self: 'a;
    /// `self += x·y`, in place where the type allows it.
    fn add_mul(&mut self, x: &Self, y: &Self);
    /// `Σ xᵢ·yᵢ` for polynomials, accumulated in one coefficient vector.
    fn dot<'a>(terms: impl IntoIterator<Item = (&'a Self::Poly, &'a Self::Poly)>) -> Self::Poly
    where
        Self: 'a;
    /// `gcd(g, content(p))` (`≥ 0`).
    fn gcd_content(g: &Self, p: &Self::Poly) -> Self;
    /// `p/k` for a `k` dividing every coefficient.
    fn div_poly(p: &Self::Poly, k: &Self) -> Self::Poly;
}

impl CentredInteger for Int {
    type Poly = ZPoly;
    fn abs(&self) -> Int {
        Int::abs(self)
    }
    fn poly(p: &ZPoly) -> ZPoly {
        p.clone()
    }
    fn constant(x: &Int) -> ZPoly {
        ZPoly::constant(x.clone())
    }
    fn combination<'a>(terms: impl IntoIterator<Item = (&'a Int, &'a ZPoly)>) -> ZPoly {
        let mut acc: Vec<Int> = Vec::new();
        for (c, p) in terms {
            if !c.is_zero() {
                for (k, x) in p.coeffs().iter().enumerate() {
                    accumulate(&mut acc, k, c, x);
                }
            }
        }
        ZPoly::new(acc)
    }
    fn add_mul(&mut self, x: &Int, y: &Int) {
        Int::add_mul(self, x, y);
    }
    fn dot<'a>(terms: impl IntoIterator<Item = (&'a ZPoly, &'a ZPoly)>) -> ZPoly {
        let mut acc: Vec<Int> = Vec::new();
        for (x, y) in terms {
            for (i, xi) in x.coeffs().iter().enumerate() {
                for (j, yj) in y.coeffs().iter().enumerate() {
                    accumulate(&mut acc, i + j, xi, yj);
                }
            }
        }
        ZPoly::new(acc)
    }
    fn gcd_content(g: &Int, p: &ZPoly) -> Int {
        g.gcd(&p.content())
    }
    fn div_poly(p: &ZPoly, k: &Int) -> ZPoly {
        p.div_exact_int(k)
    }
}

/// `acc[k] += x·y` (a new last coefficient is the product itself, not a
/// sum with a zero). The callers accumulate in order, `k ≤ acc.len()`;
/// were that ever broken, the gap is filled with zeros, so the sum stays
/// right.
fn accumulate(acc: &mut Vec<Int>, k: usize, x: &Int, y: &Int) {
    if k > acc.len() {
        acc.resize(k, Int::zero());
    }
    match acc.get_mut(k) {
        Some(a) => a.add_mul(x, y),
        None => acc.push(x * y),
    }
}

impl CentredInteger for SmallInt {
    type Poly = SmallPoly;
    fn abs(&self) -> SmallInt {
        match self.to_i128() {
            Some(v) if v < 0 => self.negated(),
            _ => *self,
        }
    }
    fn poly(p: &ZPoly) -> SmallPoly {
        SmallPoly::lowered(p)
    }
    fn constant(x: &SmallInt) -> SmallPoly {
        SmallPoly::constant(x)
    }
    fn combination<'a>(
        terms: impl IntoIterator<Item = (&'a SmallInt, &'a SmallPoly)>,
    ) -> SmallPoly {
        let mut acc = SmallPoly::zero();
        for (c, p) in terms {
            if !c.is_zero() {
                acc.add_product(&SmallPoly::constant(c), p, false);
            }
        }
        acc
    }
    fn add_mul(&mut self, x: &SmallInt, y: &SmallInt) {
        self.add_product(x, y, false);
    }
    fn dot<'a>(terms: impl IntoIterator<Item = (&'a SmallPoly, &'a SmallPoly)>) -> SmallPoly {
        let mut acc = SmallPoly::zero();
        for (x, y) in terms {
            acc.add_product(x, y, false);
        }
        acc
    }
    fn gcd_content(g: &SmallInt, p: &SmallPoly) -> SmallInt {
        // A gcd of values in i128 other than −2^127 fits i128.
        match (g.to_i128(), p.gcd_with(0)) {
            // (2^127, the gcd of −2^127 alone, is the overflow marker.)
            (Some(g), Some(c)) => {
                SmallInt::from_i128(ccd_arith::gcd_u128(g.unsigned_abs(), c) as i128)
            }
            _ => SmallInt::overflowed(),
        }
    }
    fn div_poly(p: &SmallPoly, k: &SmallInt) -> SmallPoly {
        match k.to_i128() {
            Some(k) => p.div_exact_int(k),
            // Overflowed, as `k` is.
            None => SmallPoly::constant(k),
        }
    }
}

/// The constant part of a body that does not turn, at its centre: the
/// quadric there is `scale·[[k, 0], [0, −kappa]]`.
#[derive(Clone, Debug)]
pub(crate) struct Block<I: CentredInteger> {
    /// `K = XᵀD₃X`, divided by [`Block::scale`]: the integer quadric's
    /// constant 3×3 block.
    pub(crate) k: Mat3<I>,
    /// `κ = −d₄·z² > 0`, divided by [`Block::scale`]: minus the integer
    /// quadric's corner at its centre.
    pub(crate) kappa: I,
    /// The common content `s > 0` of `K` and `κ` taken out of them.
    pub(crate) scale: I,
}

impl Block<SmallInt> {
    /// The same block over [`Int`], `None` if a number overflowed.
    pub(crate) fn lifted(&self) -> Option<Block<Int>> {
        let int = |x: &SmallInt| x.to_int();
        let k: Vec<Int> = self.k.iter().flatten().map(int).collect::<Option<_>>()?;
        Some(Block {
            k: std::array::from_fn(|i| std::array::from_fn(|j| k[3 * i + j].clone())),
            kappa: int(&self.kappa)?,
            scale: int(&self.scale)?,
        })
    }
}

/// A body that does not turn, as the frame of its own centre sees it, over
/// the integers `I` ([`CentredInteger`]).
#[derive(Clone, Debug)]
pub(crate) struct Centred<I: CentredInteger> {
    /// `K`, `κ` and their content.
    pub(crate) block: Block<I>,
    /// The centre curve `c(u)` times [`Centred::denominator`].
    pub(crate) centre: [I::Poly; 3],
    /// The centre curve's denominator (a nonzero integer).
    pub(crate) denominator: I,
}

impl<I: CentredInteger> Centred<I> {
    /// The body with block `k` (symmetric), corner `−kappa` (`kappa > 0`),
    /// centre curve `centre/denominator`; `k` and `kappa` are stored
    /// divided by their common content ([`Block::scale`]).
    pub(crate) fn new(k: Mat3<I>, kappa: I, centre: [I::Poly; 3], denominator: I) -> Centred<I> {
        let mut scale = kappa.abs();
        for (i, row) in k.iter().enumerate() {
            for x in &row[i..] {
                if scale.is_one() {
                    break;
                }
                scale = scale.gcd(x);
            }
        }
        let (k, kappa) = if scale.is_one() || scale.is_zero() {
            (k, kappa)
        } else {
            (
                k.map(|row| row.map(|x| x.div_exact(&scale))),
                kappa.div_exact(&scale),
            )
        };
        Centred {
            block: Block { k, kappa, scale },
            centre,
            denominator,
        }
    }
}

impl Centred<SmallInt> {
    /// The same body over [`Int`], `None` if a number overflowed.
    pub(crate) fn lifted(&self) -> Option<Centred<Int>> {
        Some(Centred {
            block: self.block.lifted()?,
            centre: SmallPoly::to_zpolys(&self.centre)?,
            denominator: self.denominator.to_int()?,
        })
    }

    /// Whether [`centred_characteristic`] of `a` and `b` is likely to fit
    /// `i128` (a size estimate only, from the bit lengths `k` of the
    /// blocks and corners, `e` of the centre difference and `s` of the
    /// scales: `f` has about `4k + 2e + 4s` bits; an overflow is detected
    /// anyway, this skips a doomed attempt).
    pub(crate) fn worth_small(a: &Centred<SmallInt>, b: &Centred<SmallInt>) -> bool {
        let bits = |x: &SmallInt| {
            x.to_i128()
                .map_or(128, |v| 128 - v.unsigned_abs().leading_zeros())
        };
        let block = |c: &Centred<SmallInt>| {
            let b = &c.block;
            b.k.iter().flatten().chain([&b.kappa]).map(bits).max()
        };
        let centre = |c: &Centred<SmallInt>| {
            let poly = c
                .centre
                .iter()
                .map(|p| p.max_bits() as u32)
                .max()
                .unwrap_or(0);
            poly + bits(&c.denominator)
        };
        let k = block(a).max(block(b)).unwrap_or(0);
        let e = centre(a).max(centre(b)) + 1;
        let s = bits(&a.block.scale).max(bits(&b.block.scale));
        4 * k + 2 * e + 4 * s + 12 <= 126
    }
}

/// `Σ_ij m_ij·x_ij`: the trace of `m·x` for a symmetric `x`.
fn trace_product<I: CentredInteger>(m: &Mat3<I>, x: &Mat3<I>) -> I {
    let mut s = I::zero();
    for (mr, xr) in m.iter().zip(x) {
        for (a, b) in mr.iter().zip(xr) {
            s.add_mul(a, b);
        }
    }
    s
}

/// The short numbers of [`centred_characteristic`]: those of about the
/// size of the bodies' own (twice the bits of `K` at most), which fit
/// `i128` ([`SmallInt`]) far more often than `f` does, and so are formed
/// there and lifted ([`Offset::lifted`]) even when `f` is not.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Offset<I: CentredInteger> {
    /// `δ²`, with `d = c_B − c_A = e/δ`: `e = w_A·C_B − w_B·C_A` and
    /// `δ = w_A·w_B`, both divided by their common content `h` (the
    /// formula is homogeneous of degree 2 in `(e, δ)`, so `f` is divided
    /// by `h²`).
    pub(crate) delta2: I,
    /// `b = K_B·e`.
    pub(crate) kb_e: [I::Poly; 3],
    /// `E_A = eᵀK_A·e`.
    pub(crate) e_a: I::Poly,
    /// `E_B = eᵀK_B·e`.
    pub(crate) e_b: I::Poly,
    /// `adj K_A`.
    pub(crate) adj_a: Mat3<I>,
}

impl<I: CentredInteger> Offset<I> {
    /// The short numbers of the bodies `a` and `b`.
    pub(crate) fn new(a: &Centred<I>, b: &Centred<I>) -> Offset<I> {
        let minus_wb = b.denominator.negated();
        let e: [I::Poly; 3] = std::array::from_fn(|i| {
            I::combination([(&a.denominator, &b.centre[i]), (&minus_wb, &a.centre[i])])
        });
        let delta = a.denominator.times(&b.denominator);
        let h = e.iter().fold(delta.abs(), |g, p| {
            if g.is_one() {
                g
            } else {
                I::gcd_content(&g, p)
            }
        });
        let (e, delta) = if h.is_one() {
            (e, delta)
        } else {
            (e.map(|p| I::div_poly(&p, &h)), delta.div_exact(&h))
        };
        let (ka_e, kb_e) = (times::<I>(&a.block.k, &e), times::<I>(&b.block.k, &e));
        Offset {
            delta2: delta.times(&delta),
            e_a: dot::<I>(&e, &ka_e),
            e_b: dot::<I>(&e, &kb_e),
            kb_e,
            adj_a: adj3(&a.block.k),
        }
    }
}

impl Offset<SmallInt> {
    /// The same numbers over [`Int`], `None` if one overflowed.
    pub(crate) fn lifted(&self) -> Option<Offset<Int>> {
        let int = |x: &SmallInt| x.to_int();
        let adj: Vec<Int> = self
            .adj_a
            .iter()
            .flatten()
            .map(int)
            .collect::<Option<_>>()?;

        Some(Offset {
            delta2: int(&self.delta2)?,
            kb_e: SmallPoly::to_zpolys(&self.kb_e)?,
            e_a: self.e_a.to_zpoly()?,
            e_b: self.e_b.to_zpoly()?,
            adj_a: std::array::from_fn(|i| std::array::from_fn(|j| adj[3 * i + j].clone())),
        })
    }
}

/// `det(λA + B)` (high → low in λ) times a positive constant, for two
/// bodies that do not turn (module docs) with blocks `a`, `b` and the
/// short numbers `offset` ([`Offset::new`] of the two), over the
/// integers `I`: over
/// [`SmallInt`] the result is exact unless a coefficient is overflowed,
/// and then the very polynomials of the route over [`Int`].
///
/// In the powers of λ (module docs, `E_A = eᵀK_A·e`, `E_B = eᵀK_B·e`,
/// `q = (K_B·e)ᵀ·adj K_A·(K_B·e)`):
///
/// - `c_4 = −δ²κ_A·det K_A`,
/// - `c_3 = det K_A·E_B − δ²(κ_A·p₂ + κ_B·det K_A)`,
/// - `c_2 = p₂·E_B − q − δ²(κ_A·p₁ + κ_B·p₂)`,
/// - `c_1 = det K_B·E_A − δ²(κ_A·det K_B + κ_B·p₁)`,
/// - `c_0 = −δ²κ_B·det K_B`,
///
/// with `p₁ = det(K_A + K_B) − det K_A − p₂ − det K_B` (`det P` at `λ = 1`).
///
/// The numbers are kept short by positive constants the normalisation's
/// content removal takes out anyway: `(e, δ)` divided by their common
/// content `h` ([`Offset::delta2`]), and each body's `K, κ` by theirs, `s_A` and `s_B`
/// ([`Block::scale`]). The latter rescales λ: `det(λA/s_A + B/s_B)` has
/// coefficients `c_k/(s_A^k·s_B^(4−k))`, so each is multiplied back by
/// `p^k·q^(4−k)` with `p/q = s_A/s_B` in lowest terms (a positive
/// constant times `c_k`).
pub(crate) fn centred_characteristic<I: CentredInteger>(
    a: &Block<I>,
    b: &Block<I>,
    offset: &Offset<I>,
) -> [I::Poly; 5] {
    let Offset {
        delta2,
        kb_e,
        e_a,
        e_b,
        adj_a,
    } = offset;
    // q = bᵀ·adj K_A·b with b = K_B·e.
    let q = dot::<I>(kb_e, &times::<I>(adj_a, kb_e));
    // det P = λ³ det K_A + λ² p₂ + λ p₁ + det K_B, with p₁ from
    // det(K_A + K_B) = det K_A + p₂ + p₁ + det K_B.
    let (det_a, det_b) = (det3(&a.k), det3(&b.k));
    let p2 = trace_product(adj_a, &b.k);
    let sum: Mat3<I> = std::array::from_fn(|i| std::array::from_fn(|j| a.k[i][j].plus(&b.k[i][j])));
    let p1 = det3(&sum).minus(&det_a).minus(&p2).minus(&det_b);
    let (ka, kb) = (delta2.times(&a.kappa), delta2.times(&b.kappa));
    // c_k times factor[k] (the rescaling of λ), with its constant part.
    let factor = lambda_factors(&a.scale, &b.scale);
    let scaled = |k: usize, x: &I| {
        if factor[k].is_one() {
            x.clone()
        } else {
            factor[k].times(x)
        }
    };
    let one = I::constant(&I::one());
    let constant = |k: usize, x: &I, y: &I, z: &I, w: &I| {
        // −factor_k·(x·y + z·w)
        let mut s = x.times(y);
        s.add_product(z, w, false);
        scaled(k, &s).negated()
    };
    let zero = I::zero();
    let c3 = I::combination([
        (&scaled(3, &det_a), e_b),
        (&constant(3, &ka, &p2, &kb, &det_a), &one),
    ]);
    let c2 = I::combination([
        (&scaled(2, &p2), e_b),
        (&scaled(2, &I::from_i64(-1)), &q),
        (&constant(2, &ka, &p1, &kb, &p2), &one),
    ]);
    let c1 = I::combination([
        (&scaled(1, &det_b), e_a),
        (&constant(1, &ka, &det_b, &kb, &p1), &one),
    ]);
    [
        I::constant(&constant(4, &ka, &det_a, &zero, &zero)),
        c3,
        c2,
        c1,
        I::constant(&constant(0, &kb, &det_b, &zero, &zero)),
    ]
}

/// `m·v` for a constant matrix `m` and a vector of polynomials `v`.
fn times<I: CentredInteger>(m: &Mat3<I>, v: &[I::Poly; 3]) -> [I::Poly; 3] {
    std::array::from_fn(|i| I::combination((0..3).map(|j| (&m[i][j], &v[j]))))
}

/// `xᵀ·y` for vectors of polynomials.
fn dot<I: CentredInteger>(x: &[I::Poly; 3], y: &[I::Poly; 3]) -> I::Poly {
    I::dot(x.iter().zip(y))
}

/// `p^k·q^(4−k)` for `k = 0, …, 4`, with `p/q = s_A/s_B` in lowest terms:
/// `c_k` of `det(λA/s_A + B/s_B)` times it is `c_k` of `det(λA + B)` up to
/// the positive constant `(s_B/g)^4` ([`centred_characteristic`]).
fn lambda_factors<I: CentredInteger>(s_a: &I, s_b: &I) -> [I; 5] {
    if s_a == s_b {
        return std::array::from_fn(|_| I::one());
    }
    let g = s_a.gcd(s_b);
    let (p, q) = (s_a.div_exact(&g), s_b.div_exact(&g));
    let powers = |x: &I| -> [I; 5] {
        let mut out: [I; 5] = std::array::from_fn(|_| I::one());
        for k in 1..5 {
            out[k] = out[k - 1].times(x);
        }
        out
    };
    let (pp, qp) = (powers(&p), powers(&q));
    std::array::from_fn(|k| pp[k].times(&qp[4 - k]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinds::{Bezier, Body, Motion};
    use crate::matrices::{placed_quadric, PlacedQuadric};
    use crate::{normalise, CharPoly};
    use ccd_arith::Rat;

    fn rat(n: i64, d: i64) -> Rat {
        Rat::from_frac(n, d)
    }

    /// A body that never turns: static at `pts[0]` when there is one
    /// control point, else translating along the Bézier curve `pts`; a
    /// zero quaternion is replaced by the identity.
    fn body_of(radii: [Rat; 3], q: [Rat; 4], pts: Vec<[Rat; 3]>) -> Body {
        let mut q = q;
        if q.iter().all(Rat::is_zero) {
            q[0] = Rat::one();
        }
        let motion = if pts.len() == 1 {
            Motion::Static {
                center: pts[0].clone(),
                orientation: q,
            }
        } else {
            Motion::Translation {
                center: Bezier {
                    points: pts,
                    weights: None,
                },
                orientation: q,
            }
        };
        Body { radii, motion }
    }

    /// The two bodies placed over `u ∈ [0, 1]`.
    fn placed_pair(a: &Body, b: &Body) -> (PlacedQuadric, PlacedQuadric) {
        let span = [Rat::zero(), Rat::one()];
        (
            placed_quadric(a, &span).unwrap(),
            placed_quadric(b, &span).unwrap(),
        )
    }

    /// `f` of the centred route and of the general route (`det` of the two
    /// integer quadrics, normalised), for two bodies that never turn.
    fn general_and_centred(a: &Body, b: &Body) -> (CharPoly, CharPoly) {
        let (pa, pb) = placed_pair(a, b);
        assert!(!pa.turns() && !pb.turns());
        let general = CharPoly {
            coeffs: normalise(ccd_quadric::characteristic(&pa.quadric(), &pb.quadric())),
        };
        (CharPoly::from_placed(&pa, &pb), general)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The centred route gives the very `f` of the general route
        /// (`det` of the two integer quadrics, normalised), on static and
        /// translating bodies of every orientation, with centre curves of
        /// degree 0 to 3 and long rational numbers.
        #[test]
        fn centred_route_is_the_general_route(
            radii in proptest::collection::vec((1i64..40, 1i64..9), 6),
            quats in proptest::collection::vec((-7i64..8, 1i64..1000), 8),
            points in proptest::collection::vec((-10_000_000_000i64..10_000_000_000, 1i64..1_000_000), 24),
            degrees in (0usize..4, 0usize..4),
            big in 0u32..40,
        ) {
            let body = |k: usize, deg: usize| {
                let q: [Rat; 4] = std::array::from_fn(|i| { let (n, d) = quats[4 * k + i]; rat(n, d) });
                let scale = Rat::from_int(ccd_arith::Int::from(3).pow(big));
                let pts: Vec<[Rat; 3]> = (0..=deg)
                    .map(|p| std::array::from_fn(|i| {
                        let (n, d) = points[12 * k + 3 * p + i];
                        &rat(n, d) * &scale
                    }))
                    .collect();
                let radii = std::array::from_fn(|i| { let (n, d) = radii[3 * k + i]; rat(n, d) });
                body_of(radii, q, pts)
            };
            let (a, b) = (body(0, degrees.0), body(1, degrees.1));
            let (pa, pb) = placed_pair(&a, &b);
            proptest::prop_assert!(pa.centred::<ccd_arith::Int>().is_some() && pb.centred::<ccd_arith::Int>().is_some());
            let (centred, general) = general_and_centred(&a, &b);
            proptest::prop_assert_eq!(centred, general);
        }
    }

    /// A body of the brief's kinds with radii `n/10^d`, quaternion
    /// components over `7^k`, centre control points `n/10^d` (degree `deg`).
    fn decimal_body(
        radii: &[(i64, u32)],
        quat: &[i64],
        quat_den: u32,
        points: &[(i64, u32)],
        deg: usize,
    ) -> Body {
        let decimal = |(n, d): (i64, u32)| {
            Rat::new(ccd_arith::Int::from(n), ccd_arith::Int::from(10).pow(d)).expect("nonzero")
        };
        let den = ccd_arith::Int::from(7).pow(quat_den);
        let q: [Rat; 4] = std::array::from_fn(|i| {
            Rat::new(ccd_arith::Int::from(quat[i]), den.clone()).expect("nonzero")
        });
        let pts: Vec<[Rat; 3]> = (0..=deg)
            .map(|p| std::array::from_fn(|i| decimal(points[3 * p + i])))
            .collect();
        body_of(std::array::from_fn(|i| decimal(radii[i])), q, pts)
    }

    /// `f` over `i128`, `None` when a number overflowed there.
    fn small_f(a: &Body, b: &Body) -> Option<Vec<ZPoly>> {
        let (pa, pb) = placed_pair(a, b);
        let (sa, sb) = (pa.centred::<SmallInt>()?, pb.centred::<SmallInt>()?);
        let f = centred_characteristic(&sa.block, &sb.block, &Offset::new(&sa, &sb));
        f.iter().map(SmallPoly::to_zpoly).collect()
    }

    /// `f` over [`Int`].
    fn int_f(a: &Body, b: &Body) -> Vec<ZPoly> {
        let (pa, pb) = placed_pair(a, b);
        let (ca, cb) = (pa.centred::<Int>().unwrap(), pb.centred::<Int>().unwrap());
        centred_characteristic(&ca.block, &cb.block, &Offset::new(&ca, &cb)).to_vec()
    }

    #[test]
    fn short_numbers_fit_and_long_ones_do_not() {
        let short = decimal_body(
            &[(1, 0), (2, 0), (3, 0)],
            &[1, 2, 0, 1],
            0,
            &[(1, 0), (-2, 0), (3, 0), (4, 0), (5, 0), (-6, 0)],
            1,
        );
        let other = decimal_body(
            &[(3, 1), (1, 0), (1, 0)],
            &[0, 0, 1, 1],
            1,
            &[(5, 1), (0, 0), (1, 0)],
            0,
        );
        assert_eq!(small_f(&short, &other), Some(int_f(&short, &other)));
        // Three-decimal radii (the straight-line benchmark scenes): f has
        // about 250 bits.
        let long = decimal_body(
            &[(847, 3), (2546, 3), (325, 3)],
            &[4, 3, 1, -1],
            0,
            &[
                (1067, 3),
                (-11, 3),
                (-263, 3),
                (1722, 3),
                (-1877, 3),
                (-1103, 3),
            ],
            1,
        );
        assert_eq!(small_f(&long, &other), None);
        let (pa, pb) = placed_pair(&long, &other);
        let (sa, sb) = (
            pa.centred::<SmallInt>().unwrap(),
            pb.centred::<SmallInt>().unwrap(),
        );
        assert!(!Centred::worth_small(&sa, &sb));
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// The route over `i128` ([`SmallInt`]) gives the very `f` of the
        /// route over [`Int`] whenever no number overflowed on the way, and
        /// its bodies ([`Centred::lifted`]) and short numbers
        /// ([`Offset::lifted`]) are the `Int` ones: on numbers
        /// from one digit to far beyond `i128` (radii and centres with up
        /// to 9 decimals, quaternions over `7^k` up to about `2^70`), so
        /// both sides of the overflow boundary are reached.
        #[test]
        fn small_route_is_the_int_route(
            size in 0u32..8,
            radii in proptest::collection::vec((1i64..100_000_000, 0u32..8), 6),
            quats in proptest::collection::vec(-30i64..31, 8),
            quat_den in proptest::collection::vec(0u32..25, 2),
            points in proptest::collection::vec((-1_000_000_000i64..1_000_000_000, 0u32..8), 24),
            degrees in (0usize..4, 0usize..4),
        ) {
            // Numbers of about `size` digits (and quaternion denominators
            // up to 7^(3·size)): short ones fit i128, long ones do not.
            let ten = 10i64.pow(size);
            let radii: Vec<(i64, u32)> = radii.iter().map(|&(n, d)| (n % ten + 1, d % (size + 1))).collect();
            let points: Vec<(i64, u32)> = points.iter().map(|&(n, d)| (n % (10 * ten), d % (size + 1))).collect();
            let quat_den = quat_den.iter().map(|k| k % (3 * size + 1)).collect::<Vec<_>>();
            let a = decimal_body(&radii[..3], &quats[..4], quat_den[0], &points[..12], degrees.0);
            let b = decimal_body(&radii[3..], &quats[4..], quat_den[1], &points[12..], degrees.1);
            let exact = int_f(&a, &b);
            if let Some(small) = small_f(&a, &b) {
                proptest::prop_assert_eq!(small, exact);
            }
            let (pa, pb) = placed_pair(&a, &b);
            let (sa, sb) = (pa.centred::<SmallInt>().unwrap(), pb.centred::<SmallInt>().unwrap());
            let (ia, ib) = (pa.centred::<Int>().unwrap(), pb.centred::<Int>().unwrap());
            if let Some(lifted) = Offset::new(&sa, &sb).lifted() {
                proptest::prop_assert_eq!(lifted, Offset::new(&ia, &ib));
            }
            for p in [&pa, &pb] {
                let (small, int) = (p.centred::<SmallInt>().unwrap(), p.centred::<Int>().unwrap());
                if let Some(lifted) = small.lifted() {
                    let (l, i) = (&lifted.block, &int.block);
                    proptest::prop_assert_eq!(&l.k, &i.k);
                    proptest::prop_assert_eq!(
                        (&l.kappa, &l.scale, &lifted.centre, &lifted.denominator),
                        (&i.kappa, &i.scale, &int.centre, &int.denominator)
                    );
                }
            }
        }
    }

    // From the soundness review of the i128 route (session 11): the
    // degenerate cases the generators above do not reach.
    use crate::curve::Integer;
    use ccd_arith::Ring;

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(96))]
        /// e = 0 (the same centre, static or along the same curve), and a
        /// constant offset (the same curve shifted): long numbers, both
        /// the i128 and the Int route (`big` scales every number).
        #[test]
        fn centred_route_with_equal_and_parallel_centres(
            radii in proptest::collection::vec((1i64..1000, 1i64..1000), 6),
            quats in proptest::collection::vec((-7i64..8, 1i64..50), 8),
            points in proptest::collection::vec((-1_000_000i64..1_000_000, 1i64..1000), 12),
            shift in proptest::collection::vec((-1000i64..1000, 1i64..100), 3),
            deg in 0usize..4,
            big in 0u32..30,
            same_shape in proptest::bool::ANY,
            parallel in proptest::bool::ANY,
            short in proptest::bool::ANY,
        ) {
            // Short numbers (the i128 route) or long ones (Int, lifted).
            let shorten = |v: &Vec<(i64, i64)>, m: i64, dm: i64| -> Vec<(i64, i64)> {
                if short { v.iter().map(|&(n, d)| (n % m, d % dm + 1)).collect() } else { v.clone() }
            };
            let radii: Vec<(i64, i64)> = shorten(&radii, 6, 2).into_iter().map(|(n, d)| (n.abs().max(1), d)).collect();
            let quats = shorten(&quats, 8, 1);
            let points = shorten(&points, 10, 3);
            let shift = shorten(&shift, 10, 2);
            let big = if short { 0 } else { big };
            let scale = Rat::from_int(ccd_arith::Int::from(7).pow(big));
            let r = |k: usize| -> [Rat; 3] { std::array::from_fn(|i| { let (n, d) = radii[3 * k + i]; &rat(n, d) * &scale }) };
            let q = |k: usize| -> [Rat; 4] { std::array::from_fn(|i| { let (n, d) = quats[4 * k + i]; rat(n, d) }) };
            let pts: Vec<[Rat; 3]> = (0..=deg).map(|p| std::array::from_fn(|i| { let (n, d) = points[3 * p + i]; &rat(n, d) * &scale })).collect();
            let s: [Rat; 3] = std::array::from_fn(|i| { let (n, d) = shift[i]; if parallel { &rat(n, d) * &scale } else { Rat::zero() } });
            let pts_b: Vec<[Rat; 3]> = pts.iter().map(|p| std::array::from_fn(|i| &p[i] + &s[i])).collect();
            let a = body_of(r(0), q(0), pts);
            let b = if same_shape { body_of(r(0), q(0), pts_b) } else { body_of(r(1), q(1), pts_b) };
            let (centred, general) = general_and_centred(&a, &b);
            proptest::prop_assert_eq!(centred, general);
            // And with the roles swapped.
            let (centred, general) = general_and_centred(&b, &a);
            proptest::prop_assert_eq!(centred, general);
        }
    }

    /// The overflow marker through the CentredInteger methods.
    #[test]
    fn the_overflow_marker_stays_overflowed() {
        let m = SmallInt::overflowed();
        assert!(CentredInteger::abs(&m).to_i128().is_none());
        assert!(!m.is_zero() && !m.is_one() && m != m);
        assert!(m.negated().to_i128().is_none());
        assert!(m.gcd(&SmallInt::one()).to_i128().is_none());
        assert!(SmallInt::one().div_exact(&m).to_i128().is_none());
        assert!(m.div_exact(&SmallInt::one()).to_i128().is_none());
        assert!(SmallInt::zero().div_exact(&m).to_i128().is_none());
        assert!(SmallInt::zero().times(&m).to_i128().is_none());
        // A legitimate SmallPoly coefficient −2^127: its content 2^127 is not an i128.
        let c = SmallPoly::from_i64(i64::MIN)
            .times(&SmallPoly::from_i64(i64::MAX))
            .plus(&SmallPoly::from_i64(i64::MIN)); // −2^126
        let p = c.plus(&c); // −2^127 (checked_add gives i128::MIN)
        assert!(p.is_exact());
        assert!(
            <SmallInt as CentredInteger>::gcd_content(&SmallInt::zero(), &p)
                .to_i128()
                .is_none()
        );
        assert_eq!(
            <SmallInt as CentredInteger>::gcd_content(&SmallInt::from_i64(6), &p).to_i128(),
            Some(2)
        );
        assert!(!<SmallInt as CentredInteger>::div_poly(&SmallPoly::one(), &m).is_exact());
        assert!(!<SmallInt as CentredInteger>::combination([(&m, &SmallPoly::one())]).is_exact());
        // abs(−(2^127 − 1)) = 2^127 − 1 exactly.
        let x = SmallInt::from_i128(-i128::MAX);
        assert_eq!(CentredInteger::abs(&x).to_i128(), Some(i128::MAX));
        // lambda_factors on an overflowed scale.
        let f = lambda_factors(&m, &SmallInt::one());
        assert!(f.iter().all(|x| x.to_i128().is_none()));
        let f = lambda_factors(&m, &m);
        assert!(f.iter().all(|x| x.to_i128().is_none()));
        // A Block with one overflowed entry does not lift, and f is overflowed.
        let one = SmallInt::one();
        let z = SmallInt::zero();
        let mut k = [[one, z, z], [z, one, z], [z, z, one]];
        let good = Centred::new(k, one, std::array::from_fn(|_| SmallPoly::zero()), one);
        k[2][2] = m;
        let bad = Centred::new(k, one, std::array::from_fn(|_| SmallPoly::zero()), one);
        assert!(bad.block.lifted().is_none() && bad.lifted().is_none());
        let f = centred_characteristic(&good.block, &bad.block, &Offset::new(&good, &bad));
        assert!(f.iter().any(|p| !p.is_exact()));
        let f = centred_characteristic(&bad.block, &good.block, &Offset::new(&bad, &good));
        assert!(f.iter().any(|p| !p.is_exact()));
        // Overflowed centre: the offset does not lift.
        let over_centre = Centred::new(
            [[one, z, z], [z, one, z], [z, z, one]],
            one,
            [SmallPoly::one(), SmallPoly::constant(&m), SmallPoly::one()],
            one,
        );
        assert!(Offset::new(&good, &over_centre).lifted().is_none());
        assert!(Offset::new(&over_centre, &good).lifted().is_none());
        let f = centred_characteristic(
            &good.block,
            &over_centre.block,
            &Offset::new(&good, &over_centre),
        );
        assert!(f.iter().any(|p| !p.is_exact()));
        // Overflowed denominator.
        let over_den = Centred::new(
            [[one, z, z], [z, one, z], [z, z, one]],
            one,
            std::array::from_fn(|_| SmallPoly::one()),
            m,
        );
        assert!(Offset::new(&good, &over_den).lifted().is_none());
        assert!(Offset::new(&over_den, &good).lifted().is_none());
    }

    /// Translations with equal (negative, or long) weights: a constant
    /// weight curve, so the centred route; zero weights are an error.
    #[test]
    fn weighted_translations_take_the_centred_route() {
        let q = [rat(1, 1), rat(2, 3), rat(0, 1), rat(-1, 5)];
        let pts = vec![
            [rat(1, 3), rat(-2, 7), rat(5, 1)],
            [rat(4, 1), rat(1, 1), rat(-3, 2)],
            [rat(0, 1), rat(9, 4), rat(2, 1)],
        ];
        let radii = [rat(1, 1), rat(2, 1), rat(3, 2)];
        let other = body_of(
            [rat(1, 2), rat(1, 1), rat(5, 3)],
            [rat(0, 1), rat(1, 1), rat(1, 1), rat(0, 1)],
            vec![
                [rat(1, 1), rat(0, 1), rat(2, 1)],
                [rat(-1, 1), rat(3, 1), rat(2, 1)],
            ],
        );
        for w in [rat(-1, 1), rat(-7, 3), rat(1_000_000_007, 3)] {
            let body = Body {
                radii: radii.clone(),
                motion: Motion::Translation {
                    center: Bezier {
                        points: pts.clone(),
                        weights: Some(vec![w.clone(); 3]),
                    },
                    orientation: q.clone(),
                },
            };
            let (c, g) = general_and_centred(&body, &other);
            assert_eq!(c, g, "weight {w:?}");
            let (c, g) = general_and_centred(&other, &body);
            assert_eq!(c, g, "weight {w:?}");
            let span = [Rat::zero(), Rat::one()];
            assert!(placed_quadric(&body, &span)
                .unwrap()
                .centred::<Int>()
                .is_some());
        }
        let zero = Body {
            radii,
            motion: Motion::Translation {
                center: Bezier {
                    points: pts,
                    weights: Some(vec![Rat::zero(); 3]),
                },
                orientation: q,
            },
        };
        assert!(placed_quadric(&zero, &[Rat::zero(), Rat::one()]).is_err());
    }

    /// A centre curve beyond SmallPoly's capacity (degree 20, short numbers).
    #[test]
    fn a_centre_curve_too_long_for_i128_takes_the_int_route() {
        let pts: Vec<[Rat; 3]> = (0..21i64)
            .map(|i| [rat(i % 3, 1), rat(-(i % 5), 1), rat(i % 2, 1)])
            .collect();
        let a = body_of(
            [rat(1, 1), rat(2, 1), rat(1, 1)],
            [rat(1, 1), rat(0, 1), rat(0, 1), rat(0, 1)],
            pts,
        );
        let b = body_of(
            [rat(1, 1), rat(1, 1), rat(1, 1)],
            [rat(1, 1), rat(1, 1), rat(0, 1), rat(0, 1)],
            vec![[rat(3, 1), rat(0, 1), rat(0, 1)]],
        );
        let (pa, _) = placed_pair(&a, &b);
        let sa = pa.centred::<SmallInt>().unwrap();
        assert!(sa.lifted().is_none(), "degree 20 does not fit SmallPoly");
        let (c, g) = general_and_centred(&a, &b);
        assert_eq!(c, g);
        let (c, g) = general_and_centred(&b, &a);
        assert_eq!(c, g);
    }
}
