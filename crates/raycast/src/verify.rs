//! The proofs, in outward-rounded `f64` intervals: a support plane that
//! keeps the ray outside `K` on the whole span, and a Krawczyk test that
//! encloses the unique stationary normal of `φ` near the search's result
//! (hence the entry or the exit instant, and the contact point).

use crate::line::{enclosure, Line};
use crate::scalar::{axpy, dot, lift, V3};
use crate::search::{basis, inverse2, reduced};
use crate::support::{clearance, jet, support_point};
use ccd_arith::{DwBall, Interval};

/// Box radii tried by [`crossing`], each 16 times the last.
const TRIES: usize = 4;

/// Whether the plane of `n` proves the bodies apart over the whole span:
/// the ray's points at `u = 0` and `u = 1` are both strictly beyond it
/// (`n·c(u) > h_K(n)`), hence, the condition being linear in `u`, every
/// point between them, and `K` lies on the other side.
pub fn apart(line: &Line<Interval>, n: &V3<f64>) -> bool {
    let n = lift(n);
    [0.0, 1.0]
        .into_iter()
        .all(|u| clearance(line, &n, Interval::point(u)).lo > 0.0)
}

/// A proven crossing of `∂K` by the ray: the entry or the exit.
#[derive(Clone, Copy, Debug)]
pub struct Crossing {
    /// Encloses the instant `u*`.
    pub u: Interval,
    /// Encloses a normal `n*` of `K` there (not of unit length), A's
    /// outward normal at the contact point.
    pub normal: V3<Interval>,
    /// Encloses the contact point `a(u*) + ∇h_A(n*)`.
    pub point: V3<Interval>,
}

/// `n̂ + w₀·e₀ + w₁·e₁` for an interval `w`.
fn offset(n: &V3<f64>, e: &[V3<f64>; 2], w: &[Interval; 2]) -> V3<Interval> {
    let n = lift::<Interval>(n);
    axpy(&axpy(&n, w[0], &lift(&e[0])), w[1], &lift(&e[1]))
}

/// The crossing on `side` (`−1`: the entry, where `n·v < 0`; `+1`: the
/// exit) proven near the search's normal `n` (unit), or `None`.
///
/// With `E = basis(n)`, `G(w) = Eᵀ∇φ(n + Ew)` vanishes exactly at the
/// stationary normals of `φ` near `n` (`∇φ ⟂ n` by homogeneity). Krawczyk's
/// operator `K(W) = −Y·G(0) + (I − Y·J(W))·W` over the box `W = [−r, r]²`,
/// `J = Eᵀ∇²φE` and `Y ≈ J(0)⁻¹`, lying inside `W` proves one zero `w*` of
/// `G` in `K(W)` (Krawczyk 1969; Moore, Kearfott & Cloud, *Introduction to
/// Interval Analysis*, §8.2); `n·v` keeping the sign of `side` over `W`
/// makes `n* = n + Ew*` the entry (or the exit) normal ([`crate::support`]),
/// and the mean value form `φ(n*) ∈ φ(n) + ∇φ(n + EW)·Ew*` encloses the
/// instant. `G(0)` and `φ(n)` are evaluated in double words (`fine`: the
/// same ray), since in `f64` intervals their cancellations (`∇h_K − c₀ −
/// φ·v`, `h_K − n·c₀`) leave them a few `10⁻¹⁵` wide, and the box (hence
/// the contact point) and the instant as wide; the rest runs in `f64`
/// intervals over boxes `10⁻¹⁵` small.
pub fn crossing(
    line: &Line<Interval>,
    fine: &Line<DwBall>,
    n: &V3<f64>,
    side: f64,
) -> Option<Crossing> {
    let e = basis(n);
    let j0 = jet(fine, &lift(n));
    let g0 = e.map(|ei| enclosure(dot(&lift(&ei), &j0.grad)));
    let (_, h) = reduced(
        &j0.grad.map(|x| x.hi),
        &j0.hess.map(|r| r.map(|x| x.hi)),
        &e,
    );
    let y = inverse2(&h)?.map(|r| r.map(Interval::point));
    let yg: [Interval; 2] = std::array::from_fn(|i| y[i][0] * g0[0] + y[i][1] * g0[1]);
    let mut r = (4.0
        * yg.iter()
            .map(|x| x.lo.abs().max(x.hi.abs()))
            .fold(0.0, f64::max))
    .max(1e-15);
    for _ in 0..TRIES {
        let w = [Interval::new(-r, r); 2];
        let jw = jet(line, &offset(n, &e, &w));
        if jw.d.sign() != Some(side as i32) {
            return None;
        }
        let ew = e.map(|ei| lift::<Interval>(&ei));
        let jj: [[Interval; 2]; 2] = std::array::from_fn(|i| {
            std::array::from_fn(|k| dot(&ew[i], &crate::scalar::apply(&jw.hess, &ew[k])))
        });
        let k: [Interval; 2] = std::array::from_fn(|i| {
            (0..2).fold(-yg[i], |s, c| {
                let yj = y[i][0] * jj[0][c] + y[i][1] * jj[1][c];
                let id = Interval::point(if i == c { 1.0 } else { 0.0 });
                s + (id - yj) * w[c]
            })
        });
        if k.iter().all(|x| x.lo > -r && x.hi < r) {
            let normal = offset(n, &e, &k);
            let step: V3<Interval> = std::array::from_fn(|i| ew[0][i] * k[0] + ew[1][i] * k[1]);
            let u = enclosure(j0.phi) + dot(&jw.grad, &step);
            let centre = axpy(&line.a0, u, &line.da);
            let s = support_point(&line.pa, &normal);
            let point = std::array::from_fn(|i| centre[i] + s[i]);
            return Some(Crossing { u, normal, point });
        }
        r *= 16.0;
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::polish;
    use ccd_arith::Rat;

    /// Spheres of radii 1 and 2 (K: the ball of radius 3), the ray
    /// `(−10 + 20u, y, 0)`.
    fn spheres(y: f64) -> Line<DwBall> {
        let i = |s: f64| {
            let d = DwBall::exact(s);
            let z = DwBall::exact(0.0);
            [[d, z, z], [z, d, z], [z, z, d]]
        };
        let v = |x: [f64; 3]| x.map(DwBall::exact);
        Line {
            pa: i(1.0),
            pb: i(4.0),
            c0: v([-10.0, y, 0.0]),
            v: v([20.0, 0.0, 0.0]),
            a0: v([0.0; 3]),
            da: v([0.0; 3]),
            radii: [2.0, 1.0],
        }
    }

    /// The enclosure holds the entry `u = (10 − √8)/20` (checked in
    /// rationals: `(10 − 20·lo)² >= 8 >= (10 − 20·hi)²`), one or two ulps
    /// wide, and the contact point `(−√8/3, 1/3, 0)`·1 on A's unit sphere.
    #[test]
    fn the_entry_of_a_ray_into_a_ball_is_enclosed() {
        let fine = spheres(1.0);
        let line = fine.enclosed();
        let n = polish(&line.mid(), &[-1.0, 0.2, 0.0], -1.0).expect("converges");
        let c = crossing(&line, &fine, &n, -1.0).expect("proven");
        let r = |x: f64| Rat::from_f64_exact(x).expect("finite");
        let (ten, twenty, eight) = (Rat::from(10), Rat::from(20), Rat::from(8));
        let sq = |x: Rat| &x * &x;
        assert!(sq(&ten - &(&twenty * &r(c.u.lo))) >= eight);
        assert!(sq(&ten - &(&twenty * &r(c.u.hi))) <= eight);
        assert!(c.u.width() < 3e-16, "{:?}", c.u);
        let x = -(8f64.sqrt()) / 3.0;
        assert!(c.point[0].lo <= x && x <= c.point[0].hi && c.point[0].width() < 1e-14);
        assert!(c.point[1].lo <= 1.0 / 3.0 && 1.0 / 3.0 <= c.point[1].hi);
        // The exit side of the same normal is refused.
        assert!(crossing(&line, &fine, &n, 1.0).is_none());
    }

    /// A plane proves the bodies apart only when both ends of the ray are
    /// strictly beyond it.
    #[test]
    fn planes_prove_only_what_they_separate() {
        let past = spheres(3.5).enclosed();
        assert!(apart(&past, &[0.0, 1.0, 0.0]));
        assert!(!apart(&past, &[0.0, -1.0, 0.0]));
        // Tangent (distance exactly 3): not strictly beyond.
        assert!(!apart(&spheres(3.0).enclosed(), &[0.0, 1.0, 0.0]));
        // Through the ball.
        assert!(!apart(&spheres(1.0).enclosed(), &[0.0, 1.0, 0.0]));
    }
}
