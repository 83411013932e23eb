//! Every box holds its body: exact points of random moving ellipsoids at
//! random exact instants lie in the box of their slice.

use ccd_arith::Rat;
use ccd_broad::{slice_start, sweep, Aabb};
use ccd_motion::{Bezier, Body, HelicalCenter, Motion, Quat, Vec3};
use proptest::prelude::*;

fn rat() -> impl Strategy<Value = Rat> + Clone {
    (-40i64..=40, 1i64..=8).prop_map(|(p, q)| Rat::from_frac(p, q))
}
fn positive() -> impl Strategy<Value = Rat> + Clone {
    (1i64..=40, 1i64..=8).prop_map(|(p, q)| Rat::from_frac(p, q))
}
fn vec3() -> impl Strategy<Value = Vec3> + Clone {
    [rat(), rat(), rat()]
}
fn quat() -> impl Strategy<Value = Quat> + Clone {
    [rat(), rat(), rat(), rat()].prop_filter("nonzero", |q| q.iter().any(|x| !x.is_zero()))
}
fn weights(n: usize) -> impl Strategy<Value = Option<Vec<Rat>>> {
    prop::option::of(prop::collection::vec(positive(), n))
}
fn curve<P: std::fmt::Debug + Clone>(
    p: impl Strategy<Value = P> + Clone,
    weighted: bool,
) -> impl Strategy<Value = Bezier<P>> {
    (1usize..=4).prop_flat_map(move |n| {
        let w = if weighted {
            weights(n).boxed()
        } else {
            Just(None).boxed()
        };
        (prop::collection::vec(p.clone(), n), w)
            .prop_map(|(points, weights)| Bezier { points, weights })
    })
}

fn motion() -> impl Strategy<Value = Motion> {
    let mat = [
        [rat(), rat(), rat(), rat()],
        [rat(), rat(), rat(), rat()],
        [rat(), rat(), rat(), rat()],
    ];
    prop_oneof![
        (vec3(), quat()).prop_map(|(center, orientation)| Motion::Static {
            center,
            orientation
        }),
        (curve(vec3(), true), quat()).prop_map(|(center, orientation)| Motion::Translation {
            center,
            orientation
        }),
        (curve(quat(), false), curve(vec3(), true)).prop_map(|(orientation, center)| {
            Motion::Rigid {
                orientation,
                center,
            }
        }),
        curve(mat, true).prop_map(|matrix| Motion::Affine { matrix }),
    ]
}

/// Σ Bᵢⁿ(u)·wᵢ·Pᵢ and Σ Bᵢⁿ(u)·wᵢ, exactly.
fn bezier<const N: usize>(c: &Bezier<[Rat; N]>, u: &Rat) -> ([Rat; N], Rat) {
    let n = c.points.len() - 1;
    let mut num: [Rat; N] = std::array::from_fn(|_| Rat::zero());
    let mut den = Rat::zero();
    for (i, p) in c.points.iter().enumerate() {
        let binom = (0..i).fold(Rat::one(), |b, k| {
            b * Rat::from((n - k) as i64) / Rat::from((k + 1) as i64)
        });
        let mut basis = binom;
        for _ in 0..i {
            basis = basis * u;
        }
        for _ in i..n {
            basis = basis * (Rat::one() - u);
        }
        let w = c.weights.as_ref().map_or(Rat::one(), |w| w[i].clone());
        let bw = &basis * &w;
        for k in 0..N {
            num[k] = &num[k] + &(&bw * &p[k]);
        }
        den = den + bw;
    }
    (num, den)
}

fn point<const N: usize>(c: &Bezier<[Rat; N]>, u: &Rat) -> [Rat; N] {
    let (num, den) = bezier(c, u);
    num.map(|x| x / &den)
}

/// R(q)·v for the contract's R(q) = M(q)/|q|².
fn rotate(q: &Quat, v: &Vec3) -> Vec3 {
    let [w, x, y, z] = q;
    let two = Rat::from(2);
    let m = [
        [
            w * w + x * x - y * y - z * z,
            &two * &(x * y - w * z),
            &two * &(x * z + w * y),
        ],
        [
            &two * &(x * y + w * z),
            w * w - x * x + y * y - z * z,
            &two * &(y * z - w * x),
        ],
        [
            &two * &(x * z - w * y),
            &two * &(y * z + w * x),
            w * w - x * x - y * y + z * z,
        ],
    ];
    let n = w * w + x * x + y * y + z * z;
    std::array::from_fn(|k| (0..3).fold(Rat::zero(), |s, j| s + &m[k][j] * &v[j]) / &n)
}

/// The world point of body point `y` (on the unit sphere) at `u`, exactly.
fn place(body: &Body, y: &Vec3, u: &Rat) -> Option<Vec3> {
    let dy: Vec3 = std::array::from_fn(|k| &body.radii[k] * &y[k]);
    let add = |a: Vec3, b: Vec3| std::array::from_fn(|k| &a[k] + &b[k]);
    Some(match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => add(rotate(orientation, &dy), center.clone()),
        Motion::Translation {
            center,
            orientation,
        } => add(rotate(orientation, &dy), point(center, u)),
        Motion::Rigid {
            orientation,
            center,
        } => {
            let (q, _) = bezier(orientation, u);
            if q.iter().all(Rat::is_zero) {
                return None;
            }
            add(rotate(&q, &dy), point(center, u))
        }
        Motion::Affine { matrix } => {
            let flat = matrix.flattened();
            let m = point(&flat, u);
            std::array::from_fn(|k| {
                (0..3).fold(m[4 * k + 3].clone(), |s, j| s + &m[4 * k + j] * &dy[j])
            })
        }
        Motion::Helical { .. } => return None,
    })
}

fn contains(b: &Aabb, x: &Vec3) -> bool {
    (0..3).all(|k| {
        let lo = Rat::from_f64_exact(b.lo[k]).is_none_or(|lo| lo <= x[k]);
        let hi = Rat::from_f64_exact(b.hi[k]).is_none_or(|hi| x[k] <= hi);
        lo && hi
    })
}

/// A rational point of the unit sphere (inverse stereographic projection).
fn sphere() -> impl Strategy<Value = Vec3> {
    (rat(), rat()).prop_map(|(a, b)| {
        let s = &a * &a + &b * &b;
        let d = &s + &Rat::one();
        [
            Rat::from(2) * &a / &d,
            Rat::from(2) * &b / &d,
            (s - Rat::one()) / d,
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    #[test]
    fn every_box_holds_its_body(
        radii in [positive(), positive(), positive()],
        motion in motion(),
        t0 in rat(),
        width in positive(),
        depth in 0u32..=6,
        samples in prop::collection::vec((0i64..=1000, sphere()), 1..8),
    ) {
        let body = Body { radii, motion };
        let span = [t0.clone(), &t0 + &width];
        let swept = sweep(&body, &span, depth);
        prop_assert_eq!(swept.boxes.len(), 1 << depth);
        for (m, y) in samples {
            let u = Rat::from_frac(m, 1000);
            let t = &span[0] + &(&width * &u);
            let Some(x) = place(&body, &y, &u) else { continue };
            // A small ball around the point touches the body at t: it is
            // never proven apart from it there.
            let ball = Body {
                radii: [0; 3].map(|_| Rat::from_frac(1, 1000)),
                motion: Motion::Static { center: x.clone(), orientation: Motion::identity() },
            };
            let ball = sweep(&ball, &span, depth);
            prop_assert!(!swept.apart_throughout(&ball) && !ball.apart_throughout(&swept));
            // Every slice that holds t (two at a slice boundary).
            for (k, b) in swept.boxes.iter().enumerate() {
                if slice_start(&span, depth, k) <= t && t <= slice_start(&span, depth, k + 1) {
                    prop_assert!(contains(b, &x), "slice {k}: {x:?} not in {b:?}");
                    prop_assert!(!swept.apart(&ball, k) && !ball.apart(&swept, k), "slice {k}: touching pair apart");
                }
            }
        }
    }

    /// Helical motions (cos and sin are not rational): f64 points, so the
    /// check allows a relative 1e-12 for their own rounding.
    #[test]
    fn helical_boxes_hold_their_body(
        radii in [positive(), positive(), positive()],
        orientation in quat(),
        axis in vec3().prop_filter("nonzero axis", |a| a.iter().any(|x| !x.is_zero())),
        rate in rat(),
        base in vec3(), velocity in vec3(), cos in vec3(), sin in vec3(), frequency in rat(),
        depth in 0u32..=5,
        samples in prop::collection::vec((0i64..=1000, sphere()), 1..8),
    ) {
        let body = Body {
            radii: radii.clone(),
            motion: Motion::Helical {
                orientation: orientation.clone(), axis: axis.clone(), rate: rate.clone(),
                center: HelicalCenter { base: base.clone(), velocity: velocity.clone(), cos: cos.clone(), sin: sin.clone(), frequency: frequency.clone() },
            },
        };
        let span = [Rat::zero(), Rat::from(2)];
        let boxes = sweep(&body, &span, depth).boxes;
        let f = |v: &Vec3| v.each_ref().map(Rat::to_f64);
        for (m, y) in samples {
            let t = 2.0 * m as f64 / 1000.0;
            // Rodrigues about the unit axis, after R(orientation).
            let p = f(&rotate(&orientation, &std::array::from_fn(|k| &radii[k] * &y[k])));
            let a = f(&axis);
            let n = (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]).sqrt();
            let a = a.map(|x| x / n);
            let th = rate.to_f64() * t;
            let dot = a[0] * p[0] + a[1] * p[1] + a[2] * p[2];
            let cross = [a[1] * p[2] - a[2] * p[1], a[2] * p[0] - a[0] * p[2], a[0] * p[1] - a[1] * p[0]];
            let (b, v, c, s) = (f(&base), f(&velocity), f(&cos), f(&sin));
            let w = frequency.to_f64() * t;
            let x: [f64; 3] = std::array::from_fn(|k| {
                p[k] * th.cos() + cross[k] * th.sin() + a[k] * dot * (1.0 - th.cos())
                    + b[k] + v[k] * t + c[k] * w.cos() + s[k] * w.sin()
            });
            let k = ((t / 2.0) * (1u32 << depth) as f64).floor().min(((1u32 << depth) - 1) as f64) as usize;
            let bx = &boxes[k];
            for i in 0..3 {
                let tol = 1e-12 * (1.0 + x[i].abs());
                prop_assert!(bx.lo[i] - tol <= x[i] && x[i] <= bx.hi[i] + tol, "slice {k} axis {i}: {x:?} not in {bx:?}");
            }
        }
    }
}

#[test]
fn boxes_are_tight_enough_to_prune() {
    // A unit ball moving from x = 0 to x = 16 over [0, 1]: slice k's box
    // spans x ∈ [k − 1, k + 2] (up to rounding), not the whole sweep.
    let body = Body {
        radii: [1, 1, 1].map(Rat::from),
        motion: Motion::Translation {
            center: Bezier {
                points: vec![[0, 0, 0].map(Rat::from), [16, 0, 0].map(Rat::from)],
                weights: None,
            },
            orientation: Motion::identity(),
        },
    };
    let boxes = sweep(&body, &[Rat::zero(), Rat::one()], 4).boxes;
    for (k, b) in boxes.iter().enumerate() {
        assert!(
            (b.lo[0] - (k as f64 - 1.0)).abs() < 1e-9 && (b.hi[0] - (k as f64 + 2.0)).abs() < 1e-9,
            "{k}: {b:?}"
        );
        assert!(
            (b.lo[1] + 1.0).abs() < 1e-9 && (b.hi[1] - 1.0).abs() < 1e-9,
            "{k}: {b:?}"
        );
    }
    // Numbers beyond f64 give an infinite box, never a wrong one.
    let huge = Body {
        radii: ["1e400", "1", "1"].map(|s| s.parse().unwrap()),
        motion: Motion::at_origin(),
    };
    let b = sweep(&huge, &[Rat::zero(), Rat::one()], 2).boxes[0];
    assert!(b.hi[0].is_infinite() && b.lo[0].is_infinite());
}

#[test]
fn a_separating_plane_prunes_what_boxes_cannot() {
    // Two unit balls at (0, 0, 0) and (1.5, 1.5, 0): 2.12 apart, so
    // separate, but their boxes overlap.
    let ball = |x: i64| Body {
        radii: [1, 1, 1].map(Rat::from),
        motion: Motion::Static {
            center: [Rat::from_frac(x, 2), Rat::from_frac(x, 2), Rat::zero()],
            orientation: Motion::identity(),
        },
    };
    let span = [Rat::zero(), Rat::one()];
    let (a, b) = (sweep(&ball(0), &span, 0), sweep(&ball(3), &span, 0));
    assert!(a.boxes[0].overlaps(&b.boxes[0]));
    assert!(a.apart(&b, 0) && b.apart(&a, 0));
    // At (1.4, 1.4, 0) they overlap: not apart.
    let near = Body {
        radii: [1, 1, 1].map(Rat::from),
        motion: Motion::Static {
            center: [Rat::from_frac(7, 5), Rat::from_frac(7, 5), Rat::zero()],
            orientation: Motion::identity(),
        },
    };
    assert!(!a.apart(&sweep(&near, &span, 0), 0));
}
