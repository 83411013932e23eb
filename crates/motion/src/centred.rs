//! `f(λ; u)` of two bodies that never turn (static or translating along
//! polynomial curves), set up in the frame of A's centre: a handful of
//! products of constant 3×3 integer matrices and short polynomials in `u`
//! instead of two moving 4×4 quadrics and their determinant.
//!
//! # The formula
//!
//! A placed body's integer quadric is `A = Nᵀ·D·N` with `N` its inverse
//! placement `[[X, y(u)], [0, z]]` scaled to a primitive integer matrix
//! ([`crate::matrices`]); for a body that does not turn and moves along a
//! polynomial curve, `X` and `z` are constants and its centre is
//! `c(u) = −X⁻¹·y(u)`. The translation
//! `T = [[I, c_A], [0, 1]]` has determinant 1, so
//! `det(λA + B) = det(Tᵀ(λA + B)T)`, and in that frame
//!
//! `TᵀAT = [[K_A, 0], [0, −κ_A]]`, `TᵀBT = [[K_B, −K_B·d], [−dᵀK_B, dᵀK_B·d − κ_B]]`
//!
//! with `K = XᵀD₃X`, `κ = −d₄·z² > 0` and `d(u) = c_B(u) − c_A(u)` (the
//! scales of the integer quadrics, and so λ's, are kept exactly). With
//! `P(λ) = λK_A + K_B` and `d = e/δ` (`e` integer, `δ > 0`), the Schur
//! complement of `P` gives
//!
//! `δ²·det(λA + B) = det P·(eᵀK_B·e − δ²(κ_B + λκ_A)) − (K_B·e)ᵀ·adj P·(K_B·e)`,
//!
//! where `det P = λ³ det K_A + λ² tr(adj K_A·K_B) + λ tr(K_A·adj K_B) + det K_B`
//! and `adj P = λ² adj K_A + λ·(adj(K_A + K_B) − adj K_A − adj K_B) + adj K_B`.
//! The factor `δ²` is a positive constant, which the normalisation's content
//! removal takes out: the normalised `f` is the very polynomial of the
//! general route (checked against it by a property test below).

use ccd_arith::Int;
use ccd_poly::ZPoly;
use ccd_quadric::{adj3, det3, Mat3};

/// A body that does not turn, as the frame of its own centre sees it.
#[derive(Clone, Debug)]
pub(crate) struct Centred {
    /// `K = XᵀD₃X`, divided by [`Centred::scale`]: the integer quadric's
    /// constant 3×3 block.
    pub(crate) k: Mat3<Int>,
    /// `κ = −d₄·z² > 0`, divided by [`Centred::scale`]: minus the integer
    /// quadric's corner at its centre.
    pub(crate) kappa: Int,
    /// The common content `s > 0` of `K` and `κ` taken out of them: the
    /// quadric at the centre is `s·[[k, 0], [0, −kappa]]`.
    pub(crate) scale: Int,
    /// The centre curve `c(u)` times [`Centred::denominator`].
    pub(crate) centre: [ZPoly; 3],
    /// The centre curve's denominator (a nonzero integer).
    pub(crate) denominator: Int,
}

impl Centred {
    /// The body with block `k` (symmetric), corner `−kappa` (`kappa > 0`),
    /// centre curve `centre/denominator`; `k` and `kappa` are stored
    /// divided by their common content ([`Centred::scale`]).
    pub(crate) fn new(k: Mat3<Int>, kappa: Int, centre: [ZPoly; 3], denominator: Int) -> Centred {
        let mut scale = kappa.abs();
        for (i, row) in k.iter().enumerate() {
            for x in &row[i..] {
                if scale.is_one() {
                    break;
                }
                scale = scale.gcd(x);
            }
        }
        let (k, kappa) = if scale.is_one() || scale.is_zero() {
            (k, kappa)
        } else {
            (
                k.map(|row| row.map(|x| x.div_exact(&scale))),
                kappa.div_exact(&scale),
            )
        };
        Centred {
            k,
            kappa,
            scale,
            centre,
            denominator,
        }
    }
}

/// `Σ_ij m_ij·x_ij`: the trace of `m·x` for a symmetric `x`.
fn trace_product(m: &Mat3<Int>, x: &Mat3<Int>) -> Int {
    let mut s = Int::zero();
    for (mr, xr) in m.iter().zip(x) {
        for (a, b) in mr.iter().zip(xr) {
            s.add_mul(a, b);
        }
    }
    s
}

/// `Σ cᵢ·pᵢ` for integers `cᵢ` and polynomials `pᵢ`, accumulated in one
/// coefficient vector (no intermediate polynomials).
fn combination<'a>(terms: impl IntoIterator<Item = (&'a Int, &'a ZPoly)>) -> ZPoly {
    let mut acc: Vec<Int> = Vec::new();
    for (c, p) in terms {
        if c.is_zero() {
            continue;
        }
        if acc.len() < p.coeffs().len() {
            acc.resize(p.coeffs().len(), Int::zero());
        }
        for (a, x) in acc.iter_mut().zip(p.coeffs()) {
            a.add_mul(c, x);
        }
    }
    ZPoly::new(acc)
}

/// `vᵀ·m·v` for a symmetric constant `m`, from the products `vv[i][j] = v_i·v_j` (`i ≤ j`).
fn quadratic_form(m: &Mat3<Int>, vv: &[[ZPoly; 3]; 3]) -> ZPoly {
    let doubled: Mat3<Int> = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i < j {
                m[i][j].mul_i64(2)
            } else {
                Int::zero()
            }
        })
    });
    combination((0..3).flat_map(|i| {
        let (m, doubled) = (&m, &doubled);
        (i..3).map(move |j| {
            let c = if i == j { &m[i][i] } else { &doubled[i][j] };
            (c, &vv[i][j])
        })
    }))
}

/// `det(λA + B)` (high → low in λ) times a positive constant, for two
/// bodies that do not turn (module docs).
///
/// The outer coefficients are constants: with `b = K_B·e`,
/// `bᵀ·adj K_B·b = det K_B·eᵀK_B·e` (`K·adj K·K = det K·K`), so
/// `c_0 = −δ²κ_B·det K_B` and
/// `c_4 = −δ²κ_A·det K_A` (the determinants of the two constant quadrics).
///
/// The numbers are kept short by positive constants the normalisation's
/// content removal takes out anyway: `(e, δ)` divided by their common
/// content `h` (the formula is homogeneous of degree 2 in them, so `f`
/// is divided by `h²`), and each body's `K, κ` by theirs, `s_A` and `s_B`
/// ([`Centred::scale`]). The latter rescales λ: `det(λA/s_A + B/s_B)` has
/// coefficients `c_k/(s_A^k·s_B^(4−k))`, so each is multiplied back by
/// `p^k·q^(4−k)` with `p/q = s_A/s_B` in lowest terms (a positive
/// constant times `c_k`).
pub(crate) fn centred_characteristic(a: &Centred, b: &Centred) -> [ZPoly; 5] {
    // d = c_B − c_A = e/δ with e = w_A·C_B − w_B·C_A and δ = w_A·w_B,
    // both divided by their common content (only δ² enters).
    let minus_wb = -&b.denominator;
    let e: [ZPoly; 3] = std::array::from_fn(|i| {
        combination([(&a.denominator, &b.centre[i]), (&minus_wb, &a.centre[i])])
    });
    let delta = &a.denominator * &b.denominator;
    let h = e.iter().fold(delta.abs(), |g, p| {
        if g.is_one() {
            g
        } else {
            g.gcd(&p.content())
        }
    });
    let (e, delta) = if h.is_one() {
        (e, delta)
    } else {
        (e.map(|p| p.div_exact_int(&h)), delta.div_exact(&h))
    };
    // b = K_B·e and the products b_i·b_j.
    let kb_e: [ZPoly; 3] =
        std::array::from_fn(|i| combination((0..3).map(|j| (&b.k[i][j], &e[j]))));
    let bb: [[ZPoly; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i <= j {
                &kb_e[i] * &kb_e[j]
            } else {
                ZPoly::zero()
            }
        })
    });
    let delta2 = &delta * &delta;
    // s₀(u) = eᵀK_B·e − δ²κ_B.
    let s0 = &(0..3).fold(ZPoly::zero(), |s, i| &s + &(&e[i] * &kb_e[i]))
        - &ZPoly::constant(&delta2 * &b.kappa);
    let (adj_a, adj_b) = (adj3(&a.k), adj3(&b.k));
    let sum: Mat3<Int> = std::array::from_fn(|i| std::array::from_fn(|j| &a.k[i][j] + &b.k[i][j]));
    let adj_sum = adj3(&sum);
    let mixed: Mat3<Int> = std::array::from_fn(|i| {
        std::array::from_fn(|j| &(&adj_sum[i][j] - &adj_a[i][j]) - &adj_b[i][j])
    });
    // det P, low → high in λ.
    let p = [
        det3(&b.k),
        trace_product(&adj_b, &a.k),
        trace_product(&adj_a, &b.k),
        det3(&a.k),
    ];
    // bᵀ·adj P·b, low → high in λ (the constant term is not needed: c_0).
    let q = [&mixed, &adj_a].map(|m| quadratic_form(m, &bb));
    let da = &delta2 * &a.kappa;
    let minus_one = Int::from(-1);
    // c_k = p_k·s₀ − δ²κ_A·p_(k−1) − q_k for k = 1, 2, 3.
    let c = |k: usize| -> ZPoly {
        let ck = match q.get(k - 1) {
            Some(qk) => combination([(&p[k], &s0), (&minus_one, qk)]),
            None => s0.mul_int(&p[k]),
        };
        &ck - &ZPoly::constant(&da * &p[k - 1])
    };
    let f = [
        ZPoly::constant(-&(&da * &p[3])),
        c(3),
        c(2),
        c(1),
        ZPoly::constant(-&(&(&delta2 * &b.kappa) * &p[0])),
    ];
    rescale_lambda(f, &a.scale, &b.scale)
}

/// `c_k·p^k·q^(4−k)` for `[c_4, …, c_0]` (high → low in λ), with
/// `p/q = s_A/s_B` in lowest terms: `det(λA + B)` up to a positive
/// constant from `det(λA/s_A + B/s_B)` ([`centred_characteristic`]).
fn rescale_lambda(f: [ZPoly; 5], s_a: &Int, s_b: &Int) -> [ZPoly; 5] {
    if s_a == s_b {
        return f;
    }
    let g = s_a.gcd(s_b);
    let (p, q) = (s_a.div_exact(&g), s_b.div_exact(&g));
    let powers = |x: &Int| -> [Int; 5] {
        let mut out: [Int; 5] = std::array::from_fn(|_| Int::one());
        for k in 1..5 {
            out[k] = &out[k - 1] * x;
        }
        out
    };
    let (pp, qp) = (powers(&p), powers(&q));
    let mut f = f;
    for (i, c) in f.iter_mut().enumerate() {
        // c = c_k with k = 4 − i.
        let factor = &pp[4 - i] * &qp[i];
        if !factor.is_one() {
            *c = c.mul_int(&factor);
        }
    }
    f
}

#[cfg(test)]
mod tests {
    use crate::kinds::{Bezier, Body, Motion};
    use crate::matrices::placed_quadric;
    use crate::{normalise, CharPoly};
    use ccd_arith::Rat;

    fn rat(n: i64, d: i64) -> Rat {
        Rat::from_frac(n, d)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The centred route gives the very `f` of the general route
        /// (`det` of the two integer quadrics, normalised), on static and
        /// translating bodies of every orientation, with centre curves of
        /// degree 0 to 3 and long rational numbers.
        #[test]
        fn centred_route_is_the_general_route(
            radii in proptest::collection::vec((1i64..40, 1i64..9), 6),
            quats in proptest::collection::vec((-7i64..8, 1i64..1000), 8),
            points in proptest::collection::vec((-10_000_000_000i64..10_000_000_000, 1i64..1_000_000), 24),
            degrees in (0usize..4, 0usize..4),
            big in 0u32..40,
        ) {
            let body = |k: usize, deg: usize| {
                let mut q: [Rat; 4] = std::array::from_fn(|i| { let (n, d) = quats[4 * k + i]; rat(n, d) });
                if q.iter().all(Rat::is_zero) {
                    q[0] = Rat::one();
                }
                let scale = Rat::from_int(ccd_arith::Int::from(3).pow(big));
                let pts: Vec<[Rat; 3]> = (0..=deg)
                    .map(|p| std::array::from_fn(|i| {
                        let (n, d) = points[12 * k + 3 * p + i];
                        &rat(n, d) * &scale
                    }))
                    .collect();
                let orientation = q;
                let motion = if deg == 0 {
                    Motion::Static { center: pts[0].clone(), orientation }
                } else {
                    Motion::Translation { center: Bezier { points: pts, weights: None }, orientation }
                };
                let radii = std::array::from_fn(|i| { let (n, d) = radii[3 * k + i]; rat(n, d) });
                Body { radii, motion }
            };
            let span = [Rat::zero(), Rat::one()];
            let (a, b) = (body(0, degrees.0), body(1, degrees.1));
            let (pa, pb) = (placed_quadric(&a, &span).unwrap(), placed_quadric(&b, &span).unwrap());
            let general = CharPoly { coeffs: normalise(ccd_quadric::characteristic(&pa.quadric(), &pb.quadric())) };
            proptest::prop_assert!(pa.centred().is_some() && pb.centred().is_some());
            proptest::prop_assert_eq!(CharPoly::from_placed(&pa, &pb), general);
        }
    }
}
