//! The proofs, in outward-rounded `f64` intervals: a support plane that
//! keeps the ray outside `K` on the whole span, and a Krawczyk test that
//! encloses the unique stationary normal of `φ` near the search's result
//! (hence the entry or the exit instant, and the contact point).

use crate::line::{enclosure, Line};
use crate::scalar::{axpy, cross, dot, form, lift, Scalar, V3};
use crate::search::{basis, inverse2, unit};
use crate::support::{boundary_point, clearance, gradient, support_k, support_point};
use ccd_arith::{DwBall, Interval};

/// Box radii tried by [`System::crossing`], each 16 times the last.
const TRIES: usize = 4;
/// Newton steps from the double-word `G(0)` after a test that fails or
/// encloses the instant wider than [`narrow`] (near a graze the first
/// steps gain a factor of only 4–8 each: `graze-ellipsoids-k15-overlap`'s
/// exit needs five). They stop early once a step no longer moves the
/// `f64` normal.
const REFINE_STEPS: usize = 8;

/// Whether the plane of `n` proves the bodies apart over the whole span
/// (in `f64` intervals, or in double words for a near miss):
/// the ray's points at `u = 0` and `u = 1` are both strictly beyond it
/// (`n·c(u) > h_K(n)`), hence, the condition being linear in `u`, every
/// point between them, and `K` lies on the other side.
pub fn apart<T: Scalar>(line: &Line<T>, n: &V3<f64>) -> bool {
    apart_by(line, &lift(n))
}

/// [`apart`] for the plane of `v × (n × v)`: `n` made exactly parallel to
/// the ray (an enclosure of that vector), for a near miss whose gap is
/// smaller than what an `f64` normal's tilt of an ulp (`n·v ≠ 0`) costs
/// at one end of the span.
pub fn apart_parallel<T: Scalar>(line: &Line<T>, n: &V3<f64>) -> bool {
    apart_by(line, &cross(&line.v, &cross(&lift(n), &line.v)))
}

fn apart_by<T: Scalar>(line: &Line<T>, n: &V3<T>) -> bool {
    [0.0, 1.0]
        .into_iter()
        .all(|u| clearance(line, n, T::of(u)).positive())
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

/// `n̂ + w₀·e₀ + w₁·e₁` for a box `w` (in `T`).
fn offset<T: Scalar>(n: &V3<f64>, e: &[V3<f64>; 2], w: &[T; 2]) -> V3<T> {
    let n = lift::<T>(n);
    axpy(&axpy(&n, w[0], &lift(&e[0])), w[1], &lift(&e[1]))
}

/// About two ulps of the instant: an enclosure no wider needs no further
/// Newton step.
fn narrow(u: &Interval) -> f64 {
    (4.0 * f64::EPSILON * u.hi.abs()).max(1e-17)
}

/// `G(w) = Fᵀ(∇h_K(n + Ew) − c₀)` of one ray, set up once per query for
/// its entry and its exit ([`System::crossing`]).
pub struct System<'a> {
    line: &'a Line<Interval>,
    fine: &'a Line<DwBall>,
    f: Line<f64>,
    /// `F`, two vectors spanning `v⊥` (`v × a` for a rounded basis `a` of
    /// it), enclosed in intervals and in double words.
    fv: [V3<Interval>; 2],
    fd: [V3<DwBall>; 2],
}

/// What a Newton step at a normal `n` needs: `E = basis(n)`, `Y ≈ J⁻¹`
/// and `Y·G(0)` (enclosed).
struct Newton {
    /// `φ(n)` in double words.
    phi: DwBall,
    e: [V3<f64>; 2],
    y: [[Interval; 2]; 2],
    yg: [Interval; 2],
}

impl<'a> System<'a> {
    /// The system of the ray enclosed in `line` (`f64` intervals) and
    /// `fine` (double words), or `None` for a velocity of no usable size.
    pub fn new(line: &'a Line<Interval>, fine: &'a Line<DwBall>) -> Option<System<'a>> {
        let f = line.mid();
        // `v × a` for two f64 vectors `a` across `v`: exactly orthogonal
        // to the true `v` (enclosed with it), which a rounded basis of
        // `v⊥` is not — near a graze its tilt of an ulp moves the zero.
        // Scaled by a power of two (exactly) to `|v × a| ≈ 1`, so that
        // `J` and its inverse stay far from f64's ends for any size.
        let size = f.v.iter().fold(0.0, |m: f64, x| m.max(x.abs()));
        if !(1e-300..=1e300).contains(&size) {
            return None;
        }
        let scale = 2f64.powi(-(size.log2().round() as i32));
        let across = basis(&unit(&f.v)?).map(|a| a.map(|x| x * scale));
        Some(System {
            line,
            fine,
            f,
            fv: across.map(|a| cross(&line.v, &lift(&a))),
            fd: across.map(|a| cross(&fine.v, &lift(&a))),
        })
    }

    /// The crossing on `side` (`−1`: the entry, where `n·v < 0`; `+1`: the
    /// exit) proven near the search's normal `n` (unit), or `None`.
    ///
    /// The stationary normals of `φ` are where K's boundary point
    /// `∇h_K(n)` lies on the ray's line (`D·∇φ = ∇h_K − c₀ − φ·v` and
    /// `∇φ·n = 0`), so with `E = basis(n)` and `F = (v × a₁, v × a₂)` (two
    /// vectors exactly orthogonal to `v`, spanning `v⊥`),
    /// `G(w) = Fᵀ(∇h_K(n + Ew) − c₀)` vanishes exactly at them — with no
    /// division by `D = n·v`, which near a graze is small and, in `φ`'s own
    /// derivatives, swamps an enclosure over a box with its dependency.
    /// Krawczyk's operator `K(W) = −Y·G(0) + (I − Y·J(W))·W` over the box
    /// `W = [−r, r]²`, `J = Fᵀ∇²h_K E` enclosed over it and `Y ≈ J(0)⁻¹`, lying
    /// inside `W` proves one zero `w*` of `G` in `K(W)` (Krawczyk 1969; Moore,
    /// Kearfott & Cloud, *Introduction to Interval Analysis*, §8.2); `n·v`
    /// keeping the sign of `side` over `W` makes `n* = n + Ew*` the entry (or
    /// the exit) normal ([`crate::support`]), and the mean value form
    /// `φ(n*) ∈ φ(n) + ∇φ(n + EW)·Ew*` encloses the instant.
    ///
    /// `G(0)` and `φ(n)` are cancellations, evaluated in double words (`fine`:
    /// the same ray); in `f64` intervals they leave the instant and the box a
    /// few `10⁻¹⁵` wide. Near a graze the `f64` search stops short of `n*`
    /// (its gradient is only as good as `f64` allows), and the test fails or
    /// encloses the instant wide: up to eight (`REFINE_STEPS`) Newton steps from the
    /// double-word `G(0)` then move `n` closer and the test runs again.
    pub fn crossing(&self, n: &V3<f64>, side: f64) -> Option<Crossing> {
        let mut n = *n;
        for step in 0..=REFINE_STEPS {
            let newton = self.newton(&n, step > 0)?;
            let proven = self.krawczyk(&n, &newton, side);
            match proven {
                Some(c) if step == REFINE_STEPS || c.u.width() <= narrow(&c.u) => return Some(c),
                _ if step == REFINE_STEPS => return None,
                _ => {}
            }
            let (e, w) = (&newton.e, newton.yg.map(|x| x.mid()));
            let next = unit(&axpy(&axpy(&n, -w[0], &e[0]), -w[1], &e[1]))?;
            if step > 0 && next == n {
                // Converged as far as an `f64` normal goes: another step would
                // repeat this test (step 0's test used the `f64` Hessian, the
                // next one the double-word Hessian at the same normal).
                return proven;
            }
            n = next;
        }
        None
    }

    /// `G(0)` in double words at `n`, and `Y` from the `f64` Hessian of
    /// `h_K` (`precise`: from the double-word one, so that repeated steps
    /// converge quadratically near a graze).
    fn newton(&self, n: &V3<f64>, precise: bool) -> Option<Newton> {
        let e = basis(n);
        let (g, phi): (V3<DwBall>, DwBall) = boundary_point(self.fine, &lift(n));
        let gap: V3<DwBall> = std::array::from_fn(|i| g[i] - self.fine.c0[i]);
        let g0 = self.fd.map(|fi| enclosure(dot(&fi, &gap)));
        let hess = if precise {
            support_k(self.fine, &lift(n)).2.map(|r| r.map(|x| x.hi))
        } else {
            support_k(&self.f, n).2
        };
        let fm = self.fv.map(|x| x.map(|i| i.mid()));
        let jm = fm.map(|fi| e.map(|ej| form(&fi, &hess, &ej)));
        let y = inverse2(&jm)?.map(|r| r.map(Interval::point));
        let yg = std::array::from_fn(|i| y[i][0] * g0[0] + y[i][1] * g0[1]);
        Some(Newton { phi, e, y, yg })
    }

    /// Krawczyk's test around `n` (boxes of [`TRIES`] radii from
    /// `4·|Y·G(0)|`), and the crossing it proves.
    fn krawczyk(&self, n: &V3<f64>, newton: &Newton, side: f64) -> Option<Crossing> {
        let Newton { phi, e, y, yg } = newton;
        let line = self.line;
        let ew = e.map(|ei| lift::<Interval>(&ei));
        let widest = yg
            .iter()
            .map(|x| x.lo.abs().max(x.hi.abs()))
            .fold(0.0, f64::max);
        let mut r = (4.0 * widest).max(1e-17);
        for _ in 0..TRIES {
            let w = [Interval::new(-r, r); 2];
            let boxed = offset(n, e, &w);
            if dot(&boxed, &line.v).sign() != Some(side as i32) {
                return None;
            }
            let (hk, gk, hw) = support_k(line, &boxed);
            let jj: [[Interval; 2]; 2] =
                std::array::from_fn(|i| std::array::from_fn(|k| form(&self.fv[i], &hw, &ew[k])));
            let k: [Interval; 2] = std::array::from_fn(|i| {
                (0..2).fold(-yg[i], |s, c| {
                    let yj = y[i][0] * jj[0][c] + y[i][1] * jj[1][c];
                    let id = Interval::point(if i == c { 1.0 } else { 0.0 });
                    s + (id - yj) * w[c]
                })
            });
            if k.iter().all(|x| x.lo > -r && x.hi < r) {
                let normal = offset(n, e, &k);
                let step: V3<Interval> = std::array::from_fn(|i| ew[0][i] * k[0] + ew[1][i] * k[1]);
                let u = enclosure(*phi) + dot(&gradient(line, &boxed, hk, &gk), &step);
                let centre = axpy(&line.a0, u, &line.da);
                let s = support_point(&line.pa, &normal);
                let point = std::array::from_fn(|i| centre[i] + s[i]);
                return Some(Crossing { u, normal, point });
            }
            r *= 16.0;
        }
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::search::polish;
    use ccd_arith::Rat;

    /// [`System::crossing`] of a ray set up for this one test.
    fn crossing(
        line: &Line<Interval>,
        fine: &Line<DwBall>,
        n: &V3<f64>,
        side: f64,
    ) -> Option<Crossing> {
        System::new(line, fine)?.crossing(n, side)
    }

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
        // An ulp past the ball: beyond f64 intervals' rounding of the
        // square roots, proven in double words.
        let ulp_past = spheres(3f64.next_up());
        assert!(!apart(&ulp_past.enclosed(), &[0.0, 1.0, 0.0]));
        assert!(apart(&ulp_past, &[0.0, 1.0, 0.0]));
        assert!(!apart(&spheres(3.0), &[0.0, 1.0, 0.0]));
    }

    /// The exit of a clean pass is proven on its side, and a ray tangent
    /// to the ball (distance exactly 3) has no proven crossing.
    #[test]
    fn exits_are_proven_and_tangents_are_not() {
        let fine = spheres(1.0);
        let line = fine.enclosed();
        let n = polish(&line.mid(), &[1.0, 0.2, 0.0], 1.0).expect("converges");
        let c = crossing(&line, &fine, &n, 1.0).expect("proven");
        let t = (10.0 + 8f64.sqrt()) / 20.0;
        assert!(
            c.u.lo <= t && t <= c.u.hi && c.u.width() < 6e-16,
            "{:?} {t}",
            c.u
        );
        let tangent = spheres(3.0);
        let tl = tangent.enclosed();
        for side in [-1.0, 1.0] {
            assert!(crossing(&tl, &tangent, &[0.0, 1.0, 0.0], side).is_none());
        }
    }
}
