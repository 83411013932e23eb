//! Placements of a body as functions of the time `t`, over any [`Trig`]
//! number type (`f64` intervals, multi-precision intervals, dual numbers of
//! either), and from them the quadric matrices, `f(λ; t) = det(λA + B)`
//! and the five quantities of Theorem 3.10 — one generic code path through
//! `ccd-quadric` and `ccd-subres`.
//!
//! * `helical`: `R(t) = Rot(axis, rate·t)·R(orientation)` through the
//!   quaternion `q(t) = (cos(θ/2)·|axis|, sin(θ/2)·axis) ⊗ orientation`,
//!   `θ = rate·t`, so `R = M(q)/|q|²` (`|axis|` is a rigorous enclosure of
//!   a square root of a rational, the only irrational constant), and
//!   `c(t) = base + velocity·t + cos·cos(ωt) + sin·sin(ωt)`;
//! * the rational kinds: Bézier curves (and rational Bézier curves through
//!   their weights) by de Casteljau's algorithm in `u = (t − t0)/(t1 − t0)`.
//!
//! The inverse placement (up to a positive factor, see
//! [`ccd_quadric::rigid_inverse`] and [`ccd_quadric::affine_inverse`]) and
//! the congruence with the body's diagonal give `A(t)` with interior
//! `XᵀA(t)X < 0`, as on the exact path.

use crate::trig::Trig;
use ccd_arith::{Interval, Rat, RingOps};
use ccd_motion::{Body, HelicalCenter, Motion, Quat, Vec3};
use ccd_quadric::{
    affine_inverse, body_diagonal, characteristic, congruence, norm2, quat_mul, rigid_inverse,
    rotation_numerator, Mat3, Mat4,
};
use ccd_subres::{closed_forms, QuarticInvariants};

fn konst<N: Trig>(q: &Rat, prec: u32) -> N {
    N::constant(q, prec)
}

fn konst_vec<N: Trig, const D: usize>(v: &[Rat; D], prec: u32) -> [N; D] {
    std::array::from_fn(|i| konst(&v[i], prec))
}

/// A (rational) Bézier curve at `u` by de Casteljau's algorithm: the
/// weighted numerators `Σ Bᵢ(u)·wᵢ·Pᵢ` and the denominator `Σ Bᵢ(u)·wᵢ`.
///
/// The control rows `(wᵢ·Pᵢ, wᵢ)` are combined in place, row `i` of level
/// `r + 1` being `(1 − u)·rowᵢ + u·rowᵢ₊₁` of level `r` (ascending `i`
/// reads `rowᵢ₊₁` before it is overwritten); a point without a weight
/// (`wᵢ = 1`) is taken as it is, with no rational product.
fn bezier<N: Trig, const D: usize>(
    points: &[[Rat; D]],
    weights: Option<&[Rat]>,
    u: &N,
    prec: u32,
) -> ([N; D], N) {
    bezier_of(points.iter().map(|p| p.each_ref()), weights, u, prec)
}

/// [`bezier`] of control points given by reference (`points` yields each
/// point's `D` coordinates), so that a caller whose points are stored in
/// another shape (an affine `[L | d]`) need not copy them.
fn bezier_of<'a, N: Trig, const D: usize>(
    points: impl Iterator<Item = [&'a Rat; D]>,
    weights: Option<&[Rat]>,
    u: &N,
    prec: u32,
) -> ([N; D], N) {
    let one_minus = N::one().minus(u);
    let one = Rat::one();
    let mut rows: Vec<([N; D], N)> = points
        .enumerate()
        .map(|(i, p)| match weights.and_then(|ws| ws.get(i)) {
            Some(w) => (
                std::array::from_fn(|k| konst(&(p[k] * w), prec)),
                konst(w, prec),
            ),
            None => (p.map(|x| konst(x, prec)), konst(&one, prec)),
        })
        .collect();
    let lerp = |a: &N, b: &N| a.times(&one_minus).plus(&b.times(u));
    for level in 1..rows.len() {
        for i in 0..rows.len() - level {
            let (head, tail) = rows.split_at_mut(i + 1);
            let (row, next) = (&mut head[i], &tail[0]);
            for (x, y) in row.0.iter_mut().zip(&next.0) {
                *x = lerp(x, y);
            }
            row.1 = lerp(&row.1, &next.1);
        }
    }
    rows.into_iter()
        .next()
        .unwrap_or_else(|| (std::array::from_fn(|_| N::zero()), N::one()))
}

/// The helical orientation quaternion at `t` (not unit: `|q|² = |axis|²·|q0|²`).
fn helical_quaternion<N: Trig>(
    orientation: &Quat,
    axis: &Vec3,
    rate: &Rat,
    t: &N,
    prec: u32,
) -> [N; 4] {
    let half_angle = t.times(&konst(&rate.mul_pow2(-1), prec));
    let (s, c) = half_angle.sin_cos();
    let len2 = axis.iter().fold(Rat::zero(), |acc, x| &acc + &(x * x));
    let len = N::sqrt_rat(&len2, prec);
    let a: [N; 3] = konst_vec(axis, prec);
    let spin = [
        c.times(&len),
        s.times(&a[0]),
        s.times(&a[1]),
        s.times(&a[2]),
    ];
    quat_mul(&spin, &konst_vec(orientation, prec))
}

/// The helical centre `base + velocity·t + cos·cos(ωt) + sin·sin(ωt)`.
fn helical_center<N: Trig>(center: &HelicalCenter, t: &N, prec: u32) -> [N; 3] {
    let periodic = center.frequency.signum() != 0
        && center
            .cos
            .iter()
            .chain(&center.sin)
            .any(|x| x.signum() != 0);
    let (s, c) = if periodic {
        t.times(&konst(&center.frequency, prec)).sin_cos()
    } else {
        (N::zero(), N::one())
    };
    std::array::from_fn(|i| {
        let mut x =
            konst::<N>(&center.base[i], prec).plus(&konst::<N>(&center.velocity[i], prec).times(t));
        if center.cos[i].signum() != 0 {
            x = x.plus(&konst::<N>(&center.cos[i], prec).times(&c));
        }
        if center.sin[i].signum() != 0 {
            x = x.plus(&konst::<N>(&center.sin[i], prec).times(&s));
        }
        x
    })
}

/// The inverse placement `N(t)` of a motion (up to a positive factor, or a
/// nonzero one for affine motions).
fn inverse_placement<N: Trig>(motion: &Motion, span: &[Rat; 2], t: &N, prec: u32) -> Mat4<N> {
    let rigid =
        |q: &[N; 4], c: &[N; 3], w: &N| rigid_inverse(&rotation_numerator(q), &norm2(q), c, w);
    let u = || {
        let inv_dt = (&span[1] - &span[0]).recip().unwrap_or_else(Rat::one);
        t.minus(&konst(&span[0], prec)).times(&konst(&inv_dt, prec))
    };
    match motion {
        Motion::Static {
            center,
            orientation,
        } => rigid(
            &konst_vec(orientation, prec),
            &konst_vec(center, prec),
            &N::one(),
        ),
        Motion::Translation {
            center,
            orientation,
        } => {
            let (c, w) = bezier(&center.points, center.weights.as_deref(), &u(), prec);
            rigid(&konst_vec(orientation, prec), &c, &w)
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            let uu = u();
            let (q, _) = bezier(&orientation.points, None, &uu, prec);
            let (c, w) = bezier(&center.points, center.weights.as_deref(), &uu, prec);
            rigid(&q, &c, &w)
        }
        Motion::Affine { matrix } => {
            let flat = matrix
                .points
                .iter()
                .map(|m| std::array::from_fn::<_, 12, _>(|k| &m[k / 4][k % 4]));
            let (v, w) = bezier_of(flat, matrix.weights.as_deref(), &u(), prec);
            let l: Mat3<N> = std::array::from_fn(|r| std::array::from_fn(|k| v[4 * r + k].clone()));
            let d: [N; 3] = std::array::from_fn(|r| v[4 * r + 3].clone());
            affine_inverse(&l, &d, &w)
        }
        Motion::Helical {
            orientation,
            axis,
            rate,
            center,
        } => {
            let q = helical_quaternion(orientation, axis, rate, t, prec);
            rigid(&q, &helical_center(center, t, prec), &N::one())
        }
    }
}

/// The centre `c(t)` of a body over the times `t`, enclosed in `f64`
/// intervals (it does not depend on the spin: the helical centre is
/// `base + velocity·t + cos·cos(ωt) + sin·sin(ωt)`, the rational kinds'
/// centre their (rational) Bézier curve). `None` for the affine kind, whose
/// radii do not bound its extent, or when a weight enclosure meets zero.
/// With the bounding spheres of radius `max rᵢ` and the inscribed spheres of
/// radius `min rᵢ` about these centres this proves separation or overlap
/// whatever the orientation (`run`'s gap certificates).
pub fn center_at(body: &Body, span: &[Rat; 2], t: &Interval) -> Option<[Interval; 3]> {
    use crate::real::Real;
    let u = || {
        let inv_dt = (&span[1] - &span[0]).recip().unwrap_or_else(Rat::one);
        t.minus(&Interval::from_rat(&span[0]))
            .times(&Interval::from_rat(&inv_dt))
    };
    let divided = |(c, w): ([Interval; 3], Interval)| -> Option<[Interval; 3]> {
        let v: [Option<Interval>; 3] = std::array::from_fn(|i| Real::div(&c[i], &w));
        Some([v[0]?, v[1]?, v[2]?])
    };
    match &body.motion {
        Motion::Static { center, .. } => Some(center.each_ref().map(Interval::from_rat)),
        Motion::Translation { center, .. } | Motion::Rigid { center, .. } => {
            divided(bezier(&center.points, center.weights.as_deref(), &u(), 53))
        }
        Motion::Affine { .. } => None,
        Motion::Helical { center, .. } => Some(helical_center(center, t, 53)),
    }
}

/// The quadric matrix `A(t)` of a body (interior `XᵀA(t)X < 0`), up to a
/// positive factor, enclosed in the number type `N`.
pub fn quadric_at<N: Trig>(body: &Body, span: &[Rat; 2], t: &N, prec: u32) -> Mat4<N> {
    let n = inverse_placement(&body.motion, span, t, prec);
    congruence(&n, &body_diagonal(&konst_vec(&body.radii, prec)))
}

/// The world point the inverse placement `n` maps to the body origin,
/// approximately: `−L⁻¹·v` for `n = [[L, v], [0, s]]` (Cramer's rule in
/// `f64`); `None` when degenerate.
fn approx_center<N: Trig>(n: &Mat4<N>) -> Option<[f64; 3]> {
    let l: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| n[i][j].approx_value()));
    let v: [f64; 3] = std::array::from_fn(|i| n[i][3].approx_value());
    let det = |m: &[[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(&l);
    if !d.is_finite() || d == 0.0 {
        return None;
    }
    let x: [f64; 3] = std::array::from_fn(|k| {
        let mut mk = l;
        for (row, vi) in mk.iter_mut().zip(&v) {
            row[k] = -vi;
        }
        det(&mk) / d
    });
    x.iter().all(|c| c.is_finite()).then_some(x)
}

/// `n·T(s)` with `T(s) = [[I, s], [0, 1]]`: the same inverse placement in
/// world coordinates whose origin is moved to `s`.
fn shifted<N: Trig>(mut n: Mat4<N>, s: &[N; 3]) -> Mat4<N> {
    for row in n.iter_mut() {
        let mut last = row[3].clone();
        for (x, sj) in row.iter().take(3).zip(s) {
            if !x.is_zero() {
                last = last.plus(&x.times(sj));
            }
        }
        row[3] = last;
    }
    n
}

/// Quadric matrices of both bodies in a world frame centred between them.
///
/// Moving the world origin is the congruence by `T(s)` with
/// `det T(s) = 1`, so `det(λA + B)` — and everything read from it — is
/// exactly the same function of t for every constant `s`; centring the
/// frame between the bodies keeps the matrix entries small, which makes
/// the interval evaluation of the closed forms (whose terms cancel
/// heavily) much tighter. `s` is a dyadic constant chosen per evaluation.
fn quadrics_centred<N: Trig>(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    t: &N,
    prec: u32,
) -> (Mat4<N>, Mat4<N>) {
    let (_, qa, qb) = centred_quadrics(a, b, span, t, prec);
    (qa, qb)
}

/// The quadric matrices of both bodies in the world frame whose origin is
/// moved to the returned dyadic point `s` between them (a world point `X`
/// has coordinates `X − s` there), enclosed in `N` at the time `t`: the
/// frame [`characteristic_at`] uses, also for points (add `s` back).
pub fn centred_quadrics<N: Trig>(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    t: &N,
    prec: u32,
) -> ([Rat; 3], Mat4<N>, Mat4<N>) {
    let na = inverse_placement(&a.motion, span, t, prec);
    let nb = inverse_placement(&b.motion, span, t, prec);
    let (origin, na, nb) = match (approx_center(&na), approx_center(&nb)) {
        (Some(ca), Some(cb)) => {
            // The midpoint rounded to a multiple of 2^−10: an exact constant.
            let origin: [Rat; 3] = std::array::from_fn(|i| {
                let v = ((ca[i] + cb[i]) * 512.0).round();
                Rat::from_f64_exact(v)
                    .unwrap_or_else(Rat::zero)
                    .mul_pow2(-10)
            });
            let s: [N; 3] = std::array::from_fn(|i| konst(&origin[i], prec));
            (origin, shifted(na, &s), shifted(nb, &s))
        }
        _ => (std::array::from_fn(|_| Rat::zero()), na, nb),
    };
    (
        origin,
        congruence(&na, &body_diagonal(&konst_vec(&a.radii, prec))),
        congruence(&nb, &body_diagonal(&konst_vec(&b.radii, prec))),
    )
}

/// Body `a`'s unit-sphere frame at the time `t`: coordinates `s` in which
/// `a` is the unit ball `|s| ≤ 1` (its quadric, up to a positive factor,
/// `diag(1, 1, 1, −1)`), and `b`'s quadric in them.
///
/// With `Nₐ` the inverse placement of `a` (world → body, up to a factor)
/// and `S = diag(rₐ, 1)`, `W = adj(Nₐ)·S` maps `(s, 1)` to a world point
/// in homogeneous coordinates, and `b`'s quadric in the frame is
/// `(N_b·W)ᵀ·D_b·(N_b·W)`. The frame's entries carry `a`'s radii as
/// factors, not their inverse squares: a needle or a disc of extreme ratio
/// gives small entries here instead of huge cancelling ones.
#[derive(Clone, Debug)]
pub struct UnitFrame<N> {
    /// `W`: `(s, 1)` ↦ world point (homogeneous; divide by the last entry).
    pub to_world: Mat4<N>,
    /// `Nₐ`: world → `a`'s body coordinates, up to a nonzero factor
    /// (`Nₐ[3] = (0, 0, 0, w)`; `a`'s outward normal at the frame point
    /// `s` points along `w·Nₐ[0..3][0..3]ᵀ·(s/rₐ)`).
    pub inverse_a: Mat4<N>,
    /// `b`'s quadric in the frame (positive factor).
    pub quadric_b: Mat4<N>,
}

/// [`UnitFrame`] of the bodies at `t`.
pub fn unit_frame<N: Trig>(a: &Body, b: &Body, span: &[Rat; 2], t: &N, prec: u32) -> UnitFrame<N> {
    let inverse_a = inverse_placement(&a.motion, span, t, prec);
    let radii: [N; 3] = konst_vec(&a.radii, prec);
    let adj = ccd_quadric::adj4(&inverse_a);
    let to_world: Mat4<N> = std::array::from_fn(|i| {
        std::array::from_fn(|j| match radii.get(j) {
            Some(r) => adj[i][j].times(r),
            None => adj[i][j].clone(),
        })
    });
    let nb = inverse_placement(&b.motion, span, t, prec);
    let m: Mat4<N> = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..4).fold(N::zero(), |acc, k| {
                if nb[i][k].is_zero() || to_world[k][j].is_zero() {
                    acc
                } else {
                    acc.plus(&nb[i][k].times(&to_world[k][j]))
                }
            })
        })
    });
    let quadric_b = congruence(&m, &body_diagonal(&konst_vec(&b.radii, prec)));
    UnitFrame {
        to_world,
        inverse_a,
        quadric_b,
    }
}

/// `f(λ; t) = det(λA(t) + B(t))` as `[e, a, b, c, d]` (high → low),
/// enclosed in `N` at the time `t`.
pub fn characteristic_at<N: Trig>(a: &Body, b: &Body, span: &[Rat; 2], t: &N, prec: u32) -> [N; 5] {
    let (ma, mb) = quadrics_centred(a, b, span, t, prec);
    characteristic(&ma, &mb)
}

/// [`characteristic_at`] and the five quantities of Theorem 3.10 (Section 4
/// closed forms), enclosed in `N` at the time `t`.
pub fn invariants_at<N: Trig>(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    t: &N,
    prec: u32,
) -> ([N; 5], QuarticInvariants<N>) {
    let f = characteristic_at(a, b, span, t, prec);
    let inv = closed_forms(&f);
    (f, inv)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(x: i64) -> Rat {
        Rat::from(x)
    }

    #[test]
    fn helical_rotation_is_right_handed_and_centre_follows_the_helix() {
        // Spin about z at rate 1: at t = π/2 the body x axis points along y.
        let motion = Motion::Helical {
            orientation: Motion::identity(),
            axis: [r(0), r(0), r(2)],
            rate: r(1),
            center: HelicalCenter {
                base: [r(0), r(0), r(0)],
                velocity: [r(0), r(0), r(3)],
                cos: [r(1), r(0), r(0)],
                sin: [r(0), r(1), r(0)],
                frequency: r(1),
            },
        };
        let t = Interval::point(std::f64::consts::FRAC_PI_2);
        let Motion::Helical {
            orientation,
            axis,
            rate,
            center,
        } = &motion
        else {
            unreachable!()
        };
        let q = helical_quaternion(orientation, axis, rate, &t, 53);
        let m = rotation_numerator(&q);
        let n = norm2(&q);
        // R = M/n; column 0 = R·e_x ≈ (0, 1, 0).
        let col0 = [
            m[0][0].mid() / n.mid(),
            m[1][0].mid() / n.mid(),
            m[2][0].mid() / n.mid(),
        ];
        assert!(
            col0[0].abs() < 1e-12 && (col0[1] - 1.0).abs() < 1e-12,
            "{col0:?}"
        );
        let c = helical_center(center, &t, 53);
        assert!(c[0].contains_zero() && c[1].lo <= 1.0 && c[1].hi >= 1.0);
        assert!((c[2].mid() - 1.5 * std::f64::consts::PI).abs() < 1e-12);
    }

    #[test]
    fn bezier_matches_exact_evaluation() {
        let pts = [[r(0), r(1)], [r(4), r(1)], [r(2), r(-3)]];
        let ws = [r(1), r(3), r(2)];
        let u = Interval::point(0.25);
        let (c, w) = bezier(&pts, Some(&ws), &u, 53);
        // B0 = 9/16, B1 = 6/16, B2 = 1/16; weights 1, 3, 2.
        let den = 9.0 / 16.0 + 18.0 / 16.0 + 2.0 / 16.0;
        let x = (18.0 * 4.0 / 16.0 + 2.0 * 2.0 / 16.0) / den;
        assert!((c[0].mid() / w.mid() - x).abs() < 1e-14);
    }

    /// The level-by-level de Casteljau evaluation [`bezier`] replaced (a
    /// new row vector per level, every point multiplied by its weight,
    /// `1` when there is none): the in-place one must give the same
    /// enclosures bit for bit, the printed contact boxes depending on them.
    fn bezier_by_levels<N: Trig, const D: usize>(
        points: &[[Rat; D]],
        weights: Option<&[Rat]>,
        u: &N,
        prec: u32,
    ) -> Vec<N> {
        let one_minus = N::one().minus(u);
        let mut rows: Vec<Vec<N>> = points
            .iter()
            .enumerate()
            .map(|(i, p)| {
                let w = weights
                    .and_then(|ws| ws.get(i))
                    .cloned()
                    .unwrap_or_else(Rat::one);
                let mut row: Vec<N> = p.iter().map(|x| konst(&(x * &w), prec)).collect();
                row.push(konst(&w, prec));
                row
            })
            .collect();
        while rows.len() > 1 {
            rows = rows
                .windows(2)
                .map(|w| {
                    w[0].iter()
                        .zip(&w[1])
                        .map(|(a, b)| a.times(&one_minus).plus(&b.times(u)))
                        .collect()
                })
                .collect();
        }
        rows.pop().unwrap_or_else(|| vec![N::zero(); D + 1])
    }

    fn flat<N: Clone, const D: usize>((c, w): ([N; D], N)) -> Vec<N> {
        c.iter().cloned().chain([w]).collect()
    }

    use proptest::prelude::*;

    fn small_rat() -> impl Strategy<Value = Rat> {
        (-2000i64..2000, 1i64..700).prop_map(|(n, d)| Rat::new(n.into(), d.into()).unwrap())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]
        #[test]
        fn in_place_bezier_is_the_level_by_level_one(
            points in proptest::collection::vec([small_rat(), small_rat(), small_rat()], 1..5),
            weights in proptest::collection::vec(1i64..9, 0..5),
            weighted in any::<bool>(),
            u in (0i64..=1000, 0i64..40),
        ) {
            let ws: Vec<Rat> = weights.into_iter().map(r).collect();
            let ws = weighted.then_some(ws.as_slice());
            let (lo, hi) = (Rat::new(u.0.into(), 1000.into()).unwrap(), Rat::new((u.0 + u.1).into(), 1000.into()).unwrap());
            let t = Interval::from_rat(&lo).hull(&Interval::from_rat(&hi));
            prop_assert_eq!(flat(bezier(&points, ws, &t, 53)), bezier_by_levels(&points, ws, &t, 53));
            let big = crate::BigInterval::from_rat(&lo, 128).hull(&crate::BigInterval::from_rat(&hi, 128));
            prop_assert_eq!(flat(bezier(&points, ws, &big, 128)), bezier_by_levels(&points, ws, &big, 128));
        }
    }

    /// `a`'s unit-sphere frame: a point `s` of the unit sphere maps to a
    /// point of `a`'s surface, `b`'s quadric in the frame is `b`'s world
    /// quadric at the mapped point, and `w·N[0..3][0..3]ᵀ·(s/r)` points
    /// along `a`'s outward gradient — for a turned static body, a moving
    /// one and an affine one with a reflection (`w < 0`).
    #[test]
    fn unit_frame_maps_the_sphere_onto_the_body() {
        use ccd_arith::BigInterval;
        use ccd_motion::{Bezier, Motion};
        let q = |p: i64, d: i64| Rat::from_frac(p, d);
        let turned = Body {
            radii: [q(3, 2), q(1, 3), r(2)],
            motion: Motion::Static {
                center: [r(1), q(-2, 7), r(3)],
                orientation: [r(2), r(1), r(0), r(-1)],
            },
        };
        let moving = Body {
            radii: [r(1), q(1, 2), q(3, 4)],
            motion: Motion::Translation {
                center: Bezier::polynomial(vec![[r(-1), r(0), r(2)], [r(4), r(5), r(-2)]]),
                orientation: [r(1), r(-2), r(2), r(1)],
            },
        };
        let reflected = Body {
            radii: [r(1), r(2), q(1, 2)],
            motion: Motion::Affine {
                matrix: Bezier::constant(
                    [[-2, 1, 0, 3], [0, 1, 0, -1], [1, 0, 3, 2]].map(|row| row.map(Rat::from)),
                ),
            },
        };
        let span = [Rat::zero(), r(2)];
        let prec = 300;
        let t = BigInterval::from_rat(&q(3, 5), prec);
        let on_sphere = [[q(3, 5), q(4, 5), r(0)], [r(0), q(-5, 13), q(12, 13)]];
        for (a, b) in [
            (&turned, &moving),
            (&moving, &reflected),
            (&reflected, &turned),
        ] {
            let frame = unit_frame::<BigInterval>(a, b, &span, &t, prec);
            let (qa, qb) = (
                quadric_at(a, &span, &t, prec),
                quadric_at(b, &span, &t, prec),
            );
            for s in &on_sphere {
                let hat: [BigInterval; 4] = std::array::from_fn(|i| {
                    BigInterval::from_rat(s.get(i).unwrap_or(&Rat::one()), prec)
                });
                let apply = |m: &Mat4<BigInterval>, v: &[BigInterval; 4]| -> [BigInterval; 4] {
                    std::array::from_fn(|i| {
                        (0..4).fold(BigInterval::zero(), |acc, j| {
                            acc.plus(&m[i][j].times(&v[j]))
                        })
                    })
                };
                let dot = |x: &[BigInterval; 4], y: &[BigInterval; 4]| {
                    (0..4).fold(BigInterval::zero(), |acc, i| acc.plus(&x[i].times(&y[i])))
                };
                let x = apply(&frame.to_world, &hat);
                // On a's surface.
                assert!(dot(&x, &apply(&qa, &x)).contains_zero());
                // b's quadric: the frame's at s is the world's at x.
                let diff =
                    dot(&hat, &apply(&frame.quadric_b, &hat)).minus(&dot(&x, &apply(&qb, &x)));
                assert!(diff.contains_zero(), "{diff:?}");
                // The normal rule against a's world gradient Q_a·X (X = x/x₃).
                let n = &frame.inverse_a;
                let w = n[3][3].approx().signum();
                let rule: [f64; 3] = std::array::from_fn(|c| {
                    w * (0..3)
                        .map(|k| n[k][c].approx() * s[k].to_f64() / a.radii[k].to_f64())
                        .sum::<f64>()
                });
                let grad = apply(&qa, &x);
                let x3 = x[3].approx();
                let g: [f64; 3] = std::array::from_fn(|c| grad[c].approx() / x3);
                let cos = (0..3).map(|i| rule[i] * g[i]).sum::<f64>()
                    / (rule.iter().map(|v| v * v).sum::<f64>().sqrt()
                        * g.iter().map(|v| v * v).sum::<f64>().sqrt());
                assert!((cos - 1.0).abs() < 1e-12, "{cos}");
            }
        }
    }
}
