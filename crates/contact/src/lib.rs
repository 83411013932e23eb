//! # ccd-contact
//!
//! Contact geometry at an instant `t*` of external touching: where the two
//! ellipsoids touch and in which direction.
//!
//! # The math
//!
//! At `t*`, `f(λ) = det(λA + B)` (`A = A(t*)`, `B = B(t*)`, interiors
//! `XᵀAX < 0`, `XᵀBX < 0`) has a positive double root `λ*` (Theorem 3.10(2)
//! of Jia, Choi, Mourrain & Wang 2011), and the touching point is the kernel
//! of `M = λ*·A + B` (Wang, Wang & Kim 2001): `M·X* = 0`, `X* = (x*, 1)`.
//! When `M` has rank 3 its adjugate is `c·X*·X*ᵀ` with `c = adj(M)[3][3] ≠ 0`
//! (the minor of the 3×3 block), so every column `j` with
//! `adj(M)[3][j] ≠ 0` gives `x*ᵢ = adj(M)[i][j] / adj(M)[3][j]`.
//!
//! `λ*` comes from the two touch cases of Theorem 3.10(2), written with the
//! closed forms of `ccd_subres::closed_forms` (`T = sr11`, `T2 = sr10`):
//!
//! * [`Case::Simple`] (`sr11(t*) ≠ 0`, 3.10(2a)): `gcd(f, f′)` is the
//!   first subresultant `sr_1(λ) = sr11·λ + sr10`, so
//!   `λ* = −3·T2/T` (the closed forms carry the factors 324 and 108);
//! * [`Case::TwoDouble`] (`sr11(t*) = 0`, 3.10(2b)): `f = e·(λ − λ*)²(λ − μ)²`
//!   with `μ < 0 < λ*` (every pair of spheres, whose `f` has the factor
//!   `(λ + 1)²`), so with `s = λ* + μ = −a/(2e)` and
//!   `p = λ*·μ = (b/e − s²)/2`, `λ* = (s + √(s² − 4p))/2`.
//!
//! Both formulas are exact at `t*`, so evaluating them over any enclosure
//! of the data at `t*` (interval arithmetic on `A(T)`, `B(T)` for an
//! enclosure `T ∋ t*`) encloses `λ*`, then `M`, its adjugate column and
//! `x*`. Which case holds must be decided by the caller (exactly, on the
//! exact path); nothing here guesses it.
//!
//! The normal is `A`'s gradient `∇(XᵀAX) = 2·A·X` at `X*`, first three
//! components: it points out of `A`, into `B`. It is reported divided by
//! the magnitude of its largest component (∞-norm 1; that component is
//! exactly `±1`), a scale that does not depend on the arbitrary positive
//! factor of `A`. At a touch `−∇(XᵀBX)` points the same way; where its
//! enclosure is narrower by more than `2^20` than `A`'s (a needle or disc
//! `A` of extreme radius ratio, whose curvature multiplies the point box's
//! width), the normal is enclosed from it instead.

#![warn(missing_docs)]

use ccd_arith::{Interval, Rat, RingOps};
use ccd_enclosure::{centred_quadrics, BigInterval, Real, Trig};
use ccd_motion::Body;
use ccd_quadric::{adj4_column, characteristic, Mat4};
use ccd_subres::{closed_form, Quantity};
use ccd_timeline::{Box3, Geometry};

/// Which touch case of Theorem 3.10(2) holds at `t*` (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Case {
    /// `sr11(t*) ≠ 0`: one positive double root, `λ* = −3·sr10/sr11`.
    Simple,
    /// `sr11(t*) = 0`: a positive and a negative double root.
    TwoDouble,
}

/// Why no enclosure came out of one evaluation.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ContactError {
    /// A quantity that must be nonzero (a divisor, the sign of `λ*`, the
    /// radicand) was not separated from zero at this precision and width.
    #[error("enclosure too wide: {0} not separated from 0")]
    Undecided(&'static str),
    /// Every entry of the adjugate's last column encloses 0: the kernel of
    /// `λ*·A + B` is not shown one-dimensional.
    #[error("the kernel of λ*·A + B is not shown one-dimensional")]
    Kernel,
}

/// A number type the contact formulas run over: exact rationals or an
/// interval type whose operations enclose the exact results.
pub trait Scalar: RingOps {
    /// `self / o`, `None` when `o` may be zero.
    fn divide(&self, o: &Self) -> Option<Self>;
    /// An enclosure of `√self`, `None` when `self` may be negative (or, for
    /// exact rationals, when the root is not rational).
    fn root(&self) -> Option<Self>;
    /// The sign of every value, `None` when undecided.
    fn proven_sign(&self) -> Option<i32>;
    /// A value near the middle (not certified; for choices only).
    fn estimate(&self) -> f64;
    /// The width, approximately (0 for exact values; for stopping rules
    /// only).
    fn estimate_width(&self) -> f64;
    /// The two ends exactly, `None` when unbounded.
    fn bounds(&self) -> Option<(Rat, Rat)>;
    /// The rational `q`, enclosed with `prec` bits where the type has a
    /// choice.
    fn of_rat(q: &Rat, prec: u32) -> Self;
    /// One interval Newton step for a root of `g` in `self` with `dg`
    /// enclosing `g′` on `self`: `(m − g(m)/dg) ∩ self` for a point `m` of
    /// `self`. Every root of `g` in `self` stays in the result; `None` when
    /// the step cannot be taken (or, for exact values, is not needed).
    fn newton(&self, g: impl Fn(&Self) -> Self, dg: &Self) -> Option<Self>;
    /// The common part of two enclosures of the same value (`None` for
    /// exact values, which need no tightening).
    fn meet(&self, o: &Self) -> Option<Self>;
    /// The finite `f64` `v` exactly, at the precision of `like`.
    fn of_f64(v: f64, like: &Self) -> Option<Self>;
}

impl Scalar for Rat {
    fn divide(&self, o: &Self) -> Option<Self> {
        (!o.is_zero()).then(|| self / o)
    }
    fn root(&self) -> Option<Self> {
        let exact = |n: &ccd_arith::Int| {
            let r = BigInterval::sqrt_rat(&Rat::from_int(n.clone()), 0)
                .lo_rat()
                .floor();
            (&r * &r == *n).then_some(r)
        };
        if self.signum() < 0 {
            return None;
        }
        Rat::new(exact(self.numer())?, exact(self.denom())?)
    }
    fn proven_sign(&self) -> Option<i32> {
        Some(self.signum())
    }
    fn estimate(&self) -> f64 {
        self.to_f64()
    }
    fn estimate_width(&self) -> f64 {
        0.0
    }
    fn bounds(&self) -> Option<(Rat, Rat)> {
        Some((self.clone(), self.clone()))
    }
    fn of_rat(q: &Rat, _prec: u32) -> Self {
        q.clone()
    }
    fn newton(&self, _g: impl Fn(&Self) -> Self, _dg: &Self) -> Option<Self> {
        None
    }
    fn meet(&self, _o: &Self) -> Option<Self> {
        None
    }
    fn of_f64(v: f64, _like: &Self) -> Option<Self> {
        Rat::from_f64_exact(v)
    }
}

/// [`Scalar`] for the interval types of `ccd-enclosure` ([`Real`]).
macro_rules! interval_scalar {
    ($t:ty) => {
        impl Scalar for $t {
            fn divide(&self, o: &Self) -> Option<Self> {
                Real::div(self, o)
            }
            fn root(&self) -> Option<Self> {
                let (lo, hi) = (Real::lo_rat(self)?, Real::hi_rat(self)?);
                if lo.signum() < 0 {
                    return None;
                }
                let prec = self.precision();
                Some(
                    <$t as Real>::sqrt_rat(&lo, prec)
                        .lower()
                        .hull(&<$t as Real>::sqrt_rat(&hi, prec).upper()),
                )
            }
            fn proven_sign(&self) -> Option<i32> {
                Real::sign(self)
            }
            fn estimate(&self) -> f64 {
                Real::approx(self)
            }
            fn estimate_width(&self) -> f64 {
                Real::width_f64(self)
            }
            fn bounds(&self) -> Option<(Rat, Rat)> {
                Some((Real::lo_rat(self)?, Real::hi_rat(self)?))
            }
            fn of_rat(q: &Rat, prec: u32) -> Self {
                <$t as Real>::constant(q, prec)
            }
            fn newton(&self, g: impl Fn(&Self) -> Self, dg: &Self) -> Option<Self> {
                let m = Real::midpoint(self);
                let step = Real::div(&g(&m), dg)?;
                self.intersect(&m.minus(&step))
            }
            fn meet(&self, o: &Self) -> Option<Self> {
                self.intersect(o)
            }
            fn of_f64(v: f64, like: &Self) -> Option<Self> {
                v.is_finite()
                    .then(|| <$t as PointOf>::point_of(v, like.precision()))
            }
        }
    };
}
/// The exact point `v` (finite) in an interval type.
trait PointOf {
    fn point_of(v: f64, prec: u32) -> Self;
}
impl PointOf for Interval {
    fn point_of(v: f64, _prec: u32) -> Self {
        Interval::point(v)
    }
}
impl PointOf for BigInterval {
    fn point_of(v: f64, prec: u32) -> Self {
        let mut p = BigInterval::point(
            ccd_enclosure::Dyadic::from_f64(v).unwrap_or_else(ccd_enclosure::Dyadic::zero),
        );
        p.prec = prec;
        p
    }
}
interval_scalar!(Interval);
interval_scalar!(BigInterval);

/// Enclosures (or exact values) of the contact point and of `A`'s outward
/// normal scaled to ∞-norm 1.
#[derive(Clone, Debug, PartialEq)]
pub struct Enclosed<S> {
    /// The contact point `x*` (world coordinates).
    pub point: [S; 3],
    /// `(A·X*)₀..₂ / max_k |(A·X*)_k|`.
    pub normal: [S; 3],
}

fn nonzero<S: Scalar>(x: &S, what: &'static str) -> Result<i32, ContactError> {
    x.proven_sign()
        .filter(|s| *s != 0)
        .ok_or(ContactError::Undecided(what))
}

/// `λ*` of `f = [e, a, b, c, d]` (high → low) in the given case (module
/// docs), checked positive.
pub fn double_root<S: Scalar>(f: &[S; 5], case: Case) -> Result<S, ContactError> {
    let k = |v: i64| S::from_i64(v);
    let lambda = match case {
        Case::Simple => {
            let sr11 = closed_form(f, Quantity::Sr11).ok_or(ContactError::Kernel)?;
            let sr10 = closed_form(f, Quantity::Sr10).ok_or(ContactError::Kernel)?;
            nonzero(&sr11, "sr11")?;
            k(-3).times(&sr10).divide(&sr11)
        }
        Case::TwoDouble => {
            let [e, a, b, _, _] = f;
            nonzero(e, "det A")?;
            let s = a
                .negated()
                .divide(&k(2).times(e))
                .ok_or(ContactError::Undecided("det A"))?;
            let p = b
                .divide(e)
                .ok_or(ContactError::Undecided("det A"))?
                .minus(&s.times(&s))
                .div_small(2);
            let radicand = s.times(&s).minus(&k(4).times(&p));
            nonzero(&radicand, "(λ* − μ)²")?;
            let r = radicand
                .root()
                .ok_or(ContactError::Undecided("√((λ* − μ)²)"))?;
            Some(s.plus(&r).div_small(2))
        }
    }
    .ok_or(ContactError::Undecided("sr11"))?;
    if nonzero(&lambda, "λ*")? < 0 {
        return Err(ContactError::Undecided("λ* > 0"));
    }
    Ok(tighten(f, lambda))
}

/// Interval Newton on `f′` from the enclosure `lambda ∋ λ*`: `λ*` is a
/// root of `f′` (a double root of `f`) and `f″(λ*) ≠ 0` (not a triple
/// root), so every step keeps it, and the enclosure shrinks to the
/// rounding level of `f`'s coefficients, much tighter than the closed
/// forms, whose terms cancel heavily. Stops when a step no longer shrinks
/// it (or cannot be taken: `f″` not separated from 0).
fn tighten<S: Scalar>(f: &[S; 5], mut lambda: S) -> S {
    let [e, a, b, c, _] = f;
    let k = |v: i64| S::from_i64(v);
    // f′ = 4eλ³ + 3aλ² + 2bλ + c and f″ = 12eλ² + 6aλ + 2b (Horner).
    let (e4, a3, b2) = (k(4).times(e), k(3).times(a), k(2).times(b));
    let (e12, a6) = (k(12).times(e), k(6).times(a));
    let d1 = |x: &S| e4.times(x).plus(&a3).times(x).plus(&b2).times(x).plus(c);
    let d2 = |x: &S| e12.times(x).plus(&a6).times(x).plus(&b2);
    for _ in 0..8 {
        let before = lambda.estimate_width();
        match lambda.newton(d1, &d2(&lambda)) {
            Some(next) if next.estimate_width() < before => lambda = next,
            Some(next) => return next,
            None => return lambda,
        }
    }
    lambda
}

/// The contact point and normal from the quadric matrices at `t*` (or
/// enclosures of them), `A` with interior `XᵀAX < 0` up to a positive
/// factor, in the given case of Theorem 3.10(2) (module docs).
pub fn from_quadrics<S: Scalar>(
    a: &Mat4<S>,
    b: &Mat4<S>,
    case: Case,
) -> Result<Enclosed<S>, ContactError> {
    let lambda = double_root(&characteristic(a, b), case)?;
    let m: Mat4<S> =
        std::array::from_fn(|i| std::array::from_fn(|j| lambda.times(&a[i][j]).plus(&b[i][j])));
    // adj(M) is symmetric (M is): its last row is its last column.
    let last = adj4_column(&m, 3);
    if last.iter().all(|x| x.proven_sign().is_none_or(|s| s == 0)) {
        return Err(ContactError::Kernel);
    }
    let j = argmax(&last);
    let col = if j == 3 { last } else { adj4_column(&m, j) };
    let point: [S; 3] = try_array(|i| {
        col[i]
            .divide(&col[3])
            .ok_or(ContactError::Undecided("adj(M)[3][j]"))
    })?;
    let (point, _) = krawczyk(a, b, point, lambda);
    // ∇(XᵀAX) and −∇(XᵀBX) at X*, first three components (halved): both
    // point along A's outward normal at a touch.
    let gradient = |q: &Mat4<S>| -> [S; 3] { times_point(q, &point) };
    let normal = either_normal(&gradient(a), &gradient(b).map(|g| g.negated()))?;
    Ok(Enclosed { point, normal })
}

/// A's outward normal (∞-norm 1) from two enclosures of its direction at
/// the contact, A's gradient `from_a` and B's negated gradient `from_b`:
/// A's, unless B's is narrower by more than 2^20 (a very thin or flat A,
/// whose large curvature widens its gradient's box): then B's, or, scaled
/// by the same component, the common part of both enclosures of the same
/// vector; whichever is proven nonzero when only one is.
pub(crate) fn either_normal<S: Scalar>(
    from_a: &[S; 3],
    from_b: &[S; 3],
) -> Result<[S; 3], ContactError> {
    Ok(match (unit_max(from_a), unit_max(from_b)) {
        (Ok((na, ka)), Ok((nb, kb))) => {
            let wide = |n: &[S; 3]| n.iter().map(S::estimate_width).fold(0.0, f64::max);
            if wide(&na) <= wide(&nb) * NORMAL_FROM_B {
                na
            } else if ka == kb {
                try_array(|i| Ok(nb[i].meet(&na[i]).unwrap_or_else(|| nb[i].clone())))?
            } else {
                nb
            }
        }
        (Ok((na, _)), Err(_)) => na,
        (Err(_), Ok((nb, _))) => nb,
        (Err(e), Err(_)) => return Err(e),
    })
}

/// How much narrower `−∇B`'s normal box must be than `∇A`'s to replace
/// it ([`from_quadrics`]): `2^20`.
const NORMAL_FROM_B: f64 = (1u64 << 20) as f64;

/// `g / |g_k|` with `g_k` proven nonzero (`k` the component of largest
/// estimated magnitude), and `k`; that component is exactly `±1`.
fn unit_max<S: Scalar>(g: &[S; 3]) -> Result<([S; 3], usize), ContactError> {
    let k = argmax(g);
    let sign = nonzero(&g[k], "the normal")?;
    let scale = if sign > 0 {
        g[k].clone()
    } else {
        g[k].negated()
    };
    let n = try_array(|i| {
        if i == k {
            Ok(S::from_i64(sign as i64))
        } else {
            g[i].divide(&scale)
                .ok_or(ContactError::Undecided("the normal"))
        }
    })?;
    Ok((n, k))
}

/// Tightens the enclosures `x0 ∋ x*`, `lambda ∋ λ*` with Krawczyk's
/// operator on the system
///
/// `F(x, λ) = ((λA + B)·X)₀..₂ = 0,  XᵀAX = 0`,  `X = (x, 1)`
///
/// (three rows of the kernel equation and the point on A's surface),
/// whose Jacobian `[[λA + B]₀..₂,₀..₂, (A·X)₀..₂; 2(A·X)ᵀ₀..₂, 0]` is
/// regular at a touch (unlike the kernel equation alone, which is
/// singular at a double root). With `z̃` the midpoint of the box `Z`, `C`
/// an approximate inverse of the Jacobian in `f64` and `J(Z)` its interval
/// enclosure, every zero of `F` in `Z` — for every `A`, `B` in the
/// enclosures, so the true one at `t*` — lies in
/// `K = z̃ − C·F(z̃) + (I − C·J(Z))·(Z − z̃)`; `Z ∩ K` is kept. Only `A`
/// and `B` enter, not `f(λ)`, so the result is as narrow as their
/// enclosures allow.
fn krawczyk<S: Scalar>(a: &Mat4<S>, b: &Mat4<S>, x0: [S; 3], lambda: S) -> ([S; 3], S) {
    let mut z: [S; 4] = [x0[0].clone(), x0[1].clone(), x0[2].clone(), lambda];
    // Exact inputs (zero width) are what they are: nothing to tighten.
    // A step not available (a singular midpoint Jacobian, a value outside
    // f64, or exact scalars, for which `meet` keeps nothing) leaves `z`.
    if z.iter().any(|v| v.estimate_width() > 0.0) {
        let zt = try_map(&z, |v| S::of_f64(v.estimate(), v));
        let step = zt.and_then(|zt| krawczyk_image(a, b, &z, &zt, |k, z| k.meet(z)));
        if let Some(next) = step {
            z = next;
        }
    }
    let [x0, x1, x2, l] = z;
    ([x0, x1, x2], l)
}

/// Krawczyk's operator `K(Z) = z̃ − C·F(z̃) + (I − C·J(Z))·(Z − z̃)` of the
/// system of [`krawczyk`] at the box `z` and the point `zt ∈ z`, each
/// component `Kᵢ` passed through `each(Kᵢ, Zᵢ)` (`meet` to tighten,
/// `Some` to test inclusion); `C` is the `f64` inverse of `J(Z)`'s
/// midpoint. `None` when that inverse or a piece of it is not available,
/// or `each` gives `None` (the components after it are not computed).
pub(crate) fn krawczyk_image<S: Scalar>(
    a: &Mat4<S>,
    b: &Mat4<S>,
    z: &[S; 4],
    zt: &[S; 4],
    each: impl Fn(S, &S) -> Option<S>,
) -> Option<[S; 4]> {
    let like = &z[3];
    let point = |v: f64| S::of_f64(v, like);
    // A·X and B·X, X = (z₀, z₁, z₂, 1).
    let (g, h): ([S; 4], [S; 3]) = (times_point(a, zt), times_point(b, zt));
    let a3 = &g[3];
    // F(z̃): rows 0..2 λ·(A X) + B X; row 3 XᵀAX = x·(A X)₀..₂ + (A X)₃.
    let f: [S; 4] = std::array::from_fn(|r| {
        if r < 3 {
            zt[3].times(&g[r]).plus(&h[r])
        } else {
            (0..3).fold(a3.clone(), |acc, c| acc.plus(&zt[c].times(&g[c])))
        }
    });
    let gz: [S; 3] = times_point(a, z);
    let j: Mat4<S> = std::array::from_fn(|r| {
        std::array::from_fn(|c| match (r < 3, c < 3) {
            (true, true) => z[3].times(&a[r][c]).plus(&b[r][c]),
            (true, false) => gz[r].clone(),
            (false, true) => gz[c].times(&S::from_i64(2)),
            (false, false) => S::zero(),
        })
    });
    let mid: Mat4<f64> = j.each_ref().map(|row| row.each_ref().map(|v| v.estimate()));
    let det = ccd_quadric::det4(&mid);
    let adj = ccd_quadric::adj4(&mid);
    if !(det.is_finite() && det != 0.0) {
        return None;
    }
    let c = try_map(&adj, |row| try_map(row, |v| point(v / det)))?;
    let dz: [S; 4] = std::array::from_fn(|k| z[k].minus(&zt[k]));
    try_map(&[0, 1, 2, 3], |&i| {
        let mut v = zt[i].clone();
        for (k, fk) in f.iter().enumerate() {
            v = v.minus(&c[i][k].times(fk));
        }
        for (jj, dzj) in dz.iter().enumerate() {
            let cj = (0..4).fold(S::zero(), |acc, k| acc.plus(&c[i][k].times(&j[k][jj])));
            let e = S::from_i64((i == jj) as i64).minus(&cj);
            v = v.plus(&e.times(dzj));
        }
        each(v, &z[i])
    })
}

/// Rows `0..R` of `Q·(x, 1)` (`x` three coordinates, or more, of which the
/// first three are read): a point's image under a homogeneous map, or
/// half a quadric's gradient at it.
pub(crate) fn times_point<S: RingOps, const R: usize>(q: &Mat4<S>, x: &[S]) -> [S; R] {
    std::array::from_fn(|r| (0..3).fold(q[r][3].clone(), |acc, c| acc.plus(&q[r][c].times(&x[c]))))
}

fn argmax<S: Scalar, const N: usize>(v: &[S; N]) -> usize {
    let estimates = v.each_ref().map(|x| x.estimate().abs());
    // Estimates that overflow, or underflow to 0 or below f64's normal
    // range (coordinates of 1e100 or 1e-60 square past it), do not order
    // the components: then the exact ends do.
    let usable = |e: &f64| e.is_finite() && (*e == 0.0 || e.is_normal());
    if estimates.iter().all(usable) && estimates.iter().any(|e| e.is_normal()) {
        return (0..N)
            .max_by(|&i, &j| estimates[i].total_cmp(&estimates[j]))
            .unwrap_or(0);
    }
    let magnitude = |x: &S| x.bounds().map(|(lo, hi)| lo.abs().max(hi.abs()));
    let m = v.each_ref().map(magnitude);
    (0..N).max_by(|&i, &j| m[i].cmp(&m[j])).unwrap_or(0)
}

/// `f` of each element, `None` if any is.
fn try_map<T, U, const N: usize>(v: &[T; N], f: impl Fn(&T) -> Option<U>) -> Option<[U; N]> {
    let mut out: [Option<U>; N] = std::array::from_fn(|_| None);
    for (o, x) in out.iter_mut().zip(v) {
        *o = Some(f(x)?);
    }
    Some(out.map(|o| o.expect("filled above")))
}

/// `[f(0), …, f(N − 1)]`, or the first error.
fn try_array<T, const N: usize>(
    f: impl Fn(usize) -> Result<T, ContactError>,
) -> Result<[T; N], ContactError> {
    let mut out: [Option<T>; N] = std::array::from_fn(|_| None);
    for (i, o) in out.iter_mut().enumerate() {
        *o = Some(f(i)?);
    }
    Ok(out.map(|o| o.expect("filled above")))
}

/// [`from_quadrics`] with `A(t)`, `B(t)` enclosed at the time enclosure `t`
/// (time itself, not `u`) through `ccd_enclosure::centred_quadrics`, which
/// serves every motion kind: in a frame centred between the bodies (the
/// entries stay small, so the heavily cancelling determinants stay
/// tight), the point moved back to world coordinates.
pub fn at_time<N: Scalar + Trig>(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    t: &N,
    case: Case,
    prec: u32,
) -> Result<Enclosed<N>, ContactError> {
    let (origin, qa, qb) = centred_quadrics(a, b, span, t, prec);
    let mut e = from_quadrics(&qa, &qb, case)?;
    for (x, s) in e.point.iter_mut().zip(&origin) {
        *x = x.plus(&N::of_rat(s, prec));
    }
    Ok(e)
}

fn to_box<S: Scalar>(v: &[S; 3]) -> Option<Box3> {
    let [x, y, z] = v.each_ref().map(Scalar::bounds);
    let ((x0, x1), (y0, y1), (z0, z1)) = (x?, y?, z?);
    Some(Box3 {
        lo: [x0, y0, z0],
        hi: [x1, y1, z1],
    })
}

impl<S: Scalar> Enclosed<S> {
    /// As result boxes with exact rational ends (`None` if unbounded).
    pub fn to_geometry(&self, certified: bool) -> Option<Geometry> {
        Some(Geometry::Point {
            point: to_box(&self.point)?,
            normal: to_box(&self.normal)?,
            certified,
        })
    }
}

/// The width goal for a contact box: each point coordinate within
/// `size·10^(−k)`, `size` the scene's largest radius,
/// `k = max(12, digits − 3)` (12 by default, more with `--digits` above
/// 15), and each normal component within `10^(−k)·size/r_min` (`r_min` the
/// smallest radius: the point's goal carried through the largest
/// curvature, which is what the normal's enclosure can achieve from it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Goal {
    /// For the point's coordinates.
    pub point: Rat,
    /// For the normal's components.
    pub normal: Rat,
}

impl Goal {
    /// The goal for bodies `a`, `b` at `digits` (module docs).
    pub fn new(a: &Body, b: &Body, digits: u32) -> Goal {
        let radii = || a.radii.iter().chain(&b.radii);
        let size = radii().max().cloned().unwrap_or_else(Rat::one);
        // Radii are positive in a valid scene; a zero one gets no division.
        let smallest = radii()
            .min()
            .filter(|r| r.signum() > 0)
            .cloned()
            .unwrap_or_else(Rat::one);
        let tol = Rat::new(
            ccd_arith::Int::one(),
            ccd_arith::Int::pow10(digits.saturating_sub(3).max(12)),
        )
        .unwrap_or_else(Rat::one);
        Goal {
            point: &size * &tol,
            normal: &(&size / &smallest) * &tol,
        }
    }
    /// Lower bounds of the two goals in `f64` (`[point, normal]`) from
    /// the largest and the smallest radius (rounded to nearest): a box
    /// whose widths, rounded up, are at most these meets the goal
    /// ([`Goal::met`]) without its exact rationals. The margin `1 − 10⁻⁹`
    /// covers every rounding of the radii, of `10^(−k)` and of the products.
    pub fn floors(largest: f64, smallest: f64, digits: u32) -> [f64; 2] {
        let k = digits.saturating_sub(3).clamp(12, 400) as i32;
        let tol = 10f64.powi(-k) * (1.0 - 1e-9);
        [largest * tol, largest / smallest * tol]
    }
    /// Whether a result meets the goal.
    pub fn met(&self, g: &Geometry) -> bool {
        match g {
            Geometry::Point { point, normal, .. } => {
                point.width() <= self.point && normal.width() <= self.normal
            }
            _ => false,
        }
    }
}

/// Precisions tried for one time enclosure: `f64` intervals, then
/// multi-precision intervals.
pub const PRECISIONS: [u32; 4] = [53, 128, 256, 512];

/// The contact geometry at the time enclosure `[lo, hi]` (time itself),
/// at increasing precision (`precisions`, in bits, 53 meaning `f64`
/// intervals; [`PRECISIONS`] by default) until `goal` is met: the first
/// result that meets it, otherwise the narrowest one found (still an
/// enclosure), otherwise the last error. `certified` is passed through to
/// the result (the caller knows whether the instant and the case are
/// proven).
pub fn enclose(
    bodies: (&Body, &Body, &[Rat; 2]),
    time: (&Rat, &Rat),
    case: Case,
    goal: &Goal,
    certified: bool,
    precisions: &[u32],
) -> Result<Geometry, ContactError> {
    enclose_to_goal(bodies, time, case, goal, certified, precisions).map(|(g, _)| g)
}

/// [`enclose`], and whether its result meets `goal` (`Goal::met`, decided
/// once here: the first result that meets it is returned, so `false` means
/// the narrowest one that does not), for a caller that goes on to a
/// narrower instant when it does not.
pub fn enclose_to_goal(
    (a, b, span): (&Body, &Body, &[Rat; 2]),
    (lo, hi): (&Rat, &Rat),
    case: Case,
    goal: &Goal,
    certified: bool,
    precisions: &[u32],
) -> Result<(Geometry, bool), ContactError> {
    let mut best: Option<Geometry> = None;
    let mut error = ContactError::Kernel;
    for &prec in precisions {
        let result = if prec == 53 {
            let t = Fast::flushed(Interval::from_rat(lo).hull(&Interval::from_rat(hi)));
            at_time(a, b, span, &t, case, prec).map(|e| e.to_geometry(certified))
        } else {
            let t = BigInterval::from_rat(lo, prec).hull(&BigInterval::from_rat(hi, prec));
            at_time(a, b, span, &t, case, prec).map(|e| e.to_geometry(certified))
        };
        match result {
            Ok(Some(g)) => {
                if goal.met(&g) {
                    return Ok((g, true));
                }
                let narrower = |old: &Geometry| match (old, &g) {
                    (Geometry::Point { point: p, .. }, Geometry::Point { point: q, .. }) => {
                        q.width() < p.width()
                    }
                    _ => true,
                };
                if best.as_ref().is_none_or(narrower) {
                    best = Some(g);
                }
            }
            Ok(None) => error = ContactError::Undecided("an unbounded enclosure"),
            Err(e) => error = e,
        }
    }
    best.map(|g| (g, false)).ok_or(error)
}

/// A float estimate (the paper's setting, not certified) at the time `t`:
/// the formulas in `f64` intervals at the point `t`, midpoints taken, boxes
/// of zero width marked `certified: false`. The case is `TwoDouble` when
/// `two_double` says so or `sr11` encloses 0 there.
pub fn estimate(a: &Body, b: &Body, span: &[Rat; 2], t: &Rat, two_double: bool) -> Geometry {
    let ti = Interval::from_rat(t);
    let (origin, qa, qb) = centred_quadrics(a, b, span, &ti, 53);
    let f = characteristic(&qa, &qb);
    let sr11_zero = closed_form(&f, Quantity::Sr11).is_none_or(|s| s.contains_zero());
    let case = if two_double || sr11_zero {
        Case::TwoDouble
    } else {
        Case::Simple
    };
    // Midpoints of every entry: plain f64 values, the float path's numbers.
    let mid = |m: &Mat4<Interval>| m.map(|row| row.map(|x| Interval::point(x.mid())));
    match from_quadrics(&mid(&qa), &mid(&qb), case) {
        Ok(mut e) => {
            for (x, s) in e.point.iter_mut().zip(&origin) {
                *x = Interval::point(x.mid() + s.to_f64());
            }
            let exact = |v: &[Interval; 3]| -> Option<Box3> {
                let x: Vec<Rat> = v
                    .iter()
                    .map(|i| Rat::from_f64_exact(i.mid()))
                    .collect::<Option<_>>()?;
                Some(Box3::point(std::array::from_fn(|k| x[k].clone())))
            };
            match (exact(&e.point), exact(&e.normal)) {
                (Some(point), Some(normal)) => Geometry::Point {
                    point,
                    normal,
                    certified: false,
                },
                _ => Geometry::Unknown {
                    reason: "float estimate not finite".into(),
                },
            }
        }
        Err(ContactError::Kernel) => Geometry::NotASinglePoint,
        Err(e) => Geometry::Unknown {
            reason: format!("float estimate: {e}"),
        },
    }
}

/// The [`Geometry`] of a contact whose computation failed: no single
/// point when the kernel is not one-dimensional, otherwise unknown with
/// the reason.
pub fn failed(e: ContactError) -> Geometry {
    match e {
        ContactError::Kernel => Geometry::NotASinglePoint,
        other => Geometry::Unknown {
            reason: other.to_string(),
        },
    }
}

#[cfg(test)]
mod tests;

pub mod least_point;
pub use least_point::{interiors_meet, least_point};

/// `f64` intervals for the contact formulas without subnormal ends.
///
/// Outward rounding turns every exact zero it touches into
/// `[−2⁻¹⁰⁷⁴, 2⁻¹⁰⁷⁴]`, and arithmetic on subnormal numbers is one to two
/// orders of magnitude slower on common hardware; the quadric matrices of
/// axis-aligned or translating bodies are full of zeros. This wrapper keeps
/// exact zeros exact (`0·x = 0`, `0 + x = x`, both exact) and moves a
/// subnormal end outward to `±2⁻¹⁰²²` or to 0 (still an enclosure, only
/// wider by less than `2⁻¹⁰²²`).
///
/// Its sum, difference and product are never inlined: the contact
/// formulas ([`from_quadrics`], the placements at an instant) are
/// straight-line code run once a contact, and inlined they were about
/// 39 KB of instructions touched once a query, evicting the rest of the
/// exact path from the instruction cache. Called, they are about 15 KB:
/// the degree-2 rigid query 54.5 → 51.2 µs for 1.3–2 % more instructions
/// (docs/table4.md, issue 17, session 39).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fast(pub Interval);

impl Fast {
    fn flushed(i: Interval) -> Fast {
        let tiny = f64::MIN_POSITIVE;
        let lo = if i.lo != 0.0 && i.lo.abs() < tiny {
            if i.lo < 0.0 {
                -tiny
            } else {
                0.0
            }
        } else {
            i.lo
        };
        let hi = if i.hi != 0.0 && i.hi.abs() < tiny {
            if i.hi > 0.0 {
                tiny
            } else {
                0.0
            }
        } else {
            i.hi
        };
        Fast(Interval { lo, hi })
    }
}

impl RingOps for Fast {
    fn zero() -> Self {
        Fast(Interval::point(0.0))
    }
    fn one() -> Self {
        Fast(Interval::point(1.0))
    }
    fn from_i64(v: i64) -> Self {
        Fast::flushed(Interval::from_i64(v))
    }
    fn is_zero(&self) -> bool {
        self.0.lo == 0.0 && self.0.hi == 0.0
    }
    #[inline(never)]
    fn plus(&self, o: &Self) -> Self {
        match (self.is_zero(), o.is_zero()) {
            (true, _) => *o,
            (_, true) => *self,
            _ => Fast::flushed(self.0 + o.0),
        }
    }
    #[inline(never)]
    fn minus(&self, o: &Self) -> Self {
        match (self.is_zero(), o.is_zero()) {
            (true, _) => Fast(-o.0),
            (_, true) => *self,
            _ => Fast::flushed(self.0 - o.0),
        }
    }
    #[inline(never)]
    fn times(&self, o: &Self) -> Self {
        if self.is_zero() || o.is_zero() {
            return Fast::zero();
        }
        Fast::flushed(self.0 * o.0)
    }
    fn negated(&self) -> Self {
        Fast(-self.0)
    }
    fn div_small(&self, k: i64) -> Self {
        Fast::flushed(self.0.div_small(k))
    }
}

impl Trig for Fast {
    fn constant(q: &Rat, prec: u32) -> Self {
        Fast::flushed(<Interval as Trig>::constant(q, prec))
    }
    fn sqrt_rat(q: &Rat, prec: u32) -> Self {
        Fast::flushed(<Interval as Trig>::sqrt_rat(q, prec))
    }
    fn sin_cos(&self) -> (Self, Self) {
        let (s, c) = self.0.sin_cos();
        (Fast::flushed(s), Fast::flushed(c))
    }
    fn approx_value(&self) -> f64 {
        self.0.mid()
    }
}

impl Scalar for Fast {
    fn divide(&self, o: &Self) -> Option<Self> {
        self.0.divide(&o.0).map(Fast::flushed)
    }
    fn root(&self) -> Option<Self> {
        self.0.root().map(Fast::flushed)
    }
    fn proven_sign(&self) -> Option<i32> {
        self.0.proven_sign()
    }
    fn estimate(&self) -> f64 {
        self.0.estimate()
    }
    fn estimate_width(&self) -> f64 {
        self.0.estimate_width()
    }
    fn bounds(&self) -> Option<(Rat, Rat)> {
        self.0.bounds()
    }
    fn of_rat(q: &Rat, prec: u32) -> Self {
        Fast::flushed(Interval::of_rat(q, prec))
    }
    fn newton(&self, g: impl Fn(&Self) -> Self, dg: &Self) -> Option<Self> {
        let m = Fast(Interval::point(self.0.mid()));
        let m = if self.0.lo <= m.0.lo && m.0.hi <= self.0.hi {
            m
        } else {
            return None;
        };
        let step = g(&m).divide(dg)?;
        self.meet(&m.minus(&step))
    }
    fn meet(&self, o: &Self) -> Option<Self> {
        self.0.meet(&o.0).map(Fast)
    }
    fn of_f64(v: f64, _like: &Self) -> Option<Self> {
        v.is_finite().then(|| Fast(Interval::point(v)))
    }
}
