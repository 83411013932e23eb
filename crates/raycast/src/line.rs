//! A pair whose bodies only translate, each along a straight line at
//! constant speed (or not at all), as one ray: with `u = (t − t0)/(t1 − t0)`,
//! `A(u) = a(u) + A₀` and `B(u) = b(u) + B₀` meet exactly when
//! `c(u) = b(u) − a(u) = c₀ + u·v` lies in the Minkowski difference
//! `K = A₀ ⊕ (−B₀)`, whose support function is
//! `h_K(n) = √(nᵀP_A n) + √(nᵀP_B n)` with `P = R·diag(r²)·Rᵀ`
//! (the body `{x : xᵀP⁻¹x <= 1}` has support `√(nᵀPn)`).

use crate::scalar::{symmetric, Scalar, M3, V3};
use ccd_arith::{DwBall, Interval, Rat, RingOps};
use ccd_motion::{Body, Motion, Quat};

/// The ray of a translating pair, in the parameter `u ∈ [0, 1]`.
#[derive(Clone, Debug)]
pub struct Line<T> {
    /// `P_A = R_A·diag(r_A²)·R_Aᵀ`.
    pub pa: M3<T>,
    /// `P_B`.
    pub pb: M3<T>,
    /// `c₀ = b(0) − a(0)`.
    pub c0: V3<T>,
    /// `v = c(1) − c(0)`.
    pub v: V3<T>,
    /// `a(0)`, A's centre at `t0` (the contact point is read from it).
    pub a0: V3<T>,
    /// `a(1) − a(0)`.
    pub da: V3<T>,
    /// The largest and the smallest semi-axis of the two bodies (the
    /// contact geometry's tolerances are relative to them).
    pub radii: [f64; 2],
}

/// A body's centre at `u = 0` and `u = 1` and its orientation, when it
/// does not turn and its centre moves along a straight line at constant
/// speed: static, or a translation whose centre curve has degree at most 1
/// and no weights.
fn straight(body: &Body) -> Option<([&[Rat; 3]; 2], &Quat)> {
    match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => Some(([center, center], orientation)),
        Motion::Translation {
            center,
            orientation,
        } if center.weights.is_none() && center.degree() <= 1 => {
            let p = &center.points;
            Some(([p.first()?, p.last()?], orientation))
        }
        _ => None,
    }
}

fn enclose<T: Scalar>(x: &[Rat; 3]) -> V3<T> {
    x.each_ref().map(T::rat)
}

/// `R(q)·diag(r²)·R(q)ᵀ = M(q)·diag(r²)·M(q)ᵀ / |q|⁴`, enclosed
/// (symmetric: six entries, with `M·diag(r²)` formed once).
fn shape<T: Scalar + RingOps>(radii: &[Rat; 3], q: &Quat) -> M3<T> {
    let q = q.each_ref().map(T::rat);
    let m = ccd_quadric::rotation_numerator(&q);
    let r2 = radii.each_ref().map(|r| {
        let r = T::rat(r);
        r * r
    });
    let n2 = q.iter().fold(T::of(0.0), |s, x| s + *x * *x);
    let scale = T::of(1.0).over(n2 * n2);
    let mr: M3<T> = std::array::from_fn(|i| std::array::from_fn(|k| m[i][k] * r2[k]));
    symmetric(|i, j| (mr[i][0] * m[j][0] + mr[i][1] * m[j][1] + mr[i][2] * m[j][2]) * scale)
}

impl<T: Scalar + RingOps> Line<T> {
    /// The ray of a pair whose bodies both move straight (see
    /// [`Line`]), enclosed in `T` (`f64` intervals, or double-word balls);
    /// `None` for any other pair, or when an enclosure overflows.
    pub fn of(a: &Body, b: &Body) -> Option<Line<T>> {
        let (ca, qa) = straight(a)?;
        let (cb, qb) = straight(b)?;
        let [a0, a1] = ca.map(enclose::<T>);
        let [b0, b1] = cb.map(enclose::<T>);
        let c0: V3<T> = std::array::from_fn(|i| b0[i] - a0[i]);
        let v = std::array::from_fn(|i| (b1[i] - a1[i]) - c0[i]);
        let da = std::array::from_fn(|i| a1[i] - a0[i]);
        // Within an ulp (the tolerances carry a margin of 10⁻⁹).
        let sizes: [f64; 6] = std::array::from_fn(|i| {
            let r = if i < 3 { &a.radii[i] } else { &b.radii[i - 3] };
            Interval::from_rat(r).mid()
        });
        let line = Line {
            pa: shape(&a.radii, qa),
            pb: shape(&b.radii, qb),
            c0,
            v,
            a0,
            da,
            radii: [
                sizes.into_iter().fold(0.0, f64::max),
                sizes.into_iter().fold(f64::INFINITY, f64::min),
            ],
        };
        let finite = |x: &T| x.known();
        let all = [&line.pa, &line.pb]
            .iter()
            .all(|m| m.iter().flatten().all(finite))
            && [&line.c0, &line.v, &line.a0, &line.da]
                .iter()
                .all(|x| x.iter().all(finite));
        (all && line.radii[1] > 0.0).then_some(line)
    }
}

impl<T: Copy> Line<T> {
    /// The same ray with every entry mapped by `f`.
    fn map<U>(&self, f: impl Fn(T) -> U) -> Line<U> {
        let v = |x: &V3<T>| x.map(&f);
        Line {
            pa: self.pa.map(|r| r.map(&f)),
            pb: self.pb.map(|r| r.map(&f)),
            c0: v(&self.c0),
            v: v(&self.v),
            a0: v(&self.a0),
            da: v(&self.da),
            radii: self.radii,
        }
    }
}

impl Line<DwBall> {
    /// The `f64` intervals around the double words (each about one ulp
    /// wide): the boxes the proofs evaluate over.
    pub fn enclosed(&self) -> Line<Interval> {
        self.map(enclosure)
    }
}

/// The `f64` interval around a double-word ball ([`Interval::ENTIRE`]
/// when it says nothing).
pub fn enclosure(x: DwBall) -> Interval {
    if x.is_known() {
        Interval::new(x.lower(), x.upper())
    } else {
        Interval::ENTIRE
    }
}

impl Line<Interval> {
    /// The midpoints: the `f64` problem the search runs on.
    pub fn mid(&self) -> Line<f64> {
        self.map(|i| i.mid())
    }
}

impl Line<f64> {
    /// The same ray with lengths divided by the largest radius (shape
    /// matrices by its square): the same normals and instants, with the
    /// search's products (a 3×3 determinant is of degree 6 in lengths) far
    /// from `f64`'s ends for bodies of `10^(±100)`.
    pub fn unit_sized(&self) -> Line<f64> {
        let s = self.radii[0];
        let mut l = self.clone();
        l.pa = l.pa.map(|r| r.map(|x| x / (s * s)));
        l.pb = l.pb.map(|r| r.map(|x| x / (s * s)));
        for x in [&mut l.c0, &mut l.v, &mut l.a0, &mut l.da] {
            *x = x.map(|c| c / s);
        }
        l.radii = self.radii.map(|r| r / s);
        l
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn turning_curved_and_weighted_motions_are_not_lines() {
        let r = [Rat::one(), Rat::one(), Rat::one()];
        let p = |x: i64| [Rat::from(x), Rat::zero(), Rat::zero()];
        let body = |motion| Body {
            radii: r.clone(),
            motion,
        };
        let still = body(Motion::at_origin());
        let line = body(Motion::translation(ccd_motion::Bezier::polynomial(vec![
            p(0),
            p(3),
        ])));
        let curve = body(Motion::translation(ccd_motion::Bezier::polynomial(vec![
            p(0),
            p(1),
            p(3),
        ])));
        let weighted = body(Motion::translation(ccd_motion::Bezier {
            points: vec![p(0), p(3)],
            weights: Some(vec![Rat::one(), Rat::from(2)]),
        }));
        let of = Line::<DwBall>::of;
        assert!(of(&still, &line).is_some());
        assert!(of(&still, &still).is_some());
        assert!(of(&still, &curve).is_none());
        assert!(of(&weighted, &still).is_none());
        let l = of(&line, &still).expect("a line").enclosed().mid();
        assert_eq!(l.v, [-3.0, 0.0, 0.0]);
        assert_eq!(l.c0, [0.0, 0.0, 0.0]);
        assert_eq!(l.pa[0], [1.0, 0.0, 0.0]);
    }
}
