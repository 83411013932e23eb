use super::*;
use ccd_arith::Int;
use ccd_quadric::Ellipsoid;

fn r(p: i64, q: i64) -> Rat {
    Rat::from_frac(p, q)
}

fn rat_matrix(e: &Ellipsoid) -> Mat4<Rat> {
    e.quadric_matrix()
}

/// `e·Π (λ − rᵢ)` as `[e, a, b, c, d]` over ℚ.
fn quartic(e: i64, roots: [i64; 4]) -> [Rat; 5] {
    let mut c = vec![Rat::from(e)];
    for x in roots {
        let mut next = vec![Rat::zero(); c.len() + 1];
        for (i, ci) in c.iter().enumerate() {
            next[i] = &next[i] + ci;
            next[i + 1] = &next[i + 1] - &(ci * &Rat::from(x));
        }
        c = next;
    }
    std::array::from_fn(|i| c[i].clone())
}

/// The case of Theorem 3.10(2) decided exactly.
fn case_of(f: &[Rat; 5]) -> Case {
    if closed_form(f, Quantity::Sr11).unwrap().is_zero() {
        Case::TwoDouble
    } else {
        Case::Simple
    }
}

#[test]
fn double_root_of_known_quartics() {
    // One positive double root and two simple negative ones: case (2a).
    let f = quartic(-2, [2, 2, -1, -3]);
    assert_eq!(closed_form(&f, Quantity::Sr0).unwrap(), Rat::zero());
    assert_eq!(case_of(&f), Case::Simple);
    assert_eq!(double_root(&f, Case::Simple), Ok(Rat::from(2)));
    // Two double roots of opposite signs: case (2b).
    let g = quartic(-3, [5, 5, -2, -2]);
    assert_eq!(case_of(&g), Case::TwoDouble);
    assert_eq!(double_root(&g, Case::TwoDouble), Ok(Rat::from(5)));
    // The simple formula cannot be used where sr11 = 0.
    assert!(double_root(&g, Case::Simple).is_err());
}

#[test]
fn interval_double_root_encloses_the_exact_one() {
    let f = quartic(-2, [3, 3, -1, -7]).map(|c| Interval::from_rat(&c));
    let l = double_root(&f, Case::Simple).unwrap();
    assert!(l.lo <= 3.0 && 3.0 <= l.hi && l.hi - l.lo < 1e-12);
}

#[test]
fn rational_tangency_of_spheres_is_exact() {
    // Radius 5 at the origin and at (6, 8, 0): they touch at (3, 4, 0),
    // A's outward normal (3, 4, 0) ∝ (3/4, 1, 0).
    let a = Ellipsoid::axis_aligned([5, 5, 5].map(Rat::from), [0, 0, 0].map(Rat::from));
    let b = Ellipsoid::axis_aligned([5, 5, 5].map(Rat::from), [6, 8, 0].map(Rat::from));
    let (qa, qb) = (rat_matrix(&a), rat_matrix(&b));
    let f = characteristic(&qa, &qb);
    assert_eq!(case_of(&f), Case::TwoDouble);
    let e = from_quadrics(&qa, &qb, Case::TwoDouble).unwrap();
    assert_eq!(e.point, [3, 4, 0].map(Rat::from));
    assert_eq!(e.normal, [r(3, 4), Rat::one(), Rat::zero()]);
}

#[test]
fn rational_tangency_of_ellipsoids_is_exact() {
    // x²/4 + y² + z² <= 1 and the unit sphere at (3, 0, 0) touch at (2, 0, 0).
    let a = Ellipsoid::axis_aligned([2, 1, 1].map(Rat::from), [0, 0, 0].map(Rat::from));
    let b = Ellipsoid::axis_aligned([1, 1, 1].map(Rat::from), [3, 0, 0].map(Rat::from));
    let (qa, qb) = (rat_matrix(&a), rat_matrix(&b));
    let f = characteristic(&qa, &qb);
    let case = case_of(&f);
    let e = from_quadrics(&qa, &qb, case).unwrap();
    assert_eq!(e.point, [2, 0, 0].map(Rat::from));
    assert_eq!(e.normal, [1, 0, 0].map(Rat::from));
    // Swapped: B's outward normal at the same point is −x.
    let e = from_quadrics(&qb, &qa, case_of(&characteristic(&qb, &qa))).unwrap();
    assert_eq!(e.point, [2, 0, 0].map(Rat::from));
    assert_eq!(e.normal, [-1, 0, 0].map(Rat::from));
}

#[test]
fn the_wrong_case_or_a_separate_pair_is_not_a_point() {
    // Spheres apart: f has two distinct positive roots, no double one; the
    // case (2b) formula then has no rational root or gives a matrix of full
    // rank, whose adjugate column does not vanish but is no kernel; the
    // caller must decide the case, and with intervals around a separate
    // configuration the formula for (2a) is still a formula: here we only
    // check that nothing panics and that concentric equal spheres (M ≡ 0
    // at λ* = 1) are reported as not a single point.
    let a = Ellipsoid::axis_aligned([1, 1, 1].map(Rat::from), [0, 0, 0].map(Rat::from));
    let qa = rat_matrix(&a);
    let mut neg = qa.clone();
    for row in neg.iter_mut() {
        for x in row.iter_mut() {
            *x = -x.clone();
        }
    }
    // λA + (−A) vanishes at λ = 1: the kernel is everything.
    let f = characteristic(&qa, &neg);
    assert_eq!(f, quartic(-1, [1, 1, 1, 1]));
    assert!(matches!(
        from_quadrics(&qa, &neg, Case::TwoDouble),
        Err(ContactError::Undecided(_)) | Err(ContactError::Kernel)
    ));
}

#[test]
fn goal_follows_digits_and_size() {
    let body = |x: i64| Body {
        radii: [x, 1, 1].map(Rat::from),
        motion: ccd_motion::Motion::at_origin(),
    };
    let g = Goal::new(&body(4), &body(2), 15);
    assert_eq!(g.point, Rat::new(Int::from(4), Int::pow10(12)).unwrap());
    let g = Goal::new(&body(4), &body(2), 20);
    assert_eq!(g.normal, Rat::new(Int::from(4), Int::pow10(17)).unwrap());
    // The f64 floors are below the exact goals, and close to them.
    for (radii, digits) in [((4.0, 1.0), 15), ((4.0, 1.0), 20), ((3.7, 0.3), 30)] {
        let exact = Goal::new(&body(4), &body(2), digits);
        let exact = if radii.0 == 4.0 {
            exact
        } else {
            let b = |r: [Rat; 3]| Body {
                radii: r,
                motion: ccd_motion::Motion::at_origin(),
            };
            Goal::new(
                &b([r(37, 10), Rat::one(), Rat::one()]),
                &b([r(3, 10), Rat::one(), Rat::one()]),
                digits,
            )
        };
        let [p, n] = Goal::floors(radii.0, radii.1, digits);
        for (floor, goal) in [(p, &exact.point), (n, &exact.normal)] {
            let f = Rat::from_f64_exact(floor).unwrap();
            assert!(
                f <= *goal && f > goal * &r(999_999, 1_000_000),
                "{floor} {goal}"
            );
        }
    }
}

#[test]
fn interval_tangency_encloses_the_exact_point_tightly() {
    // (2a) with intervals: x²/4 + y² + z² <= 1 and an ellipsoid (1, 3/2, 1/2)
    // at (3, 0, 0) touch at (2, 0, 0), normal +x.
    let a = Ellipsoid::axis_aligned([2, 1, 1].map(Rat::from), [0, 0, 0].map(Rat::from));
    let b = Ellipsoid::axis_aligned([Rat::from(1), r(3, 2), r(1, 2)], [3, 0, 0].map(Rat::from));
    let (qa, qb) = (rat_matrix(&a), rat_matrix(&b));
    let case = case_of(&characteristic(&qa, &qb));
    assert_eq!(case, Case::Simple);
    let iv = |m: &Mat4<Rat>| {
        m.each_ref()
            .map(|row| row.each_ref().map(Interval::from_rat))
    };
    let e = from_quadrics(&iv(&qa), &iv(&qb), case).unwrap();
    for (x, want) in e.point.iter().zip([2.0, 0.0, 0.0]) {
        assert!(x.lo <= want && want <= x.hi && x.hi - x.lo < 1e-14, "{x:?}");
    }
    for (n, want) in e.normal.iter().zip([1.0, 0.0, 0.0]) {
        assert!(n.lo <= want && want <= n.hi && n.hi - n.lo < 1e-14, "{n:?}");
    }
}

#[test]
fn enclose_to_goal_says_whether_the_goal_is_met() {
    // Two static axis-aligned bodies touching at (2, 0, 0) (the pair of
    // `interval_tangency_encloses_the_exact_point_tightly`), at any time.
    let body = |radii: [Rat; 3], x: i64| Body {
        radii,
        motion: ccd_motion::Motion::Static {
            center: [x, 0, 0].map(Rat::from),
            orientation: ccd_motion::Motion::identity(),
        },
    };
    let a = body([2, 1, 1].map(Rat::from), 0);
    let b = body([Rat::from(1), r(3, 2), r(1, 2)], 3);
    let span = [Rat::zero(), Rat::one()];
    let t = r(1, 3);
    for digits in [15, 40] {
        let goal = Goal::new(&a, &b, digits);
        let precisions = [53];
        let (g, met) = enclose_to_goal(
            (&a, &b, &span),
            (&t, &t),
            Case::Simple,
            &goal,
            true,
            &precisions,
        )
        .unwrap();
        // f64 meets the default goal, not one of 37 digits.
        assert_eq!(met, digits == 15);
        assert_eq!(met, goal.met(&g));
        let plain = enclose(
            (&a, &b, &span),
            (&t, &t),
            Case::Simple,
            &goal,
            true,
            &precisions,
        );
        assert_eq!(plain, Ok(g));
    }
}
