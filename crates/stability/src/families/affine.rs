//! The families built on the similarity-affine construction:
//! `affine-degree` and `affine-cluster`.
//!
//! # The similarity-affine construction
//!
//! For high-degree motions, `B`'s placement is the affine map
//! `X = s(u)·R·Xbody + R·(x(u), 0, 0)` (an `affine` motion: a similarity of
//! degree `n`), i.e. `B = s(u)·E + c(u)` again. With `s(u) > 0` of degree `n`
//! (positive Bernstein coefficients) and `x(u) = r0·(1 + s(u)) + κ·p(u)`,
//! `p(u) = Π (u − ρⱼ)^mⱼ` with chosen rational roots `ρⱼ ∈ (0, 1)` and
//! `0 < κ < r0` (so `x > 0`), the level function is `φ = x/r0 − (1 + s) =
//! κ·p(u)/r0`: the contacts are exactly the `ρⱼ`, crossings for odd `mⱼ`
//! and tangencies (touch and separate again) for even `mⱼ`.

use super::homothetic::Pair;
use super::{int, pow10, rat, tilt, unit, v3};
use crate::truth::Truth;
use crate::{Case, Level, StabilityError, Surd};
use ccd_arith::Rat;
use ccd_exact::Scene;
use ccd_motion::{Bezier, Body, Mat34, Motion};
use ccd_quadric::{norm2, rotation_numerator};

/// Power-basis coefficients (low → high) of `Π (u − ρ)^m`.
pub fn poly_from_roots(roots: &[(Rat, u32)]) -> Vec<Rat> {
    let mut p = vec![Rat::one()];
    for (rho, m) in roots {
        for _ in 0..*m {
            let mut next = vec![Rat::zero(); p.len() + 1];
            for (i, c) in p.iter().enumerate() {
                next[i + 1] = &next[i + 1] + c;
                next[i] = &next[i] - &(c * rho);
            }
            p = next;
        }
    }
    p
}

fn binomial(n: usize, k: usize) -> Rat {
    (0..k).fold(Rat::one(), |acc, i| {
        &(&acc * &Rat::from((n - i) as i64)) / &Rat::from((i + 1) as i64)
    })
}

/// Bernstein coefficients of degree `n` of a power-basis polynomial
/// (`deg <= n`): `bᵢ = Σ_{j<=i} C(i, j)/C(n, j)·aⱼ`.
pub fn to_bernstein(a: &[Rat], n: usize) -> Vec<Rat> {
    (0..=n)
        .map(|i| {
            a.iter()
                .enumerate()
                .take(i + 1)
                .fold(Rat::zero(), |acc, (j, aj)| {
                    &acc + &(&(aj * &binomial(i, j)) / &binomial(n, j))
                })
        })
        .collect()
}

/// The similarity-affine construction (module docs) of degree `n` with
/// roots `roots` of `p`.
fn similarity(
    family: &str,
    name: String,
    k: Option<u32>,
    n: usize,
    roots: &[(Rat, u32)],
) -> Result<Case, StabilityError> {
    let e = Pair {
        radii: v3(int(2), int(1), rat(1, 2)),
        q: tilt(),
        s: Rat::one(),
        span: unit(),
    };
    let p = poly_from_roots(roots);
    if p.len() > n + 1 {
        return Err(StabilityError::Truth(format!("deg p > n = {n}")));
    }
    let kappa = rat(1, 2);
    let pb = to_bernstein(&p, n);
    // s(u): Bernstein coefficients 1/2 + i²/(n+1), all positive.
    let s: Vec<Rat> = (0..=n)
        .map(|i| &rat(1, 2) + &Rat::from_frac((i * i) as i64, (n + 1) as i64))
        .collect();
    let m = rotation_numerator(&e.q);
    let nq = norm2(&e.q);
    let r0 = &e.radii[0];
    let points: Vec<Mat34> = (0..=n)
        .map(|i| {
            let x = &(r0 * &(&Rat::one() + &s[i])) + &(&kappa * &pb[i]);
            std::array::from_fn(|row| {
                let rr = |col: usize| &m[row][col] / &nq;
                [&s[i] * &rr(0), &s[i] * &rr(1), &s[i] * &rr(2), &x * &rr(0)]
            })
        })
        .collect();
    let scene = Scene {
        span: e.span.clone(),
        a: e.body_a(Motion::Static {
            center: v3(Rat::zero(), Rat::zero(), Rat::zero()),
            orientation: e.q.clone(),
        }),
        b: Body {
            radii: e.radii.clone(),
            motion: Motion::Affine {
                matrix: Bezier {
                    points,
                    weights: None,
                },
            },
        },
    };
    // φ = κ·p(u) (sign only matters): Horner.
    let phi = |u: &Rat| {
        let pu = p.iter().rev().fold(Rat::zero(), |acc, c| &(&acc * u) + c);
        &kappa * &pu
    };
    let mut distinct: Vec<Rat> = roots.iter().map(|r| r.0.clone()).collect();
    distinct.sort();
    distinct.dedup();
    let contacts = distinct.into_iter().map(Surd::rational).collect();
    let truth = Truth::from_level(family, name.clone(), k, &e.span, contacts, &phi)?;
    Ok(Case {
        name: format!("{family}-{name}"),
        scene,
        truth,
    })
}

pub(super) fn affine_degree(level: Level) -> Result<Vec<Case>, StabilityError> {
    let ns: &[usize] = match level {
        Level::Shipped => &[2, 4],
        Level::Full => &[2, 3, 4, 6, 8, 10, 12, 15],
    };
    ns.iter()
        .map(|&n| {
            let roots = match n {
                2 => vec![(rat(2, 7), 1), (rat(5, 7), 1)],
                3 => vec![(rat(1, 4), 1), (rat(3, 5), 2)],
                _ => vec![(rat(1, 5), 1), (rat(1, 2), 2), (rat(4, 5), 1)],
            };
            similarity(
                "affine-degree",
                format!("n{n:02}"),
                Some(n as u32),
                n,
                &roots,
            )
        })
        .collect()
}

pub(super) fn affine_cluster(level: Level) -> Result<Vec<Case>, StabilityError> {
    let ks: Vec<u32> = match level {
        Level::Shipped => vec![2, 12],
        Level::Full => (1..=30).collect(),
    };
    ks.into_iter()
        .map(|k| {
            let a = rat(2, 7);
            let b = &a + &pow10(-(k as i32));
            similarity(
                "affine-cluster",
                format!("k{k:02}"),
                Some(k),
                3,
                &[(a, 1), (b, 1)],
            )
        })
        .collect()
}
