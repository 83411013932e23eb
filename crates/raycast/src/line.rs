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

/// What every enclosure of a pair's ray is formed from, read from the
/// scene once: each body's centre at `u = 0` and `u = 1`, its radii and
/// orientation, and its shape matrix `P` exactly in integers when its
/// numbers are short ([`ccd_motion::matrices::shape_small`]).
pub struct Pair<'a> {
    centres: [[&'a [Rat; 3]; 2]; 2],
    bodies: [(&'a [Rat; 3], &'a Quat); 2],
    exact: [Option<(M3<i128>, i128)>; 2],
    /// `[c₀, v, a(0), a(1) − a(0)]` exactly as integers over one
    /// denominator, when every number fits `i128`.
    ray: Option<([V3<i128>; 4], i128)>,
    /// [`Line::radii`].
    radii: [f64; 2],
}

/// The vectors of [`Pair::ray`] from the centres `[[a(0), a(1)], [b(0), b(1)]]`.
fn small_ray(centres: &[[&[Rat; 3]; 2]; 2]) -> Option<([V3<i128>; 4], i128)> {
    let all: [&Rat; 12] = std::array::from_fn(|i| &centres[i / 6][(i / 3) % 2][i % 3]);
    let (n, den) = ccd_motion::matrices::small_over_common_denominator(all)?;
    let [a0, a1, b0, b1]: [V3<i128>; 4] =
        std::array::from_fn(|k| [n[3 * k], n[3 * k + 1], n[3 * k + 2]]);
    let diff = |x: &V3<i128>, y: &V3<i128>| -> Option<V3<i128>> {
        Some([
            x[0].checked_sub(y[0])?,
            x[1].checked_sub(y[1])?,
            x[2].checked_sub(y[2])?,
        ])
    };
    let c0 = diff(&b0, &a0)?;
    let v = diff(&diff(&b1, &a1)?, &c0)?;
    Some(([c0, v, a0, diff(&a1, &a0)?], den))
}

impl<'a> Pair<'a> {
    /// The pair when both bodies move straight (see [`Line`]), else `None`.
    pub fn of(a: &'a Body, b: &'a Body) -> Option<Pair<'a>> {
        let (ca, qa) = straight(a)?;
        let (cb, qb) = straight(b)?;
        let bodies = [(&a.radii, qa), (&b.radii, qb)];
        let centres = [ca, cb];
        // Within an ulp (the tolerances carry a margin of 10⁻⁹).
        let sizes: [f64; 6] =
            std::array::from_fn(|i| Interval::from_rat(&bodies[i / 3].0[i % 3]).mid());
        Some(Pair {
            centres,
            bodies,
            exact: bodies.map(|(r, q)| ccd_motion::matrices::shape_small(r, q)),
            ray: small_ray(&centres),
            radii: [
                sizes.into_iter().fold(0.0, f64::max),
                sizes.into_iter().fold(f64::INFINITY, f64::min),
            ],
        })
    }

    /// `[c₀, v, a(0), a(1) − a(0)]` enclosed: from their exact integer
    /// form over one denominator (one rounding each, one division) when it
    /// fits, else as differences of the enclosed centres.
    fn ray<T: Scalar>(&self) -> [V3<T>; 4] {
        if let Some((x, den)) = &self.ray {
            let inv = T::of(1.0).over(T::int(*den));
            return x.map(|x| x.map(|e| T::int(e) * inv));
        }
        let [a0, a1] = self.centres[0].map(enclose::<T>);
        let [b0, b1] = self.centres[1].map(enclose::<T>);
        let c0: V3<T> = std::array::from_fn(|i| b0[i] - a0[i]);
        let v = std::array::from_fn(|i| (b1[i] - a1[i]) - c0[i]);
        let da = std::array::from_fn(|i| a1[i] - a0[i]);
        [c0, v, a0, da]
    }

    /// Body `k`'s shape matrix `R(q)·diag(r²)·R(q)ᵀ = M(q)·diag(r²)·M(q)ᵀ / |q|⁴`,
    /// enclosed: from its exact integer form `S/d` (one rounding of each of
    /// `S`'s entries, one division) for short numbers, else in `T`
    /// throughout (symmetric: six entries, with `M·diag(r²)` formed once).
    fn shape<T: Scalar + RingOps>(&self, k: usize) -> M3<T> {
        if let Some((s, d)) = &self.exact[k] {
            let inv = T::of(1.0).over(T::int(*d));
            return symmetric(|i, j| T::int(s[i][j]) * inv);
        }
        let (radii, q) = self.bodies[k];
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
}

fn enclose<T: Scalar>(x: &[Rat; 3]) -> V3<T> {
    x.each_ref().map(T::rat)
}

impl<T: Scalar + RingOps> Line<T> {
    /// The ray of a pair whose bodies both move straight, enclosed in `T`
    /// (`f64`, `f64` intervals, or double-word balls); `None` when an
    /// enclosure overflows.
    pub fn of(pair: &Pair) -> Option<Line<T>> {
        let [c0, v, a0, da] = pair.ray();
        let line = Line {
            pa: pair.shape(0),
            pb: pair.shape(1),
            c0,
            v,
            a0,
            da,
            radii: pair.radii,
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
    use proptest::prelude::*;
    use proptest::sample::select;

    /// `x` holds `want` (a ball or interval that says nothing fails).
    fn ball_holds(x: &DwBall, want: &Rat) -> bool {
        x.ends().is_some_and(|(lo, hi)| lo <= *want && *want <= hi)
    }
    fn interval_holds(x: &Interval, want: &Rat) -> bool {
        let r = |v: f64| Rat::from_f64_exact(v);
        matches!((r(x.lo), r(x.hi)), (Some(lo), Some(hi)) if lo <= *want && *want <= hi)
    }

    proptest! {
        /// Both ways of enclosing the ray — from the exact integer forms of
        /// the shapes and vectors, and from the scene's rationals entry by
        /// entry (the path of long numbers) — hold the exact values, in
        /// double words and in intervals, in every orientation.
        #[test]
        fn both_enclosures_hold_the_exact_ray(
            radii in proptest::collection::vec((1i64..10_000, select(vec![1i64, 7, 10, 100, 1000])), 6),
            quat in proptest::collection::vec((-99i64..100, select(vec![1i64, 2, 10])), 8),
            centres in proptest::collection::vec((-99_999i64..100_000, select(vec![1i64, 3, 10, 1000])), 12),
        ) {
            let rat = |(n, d): (i64, i64)| Rat::from_frac(n, d);
            let point = |k: usize| std::array::from_fn(|i| rat(centres[3 * k + i]));
            let body = |k: usize| {
                let orientation: Quat = std::array::from_fn(|i| rat(quat[4 * k + i]));
                let motion = Motion::Translation {
                    center: ccd_motion::Bezier::polynomial(vec![point(2 * k), point(2 * k + 1)]),
                    orientation,
                };
                Body { radii: std::array::from_fn(|i| rat(radii[3 * k + i])), motion }
            };
            let (a, b) = (body(0), body(1));
            let nonzero = |b: &Body| match &b.motion {
                Motion::Translation { orientation, .. } => orientation.iter().any(|x| !x.is_zero()),
                _ => false,
            };
            prop_assume!(nonzero(&a) && nonzero(&b));
            let pair = Pair::of(&a, &b).expect("both straight");
            prop_assert!(pair.exact.iter().all(Option::is_some) && pair.ray.is_some());
            let generic = Pair { exact: [None, None], ray: None, ..pair };
            // The exact values: the integer shapes (exact by ccd-motion's
            // tests) and the vectors from the centres in rationals.
            let shapes: [M3<Rat>; 2] = std::array::from_fn(|k| {
                let (s, d) = pair.exact[k].as_ref().expect("small");
                let d = Rat::from(ccd_arith::Int::from_i128(*d));
                s.map(|row| row.map(|x| &Rat::from(ccd_arith::Int::from_i128(x)) / &d))
            });
            let [a0, a1, b0, b1] = [0, 1, 2, 3].map(point);
            let sub = |x: &V3<Rat>, y: &V3<Rat>| -> V3<Rat> { std::array::from_fn(|i| &x[i] - &y[i]) };
            let c0 = sub(&b0, &a0);
            let vectors = [c0.clone(), sub(&sub(&b1, &a1), &c0), a0.clone(), sub(&a1, &a0)];
            for p in [&pair, &generic] {
                let fine = Line::<DwBall>::of(p).expect("finite");
                let line = Line::<Interval>::of(p).expect("finite");
                let fv = [fine.c0, fine.v, fine.a0, fine.da];
                let lv = [line.c0, line.v, line.a0, line.da];
                for i in 0..3 {
                    for j in 0..3 {
                        for (k, (fm, lm)) in [(&fine.pa, &line.pa), (&fine.pb, &line.pb)].into_iter().enumerate() {
                            prop_assert!(ball_holds(&fm[i][j], &shapes[k][i][j]));
                            prop_assert!(interval_holds(&lm[i][j], &shapes[k][i][j]));
                        }
                    }
                    for k in 0..4 {
                        prop_assert!(ball_holds(&fv[k][i], &vectors[k][i]));
                        prop_assert!(interval_holds(&lv[k][i], &vectors[k][i]));
                    }
                }
            }
        }
    }

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
        let of = |a, b| Pair::of(a, b).and_then(|p| Line::<DwBall>::of(&p));
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
