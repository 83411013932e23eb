//! Moving quadric matrices `A(t) ∝ N(t)ᵀ·D·N(t)` with integer polynomial
//! entries in `u ∈ [0, 1]`, built from a motion and validated exactly.

use crate::curve::{bernstein_to_power, to_poly_curve};
use crate::error::MotionError;
use crate::kinds::{Bezier, Body, Motion, Quat};
use ccd_arith::{Int, Rat};
use ccd_poly::{QPoly, ZPoly};
use ccd_quadric::{
    affine_inverse, body_diagonal, congruence, det3, norm2, rigid_inverse, rotation_numerator,
    Mat3, Mat4,
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

/// The inverse placement `N(u)` over ℚ[u] (up to a positive factor, or a
/// nonzero one for affine motions, whose square is what counts), and the
/// polynomials whose powers make up `det N` (the weight curve, and `|q|²`
/// or `det L`): the only factors `det A` can have.
fn inverse_placement(
    motion: &Motion,
    span: &[Rat; 2],
) -> Result<(Mat4<QPoly>, Vec<QPoly>), MotionError> {
    let rigid = |q: &[QPoly; 4], center: &[QPoly; 3], w: &QPoly| {
        rigid_inverse(&rotation_numerator(q), &norm2(q), center, w)
    };
    let check_weight = |w: &QPoly| match first_root_in_span(w.prim(), span) {
        Some(at) => Err(MotionError::WeightVanishes { at }),
        None => Ok(()),
    };
    match motion {
        Motion::Static {
            center,
            orientation,
        } => Ok((
            rigid(
                &constant_vec(orientation),
                &constant_vec(center),
                &QPoly::one(),
            ),
            vec![],
        )),
        Motion::Translation {
            center,
            orientation,
        } => {
            let c = to_poly_curve(center);
            check_weight(&c.denominator)?;
            let m = rigid(&constant_vec(orientation), &c.numerators, &c.denominator);
            Ok((m, vec![c.denominator]))
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
            Ok((
                rigid(&q, &c.numerators, &c.denominator),
                vec![c.denominator, norm2(&q)],
            ))
        }
        Motion::Affine { matrix } => {
            let entry = |r: usize, k: usize| -> Bezier<[Rat; 1]> {
                Bezier {
                    points: matrix.points.iter().map(|m| [m[r][k].clone()]).collect(),
                    weights: matrix.weights.clone(),
                }
            };
            let poly = |r: usize, k: usize| -> QPoly {
                let [p] = to_poly_curve(&entry(r, k)).numerators;
                p
            };
            let l: Mat3<QPoly> = std::array::from_fn(|r| std::array::from_fn(|k| poly(r, k)));
            let d: [QPoly; 3] = std::array::from_fn(|r| poly(r, 3));
            let w = match &matrix.weights {
                Some(ws) => bernstein_to_power(ws),
                None => QPoly::one(),
            };
            check_weight(&w)?;
            let det_l = det3(&l);
            if let Some(at) = first_root_in_span(det_l.prim(), span) {
                return Err(MotionError::SingularAffine { at });
            }
            Ok((affine_inverse(&l, &d, &w), vec![w, det_l]))
        }
        Motion::Helical { .. } => Err(MotionError::NotRational { kind: "helical" }),
    }
}

fn quaternion_curve(curve: &Bezier<Quat>) -> [QPoly; 4] {
    std::array::from_fn(|k| {
        let vals: Vec<Rat> = curve.points.iter().map(|q| q[k].clone()).collect();
        bernstein_to_power(&vals)
    })
}

/// Lowest common multiple of positive integers.
fn lcm(a: &Int, b: &Int) -> Int {
    (a * b).div_exact(&a.gcd(b)).abs()
}

/// Clears the denominators of a matrix over ℚ[u] by one positive integer
/// and divides out the polynomial gcd of all entries (a common factor `g`
/// of `N` scales the quadric by `g²`, which never changes a sign).
fn to_integer_matrix(n: &Mat4<QPoly>) -> Mat4<ZPoly> {
    let den = n
        .iter()
        .flatten()
        .fold(Int::one(), |l, e| lcm(&l, e.scale().denom()));
    let m: Mat4<ZPoly> = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let e = &n[i][j];
            let factor = (&Rat::from_int(den.clone()) * e.scale()).floor();
            e.prim().mul_int(&factor)
        })
    });
    let g = m.iter().flatten().fold(ZPoly::zero(), |g, e| g.gcd(e));
    if g.degree().unwrap_or(0) == 0 && g.content().is_one() {
        return m;
    }
    m.map(|row| row.map(|e| e.div_exact(&g).expect("g divides every entry")))
}

fn rat_vec_to_int<const N: usize>(v: &[Rat; N]) -> [Int; N] {
    let den = v.iter().fold(Int::one(), |l, r| lcm(&l, r.denom()));
    std::array::from_fn(|i| (&Rat::from_int(den.clone()) * &v[i]).floor())
}

/// A moving quadric and what is known about its determinant.
#[derive(Clone, Debug, PartialEq)]
pub struct PlacedQuadric {
    /// `A(u)` with integer polynomial entries (interior `XᵀA(u)X < 0`), up to
    /// a factor positive on the span.
    pub matrix: Mat4<ZPoly>,
    /// Primitive polynomials nonzero on the span such that `det A(u)` is a
    /// constant times a product of their powers.
    pub det_factors: Vec<ZPoly>,
}

/// The moving quadric of a body, with the factors of its determinant.
/// Fails if the motion degenerates somewhere on the span (decided exactly
/// with the solver) or is not rational.
pub fn placed_quadric(body: &Body, span: &[Rat; 2]) -> Result<PlacedQuadric, MotionError> {
    let (inverse, factors) = inverse_placement(&body.motion, span)?;
    let n = to_integer_matrix(&inverse);
    let d = rat_vec_to_int(&body_diagonal(&body.radii)).map(ZPoly::constant);
    let det_factors = factors
        .iter()
        .map(|f| f.prim().clone())
        .filter(|f| f.degree().unwrap_or(0) > 0)
        .collect();
    Ok(PlacedQuadric {
        matrix: congruence(&n, &d),
        det_factors,
    })
}

/// The moving quadric `A(u)` of a body (interior `XᵀA(u)X < 0`), with
/// integer polynomial entries in `u = (t − t0)/(t1 − t0)`, up to a factor
/// positive on the span. Fails if the motion degenerates somewhere on the
/// span (decided exactly with the solver) or is not rational.
pub fn moving_quadric(body: &Body, span: &[Rat; 2]) -> Result<Mat4<ZPoly>, MotionError> {
    Ok(placed_quadric(body, span)?.matrix)
}
