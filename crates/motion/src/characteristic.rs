//! The characteristic polynomial `f(λ; u) = det(λA(u) + B(u))` with
//! coefficients in `ℤ[u]`, normalised to the lowest degrees the scene allows.
//!
//! # Normalisation
//!
//! Writing `f = Σ c_k(u)·λ^k`, two changes keep every sign Theorem 3.10
//! reads and every root sign and multiplicity in λ:
//! * dividing all `c_k` by a common factor nonzero on the span
//!   (the closed forms are homogeneous of even degree);
//! * rescaling `λ ↦ λ·s(u)` with `s > 0` on the span, i.e.
//!   `c_k ↦ c_k·s^k` (what scaling `A` by `s` does).
//!
//! For each factor `π` of `c_4 = det A` and `c_0 = det B` (these never vanish
//! on the span, so `π` has a constant sign there and is made positive), with
//! `v_k` its multiplicity in `c_k`, we replace `c_k` by `c_k·π^(α + β·k)`
//! for the integers `α, β` that keep every `c_k` a polynomial
//! (`α + β·k >= −v_k`) and minimise `α + 2β`: the closed forms are
//! homogeneous of degrees `w` = 2, 2, 4, 4, 6 and isobaric of weights `i`
//! = 6, 4, 10, 9, 12 (`sr22, sr20, sr11, sr10, sr0`;
//! `ccd_subres::isobaric_weight`), so every `sr_ij` is multiplied by
//! `π^(α·w + β·i) > 0`, `sr0` by `π^(6·(α + 2β))`, and `deg sr0` drops by
//! `6·(α + 2β)·deg π`. This is what the paper's normalisation (make `f`
//! monic, reduce, clear denominators) achieves, found without rational
//! functions, and it also finds the λ-rescaling hidden in the homogeneous
//! integer form of a rotation (`R = M(q)/|q|²`).
//!
//! Constant factors get the same treatment: for `f` past `i128`, each small
//! prime `p` dividing some `c_k` (its multiplicity `v_k` in the content of
//! `c_k`) plays the part of `π` (`balance_primes`). Tiny radii and long
//! decimals leave a constant rescaling of λ that the content alone cannot
//! take out (`ratio-needle-k0064-*`, radii `1` and `10⁻⁶⁴`: `sr0` of 9,387
//! bits, 6,336 of them content, becomes 3,068 bits), and usually brings
//! the sizes of the `c_k` together (never lengthening the longest one,
//! which the exact path's size bound reads).

use crate::centred::{centred_characteristic, Centred, Offset};
use crate::curve::{content, Integer};
use crate::error::MotionError;
use crate::kinds::{Body, Motion, Quat, Vec3};
use crate::matrices::{
    placed_quadric, shortened_tables, small_first, static_quadric, through_quadrics, PlacedQuadric,
};
use ccd_arith::{Int, Rat, RingOps, SmallInt};
use ccd_poly::{Residues, SmallPoly, ZPoly};
use ccd_quadric::{
    characteristic, is_affine_placement, placed_characteristic, rigid_characteristic,
    rigid_characteristic_degree, rigid_values, Mat4,
};

/// `f(λ; u)` as `[c_4, c_3, c_2, c_1, c_0]` (high → low in λ), each in `ℤ[u]`,
/// `u = (t − t0)/(t1 − t0) ∈ [0, 1]`.
#[derive(Clone, Debug, PartialEq)]
pub struct CharPoly {
    /// Coefficients, high → low in λ.
    pub coeffs: [ZPoly; 5],
}

impl CharPoly {
    /// `det(λA + B)` of two moving quadrics, normalised (module docs); the
    /// factors of `det A` and `det B` are found by squarefree factorisation.
    pub fn new(a: &Mat4<ZPoly>, b: &Mat4<ZPoly>) -> CharPoly {
        CharPoly {
            coeffs: normalise(characteristic(a, b)),
        }
    }

    /// `det(λA + B)` of two placed bodies, normalised with the determinant
    /// factors the motions already know (no factorisation of `det A`,
    /// `det B` needed). Bodies that never turn: in the frame of A's centre
    /// (`centred.rs`). Two rigid bodies: from the minors of their
    /// relative placement ([`rigid_characteristic`], at the pair's own
    /// degree; scaled as the quadrics' route below scales `f`, so the
    /// same normalised `f`). Otherwise through the quadrics `NᵀDN` (for
    /// numbers past 80 bits, by Cauchy–Binet on the rows of the inverse
    /// placements instead, with the diagonal products of
    /// `diag(1/r², −1)`) or, when the inverse placements have higher
    /// degree than the placements (affine motions: `N = adj M`), from the
    /// Plücker coordinates of the placements ([`placed_characteristic`]:
    /// degree 16 instead of 48 for degree-2 rational affine motions,
    /// before normalisation).
    pub fn from_placed(a: &PlacedQuadric, b: &PlacedQuadric) -> CharPoly {
        let candidates = known_factors(a, b);
        // Bodies that never turn: in the frame of A's centre (crate::centred),
        // in i128 first, over Int if a number does not fit.
        let centred = (!(a.turns() || b.turns()))
            .then(|| centred_quartic(a, b))
            .flatten();
        if let Some(f) = centred {
            return CharPoly {
                coeffs: match f {
                    Quartic::Small(f) => normalise_small(&f, candidates),
                    Quartic::Exact(f) => normalise_with(f, candidates),
                },
            };
        }
        // Both routes first in i128 (short decimal inputs fit), exactly
        // in ZPoly if a number does not.
        let long = a.bits().max(b.bits()) > SMALL_BODY_BITS;
        // Two rigid bodies: from their relative placement, scaled as the
        // quadrics' route below scales f (for long bodies, once the
        // quadrics do not fit i128, as its Cauchy–Binet on the inverse
        // placements does).
        let relative = |scaling| rigid_quartic(a, b, scaling);
        let f = if let Some(f) = (!long).then(|| relative(Scaling::Quadrics)).flatten() {
            f
        } else if through_quadrics(a, b) {
            // The quadrics themselves in i128 when they fit (they usually
            // do when f does).
            let (sa, sb) = (a.quadric_small(), b.quadric_small());
            let small = match (&sa, &sb) {
                (Some(qa), Some(qb)) if worth_small(sizes(&[qa, qb]), 4) => {
                    exact(characteristic(qa, qb))
                }
                _ => None,
            };
            small.map(Quartic::Small).unwrap_or_else(|| {
                // Long bodies: Cauchy–Binet on the inverse placements, whose
                // columns lose their contents first.
                if long {
                    return relative(Scaling::InversePlacements)
                        .unwrap_or_else(|| Quartic::Exact(inverse_characteristic(a, b)));
                }
                let (qa, qb) = (a.quadric(), b.quadric());
                worth_small(sizes(&[&qa, &qb]), 4)
                    .then(|| exact(characteristic(&lowered(&qa), &lowered(&qb))))
                    .flatten()
                    .map_or_else(|| Quartic::Exact(characteristic(&qa, &qb)), Quartic::Small)
            })
        } else {
            let (pa, pb) = (a.placement(), b.placement());
            // The tables shortened by the radii's shared denominator
            // (`shortened_tables`).
            let affine = is_affine_placement(&pa) && is_affine_placement(&pb);
            worth_small(sizes(&[&pa, &pb]), 8)
                .then(|| {
                    let [x, y] = [&pa, &pb].map(lowered);
                    let (tables, both) = shortened_tables::<SmallInt>(a, b, affine);
                    let [dx, dy] = tables.each_ref().map(constants);
                    let both = both.map(|c| SmallPoly::constant(&c));
                    exact(placed_characteristic(&x, &dx, &y, &dy, both.as_ref()))
                })
                .flatten()
                .map_or_else(
                    || {
                        let (pa, pb) = without_row_contents(pa, pb);
                        let (tables, both) = shortened_tables::<Int>(a, b, affine);
                        let [da, db] = tables.map(|t| t.map(ZPoly::constant));
                        let both = both.map(ZPoly::constant);
                        Quartic::Exact(placed_characteristic(&pa, &da, &pb, &db, both.as_ref()))
                    },
                    Quartic::Small,
                )
        };
        CharPoly {
            coeffs: match f {
                Quartic::Small(f) => normalise_small(&f, candidates),
                Quartic::Exact(f) => normalise_with(f, candidates),
            },
        }
    }

    /// `f(λ)` of two static bodies (both [`Motion::Static`]; `None`
    /// otherwise): the very polynomial [`CharPoly::from_placed`] gives
    /// them, without placements or polynomials in `u`. Both quadrics are
    /// constant integer matrices (`static_quadric`: the ones
    /// [`PlacedQuadric::quadric`] forms), `det(λA + B)` is their
    /// [`characteristic`], and the normalisation (module docs) of constant
    /// coefficients is the removal of their content and, past `i128`, the
    /// small primes' rescaling (`balance_primes`) (`det A`, `det B` have
    /// no factor in `u`). In `i128` ([`SmallInt`]) when every number on the
    /// way fits, else over [`Int`] (the same integers).
    pub fn of_static(a: &Body, b: &Body) -> Option<CharPoly> {
        fn static_body(body: &Body) -> Option<StaticBody<'_>> {
            match &body.motion {
                Motion::Static {
                    center,
                    orientation,
                } => Some((&body.radii, center, orientation)),
                _ => None,
            }
        }
        let (a, b) = (static_body(a)?, static_body(b)?);
        let f = small_first(
            || static_characteristic::<SmallInt>(&a, &b),
            || static_characteristic::<Int>(&a, &b),
        );
        Some(CharPoly {
            coeffs: balance_primes(f.map(ZPoly::constant)),
        })
    }

    /// A repeated factor in `λ` of `f(λ; t)` at every `t` (`h` with `h²`
    /// dividing `f`), with `f = Σ_j t^j·F_j(λ)`. Modulo a word prime every
    /// part's image keeps `h̄²`. First, for one gcd: when the repeated part
    /// `gcd(F̄, F̄′)` of the last nonzero image `F̄` is linear with a short
    /// root `n/d` (numerator and denominator up to `2^26`:
    /// [`Residues::linear_candidate`]), `h = d·λ − n` when every part has
    /// the root `n/d` twice, `F_j(n/d) = F_j′(n/d) = 0` (exact homogeneous
    /// evaluations: for a linear `h` that is `h² | F_j`). Otherwise the
    /// parts' gcd modulo the prime must keep a repeated factor; when that
    /// factor's image is linear with a short root, `h` is that root's
    /// `d·λ − n`, proven alike; otherwise `h` is the product of the distinct
    /// repeated factors of one `F_b` (the squarefree part of
    /// `gcd(F_b, F_b′)`; `b` the part with the fewest of them modulo a word
    /// prime, where the images' common gcd must have a repeated factor
    /// first), and the answer is whether `h² | F_j` for every `j` (exact
    /// division; `h` is primitive, so this is divisibility over `ℚ`);
    /// `Some(h)` when so. Then `sr0` vanishes identically (Theorem 5.4's
    /// branch): it is a constant times the discriminant of the quartic
    /// `f(·; t)`, which is zero wherever `h²` divides it — also where the
    /// leading coefficient `c₄(t)` vanishes, since `Disc₄(0, a, b, c, d) =
    /// a²·Disc₃(a, b, c, d)` and the cubic keeps `h²` (or `a = 0`). That is the usual reason for it: spheres (a double root
    /// `λ = −1`), homothetic pairs, two translates of one body. A
    /// sufficient test only (`None` does not mean `sr0 ≢ 0`), costing a
    /// gcd of quartics modulo a prime and a few evaluations (the usual
    /// case) or divisions instead of the degree-`6n` closed form.
    ///
    /// ```
    /// use ccd_motion::CharPoly;
    /// use ccd_poly::ZPoly;
    /// // (λ + 1)²·(λ² + t·λ + 2) = λ⁴ + (t + 2)λ³ + (2t + 3)λ² + (t + 4)λ + 2
    /// let c = |v: &[i64]| ZPoly::from_i64s(v);
    /// let f = CharPoly { coeffs: [c(&[1]), c(&[2, 1]), c(&[3, 2]), c(&[4, 1]), c(&[2])] };
    /// assert_eq!(f.fixed_repeated_factor(), Some(c(&[1, 1])));
    /// // λ⁴ + 2λ² + (1 − t)·λ + 1: F_0 = (λ² + 1)², but not for every t.
    /// let g = CharPoly { coeffs: [c(&[1]), c(&[]), c(&[2]), c(&[1, -1]), c(&[1])] };
    /// assert_eq!(g.fixed_repeated_factor(), None);
    /// ```
    pub fn fixed_repeated_factor(&self) -> Option<ZPoly> {
        // F_j, constant term first: coeffs[k] is the coefficient of λ^(4−k).
        let part = |j: usize| {
            ZPoly::new(
                self.coeffs
                    .iter()
                    .rev()
                    .map(|k| k.coeffs().get(j).cloned().unwrap_or_else(Int::zero))
                    .collect(),
            )
        };
        let parts: Vec<ZPoly> = (0..=self.degree()).map(part).collect();
        // The repeated part gcd(r, r′) of an image.
        let repeated = |r: &Residues| r.gcd(&r.derivative());
        // A short h read off a linear image (rational reconstruction: the
        // usual double root, λ = −1 or a ratio of squared radii), proven
        // by exact evaluations: for h = d·λ − n, h² | F_j ⇔ F_j(n/d) =
        // F_j′(n/d) = 0.
        let short_root = |image: &Residues| {
            let h = image.linear_candidate()?;
            let root = Rat::new(-h.coeff(0), h.coeff(1)).expect("a linear h");
            let twice = |p: &ZPoly| {
                p.is_zero() || {
                    let (value, slope) = p.eval_homogeneous_with_derivative(&root);
                    value.is_zero() && slope.is_zero()
                }
            };
            parts.iter().all(twice).then_some(h)
        };
        // The usual case first, for one gcd of quartics modulo the word
        // prime instead of one per part: the last nonzero image (of the
        // top part, usually; F_0's has a repeated factor of its own where
        // the bodies touch at t = 0). Its repeated part keeps h̄ (degree
        // 0: no h, a filter's "no" as below).
        let last = parts.iter().rev().map(Residues::of).find(|r| !r.is_zero());
        let last = repeated(&last?);
        if last.degree().is_none_or(|d| d == 0) {
            return None;
        }
        if let Some(h) = short_root(&last) {
            return Some(h);
        }
        // Modulo the word prime (a filter whose "no" may be wrong, when the
        // prime divides lc(h)): h̄² divides every image, so their gcd keeps
        // degree 2 or more, and has a repeated factor.
        let mut images = Vec::with_capacity(parts.len());
        let mut common = Residues::of(&ZPoly::zero());
        for p in &parts {
            images.push(Residues::of(p));
            common = common.gcd(&images[images.len() - 1]);
            // (While every image so far is zero, the gcd is zero: no
            // constraint yet.)
            if common.degree().is_some_and(|d| d < 2) {
                return None;
            }
        }
        let image = repeated(&common);
        if image.degree().is_none_or(|d| d == 0) {
            return None;
        }
        // A short h read off the common image (unless it is the last one's,
        // already tried); else h from an exact gcd of the part with the
        // fewest repeated factors of its own (F_0 has one more where the
        // bodies touch at t = 0), proven when h² divides every other part.
        if image != last {
            if let Some(h) = short_root(&image) {
                return Some(h);
            }
        }
        let base = (0..parts.len())
            .min_by_key(|&j| repeated(&images[j]).degree().unwrap_or(usize::MAX))
            .unwrap_or(0);
        let g = parts[base].gcd(&parts[base].derivative());
        if g.degree().is_none_or(|d| d == 0) {
            return None;
        }
        let h = g.squarefree_part();
        let h2 = &h * &h;
        let divides = |(j, p): (usize, &ZPoly)| j == base || p.div_exact(&h2).is_some();
        parts.iter().enumerate().all(divides).then_some(h)
    }

    /// `deg_t f`: the largest degree of a coefficient.
    pub fn degree(&self) -> usize {
        self.coeffs
            .iter()
            .filter_map(ZPoly::degree)
            .max()
            .unwrap_or(0)
    }

    /// The coefficients at a rational `u`, exactly.
    pub fn at(&self, u: &Rat) -> [Rat; 5] {
        self.coeffs.each_ref().map(|c| c.eval_rat(u))
    }

    /// The coefficients at `u = p/q` times the common positive factor
    /// `q^deg`: integers with the signs and ratios of [`CharPoly::at`], which
    /// is all Theorem 3.10 reads.
    pub fn at_scaled(&self, u: &Rat) -> [Int; 5] {
        let d = self.degree();
        // q^deg(c)·c(p/q), brought to the common q^d.
        self.coeffs.each_ref().map(|c| {
            let top = c.degree().unwrap_or(0);
            c.eval_homogeneous(u) * u.denom().pow((d - top) as u32)
        })
    }
}

/// The squarefree factors of the polynomials whose powers make up
/// `det A` and `det B` (the motions know them): the normalisation's
/// candidate factors.
fn known_factors(a: &PlacedQuadric, b: &PlacedQuadric) -> Vec<ZPoly> {
    a.det_factors
        .iter()
        .chain(&b.det_factors)
        .flat_map(|p| squarefree_factors(p).into_iter().map(|(f, _)| f))
        .collect()
}

/// A static body's radii, centre and orientation.
type StaticBody<'a> = (&'a [Rat; 3], &'a Vec3, &'a Quat);

/// `det(λA + B)` of two static bodies over `I`, divided by the gcd of its
/// coefficients ([`CharPoly::of_static`]).
fn static_characteristic<I: Integer>(a: &StaticBody, b: &StaticBody) -> [I; 5] {
    let quadric = |(radii, center, q): &StaticBody| static_quadric::<I>(radii, center, q);
    let f = characteristic(&quadric(a), &quadric(b));
    let g = content(&f);
    if g.is_zero() || g.is_one() {
        return f;
    }
    f.map(|c| c.div_exact(&g))
}

/// A matrix in [`SmallPoly`] (entries that do not fit come in overflowed,
/// and so do the results they reach).
fn lowered(m: &Mat4<ZPoly>) -> Mat4<SmallPoly> {
    // In place: the entries are 288-byte values.
    let mut out: Mat4<SmallPoly> =
        std::array::from_fn(|_| std::array::from_fn(|_| SmallPoly::zero()));
    for (slots, row) in out.iter_mut().zip(m) {
        for (slot, p) in slots.iter_mut().zip(row) {
            slot.set_lowered(p);
        }
    }
    out
}

/// The table's entries as constant [`SmallPoly`]s, formed in place.
fn constants<const N: usize>(t: &[SmallInt; N]) -> [SmallPoly; N] {
    let mut out: [SmallPoly; N] = std::array::from_fn(|_| SmallPoly::zero());
    for (slot, d) in out.iter_mut().zip(t) {
        slot.set_constant(d);
    }
    out
}

/// `(degree, bits)` of every entry of these matrices.
fn sizes<'a, P: IntegerPoly>(
    mats: &'a [&Mat4<P>],
) -> impl Iterator<Item = (usize, u64)> + Clone + 'a {
    mats.iter().flat_map(|m| m.iter().flatten()).map(P::size)
}

/// Whether `f` from matrices with entries of these `(degree, bits)`, a
/// sum of products of `factors` entries each, is likely to fit
/// [`SmallPoly`] (degree and size estimates only: an overflow is detected
/// anyway, this just skips a doomed attempt).
fn worth_small(entries: impl Iterator<Item = (usize, u64)> + Clone, factors: usize) -> bool {
    let degree = entries.clone().map(|(d, _)| d).max().unwrap_or(0);
    let bits = entries.map(|(_, b)| b).max().unwrap_or(0) as usize;
    degree * factors <= SmallPoly::MAX_DEGREE && (bits + degree) * factors + 24 <= 126
}

/// The placements with each row of `[M_A | M_B]` divided by the integer
/// content of its eight entries. Every Plücker coordinate is a 4×4 minor
/// of that matrix, so dividing row `i` by `r_i` divides every `P_T`, hence
/// every coefficient of [`placed_characteristic`], by `r_i²`: the same `f`
/// up to a positive constant, which the normalisation's content removal
/// takes out (so the same normalised `f`), on shorter numbers. The
/// homogeneous row `(0, 0, 0, w_A | 0, 0, 0, w_B)` of two polynomial
/// motions holds their common denominator: 336 of the 4,001 content bits
/// of `bench-perturbed-affine-deg2-d0100`'s `f`. Only on the [`Int`]
/// route: the `i128` one gains nothing from shorter numbers. The quadric
/// route applies it to the columns of the inverse placements.
fn without_row_contents(mut pa: Mat4<ZPoly>, mut pb: Mat4<ZPoly>) -> (Mat4<ZPoly>, Mat4<ZPoly>) {
    for (ra, rb) in pa.iter_mut().zip(pb.iter_mut()) {
        let r = ZPoly::common_content(&[&ra[..], &rb[..]].concat());
        if r.is_zero() || r.is_one() {
            continue;
        }
        for e in ra.iter_mut().chain(rb.iter_mut()) {
            *e = e.div_exact_int(&r);
        }
    }
    (pa, pb)
}

/// `det(λA + B)` for `A = N_AᵀD_AN_A`, `B = N_BᵀD_BN_B` by Cauchy–Binet on
/// the rows of `G = [N_A; N_B]` (8×4): `Σ_S λ^|S∩A|·D_A(S∩A)·D_B(S∩B)·det(G_S)²`,
/// which is [`placed_characteristic`] of the columns of `Gᵀ = [N_Aᵀ | N_Bᵀ]`
/// with the tables indexed by complements and λ reversed. The columns of
/// `N` lose their common contents first ([`without_row_contents`] on `Nᵀ`)
/// and the diagonals are the reduced products of
/// [`PlacedQuadric::diagonal_products`]: the same `f` up to a rescaling of
/// λ and a positive constant.
fn inverse_characteristic(a: &PlacedQuadric, b: &PlacedQuadric) -> [ZPoly; 5] {
    let (ta, tb) = without_row_contents(transposed(a.inverse()), transposed(b.inverse()));
    let (tables, _) = shortened_tables::<Int>(a, b, false);
    let [pa, pb] = tables.map(|d| std::array::from_fn(|s| ZPoly::constant(d[!s & 0xf].clone())));
    let mut f = placed_characteristic(&ta, &pa, &tb, &pb, None);
    f.reverse();
    f
}

/// `mᵀ`.
fn transposed(m: Mat4<ZPoly>) -> Mat4<ZPoly> {
    let mut t = m;
    for i in 0..4 {
        for j in i + 1..4 {
            let (upper, lower) = t.split_at_mut(j);
            std::mem::swap(&mut upper[i][j], &mut lower[0][i]);
        }
    }
    t
}

/// `f` unless a [`SmallPoly`] step overflowed.
fn exact(f: [SmallPoly; 5]) -> Option<[SmallPoly; 5]> {
    f.iter().all(SmallPoly::is_exact).then_some(f)
}

/// Above this many bits in a placement's numbers ([`PlacedQuadric::bits`]),
/// the bodies that never turn are set up over [`Int`] without an `i128`
/// attempt.
const SMALL_BODY_BITS: u64 = 80;

/// `f` of two bodies that never turn ([`centred_characteristic`]), over
/// [`SmallInt`] when no number overflows there, else over [`Int`] (the
/// same polynomials); `None` if a body turns or has a rational centre
/// curve.
fn centred_quartic(a: &PlacedQuadric, b: &PlacedQuadric) -> Option<Quartic> {
    let over_int = || {
        let (ia, ib) = (a.centred::<Int>()?, b.centred::<Int>()?);
        let f = centred_characteristic(&ia.block, &ib.block, &Offset::new(&ia, &ib));
        Some(Quartic::Exact(f))
    };
    // Placements of longer numbers never give bodies that fit i128 (on the
    // shipped scenes: every one up to 65 bits fits, none from 87 bits on),
    // and a doomed attempt costs a fifth of the set-up.
    if a.bits().max(b.bits()) > SMALL_BODY_BITS {
        return over_int();
    }
    // The bodies themselves are short numbers even when f is not.
    let (sa, sb) = (a.centred::<SmallInt>()?, b.centred::<SmallInt>()?);
    // The short numbers of the set-up fit i128 even when f does not.
    let offset = Offset::new(&sa, &sb);
    if Centred::worth_small(&sa, &sb) {
        let f = centred_characteristic(&sa.block, &sb.block, &offset);
        if f.iter().all(SmallPoly::is_exact) {
            return Some(Quartic::Small(f));
        }
    }
    // Over Int: only the blocks and the short numbers are needed there;
    // the short numbers lifted, or formed over Int from the lifted bodies
    // (the three-decimal straight-line scenes), else everything over Int.
    let int_offset = || {
        offset
            .lifted()
            .or_else(|| Some(Offset::new(&sa.lifted()?, &sb.lifted()?)))
    };
    match (sa.block.lifted(), sb.block.lifted(), int_offset()) {
        (Some(ba), Some(bb), Some(offset)) => {
            Some(Quartic::Exact(centred_characteristic(&ba, &bb, &offset)))
        }
        _ => over_int(),
    }
}

/// Which of [`CharPoly::from_placed`]'s routes [`rigid_quartic`] scales
/// `f` like: both give the same normalised `f` as that route, since the
/// normalisation takes out a positive constant and powers of `det A`,
/// `det B`'s factors but not a constant rescaling of λ.
#[derive(Clone, Copy)]
enum Scaling {
    /// The quadrics `NᵀDN` of the primitive inverse placements `N` and the
    /// integer diagonals [`PlacedQuadric::diagonal`].
    Quadrics,
    /// [`inverse_characteristic`]: the primitive inverse placements with
    /// the rational diagonals `diag(1/r², −1)` (its tables and column
    /// contents only scale `f` by a positive constant).
    InversePlacements,
}

/// `f` of two rigid bodies from their relative placement
/// ([`rigid_characteristic`]), with the diagonals scaled so that it is the
/// quartic of the `scaling` route up to a positive constant and powers of
/// `n·w` (what the normalisation removes): with `g` the content that
/// makes a body's inverse placement primitive, that route's quadric is
/// `(n·w/g)²·N_ratᵀ·D·N_rat`, whose integer content `κ = cont(n·w)` is a
/// constant rescaling of λ that the normalisation keeps, so `D_A` is taken
/// times `(κ_A·g_B)²` and `D_B` times `(κ_B·g_A)²`. In `i128` when every number fits, else over [`ZPoly`];
/// `None` for an affine body. `rigid-deg2`: coefficients of degree 4
/// instead of 16, 12, 8, 4, 0.
fn rigid_quartic(a: &PlacedQuadric, b: &PlacedQuadric, scaling: Scaling) -> Option<Quartic> {
    if !(a.is_rigid() && b.is_rigid()) {
        return None;
    }
    let [da, db]: [[Int; 4]; 2] = match scaling {
        Scaling::Quadrics => [a, b].map(|body| body.diagonal.each_ref().map(|d| d.coeff(0))),
        Scaling::InversePlacements => {
            let (ra, rb) = (a.rational_diagonal(), b.rational_diagonal());
            let beta: Int = ra
                .iter()
                .chain(&rb)
                .fold(Int::one(), |l, x| l.lcm(x.denom()));
            [ra, rb].map(|r| r.map(|x| beta.div_exact(x.denom()) * x.numer()))
        }
    };
    // κ·g′ with κ the content of n·w (its primitive part is what the
    // normalisation takes out) and g′ the other body's inverse content.
    let (ka, kb) = (a.rotation_content(), b.rotation_content());
    let (ga, gb) = (a.inverse_content(), b.inverse_content());
    let scale = |d: [Int; 4], k: Int, g: &Int| {
        let c = k * g;
        if c.is_one() {
            d
        } else {
            let c2 = &c * &c;
            d.map(|x| x * &c2)
        }
    };
    let (da, db) = (scale(da, ka, &gb), scale(db, kb, &ga));
    // In i128 by values, else as polynomials when the numbers are likely
    // to fit (every term is a product of eight frame numbers, summed over
    // the products of their coefficients, and four diagonal entries; an
    // overflow is detected anyway, this skips doomed attempts).
    let small = by_values(a, b, &da, &db).or_else(|| {
        let frame_bits = a.frame_bits().max(b.frame_bits());
        let degree = a.degree_bounds().0.max(b.degree_bounds().0) as u64;
        let diagonal_bits = da.iter().chain(&db).map(Int::bits).max().unwrap_or(0);
        let likely =
            8 * frame_bits + 4 * diagonal_bits + 8 * (64 - degree.leading_zeros() as u64) + 14
                <= 126;
        // The frames in i128 (numbers that do not fit come in overflowed).
        let [sa, sb] = [a, b].map(|body| body.rigid_frame(SmallPoly::lowered));
        let [ta, tb] = [&da, &db].map(|d| d.each_ref().map(SmallInt::of));
        likely
            .then(|| exact(rigid_characteristic(&sa?, &sb?, &ta, &tb)))
            .flatten()
    });
    Some(small.map_or_else(
        || {
            let [fa, fb] = [a, b].map(|body| body.rigid_frame(ZPoly::clone));
            let (fa, fb) = (fa.expect("a rigid frame"), fb.expect("a rigid frame"));
            Quartic::Exact(rigid_characteristic(&fa, &fb, &da, &db))
        },
        Quartic::Small,
    ))
}

/// [`rigid_characteristic`] in `i128` by evaluation and interpolation:
/// its value at `D + 1` integers `u` around 0 (`D` the degree bound of
/// [`rigid_characteristic_degree`]) from the frames' values there, a few
/// hundred word products each, then each coefficient interpolated
/// ([`SmallPoly::interpolate`]). The same polynomials as over
/// [`SmallPoly`] (an integer polynomial of degree at most `D` is its
/// interpolant) at a fifth of the cost (`rigid-deg2`: `D = 4`); `None`
/// when a number does not fit or `D` exceeds the capacity.
fn by_values(
    a: &PlacedQuadric,
    b: &PlacedQuadric,
    da: &[Int; 4],
    db: &[Int; 4],
) -> Option<[SmallPoly; 5]> {
    let degree = |p: &ZPoly| p.degree().unwrap_or(0);
    let top = rigid_characteristic_degree(&a.rigid_frame(degree)?, &b.rigid_frame(degree)?);
    if top > SmallPoly::MAX_DEGREE {
        return None;
    }
    let word = |d: &[Int; 4]| -> Option<[i128; 4]> {
        let [w, x, y, z] = d.each_ref().map(Int::to_i128);
        Some([w?, x?, y?, z?])
    };
    let (da, db) = (word(da)?, word(db)?);
    let first = -(top as i64 / 2);
    let (fa, fb) = (
        a.rigid_frame_values(first, top + 1)?,
        b.rigid_frame_values(first, top + 1)?,
    );
    let mut values = [[SmallInt::zero(); SmallPoly::MAX_DEGREE + 1]; 5];
    for (i, f) in rigid_values(&fa, &fb, &da, &db)?.into_iter().enumerate() {
        for (column, v) in values.iter_mut().zip(f) {
            column[i] = SmallInt::from_i128(v);
        }
    }
    exact(values.map(|v| SmallPoly::interpolate(first, &v[..=top])))
}

/// `f = det(λA + B)` from one of the two routes of
/// [`CharPoly::from_placed`]: in `i128` (exact) or over [`ZPoly`].
#[allow(clippy::large_enum_variant)]
enum Quartic {
    Small([SmallPoly; 5]),
    Exact([ZPoly; 5]),
}

/// `f(λ; u)` of two moving bodies, normalised (module docs) with the
/// determinant factors the motions know.
pub fn char_poly(a: &Body, b: &Body, span: &[Rat; 2]) -> Result<CharPoly, MotionError> {
    Ok(CharPoly::from_placed(
        &placed_quadric(a, span)?,
        &placed_quadric(b, span)?,
    ))
}

/// Squarefree factorisation (Yun): `p = Π fᵢ^i` up to a constant, `fᵢ`
/// squarefree and pairwise coprime; returns the nonconstant `(fᵢ, i)`.
pub fn squarefree_factors(p: &ZPoly) -> Vec<(ZPoly, usize)> {
    let mut out = Vec::new();
    if p.degree().unwrap_or(0) == 0 {
        return out;
    }
    // The usual case first: a squarefree `p` (one gcd modulo a word prime
    // proves it) is its own factorisation.
    let s = p.squarefree_part();
    if s.degree() == p.degree() {
        out.push((s, 1));
        return out;
    }
    let p = p.primitive_part();
    let mut c = p.gcd(&p.derivative());
    let mut w = p.div_exact(&c).expect("gcd divides");
    let mut i = 1;
    while w.degree().unwrap_or(0) > 0 {
        let y = w.gcd(&c);
        let z = w.div_exact(&y).expect("gcd divides");
        if z.degree().unwrap_or(0) > 0 {
            out.push((z, i));
        }
        c = c.div_exact(&y).expect("gcd divides");
        w = y;
        i += 1;
    }
    out
}

/// Splits a list of polynomials into pairwise coprime nonconstant factors
/// whose products generate the same multiplicative structure.
fn coprime_basis(items: Vec<ZPoly>) -> Vec<ZPoly> {
    refine_coprime(
        items,
        |p| p.degree().unwrap_or(0) > 0,
        ZPoly::gcd,
        |p, g| p.div_exact(g).expect("gcd divides"),
        usize::MAX,
    )
    .expect("no budget")
}

/// Factor refinement: `items` split into pairwise coprime `proper` elements
/// (not constants, for polynomials; not units, for integers) whose products
/// generate the same multiplicative structure: two elements with a proper
/// gcd `g` are replaced by `g` and their cofactors until no two have one.
/// `None` after `budget` gcds (chains such as `2^N·3`, `2^(N−1)·3` take
/// `N` splits).
fn refine_coprime<T>(
    mut items: Vec<T>,
    proper: impl Fn(&T) -> bool,
    gcd: impl Fn(&T, &T) -> T,
    quotient: impl Fn(&T, &T) -> T,
    mut budget: usize,
) -> Option<Vec<T>> {
    items.retain(&proper);
    let mut i = 0;
    while i < items.len() {
        let mut j = i + 1;
        let mut split = false;
        while j < items.len() {
            budget = budget.checked_sub(1)?;
            let g = gcd(&items[i], &items[j]);
            if proper(&g) {
                let a = quotient(&items[i], &g);
                let b = quotient(&items[j], &g);
                items.swap_remove(j);
                items.swap_remove(i);
                items.extend([g, a, b].into_iter().filter(&proper));
                split = true;
                break;
            }
            j += 1;
        }
        if split {
            i = 0;
        } else {
            i += 1;
        }
    }
    Some(items)
}

/// The normalisation's two integer polynomial types: exact [`ZPoly`], and
/// [`SmallPoly`] whose steps may overflow.
trait IntegerPoly: RingOps {
    /// `Some(Some(q))` if `self = q·d`, `Some(None)` if `d` does not
    /// divide `self`, `None` if this type cannot tell (an overflow).
    fn quotient(&self, d: &Self) -> Option<Option<Self>>;
    /// `(degree, bits of the longest coefficient)`.
    fn size(&self) -> (usize, u64);
    /// `(v, p/π^v)` with `v` the multiplicity of `π` in `self ≠ 0`
    /// ([`multiplicity`]); `None` on an overflow.
    fn split(&self, pi: &Self) -> Option<(usize, Self)> {
        multiplicity(self, pi)
    }
    /// `self·π^e`, `None` on an overflow.
    fn times_power(&self, pi: &Self, e: u32) -> Option<Self>;
    /// The polynomials divided by the gcd of all their coefficients
    /// (a positive integer; unchanged when it is 0 or 1), `None` on an
    /// overflow.
    fn without_content(c: [Self; 5]) -> Option<[Self; 5]>;
}

impl IntegerPoly for ZPoly {
    fn quotient(&self, d: &Self) -> Option<Option<Self>> {
        Some(self.div_exact(d))
    }
    fn size(&self) -> (usize, u64) {
        (self.degree().unwrap_or(0), self.max_bits())
    }
    /// In `i128` when `self` and `π` fit ([`SmallPoly`]), else exactly.
    fn split(&self, pi: &Self) -> Option<(usize, Self)> {
        SmallPoly::from_zpoly(pi)
            .zip(SmallPoly::from_zpoly(self))
            .and_then(|(pi, p)| {
                let (v, q) = multiplicity(&p, &pi)?;
                Some((v, q.to_zpoly()?))
            })
            .or_else(|| multiplicity(self, pi))
    }
    /// In `i128` when the product fits ([`SmallPoly`]), else exactly.
    fn times_power(&self, pi: &Self, e: u32) -> Option<Self> {
        SmallPoly::from_zpoly(self)
            .zip(SmallPoly::from_zpoly(pi))
            .and_then(|(q, pi)| times_power(&q, &pi, e).to_zpoly())
            .or_else(|| Some(times_power(self, pi, e)))
    }
    fn without_content(c: [Self; 5]) -> Option<[Self; 5]> {
        match ZPoly::divide_common_content(&c) {
            Some((_, parts)) => parts.try_into().ok(),
            None => Some(c),
        }
    }
}

impl IntegerPoly for SmallPoly {
    fn quotient(&self, d: &Self) -> Option<Option<Self>> {
        match self.div_exact(d) {
            None => Some(None),
            Some(q) => q.is_exact().then_some(Some(q)),
        }
    }
    fn size(&self) -> (usize, u64) {
        (self.degree().unwrap_or(0), self.max_bits())
    }
    fn times_power(&self, pi: &Self, e: u32) -> Option<Self> {
        let p = times_power(self, pi, e);
        p.is_exact().then_some(p)
    }
    fn without_content(c: [Self; 5]) -> Option<[Self; 5]> {
        let g = c.iter().try_fold(0, |g, p| p.gcd_with(g))?;
        if g <= 1 {
            return Some(c);
        }
        // g divides a coefficient below 2^127 in size: it fits i128.
        let g = i128::try_from(g).ok()?;
        let mut c = c;
        for p in &mut c {
            p.div_exact_int_assign(g);
        }
        c.iter().all(SmallPoly::is_exact).then_some(c)
    }
}

/// How often `pi` divides `p` (`p ≠ 0`), and the cofactor `p/π^v`; `None`
/// on an overflow.
fn multiplicity<P: IntegerPoly>(p: &P, pi: &P) -> Option<(usize, P)> {
    let mut q = p.clone();
    let mut v = 0;
    while let Some(next) = q.quotient(pi)? {
        q = next;
        v += 1;
    }
    Some((v, q))
}

/// `c·π^e` (a [`SmallPoly`] result must still be checked with
/// `to_zpoly`).
fn times_power<P: RingOps>(c: &P, pi: &P, e: u32) -> P {
    (0..e).fold(c.clone(), |p, _| p.times(pi))
}

/// The exponents `α + β·k` (k = 0..4, low → high) minimising `α + 2β`
/// subject to `α + β·k >= −v_k`, ties broken by the smallest largest
/// resulting size (`sizes[k] + e_k·size_pi`: degrees, or bits for a prime),
/// then by the smallest `β`.
///
/// With `α` the least that meets the constraints, `f(β) = α + 2β =
/// max_k(−v_k + (2 − k)·β)` is convex and piecewise linear, and so is the
/// largest size, `π·f(β) + max_k(sizes[k] + π·(k − 2)·β)`. The integers
/// where `f` is least form a range whose ends are each an end of `[lo, hi]`
/// or the floor or ceiling of a crossing of two of `f`'s lines; within it
/// the sizes decide, and their least integer minimiser is an end of that
/// range or next to a crossing of two of their lines. So only those `β`
/// need trying ([`exponent_candidates`]): at most 42, where the range
/// reaches hundreds (306 and 321 on `ratio-disc-k0064-miss`, whose `v_k`
/// reach 640).
fn best_exponents(v: &[Option<usize>; 5], sizes: &[usize; 5], size_pi: usize) -> [i64; 5] {
    let (lo, hi) = exponent_range(v);
    if hi - lo < SHORT_EXPONENT_RANGE {
        least_exponents(v, sizes, size_pi, lo..=hi)
    } else {
        least_exponents(
            v,
            sizes,
            size_pi,
            exponent_candidates(v, sizes, size_pi, lo, hi),
        )
    }
}

/// While `hi − lo` is below this, [`best_exponents`] walks every `β`:
/// listing and sorting the candidates (up to 42: the ends, and a floor and
/// a ceiling for each of the 20 crossings, 10 pairs of lines in each key)
/// costs more than walking a short range (`ratio-size-j6-touch`, about 50
/// `β`: 14.0K instructions walking, 20.8K listing, so the two break even
/// near 75). 128 keeps a margin; ranges between 75 and 128 were not
/// measured apart.
const SHORT_EXPONENT_RANGE: i64 = 128;

/// The exponents of the least `β` (ascending) under [`best_exponents`]'s
/// order.
fn least_exponents(
    v: &[Option<usize>; 5],
    sizes: &[usize; 5],
    size_pi: usize,
    betas: impl IntoIterator<Item = i64>,
) -> [i64; 5] {
    let mut best: Option<((i64, i64), [i64; 5])> = None;
    for beta in betas {
        // The sizes only break ties: a larger `α + 2β` loses at once.
        let alpha = least_alpha(v, beta);
        if best
            .as_ref()
            .is_some_and(|((b, _), _)| alpha + 2 * beta > *b)
        {
            continue;
        }
        let (key, e) = exponent_key(v, sizes, size_pi, alpha, beta);
        if best.as_ref().is_none_or(|(b, _)| key < *b) {
            best = Some((key, e));
        }
    }
    best.map_or([0; 5], |(_, e)| e)
}

/// The least `α` with `α + β·k >= −v_k` for every nonzero `c_k`.
fn least_alpha(v: &[Option<usize>; 5], beta: i64) -> i64 {
    let mut alpha = None::<i64>;
    for (k, vk) in v.iter().enumerate() {
        if let Some(vk) = vk {
            let a = -(*vk as i64) - beta * k as i64;
            alpha = Some(alpha.map_or(a, |x| x.max(a)));
        }
    }
    alpha.unwrap_or(0)
}

/// The range of `β` that can tie with `β = 0` in [`best_exponents`].
fn exponent_range(v: &[Option<usize>; 5]) -> (i64, i64) {
    let vmax = v.iter().flatten().copied().max().unwrap_or(0) as i64;
    let vmin = v.iter().flatten().copied().min().unwrap_or(0) as i64;
    // α + 2β >= −v_j + (2 − j)·β for every j, and β = 0 gives −v_min: no
    // β past these bounds can tie with it.
    let (mut lo, mut hi) = (-vmax, vmax);
    for (j, vj) in v.iter().enumerate() {
        let Some(vj) = vj.map(|x| x as i64) else {
            continue;
        };
        match 2 - j as i64 {
            d if d > 0 => hi = hi.min((vj - vmin).div_euclid(d)),
            d if d < 0 => lo = lo.max(-(vj - vmin).div_euclid(-d)),
            _ => {}
        }
    }
    (lo, hi)
}

/// [`best_exponents`]'s order at `β` (with `α` its [`least_alpha`]):
/// `(α + 2β, largest size)` and the exponents `e_k = α + β·k`.
fn exponent_key(
    v: &[Option<usize>; 5],
    sizes: &[usize; 5],
    size_pi: usize,
    alpha: i64,
    beta: i64,
) -> ((i64, i64), [i64; 5]) {
    let e: [i64; 5] = std::array::from_fn(|k| alpha + beta * k as i64);
    let largest = (0..5)
        .filter(|&k| v[k].is_some())
        .map(|k| sizes[k] as i64 + e[k] * size_pi as i64)
        .max()
        .unwrap_or(0);
    ((alpha + 2 * beta, largest), e)
}

/// The `β` in `[lo, hi]` where [`best_exponents`]'s order may have its
/// least minimiser, ascending: both ends, and the floor and ceiling of
/// every crossing of two lines `−v_k + (2 − k)·β` (the first key) and of
/// two lines `sizes[k] + size_pi·(k − 2)·β` (the second, up to a constant).
fn exponent_candidates(
    v: &[Option<usize>; 5],
    sizes: &[usize; 5],
    size_pi: usize,
    lo: i64,
    hi: i64,
) -> Vec<i64> {
    let mut out = vec![lo, hi];
    // (k, v_k, sizes[k]) of the nonzero c_k.
    let present: Vec<(i64, i64, i64)> = (0..5)
        .filter_map(|k| v[k].map(|vk| (k as i64, vk as i64, sizes[k] as i64)))
        .collect();
    for (a, &(j, vj, sj)) in present.iter().enumerate() {
        for &(k, vk, sk) in &present[a + 1..] {
            // (2 − j)β − v_j = (2 − k)β − v_k, and sizes_j + π(j − 2)β =
            // sizes_k + π(k − 2)β: both with k > j (no crossing of the
            // second kind for π = 0, where the sizes are constant).
            for (num, den) in [(vj - vk, k - j), (sj - sk, size_pi as i64 * (k - j))] {
                if den > 0 {
                    out.push(num.div_euclid(den));
                    out.push(-(-num).div_euclid(den));
                }
            }
        }
    }
    out.retain(|b| (lo..=hi).contains(b));
    out.sort_unstable();
    out.dedup();
    out
}

/// The normalisation of the module docs, on `[c_4, …, c_0]`, with the
/// candidate factors taken from a squarefree factorisation of `c_4 = det A`
/// and `c_0 = det B`.
pub fn normalise(f: [ZPoly; 5]) -> [ZPoly; 5] {
    let candidates: Vec<ZPoly> = [&f[0], &f[4]]
        .iter()
        .flat_map(|p| squarefree_factors(p).into_iter().map(|(f, _)| f))
        .collect();
    normalise_with(f, candidates)
}

/// The normalisation with given candidate factors: every factor of
/// `det A · det B` must divide a product of them (they are refined into a
/// coprime basis here).
pub fn normalise_with(f: [ZPoly; 5], candidates: Vec<ZPoly>) -> [ZPoly; 5] {
    balance_primes(normalise_in(f, &positive_basis(candidates)).expect("ZPoly arithmetic is exact"))
}

/// Above this many bits in a coefficient of `f`, [`balance_primes`] looks
/// for small primes to take out: below it the whole of `f`'s work runs in
/// `i128` and machine words anyway.
const BALANCE_BITS: u64 = 126;

/// ... and only when the longest and shortest nonzero `c_k` are more than
/// this many bits apart: the rescaling of λ is what pays (the straight
/// lines of `benches/scenes/lines`, 140 to 197 bits within 40 of each
/// other, lost 65–70K instructions to the search and gained nothing).
const BALANCE_SPREAD: u64 = 64;

/// The primes [`balance_primes`] tries: those of decimal inputs (2, 5)
/// and of short rational radii and quaternions.
const SMALL_PRIMES: [u32; 25] = [
    2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47, 53, 59, 61, 67, 71, 73, 79, 83, 89, 97,
];

/// The normalisation's last step (module docs) for constant factors: each
/// small prime `p` ([`SMALL_PRIMES`]) dividing some `c_k` takes the place
/// of a factor of `det A`, `det B` (positive everywhere; `v_k` its
/// multiplicity in the content of `c_k`, found by [`Int::valuation`]),
/// for `f` of more than [`BALANCE_BITS`] bits whose `c_k` are more than
/// [`BALANCE_SPREAD`] bits apart. Radii of `10⁻⁶⁴` and long
/// decimal quaternions leave such factors: `ratio-needle-k0064-*` has
/// contents of 2,522, 1,676, 1,056, 433 and 32 bits in `c_4 … c_0` (a
/// rescaling of λ by a power of 10 in all but name), so that
/// `sr0` carried 6,336 of its 9,387 bits as content (3,068 bits after).
/// Large prime factors (products of long denominators) would need the
/// contents themselves, which cost more than they save.
fn balance_primes(f: [ZPoly; 5]) -> [ZPoly; 5] {
    let bits = f.iter().filter(|c| !c.is_zero()).map(ZPoly::max_bits);
    let (least, most) = (bits.clone().min().unwrap_or(0), bits.max().unwrap_or(0));
    if most <= BALANCE_BITS || most - least <= BALANCE_SPREAD {
        return f;
    }
    // Indexed by the power of λ.
    let c: [&ZPoly; 5] = std::array::from_fn(|k| &f[4 - k]);
    let divisors: [u32; 5] = std::array::from_fn(|k| small_prime_divisors(c[k]));
    let any = divisors.iter().fold(0, |a, d| a | d);
    let factors = SMALL_PRIMES
        .into_iter()
        .enumerate()
        .filter(|(i, _)| any & (1 << i) != 0)
        .map(|(i, p)| {
            let v: [Option<usize>; 5] = std::array::from_fn(|k| {
                let divides = divisors[k] & (1 << i) != 0;
                (!c[k].is_zero()).then(|| {
                    if divides {
                        multiplicity_of_prime(c[k], p)
                    } else {
                        0
                    }
                })
            });
            (Int::from(i64::from(p)), v)
        })
        .collect();
    let scaled = rescale(&f, factors);
    // sr0 only shortens, but the longest c_k may grow (a few bits), which
    // the exact size bound reads: then f stays as it was.
    if scaled.iter().map(ZPoly::max_bits).max().unwrap_or(0) > most {
        return f;
    }
    scaled
}

/// `c_k·Π π^(α_π + β_π·k)` for factors `π > 1` with multiplicities `v_k`
/// in the `c_k` (`v` indexed by the power of λ, `None` for `c_k = 0`; `f`
/// high → low as stored): the exponents of [`best_exponents`] for each,
/// then one division and one product per `c_k`.
fn rescale(f: &[ZPoly; 5], factors: Vec<(Int, [Option<usize>; 5])>) -> [ZPoly; 5] {
    let sizes: [usize; 5] = std::array::from_fn(|k| f[4 - k].max_bits() as usize);
    let (mut up, mut down) = (
        std::array::from_fn::<Int, 5, _>(|_| Int::one()),
        std::array::from_fn::<Int, 5, _>(|_| Int::one()),
    );
    for (pi, v) in factors {
        let e = best_exponents(&v, &sizes, pi.bits() as usize);
        for k in 0..5 {
            match e[k] {
                e if e > 0 => up[k] *= pi.pow(e as u32),
                e if e < 0 => down[k] *= pi.pow(-e as u32),
                _ => {}
            }
        }
    }
    std::array::from_fn(|i| {
        let k = 4 - i;
        let c = if down[k].is_one() {
            f[i].clone()
        } else {
            f[i].div_exact_int(&down[k])
        };
        if up[k].is_one() {
            c
        } else {
            c.mul_int(&up[k])
        }
    })
}

impl CharPoly {
    /// The normalisation's rescaling of λ (module docs) by every constant
    /// factor of the `c_k`, not only small primes: the factors `π > 1` of a
    /// coprime basis of the contents of the `c_k` (factor refinement),
    /// each with its multiplicities in them. It takes a gcd over every
    /// coefficient of `f`, which costs more than it saves on ordinary long
    /// scenes (contents of 6,700-bit degree-16 coefficients: +20M
    /// instructions against 2.3M saved), so the exact path takes it only
    /// for an `f` whose closed forms it would otherwise refuse as too long
    /// (`bench-perturbed-affine-rational-deg2-d1000`: coefficients of
    /// 66,500 bits with contents of 26,580 to 46,535).
    pub fn without_constant_scalings(self) -> CharPoly {
        // Indexed by the power of λ.
        let contents: [Option<Int>; 5] = std::array::from_fn(|k| {
            let c = &self.coeffs[4 - k];
            (!c.is_zero()).then(|| c.content())
        });
        let Some(basis) = refine_coprime(
            contents.iter().flatten().cloned().collect(),
            |x: &Int| x.bits() >= 2,
            Int::gcd,
            Int::div_exact,
            REFINE_BUDGET,
        ) else {
            return self;
        };
        let factors = basis
            .into_iter()
            .map(|pi| {
                let v = contents
                    .each_ref()
                    .map(|x| x.as_ref().map(|x| multiplicity_in(x, &pi)));
                (pi, v)
            })
            .collect();
        CharPoly {
            coeffs: rescale(&self.coeffs, factors),
        }
    }
}

/// The gcds [`CharPoly::without_constant_scalings`] may spend refining
/// the contents into a coprime basis (five contents usually take a few
/// dozen; exponent chains such as `2^N·3`, `2^(N−1)·3`, which the small
/// primes leave when their sizes are close, take `N` and gain nothing).
const REFINE_BUDGET: usize = 200;

/// How often `pi > 1` divides `x ≠ 0`: [`Int::valuation`] for a word
/// `pi`, else by repeated division (a factor of more than 32 bits divides
/// `x` fewer than `bits(x)/32` times).
fn multiplicity_in(x: &Int, pi: &Int) -> usize {
    if let Some(p) = pi.to_i64().and_then(|p| u32::try_from(p).ok()) {
        return x.valuation(p, u64::MAX) as usize;
    }
    let (mut v, mut rest) = (0, x.clone());
    loop {
        let (q, r) = rest.div_rem_trunc(pi);
        if !r.is_zero() {
            return v;
        }
        (v, rest) = (v + 1, q);
    }
}

/// The products of [`SMALL_PRIMES`] in words: one remainder by each
/// tells which of them divide a number.
const PRIME_WORDS: [u64; 2] = [
    2 * 3 * 5 * 7 * 11 * 13 * 17 * 19 * 23 * 29 * 31 * 37 * 41 * 43 * 47,
    53 * 59 * 61 * 67 * 71 * 73 * 79 * 83 * 89 * 97,
];

/// Bit `i` set when `SMALL_PRIMES[i]` divides every coefficient of `c`
/// (none for `c = 0`): two word remainders per coefficient.
fn small_prime_divisors(c: &ZPoly) -> u32 {
    let mut all = if c.is_zero() { 0 } else { u32::MAX };
    for x in c.coeffs().iter().filter(|x| !x.is_zero()) {
        let r = PRIME_WORDS.map(|w| x.mod_u64(w));
        let word = |p: u32| r[usize::from(p > 47)];
        all &= SMALL_PRIMES
            .iter()
            .enumerate()
            .filter(|(_, &p)| word(p) % u64::from(p) == 0)
            .fold(0, |m, (i, _)| m | 1 << i);
        if all == 0 {
            break;
        }
    }
    all
}

/// How often the prime `p` divides every coefficient of `c ≠ 0`: the
/// least [`Int::valuation`], the shortest coefficient first (the
/// likeliest least); each later one is first tested for `p^v`, `v` the
/// least so far (one remainder), and counted (up to `v`) only when that
/// fails.
fn multiplicity_of_prime(c: &ZPoly, p: u32) -> usize {
    let mut nonzero: Vec<&Int> = c.coeffs().iter().filter(|x| !x.is_zero()).collect();
    nonzero.sort_by_key(|x| x.bits());
    let Some((first, rest)) = nonzero.split_first() else {
        return 0;
    };
    let mut v = first.valuation(p, u64::MAX);
    // The coefficients usually share the content: one remainder by `p^v`
    // shows that it divides a later one (whose valuation capped at `v` is
    // then `v`) where counting the factors takes a division per word of
    // them. For 2 the trailing zeros cost less than a remainder.
    let mut power: Option<Int> = None;
    for x in rest {
        if v == 0 {
            break;
        }
        let divides = p != 2
            && u32::try_from(v).is_ok_and(|e| {
                let pv = power.get_or_insert_with(|| Int::from(i64::from(p)).pow(e));
                match pv.to_i64() {
                    Some(word) => x.mod_u64(word as u64) == 0,
                    None => x.is_divisible_by(pv),
                }
            });
        if !divides {
            v = x.valuation(p, v);
            power = None;
        }
    }
    v as usize
}

/// [`normalise_with`] of an exact `f` given in `i128` ([`SmallPoly`]):
/// the whole normalisation in `i128` when every number on the way fits,
/// else over [`ZPoly`]; the same polynomial either way.
fn normalise_small(f: &[SmallPoly; 5], candidates: Vec<ZPoly>) -> [ZPoly; 5] {
    let basis = positive_basis(candidates);
    let small = basis
        .iter()
        .map(SmallPoly::from_zpoly)
        .collect::<Option<Vec<_>>>()
        .and_then(|pis| normalise_in(f.clone(), &pis));
    // Coefficients of at most BALANCE_BITS bits: balance_primes would
    // leave them as they are.
    let short = |f: &[SmallPoly; 5]| f.iter().all(|c| c.max_bits() <= BALANCE_BITS);
    match small.as_ref().map(|f| (short(f), SmallPoly::to_zpolys(f))) {
        Some((true, Some(f))) => f,
        Some((false, Some(f))) => balance_primes(f),
        _ => {
            let f = SmallPoly::to_zpolys(f).expect("an exact f");
            balance_primes(normalise_in(f, &basis).expect("ZPoly arithmetic is exact"))
        }
    }
}

/// The coprime basis of the candidates ([`coprime_basis`]), each made
/// positive on the span (it divides det A or det B, which do not vanish
/// there, so its sign at `u = 1/2` is its sign throughout).
fn positive_basis(candidates: Vec<ZPoly>) -> Vec<ZPoly> {
    let half = Rat::from_frac(1, 2);
    coprime_basis(candidates)
        .into_iter()
        .map(|pi| if pi.sign_at(&half) < 0 { -&pi } else { pi })
        .collect()
}

/// The normalisation of the module docs on `[c_4, …, c_0]` over `P`, with
/// the coprime, positive factors `basis`; `None` if a step overflowed `P`.
fn normalise_in<P: IntegerPoly>(f: [P; 5], basis: &[P]) -> Option<[P; 5]> {
    // Low → high for indexing by the power of λ.
    let mut c = f;
    c.reverse();
    'factors: for pi in basis {
        // v_k and the cofactor c_k/π^v_k, nearest k = 2 first on each side:
        // once π divides neither some c_j (j < 2) nor some c_l (l > 2),
        // both nonzero, `e = 0` is the only best choice of
        // [`best_exponents`] (`α + 2β` is a convex combination of
        // `α + βj >= 0` and `α + βl >= 0`, zero only at `α = β = 0`): π
        // changes nothing and the remaining divisions, successful and
        // long ones among them, are skipped (`bench-perturbed-affine-deg2-d0100`:
        // `π_A² | c_0`, `π_B² | c_4`, 1.3M instructions).
        let mut split: [Option<(usize, P)>; 5] = Default::default();
        let mut undivided = [false; 2];
        for k in [3, 1, 4, 0, 2] {
            if !c[k].is_zero() {
                let part = c[k].split(pi)?;
                if part.0 == 0 && k != 2 {
                    undivided[usize::from(k > 2)] = true;
                    if undivided == [true, true] {
                        continue 'factors;
                    }
                }
                split[k] = Some(part);
            }
        }
        let v: [Option<usize>; 5] = std::array::from_fn(|k| split[k].as_ref().map(|(v, _)| *v));
        let degs: [usize; 5] = std::array::from_fn(|k| c[k].size().0);
        let e = best_exponents(&v, &degs, pi.size().0);
        for (k, part) in split.iter().enumerate() {
            // c_k·π^e_k = cofactor·π^(v_k + e_k), a product since e_k >= −v_k
            // (one more product rather than dividing c_k again).
            let Some((vk, cofactor)) = part else { continue };
            if e[k] == 0 {
                continue;
            }
            c[k] = cofactor.times_power(pi, (*vk as i64 + e[k]) as u32)?;
        }
    }
    // The common integer content (a positive constant).
    let mut c = P::without_content(c)?;
    c.reverse();
    Some(c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_quadric::{congruence, subset_products};

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Static bodies of short radii and centres whose quaternion
        /// components are short numerators over long denominators of their
        /// own (beyond `i128` together from 2^127 on; found by review: two
        /// overflowed denominators compared equal, so `i128` returned bare
        /// numerators as exact): the lean `f` is the placements' one.
        #[test]
        fn static_pairs_with_denominators_beyond_i128(
            numerators in proptest::collection::vec(1i64..20, 4),
            extra in proptest::collection::vec(1i64..50, 4),
            long in 40u32..52,
            radii in proptest::collection::vec(1i64..12, 6),
            centre in proptest::collection::vec(-9i64..10, 3),
        ) {
            use crate::kinds::Motion;
            let tail = Int::from(7).pow(long);
            let q: [Rat; 4] = std::array::from_fn(|i| {
                Rat::new(Int::from(numerators[i]), &tail * &Int::from(extra[i])).expect("nonzero")
            });
            let body = |r: &[i64], c: [Rat; 3], orientation: [Rat; 4]| Body {
                radii: std::array::from_fn(|i| Rat::from(r[i])),
                motion: Motion::Static { center: c, orientation },
            };
            let a = body(&radii[..3], std::array::from_fn(|_| Rat::zero()), q);
            let b = body(&radii[3..], centre.iter().map(|&x| Rat::from(x)).collect::<Vec<_>>().try_into().expect("three"), [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()]);
            let span = [Rat::zero(), Rat::one()];
            let placed = CharPoly::from_placed(
                &placed_quadric(&a, &span).expect("a valid body"),
                &placed_quadric(&b, &span).expect("a valid body"),
            );
            proptest::prop_assert_eq!(CharPoly::of_static(&a, &b), Some(placed));
        }
    }

    #[test]
    fn known_factors_give_the_same_normalisation() {
        use crate::kinds::{Bezier, Motion};
        let r = |s: &str| -> Rat { s.parse().unwrap() };
        let v = |a: &str, b: &str, c: &str| [r(a), r(b), r(c)];
        let q = |a: &str, b: &str, c: &str, d: &str| [r(a), r(b), r(c), r(d)];
        let rigid = Body {
            radii: v("3", "1", "1/2"),
            motion: Motion::Rigid {
                orientation: Bezier {
                    points: vec![q("1", "0", "0", "0"), q("1", "0", "1", "1")],
                    weights: None,
                },
                center: Bezier {
                    points: vec![v("0", "0", "0"), v("1", "2", "0")],
                    weights: Some(vec![r("1"), r("2")]),
                },
            },
        };
        let affine = Body {
            radii: v("2", "1", "1"),
            motion: Motion::Affine {
                matrix: Bezier {
                    points: vec![
                        [
                            q("1", "0", "0", "4"),
                            q("0", "1", "0", "0"),
                            q("0", "0", "1", "0"),
                        ],
                        [
                            q("2", "1/2", "0", "0"),
                            q("0", "3/5", "3/10", "1"),
                            q("0", "0", "3/2", "1/2"),
                        ],
                    ],
                    weights: Some(vec![r("1"), r("3")]),
                },
            },
        };
        let span = [Rat::zero(), Rat::one()];
        let (pa, pb) = (
            crate::matrices::placed_quadric(&rigid, &span).unwrap(),
            crate::matrices::placed_quadric(&affine, &span).unwrap(),
        );
        // Plücker coordinates of the placements with known factors, against
        // the adjugate quadrics with factors found by factorisation.
        let fast = CharPoly::from_placed(&pa, &pb);
        let slow = CharPoly::new(
            &crate::matrices::moving_quadric(&rigid, &span).unwrap(),
            &crate::matrices::moving_quadric(&affine, &span).unwrap(),
        );
        assert_eq!(fast, slow);
    }

    /// An unlucky prime: `a` and `a + p` are one root modulo the word
    /// prime `p`, so every image has the repeated factor `(λ − a)²` while
    /// over `ℚ` the parts share the simple factors `λ − a`, `λ − a − p` only
    /// (`sr0 ≢ 0`). `F_0` and `F_1` each have a repeated factor of their
    /// own ((λ + 1)², (λ + 2)²), so the exact `h` (from `F_0`) is
    /// `λ + 1`, and only the final division test says no.
    #[test]
    fn an_unlucky_prime_is_caught_by_the_exact_division() {
        let p = Int::from(ccd_poly::Residues::modulus());
        let a = Int::from(5);
        let (r, s) = (
            ZPoly::new(vec![-&a, Int::one()]),
            ZPoly::new(vec![-(&a + &p), Int::one()]),
        );
        let shared = &r * &s;
        let parts = [
            &shared * &ZPoly::from_i64s(&[1, 2, 1]),
            &shared * &ZPoly::from_i64s(&[4, 4, 1]),
        ];
        // Coefficient of λ^(4 − k), a polynomial in t.
        let coeffs =
            std::array::from_fn(|k| ZPoly::new(parts.iter().map(|f| f.coeff(4 - k)).collect()));
        let f = CharPoly { coeffs };
        assert_eq!(f.fixed_repeated_factor(), None);
        // With a lucky base (F_1 alone has no repeated factor over ℚ) the
        // exact gcd already says no.
        let clean = [parts[0].clone(), &shared * &ZPoly::from_i64s(&[3, 0, 1])];
        let coeffs =
            std::array::from_fn(|k| ZPoly::new(clean.iter().map(|f| f.coeff(4 - k)).collect()));
        assert_eq!(CharPoly { coeffs }.fixed_repeated_factor(), None);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// Dividing the rows of `[M_A | M_B]` by their contents divides the
        /// Plücker quartic by the contents' squares, nothing else (linear
        /// entries, rows multiplied by long factors, some zero entries);
        /// so does dividing the columns of two inverse placements `N` for
        /// the quartic of the quadrics `NᵀDN`.
        #[test]
        fn line_contents_only_scale_the_quartics(
            entries in proptest::collection::vec(-3i64..4, 64),
            diagonal in proptest::collection::vec(1i64..5, 8),
            rows in proptest::collection::vec((1i64..40, 0u32..30), 4),
        ) {
            let factor = |i: usize| &Int::from(rows[i].0) * &Int::from(3).pow(rows[i].1);
            let matrix = |k: usize| -> Mat4<ZPoly> {
                std::array::from_fn(|r| {
                    std::array::from_fn(|c| {
                        let e = &entries[32 * k + 8 * r + 2 * c..][..2];
                        ZPoly::from_i64s(&[e[0] + 4 * i64::from(r == c), e[1]]).mul_int(&factor(r))
                    })
                })
            };
            let d = |k: usize| -> [ZPoly; 4] {
                std::array::from_fn(|i| {
                    let v = diagonal[4 * k + i];
                    ZPoly::from_i64s(&[if i == 3 { -v } else { v }])
                })
            };
            let (ma, mb) = (matrix(0), matrix(1));
            let raw = placed_characteristic(&ma, &subset_products(&d(0)), &mb, &subset_products(&d(1)), None);
            let scale = (0..4).fold(Int::one(), |s, i| {
                let row: Vec<ZPoly> = ma[i].iter().chain(&mb[i]).cloned().collect();
                &s * &ZPoly::common_content(&row).pow(2)
            });
            let (xa, xb) = without_row_contents(ma.clone(), mb.clone());
            let lean = placed_characteristic(&xa, &subset_products(&d(0)), &xb, &subset_products(&d(1)), None);
            proptest::prop_assert_eq!(lean.map(|c| c.mul_int(&scale)), raw);
            // The same matrices as inverse placements `N` with long column
            // factors: `det(λNᵀD_AN + ...)` scales by the columns' contents
            // squared.
            let (na, nb) = (transposed(ma), transposed(mb));
            let quartic = |na: &Mat4<ZPoly>, nb: &Mat4<ZPoly>| {
                characteristic(&congruence(na, &d(0)), &congruence(nb, &d(1)))
            };
            let raw = quartic(&na, &nb);
            let (ta, tb) = without_row_contents(transposed(na), transposed(nb));
            let lean = quartic(&transposed(ta), &transposed(tb));
            proptest::prop_assert_eq!(lean.map(|c| c.mul_int(&scale)), raw);
        }

        /// Placements of long decimals (past 80 bits, past `i128`): the
        /// lean routes (rows of `[M_A | M_B]` or columns of the inverse
        /// placements divided by their contents) give the `f` of the
        /// quadrics themselves, normalised by factorisation — for a rigid
        /// body beside a static one (the quadric route) and for two affine
        /// bodies (the Plücker route).
        #[test]
        fn long_placements_take_the_lean_routes(
            digits in proptest::collection::vec(-9i64..10, 40),
            scale in 25u32..40,
        ) {
            use crate::kinds::{Bezier, Motion};
            let ten = Int::from(10).pow(scale);
            // (10^s·(k + 7) + digit) / (2·10^s): near (k + 7)/2, long.
            let long = |k: usize| {
                Rat::new(&(&ten * &Int::from(k as i64 % 5 + 7)) + &Int::from(digits[k % 40]), &ten * &Int::from(2))
                    .expect("nonzero")
            };
            let radii = |o: usize| std::array::from_fn(|i| long(o + i));
            let quat = |o: usize| -> [Rat; 4] { std::array::from_fn(|i| long(o + i)) };
            let vec3 = |o: usize| -> [Rat; 3] { std::array::from_fn(|i| &long(o + i) * &Rat::from(3 * (i as i64) - 2)) };
            let span = [Rat::zero(), Rat::one()];
            let rigid = Body {
                radii: radii(0),
                motion: Motion::Rigid {
                    orientation: Bezier { points: vec![quat(3), quat(7)], weights: None },
                    center: Bezier { points: vec![vec3(11), vec3(14)], weights: None },
                },
            };
            let still = Body { radii: radii(17), motion: Motion::Static { center: vec3(20), orientation: quat(23) } };
            let affine = |o: usize| Body {
                radii: radii(o),
                motion: Motion::Affine {
                    matrix: Bezier {
                        points: (0..2)
                            .map(|p| std::array::from_fn(|r| std::array::from_fn(|c| {
                                let x = long(o + 4 * r + c + p);
                                if r == c { &x * &Rat::from(4) } else { x }
                            })))
                            .collect(),
                        weights: None,
                    },
                },
            };
            for (a, b) in [(rigid, still), (affine(2), affine(9))] {
                let (Ok(pa), Ok(pb)) = (
                    crate::matrices::placed_quadric(&a, &span),
                    crate::matrices::placed_quadric(&b, &span),
                ) else {
                    continue;
                };
                proptest::prop_assert!(pa.bits().max(pb.bits()) > SMALL_BODY_BITS);
                let slow = CharPoly::new(&pa.quadric(), &pb.quadric());
                let fast = CharPoly::from_placed(&pa, &pb);
                proptest::prop_assert!(same_up_to_constant_scalings(&fast, &slow), "{fast:?} vs {slow:?}");
            }
        }

        /// Two rigid bodies (each turning by a quaternion curve of degree
        /// 0 to 2, its centre on a rational curve, rational radii): the
        /// relative placement's quartic ([`rigid_quartic`]) normalises to
        /// the very polynomial of the quadrics' own route, bit for bit —
        /// the normalisation takes out the powers of `n·w` and the
        /// positive constant by which they differ. With `long`, every
        /// number is stretched past 80 bits (times `10^30 + 1`, over
        /// `10^30`), where the route it must match is the inverse
        /// placements' Cauchy–Binet ([`inverse_characteristic`]) — except
        /// where the normalisation's tie between rescalings of λ of equal
        /// `α + 2β` is broken by sizes the old route saw with the other
        /// body's powers still in ([`same_but_a_tie`]). On the
        /// way, its `i128` routes (by values, [`by_values`], and as
        /// polynomials) agree with its exact one wherever they answer.
        #[test]
        fn relative_placement_gives_the_quadrics_route(
            quats in proptest::collection::vec(-3i64..4, 24),
            centres in proptest::collection::vec(-5i64..6, 18),
            weights in proptest::collection::vec(1i64..4, 6),
            radii in proptest::collection::vec((1i64..9, 1i64..5), 6),
            degrees in (0usize..3, 0usize..3),
            long in proptest::bool::ANY,
        ) {
            use crate::kinds::{Bezier, Motion};
            let stretch = |x: Rat| {
                if long {
                    let ten = Int::from(10).pow(30);
                    &x * &Rat::new(&ten + &Int::one(), ten).expect("nonzero")
                } else {
                    x
                }
            };
            let body = |k: usize, degree: usize| Body {
                radii: std::array::from_fn(|i| {
                    stretch(Rat::from_frac(radii[3 * k + i].0, radii[3 * k + i].1))
                }),
                motion: Motion::Rigid {
                    orientation: Bezier {
                        points: (0..=degree)
                            .map(|p| std::array::from_fn(|i| {
                                // Mostly away from zero, so few curves vanish.
                                let base = if i == 0 { 4 } else { 0 };
                                stretch(Rat::from(base + quats[12 * k + 4 * p + i]))
                            }))
                            .collect(),
                        weights: None,
                    },
                    center: Bezier {
                        points: (0..3)
                            .map(|p| std::array::from_fn(|i| {
                                Rat::from(centres[9 * k + 3 * p + i] + 6 * k as i64)
                            }))
                            .collect(),
                        weights: Some((0..3).map(|p| Rat::from(weights[3 * k + p])).collect()),
                    },
                },
            };
            let span = [Rat::zero(), Rat::one()];
            let (Ok(pa), Ok(pb)) = (
                crate::matrices::placed_quadric(&body(0, degrees.0), &span),
                crate::matrices::placed_quadric(&body(1, degrees.1), &span),
            ) else {
                return Err(proptest::test_runner::TestCaseError::reject("a degenerate motion"));
            };
            if !(pa.turns() || pb.turns()) {
                // Bodies that never turn take the centred route.
                return Err(proptest::test_runner::TestCaseError::reject("no turn"));
            }
            // The i128 routes (by values, as polynomials) give the exact
            // polynomials wherever they give any.
            let [fa, fb] = [&pa, &pb].map(|p| p.rigid_frame(ZPoly::clone).expect("rigid"));
            let [da, db] = [&pa, &pb].map(|p| p.diagonal.each_ref().map(|d| d.coeff(0)));
            let polynomial = rigid_characteristic(&fa, &fb, &da, &db);
            if let Some(f) = by_values(&pa, &pb, &da, &db) {
                proptest::prop_assert_eq!(SmallPoly::to_zpolys(&f), Some(polynomial.clone()));
            }
            let [sa, sb] = [&pa, &pb].map(|p| p.rigid_frame(SmallPoly::lowered).expect("rigid"));
            let [ta, tb] = [&da, &db].map(|d| d.each_ref().map(SmallInt::of));
            if let Some(f) = exact(rigid_characteristic(&sa, &sb, &ta, &tb)) {
                proptest::prop_assert_eq!(SmallPoly::to_zpolys(&f), Some(polynomial.clone()));
            }
            let candidates = known_factors(&pa, &pb);
            let reference = if pa.bits().max(pb.bits()) > SMALL_BODY_BITS {
                proptest::prop_assert!(long);
                inverse_characteristic(&pa, &pb)
            } else {
                characteristic(&pa.quadric(), &pb.quadric())
            };
            let reference = CharPoly { coeffs: normalise_with(reference, candidates) };
            let f = CharPoly::from_placed(&pa, &pb);
            proptest::prop_assert!(
                f == reference || same_but_a_tie(&f, &reference),
                "{f:?} vs {reference:?}"
            );
        }

        /// The Plücker route (affine bodies) against the adjugate quadrics
        /// with factors found by factorisation: the same normalised `f`.
        #[test]
        fn plucker_route_matches_adjugate_quadrics(
            entries in proptest::collection::vec(-4i64..5, 72),
            weights in proptest::collection::vec(1i64..4, 6),
            radii in proptest::collection::vec((1i64..9, 1i64..5), 6),
        ) {
            use crate::kinds::{Bezier, Motion};
            let body = |k: usize| Body {
                radii: std::array::from_fn(|i| Rat::from_frac(radii[3 * k + i].0, radii[3 * k + i].1)),
                motion: Motion::Affine {
                    matrix: Bezier {
                        points: (0..3)
                            .map(|p| {
                                std::array::from_fn(|r| {
                                    std::array::from_fn(|c| {
                                        // Diagonal-dominant so most motions stay regular.
                                        let base = if r == c { 6 } else { 0 };
                                        Rat::from(base + entries[36 * k + 12 * p + 4 * r + c])
                                    })
                                })
                            })
                            .collect(),
                        weights: Some((0..3).map(|p| Rat::from(weights[3 * k + p])).collect()),
                    },
                },
            };
            let span = [Rat::zero(), Rat::one()];
            let (a, b) = (body(0), body(1));
            let (Ok(pa), Ok(pb)) = (
                crate::matrices::placed_quadric(&a, &span),
                crate::matrices::placed_quadric(&b, &span),
            ) else {
                return Err(proptest::test_runner::TestCaseError::reject("singular motion"));
            };
            let slow = CharPoly::new(&pa.quadric(), &pb.quadric());
            let fast = CharPoly::from_placed(&pa, &pb);
            proptest::prop_assert!(same_up_to_constant_scalings(&fast, &slow), "{fast:?} vs {slow:?}");
        }
    }

    /// Radii with long numerators (`(10⁴⁰ + k)/7`, whose large prime
    /// factors no small-prime rescaling takes out): both routes to `f` —
    /// Plücker coordinates of affine placements, Cauchy–Binet on rigid
    /// inverse placements — give the `f` of the quadrics up to constant
    /// scalings, and a shorter one than the integer diagonal's, by at least
    /// the bits of `n₀n₁n₂` (the rescaling
    /// [`PlacedQuadric::diagonal_products`] leaves out).
    #[test]
    fn long_radii_leave_their_rescaling_out() {
        use crate::kinds::{Bezier, Motion};
        let ten = Int::from(10).pow(40);
        let radii = |k: i64| -> [Rat; 3] {
            std::array::from_fn(|i| {
                Rat::new(&ten + &Int::from(k + 2 * i as i64), Int::from(7)).unwrap()
            })
        };
        let numerators: u64 = (0..3).map(|i| radii(1)[i].numer().bits()).sum();
        let r = |x: i64| Rat::from(x);
        let affine = |k: i64| Body {
            radii: radii(k),
            motion: Motion::Affine {
                matrix: Bezier {
                    points: (0..3)
                        .map(|p: i64| {
                            std::array::from_fn(|i| {
                                std::array::from_fn(|j| {
                                    let diagonal = if i == j { 3 + p + k } else { 0 };
                                    r(diagonal + (i + 2 * j) as i64 % 3 - p)
                                })
                            })
                        })
                        .collect(),
                    weights: None,
                },
            },
        };
        let rigid = Body {
            radii: radii(3),
            motion: Motion::Rigid {
                orientation: Bezier {
                    points: vec![[1, 2, 0, 1].map(r), [2, -1, 1, 3].map(r)],
                    weights: None,
                },
                center: Bezier {
                    points: vec![[0, 1, 2].map(r), [3, -1, 1].map(r)],
                    weights: None,
                },
            },
        };
        let still = Body {
            radii: radii(1),
            motion: Motion::Static {
                center: [1, 0, 0].map(r),
                orientation: [1, 0, 0, 0].map(r),
            },
        };
        let span = [Rat::zero(), Rat::one()];
        for (a, b) in [(affine(1), affine(2)), (rigid, still)] {
            let (pa, pb) = (
                crate::matrices::placed_quadric(&a, &span).unwrap(),
                crate::matrices::placed_quadric(&b, &span).unwrap(),
            );
            let slow = CharPoly::new(&pa.quadric(), &pb.quadric());
            let fast = CharPoly::from_placed(&pa, &pb);
            assert!(same_up_to_constant_scalings(&fast, &slow));
            let longest = |f: &CharPoly| f.coeffs.iter().map(ZPoly::max_bits).max().unwrap();
            // 813 against 2,416 bits (affine), 815 against 1,347 (rigid),
            // with numerators of 397 bits together.
            assert!(
                longest(&fast) + numerators <= longest(&slow),
                "{} vs {}",
                longest(&fast),
                longest(&slow)
            );
        }
    }

    /// `c_k = κ·σ^k·d_k` (low → high in λ) for constants `κ, σ > 0`: the
    /// normalisation is canonical up to these (it removes polynomial factors
    /// and the integer content, not a constant rescaling of λ).
    fn same_up_to_constant_scalings(f: &CharPoly, g: &CharPoly) -> bool {
        // r_k = c_k/d_k must be a positive constant, r_k⁴ = r_0^(4−k)·r_4^k.
        let ratio = |k: usize| -> Option<Rat> {
            let (c, d) = (&f.coeffs[4 - k], &g.coeffs[4 - k]);
            let (lc, ld) = (c.coeffs().last()?, d.coeffs().last()?);
            (c.mul_int(ld) == d.mul_int(lc)).then(|| Rat::new(lc.clone(), ld.clone()).unwrap())
        };
        let Some(r) = (0..5).map(ratio).collect::<Option<Vec<Rat>>>() else {
            return false;
        };
        let pow = |x: &Rat, e: usize| (0..e).fold(Rat::one(), |acc, _| &acc * x);
        r.iter().all(|x| x.signum() > 0)
            && (0..5).all(|k| pow(&r[k], 4) == &pow(&r[0], 4 - k) * &pow(&r[4], k))
    }

    /// `f(λ) = g(r·λ)` up to the factor `r⁻²` for a rational function `r`
    /// (`c_k^f = c_k^g·r^(k−2)`): the same `c_2`, so the same `α + 2β` of
    /// the normalisation and the same `sr0` (weight 12, degree 6:
    /// `r^(12 − 2·6) = 1`); only a tie between such rescalings broken
    /// otherwise. `r = N/D` from `c_3` (else `c_1`), checked on every
    /// coefficient by cross-multiplication.
    fn same_but_a_tie(f: &CharPoly, g: &CharPoly) -> bool {
        let (cf, cg) = (|k: usize| &f.coeffs[4 - k], |k: usize| &g.coeffs[4 - k]);
        let (n, d) = if !cf(3).is_zero() && !cg(3).is_zero() {
            (cf(3).clone(), cg(3).clone())
        } else if !cf(1).is_zero() && !cg(1).is_zero() {
            (cg(1).clone(), cf(1).clone())
        } else {
            return cf(2) == cg(2) && (cf(4) * cf(0)) == (cg(4) * cg(0));
        };
        let pow = |p: &ZPoly, e: usize| (0..e).fold(ZPoly::from_i64s(&[1]), |a, _| &a * p);
        cf(2) == cg(2)
            && (0..5usize).all(|k| {
                let e = k.abs_diff(2);
                let (up, down) = if k >= 2 { (&d, &n) } else { (&n, &d) };
                (cf(k) * &pow(up, e)) == (cg(k) * &pow(down, e))
            })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The normalisation in i128 (small numbers) and in ZPoly (the same
        /// `f` times a huge positive constant, which the content removal
        /// takes out) agree: `c_k = g_k·s^(4−k)·p^m` with `s`, `p` positive.
        #[test]
        fn small_and_big_normalisations_agree(
            g in proptest::collection::vec(proptest::collection::vec(-6i64..7, 1..4), 5),
            a in 1i64..6,
            b in -3i64..4,
            m in 0u32..3,
        ) {
            proptest::prop_assume!(g[0].iter().any(|&x| x != 0) && g[4].iter().any(|&x| x != 0));
            let s = ZPoly::from_i64s(&[a, 0, 1]); // u² + a
            let p = ZPoly::from_i64s(&[b * b + 1, 2 * b, 1]); // (u + b)² + 1
            let f: [ZPoly; 5] = std::array::from_fn(|i| {
                &(&ZPoly::from_i64s(&g[i]) * &s.pow((4 - i) as u32)) * &p.pow(m)
            });
            let huge = Int::from(3).pow(90);
            let big: [ZPoly; 5] = f.each_ref().map(|c| c.mul_int(&huge));
            proptest::prop_assert!(big.iter().all(|c| SmallPoly::from_zpoly(c).is_none() || c.is_zero()));
            // The whole normalisation in i128 (f given as SmallPoly) too.
            let small = f.each_ref().map(|c| SmallPoly::from_zpoly(c).expect("short"));
            let candidates = [&f[0], &f[4]]
                .iter()
                .flat_map(|p| squarefree_factors(p).into_iter().map(|(f, _)| f))
                .collect();
            proptest::prop_assert_eq!(normalise_small(&small, candidates), normalise(f.clone()));
            proptest::prop_assert_eq!(normalise(f), normalise(big));
        }
    }

    #[test]
    fn balancing_removes_a_constant_lambda_scaling() {
        // c_k = 7³·(2^64·5^64)^k·g_k (k the power of λ), the g_k with no
        // small prime common to their coefficients: balancing gives g back.
        let g = [
            ZPoly::from_i64s(&[3, 1]),
            ZPoly::from_i64s(&[1, -1, 11]),
            ZPoly::from_i64s(&[-13, 0, 2]),
            ZPoly::from_i64s(&[5, 1]),
            ZPoly::from_i64s(&[-7, 9]),
        ];
        let scale = |k: u32| Int::from(7).pow(3) * Int::from(10).pow(64 * k);
        let f: [ZPoly; 5] = std::array::from_fn(|i| g[i].mul_int(&scale(4 - i as u32)));
        assert!(f[0].max_bits() > BALANCE_BITS);
        assert_eq!(balance_primes(f.clone()), g);
        // Through the whole normalisation too (no polynomial factors).
        assert_eq!(normalise(f), g);
        // The primes at the ends of the two words: 47^(30k)·97^(20(4 − k)).
        let scale = |k: u32| Int::from(47).pow(30 * k) * Int::from(97).pow(20 * (4 - k));
        let f: [ZPoly; 5] = std::array::from_fn(|i| g[i].mul_int(&scale(4 - i as u32)));
        assert_eq!(balance_primes(f), g);
    }

    /// The exponents by brute force over the search's whole box, `β ∈
    /// [−v_max, v_max]` and `α ∈ [−5·v_max, 5·v_max]`, in the order the
    /// search takes them (β ascending; for each, the least feasible α), the
    /// first of the least `(α + 2β, largest size)` kept.
    fn best_exponents_brute(
        v: &[Option<usize>; 5],
        sizes: &[usize; 5],
        size_pi: usize,
    ) -> [i64; 5] {
        let vmax = v.iter().flatten().copied().max().unwrap_or(0) as i64;
        let exponents = |alpha: i64, beta: i64| -> [i64; 5] {
            std::array::from_fn(|k| alpha + beta * k as i64)
        };
        let feasible = |e: &[i64; 5]| (0..5).all(|k| v[k].is_none_or(|vk| e[k] >= -(vk as i64)));
        let largest = |e: &[i64; 5]| {
            (0..5)
                .filter(|&k| v[k].is_some())
                .map(|k| sizes[k] as i64 + e[k] * size_pi as i64)
                .max()
                .unwrap_or(0)
        };
        let candidates = (-vmax..=vmax).filter_map(|beta| {
            (-5 * vmax..=5 * vmax)
                .map(|alpha| (alpha, exponents(alpha, beta)))
                .find(|(_, e)| feasible(e))
                .map(|(alpha, e)| ((alpha + 2 * beta, largest(&e)), e))
        });
        candidates
            .fold(
                None::<((i64, i64), [i64; 5])>,
                |best, (key, e)| match best {
                    Some((b, _)) if b <= key => best,
                    _ => Some((key, e)),
                },
            )
            .map_or([0; 5], |(_, e)| e)
    }

    /// [`best_exponents`] and the search over the crossings alone
    /// ([`exponent_candidates`], whatever the range) give the brute force's
    /// exponents (only those of nonzero `c_k` mean anything).
    fn exponents_are_the_brute_forces(
        v: &[Option<usize>; 5],
        sizes: &[usize; 5],
        size_pi: usize,
    ) -> Result<(), proptest::test_runner::TestCaseError> {
        let brute = best_exponents_brute(v, sizes, size_pi);
        let (lo, hi) = exponent_range(v);
        let listed = least_exponents(
            v,
            sizes,
            size_pi,
            exponent_candidates(v, sizes, size_pi, lo, hi),
        );
        let fast = best_exponents(v, sizes, size_pi);
        for k in (0..5).filter(|&k| v[k].is_some()) {
            proptest::prop_assert_eq!(fast[k], brute[k], "k = {}", k);
            proptest::prop_assert_eq!(listed[k], brute[k], "crossings, k = {}", k);
        }
        Ok(())
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(512))]
        /// The bounded search finds the full search's exponents, ties
        /// included (the β it skips are strictly worse than β = 0).
        #[test]
        fn bounded_search_finds_the_best_exponents(
            v in proptest::collection::vec(proptest::option::weighted(0.85, 0usize..12), 5),
            sizes in proptest::collection::vec(0usize..60, 5),
            size_pi in 0usize..8,
        ) {
            let v: [Option<usize>; 5] = std::array::from_fn(|k| v[k]);
            proptest::prop_assume!(v.iter().any(Option::is_some));
            exponents_are_the_brute_forces(&v, &std::array::from_fn(|k| sizes[k]), size_pi)?;
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// The multiplicity of a small prime in a polynomial's content is
        /// the least count of it in a coefficient, counted one division
        /// at a time: with a shared power past a word (the remainder by
        /// `p^v`), within a word, or none, and with one coefficient
        /// holding fewer factors than the shortest.
        #[test]
        fn multiplicity_of_prime_counts_the_content(
            p in proptest::sample::select(vec![2u32, 3, 5, 7, 97]),
            shared in 0u32..90,
            cofactors in proptest::collection::vec(-10_000i64..10_000, 1..6),
            fewer in proptest::option::of((0usize..6, 0u32..90)),
        ) {
            let pi = Int::from(i64::from(p));
            let mut coeffs: Vec<Int> = cofactors.iter().map(|&c| Int::from(c) * pi.pow(shared)).collect();
            if let Some((k, e)) = fewer {
                let k = k % coeffs.len();
                coeffs[k] = Int::from(cofactors[k]) * pi.pow(e.min(shared));
            }
            let c = ZPoly::new(coeffs.clone());
            proptest::prop_assume!(!c.is_zero());
            let count = |x: &Int| {
                let (mut v, mut x) = (0, x.clone());
                while x.is_divisible_by(&pi) {
                    x = x.div_exact(&pi);
                    v += 1;
                }
                v
            };
            let expected = coeffs.iter().filter(|x| !x.is_zero()).map(count).min().unwrap_or(0);
            proptest::prop_assert_eq!(multiplicity_of_prime(&c, p), expected);
        }
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The same at the sizes of long scenes (multiplicities in the
        /// hundreds, coefficients of thousands of bits, word-long factors):
        /// `c_2`'s multiplicity low and the others' high, as with radii of
        /// `10⁻⁶⁴`, makes ranges of hundreds, where [`best_exponents`]
        /// tries only the candidates (the check of the candidates alone
        /// runs on every case).
        #[test]
        fn candidate_search_finds_the_best_exponents_of_long_scenes(
            v in proptest::strategy::Strategy::prop_map(
                proptest::collection::vec(proptest::option::weighted(0.9, 0usize..320), 5),
                |mut v| {
                    v[2] = v[2].map(|x| x % 20);
                    v
                },
            ),
            sizes in proptest::collection::vec(0usize..4000, 5),
            size_pi in 1usize..70,
        ) {
            let v: [Option<usize>; 5] = std::array::from_fn(|k| v[k]);
            proptest::prop_assume!(v.iter().any(Option::is_some));
            exponents_are_the_brute_forces(&v, &std::array::from_fn(|k| sizes[k]), size_pi)?;
        }
    }

    #[test]
    fn balancing_never_lengthens_the_longest_coefficient() {
        // Found by review: the rescaling that shortens sr0 (1,025 → 965
        // bits) would lengthen c_0 (302 → 312 bits), which the exact size
        // bound reads; f stays as it was.
        let c = |x: Int| ZPoly::constant(x);
        let two = Int::from(2);
        let f = [
            c(two.pow(30) * Int::from(9)),
            c(two.pow(20) * Int::from(7)),
            c(two.pow(10) * Int::from(5)),
            c(Int::from(3)),
            c(Int::from(3).pow(190) + Int::one()),
        ];
        let longest = |f: &[ZPoly; 5]| f.iter().map(ZPoly::max_bits).max().unwrap_or(0);
        let balanced = balance_primes(f.clone());
        assert!(longest(&balanced) <= longest(&f));
    }

    #[test]
    fn refinement_stops_at_its_budget() {
        let n = |x: i64| Int::from(x);
        // 12 = 2²·3 and 18 = 2·3²: bases {2, 3} within a few gcds.
        let basis = refine_coprime(
            vec![n(12), n(18)],
            |x: &Int| x.bits() >= 2,
            Int::gcd,
            Int::div_exact,
            50,
        );
        let mut basis = basis.expect("within the budget");
        basis.sort_by_key(|x| x.to_i64());
        assert_eq!(basis, vec![n(2), n(3)]);
        // An exponent chain 2^40·3, 2^39·3 needs about 40 splits.
        let chain = vec![n(2).pow(40) * n(3), n(2).pow(39) * n(3)];
        assert!(
            refine_coprime(chain, |x: &Int| x.bits() >= 2, Int::gcd, Int::div_exact, 20).is_none()
        );
    }

    #[test]
    fn long_constant_scalings_are_taken_out() {
        // c_k = M89^k·M107^(4 − k)·g_k (k the power of λ) with two
        // Mersenne primes: a rescaling of λ by M89/M107 that no small
        // prime shows, and that balance_primes leaves.
        let (m89, m107) = (
            Int::from(2).pow(89) - Int::one(),
            Int::from(2).pow(107) - Int::one(),
        );
        let g = [
            ZPoly::from_i64s(&[4, -3, 1]),
            ZPoly::from_i64s(&[1, 1]),
            ZPoly::from_i64s(&[-6, 0, 5]),
            ZPoly::from_i64s(&[2, 7]),
            ZPoly::from_i64s(&[9, -2]),
        ];
        let f: [ZPoly; 5] = std::array::from_fn(|i| {
            let k = 4 - i as u32;
            g[i].mul_int(&(m89.pow(k) * m107.pow(4 - k)))
        });
        assert_eq!(balance_primes(f.clone()), f);
        let balanced = CharPoly { coeffs: f.clone() }.without_constant_scalings();
        assert_eq!(balanced.coeffs, g);
        // With a common factor M107 in every c_k too: g again, and a
        // positive multiple of a λ-rescaling of f.
        let f2: [ZPoly; 5] = std::array::from_fn(|i| f[i].mul_int(&m107));
        let f2 = CharPoly { coeffs: f2 };
        let balanced = f2.clone().without_constant_scalings();
        assert!(same_up_to_constant_scalings(&f2, &balanced));
        assert_eq!(balanced.coeffs, g);
        // A word-sized factor alone (the valuation's path): 1000003^k.
        let w = Int::from(1_000_003);
        let f3: [ZPoly; 5] = std::array::from_fn(|i| g[i].mul_int(&w.pow(4 - i as u32)));
        let balanced = CharPoly { coeffs: f3 }.without_constant_scalings();
        assert_eq!(balanced.coeffs, g);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// Balancing multiplies `c_k` by `κ·σ^k` with positive constants
        /// (every sign Theorem 3.10 reads, every root in λ up to the
        /// positive factor σ) and never lengthens `sr0`; on planted powers
        /// of small primes in κ and σ (beyond `i128`; 47 and 97 are the
        /// ends of the two prime words) it shortens it once
        /// the `c_k` are more than `BALANCE_SPREAD` bits apart, and leaves
        /// `f` alone below that.
        #[test]
        fn balancing_only_rescales_and_shortens_sr0(
            g in proptest::collection::vec(proptest::collection::vec(-9i64..10, 1..4), 5),
            kappa in proptest::collection::vec(0u32..40, 5),
            sigma in proptest::collection::vec(0u32..40, 5),
        ) {
            proptest::prop_assume!(g.iter().all(|c| c.iter().any(|&x| x != 0)));
            let primes = [2i64, 5, 41, 47, 97].map(Int::from);
            let power = |e: &[u32], k: u32| {
                primes.iter().zip(e).fold(Int::one(), |acc, (p, &e)| acc * p.pow(e * k))
            };
            // A long factor no small prime divides keeps f past i128.
            let long = Int::from(1_000_003).pow(12);
            let f: [ZPoly; 5] = std::array::from_fn(|i| {
                let k = 4 - i as u32;
                let scale = power(&kappa, 1) * power(&sigma, k) * long.clone();
                ZPoly::from_i64s(&g[i]).mul_int(&scale)
            });
            let bits: Vec<u64> = f.iter().map(ZPoly::max_bits).collect();
            let spread = bits.iter().max().unwrap() - bits.iter().min().unwrap();
            let balanced = balance_primes(f.clone());
            let (f, balanced) = (CharPoly { coeffs: f }, CharPoly { coeffs: balanced });
            proptest::prop_assert!(same_up_to_constant_scalings(&f, &balanced));
            let sr0 = |c: &CharPoly| sr0_bits(&c.coeffs);
            proptest::prop_assert!(sr0(&balanced) <= sr0(&f));
            // Past the spread the rescaling of λ runs and pays.
            if spread > BALANCE_SPREAD && sigma.iter().any(|&e| e > 0) {
                proptest::prop_assert!(sr0(&balanced) < sr0(&f));
            } else if spread <= BALANCE_SPREAD {
                proptest::prop_assert_eq!(&balanced, &f);
            }
        }
    }

    /// Bits of `sr0` (the discriminant's closed form) of `f`.
    fn sr0_bits(f: &[ZPoly; 5]) -> u64 {
        ccd_subres::closed_form(f, ccd_subres::Quantity::Sr0)
            .expect("sr0 has a closed form")
            .max_bits()
    }

    #[test]
    fn yun_splits_multiplicities() {
        let a = ZPoly::from_i64s(&[-1, 1]); // u - 1
        let b = ZPoly::from_i64s(&[2, 1]); // u + 2
        let p = &(&a.pow(3) * &b.pow(2)) * &ZPoly::from_i64s(&[1, 0, 1]);
        let f = squarefree_factors(&p);
        assert_eq!(f.len(), 3);
        assert!(f.contains(&(ZPoly::from_i64s(&[1, 0, 1]), 1)));
        assert!(f.contains(&(b.clone(), 2)));
        assert!(f.contains(&(a.clone(), 3)));
    }

    #[test]
    fn rescaling_removes_hidden_lambda_scale() {
        // c_k = s^k · g_k with s = u² + 1: the λ-rescaling must undo it.
        let s = ZPoly::from_i64s(&[1, 0, 1]);
        let g = [
            ZPoly::from_i64s(&[3]),
            ZPoly::from_i64s(&[1, 1]),
            ZPoly::from_i64s(&[2, 0, 1]),
            ZPoly::from_i64s(&[5, 1]),
            ZPoly::from_i64s(&[-7]),
        ];
        let f: [ZPoly; 5] = std::array::from_fn(|i| &g[i] * &s.pow((4 - i) as u32));
        let n = normalise(f);
        assert_eq!(n, g);
    }

    #[test]
    fn scaled_evaluation_is_a_positive_multiple() {
        let f = CharPoly {
            coeffs: [
                ZPoly::from_i64s(&[3]),
                ZPoly::from_i64s(&[1, -4]),
                ZPoly::from_i64s(&[2, 0, 1]),
                ZPoly::from_i64s(&[5, 1]),
                ZPoly::from_i64s(&[-7, 0, 0, 2]),
            ],
        };
        for u in [
            Rat::from_frac(1, 3),
            Rat::from_frac(-5, 7),
            Rat::from(2),
            Rat::zero(),
        ] {
            let exact = f.at(&u);
            let scaled = f.at_scaled(&u);
            let factor = u.denom().pow(3);
            for (e, s) in exact.iter().zip(&scaled) {
                assert_eq!(
                    &(e * &Rat::from_int(factor.clone())),
                    &Rat::from_int(s.clone())
                );
            }
        }
    }
}
