//! The entry time of the ray as a function of a plane's normal, and its
//! first two derivatives.
//!
//! For a normal `n` with `D = n·v ≠ 0`, the half-space
//! `{x : n·x <= h_K(n)}` holds `K`, and the ray crosses its boundary at
//!
//! ```text
//! φ(n) = (h_K(n) − n·c₀) / (n·v).
//! ```
//!
//! When `D < 0` the ray is outside the half-space, hence outside `K`,
//! for every `u < φ(n)`; when `D > 0`, for every `u > φ(n)`. At a
//! stationary point `∇φ(n*) = 0` the identity `D·∇φ = ∇h_K − c₀ − φ·v`
//! gives `c(φ(n*)) = ∇h_K(n*)`, the point of `K` where `n*` is the outward
//! normal: the ray touches `∂K` there. So the entry time of the ray is
//! `φ(n*)` for a stationary `n*` with `D < 0` (the maximum of `φ` there)
//! and the exit time is `φ(n*)` for one with `D > 0` (the minimum), and
//! the bodies' common point at that instant is `a(u) + ∇h_A(n*)`.
//!
//! With `N = h_K(n) − n·c₀` and `h(n) = √(nᵀPn)`, `∇h = Pn/h` (the
//! support point) and `∇²h = (P − ∇h·∇hᵀ)/h`:
//!
//! ```text
//! ∇φ  = (∇N − φ·v) / D
//! ∇²φ = (∇²N − ∇φ·vᵀ − v·∇φᵀ) / D
//! ```
//!
//! `φ` is homogeneous of degree 0, so `n` need not be a unit vector.

use crate::line::Line;
use crate::scalar::{apply, dot, symmetric, Scalar, M3, V3};

/// `φ`, `n·v`, `∇φ` and `∇²φ` at one normal.
#[derive(Clone, Copy, Debug)]
pub struct Jet<T> {
    /// `φ(n)`: where the ray crosses the support plane.
    pub phi: T,
    /// `D = n·v`.
    pub d: T,
    /// `∇φ(n)`.
    pub grad: V3<T>,
    /// `∇²φ(n)`.
    pub hess: M3<T>,
}

/// `h(n)`, `∇h(n)` and `1/h(n)` of the body with shape matrix `p`.
fn support<T: Scalar>(p: &M3<T>, n: &V3<T>) -> (T, V3<T>, T) {
    let pn = apply(p, n);
    let h = dot(n, &pn).root();
    let inv = T::of(1.0).over(h);
    (h, pn.map(|x| x * inv), inv)
}

/// `∇²h(n) = (P − ∇h·∇hᵀ)/h` from [`support`]'s `∇h` and `1/h`.
fn curvature<T: Scalar>(p: &M3<T>, g: &V3<T>, inv: T) -> M3<T> {
    symmetric(|i, j| (p[i][j] - g[i] * g[j]) * inv)
}

/// `∇h(n) = P·n / h(n)`: the point (around the centre) of the body with
/// shape matrix `p` whose outward normal is `n`.
pub fn support_point<T: Scalar>(p: &M3<T>, n: &V3<T>) -> V3<T> {
    support(p, n).1
}

/// `∇h_K(n) = ∇h_A(n) + ∇h_B(n)`, the point of `K` whose outward normal
/// is `n`, and `φ(n)` from the same support functions.
pub fn boundary_point<T: Scalar>(line: &Line<T>, n: &V3<T>) -> (V3<T>, T) {
    let ((ha, ga, _), (hb, gb, _)) = (support(&line.pa, n), support(&line.pb, n));
    let phi = (ha + hb - dot(n, &line.c0)).over(dot(n, &line.v));
    (std::array::from_fn(|i| ga[i] + gb[i]), phi)
}

/// The support functions of both bodies, summed: `h_K`, `∇h_K`, `∇²h_K`.
pub fn support_k<T: Scalar>(line: &Line<T>, n: &V3<T>) -> (T, V3<T>, M3<T>) {
    let (ha, ga, ia) = support(&line.pa, n);
    let (hb, gb, ib) = support(&line.pb, n);
    let (sa, sb) = (curvature(&line.pa, &ga, ia), curvature(&line.pb, &gb, ib));
    let g = std::array::from_fn(|i| ga[i] + gb[i]);
    let s = std::array::from_fn(|i| std::array::from_fn(|j| sa[i][j] + sb[i][j]));
    (ha + hb, g, s)
}

/// `φ`, `D = n·v`, `∇φ` and `1/D` at `n`, from `h_K` and `∇h_K`.
fn first<T: Scalar>(line: &Line<T>, n: &V3<T>, h: T, gh: &V3<T>) -> (T, T, V3<T>, T) {
    let d = dot(n, &line.v);
    let inv = T::of(1.0).over(d);
    let phi = (h - dot(n, &line.c0)) * inv;
    let grad = std::array::from_fn(|i| (gh[i] - line.c0[i] - phi * line.v[i]) * inv);
    (phi, d, grad, inv)
}

/// `∇φ(n)` from `h_K(n)` and `∇h_K(n)` ([`support_k`]'s first two), e.g.
/// enclosed over a box for the mean-value form of the instant.
pub fn gradient<T: Scalar>(line: &Line<T>, n: &V3<T>, h: T, gh: &V3<T>) -> V3<T> {
    first(line, n, h, gh).2
}

/// The [`Jet`] of `φ` at `n` (each entry enclosed when `T` is an
/// interval type and `n` a box).
pub fn jet<T: Scalar>(line: &Line<T>, n: &V3<T>) -> Jet<T> {
    let (h, gh, hh) = support_k(line, n);
    let (phi, d, grad, inv) = first(line, n, h, &gh);
    let v = &line.v;
    let hess = symmetric(|i, k| (hh[i][k] - grad[i] * v[k] - v[i] * grad[k]) * inv);
    Jet { phi, d, grad, hess }
}

/// `n·c(u) − h_K(n)`: positive when the ray's point at `u` is strictly
/// outside the half-space of `n`, so outside `K` (the bodies apart).
pub fn clearance<T: Scalar>(line: &Line<T>, n: &V3<T>, u: T) -> T {
    let c: V3<T> = std::array::from_fn(|i| line.c0[i] + u * line.v[i]);
    let h = dot(n, &apply(&line.pa, n)).root() + dot(n, &apply(&line.pb, n)).root();
    dot(n, &c) - h
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::axpy;

    fn line() -> Line<f64> {
        let pa = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.25], [0.5, 0.25, 2.0]];
        let pb = [[1.0, 0.2, 0.0], [0.2, 2.0, 0.3], [0.0, 0.3, 1.5]];
        Line {
            pa,
            pb,
            c0: [7.0, -1.0, 2.0],
            v: [-9.0, 2.0, -1.0],
            a0: [0.0; 3],
            da: [0.0; 3],
            radii: [2.0, 1.0],
        }
    }

    /// The derivatives are those of `φ`: central differences agree.
    #[test]
    fn derivatives_are_the_differences_of_phi() {
        let l = line();
        let n = [-0.6, 0.3, -0.2];
        let j = jet(&l, &n);
        let eps = 1e-6;
        for k in 0..3 {
            let mut e = [0.0; 3];
            e[k] = eps;
            let (p, m) = (jet(&l, &axpy(&n, 1.0, &e)), jet(&l, &axpy(&n, -1.0, &e)));
            let dphi = (p.phi - m.phi) / (2.0 * eps);
            assert!((dphi - j.grad[k]).abs() < 1e-6 * (1.0 + dphi.abs()), "{k}");
            for i in 0..3 {
                let dg = (p.grad[i] - m.grad[i]) / (2.0 * eps);
                assert!(
                    (dg - j.hess[i][k]).abs() < 1e-5 * (1.0 + dg.abs()),
                    "{i}{k}"
                );
            }
        }
        // Homogeneous of degree 0: ∇φ ⟂ n.
        assert!(dot(&j.grad, &n).abs() < 1e-12);
    }

    /// At `u = φ(n)` the ray's point lies on the support plane.
    #[test]
    fn phi_is_where_the_ray_meets_the_plane() {
        let l = line();
        // n·v < 0: outside before φ; n·v > 0: outside after.
        for (n, side) in [([0.6, -0.3, 0.2], -1.0), ([-0.6, 0.3, -0.2], 1.0)] {
            let j = jet(&l, &n);
            assert!(j.d * side > 0.0);
            assert!(clearance(&l, &n, j.phi).abs() < 1e-12);
            assert!(clearance(&l, &n, j.phi + 0.1 * side) > 0.0);
            assert!(clearance(&l, &n, j.phi - 0.1 * side) < 0.0);
        }
    }
}
