//! The contact as the point of body A where B's quadric is least, proven
//! by Krawczyk's test in A's unit-sphere frame.
//!
//! # The math
//!
//! In A's unit-sphere frame ([`ccd_enclosure::UnitFrame`]) A is the unit
//! ball `|s| ≤ 1` and B's quadric is `Q̂(t) = [[H, g], [gᵀ, k]]` (up to a
//! positive factor), `H` positive definite (B is an ellipsoid). At an
//! instant `t*` of external touch the contact is the point of A where
//! `q(s) = sᵀH·s + 2gᵀs + k` is least (it is 0 there, and positive on the
//! rest of A: the interiors are disjoint and a strictly convex `q` has one
//! minimiser on the convex A), and it lies on the sphere (B's centre, the
//! free minimum, is outside A).
//!
//! **The minimiser on the sphere** (Sorensen 1982; Moré & Sorensen 1983):
//! `s` is the global minimiser of `q` on `|s| = 1` if and only if, for
//! some `ν`, `(H + ν·I)·s = −g` and `H + ν·I ⪰ 0`; with `ν > 0` and `H`
//! positive definite the second condition holds. So a proven zero of
//!
//! `F(s, ν; t) = (H(t)·s + g(t) + ν·s,  sᵀs − 1)`
//!
//! with `ν > 0` is the minimiser at `t`, and at `t = t*` it is the contact.
//! `F` is the system of [`crate::from_quadrics`]'s tightening step with A
//! the unit sphere, `diag(1, 1, 1, −1)`, and B `Q̂`.
//!
//! **Krawczyk's test** (Krawczyk 1969, Moore 1977), for all `t` of a time
//! enclosure `T ∋ t*` at once: with `z̃ ∈ Z`, `C` any matrix and
//! `F(z̃; T)`, `J(Z; T)` enclosing `F(z̃; t)` and `F′(z; t)` over `z ∈ Z`,
//! `t ∈ T`, every zero of `F(·; t)` in `Z` lies in
//! `K(Z) = z̃ − C·F(z̃; T) + (I − C·J(Z; T))·(Z − z̃)`, and `K(Z) ⊂ int Z`
//! proves there is exactly one, for each `t ∈ T`. `Z` grows from a guess
//! by ε-inflation (Rump 1983).
//!
//! **Why this frame.** The closed form `λ* = −3·sr10/sr11` cancels past
//! thousands of bits for a needle of radius ratio 10⁶⁴ (its `f` has a
//! near-triple root), and the needle's world quadric has entries 10¹²⁸
//! that cancel against a point 10⁻¹²⁸ off its axis. In the frame the
//! needle is the unit ball, B's quadric carries the small radii as
//! factors, and `F` is well-conditioned (the Jacobian's determinant is
//! `−4·sᵀ adj(H + ν·I) s`, nonzero where `H + ν·I` is definite): `f64`
//! intervals prove the needle's contact, where the closed forms needed
//! 2,048 bits.
//!
//! The guess is the minimiser itself, in `f64` at the middle of `T`
//! ([`least_on_sphere`]).

use crate::{
    either_normal, krawczyk_image, times_point, try_array, try_map, ContactError, Enclosed, Scalar,
};
use ccd_arith::Rat;
use ccd_enclosure::{quadric_at, unit_frame, Real, Trig};
use ccd_motion::Body;
use ccd_quadric::{det3, Mat4};

/// Inflation rounds before the test gives up.
const ROUNDS: usize = 6;

/// Krawczyk steps at most after the proof ([`tightened`]).
const TIGHTEN: usize = 4;

/// The certified contact at the instant `t*` of external touch in the
/// time interval `[lo, hi]` (time itself), which the caller has proven
/// (module docs), with intervals of `prec` bits (53: `f64`). `Err` when
/// the test does not succeed (a time interval too wide for the
/// enclosures, a guess too far off, a multiplier not proven positive).
pub fn least_point<N: Scalar + Real + Trig>(
    (a, b, span): (&Body, &Body, &[Rat; 2]),
    (lo, hi): (&Rat, &Rat),
    prec: u32,
) -> Result<Enclosed<N>, ContactError> {
    let fail = ContactError::Undecided("the least point on A");
    let time = outward_time::<N>((lo, hi), prec);
    let frame = unit_frame::<N>(a, b, span, &time, prec);
    let Scaled { q, h, g } = scaled(&frame.quadric_b, prec).ok_or(fail.clone())?;
    let (s, nu) = least_on_sphere(&h, &g).ok_or(fail.clone())?;
    let point = |v: f64| N::of_f64(v, &time).ok_or(fail.clone());
    let guess: [N; 4] = [point(s[0])?, point(s[1])?, point(s[2])?, point(nu)?];
    let z = proven_minimiser(&q, &guess, prec)?;
    enclosed((a, b, span), &time, &frame, &z, prec)
}

/// B's quadric in A's frame scaled by a power of two to entries ≤ 1 (a
/// positive factor: the same minimiser, the same signs), with its `f64`
/// parts.
struct Scaled<N> {
    q: Mat4<N>,
    /// Rows and columns 0..2.
    h: [[f64; 3]; 3],
    /// Column 3, rows 0..2.
    g: [f64; 3],
}

/// [`Scaled`] of B's quadric; `None` when its entries are all zero or not
/// finite in `f64`.
fn scaled<N: Scalar + Real>(quadric_b: &Mat4<N>, prec: u32) -> Option<Scaled<N>> {
    let top = quadric_b
        .iter()
        .flatten()
        .map(|x| Real::approx(x).abs())
        .fold(0.0, f64::max);
    if !(top.is_finite() && top > 0.0) {
        return None;
    }
    let scale = <N as Real>::constant(&Rat::one().mul_pow2(-(top.log2().ceil() as i64)), prec);
    let q: Mat4<N> = quadric_b
        .each_ref()
        .map(|row| row.each_ref().map(|x| x.times(&scale)));
    let approx = |i: usize, j: usize| Real::approx(&q[i][j]);
    let h: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| approx(i, j)));
    let g: [f64; 3] = std::array::from_fn(|i| approx(i, 3));
    Some(Scaled { q, h, g })
}

/// A box of `(s, ν)` proven to hold the one zero of `F(·; t)` for every
/// `t` of the enclosure `q` of B's quadric, with `ν > 0`: the least point
/// (module docs). ε-inflation from `guess`: a box around it, then each
/// Krawczyk image widened by a quarter, at most [`ROUNDS`] times; the
/// proof is `K(Z) ⊂ int Z` in all four components (a box with an infinite
/// end is refused: its midpoint need not lie in it).
fn proven_minimiser<N: Scalar + Real>(
    q: &Mat4<N>,
    guess: &[N; 4],
    prec: u32,
) -> Result<[N; 4], ContactError> {
    let fail = ContactError::Undecided("the least point on A");
    let sphere: Mat4<N> = std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i == j, i) {
            (true, 3) => N::from_i64(-1),
            (true, _) => N::one(),
            _ => N::zero(),
        })
    });
    let widen = |x: &N, d: f64| -> Result<N, ContactError> {
        let d = N::of_f64(d, x).ok_or(fail.clone())?;
        Ok(x.plus(&<N as Real>::unit(prec).times(&d)))
    };
    let mut z: [N; 4] =
        try_array(|i| widen(&guess[i], Real::approx(&guess[i]).abs() * 1e-9 + 1e-290))?;
    for _ in 0..ROUNDS {
        if !z.iter().all(Real::is_finite) {
            return Err(fail);
        }
        let mid: [N; 4] = std::array::from_fn(|i| Real::midpoint(&z[i]));
        let k = krawczyk_image(&sphere, q, &z, &mid, |k, _| Some(k)).ok_or(fail.clone())?;
        if k.iter().zip(&z).all(|(k, z)| k.strictly_inside(z)) {
            if Real::sign(&k[3]) != Some(1) {
                return Err(fail);
            }
            return Ok(tightened(&sphere, q, k));
        }
        z = try_array(|i| {
            let hull = k[i].hull(&z[i].midpoint());
            widen(&hull, Real::width_f64(&hull) * 0.25 + 1e-290)
        })?;
    }
    Err(fail)
}

/// Krawczyk steps on the proven box `z` (each keeps the zero) while they
/// at least halve its widest side, at most [`TIGHTEN`] of them: the proof
/// came from a box the size of the guess's error, and the precision
/// allows a box as narrow as the enclosures of `Q̂`.
fn tightened<N: Scalar + Real>(sphere: &Mat4<N>, q: &Mat4<N>, mut z: [N; 4]) -> [N; 4] {
    let widest = |z: &[N; 4]| z.iter().map(Real::width_f64).fold(0.0, f64::max);
    for _ in 0..TIGHTEN {
        let mid: [N; 4] = std::array::from_fn(|i| Real::midpoint(&z[i]));
        let next = krawczyk_image(sphere, q, &z, &mid, |k, z| k.intersect(z));
        match next {
            Some(next) if widest(&next) <= widest(&z) / 2.0 => z = next,
            Some(next) => return next,
            None => return z,
        }
    }
    z
}

/// Whether the bodies' interiors provably meet at every time of
/// `[lo, hi]` (time itself): a point `s` strictly inside A's unit ball
/// with `q̂(s; t) < 0` for all those `t` (B's quadric in A's frame, over
/// the time enclosure) is a point of both interiors (`|s| < 1` puts
/// `x(s)` inside A; `q̂` is B's quadric at `x(s)` times a positive
/// factor). No instant there is an external touch (Theorem 3.10(2)), so
/// a root of `sr0` there needs no signs. The witness tried: B's centre
/// when it lies inside A's ball, else the least point on the sphere
/// ([`least_on_sphere`]) pulled inside by a factor `1 − 2⁻²⁰`. `false`
/// when it does not prove it (no error: the signs decide then).
pub fn interiors_meet<N: Scalar + Real + Trig>(
    (a, b, span): (&Body, &Body, &[Rat; 2]),
    (lo, hi): (&Rat, &Rat),
    prec: u32,
) -> bool {
    let time = outward_time((lo, hi), prec);
    let Some(Scaled { q, h, g }) =
        scaled(&unit_frame::<N>(a, b, span, &time, prec).quadric_b, prec)
    else {
        return false;
    };
    let witness = match least_on_sphere(&h, &g) {
        Some((s, _)) => s.map(|x| x * (1.0 - 1.0 / f64::from(1u32 << 20))),
        // B's centre −H⁻¹g inside the ball (or H + μI singular).
        None => match free_minimum(&h, &g) {
            Some(c) => c,
            None => return false,
        },
    };
    let Some(s) = try_map(&witness, |&v| N::of_f64(v, &time)) else {
        return false;
    };
    // |s|² − 1 and (s, 1)ᵀ·Q·(s, 1).
    let inside = (0..3).fold(N::from_i64(-1), |acc, i| acc.plus(&s[i].times(&s[i])));
    let qx: [N; 4] = times_point(&q, &s);
    let qs = (0..3).fold(qx[3].clone(), |acc, i| acc.plus(&s[i].times(&qx[i])));
    Real::sign(&inside) == Some(-1) && Real::sign(&qs) == Some(-1)
}

/// The time enclosure `[lo, hi]` from dyadic ends a little outside: the
/// ends of a refined root have thousands of digits, past `f64`'s range
/// as a numerator and a denominator.
fn outward_time<N: Real>((lo, hi): (&Rat, &Rat), prec: u32) -> N {
    let bits = u64::from(prec) + 64;
    let down = |q: &Rat| Rat::dyadic(q.mul_pow2(bits as i64).floor(), bits);
    N::constant(&down(lo), prec).hull(&N::constant(&-down(&-hi), prec))
}

/// `−H⁻¹g` when it lies strictly inside the unit ball.
fn free_minimum(h: &[[f64; 3]; 3], g: &[f64; 3]) -> Option<[f64; 3]> {
    solve_shifted(h, 0.0, &g.map(|x| -x)).filter(|c| norm(c) < 1.0)
}

/// `(H + μI)⁻¹·rhs` by Cramer's rule, `None` when `H + μI` is singular
/// in `f64` or a component is not finite.
fn solve_shifted(h: &[[f64; 3]; 3], mu: f64, rhs: &[f64; 3]) -> Option<[f64; 3]> {
    let m: [[f64; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|j| h[i][j] + if i == j { mu } else { 0.0 }));
    let det = det3(&m);
    if !(det.is_finite() && det != 0.0) {
        return None;
    }
    let x: [f64; 3] = std::array::from_fn(|k| {
        let mut mk = m;
        for (row, v) in mk.iter_mut().zip(rhs) {
            row[k] = *v;
        }
        det3(&mk) / det
    });
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// The Euclidean norm.
fn norm(v: &[f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The world point and A's outward normal (∞-norm 1) from the proven box
/// `z` of `(s, ν)`, in the frame over the time enclosure `time`; the
/// normal from A's gradient or B's, as [`crate::from_quadrics`] chooses.
fn enclosed<N: Scalar + Real + Trig>(
    (a, b, span): (&Body, &Body, &[Rat; 2]),
    time: &N,
    frame: &ccd_enclosure::UnitFrame<N>,
    z: &[N; 4],
    prec: u32,
) -> Result<Enclosed<N>, ContactError> {
    let undecided = ContactError::Undecided("the least point's world box");
    let world: [N; 4] = times_point(&frame.to_world, z);
    let point = try_array(|i| Real::div(&world[i], &world[3]).ok_or(undecided.clone()))?;
    // A's outward normal along w·N[0..3][0..3]ᵀ·(s/r) (`UnitFrame`); for
    // a radius below the box's resolution (10⁻⁴⁰⁹⁶) s/r is too wide to
    // sign, and B's negated gradient −Q_B·X (world) serves.
    let n = &frame.inverse_a;
    let w = Real::sign(&n[3][3])
        .filter(|s| *s != 0)
        .ok_or(undecided.clone())?;
    let over_r: [N; 3] = std::array::from_fn(|k| {
        let r = a.radii[k].recip().unwrap_or_else(Rat::one);
        z[k].times(&<N as Real>::constant(&r, prec))
    });
    let from_a: [N; 3] = std::array::from_fn(|c| {
        let g = (0..3).fold(N::zero(), |acc, k| acc.plus(&n[k][c].times(&over_r[k])));
        if w < 0 {
            g.negated()
        } else {
            g
        }
    });
    let qb = quadric_at(b, span, time, prec);
    let from_b = times_point::<N, 3>(&qb, &point).map(|g| g.negated());
    let normal = either_normal(&from_a, &from_b)?;
    Ok(Enclosed { point, normal })
}

/// The point `s` of the unit sphere where `sᵀH·s + 2gᵀs` is least, and
/// its multiplier `μ > 0` (`(H + μI)·s = −g`), for `H` positive
/// definite and the unconstrained minimum `−H⁻¹g` outside the ball (B's
/// centre outside A): `|s(μ)|` falls from above 1 to 0 as `μ` grows, and
/// Newton's method on `1/|s(μ)| − 1` (nearly linear; Moré & Sorensen
/// 1983), kept inside a bracket, finds it. `None` when `H + μI` is
/// singular in `f64` or the centre is not outside.
pub fn least_on_sphere(h: &[[f64; 3]; 3], g: &[f64; 3]) -> Option<([f64; 3], f64)> {
    let solve = |mu: f64, rhs: &[f64; 3]| solve_shifted(h, mu, rhs);
    let minus_g = g.map(|x| -x);
    let outside = solve(0.0, &minus_g).is_none_or(|s| norm(&s) > 1.0);
    if !outside {
        return None;
    }
    let (mut lo, mut hi) = (0.0, norm(g) * 2.0 + f64::MIN_POSITIVE);
    let mut mu = hi / 2.0;
    // Converged: |s| = 1 to rounding, or μ no longer moves.
    let tiny = 4.0 * f64::EPSILON;
    for _ in 0..400 {
        let s = solve(mu, &minus_g)?;
        let len = norm(&s);
        let phi = 1.0 / len - 1.0;
        if phi.abs() < tiny {
            return Some((s.map(|x| x / len), mu));
        }
        if phi < 0.0 {
            lo = mu;
        } else {
            hi = mu;
        }
        // d|s|/dμ = −sᵀ(H + μI)⁻¹s/|s|.
        let w = solve(mu, &s)?;
        let slope = s.iter().zip(&w).map(|(a, b)| a * b).sum::<f64>() / (len * len * len);
        let next = mu - phi / slope;
        if (next - mu).abs() <= tiny * mu || hi - lo <= tiny * hi {
            return Some((s.map(|x| x / len), mu));
        }
        // Outside the bracket: bisect it, geometrically (μ may be tiny
        // beside H's largest entries, as for a needle touched on its side).
        mu = if next > lo && next < hi && next.is_finite() {
            next
        } else if lo > 0.0 {
            (lo * hi).sqrt()
        } else {
            hi / 1024.0
        };
        if mu <= 0.0 {
            return None;
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Interval;
    use ccd_enclosure::BigInterval;
    use ccd_motion::{Bezier, Motion, Quat};
    use ccd_timeline::{Box3, Geometry};
    use proptest::prelude::*;

    fn q(p: i64, d: i64) -> Rat {
        Rat::from_frac(p, d)
    }

    fn placed(radii: [Rat; 3], center: [Rat; 3], orientation: Quat) -> Body {
        Body {
            radii,
            motion: Motion::Static {
                center,
                orientation,
            },
        }
    }

    fn boxes(e: &Enclosed<impl Scalar>) -> (Box3, Box3) {
        match e.to_geometry(true) {
            Some(Geometry::Point { point, normal, .. }) => (point, normal),
            other => panic!("not a point: {other:?}"),
        }
    }

    fn holds(b: &Box3, v: &[Rat; 3]) -> bool {
        (0..3).all(|i| b.lo[i] <= v[i] && v[i] <= b.hi[i])
    }

    /// A named static pair touching at a known point, with A's outward
    /// normal there scaled to ∞-norm 1.
    type Touching = (&'static str, Body, Body, [Rat; 3], [Rat; 3]);

    fn touching() -> Vec<Touching> {
        let int = |v: [i64; 3]| v.map(Rat::from);
        let id = Motion::identity();
        // The axis (3/5, 4/5, 0): the quaternion (2, 0, 0, 1) turns x onto it.
        let turned = [2, 0, 0, 1].map(Rat::from);
        let thin = Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(64)).unwrap();
        let hair = Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(4096)).unwrap();
        let reflected = Body {
            radii: int([1, 1, 1]),
            motion: Motion::Affine {
                matrix: Bezier::constant(
                    [[-2, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]].map(|row| row.map(Rat::from)),
                ),
            },
        };
        vec![
            (
                "spheres",
                placed(int([5, 5, 5]), int([0, 0, 0]), id.clone()),
                placed(int([5, 5, 5]), int([6, 8, 0]), id.clone()),
                int([3, 4, 0]),
                [q(3, 4), Rat::one(), Rat::zero()],
            ),
            (
                "ellipsoid and sphere",
                placed(int([2, 1, 1]), int([0, 0, 0]), id.clone()),
                placed(int([1, 1, 1]), int([3, 0, 0]), id.clone()),
                int([2, 0, 0]),
                int([1, 0, 0]),
            ),
            (
                "sphere and ellipsoid",
                placed(int([1, 1, 1]), int([3, 0, 0]), id.clone()),
                placed(int([2, 1, 1]), int([0, 0, 0]), id.clone()),
                int([2, 0, 0]),
                int([-1, 0, 0]),
            ),
            (
                // A reflection (det L < 0): the inverse placement's w is negative.
                "reflected ellipsoid and sphere",
                reflected,
                placed(int([1, 1, 1]), int([3, 0, 0]), id.clone()),
                int([2, 0, 0]),
                int([1, 0, 0]),
            ),
            (
                // Off A's axes with unequal radii: the normal is along
                // (x/4, y/25, 0) ∝ (15, 8, 0), not along the frame's s.
                "off-axis contact on an ellipsoid",
                placed(int([2, 5, 1]), int([0, 0, 0]), id.clone()),
                placed(
                    [q(17, 5), q(17, 5), q(17, 5)],
                    [q(21, 5), q(28, 5), Rat::zero()],
                    id.clone(),
                ),
                [q(6, 5), Rat::from(4), Rat::zero()],
                [Rat::one(), q(8, 15), Rat::zero()],
            ),
            (
                // A needle of radius 10⁻⁴⁰⁹⁶ touched at its tip: s/r is
                // too wide to sign, and B's gradient gives the normal.
                "needle of radius 10^-4096",
                placed(
                    [Rat::one(), hair.clone(), hair],
                    int([0, 0, 0]),
                    [2, 0, 0, 1].map(Rat::from),
                ),
                placed(int([1, 1, 1]), [q(6, 5), q(8, 5), Rat::zero()], id.clone()),
                [q(3, 5), q(4, 5), Rat::zero()],
                [q(3, 4), Rat::one(), Rat::zero()],
            ),
            (
                // A needle of radius ratio 10⁶⁴ touched at its tip: its
                // closed forms cancel past 2,000 bits.
                "needle",
                placed([Rat::one(), thin.clone(), thin], int([0, 0, 0]), turned),
                placed(int([1, 1, 1]), [q(6, 5), q(8, 5), Rat::zero()], id),
                [q(3, 5), q(4, 5), Rat::zero()],
                [q(3, 4), Rat::one(), Rat::zero()],
            ),
        ]
    }

    #[test]
    fn encloses_known_contacts_in_f64_and_128_bits() {
        let span = [Rat::zero(), Rat::one()];
        let t = q(1, 3);
        for (name, a, b, point, normal) in touching() {
            let fast = least_point::<Interval>((&a, &b, &span), (&t, &t), 53);
            let (p, n) = boxes(&fast.unwrap_or_else(|e| panic!("{name}: {e}")));
            assert!(
                holds(&p, &point) && holds(&n, &normal),
                "{name}: {p:?} {n:?}"
            );
            assert!(p.width() < q(1, 1 << 40), "{name}: {p:?}");
            let big = least_point::<BigInterval>((&a, &b, &span), (&t, &t), 128).unwrap();
            let (p, n) = boxes(&big);
            assert!(
                holds(&p, &point) && holds(&n, &normal),
                "{name}: {p:?} {n:?}"
            );
            let tiny = Rat::dyadic(ccd_arith::Int::one(), 100);
            assert!(p.width() < tiny, "{name}: {p:?}");
        }
    }

    #[test]
    fn holds_for_every_time_of_the_enclosure() {
        // Unit spheres, B from (−4, 0, 0) to (4, 0, 0): they touch at
        // t* = 1/4 at (−1, 0, 0); A's normal there is −x.
        let a = placed(
            [1, 1, 1].map(Rat::from),
            [0, 0, 0].map(Rat::from),
            Motion::identity(),
        );
        let b = Body {
            radii: [1, 1, 1].map(Rat::from),
            motion: Motion::Translation {
                center: Bezier::polynomial(vec![
                    [-4, 0, 0].map(Rat::from),
                    [4, 0, 0].map(Rat::from),
                ]),
                orientation: Motion::identity(),
            },
        };
        let span = [Rat::zero(), Rat::one()];
        let eps = Rat::dyadic(ccd_arith::Int::one(), 60);
        let (lo, hi) = (&q(1, 4) - &eps, &q(1, 4) + &eps);
        let e = least_point::<Interval>((&a, &b, &span), (&lo, &hi), 53).unwrap();
        let (p, n) = boxes(&e);
        assert!(holds(&p, &[-1, 0, 0].map(Rat::from)), "{p:?}");
        assert!(holds(&n, &[-1, 0, 0].map(Rat::from)), "{n:?}");
        assert!(p.width() < q(1, 1 << 40));
    }

    #[test]
    fn refuses_when_the_centre_is_inside() {
        // B's centre inside A: the least point on A's sphere is no
        // minimiser over A, and the guess says so.
        let int = |v: [i64; 3]| v.map(Rat::from);
        let a = placed(int([2, 2, 2]), int([0, 0, 0]), Motion::identity());
        let b = placed(int([1, 1, 1]), int([1, 0, 0]), Motion::identity());
        let span = [Rat::zero(), Rat::one()];
        let t = Rat::zero();
        assert!(least_point::<Interval>((&a, &b, &span), (&t, &t), 53).is_err());
    }

    /// `sᵀH·s + 2gᵀs`.
    fn form(h: &[[f64; 3]; 3], g: &[f64; 3], s: &[f64; 3]) -> f64 {
        let hs: [f64; 3] = std::array::from_fn(|i| (0..3).map(|j| h[i][j] * s[j]).sum());
        (0..3).map(|i| s[i] * hs[i] + 2.0 * g[i] * s[i]).sum()
    }

    proptest! {
        #[test]
        fn least_on_sphere_is_the_minimum(
            l in prop::array::uniform3(prop::array::uniform3(-2.0f64..2.0)),
            g in prop::array::uniform3(-6.0f64..6.0),
            grade in prop::array::uniform3(prop::sample::select(vec![0i32, 20, 60])),
            probes in prop::collection::vec(prop::array::uniform3(-1.0f64..1.0), 64),
        ) {
            // H = D·(LᵀL + I/10)·D, g ↦ D·g: a body's radii D as the frame
            // scales them (graded like a needle's).
            let d = grade.map(|e| 10f64.powi(-e));
            let h: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| {
                let m: f64 = (0..3).map(|k| l[k][i] * l[k][j]).sum::<f64>()
                    + if i == j { 0.1 } else { 0.0 };
                d[i] * m * d[j]
            }));
            let g: [f64; 3] = std::array::from_fn(|i| d[i] * g[i]);
            match least_on_sphere(&h, &g) {
                None => {
                    // Only when the free minimum −H⁻¹g is inside the ball.
                    let det = det3(&h);
                    let free: [f64; 3] = std::array::from_fn(|k| {
                        let mut hk = h;
                        for (row, v) in hk.iter_mut().zip(&g) {
                            row[k] = -v;
                        }
                        det3(&hk) / det
                    });
                    let len: f64 = free.iter().map(|x| x * x).sum::<f64>().sqrt();
                    prop_assert!(len <= 1.0 + 1e-9, "{free:?}");
                }
                Some((s, mu)) => {
                    prop_assert!(mu > 0.0);
                    let len: f64 = s.iter().map(|x| x * x).sum::<f64>().sqrt();
                    prop_assert!((len - 1.0).abs() < 1e-12);
                    let best = form(&h, &g, &s);
                    let scale = h.iter().flatten().chain(&g).fold(0.0f64, |m, x| m.max(x.abs()));
                    for p in &probes {
                        let n: f64 = p.iter().map(|x| x * x).sum::<f64>().sqrt();
                        if n > 1e-3 {
                            let p = p.map(|x| x / n);
                            prop_assert!(best <= form(&h, &g, &p) + 1e-9 * scale, "{best} {p:?}");
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn a_moving_contact_is_held_over_the_whole_time_enclosure() {
        // Unit spheres, B from (−4, −6/5, 0) to (4, −6/5, 0): they touch at
        // t* = 3/10 at (−4/5, −3/5, 0); the least point moves with t, so
        // an enclosure of an end of [lo, hi] alone would miss it.
        let int = |v: [i64; 3]| v.map(Rat::from);
        let a = placed(int([1, 1, 1]), int([0, 0, 0]), Motion::identity());
        let b = Body {
            radii: int([1, 1, 1]),
            motion: Motion::Translation {
                center: Bezier::polynomial(vec![
                    [Rat::from(-4), q(-6, 5), Rat::zero()],
                    [Rat::from(4), q(-6, 5), Rat::zero()],
                ]),
                orientation: Motion::identity(),
            },
        };
        let span = [Rat::zero(), Rat::one()];
        let point = [q(-4, 5), q(-3, 5), Rat::zero()];
        let normal = [Rat::from(-1), q(-3, 4), Rat::zero()];
        for (lo, hi) in [
            (q(29, 100), q(3, 10)),
            (q(3, 10), q(31, 100)),
            (q(3, 10), q(3, 10)),
        ] {
            let e = least_point::<Interval>((&a, &b, &span), (&lo, &hi), 53).unwrap();
            let (p, n) = boxes(&e);
            assert!(
                holds(&p, &point) && holds(&n, &normal),
                "[{lo}, {hi}]: {p:?} {n:?}"
            );
        }
    }

    #[test]
    fn a_critical_point_with_a_negative_multiplier_is_refused() {
        // A the unit ball, B's quadric |s − c|² − 1 with c = (3, 0, 0):
        // (H + νI)s = −g holds at s = (1, 0, 0) with ν = 2 (the least
        // point) and at s = (−1, 0, 0) with ν = −4 (the greatest).
        let iv = |v: i64| Interval::point(v as f64);
        let q: Mat4<Interval> = [
            [iv(1), iv(0), iv(0), iv(-3)],
            [iv(0), iv(1), iv(0), iv(0)],
            [iv(0), iv(0), iv(1), iv(0)],
            [iv(-3), iv(0), iv(0), iv(8)],
        ];
        let least = proven_minimiser(&q, &[iv(1), iv(0), iv(0), iv(2)], 53).unwrap();
        for (x, want) in least.iter().zip([1.0, 0.0, 0.0, 2.0]) {
            assert!(x.lo <= want && want <= x.hi && x.hi - x.lo < 1e-12, "{x:?}");
        }
        assert!(proven_minimiser(&q, &[iv(-1), iv(0), iv(0), iv(-4)], 53).is_err());
        // A guess off in ν alone: the proof needs all four components.
        let off = proven_minimiser(&q, &[iv(1), iv(0), iv(0), Interval::point(2.5)], 53);
        if let Ok(z) = off {
            assert!(z[3].lo <= 2.0 && 2.0 <= z[3].hi, "{z:?}");
        }
        // A box with an infinite end is refused.
        let wide = [Interval::new(f64::NEG_INFINITY, 2.0), iv(0), iv(0), iv(2)];
        assert!(proven_minimiser(&q, &wide, 53).is_err());
    }

    #[test]
    fn interiors_meet_only_where_they_do() {
        let int = |v: [i64; 3]| v.map(Rat::from);
        let span = [Rat::zero(), Rat::one()];
        let t = Rat::zero();
        let id = Motion::identity;
        let sphere = |r: i64, c: [Rat; 3]| placed(int([r, r, r]), c, id());
        let thin = Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(64)).unwrap();
        let needle = placed(
            [r(2), thin.clone(), thin],
            int([0, 0, 0]),
            [2, 0, 0, 1].map(Rat::from),
        );
        let meet = |a: &Body, b: &Body| interiors_meet::<Interval>((a, b, &span), (&t, &t), 53);
        // B's centre inside A; centres outside each other; a needle
        // through a sphere across its axis.
        assert!(meet(&sphere(2, int([0, 0, 0])), &sphere(1, int([1, 0, 0]))));
        assert!(meet(
            &sphere(1, int([0, 0, 0])),
            &sphere(1, [q(3, 2), r(0), r(0)])
        ));
        assert!(meet(&needle, &sphere(1, [q(-2, 5), q(3, 10), r(0)])));
        // Touching (at (1, 0, 0) and at the needle's tip) or apart: never.
        for (a, b) in [
            (sphere(1, int([0, 0, 0])), sphere(1, int([2, 0, 0]))),
            (needle.clone(), sphere(1, [q(12, 5), q(16, 5), r(0)])),
            (sphere(1, int([0, 0, 0])), sphere(1, int([3, 0, 0]))),
        ] {
            assert!(!meet(&a, &b) && !meet(&b, &a));
        }
        // Moving: unit spheres, B from (−4, 0, 0) to (4, 0, 0), touching at
        // t = 1/4 and 3/4, overlapping between.
        let a = sphere(1, int([0, 0, 0]));
        let b = Body {
            radii: int([1, 1, 1]),
            motion: Motion::Translation {
                center: Bezier::polynomial(vec![int([-4, 0, 0]), int([4, 0, 0])]),
                orientation: id(),
            },
        };
        let over = |lo: Rat, hi: Rat| interiors_meet::<Interval>((&a, &b, &span), (&lo, &hi), 53);
        assert!(over(q(9, 20), q(11, 20)));
        assert!(over(q(1, 2), q(1, 2)));
        assert!(!over(q(1, 5), q(3, 10)), "holds the touch at 1/4");
        assert!(!over(q(0, 1), q(1, 5)), "apart");
    }

    fn r(x: i64) -> Rat {
        Rat::from(x)
    }

    proptest! {
        /// Never claims overlap where the exact classification (Theorem
        /// 3.10 on `f`) says otherwise, and finds it where B's centre lies
        /// deep inside A.
        #[test]
        fn interiors_meet_agrees_with_theorem_3_10(
            ra in prop::array::uniform3(1i64..40),
            rb in prop::array::uniform3(1i64..40),
            c in prop::array::uniform3(-60i64..60),
        ) {
            use ccd_classify::Configuration;
            use ccd_quadric::{classify_pair, Ellipsoid};
            let tenth = |v: [i64; 3]| v.map(|x| q(x, 10));
            let (ra, rb, c) = (tenth(ra), tenth(rb), tenth(c));
            let zero = [Rat::zero(), Rat::zero(), Rat::zero()];
            let a = placed(ra.clone(), zero.clone(), Motion::identity());
            let b = placed(rb.clone(), c.clone(), Motion::identity());
            let span = [Rat::zero(), Rat::one()];
            let t = Rat::zero();
            let meet = interiors_meet::<Interval>((&a, &b, &span), (&t, &t), 53);
            // B's centre at most halfway out to A's surface: a witness of
            // its own, which the test must find.
            let deep = c
                .iter()
                .zip(&ra)
                .fold(Rat::zero(), |acc, (x, r)| &acc + &(&(x * x) / &(r * r)))
                <= Rat::from_frac(1, 4);
            let exact = classify_pair(&Ellipsoid::axis_aligned(ra, zero), &Ellipsoid::axis_aligned(rb, c));
            if meet {
                prop_assert_eq!(exact, Configuration::Overlap);
            }
            prop_assert!(meet || !deep, "B's centre deep inside A, not found");
        }
    }
}
