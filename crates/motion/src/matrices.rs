//! Placements `M(u)` (body → world) and moving quadric matrices
//! `A(u) ∝ N(u)ᵀ·D·N(u)` (`N ∝ M⁻¹`) with integer polynomial entries in
//! `u ∈ [0, 1]`, built from a motion and validated exactly.

use crate::centred::{Centred, CentredInteger};
use crate::curve::{
    common_denominator, content, times_denominator, to_poly_curve, Integer, PolyCurve,
};
use crate::error::MotionError;
use crate::kinds::{Bezier, Body, Motion, Quat, Vec3};
use ccd_arith::{Int, Rat, RingOps, SmallInt};
use ccd_poly::{SmallPoly, ZPoly};
use ccd_quadric::{
    affine_inverse, affine_placement, body_diagonal, characteristic, congruence, det3, norm2,
    placed_characteristic, rigid_inverse, rigid_placement, rotation_numerator, Mat3, Mat4,
    RigidFrame,
};

/// The first root of `p` in `[0, 1]`, mapped to `t` (approximately), if any.
fn first_root_in_span(p: &ZPoly, span: &[Rat; 2]) -> Option<f64> {
    if p.is_zero() {
        return Some(span[0].to_f64());
    }
    if p.degree() == Some(0) {
        return None; // a nonzero constant (a curve without weights)
    }
    // Bernstein coefficients on [0, 1] all of one strict sign: `p` is
    // of that sign on the whole of [0, 1] (they bound it, and the first and
    // last are p(0) and p(1)), so there is no root, and no squarefree part
    // or isolation is needed (the usual weight, positive throughout).
    let signs = ccd_poly::Bernstein::signs_of_power(p, &Rat::zero(), &Rat::one());
    if signs.iter().all(|&s| s == signs[0]) && signs[0] != 0 {
        return None;
    }
    let mut roots = ccd_solver::isolate(p, &Rat::zero(), &Rat::one()).ok()?;
    let r = roots.next()?;
    let u = r.midpoint();
    Some((&span[0] + &(&u * &(&span[1] - &span[0]))).to_f64())
}

/// A rational placement `X = R·Xbody + C/w` (rigid, `R = M/n`) or
/// `X = (L·Xbody + d)/w` (affine), with entries in ℤ[u] (or their values at
/// one `u`).
///
/// # Integer frames
///
/// The matrices a frame gives are only ever used up to a positive factor
/// (made primitive, [`primitive_matrix`]), and scaling `(M, n)` by one
/// positive constant and `(C, w)` by another (rigid), or `(L, d, w)` by one
/// (affine), scales [`Frame::forward`] and [`Frame::inverse`] by a positive
/// constant. So a motion's rational data is brought to integers once, by
/// such scalings (a quaternion `q` by the lcm `L` of its denominators gives
/// `M(Lq) = L²·M(q)`, `|Lq|² = L²·|q|²`), and everything after runs in ℤ[u].
#[derive(Clone, Debug, PartialEq)]
enum Frame<P> {
    Rigid {
        m: Mat3<P>,
        n: P,
        center: [P; 3],
        w: P,
    },
    Affine {
        l: Mat3<P>,
        d: [P; 3],
        w: P,
    },
}

impl<P: RingOps> Frame<P> {
    /// The homogeneous body → world matrix, up to a factor nonzero on the span.
    fn forward(&self) -> Mat4<P> {
        match self {
            Frame::Rigid { m, n, center, w } => rigid_placement(m, n, center, w),
            Frame::Affine { l, d, w } => affine_placement(l, d, w),
        }
    }

    /// The world → body matrix `N ∝ M⁻¹`, up to a factor nonzero on the span.
    fn inverse(&self) -> Mat4<P> {
        match self {
            Frame::Rigid { m, n, center, w } => rigid_inverse(m, n, center, w),
            Frame::Affine { l, d, w } => affine_inverse(l, d, w),
        }
    }

    /// Every entry.
    fn entries(&self) -> impl Iterator<Item = &P> {
        let (m, v, n, w) = match self {
            Frame::Rigid { m, n, center, w } => (m, center, Some(n), w),
            Frame::Affine { l, d, w } => (l, d, None, w),
        };
        m.iter()
            .flatten()
            .chain(v)
            .chain(n)
            .chain(std::iter::once(w))
    }

    /// Every entry, mutably, in the order of [`Frame::entries`].
    fn entries_mut(&mut self) -> impl Iterator<Item = &mut P> {
        let (m, v, n, w) = match self {
            Frame::Rigid { m, n, center, w } => (m, center, Some(n), w),
            Frame::Affine { l, d, w } => (l, d, None, w),
        };
        m.iter_mut()
            .flatten()
            .chain(v)
            .chain(n)
            .chain(std::iter::once(w))
    }

    /// Every entry mapped by `f`.
    fn map<Q>(&self, f: impl Fn(&P) -> Q) -> Frame<Q> {
        let m3 = |m: &Mat3<P>| m.each_ref().map(|row| row.each_ref().map(&f));
        match self {
            Frame::Rigid { m, n, center, w } => Frame::Rigid {
                m: m3(m),
                n: f(n),
                center: center.each_ref().map(&f),
                w: f(w),
            },
            Frame::Affine { l, d, w } => Frame::Affine {
                l: m3(l),
                d: d.each_ref().map(&f),
                w: f(w),
            },
        }
    }
}

impl Frame<ZPoly> {
    /// Degree bounds `(forward, inverse)` of the matrices above, from the
    /// entries' degrees (no products formed).
    fn degree_bounds(&self) -> (usize, usize) {
        let deg = |p: &ZPoly| p.degree().unwrap_or(0);
        let max3 = |m: &Mat3<ZPoly>| m.iter().flatten().map(deg).max().unwrap_or(0);
        let maxv = |v: &[ZPoly; 3]| v.iter().map(deg).max().unwrap_or(0);
        match self {
            Frame::Rigid { m, n, center, w } => {
                let (m, n, c, w) = (max3(m), deg(n), maxv(center), deg(w));
                ((w + m).max(n + c).max(n + w), (w + m).max(m + c).max(n + w))
            }
            Frame::Affine { l, d, w } => {
                let (l, d, w) = (max3(l), maxv(d), deg(w));
                (l.max(d).max(w), (w + 2 * l).max(2 * l + d).max(3 * l))
            }
        }
    }
}

/// The placement of a body as an integer frame (see [`Frame`]), validated
/// exactly on the span, and the polynomials whose powers make up its
/// determinant (the weight curve, and `|q|²` or `det L`): the only factors
/// `det A` can have.
fn frame(motion: &Motion, span: &[Rat; 2]) -> Result<(Frame<ZPoly>, Vec<ZPoly>), MotionError> {
    // A constant orientation: the rotation of the integer quaternion `L·q`
    // over ℤ (in i128 where it fits: `small_first`; the polynomial
    // `rotation` costs 8–14K more instructions a query on `rigid-deg2` and
    // Example 5.1), then as constants.
    let fixed = |q: &Quat, center: [ZPoly; 3], w: ZPoly| {
        let q: [Int; 4] = rat_vec_to_int(q.each_ref());
        let small = q.each_ref().map(SmallInt::of);
        // M(q)'s nine entries row by row, then |q|².
        fn entries<R: RingOps>(q: &[R; 4]) -> [R; 10] {
            let [[a, b, c], [d, e, f], [g, h, i]] = rotation_numerator(q);
            [a, b, c, d, e, f, g, h, i, norm2(q)]
        }
        let [m0, m1, m2, m3, m4, m5, m6, m7, m8, n] =
            small_first(|| entries(&small), || entries(&q)).map(ZPoly::constant);
        Frame::Rigid {
            m: [[m0, m1, m2], [m3, m4, m5], [m6, m7, m8]],
            n,
            center,
            w,
        }
    };
    for (points, weights) in motion.curve_shapes() {
        if points == 0 || weights.is_some_and(|w| w != points) {
            return Err(MotionError::MalformedCurve {
                points,
                weights: weights.unwrap_or(points),
            });
        }
    }
    let check_weight = |w: &ZPoly| match first_root_in_span(&w.primitive_part(), span) {
        Some(at) => Err(MotionError::WeightVanishes { at }),
        None => Ok(()),
    };
    match motion {
        Motion::Static {
            center,
            orientation,
        } => {
            // (C, 1) times the lcm of the denominators.
            let one = Rat::one();
            let [x, y, z, w] = rat_vec_to_int::<Int, 4>([&center[0], &center[1], &center[2], &one])
                .map(ZPoly::constant);
            Ok((fixed(orientation, [x, y, z], w), vec![]))
        }
        Motion::Translation {
            center,
            orientation,
        } => {
            let c = to_poly_curve(center);
            check_weight(&c.denominator)?;
            let w = c.denominator.clone();
            Ok((fixed(orientation, c.numerators, c.denominator), vec![w]))
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            let q = quaternion_curve(orientation);
            let common = q.iter().fold(ZPoly::zero(), |g, c| g.gcd(c));
            if common.degree().unwrap_or(0) >= 1 || q.iter().all(ZPoly::is_zero) {
                if let Some(at) = first_root_in_span(&common, span) {
                    return Err(MotionError::QuaternionVanishes { at });
                }
            }
            let c = to_poly_curve(center);
            check_weight(&c.denominator)?;
            // |q|² formed once, with the rotation.
            let (m, n) = rotation(&q);
            let factors = vec![c.denominator.clone(), n.clone()];
            let (center, w) = (c.numerators, c.denominator);
            Ok((Frame::Rigid { m, n, center, w }, factors))
        }
        Motion::Affine { matrix } => {
            // The twelve entries as one curve: one weight polynomial.
            let curve = matrix.flattened();
            let PolyCurve {
                numerators: entries,
                denominator: w,
            } = to_poly_curve(&curve);
            let poly = |r: usize, k: usize| entries[4 * r + k].clone();
            let l: Mat3<ZPoly> = std::array::from_fn(|r| std::array::from_fn(|k| poly(r, k)));
            let d: [ZPoly; 3] = std::array::from_fn(|r| poly(r, 3));
            check_weight(&w)?;
            let det_l = small_det3(&l);
            if let Some(at) = first_root_in_span(&det_l.primitive_part(), span) {
                return Err(MotionError::SingularAffine { at });
            }
            let factors = vec![w.clone(), det_l];
            Ok((Frame::Affine { l, d, w }, factors))
        }
        Motion::Helical { .. } => Err(MotionError::NotRational { kind: "helical" }),
    }
}

/// `det L` of a matrix of polynomials: in i128 ([`SmallPoly`], lifted
/// back) when the numbers fit, else over [`ZPoly`]; the same polynomial.
fn small_det3(l: &Mat3<ZPoly>) -> ZPoly {
    let small = l
        .each_ref()
        .map(|row| row.each_ref().map(SmallPoly::lowered));
    det3(&small).to_zpoly().unwrap_or_else(|| det3(l))
}

/// `(M(q), |q|²)` of a quaternion curve: in i128 ([`SmallPoly`], lifted
/// back) when the numbers fit, else over [`ZPoly`]; the same polynomials.
fn rotation(q: &[ZPoly; 4]) -> (Mat3<ZPoly>, ZPoly) {
    let small = q.each_ref().map(SmallPoly::lowered);
    let m: Option<Vec<ZPoly>> = rotation_numerator(&small)
        .iter()
        .flatten()
        .map(SmallPoly::to_zpoly)
        .collect();
    match (m, norm2(&small).to_zpoly()) {
        (Some(m), Some(n)) => {
            let mut m = m.into_iter();
            let m =
                std::array::from_fn(|_| std::array::from_fn(|_| m.next().expect("nine entries")));
            (m, n)
        }
        _ => (rotation_numerator(q), norm2(q)),
    }
}

fn quaternion_curve(curve: &Bezier<Quat>) -> [ZPoly; 4] {
    // The rotation of q is that of any positive multiple, so the weight
    // curve's denominator drops out; the weights stay in the numerators.
    to_poly_curve(curve).numerators
}

/// The matrix divided by the gcd of all its coefficients: the positive
/// multiple of a frame's matrix with integer polynomial entries and no
/// common integer factor (a constant factor `c` of a placement would
/// rescale λ by `c²` and grow every coefficient). It does not depend on the
/// scaling of the frame ([`Frame`]).
fn primitive_matrix(n: Mat4<ZPoly>) -> Mat4<ZPoly> {
    let g = n.iter().flatten().fold(Int::zero(), |g, e| {
        if g.is_one() {
            g
        } else {
            g.gcd(&e.content())
        }
    });
    if g.is_zero() || g.is_one() {
        return n;
    }
    n.map(|row| row.map(|e| e.div_exact_int(&g)))
}

/// Integers computed in `i128` ([`SmallInt`], overflow detected) when
/// every one fits, else over [`Int`]: the same integers, without
/// big-integer arithmetic on the usual short numbers.
pub(crate) fn small_first<const N: usize>(
    small: impl FnOnce() -> [SmallInt; N],
    big: impl FnOnce() -> [Int; N],
) -> [Int; N] {
    let lifted: Option<Vec<Int>> = small().iter().map(SmallInt::to_int).collect();
    match lifted.map(<[Int; N]>::try_from) {
        Some(Ok(x)) => x,
        _ => big(),
    }
}

/// `v` times the lcm of its denominators.
fn rat_vec_to_int<I: Integer, const N: usize>(v: [&Rat; N]) -> [I; N] {
    let den = common_denominator(v);
    v.map(|x| times_denominator(x, &den))
}

/// `v` over one denominator: `(n, L)` with `v = n/L` and `L` the lcm of
/// `v`'s denominators, in `i128`; `None` when a number does not fit (the
/// caller then encloses `v` otherwise).
///
/// ```
/// use ccd_arith::Rat;
/// let v = [Rat::from_frac(1, 4), Rat::from_frac(-5, 6), Rat::from(2)];
/// let (n, l) = ccd_motion::matrices::small_over_common_denominator(v.each_ref()).unwrap();
/// assert_eq!((n, l), ([3, -10, 24], 12));
/// ```
///
/// Numerators and denominators must fit `i64` and the lcm too (the short
/// numbers of a scene): word operations only, no big-integer steps.
pub fn small_over_common_denominator<const N: usize>(v: [&Rat; N]) -> Option<([i128; N], i128)> {
    let mut parts = [(0i64, 1i64); N];
    for (p, x) in parts.iter_mut().zip(v) {
        *p = (x.numer().to_i64()?, x.denom().to_i64()?);
    }
    // Denominators are positive; the lcm skips those it already holds.
    let mut den = 1i64;
    for &(_, d) in &parts {
        if den % d != 0 {
            let g = ccd_arith::gcd_u128(den as u128, d as u128) as i64;
            den = (den / g).checked_mul(d)?;
        }
    }
    // |n| <= 2^63 and den/d < 2^63: the product fits.
    Some((
        parts.map(|(n, d)| i128::from(n) * i128::from(den / d)),
        i128::from(den),
    ))
}

/// `body_diagonal(radii)` times the lcm of its entries' denominators, in
/// integers only. With `rᵢ = nᵢ/dᵢ`, `M = (d₀d₁d₂)²` is a common
/// denominator of the entries `e`, and `E = M·e` is `body_diagonal` of the
/// numerators with row `i < 3` times `dᵢ²`:
/// `[(d₀n₁n₂)², (n₀d₁n₂)², (n₀n₁d₂)², −(n₀n₁n₂)²]`. The integers `t` with
/// `t·e` integral are the multiples of the lcm `L` of the reduced
/// denominators, and `L | M`; so `L = M/k` for the largest `k` dividing `M`
/// and every `Eⱼ`, `k = gcd(M, E)`, and the result `L·e` is `E/k`.
fn integer_diagonal<I: Integer>(radii: &[Rat; 3]) -> [I; 4] {
    let e = body_diagonal(&radii.each_ref().map(|r| I::of(r.numer())));
    let [d0, d1, d2] = radii.each_ref().map(|r| I::of(r.denom()));
    let m = d0.times(&d1).times(&d2);
    let squares = [d0, d1, d2].map(|d| d.times(&d));
    let scaled: [I; 4] = std::array::from_fn(|i| match squares.get(i) {
        Some(s) if !s.is_one() => e[i].times(s),
        _ => e[i].clone(),
    });
    let mm = m.times(&m);
    let k = content(std::iter::once(&mm).chain(&scaled));
    if k.is_one() {
        return scaled;
    }
    scaled.map(|x| x.div_exact(&k))
}

/// The quadric of a static body (radii, centre, orientation quaternion)
/// over `I`: the constant matrix [`PlacedQuadric::quadric`] gives, formed
/// without polynomials. The frame of [`frame`] (the quaternion and
/// `(C, 1)` each times the lcm of its denominators), its inverse
/// `rigid_inverse(M(q), |q|², C, w)` divided by the gcd of its entries
/// (what [`primitive_matrix`] does to constants), then `NᵀDN` with the
/// integer body diagonal.
pub(crate) fn static_quadric<I: Integer>(radii: &[Rat; 3], center: &Vec3, q: &Quat) -> Mat4<I> {
    let q: [I; 4] = rat_vec_to_int(q.each_ref());
    let one = Rat::one();
    let [x, y, z, w] = rat_vec_to_int([&center[0], &center[1], &center[2], &one]);
    let n = rigid_inverse(&rotation_numerator(&q), &norm2(&q), &[x, y, z], &w);
    congruence(&primitive_constant(n), &integer_diagonal(radii))
}

/// The shape matrix `P = R(q)·diag(r²)·R(q)ᵀ` of a body that does not
/// turn — centred at the origin it is `{x : xᵀP⁻¹x <= 1}`, with support
/// function `√(nᵀPn)` — exactly, as `P = S/d` with `S` an integer matrix
/// and `d > 0`, computed in `i128`. With `q'` the quaternion times the lcm
/// of its denominators (`R(q') = M(q')/|q'|² = R(q)`) and `m = L·r` for
/// `L` the lcm of the radii's denominators,
/// `S = M(q')·diag(m²)·M(q')ᵀ` and `d = |q'|⁴·L²`. `None` when a number on
/// the way does not fit `i128` (long numbers: the caller encloses `P`
/// otherwise).
///
/// ```
/// use ccd_arith::Rat;
/// // Radii 1/2, 1, 3 turned by a quarter turn about z: P = diag(1, 1/4, 9).
/// let r = [Rat::from_frac(1, 2), Rat::from(1), Rat::from(3)];
/// let q = [1, 0, 0, 1].map(Rat::from);
/// let (s, d) = ccd_motion::matrices::shape_small(&r, &q).unwrap();
/// let p = |x: i128| Rat::from_frac(x as i64, d as i64);
/// assert_eq!([p(s[0][0]), p(s[1][1]), p(s[2][2])],
///            [Rat::from(1), Rat::from_frac(1, 4), Rat::from(9)]);
/// assert_eq!(s[0][1], 0);
/// ```
pub fn shape_small(radii: &[Rat; 3], q: &Quat) -> Option<(Mat3<i128>, i128)> {
    let (q, _) = small_over_common_denominator(q.each_ref())?;
    let (m, den) = small_over_common_denominator(radii.each_ref())?;
    let (q, m, den) = (
        q.map(SmallInt::from_i128),
        m.map(SmallInt::from_i128),
        SmallInt::from_i128(den),
    );
    let rot = rotation_numerator(&q);
    let transposed: Mat3<SmallInt> = std::array::from_fn(|k| std::array::from_fn(|i| rot[i][k]));
    let s = congruence(&transposed, &m.map(|x| x.times(&x)));
    let n2 = norm2(&q);
    let d = n2.times(&n2).times(&den).times(&den).to_i128()?;
    let mut out = [[0i128; 3]; 3];
    for (o, e) in out.iter_mut().flatten().zip(s.iter().flatten()) {
        *o = e.to_i128()?;
    }
    Some((out, d))
}

/// A constant matrix divided by the gcd of its entries: what
/// [`primitive_matrix`] does to constant polynomials.
fn primitive_constant<I: Integer>(n: Mat4<I>) -> Mat4<I> {
    let g = content(n.iter().flatten());
    if g.is_zero() || g.is_one() {
        return n;
    }
    n.map(|row| row.map(|e| e.div_exact(&g)))
}

/// A placed body: its placement, its body quadric and what is known about
/// the determinant of the placement. The integer matrices are formed only
/// when asked for (each route to `f` needs one of them).
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedQuadric {
    frame: Frame<ZPoly>,
    /// The body quadric `diag(D)` (interior `XᵀDX < 0`), scaled to integers.
    pub diagonal: [ZPoly; 4],
    /// The body's radii, for [`PlacedQuadric::diagonal_products`].
    radii: [Rat; 3],
    /// Primitive polynomials nonzero on the span such that `det M(u)` is a
    /// constant times a product of their powers.
    pub det_factors: Vec<ZPoly>,
}

impl PlacedQuadric {
    /// The homogeneous body → world matrix `M(u)` with integer polynomial
    /// entries, up to a factor nonzero on the span.
    pub fn placement(&self) -> Mat4<ZPoly> {
        primitive_matrix(self.frame.forward())
    }

    /// The products `D(S)` of [`ccd_quadric::subset_products`] for the body quadric
    /// `D̃ = diag(1/r₀², 1/r₁², 1/r₂², −1)` (over ℚ) times `(n₀n₁n₂)²`:
    /// with `rᵢ = nᵢ/dᵢ` in lowest terms,
    /// `D(S) = ±Π_(i ∈ S) dᵢ²·Π_(i ∉ S) nᵢ²` (`i < 3`; negative iff
    /// `3 ∈ S`). The integer diagonal [`PlacedQuadric::diagonal`] is
    /// `(n₀n₁n₂)²·D̃` up to a constant, whose products carry
    /// `(n₀n₁n₂)^(2(|S| − 1))` more: a rescaling of λ
    /// ([`ccd_quadric::placed_characteristic`]) that the normalisation's content removal
    /// cannot take out when the `nᵢ` are long primes
    /// (`bench-perturbed-affine-deg2-d0100`: 100-digit radii, `f` of 6,700
    /// bits per coefficient after normalisation, 4,030 without it).
    ///
    /// Each table is further divided by `c^(a(S))`, `c = g²` for `g` a
    /// common divisor of every `dᵢ` of both bodies ([`shared_denominator`])
    /// and `a(S) = |S ∖ {3}|` the number of axes in `S`, and multiplied by
    /// `c` when `3 ∉ S` unless `affine`: `±Π_(i∈S) (dᵢ/g)²·Π_(i∉S) nᵢ²`,
    /// an integer. Every Cauchy–Binet term of
    /// [`ccd_quadric::placed_characteristic`] multiplies the tables of
    /// `S_A = A ∖ T` and `S_B = B ∖ T`, `|S_A| + |S_B| = 4`:
    /// * without `affine` each term is divided by `c^(4 − m)·c^(−(2 − m)) = c²`,
    ///   `m` the number of homogeneous columns in `S_A, S_B` (`a = |S| − [3 ∈ S]`);
    /// * with `affine` (both placements [`ccd_quadric::is_affine_placement`],
    ///   whose terms with `m = 2` vanish, and the sum's `both = c`) by
    ///   `c^(4 − m)` times `c` when `m = 0`: `c³` for every nonzero term.
    ///
    /// Either way `f` becomes `f/c²` or `f/c³`, a positive constant factor
    /// that the normalisation's content removal takes out (the same
    /// normalised `f`, bit for bit), and [`characteristic_at`]'s signs are
    /// unchanged. Decimal radii share powers of ten: those of
    /// `bench-perturbed-affine-deg2-d0100` put `2^598·3²·5^600` (1,995 bits,
    /// about `c³`) into the content of `f`, carried through every long
    /// product before.
    /// Over `I` (an `i128` overflow marks the entries, as everywhere).
    pub(crate) fn diagonal_products<I: Integer>(&self, g: &Int, affine: bool) -> [I; 16] {
        let square = |x: &Int| {
            let x = I::of(x);
            x.times(&x)
        };
        let n = self.radii.each_ref().map(|r| square(r.numer()));
        let d = self.radii.each_ref().map(|r| {
            if g.is_one() {
                square(r.denom())
            } else {
                square(&r.denom().div_exact(g))
            }
        });
        let body: [I; 8] = std::array::from_fn(|s| {
            (0..3).fold(I::one(), |p, i| {
                p.times(if s >> i & 1 == 1 { &d[i] } else { &n[i] })
            })
        });
        let c = (!g.is_one() && !affine).then(|| square(g));
        std::array::from_fn(|s| match (s & 8 == 0, &c) {
            (true, Some(c)) => body[s].times(c),
            (true, None) => body[s].clone(),
            (false, _) => body[s & 7].negated(),
        })
    }

    /// The world → body matrix `N(u) ∝ M(u)⁻¹` with integer polynomial
    /// entries, up to a factor nonzero on the span.
    pub fn inverse(&self) -> Mat4<ZPoly> {
        primitive_matrix(self.frame.inverse())
    }

    /// [`PlacedQuadric::quadric`] with `i128` coefficients ([`SmallPoly`]),
    /// or `None` if a number on the way does not fit: the same matrix (the
    /// inverse placement made primitive, then `NᵀDN`), without big-integer
    /// arithmetic.
    pub fn quadric_small(&self) -> Option<Mat4<SmallPoly>> {
        if self.degree_bounds() == (0, 0) {
            // A constant frame (a static body): the same matrix over
            // `i128` numbers rather than constant polynomials.
            let constant = |p: &ZPoly| SmallInt::of(&p.coeff(0));
            let n = primitive_constant(self.frame.map(constant).inverse());
            let q = congruence(&n, &self.diagonal.each_ref().map(constant));
            return q
                .iter()
                .flatten()
                .all(|e| e.to_i128().is_some())
                .then(|| q.map(|row| row.map(|e| SmallPoly::constant(&e))));
        }
        // The entries lowered in place (288-byte values).
        let mut small = self.frame.map(|_| SmallPoly::zero());
        for (slot, p) in small.entries_mut().zip(self.frame.entries()) {
            slot.set_lowered(p);
        }
        let mut n = small.inverse();
        let g = n.iter().flatten().try_fold(0, |g, e| e.gcd_with(g))?;
        if g > 1 {
            let g = i64::try_from(g).ok()?;
            // In place: the entries are 288-byte values.
            for e in n.iter_mut().flatten() {
                e.div_exact_int_assign(g.into());
            }
        }
        let q = congruence(&n, &self.diagonal.each_ref().map(SmallPoly::lowered));
        q.iter().flatten().all(SmallPoly::is_exact).then_some(q)
    }

    /// Whether the frame is rigid (`X = (M/n)·Y + C/w`), not affine.
    pub(crate) fn is_rigid(&self) -> bool {
        matches!(self.frame, Frame::Rigid { .. })
    }

    /// The numbers of a rigid frame (`X = (M/n)·Y + C/w`), each mapped by
    /// `lower`; `None` for an affine one.
    pub(crate) fn rigid_frame<P>(&self, lower: impl Fn(&ZPoly) -> P) -> Option<RigidFrame<P>> {
        let Frame::Rigid { m, n, center, w } = &self.frame else {
            return None;
        };
        Some(RigidFrame {
            m: m.each_ref().map(|row| row.each_ref().map(&lower)),
            n: lower(n),
            center: center.each_ref().map(&lower),
            w: lower(w),
        })
    }

    /// The numbers of a rigid frame at the integers `first`, `first + 1`,
    /// …, (`count` of them) in `i128`: each polynomial's coefficients
    /// brought to `i128` once and evaluated by Horner (checked). `None` for
    /// an affine frame or when a number does not fit.
    pub(crate) fn rigid_frame_values(
        &self,
        first: i64,
        count: usize,
    ) -> Option<Vec<RigidFrame<i128>>> {
        let Frame::Rigid { .. } = &self.frame else {
            return None;
        };
        let zero = RigidFrame {
            m: [[0; 3]; 3],
            n: 0,
            center: [0; 3],
            w: 0,
        };
        let mut out = vec![zero; count];
        // Frame::entries' order: M row by row, C, n, w.
        fn slot(f: &mut RigidFrame<i128>, k: usize) -> &mut i128 {
            match k {
                0..9 => &mut f.m[k / 3][k % 3],
                9..12 => &mut f.center[k - 9],
                12 => &mut f.n,
                _ => &mut f.w,
            }
        }
        let mut c = [0i128; SmallPoly::MAX_DEGREE + 1];
        let last = first + count as i64 - 1;
        let u_bits = 64
            - first
                .unsigned_abs()
                .max(last.unsigned_abs())
                .leading_zeros();
        for (k, p) in self.frame.entries().enumerate() {
            let len = p.coeffs().len();
            if len > c.len() {
                return None;
            }
            let mut c_bits = 0;
            for (x, y) in c.iter_mut().zip(p.coeffs()) {
                *x = y.to_i128()?;
                c_bits = c_bits.max(128 - x.unsigned_abs().leading_zeros());
            }
            // Plain machine arithmetic when |Σ c_i·u^i| < 2^126 along the
            // way (|c_i| < 2^c_bits, |u| < 2^u_bits, len terms); checked
            // otherwise.
            let plain = c_bits + u_bits * len as u32 + len as u32 <= 126;
            for (i, f) in out.iter_mut().enumerate() {
                let u = i128::from(first + i as i64);
                let mut terms = c[..len].iter().rev();
                *slot(f, k) = if plain {
                    terms.fold(0i128, |v, &x| v * u + x)
                } else {
                    terms.try_fold(0i128, |v, &x| v.checked_mul(u)?.checked_add(x))?
                };
            }
        }
        Some(out)
    }

    /// The integer content of the frame's inverse before
    /// [`primitive_matrix`]: [`PlacedQuadric::inverse`] times it is
    /// `rigid_inverse(M, n, C, w)` (`1` for an affine frame, which is not
    /// asked). By Gauss's lemma the contents of `w·Mᵀ` and `w·n` are
    /// products of contents; only the column `−Mᵀ·C` is formed, and only
    /// when those leave a common factor.
    pub(crate) fn inverse_content(&self) -> Int {
        let Frame::Rigid { m, n, center, w } = &self.frame else {
            return Int::one();
        };
        // One pass over M's coefficients, stopping at 1.
        let g = ZPoly::common_content(m.as_flattened());
        let g = if g.is_one() { g } else { g.gcd(&n.content()) };
        let g = g * w.content();
        if g.is_one() {
            return g;
        }
        (0..3).fold(g, |g, i| {
            if g.is_one() {
                return g;
            }
            let column = (0..3).fold(ZPoly::zero(), |s, k| &s + &(&m[k][i] * &center[k]));
            if column.is_zero() {
                g
            } else {
                g.gcd(&column.content())
            }
        })
    }

    /// The integer content of `n·w` (a rigid frame; `1` for an affine
    /// one): `cont(n)·cont(w)` by Gauss's lemma.
    pub(crate) fn rotation_content(&self) -> Int {
        match &self.frame {
            Frame::Rigid { n, w, .. } => n.content() * w.content(),
            Frame::Affine { .. } => Int::one(),
        }
    }

    /// `diag(1/r₀², 1/r₁², 1/r₂², −1)`, the body quadric over ℚ.
    pub(crate) fn rational_diagonal(&self) -> [Rat; 4] {
        let inverse_square = |r: &Rat| &Rat::one() / &(r * r);
        let [a, b, c] = self.radii.each_ref().map(inverse_square);
        [a, b, c, -Rat::one()]
    }

    /// Upper bounds `(deg M, deg N)` on the entries' degrees of
    /// [`PlacedQuadric::placement`] and [`PlacedQuadric::inverse`], without
    /// forming them: equal for rigid motions (`N` is a transpose), about
    /// three times higher for `N` under affine ones (`N = adj M`).
    pub fn degree_bounds(&self) -> (usize, usize) {
        self.frame.degree_bounds()
    }

    /// The moving quadric `A(u) = N(u)ᵀ·D·N(u)` in world coordinates
    /// (interior `XᵀA(u)X < 0`), up to a factor positive on the span.
    pub fn quadric(&self) -> Mat4<ZPoly> {
        congruence(&self.inverse(), &self.diagonal)
    }

    /// The longest number of the placement (its integer frame) and body
    /// quadric, in bits: a size estimate.
    pub fn bits(&self) -> u64 {
        let diagonal = self.diagonal.iter().map(ZPoly::max_bits).max().unwrap_or(0);
        self.frame_bits().max(diagonal)
    }

    /// The longest number of the placement (its integer frame), in bits.
    pub(crate) fn frame_bits(&self) -> u64 {
        let poly = ZPoly::max_bits;
        let frame = match &self.frame {
            Frame::Rigid { m, n, center, w } => m
                .iter()
                .flatten()
                .chain(center)
                .chain([n, w])
                .map(poly)
                .max(),
            Frame::Affine { l, d, w } => l.iter().flatten().chain(d).chain([w]).map(poly).max(),
        };
        frame.unwrap_or(0)
    }

    /// Whether the body's orientation changes on the span (a rotating rigid
    /// or an affine motion); a static or translating body does not turn, and
    /// `f(λ; u)` of two such bodies is cheap: [`crate::CharPoly::from_placed`]
    /// sets it up in the frame of A's centre.
    pub fn turns(&self) -> bool {
        match &self.frame {
            Frame::Rigid { m, n, .. } => {
                n.degree().unwrap_or(0) > 0
                    || m.iter().flatten().any(|e| e.degree().unwrap_or(0) > 0)
            }
            Frame::Affine { .. } => true,
        }
    }

    /// A body that never turns (static, or translating along a polynomial
    /// curve), seen from its own centre ([`crate::centred`]): the constant
    /// block `K` and corner `κ` of [`PlacedQuadric::quadric`] there, and the
    /// centre curve, over the integers `I` (over [`SmallInt`], numbers that
    /// do not fit come out overflowed). `None` for a body that turns or a
    /// rational centre curve.
    pub(crate) fn centred<I: CentredInteger>(&self) -> Option<Centred<I>> {
        let Frame::Rigid { m, n, center, w } = &self.frame else {
            return None;
        };
        let constant = |p: &ZPoly| p.degree().unwrap_or(0) == 0;
        if !(constant(n) && constant(w) && m.iter().flatten().all(constant)) {
            return None;
        }
        // N = rigid_inverse(m, n, center, w) in integers (an integer frame),
        // made primitive (primitive_matrix) by the gcd g of its coefficients:
        // N is rigid_inverse at a zero centre (the blocks X, z) plus the
        // centre column.
        let value = |p: &ZPoly| I::of(&p.coeff(0));
        let (m, n, w) = (
            m.each_ref().map(|r| r.each_ref().map(value)),
            value(n),
            value(w),
        );
        let coeffs: [Vec<I>; 3] = center
            .each_ref()
            .map(|c| c.coeffs().iter().map(I::of).collect());
        let blocks = rigid_inverse(&m, &n, &[I::zero(), I::zero(), I::zero()], &w);
        // The centre column −mᵀ·C(u), coefficient by coefficient.
        let len = coeffs.iter().map(Vec::len).max().unwrap_or(0);
        let column = (0..3).flat_map(|i| {
            let (m, coeffs) = (&m, &coeffs);
            (0..len).map(move |k| {
                (0..3).fold(I::zero(), |mut s, j| {
                    if let Some(c) = coeffs[j].get(k) {
                        s.add_product(&m[j][i], c, false);
                    }
                    s
                })
            })
        });
        // The gcd stops at 1 (the column, lazy, is then not even formed).
        let mut g = I::zero();
        for v in blocks.iter().flatten().cloned().chain(column) {
            if !v.is_zero() {
                g = g.gcd(&v);
                if g.is_one() {
                    break;
                }
            }
        }
        if g.is_zero() {
            return None;
        }
        let blocks = if g.is_one() {
            blocks
        } else {
            blocks.map(|row| row.map(|e| e.div_exact(&g)))
        };
        // At the centre, A = N₀ᵀ·D·N₀ with N₀ = [[X, 0], [0, z]]/g.
        let centred = congruence(&blocks, &self.diagonal.each_ref().map(value));
        Some(Centred::new(
            std::array::from_fn(|i| std::array::from_fn(|j| centred[i][j].clone())),
            centred[3][3].negated(),
            center.each_ref().map(I::poly),
            w,
        ))
    }

    /// The quadric at one parameter `u`, exactly, scaled to integers (a
    /// positive multiple of `A(u)`), from the placement's values there.
    pub fn quadric_at(&self, u: &Rat) -> Mat4<Int> {
        let n = self.frame_at(u).inverse();
        congruence(&n, &self.diagonal.each_ref().map(|e| e.coeff(0)))
    }

    /// The placement at one parameter `u`, exactly, scaled to integers (a
    /// nonzero multiple of `M(u)`).
    pub fn placement_at(&self, u: &Rat) -> Mat4<Int> {
        self.frame_at(u).forward()
    }

    /// The frame's polynomials at `u = a/b` times `b^N` (`N` their highest
    /// degree): `bⁿ·p(a/b)` by homogeneous Horner (`n = deg p`, no gcd)
    /// times `b^(N − n)`, integers. The placement and its inverse are forms
    /// of one degree in these values (2 for a rigid frame, 1 and 3 for an
    /// affine one), so they come out as positive multiples of their values
    /// at `u`; at an integer `u` (the state at `t0`, `u = 0`) they are those
    /// values.
    fn frame_at(&self, u: &Rat) -> Frame<Int> {
        let top = self
            .frame
            .entries()
            .filter_map(ZPoly::degree)
            .max()
            .unwrap_or(0);
        let b = u.denom();
        self.frame.map(|p| {
            let value = p.eval_homogeneous(u);
            match top - p.degree().unwrap_or(0) {
                0 => value,
                gap => value * b.pow(gap as u32),
            }
        })
    }
}

/// The greatest common divisor `g` of the six radii denominators of two
/// bodies (radii in lowest terms), by which
/// [`PlacedQuadric::diagonal_products`] shortens both bodies' tables.
fn shared_denominator(a: &PlacedQuadric, b: &PlacedQuadric) -> Int {
    content(a.radii.iter().chain(&b.radii).map(Rat::denom))
}

/// Both bodies' tables for [`ccd_quadric::placed_characteristic`],
/// shortened by the radii's shared denominator `g`
/// ([`PlacedQuadric::diagonal_products`]), and the `both` that goes with
/// them: `c = g²` for `affine` placements (both
/// [`ccd_quadric::is_affine_placement`]), else none. The sum is then `f`
/// over `c²` (over `c³` with `affine`).
pub(crate) fn shortened_tables<I: Integer>(
    a: &PlacedQuadric,
    b: &PlacedQuadric,
    affine: bool,
) -> ([[I; 16]; 2], Option<I>) {
    let g = shared_denominator(a, b);
    let both = (affine && !g.is_one()).then(|| {
        let x = I::of(&g);
        x.times(&x)
    });
    ([a, b].map(|body| body.diagonal_products(&g, affine)), both)
}

/// `det(λ·A(u) + B(u))` of two placed bodies at one parameter `u`, exactly,
/// up to a positive factor and a positive rescaling of `λ` (which keep the
/// sign of every quantity Theorem 3.10 reads: its closed forms are
/// isobaric), by the route [`crate::CharPoly::from_placed`] takes for the
/// polynomial: the [`characteristic`] of the quadrics at `u`
/// ([`PlacedQuadric::quadric_at`]) when their entries are no longer than the
/// placements' (rigid motions), else the Cauchy–Binet sum
/// [`placed_characteristic`] over the placements' values at `u` (affine
/// motions, whose inverse placements are three times longer). The frame's
/// own nonzero factor and the lcm that brings a placement to integers
/// multiply it by a nonzero `α`, which scales the coefficient of `λ^j` by
/// `α^(2(4 − j)) > 0`: again a positive factor and a positive rescaling of
/// `λ`.
///
/// The state at `t0` of a first-contact query, before `f(λ; u)` exists:
/// `bench-perturbed-affine-deg2-d0100` (100-digit radii) spent 9M
/// instructions there through the quadrics.
///
/// The products run in `i128` ([`SmallInt`]) when every number on the way
/// fits and over [`Int`] otherwise: the same integers either way (an
/// overflow is detected, never wrapped).
pub fn characteristic_at(a: &PlacedQuadric, b: &PlacedQuadric, u: &Rat) -> [Int; 5] {
    let quadrics = through_quadrics(a, b);
    let (ma, mb) = if quadrics {
        (a.quadric_at(u), b.quadric_at(u))
    } else {
        (a.placement_at(u), b.placement_at(u))
    };
    let of = |m: &Mat4<Int>| m.each_ref().map(|r| r.each_ref().map(SmallInt::of));
    let small = quartic_of(a, b, &of(&ma), &of(&mb), quadrics).map(|c| c.to_int());
    if small.iter().all(Option::is_some) {
        return small.map(Option::unwrap);
    }
    quartic_of(a, b, &ma, &mb, quadrics)
}

/// [`characteristic_at`]'s quartic over `I` from the matrices it formed at
/// `u`: the quadrics' ([`characteristic`]) or the placements'
/// ([`placed_characteristic`]).
fn quartic_of<I: Integer>(
    a: &PlacedQuadric,
    b: &PlacedQuadric,
    ma: &Mat4<I>,
    mb: &Mat4<I>,
    quadrics: bool,
) -> [I; 5] {
    if quadrics {
        return characteristic(ma, mb);
    }
    let ([da, db], _) = shortened_tables::<I>(a, b, false);
    placed_characteristic(ma, &da, mb, &db, None)
}

/// Which route forms `det(λA + B)` of two placed bodies: coefficient `k`
/// has degree at most `2·(k·deg A + (4 − k)·deg B)` in the entries of the
/// inverse placements `N` (through the quadrics `NᵀDN`) or of the
/// placements `M` (through Plücker coordinates), so the route with the
/// lower maximum wins; on a tie (rigid motions, whose inverse is a
/// transpose) the quadrics, whose five determinants take fewer products
/// than 70 coordinates.
pub(crate) fn through_quadrics(a: &PlacedQuadric, b: &PlacedQuadric) -> bool {
    let ((ma, na), (mb, nb)) = (a.degree_bounds(), b.degree_bounds());
    na.max(nb) <= ma.max(mb)
}

/// A body's placement and body quadric, with the factors of the placement's
/// determinant. Fails if the motion degenerates somewhere on the span
/// (decided exactly with the solver) or is not rational.
pub fn placed_quadric(body: &Body, span: &[Rat; 2]) -> Result<PlacedQuadric, MotionError> {
    let (frame, factors) = frame(&body.motion, span)?;
    let det_factors = factors
        .iter()
        .map(ZPoly::primitive_part)
        .filter(|f| f.degree().unwrap_or(0) > 0)
        .collect();
    Ok(PlacedQuadric {
        frame,
        diagonal: small_first(
            || integer_diagonal::<SmallInt>(&body.radii),
            || integer_diagonal::<Int>(&body.radii),
        )
        .map(ZPoly::constant),
        radii: body.radii.clone(),
        det_factors,
    })
}

/// The moving quadric `A(u) = N(u)ᵀ·D·N(u)` of a body (interior
/// `XᵀA(u)X < 0`) in world coordinates, with integer polynomial entries in
/// `u = (t − t0)/(t1 − t0)`, up to a factor positive on the span. Fails if
/// the motion degenerates somewhere on the span (decided exactly with the
/// solver) or is not rational.
pub fn moving_quadric(body: &Body, span: &[Rat; 2]) -> Result<Mat4<ZPoly>, MotionError> {
    Ok(placed_quadric(body, span)?.quadric())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::{any, prop_oneof, Just};

    proptest::proptest! {
        /// Whether `first_root_in_span` finds a root is whether `p` has one
        /// in `[0, 1]` (the Bernstein sign test that answers "none" first
        /// agrees with the isolation), for polynomials of degree up to 8
        /// with roots near and at the ends, inside and outside, and a
        /// factor without real roots, `(4t − a)² + b`, whose Bernstein
        /// coefficients change sign for `a = 2` (there the isolation must
        /// answer "none").
        #[test]
        fn a_root_in_the_span_is_found_exactly_when_there_is_one(
            roots in proptest::collection::vec((-3i64..=11, 1i64..=8), 0..=6),
            lead in -5i64..=5,
            (a, b) in (0i64..=4, 1i64..=3),
            complex in proptest::bool::ANY,
        ) {
            proptest::prop_assume!(lead != 0);
            // Π (d·t − n) for roots n/d, times `lead`.
            let p = roots.iter().fold(ZPoly::new(vec![Int::from(lead)]), |acc, &(n, d)| {
                &acc * &ZPoly::new(vec![Int::from(-n), Int::from(d)])
            });
            // (4t − a)² + b = 16t² − 8a·t + a² + b, positive for b > 0.
            let p = if complex {
                &p * &ZPoly::new(vec![Int::from(a * a + b), Int::from(-8 * a), Int::from(16)])
            } else {
                p
            };
            let span = [Rat::zero(), Rat::one()];
            let inside = roots.iter().any(|&(n, d)| (0..=d).contains(&n));
            proptest::prop_assert_eq!(first_root_in_span(&p, &span).is_some(), inside);
        }

        /// `small_det3` is `det3` over `ZPoly`, short entries (the i128
        /// route) and long ones (past i128: the fallback) alike.
        #[test]
        fn small_det3_is_det3(
            entries in proptest::collection::vec(proptest::collection::vec(
                prop_oneof![-1000i64..1000, any::<i64>()], 0..4), 9),
            long in prop_oneof![Just(0u64), 0u64..100],
        ) {
            let mut e = entries.iter().map(|c| ZPoly::new(c.iter().map(|&x| Int::from(x).shl(long)).collect()));
            let l: Mat3<ZPoly> = std::array::from_fn(|_| std::array::from_fn(|_| e.next().expect("nine")));
            proptest::prop_assert_eq!(small_det3(&l), det3(&l));
        }
    }

    fn q(v: [i64; 4]) -> Quat {
        v.map(Rat::from)
    }

    fn rigid(orientation: Bezier<Quat>) -> Body {
        Body {
            radii: [3, 2, 1].map(Rat::from),
            motion: Motion::Rigid {
                orientation,
                center: Bezier::constant([1, 0, 0].map(Rat::from)),
            },
        }
    }

    #[test]
    fn quaternion_weights_scale_the_control_points() {
        // Weights (1, 3) on (q0, q1) give the curve (q0·B0 + 3q1·B1)/w: the
        // rotation of the unweighted curve through q0 and 3·q1.
        let span = [Rat::zero(), Rat::one()];
        let weighted = rigid(Bezier {
            points: vec![q([1, 0, 0, 0]), q([1, 0, 1, 1])],
            weights: Some(vec![Rat::one(), Rat::from(3)]),
        });
        let scaled = rigid(Bezier {
            points: vec![q([1, 0, 0, 0]), q([3, 0, 3, 3])],
            weights: None,
        });
        assert_eq!(
            moving_quadric(&weighted, &span).unwrap(),
            moving_quadric(&scaled, &span).unwrap()
        );
    }

    /// `Σ Bᵢⁿ(u)·wᵢ·Pᵢ / Σ Bᵢⁿ(u)·wᵢ` over ℚ, from the definition.
    fn bezier_at<const N: usize>(curve: &Bezier<[Rat; N]>, u: &Rat) -> [Rat; N] {
        let n = curve.points.len() - 1;
        let mut num: [Rat; N] = std::array::from_fn(|_| Rat::zero());
        let mut den = Rat::zero();
        for (i, p) in curve.points.iter().enumerate() {
            let binom = ccd_poly::binomials(n)[i].clone();
            let mut b = Rat::from_int(binom);
            for _ in 0..i {
                b = &b * u;
            }
            for _ in i..n {
                b = &b * &(&Rat::one() - u);
            }
            let w = curve.weights.as_ref().map_or(Rat::one(), |w| w[i].clone());
            let bw = &b * &w;
            for (x, c) in num.iter_mut().zip(p) {
                *x = &*x + &(&bw * c);
            }
            den = &den + &bw;
        }
        num.map(|x| &x / &den)
    }

    /// The world quadric at `u` over ℚ from the contract's formulas:
    /// `A = Nᵀ·diag(1/r², −1)·N` with `N = M⁻¹`, `M` the placement
    /// (`R(q) = M(q)/|q|²` or `[L | d]`) at `u`.
    fn quadric_by_definition(body: &Body, u: &Rat) -> Mat4<Rat> {
        let zero = || Rat::zero();
        let mut m: Mat4<Rat> = std::array::from_fn(|_| std::array::from_fn(|_| zero()));
        m[3][3] = Rat::one();
        let mut rigid = |q: &Quat, c: &[Rat; 3]| {
            let n = norm2(q);
            let r = rotation_numerator(q);
            for i in 0..3 {
                for j in 0..3 {
                    m[i][j] = &r[i][j] / &n;
                }
                m[i][3] = c[i].clone();
            }
        };
        match &body.motion {
            Motion::Static {
                center,
                orientation,
            } => rigid(orientation, center),
            Motion::Translation {
                center,
                orientation,
            } => rigid(orientation, &bezier_at(center, u)),
            Motion::Rigid {
                orientation,
                center,
            } => rigid(&bezier_at(orientation, u), &bezier_at(center, u)),
            Motion::Affine { matrix } => {
                let e = bezier_at(&matrix.flattened(), u);
                for (i, row) in m.iter_mut().take(3).enumerate() {
                    for (j, x) in row.iter_mut().enumerate() {
                        *x = e[4 * i + j].clone();
                    }
                }
            }
            Motion::Helical { .. } => unreachable!(),
        }
        // N = adj(M)/det(M); D = diag(1/r0², 1/r1², 1/r2², −1).
        let det = ccd_quadric::det4(&m);
        let n = ccd_quadric::adj4(&m).map(|row| row.map(|x| &x / &det));
        let mut d = body
            .radii
            .each_ref()
            .map(|r| &Rat::one() / &(r * r))
            .to_vec();
        d.push(-Rat::one());
        congruence(
            &n,
            &[d[0].clone(), d[1].clone(), d[2].clone(), d[3].clone()],
        )
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(48))]
        /// The integer quadric of the integer frame is a positive multiple
        /// of the quadric the contract defines, at several `u` (a sign or a
        /// scaling broken anywhere in the frame fails here).
        #[test]
        fn quadric_is_a_positive_multiple_of_the_definition(
            kind in 0usize..4,
            nums in proptest::collection::vec(-9i64..10, 36),
            dens in proptest::collection::vec(1i64..7, 36),
            weights in proptest::collection::vec(1i64..5, 3),
            weighted in proptest::bool::ANY,
        ) {
            let r = |k: usize| Rat::from_frac(nums[k], dens[k]);
            let weights = weighted.then(|| weights.iter().map(|&w| Rat::from_frac(w, 2)).collect::<Vec<_>>());
            let motion = sample_motion(kind, &r, 0, 3, weights);
            let body = Body { radii: [r(24).abs() + Rat::one(), Rat::from_frac(1, 2), r(25).abs() + Rat::from(2)], motion };
            let span = [Rat::zero(), Rat::one()];
            let Ok(placed) = placed_quadric(&body, &span) else {
                return Err(proptest::test_runner::TestCaseError::reject("degenerate motion"));
            };
            let quadric = placed.quadric();
            // The i128 route gives the very same matrix when it fits.
            if let Some(small) = placed.quadric_small() {
                let lifted = small.map(|row| row.map(|e| e.to_zpoly().unwrap()));
                proptest::prop_assert_eq!(&lifted, &quadric);
            }
            for u in [Rat::zero(), Rat::from_frac(1, 3), Rat::from_frac(1, 2), Rat::one()] {
                let exact = quadric_by_definition(&body, &u);
                let ours = quadric.each_ref().map(|row| row.each_ref().map(|e| e.eval_rat(&u)));
                // ours = s·exact with s > 0; exact[3][3] − … : find s from a nonzero entry.
                let (i, j) = (0..16).map(|k| (k / 4, k % 4)).find(|&(i, j)| !exact[i][j].is_zero()).unwrap();
                let s = &ours[i][j] / &exact[i][j];
                proptest::prop_assert!(s.signum() > 0, "negative multiple at u = {u:?}");
                for (orow, erow) in ours.iter().zip(&exact) {
                    for (o, e) in orow.iter().zip(erow) {
                        proptest::prop_assert_eq!(o, &(&s * e));
                    }
                }
            }
        }
    }

    proptest::proptest! {
        /// The i128 rotation is the ZPoly one, and a quaternion too long
        /// for i128 takes the ZPoly route.
        #[test]
        fn rotation_in_i128_is_exact(
            q in proptest::collection::vec(proptest::collection::vec(-1000i64..1000, 1..4), 4),
            big in 0u32..3,
        ) {
            let scale = Int::from(7).pow(30 * big);
            let q: [ZPoly; 4] = std::array::from_fn(|i| ZPoly::from_i64s(&q[i]).mul_int(&scale));
            let (m, n) = rotation(&q);
            proptest::prop_assert_eq!(m, rotation_numerator(&q));
            proptest::prop_assert_eq!(n, norm2(&q));
        }

        /// Tables shortened by a shared denominator `g` multiply every
        /// Cauchy–Binet term by `c^(−2)` (`c = g²`), or with affine
        /// placements, their tables without the `c` of `3 ∉ S` and
        /// `both = c`, by `c^(−3)`: the characteristic of any two
        /// placements is the unshortened one over `c²` (over `c³`),
        /// coefficient by coefficient (so the normalised `f` is the same).
        /// Radii `nᵢ/(g·kᵢ)` with a long decimal or a short shared `g`.
        #[test]
        fn shared_denominator_divides_f_by_a_power_of_its_square(
            radii in proptest::collection::vec((1i64..10_000, 1i64..9), 6),
            shared in proptest::sample::select(vec![1i64, 2, 6, 10]),
            digits in 0u32..40,
            entries in proptest::collection::vec(-50i64..50, 32),
            affine in proptest::prelude::any::<bool>(),
        ) {
            let g0 = Int::from(shared) * Int::from(10).pow(digits);
            let r: Vec<Rat> = radii
                .iter()
                .map(|&(n, k)| Rat::new(Int::from(n), &g0 * &Int::from(k)).expect("positive"))
                .collect();
            let still = Motion::Static { center: [0, 0, 0].map(Rat::from), orientation: q([1, 0, 0, 0]) };
            let [a, b] = [0, 3].map(|i| {
                let body = Body { radii: [r[i].clone(), r[i + 1].clone(), r[i + 2].clone()], motion: still.clone() };
                placed_quadric(&body, &[Rat::zero(), Rat::one()]).expect("a static body")
            });
            let g = shared_denominator(&a, &b);
            for x in r.iter() {
                proptest::prop_assert!(x.denom().is_divisible_by(&g));
            }
            // Affine: last rows (0, 0, 0, w), the two w independent.
            let m = |k: usize| -> Mat4<Int> {
                std::array::from_fn(|i| std::array::from_fn(|j| {
                    let v = Int::from(entries[16 * k + 4 * i + j]);
                    if affine && i == 3 && j < 3 { Int::zero() } else { v }
                }))
            };
            proptest::prop_assert_eq!(ccd_quadric::is_affine_placement(&m(0)), affine || m(0)[3][..3].iter().all(Int::is_zero));
            let long = placed_characteristic(&m(0), &a.diagonal_products::<Int>(&Int::one(), false), &m(1), &b.diagonal_products::<Int>(&Int::one(), false), None);
            let c = g.pow(2);
            let ([sa, sb], both) = shortened_tables::<Int>(&a, &b, affine);
            let short = placed_characteristic(&m(0), &sa, &m(1), &sb, both.as_ref());
            let scale = c.pow(if affine { 3 } else { 2 });
            for (l, s) in long.iter().zip(&short) {
                proptest::prop_assert_eq!(l.clone(), s * &scale);
            }
        }

        /// The reduced diagonal products are those of `diag(1/r², −1)`
        /// over ℚ times `(n₀n₁n₂)²`, all integers.
        #[test]
        fn diagonal_products_are_the_rational_ones_scaled(
            radii in proptest::collection::vec((1i64..60, 1i64..60), 3),
            long in 0u32..3,
        ) {
            // A first radius of up to 41 digits: past i128 in the tables.
            let r: [Rat; 3] = std::array::from_fn(|i| {
                let n = Int::from(radii[i].0) * Int::from(10).pow(if i == 0 { 20 * long } else { 0 });
                Rat::new(n + Int::one(), Int::from(radii[i].1)).expect("positive")
            });
            let still = Motion::Static { center: [0, 0, 0].map(Rat::from), orientation: q([1, 0, 0, 0]) };
            let body = Body { radii: r.clone(), motion: still };
            let placed = placed_quadric(&body, &[Rat::zero(), Rat::one()]).expect("a static body");
            let scale = r.iter().fold(Rat::one(), |p, x| &p * &Rat::from(x.numer() * x.numer()));
            let [d0, d1, d2] = r.each_ref().map(|x| &Rat::one() / &(x * x));
            let expected = ccd_quadric::subset_products(&[d0, d1, d2, Rat::from(-1)]).map(|p| &p * &scale);
            let exact = placed.diagonal_products::<Int>(&Int::one(), false);
            proptest::prop_assert_eq!(exact.clone().map(Rat::from), expected);
            // Over i128: the same integers, or marked as overflowed.
            for (small, big) in placed.diagonal_products::<SmallInt>(&Int::one(), false).iter().zip(&exact) {
                if let Some(v) = small.to_i128() {
                    proptest::prop_assert_eq!(Int::from_i128(v), big.clone());
                } else {
                    proptest::prop_assert!(big.bits() > 100);
                }
            }
        }

        /// The integer body diagonal is `body_diagonal` over ℚ times the
        /// lcm of its denominators.
        #[test]
        fn integer_diagonal_matches_the_rational_one(
            radii in proptest::collection::vec((1i64..60, 1i64..60), 3),
        ) {
            let r: [Rat; 3] = std::array::from_fn(|i| Rat::from_frac(radii[i].0, radii[i].1));
            proptest::prop_assert_eq!(integer_diagonal::<Int>(&r), rat_vec_to_int::<Int, 4>(body_diagonal(&r).each_ref()));
        }
    }

    #[test]
    fn malformed_curves_are_errors() {
        let span = [Rat::zero(), Rat::one()];
        let short = rigid(Bezier {
            points: vec![q([1, 0, 0, 0]), q([1, 0, 1, 1])],
            weights: Some(vec![Rat::one()]),
        });
        assert!(matches!(
            placed_quadric(&short, &span),
            Err(MotionError::MalformedCurve {
                points: 2,
                weights: 1
            })
        ));
        let empty = rigid(Bezier {
            points: vec![],
            weights: None,
        });
        assert!(matches!(
            placed_quadric(&empty, &span),
            Err(MotionError::MalformedCurve { points: 0, .. })
        ));
    }

    /// `R(q)·diag(r²)·R(q)ᵀ` by its definition in rationals.
    fn shape_by_definition(radii: &[Rat; 3], q: &Quat) -> Mat3<Rat> {
        let n2 = norm2(q);
        let r = rotation_numerator(q).map(|row| row.map(|x| &x / &n2));
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..3).fold(Rat::zero(), |acc, k| {
                    &acc + &(&(&r[i][k] * &r[j][k]) * &(&radii[k] * &radii[k]))
                })
            })
        })
    }

    proptest::proptest! {
        /// The integer form is the shape matrix exactly, for rational radii
        /// and quaternions with unlike denominators, in every orientation.
        #[test]
        fn the_small_shape_is_exact(
            radii in proptest::collection::vec((1i64..10_000, proptest::sample::select(vec![1i64, 3, 7, 10, 100, 1000])), 3),
            quat in proptest::collection::vec((-99i64..100, proptest::sample::select(vec![1i64, 2, 3, 10, 100])), 4),
        ) {
            let radii: [Rat; 3] = std::array::from_fn(|i| Rat::from_frac(radii[i].0, radii[i].1));
            let q: Quat = std::array::from_fn(|i| Rat::from_frac(quat[i].0, quat[i].1));
            proptest::prop_assume!(!norm2(&q).is_zero());
            let (s, d) = shape_small(&radii, &q).expect("short numbers fit");
            proptest::prop_assert!(d > 0);
            let want = shape_by_definition(&radii, &q);
            for i in 0..3 {
                for j in 0..3 {
                    let got = &Rat::from(Int::from_i128(s[i][j])) / &Rat::from(Int::from_i128(d));
                    proptest::prop_assert_eq!(&got, &want[i][j]);
                }
            }
        }

        /// `n/L` gives back every value, over the least common denominator.
        #[test]
        fn values_over_their_least_common_denominator(
            nums in proptest::collection::vec(-(1i64 << 40)..(1i64 << 40), 5),
            dens in proptest::collection::vec(1i64..1_000, 5),
        ) {
            let v: [Rat; 5] = std::array::from_fn(|i| Rat::from_frac(nums[i], dens[i]));
            let (n, l) = small_over_common_denominator(v.each_ref()).expect("fits");
            let lcm = v.iter().fold(Int::one(), |acc, x| acc.lcm(x.denom()));
            proptest::prop_assert_eq!(Int::from_i128(l), lcm);
            for (x, ni) in v.iter().zip(n) {
                proptest::prop_assert_eq!(&Rat::from(Int::from_i128(ni)) / &Rat::from(Int::from_i128(l)), x.clone());
            }
        }
    }

    /// A motion of `kind` (0 static, 1 translation, 2 rigid, 3 affine) of
    /// `points` control points (weighted or not), its numbers `r(k + i)`:
    /// quaternions from `r(k)`, `r(k + 4)`, …, centres from `r(k + 12)`,
    /// `r(k + 15)`, …, affine matrices `8·I + (r(k + 12p + 4i + j))`.
    fn sample_motion(
        kind: usize,
        r: &dyn Fn(usize) -> Rat,
        k: usize,
        points: usize,
        weights: Option<Vec<Rat>>,
    ) -> Motion {
        let quat = |j: usize| -> Quat {
            let q: Quat = std::array::from_fn(|i| r(k + j + i));
            if q.iter().all(Rat::is_zero) {
                [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()]
            } else {
                q
            }
        };
        let vec3 = |j: usize| -> [Rat; 3] { std::array::from_fn(|i| r(k + j + i)) };
        let centre = Bezier {
            points: (0..points).map(|p| vec3(12 + 3 * p)).collect(),
            weights: weights.clone(),
        };
        match kind {
            0 => Motion::Static {
                center: vec3(12),
                orientation: quat(0),
            },
            1 => Motion::Translation {
                center: centre,
                orientation: quat(0),
            },
            2 => Motion::Rigid {
                orientation: Bezier {
                    points: (0..points).map(|p| quat(4 * p)).collect(),
                    weights,
                },
                center: centre,
            },
            _ => Motion::Affine {
                matrix: Bezier {
                    points: (0..points)
                        .map(|p| {
                            std::array::from_fn(|i| {
                                std::array::from_fn(|j| {
                                    let base = if i == j { Rat::from(8) } else { Rat::zero() };
                                    &base + &r(k + 12 * p + 4 * i + j)
                                })
                            })
                        })
                        .collect(),
                    weights,
                },
            },
        }
    }

    /// `p = c·(s^j·q_j)` for some `c, s > 0`: the same quartic up to a
    /// positive factor and a positive rescaling of `λ`. Zero coefficients
    /// match; the ratios `r_j = p_j/q_j` of the others are positive and
    /// geometric in `j` (`r_j^(k−i) = r_i^(k−j)·r_k^(j−i)` for `i < j < k`).
    fn same_up_to_scalings(p: &[Int; 5], q: &[Int; 5]) -> bool {
        let nonzero: Vec<usize> = (0..5).filter(|&j| !q[j].is_zero()).collect();
        let r = |j: usize| &Rat::from(p[j].clone()) / &Rat::from(q[j].clone());
        let pow = |x: &Rat, e: usize| (0..e).fold(Rat::one(), |acc, _| &acc * x);
        (0..5).all(|j| q[j].is_zero() == p[j].is_zero())
            && nonzero.iter().all(|&j| r(j).signum() > 0)
            && nonzero.windows(3).all(|w| {
                let (i, j, k) = (w[0], w[1], w[2]);
                pow(&r(j), k - i) == &pow(&r(i), k - j) * &pow(&r(k), j - i)
            })
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// `characteristic_at` gives `det(λA(u) + B(u))` of the quadrics at
        /// `u` up to a positive factor and rescaling of `λ`, on affine
        /// (the placements' route) and rigid (the quadrics') pairs, with
        /// numbers short (the `i128` products) and long (`10^(13·long)`:
        /// past `i128`, the `Int` products). The reference is the moving
        /// quadric's polynomial entries evaluated at `u` in rationals.
        #[test]
        fn characteristic_at_is_the_quadrics_quartic(
            nums in proptest::collection::vec(-9i64..10, 48),
            dens in proptest::collection::vec(1i64..7, 48),
            rigid in proptest::bool::ANY,
            at in (0i64..9, 1i64..9),
            long in 0u32..3,
        ) {
            let scale = Rat::from(Int::pow10(13 * long));
            let r = |k: usize| &Rat::from_frac(nums[k], dens[k]) * &scale;
            let body = |k: usize| {
                let motion = sample_motion(if rigid { 2 } else { 3 }, &r, k, 2, None);
                Body { radii: [r(k).abs() + Rat::one(), Rat::from_frac(1, 2), r(k + 1).abs() + Rat::from(2)], motion }
            };
            let span = [Rat::zero(), Rat::one()];
            let (Ok(a), Ok(b)) = (placed_quadric(&body(0), &span), placed_quadric(&body(24), &span)) else {
                return Err(proptest::test_runner::TestCaseError::reject("degenerate motion"));
            };
            let quadric_at = |q: &PlacedQuadric, u: &Rat| {
                ccd_quadric::integral(&q.quadric().map(|row| row.map(|e| e.eval_rat(u))))
            };
            for u in [Rat::zero(), Rat::from_frac(at.0.min(at.1), at.1), Rat::one()] {
                let direct = characteristic(&quadric_at(&a, &u), &quadric_at(&b, &u));
                proptest::prop_assert!(same_up_to_scalings(&characteristic_at(&a, &b, &u), &direct), "at {}", u);
            }
        }
    }

    /// Numbers past `i64` (or an lcm past it, or products past `i128`) are
    /// refused, for the caller's other path.
    #[test]
    fn long_numbers_have_no_small_shape() {
        let one = [Rat::one(), Rat::one(), Rat::one()];
        let q = |x: Rat| [x, Rat::one(), Rat::zero(), Rat::zero()];
        let big = Rat::from(Int::one().shl(70));
        assert!(shape_small(&one, &q(big.clone())).is_none());
        let radii = [big, Rat::one(), Rat::one()];
        assert!(shape_small(&radii, &q(Rat::one())).is_none());
        // Denominators 2^40 − 87 and 2^40 − 57 (coprime): lcm past i64.
        let p = |k: i64| Rat::from_frac(1, (1 << 40) - k);
        assert!(small_over_common_denominator([&p(87), &p(57)]).is_none());
        // A quaternion of 2^40: |q|⁴ overflows i128.
        let q40 = [(1i64 << 40) - 1, (1 << 40) - 3, 5, 7].map(Rat::from);
        assert!(shape_small(&one, &q40).is_none());
        assert!(shape_small(&one, &[1, 2, 3, 4].map(Rat::from)).is_some());
    }
}
