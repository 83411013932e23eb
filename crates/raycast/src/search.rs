//! The `f64` search for the normals the proofs start from: an outer
//! ellipsoid of `K` for a first guess, then Newton's method on `∇φ = 0`
//! over the plane orthogonal to the current normal. Nothing here is
//! trusted: [`crate::verify`] proves or rejects what it returns.

use crate::line::Line;
use crate::scalar::{apply, axpy, cross, dot, form, M3, V3};
use crate::support::{jet, support_k};

/// Newton steps before the search gives up.
const MAX_STEPS: usize = 40;
/// A step shorter than this (on a unit normal) ends the search.
const CONVERGED: f64 = 1e-12;
/// A last step shorter than this still returns the normal after
/// [`MAX_STEPS`] ([`polish`]).
const NOISE_FLOOR: f64 = 1e-6;

/// Where the ray meets an outer ellipsoid of `K`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Guess {
    /// It crosses it: the outward normals at the entry and at the exit.
    Crosses {
        /// Normal at the entry (`n·v < 0`).
        entry: V3<f64>,
        /// Normal at the exit (`n·v > 0`).
        exit: V3<f64>,
    },
    /// It misses it: the normal at the ray's point nearest in the
    /// ellipsoid's metric, whose plane is parallel to the ray.
    Misses(V3<f64>),
}

/// `x/|x|` (`None` for zero or a non-finite length).
pub fn unit(x: &V3<f64>) -> Option<V3<f64>> {
    let n = dot(x, x).sqrt();
    (n > 0.0 && n.is_finite()).then(|| x.map(|c| c / n))
}

/// `m⁻¹` by the adjugate (`None` when singular).
fn inverse(m: &M3<f64>) -> Option<M3<f64>> {
    let c = |i: usize, j: usize| {
        let (r0, r1) = ((i + 1) % 3, (i + 2) % 3);
        let (c0, c1) = ((j + 1) % 3, (j + 2) % 3);
        m[r0][c0] * m[r1][c1] - m[r0][c1] * m[r1][c0]
    };
    let det = (0..3).map(|j| m[0][j] * c(0, j)).sum::<f64>();
    (det != 0.0 && det.is_finite())
        .then(|| std::array::from_fn(|i| std::array::from_fn(|j| c(j, i) / det)))
}

/// The ray against `E_p = A₀ ⊕ (−B₀)`'s outer ellipsoid
/// `{x : xᵀ((1 + 1/p)P_A + (1 + p)P_B)⁻¹x <= 1}`, which holds `K` for every
/// `p > 0` (its support `√((1 + 1/p)h_A² + (1 + p)h_B²) >= h_A + h_B`) and
/// touches it in the direction `dir` for `p = h_A(dir)/h_B(dir)`.
fn outer(line: &Line<f64>, dir: &V3<f64>) -> Option<Guess> {
    let h = |p: &M3<f64>| form(dir, p, dir).sqrt();
    let p = h(&line.pa) / h(&line.pb);
    let (wa, wb) = (1.0 + 1.0 / p, 1.0 + p);
    let m =
        std::array::from_fn(|i| std::array::from_fn(|j| wa * line.pa[i][j] + wb * line.pb[i][j]));
    let q = inverse(&m)?;
    let (c0, v) = (&line.c0, &line.v);
    let a = form(v, &q, v);
    let b = form(v, &q, c0);
    let c = form(c0, &q, c0) - 1.0;
    if !a.is_finite() || a <= 0.0 {
        return None;
    }
    let normal = |s: f64| unit(&apply(&q, &axpy(c0, s, v)));
    let disc = b * b - a * c;
    if disc < 0.0 {
        return Some(Guess::Misses(normal(-b / a)?));
    }
    let r = disc.sqrt();
    Some(Guess::Crosses {
        entry: normal((-b - r) / a)?,
        exit: normal((-b + r) / a)?,
    })
}

/// A first guess: the outer ellipsoid tuned (three times) to touch `K` in
/// the direction of the last entry normal.
pub fn guess(line: &Line<f64>) -> Option<Guess> {
    let mut dir = unit(&line.c0).unwrap_or([1.0, 0.0, 0.0]);
    let mut g = outer(line, &dir)?;
    for _ in 0..3 {
        match g {
            Guess::Crosses { entry, .. } => dir = entry,
            Guess::Misses(n) => dir = n,
        }
        g = outer(line, &dir)?;
    }
    Some(g)
}

/// Two unit vectors completing the unit `n` to an orthonormal basis.
pub fn basis(n: &V3<f64>) -> [V3<f64>; 2] {
    let k = (0..3)
        .min_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs()))
        .unwrap_or(0);
    let mut e = [0.0; 3];
    e[k] = 1.0;
    let e1 = unit(&cross(n, &e)).unwrap_or([0.0, 1.0, 0.0]);
    let e2 = cross(n, &e1);
    [e1, e2]
}

/// `G = Eᵀ∇φ` and `J = Eᵀ∇²φE` in the plane `E = basis(n)`.
pub fn reduced(grad: &V3<f64>, hess: &M3<f64>, e: &[V3<f64>; 2]) -> ([f64; 2], [[f64; 2]; 2]) {
    let g = e.map(|ei| dot(&ei, grad));
    let j = e.map(|ei| e.map(|ej| form(&ei, hess, &ej)));
    (g, j)
}

/// `m⁻¹` of a 2×2 matrix (`None` when singular).
pub fn inverse2(m: &[[f64; 2]; 2]) -> Option<[[f64; 2]; 2]> {
    let det = m[0][0] * m[1][1] - m[0][1] * m[1][0];
    (det != 0.0 && det.is_finite()).then(|| {
        [
            [m[1][1] / det, -m[0][1] / det],
            [-m[1][0] / det, m[0][0] / det],
        ]
    })
}

/// Newton's method on `∇φ = 0` from `n`, keeping `sign(n·v) = side`
/// (`−1`: the entry, where `φ` has its maximum; `+1`: the exit, its
/// minimum). Where the reduced Hessian is not definite with the sign of
/// that extremum the step follows the gradient instead; a step goes at
/// most half the way to the side's edge `n·v = 0` (and at most `1/2`).
/// `None` when the side is left, or when the steps neither converge nor
/// end shorter than `NOISE_FLOOR` (10⁻⁶).
pub fn polish(line: &Line<f64>, n: &V3<f64>, side: f64) -> Option<V3<f64>> {
    polished(line, n, side).map(|p| p.normal)
}

/// A normal from [`polish`], and how its steps ended.
#[derive(Clone, Copy, Debug)]
pub struct Polished {
    /// The unit normal.
    pub normal: V3<f64>,
    /// Whether the steps converged (a last step below `10⁻¹²`), rather
    /// than stopping at the noise floor that `f64` rounding leaves near a
    /// graze or a near miss.
    pub converged: bool,
}

/// [`polish`], saying whether the steps converged.
pub fn polished(line: &Line<f64>, n: &V3<f64>, side: f64) -> Option<Polished> {
    let mut n = unit(n)?;
    let mut last = f64::INFINITY;
    for _ in 0..MAX_STEPS {
        let j = jet(line, &n);
        if j.d.is_nan() || j.d * side <= 0.0 || !j.phi.is_finite() {
            return None;
        }
        let e = basis(&n);
        let (g, h) = reduced(&j.grad, &j.hess, &e);
        // Maximum (side < 0): h negative definite; minimum: positive.
        let definite = h[0][0] * side > 0.0 && h[0][0] * h[1][1] - h[0][1] * h[1][0] > 0.0;
        let mut w = match inverse2(&h) {
            Some(y) if definite => [
                -(y[0][0] * g[0] + y[0][1] * g[1]),
                -(y[1][0] * g[0] + y[1][1] * g[1]),
            ],
            _ => [-side * g[0], -side * g[1]],
        };
        let len = (w[0] * w[0] + w[1] * w[1]).sqrt();
        if !len.is_finite() {
            return None;
        }
        // At most half the way to the plane `n·v = 0` (the side's edge,
        // about |D|/|v| away), and at most 1/2.
        let room = 0.5 * (j.d.abs() / dot(&line.v, &line.v).sqrt()).min(1.0);
        if len > room {
            w = w.map(|x| x * room / len);
        }
        n = unit(&axpy(&axpy(&n, w[0], &e[0]), w[1], &e[1]))?;
        if len < CONVERGED {
            return Some(Polished {
                normal: n,
                converged: true,
            });
        }
        last = len;
    }
    // Near a graze f64 rounding leaves a noise floor above CONVERGED (∇φ
    // is a cancellation divided by a small n·v): a normal that close is
    // what the double-word steps of the proof start from.
    (last < NOISE_FLOOR).then_some(Polished {
        normal: n,
        converged: false,
    })
}

/// A plane parallel to the ray that keeps it outside `K`, for a ray that
/// misses `K` (a near miss that crosses the outer ellipsoid): Newton's
/// method on `θ` for the maximum of `ψ(θ) = n·c₀ − h_K(n)` over the unit
/// normals `n(θ) = cos θ·e₁ + sin θ·e₂` orthogonal to `v`, from `start`
/// projected on that plane. `ψ' = (c₀ − ∇h_K)·n'` and
/// `ψ'' = −n'ᵀ∇²h_K n' − (c₀ − ∇h_K)·n`; where `ψ'' >= 0` a short step
/// climbs the slope. The normal is returned when the steps converge,
/// whether or not `ψ > 0` there ([`crate::verify::apart`] decides).
pub fn parallel(line: &Line<f64>, start: &V3<f64>) -> Option<V3<f64>> {
    let v = unit(&line.v)?;
    let [e1, e2] = basis(&v);
    let mut theta = dot(start, &e2).atan2(dot(start, &e1));
    for _ in 0..MAX_STEPS {
        let (c, s) = (theta.cos(), theta.sin());
        let n = axpy(&e1.map(|x| x * c), s, &e2);
        let dn = axpy(&e1.map(|x| -x * s), c, &e2);
        let (_, g, h) = support_k(line, &n);
        let gap: V3<f64> = std::array::from_fn(|i| line.c0[i] - g[i]);
        let d1 = dot(&gap, &dn);
        let d2 = -form(&dn, &h, &dn) - dot(&gap, &n);
        let step = if d2 < 0.0 {
            -d1 / d2
        } else {
            0.1 * d1.signum()
        };
        if !step.is_finite() {
            return None;
        }
        theta += step.clamp(-0.5, 0.5);
        if step.abs() < CONVERGED {
            return Some(n);
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spheres(c0: V3<f64>, v: V3<f64>) -> Line<f64> {
        let i = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        Line {
            pa: i,
            pb: i.map(|r| r.map(|x| 4.0 * x)),
            c0,
            v,
            a0: [0.0; 3],
            da: [0.0; 3],
            radii: [2.0, 1.0],
        }
    }

    /// Two spheres of radii 1 and 2: `K` is the ball of radius 3, so the
    /// ray `(−10 + 20u, 1, 0)` enters at `u = (10 − √8)/20`.
    #[test]
    fn spheres_are_entered_where_the_ball_of_summed_radii_is() {
        let l = spheres([-10.0, 1.0, 0.0], [20.0, 0.0, 0.0]);
        let Some(Guess::Crosses { entry, exit }) = guess(&l) else {
            panic!("the ray crosses")
        };
        let n = polish(&l, &entry, -1.0).expect("entry");
        let t = jet(&l, &n).phi;
        assert!((t - (10.0 - 8f64.sqrt()) / 20.0).abs() < 1e-15, "{t}");
        let m = polish(&l, &exit, 1.0).expect("exit");
        assert!((jet(&l, &m).phi - (10.0 + 8f64.sqrt()) / 20.0).abs() < 1e-15);
        // The normal at the entry points from the ball's centre to it.
        assert!((n[0] + 8f64.sqrt() / 3.0).abs() < 1e-12 && (n[1] - 1.0 / 3.0).abs() < 1e-12);
    }

    /// A clean crossing's normals converge; a ray that only grazes the
    /// ball (overlap depth 10⁻¹²) leaves the entry's steps at the noise
    /// floor, which [`polished`] reports.
    #[test]
    fn polishing_says_whether_it_converged() {
        let clean = spheres([-10.0, 1.0, 0.0], [20.0, 0.0, 0.0]);
        let Some(Guess::Crosses { entry, .. }) = guess(&clean) else {
            panic!("the ray crosses")
        };
        assert!(polished(&clean, &entry, -1.0).expect("entry").converged);
        let graze = spheres([-10.0, 3.0 - 1e-12, 0.0], [20.0, 0.0, 0.0]);
        let Some(Guess::Crosses { entry, .. }) = guess(&graze) else {
            panic!("the ray crosses")
        };
        assert!(
            !polished(&graze, &entry, -1.0)
                .expect("stops at the noise floor")
                .converged
        );
    }

    #[test]
    fn a_ray_past_the_ball_misses_its_outer_ellipsoid() {
        let l = spheres([-10.0, 3.5, 0.0], [20.0, 0.0, 0.0]);
        let Some(Guess::Misses(n)) = guess(&l) else {
            panic!("the ray misses")
        };
        assert!(n[1] > 0.99, "{n:?}");
        assert!(guess(&spheres([1.0, 5.0, 0.0], [0.0; 3])).is_none());
    }

    /// A ray just past the ball of radius 3 (at distance 3.01) crosses
    /// the outer ellipsoid of the tuned guess only when it is untuned; the
    /// parallel plane's normal points from the ball to the ray.
    #[test]
    fn parallel_planes_point_at_a_near_miss() {
        let l = spheres([-10.0, 3.01, 0.0], [20.0, 0.0, 0.0]);
        let n = parallel(&l, &[0.3, 0.5, 0.8]).expect("converges");
        assert!((n[1] - 1.0).abs() < 1e-12, "{n:?}");
        let (h, _, _) = support_k(&l, &n);
        assert!(dot(&n, &l.c0) - h > 0.009);
    }

    #[test]
    fn inverses_are_inverses() {
        let m = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.25], [0.5, 0.25, 2.0]];
        let q = inverse(&m).expect("regular");
        let prod: M3<f64> = std::array::from_fn(|i| {
            std::array::from_fn(|j| (0..3).map(|k| m[i][k] * q[k][j]).sum())
        });
        for (i, row) in prod.iter().enumerate() {
            for (j, p) in row.iter().enumerate() {
                assert!((p - f64::from(u8::from(i == j))).abs() < 1e-15);
            }
        }
        let y = inverse2(&[[2.0, 1.0], [1.0, 3.0]]).expect("regular");
        assert!((y[0][0] - 0.6).abs() < 1e-15 && (y[0][1] + 0.2).abs() < 1e-15);
        assert!(inverse2(&[[1.0, 2.0], [2.0, 4.0]]).is_none());
    }
}
