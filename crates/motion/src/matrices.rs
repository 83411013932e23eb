//! Placements `M(u)` (body → world) and moving quadric matrices
//! `A(u) ∝ N(u)ᵀ·D·N(u)` (`N ∝ M⁻¹`) with integer polynomial entries in
//! `u ∈ [0, 1]`, built from a motion and validated exactly.

use crate::centred::Centred;
use crate::curve::{to_poly_curve, PolyCurve};
use crate::error::MotionError;
use crate::kinds::{Bezier, Body, Motion, Quat};
use ccd_arith::{Int, Rat, RingOps};
use ccd_poly::{QPoly, ZPoly};
use ccd_quadric::{
    affine_inverse, affine_placement, body_diagonal, congruence, det3, integral, norm2,
    rigid_inverse, rigid_placement, rotation_numerator, Mat3, Mat4,
};

fn constant_vec<const N: usize>(v: &[Rat; N]) -> [QPoly; N] {
    std::array::from_fn(|i| QPoly::constant(v[i].clone()))
}

/// The first root of `p` in `[0, 1]`, mapped to `t` (approximately), if any.
fn first_root_in_span(p: &ZPoly, span: &[Rat; 2]) -> Option<f64> {
    if p.is_zero() {
        return Some(span[0].to_f64());
    }
    let mut roots = ccd_solver::isolate(p, &Rat::zero(), &Rat::one()).ok()?;
    let r = roots.next()?;
    let u = r.midpoint();
    Some((&span[0] + &(&u * &(&span[1] - &span[0]))).to_f64())
}

/// A rational placement `X = R·Xbody + C/w` (rigid, `R = M/n`) or
/// `X = (L·Xbody + d)/w` (affine), with entries in ℚ[u] (or their values at
/// one `u`).
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

impl Frame<QPoly> {
    /// Degree bounds `(forward, inverse)` of the matrices above, from the
    /// entries' degrees (no products formed).
    fn degree_bounds(&self) -> (usize, usize) {
        let deg = |p: &QPoly| p.degree().unwrap_or(0);
        let max3 = |m: &Mat3<QPoly>| m.iter().flatten().map(deg).max().unwrap_or(0);
        let maxv = |v: &[QPoly; 3]| v.iter().map(deg).max().unwrap_or(0);
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

/// The placement of a body over ℚ[u], validated exactly on the span, and
/// the polynomials whose powers make up its determinant (the weight curve,
/// and `|q|²` or `det L`): the only factors `det A` can have.
fn frame(motion: &Motion, span: &[Rat; 2]) -> Result<(Frame<QPoly>, Vec<QPoly>), MotionError> {
    let rigid = |q: &[QPoly; 4], center: [QPoly; 3], w: QPoly| Frame::Rigid {
        m: rotation_numerator(q),
        n: norm2(q),
        center,
        w,
    };
    // A constant orientation: the rotation over ℚ, then as constants (the
    // same entries, without polynomial arithmetic).
    let fixed = |q: &Quat, center: [QPoly; 3], w: QPoly| Frame::Rigid {
        m: rotation_numerator(q).map(|row| row.map(QPoly::constant)),
        n: QPoly::constant(norm2(q)),
        center,
        w,
    };
    for (points, weights) in motion.curve_shapes() {
        if points == 0 || weights.is_some_and(|w| w != points) {
            return Err(MotionError::MalformedCurve {
                points,
                weights: weights.unwrap_or(points),
            });
        }
    }
    let check_weight = |w: &QPoly| match first_root_in_span(w.prim(), span) {
        Some(at) => Err(MotionError::WeightVanishes { at }),
        None => Ok(()),
    };
    match motion {
        Motion::Static {
            center,
            orientation,
        } => Ok((
            fixed(orientation, constant_vec(center), QPoly::one()),
            vec![],
        )),
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
            let common = q.iter().fold(ZPoly::zero(), |g, c| g.gcd(c.prim()));
            if common.degree().unwrap_or(0) >= 1 || q.iter().all(QPoly::is_zero) {
                if let Some(at) = first_root_in_span(&common, span) {
                    return Err(MotionError::QuaternionVanishes { at });
                }
            }
            let c = to_poly_curve(center);
            check_weight(&c.denominator)?;
            let factors = vec![c.denominator.clone(), norm2(&q)];
            Ok((rigid(&q, c.numerators, c.denominator), factors))
        }
        Motion::Affine { matrix } => {
            // The twelve entries as one curve: one weight polynomial.
            let curve = matrix.flattened();
            let PolyCurve {
                numerators: entries,
                denominator: w,
            } = to_poly_curve(&curve);
            let poly = |r: usize, k: usize| entries[4 * r + k].clone();
            let l: Mat3<QPoly> = std::array::from_fn(|r| std::array::from_fn(|k| poly(r, k)));
            let d: [QPoly; 3] = std::array::from_fn(|r| poly(r, 3));
            check_weight(&w)?;
            let det_l = det3(&l);
            if let Some(at) = first_root_in_span(det_l.prim(), span) {
                return Err(MotionError::SingularAffine { at });
            }
            let factors = vec![w.clone(), det_l];
            Ok((Frame::Affine { l, d, w }, factors))
        }
        Motion::Helical { .. } => Err(MotionError::NotRational { kind: "helical" }),
    }
}

fn quaternion_curve(curve: &Bezier<Quat>) -> [QPoly; 4] {
    // The rotation of q is that of any positive multiple, so the weight
    // curve's denominator drops out; the weights stay in the numerators.
    to_poly_curve(curve).numerators
}

/// The matrix over ℚ[u] times the positive rational that makes its entries
/// integer polynomials with no common integer factor (a constant factor
/// `c` of a placement would rescale λ by `c²` and grow every coefficient).
fn to_integer_matrix(n: &Mat4<QPoly>) -> Mat4<ZPoly> {
    let entries = || n.iter().flatten().filter(|e| !e.is_zero());
    let den = entries().fold(Int::one(), |l, e| l.lcm(e.scale().denom()));
    let num = entries().fold(Int::zero(), |g, e| g.gcd(e.scale().numer()));
    let scale = Rat::new(den, num).unwrap_or_else(Rat::one);
    n.each_ref().map(|row| {
        row.each_ref().map(|e| {
            let factor = (&scale * e.scale()).floor();
            e.prim().mul_int(&factor)
        })
    })
}

/// `v` times the lcm of its denominators.
fn rat_vec_to_int<const N: usize>(v: &[Rat; N]) -> [Int; N] {
    let den = v.iter().fold(Int::one(), |l, r| l.lcm(r.denom()));
    v.each_ref().map(|x| x.numer() * &den.div_exact(x.denom()))
}

/// A placed body: its placement, its body quadric and what is known about
/// the determinant of the placement. The integer matrices are formed only
/// when asked for (each route to `f` needs one of them).
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedQuadric {
    frame: Frame<QPoly>,
    /// The body quadric `diag(D)` (interior `XᵀDX < 0`), scaled to integers.
    pub diagonal: [ZPoly; 4],
    /// Primitive polynomials nonzero on the span such that `det M(u)` is a
    /// constant times a product of their powers.
    pub det_factors: Vec<ZPoly>,
}

impl PlacedQuadric {
    /// The homogeneous body → world matrix `M(u)` with integer polynomial
    /// entries, up to a factor nonzero on the span.
    pub fn placement(&self) -> Mat4<ZPoly> {
        to_integer_matrix(&self.frame.forward())
    }

    /// The world → body matrix `N(u) ∝ M(u)⁻¹` with integer polynomial
    /// entries, up to a factor nonzero on the span.
    pub fn inverse(&self) -> Mat4<ZPoly> {
        to_integer_matrix(&self.frame.inverse())
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

    /// The longest number of the placement and body quadric, in bits (the
    /// larger of a rational's numerator and denominator): a size estimate.
    pub fn bits(&self) -> u64 {
        let poly = |p: &QPoly| {
            let s = p.scale();
            s.numer().bits().max(s.denom().bits()) + p.prim().max_bits()
        };
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
        let diagonal = self.diagonal.iter().map(ZPoly::max_bits).max();
        frame.max(diagonal).unwrap_or(0)
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
    /// centre curve. `None` for a body that turns or a rational centre curve.
    pub(crate) fn centred(&self) -> Option<Centred> {
        let Frame::Rigid { m, n, center, w } = &self.frame else {
            return None;
        };
        let constant = |p: &QPoly| p.degree().unwrap_or(0) == 0;
        if !(constant(n) && constant(w) && m.iter().flatten().all(constant)) {
            return None;
        }
        // Every input over one denominator D: m = M/D, n = n'/D, w = w'/D,
        // center = C/D. Each entry of N = rigid_inverse(m, n, center, w) is
        // a product of two inputs, so N·D² is integral, and the primitive
        // integer matrix (to_integer_matrix) is N·D²/g with g the gcd of its
        // coefficients: integer arithmetic only. N is rigid_inverse at a
        // zero centre (the blocks X, z) plus the centre column.
        let (m, n, w) = (
            m.each_ref().map(|r| r.each_ref().map(|e| e.coeff(0))),
            n.coeff(0),
            w.coeff(0),
        );
        let center = center.each_ref().map(QPoly::coeffs);
        let rats = || {
            m.iter()
                .flatten()
                .chain([&n, &w])
                .chain(center.iter().flatten())
        };
        let den = rats().fold(Int::one(), |l, r| l.lcm(r.denom()));
        let int = |r: &Rat| r.numer() * &den.div_exact(r.denom());
        let (m, n, w) = (
            m.each_ref().map(|r| r.each_ref().map(int)),
            int(&n),
            int(&w),
        );
        let center: [Vec<Int>; 3] = center.each_ref().map(|c| c.iter().map(int).collect());
        let blocks = rigid_inverse(&m, &n, &[Int::zero(), Int::zero(), Int::zero()], &w);
        // The centre column −mᵀ·C(u), coefficient by coefficient.
        let len = center.iter().map(Vec::len).max().unwrap_or(0);
        let column = (0..3).flat_map(|i| {
            let (m, center) = (&m, &center);
            (0..len).map(move |k| {
                (0..3).fold(Int::zero(), |mut s, j| {
                    if let Some(c) = center[j].get(k) {
                        s.add_mul(&m[j][i], c);
                    }
                    s
                })
            })
        });
        let g = blocks
            .iter()
            .flatten()
            .cloned()
            .chain(column)
            .fold(Int::zero(), |g, v| g.gcd(&v));
        if g.is_zero() {
            return None;
        }
        // At the centre, A = N₀ᵀ·D·N₀ with N₀ = [[X, 0], [0, z]]/g.
        let centred = congruence(
            &blocks.map(|row| row.map(|e| e.div_exact(&g))),
            &self.diagonal.each_ref().map(|e| e.coeff(0)),
        );
        Some(Centred {
            k: std::array::from_fn(|i| std::array::from_fn(|j| centred[i][j].clone())),
            kappa: -&centred[3][3],
            centre: center.map(ZPoly::new),
            denominator: w,
        })
    }

    /// The quadric at one parameter `u`, exactly, scaled to integers (a
    /// positive multiple of `A(u)`), from the placement's values there.
    pub fn quadric_at(&self, u: &Rat) -> Mat4<Int> {
        let n = integral(&self.frame.map(|p| p.eval_rat(u)).inverse());
        congruence(&n, &self.diagonal.each_ref().map(|e| e.coeff(0)))
    }
}

/// A body's placement and body quadric, with the factors of the placement's
/// determinant. Fails if the motion degenerates somewhere on the span
/// (decided exactly with the solver) or is not rational.
pub fn placed_quadric(body: &Body, span: &[Rat; 2]) -> Result<PlacedQuadric, MotionError> {
    let (frame, factors) = frame(&body.motion, span)?;
    let det_factors = factors
        .iter()
        .map(|f| f.prim().clone())
        .filter(|f| f.degree().unwrap_or(0) > 0)
        .collect();
    Ok(PlacedQuadric {
        frame,
        diagonal: rat_vec_to_int(&body_diagonal(&body.radii)).map(ZPoly::constant),
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
}
