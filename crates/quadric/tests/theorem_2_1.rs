//! Theorem 3.10 (signs of the closed-form subresultants) against Theorem 2.1
//! decided independently: exact real-root isolation of `f(λ)` and the
//! multiplicities of its positive roots.
//!
//! Pairs: thousands of random ones; exactly touching ones built by
//! construction (spheres at distance r1 + r2, an ellipsoid and its copy
//! shifted along a principal axis by twice that semi-axis, a rotated
//! ellipsoid and its mirror image in a tangent plane at a rational point);
//! and the same moved by 10⁻³⁰ either way.

use ccd_arith::{Int, Rat};
use ccd_poly::ZPoly;
use ccd_quadric::{
    characteristic, classify_pair, classify_quartic, congruence, Configuration, Ellipsoid, Mat4,
};

/// Theorem 2.1: two distinct positive roots → separate; a positive double
/// root → touching; no positive root → overlapping.
fn by_root_counting(f: &[Rat; 5]) -> Configuration {
    let den = f.iter().fold(Int::one(), |l, c| {
        (&l * c.denom()).div_exact(&l.gcd(c.denom()))
    });
    let coeffs: Vec<Int> = f
        .iter()
        .rev()
        .map(|c| (&Rat::from_int(den.clone()) * c).floor())
        .collect();
    let p = ZPoly::new(coeffs);
    // Cauchy bound on the roots.
    let lead = p.leading().expect("quartic").abs();
    let bound = p
        .coeffs()
        .iter()
        .map(|c| Rat::new(c.abs(), lead.clone()).expect("lead ≠ 0"))
        .max()
        .expect("nonempty")
        + Rat::one();
    let deriv = p.derivative();
    let mut simple = 0;
    let mut double = 0;
    for mut r in ccd_solver::isolate(&p, &Rat::zero(), &bound).expect("nonzero") {
        assert!(r.lo().signum() >= 0);
        if r.exact_value().is_some_and(|v| v.is_zero()) {
            panic!("λ = 0 is never a root for ellipsoids");
        }
        if r.sign_of(&deriv) == 0 {
            double += 1;
        } else {
            simple += 1;
        }
    }
    match (simple, double) {
        (2, 0) => Configuration::Separate,
        (0, 1) => Configuration::ExternalTouch,
        (0, 0) => Configuration::Overlap,
        other => panic!("impossible positive-root pattern for two ellipsoids: {other:?}"),
    }
}

fn check(a: &Mat4<Rat>, b: &Mat4<Rat>) -> Configuration {
    let f = characteristic(a, b);
    let by_signs = classify_quartic(&f, Rat::signum);
    assert_eq!(
        by_signs,
        by_root_counting(&f),
        "Theorem 3.10 and Theorem 2.1 disagree on f = {f:?}"
    );
    by_signs
}

fn check_pair(a: &Ellipsoid, b: &Ellipsoid) -> Configuration {
    let c = check(&a.quadric_matrix(), &b.quadric_matrix());
    assert_eq!(c, classify_pair(a, b));
    c
}

/// A deterministic xorshift generator: reproducible without a dependency.
struct Gen(u64);
impl Gen {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
    fn rat(&mut self, lo: i64, hi: i64) -> Rat {
        Rat::from_frac(self.int(lo * 8, hi * 8), 8)
    }
    fn positive(&mut self) -> Rat {
        Rat::from_frac(self.int(1, 40), 8)
    }
    fn quat(&mut self) -> [Rat; 4] {
        loop {
            let q = [
                self.rat(-3, 3),
                self.rat(-3, 3),
                self.rat(-3, 3),
                self.rat(-3, 3),
            ];
            if q.iter().any(|c| !c.is_zero()) {
                return q;
            }
        }
    }
    fn ellipsoid(&mut self) -> Ellipsoid {
        Ellipsoid {
            radii: [self.positive(), self.positive(), self.positive()],
            center: [self.rat(-4, 4), self.rat(-4, 4), self.rat(-4, 4)],
            orientation: self.quat(),
        }
    }
    /// A rational point of the unit sphere: (2s, 2t, 1 − s² − t²)/(1 + s² + t²).
    fn unit(&mut self) -> [Rat; 3] {
        let (s, t) = (self.rat(-3, 3), self.rat(-3, 3));
        let d = &(&Rat::one() + &(&s * &s)) + &(&t * &t);
        [
            &(&s * &Rat::from(2)) / &d,
            &(&t * &Rat::from(2)) / &d,
            &(&(&Rat::one() - &(&s * &s)) - &(&t * &t)) / &d,
        ]
    }
}

fn tiny() -> Rat {
    Rat::new(Int::one(), Int::pow10(30)).unwrap()
}
fn add(a: &[Rat; 3], b: &[Rat; 3], k: &Rat) -> [Rat; 3] {
    std::array::from_fn(|i| &a[i] + &(&b[i] * k))
}

#[test]
fn random_pairs_agree() {
    let mut g = Gen(0x9e3779b97f4a7c15);
    let mut seen = std::collections::HashMap::new();
    for _ in 0..2000 {
        let (a, b) = (g.ellipsoid(), g.ellipsoid());
        *seen.entry(check_pair(&a, &b)).or_insert(0) += 1;
    }
    // Both generic outcomes occur plenty; touching has probability zero here.
    assert!(
        seen.get(&Configuration::Separate).copied().unwrap_or(0) > 200,
        "{seen:?}"
    );
    assert!(
        seen.get(&Configuration::Overlap).copied().unwrap_or(0) > 200,
        "{seen:?}"
    );
}

#[test]
fn spheres_at_distance_r1_plus_r2() {
    let mut g = Gen(12345);
    for _ in 0..100 {
        let (r1, r2) = (g.positive(), g.positive());
        let c = [g.rat(-4, 4), g.rat(-4, 4), g.rat(-4, 4)];
        let dir = g.unit();
        let sphere = |r: &Rat, center: [Rat; 3]| Ellipsoid {
            radii: [r.clone(), r.clone(), r.clone()],
            center,
            orientation: g_identity(),
        };
        let a = sphere(&r1, c.clone());
        let d = &r1 + &r2;
        assert_eq!(
            check_pair(&a, &sphere(&r2, add(&c, &dir, &d))),
            Configuration::ExternalTouch
        );
        assert_eq!(
            check_pair(&a, &sphere(&r2, add(&c, &dir, &(&d + &tiny())))),
            Configuration::Separate
        );
        assert_eq!(
            check_pair(&a, &sphere(&r2, add(&c, &dir, &(&d - &tiny())))),
            Configuration::Overlap
        );
    }
}

fn g_identity() -> [Rat; 4] {
    [Rat::one(), Rat::zero(), Rat::zero(), Rat::zero()]
}

/// Column `k` of `R(q) = M(q)/|q|²`: the world direction of body axis `k`.
fn axis(q: &[Rat; 4], k: usize) -> [Rat; 3] {
    let m = ccd_quadric::rotation_numerator(q);
    let n = ccd_quadric::norm2(q);
    std::array::from_fn(|i| &m[i][k] / &n)
}

#[test]
fn copies_shifted_along_a_principal_axis() {
    let mut g = Gen(777);
    for _ in 0..100 {
        let a = g.ellipsoid();
        let k = g.int(0, 2) as usize;
        let dir = axis(&a.orientation, k);
        let d = &a.radii[k] * &Rat::from(2);
        let shifted = |by: &Rat| Ellipsoid {
            center: add(&a.center, &dir, by),
            ..a.clone()
        };
        assert_eq!(check_pair(&a, &shifted(&d)), Configuration::ExternalTouch);
        assert_eq!(
            check_pair(&a, &shifted(&(&d + &tiny()))),
            Configuration::Separate
        );
        assert_eq!(
            check_pair(&a, &shifted(&(&d - &tiny()))),
            Configuration::Overlap
        );
    }
}

/// The homogeneous reflection in the plane through `p` with normal `n`,
/// times `|n|²` (a positive factor): `X ↦ X − 2 (n·(X − p)) n / |n|²`.
fn reflection(p: &[Rat; 3], n: &[Rat; 3]) -> Mat4<Rat> {
    let nn = n.iter().fold(Rat::zero(), |s, c| &s + &(c * c));
    let np = n.iter().zip(p).fold(Rat::zero(), |s, (a, b)| &s + &(a * b));
    let two = Rat::from(2);
    std::array::from_fn(|i| {
        std::array::from_fn(|j| match (i, j) {
            (3, 3) => nn.clone(),
            (3, _) => Rat::zero(),
            (i, 3) => &(&two * &np) * &n[i],
            (i, j) => {
                let id = if i == j { nn.clone() } else { Rat::zero() };
                &id - &(&(&two * &n[i]) * &n[j])
            }
        })
    })
}

#[test]
fn mirror_images_in_a_rational_tangent_plane() {
    let mut g = Gen(4242);
    for _ in 0..100 {
        let a = g.ellipsoid();
        // A rational surface point and its normal, in the body frame …
        let u = g.unit();
        let body_p: [Rat; 3] = std::array::from_fn(|i| &u[i] * &a.radii[i]);
        let body_n: [Rat; 3] = std::array::from_fn(|i| &u[i] / &a.radii[i]);
        // … and in the world: X = R·Xbody + c.
        let r: Vec<[Rat; 3]> = (0..3).map(|k| axis(&a.orientation, k)).collect();
        let world = |v: &[Rat; 3]| -> [Rat; 3] {
            std::array::from_fn(|i| (0..3).fold(Rat::zero(), |s, k| &s + &(&r[k][i] * &v[k])))
        };
        let p = add(&world(&body_p), &a.center, &Rat::one());
        let n = world(&body_n);
        let ma = a.quadric_matrix();
        // B = H A H (H is an involution up to the factor |n|²).
        for (shift, expected) in [
            (Rat::zero(), Configuration::ExternalTouch),
            (tiny(), Configuration::Separate),
            (-tiny(), Configuration::Overlap),
        ] {
            let plane_point = add(&p, &n, &(&shift * &Rat::from_frac(1, 2)));
            let h = reflection(&plane_point, &n);
            let mb = congruence_full(&h, &ma);
            assert_eq!(check(&ma, &mb), expected, "shift {shift}");
        }
    }
}

/// `Hᵀ·M·H` for a general symmetric `M` (the library's `congruence` takes a
/// diagonal middle factor).
fn congruence_full(h: &Mat4<Rat>, m: &Mat4<Rat>) -> Mat4<Rat> {
    let mh: Mat4<Rat> = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(Rat::zero(), |s, k| &s + &(&m[i][k] * &h[k][j])))
    });
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..4).fold(Rat::zero(), |s, k| &s + &(&h[k][i] * &mh[k][j])))
    })
}

#[test]
fn congruence_with_identity_is_the_body_quadric() {
    let id: Mat4<Rat> = std::array::from_fn(|i| {
        std::array::from_fn(|j| if i == j { Rat::one() } else { Rat::zero() })
    });
    let d = [Rat::from(1), Rat::from(4), Rat::from(9), Rat::from(-36)];
    let m = congruence(&id, &d);
    assert_eq!(m[1][1], Rat::from(4));
    assert_eq!(congruence_full(&id, &m), m);
}
