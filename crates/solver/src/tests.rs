//! Isolation, refinement and sign decisions against roots known by
//! construction.

use crate::{has_root_in, isolate, SolverError};
use ccd_arith::{Int, Interval, Rat};
use ccd_poly::ZPoly;
use proptest::prelude::*;

/// `q·t − p`, the linear factor with root `p/q`.
fn linear(r: &Rat) -> ZPoly {
    ZPoly::new(vec![-r.numer().clone(), r.denom().clone()])
}

fn product(factors: &[(Rat, u32)]) -> ZPoly {
    factors
        .iter()
        .fold(ZPoly::one(), |acc, (r, m)| &acc * &linear(r).pow(*m))
}

/// A root pair at `a`: `2^(2k)·(d·t − n)² ∓ d²` for `a = n/d`, with real
/// roots `a ± 2^(−k)` (`hit`, a near hit) or complex roots `a ± 2^(−k)·i`
/// (a near miss).
pub(crate) fn cluster(a: &Rat, k: u64, hit: bool) -> ZPoly {
    let two_k = Int::one().shl(2 * k);
    let (n, d) = (a.numer().clone(), a.denom().clone());
    let sq = ZPoly::new(vec![
        &(&n * &n) * &two_k,
        -&(&(&n * &d) * &two_k.shl(1)),
        &(&d * &d) * &two_k,
    ]);
    let dd = ZPoly::new(vec![&d * &d]);
    if hit {
        &sq - &dd
    } else {
        &sq + &dd
    }
}

/// The dyadic interval of width `2^(−j)` holding `a`.
pub(crate) fn dyadic_node(a: &Rat, j: u64) -> (Rat, Rat) {
    let lo = Rat::dyadic(a.mul_pow2(j as i64).floor(), j);
    let hi = &lo + &Rat::dyadic(Int::one(), j);
    (lo, hi)
}

/// The filter-only isolation of `p` on `[0, 1]` from enclosures of its
/// Bernstein coefficients, scaled by one power of two so that the longest
/// has about 900 bits: the roots it yields, and whether it is undecided.
fn filtered_roots(p: &ZPoly) -> (Vec<crate::RealRoot>, bool) {
    let (found, undecided, _) = filtered_roots_counted(p);
    (found, undecided)
}

/// [`filtered_roots`] and the number of nodes split.
fn filtered_roots_counted(p: &ZPoly) -> (Vec<crate::RealRoot>, bool, usize) {
    let b = ccd_poly::Bernstein::from_power(p, &Rat::zero(), &Rat::one());
    let top = b.coeffs().iter().map(Int::bits).max().unwrap_or(0) as i64;
    let coeffs: Vec<Interval> = b
        .coeffs()
        .iter()
        .map(|c| Interval::from_int_scaled(c, top - 900))
        .collect();
    let model = std::sync::Arc::new(crate::SignProbe::new(p));
    let mut iter = crate::RootIter::filtered(model, &Rat::zero(), &Rat::one(), &coeffs);
    let found = iter.by_ref().collect();
    (found, iter.undecided(), iter.splits())
}

fn all_roots(p: &ZPoly, lo: &Rat, hi: &Rat) -> Vec<crate::RealRoot> {
    isolate(p, lo, hi).expect("nonzero").collect()
}

#[test]
fn exact_roots_at_ends_and_split_points() {
    let roots = [
        Rat::zero(),
        Rat::from_frac(1, 4),
        Rat::from_frac(1, 2),
        Rat::one(),
    ];
    let p = product(&roots.iter().map(|r| (r.clone(), 1)).collect::<Vec<_>>());
    let found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 4);
    for (f, r) in found.iter().zip(&roots) {
        assert_eq!(f.exact_value(), Some(r), "{f:?}");
    }
}

#[test]
fn multiple_roots_are_found_once() {
    let p = product(&[(Rat::from_frac(1, 3), 3), (Rat::from_frac(2, 3), 2)]);
    let found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 2);
    assert!(found[0].lo() <= &Rat::from_frac(1, 3) && &Rat::from_frac(1, 3) <= found[0].hi());
}

#[test]
fn irrational_roots_refine_to_any_width() {
    // t² − 2 on [0, 2]: √2.
    let p = ZPoly::from_i64s(&[-2, 0, 1]);
    let mut r = all_roots(&p, &Rat::zero(), &Rat::from(2)).remove(0);
    let w = Rat::new(Int::one(), Int::pow10(60)).unwrap();
    r.refine_to(&w);
    assert!(r.width() <= w);
    // lo² < 2 < hi², exactly.
    assert!(r.lo() * r.lo() < Rat::from(2) && r.hi() * r.hi() > Rat::from(2));
}

/// A root with a close neighbour just beyond an end of its enclosure, the
/// end next to it: Newton's step only halves the error there (one bit per
/// exact evaluation), and the refinement cuts slivers off that end
/// instead. The roots `1/2 ± 2^(−600)/√3` of `3·2^1200·(t − 1/2)² − 1`
/// (times `5t − 1`), refined to `2^(−3000)`: each enclosure is that narrow
/// and holds its root (a sign change of `p`, exactly, on the right side of
/// `1/2`).
#[test]
fn a_root_next_to_its_neighbour_refines_fast_and_right() {
    let pair = ZPoly::new(vec![
        Int::one().shl(1198) * Int::from(3) - Int::one(),
        -(Int::one().shl(1200) * Int::from(3)),
        Int::one().shl(1200) * Int::from(3),
    ]);
    let p = &pair * &linear(&Rat::from_frac(1, 5));
    let mut found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 3);
    let target = pow2(3000);
    let half = Rat::from_frac(1, 2);
    for (i, r) in found.iter_mut().enumerate().skip(1) {
        r.refine_to(&target);
        assert!(r.width() <= target);
        assert!(p.sign_at(r.lo()) * p.sign_at(r.hi()) < 0);
        assert_eq!(i == 1, r.hi() < &half, "{i}: {r:?}");
    }
}

/// The roots `1/3`, `1/3 + 2^(−700)` and `5/7`, and quantities whose signs
/// there take the pair apart or sit `2^(−1500)` past a root, all times
/// `2^(LOCAL_WORTH/2 + 1000)`: every exact evaluation of them is costly,
/// so the roots' model is re-centred next to the pair (`SignProbe`; the
/// test checks that it decided points) and each quantity next to the
/// enclosure (`RealRoot::sign_with`, whose Descartes rounds it skips while
/// the quantity's root is inside). The signs are those of the polynomials
/// themselves, and the enclosures, refined to `2^(−2000)`, hold the roots.
#[test]
fn costly_polynomials_get_the_exact_signs_next_to_a_pair() {
    let s = crate::LOCAL_WORTH / 2 + 1000;
    let a = Rat::from_frac(1, 3);
    let d = pow2(700);
    let roots = [a.clone(), &a + &d, Rat::from_frac(5, 7)];
    let p = product(&roots.iter().map(|r| (r.clone(), 1)).collect::<Vec<_>>());
    let scale = Int::one().shl(s);
    let model = std::sync::Arc::new(crate::SignProbe::new(&p.mul_int(&scale)));
    let cuts = [&a - &d, &a + &d.mul_pow2(-1), &a + &d.mul_pow2(1)];
    let found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 3);
    for (r, alpha) in found.iter().zip(&roots) {
        let sign_lo = p.sign_at(r.lo());
        let mut costly =
            crate::RealRoot::isolated(model.clone(), r.lo().clone(), r.hi().clone(), sign_lo);
        // And one 2^(−1500) past the root: decided only after rounds of
        // Descartes' tests, which the re-centred quantity skips while its
        // root is in the enclosure.
        let past = alpha + &pow2(1500);
        for c in cuts.iter().chain([&past]) {
            let q = linear(c).mul_int(&scale);
            let expected = if alpha > c { 1 } else { -1 };
            assert_eq!(
                costly.sign_with(&crate::SignProbe::new(&q)),
                expected,
                "{alpha} vs {c}"
            );
        }
        let target = pow2(2000);
        costly.refine_to(&target);
        assert!(costly.width() <= target);
        assert!(costly.lo() <= alpha && alpha <= costly.hi());
    }
    assert!(model.recentred_hits() > 10, "{}", model.recentred_hits());
}

#[test]
fn identically_zero_and_empty_interval_are_errors() {
    assert!(matches!(
        isolate(&ZPoly::zero(), &Rat::zero(), &Rat::one()),
        Err(SolverError::IdenticallyZero)
    ));
    assert!(matches!(
        isolate(&ZPoly::x(), &Rat::one(), &Rat::one()),
        Err(SolverError::EmptyInterval)
    ));
    assert!(!has_root_in(&ZPoly::from_i64s(&[5]), &Rat::zero(), &Rat::one()).unwrap());
    assert!(!has_root_in(&ZPoly::from_i64s(&[1, 0, 1]), &Rat::from(-9), &Rat::from(9)).unwrap());
}

#[test]
fn sign_decisions_at_algebraic_roots() {
    // α = √2 − 1 ∈ (0, 1), root of t² + 2t − 1.
    let p = ZPoly::from_i64s(&[-1, 2, 1]);
    let mut alpha = all_roots(&p, &Rat::zero(), &Rat::one()).remove(0);
    // q vanishes at α: (t² + 2t − 1)(t − 5).
    let q = &p * &ZPoly::from_i64s(&[-5, 1]);
    assert_eq!(alpha.sign_of(&q), 0);
    // The zero polynomial vanishes everywhere (decided by gcd(p, 0) = p).
    assert_eq!(alpha.clone().sign_of(&ZPoly::zero()), 0);
    // 1000 t − 414 > 0 at α ≈ 0.41421; 1000 t − 415 < 0.
    assert_eq!(alpha.sign_of(&ZPoly::from_i64s(&[-414, 1000])), 1);
    assert_eq!(alpha.sign_of(&ZPoly::from_i64s(&[-415, 1000])), -1);
    // A near miss: a rational 1e-40 away from α.
    let mut near = alpha.clone();
    near.refine_to(&Rat::new(Int::one(), Int::pow10(50)).unwrap());
    let c = near.lo() - &Rat::new(Int::one(), Int::pow10(40)).unwrap();
    assert_eq!(alpha.sign_of(&linear(&c)), 1);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Distinct rational roots with multiplicities, times an irreducible
    /// quadratic: isolation finds exactly the distinct roots in [0, 1], in
    /// order, each enclosed.
    /// Rational roots off every split point come out exact after
    /// refinement (the simplest-rational test, behind the rational root
    /// theorem's screen `k/L`), whatever the leading coefficient's extra
    /// factor `k`.
    #[test]
    fn rational_roots_refine_to_themselves(
        raw in proptest::collection::vec((1i64..=500, 1i64..=500), 1..4),
        k in 1i64..1_000_000, shift in 1i64..7,
    ) {
        let mut roots: Vec<Rat> = Vec::new();
        for (p, q) in raw {
            let r = Rat::from_frac(p.min(2 * q), 2 * q + 1);
            if !roots.contains(&r) {
                roots.push(r);
            }
        }
        roots.sort();
        let linear = |r: &Rat| ZPoly::new(vec![-r.numer().clone(), r.denom().clone()]);
        let poly = roots
            .iter()
            .fold(ZPoly::from_i64s(&[shift * k, 0, k]), |acc, r| &acc * &linear(r));
        let found = all_roots(&poly, &Rat::zero(), &Rat::one());
        prop_assert_eq!(found.len(), roots.len());
        for (mut f, r) in found.into_iter().zip(&roots) {
            f.refine_to(&Rat::from_frac(1, 1 << 40));
            prop_assert_eq!(f.exact_value(), Some(r));
        }
    }

    #[test]
    fn isolates_constructed_roots(raw in proptest::collection::vec((0i64..=60, 1i64..=60, 1u32..=3), 1..7), shift in 1i64..5) {
        let mut roots: Vec<(Rat, u32)> = Vec::new();
        for (p, q, m) in raw {
            let r = Rat::from_frac(p.min(q), q);
            if !roots.iter().any(|(x, _)| *x == r) {
                roots.push((r, m));
            }
        }
        let poly = &product(&roots) * &ZPoly::from_i64s(&[shift, 0, 1]);
        roots.sort();
        let found = all_roots(&poly, &Rat::zero(), &Rat::one());
        prop_assert_eq!(found.len(), roots.len());
        for (f, (r, _)) in found.iter().zip(&roots) {
            prop_assert!(f.lo() <= r && r <= f.hi());
            prop_assert_eq!(f.exact_value().is_some(), f.lo() == f.hi());
        }
        // Sign of the derivative-free test polynomial t − c at each root.
        for (mut f, (r, _)) in found.into_iter().zip(&roots) {
            let c = Rat::from_frac(1, 3);
            let expected = (r - &c).signum();
            prop_assert_eq!(f.sign_of(&linear(&c)), expected);
        }
    }

    /// Filter-only isolation from enclosures of the Bernstein coefficients
    /// finds the same roots as exact isolation when the roots are simple,
    /// refines them through the model, and reports a multiple root (or a
    /// coefficient enclosure holding 0) as undecided instead of guessing.
    #[test]
    fn filtered_isolation_matches_exact(raw in proptest::collection::vec((1i64..=60, 2i64..=61), 1..6), shift in 1i64..5, double in proptest::bool::ANY) {
        let mut roots: Vec<Rat> = Vec::new();
        for (p, q) in raw {
            let r = Rat::from_frac(p.min(q - 1), q);
            if !roots.contains(&r) {
                roots.push(r);
            }
        }
        let mult = if double { 2 } else { 1 };
        let factors: Vec<(Rat, u32)> = roots.iter().enumerate().map(|(i, r)| (r.clone(), if i == 0 { mult } else { 1 })).collect();
        let poly = &product(&factors) * &ZPoly::from_i64s(&[shift, 0, 1]);
        let b = ccd_poly::Bernstein::from_power(&poly, &Rat::zero(), &Rat::one());
        let sign = b.scale().signum();
        let coeffs: Vec<Interval> = b.coeffs().iter().map(|c| {
            let iv = Interval::from_int_scaled(c, 0);
            if sign < 0 { -iv } else { iv }
        }).collect();
        let model = std::sync::Arc::new(crate::SignProbe::new(&poly));
        let mut iter = crate::RootIter::filtered(model, &Rat::zero(), &Rat::one(), &coeffs);
        let found: Vec<_> = iter.by_ref().collect();
        roots.sort();
        if double {
            prop_assert!(iter.undecided());
        } else {
            prop_assert!(!iter.undecided());
            prop_assert_eq!(found.len(), roots.len());
            for (mut f, r) in found.into_iter().zip(&roots) {
                prop_assert!(f.lo() <= r && r <= f.hi());
                f.refine_to(&Rat::from_frac(1, 1 << 40));
                prop_assert!(f.lo() <= r && r <= f.hi());
            }
        }
        // A coefficient that cannot be signed stops the isolation.
        let mut blurred = coeffs.clone();
        blurred[coeffs.len() / 2] = blurred[coeffs.len() / 2].hull(&Interval::point(0.0));
        let model = std::sync::Arc::new(crate::SignProbe::new(&poly));
        let mut iter = crate::RootIter::filtered(model, &Rat::zero(), &Rat::one(), &blurred);
        let _ = iter.by_ref().count();
        prop_assert!(iter.undecided() || blurred[coeffs.len() / 2].lo == 0.0 && blurred[coeffs.len() / 2].hi == 0.0);
    }

    /// Clusters at every depth the isolation meets: one to three pairs
    /// `a ± 2^(−k)` (real, a near hit) or `a ± 2^(−k)·i` (a near miss) with
    /// `k` up to 700, times a linear factor. Exact isolation finds exactly
    /// the real roots in `[0, 1]`, each in its own interval, in order;
    /// filter-only isolation, from enclosures of the same coefficients,
    /// finds a prefix of them, all of them when it is decided.
    #[test]
    fn clusters_are_isolated_exactly(
        raw in proptest::collection::vec((1i64..50, 2i64..51, 8u64..700, proptest::bool::ANY), 1..4),
        r in (0i64..=60, 1i64..=60),
    ) {
        let mut centres: Vec<Rat> = Vec::new();
        let mut poly = linear(&Rat::from_frac(r.0.min(r.1), r.1));
        let mut roots = vec![Rat::from_frac(r.0.min(r.1), r.1)];
        for (n, d, k, hit) in raw {
            let a = Rat::from_frac(n.min(d - 1), d);
            if centres.contains(&a) {
                continue;
            }
            centres.push(a.clone());
            poly = &poly * &cluster(&a, k, hit);
            if hit {
                roots.push(&a - &pow2(k));
                roots.push(&a + &pow2(k));
            }
        }
        roots.sort();
        roots.dedup();
        let found = all_roots(&poly, &Rat::zero(), &Rat::one());
        prop_assert_eq!(found.len(), roots.len());
        for (f, r) in found.iter().zip(&roots) {
            prop_assert!(f.lo() <= r && r <= f.hi(), "{} not in {:?}", r, f);
        }
        for pair in found.windows(2) {
            prop_assert!(pair[0].hi() <= pair[1].lo());
        }
        let (found, undecided) = filtered_roots(&poly);
        prop_assert!(found.len() <= roots.len());
        prop_assert!(undecided || found.len() == roots.len(), "{:?} {:?}", found, roots);
        for (f, r) in found.iter().zip(&roots) {
            prop_assert!(f.lo() <= r && r <= f.hi(), "filtered: {} not in {:?}", r, f);
        }
    }

    /// First-root-only isolation returns the smallest root.
    #[test]
    fn first_root_is_smallest(a in 1i64..99, b in 1i64..99) {
        let (x, y) = (Rat::from_frac(a, 100), Rat::from_frac(b, 100));
        let p = &(&linear(&x) * &linear(&y)) * &ZPoly::from_i64s(&[-2, 0, 1]);
        let first = isolate(&p, &Rat::zero(), &Rat::one()).unwrap().next().unwrap();
        let m = if x < y { x } else { y };
        prop_assert!(first.lo() <= &m && &m <= first.hi());
    }
}

/// `2^(−k)`.
fn pow2(k: u64) -> Rat {
    Rat::dyadic(Int::one(), k)
}

/// Root clusters far below bisection's reach (the Newton zoom): two real
/// roots `2^(−3000)` apart next to a third, and a complex pair
/// `a ± 2^(−2000)·i` that no real root explains. Every real root is found
/// once, in order, in its own enclosure, and the pair yields none.
#[test]
fn clusters_far_below_bisection_depth() {
    let a = Rat::from_frac(1, 3);
    let d = pow2(3000);
    let roots = [a.clone(), &a + &d, Rat::from_frac(5, 7)];
    let p = product(&roots.iter().map(|r| (r.clone(), 1)).collect::<Vec<_>>());
    let found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 3);
    for (f, r) in found.iter().zip(&roots) {
        assert!(f.lo() <= r && r <= f.hi(), "{r} not in {f:?}");
    }
    assert!(found[0].hi() <= found[1].lo());
    // (t − a)² + ε² with a = 2/5, ε = 2^(−2000), times (t − 3/4):
    // den(a)²·((t − a)² + ε²) = (5t − 2)² + 25ε², cleared of 2^4000.
    let scale = Int::one().shl(4000);
    let pair = ZPoly::new(vec![
        Int::from(4) * &scale + Int::from(25),
        Int::from(-20) * &scale,
        Int::from(25) * &scale,
    ]);
    let p = &pair * &linear(&Rat::from_frac(3, 4));
    let found = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].lo() <= &Rat::from_frac(3, 4) && &Rat::from_frac(3, 4) <= found[0].hi());
}

/// A filter-only isolation gives up on a stalled cluster where the filter
/// cannot resolve it: a double root at 2/5 (var 2 at every depth) ends
/// when the streak completes and the certified value at the cluster's
/// minimum holds 0 (9 splits), not once its halves are unsignable (26
/// splits with that rule alone), nor at the depth limit of 64 or after
/// the budget of `2n + 16` unsignable nodes (50 splits before both). Simple roots `2^(−k)`
/// apart that the filter separates (`k ≤ 24` here; from 28 on it gives
/// up either way) are still all found after their stall.
#[test]
fn filtered_isolation_gives_up_on_a_stalled_cluster_at_its_precision() {
    let double = &(&linear(&Rat::from_frac(2, 5)) * &linear(&Rat::from_frac(2, 5)))
        * &linear(&Rat::from_frac(3, 4));
    let (found, undecided, splits) = filtered_roots_counted(&double);
    assert!(undecided && found.is_empty(), "{found:?}");
    assert!(splits <= 12, "{splits} splits");
    for k in [12, 18, 24] {
        let a = Rat::from_frac(2, 5);
        let b = &a + &Rat::dyadic(Int::one(), k);
        let close = &(&linear(&a) * &linear(&b)) * &linear(&Rat::from_frac(3, 4));
        let (found, undecided, _) = filtered_roots_counted(&close);
        assert!(!undecided, "2^-{k} apart");
        assert_eq!(found.len(), 3, "2^-{k} apart");
    }
}

/// The filter's prospect ([`crate::RootIter::filter_may_decide`]): yes for
/// simple roots apart and for a clear miss; no for a double root (a
/// touch), a complex pair `2^(−100)` off the axis (a near miss closer than
/// `f64`), simple roots `2^(−60)` apart, or a root at an end of the span.
#[test]
fn filter_prospect_sees_touches_near_misses_and_ends() {
    let prospect = |p: &ZPoly| {
        let model = std::sync::Arc::new(crate::SignProbe::new(p));
        crate::RootIter::filter_may_decide(&model, &Rat::zero(), &Rat::one())
    };
    let l = |n: i64, d: i64| linear(&Rat::from_frac(n, d));
    let other = &l(3, 4) * &l(1, 9);
    let pair = |k: u64, hit: bool| cluster(&Rat::from_frac(2, 5), k, hit);
    assert!(prospect(&(&l(2, 5) * &other)));
    assert!(prospect(&(&pair(4, false) * &other)));
    assert!(prospect(&(&pair(8, true) * &other)));
    assert!(!prospect(&(&(&l(2, 5) * &l(2, 5)) * &other)));
    assert!(!prospect(&(&pair(100, false) * &other)));
    assert!(!prospect(&(&pair(60, true) * &other)));
    assert!(!prospect(&(&l(0, 1) * &other)));
    assert!(!prospect(&(&l(1, 1) * &other)));
}

/// A filter-only isolation settles a near miss by the convexity test when
/// its function is proven squarefree: a complex pair `2/5 ± 2^(−100)·i`
/// (whose Bernstein coefficients keep var 2 down to the filter's depth)
/// next to a simple root at 3/4 is decided, with that one root; the same
/// pair squared (a multiple root, never settled by the test) is left
/// undecided, as before.
#[test]
fn filtered_near_miss_is_settled_when_squarefree() {
    let scale = Int::one().shl(200);
    let pair = ZPoly::new(vec![
        Int::from(4) * &scale + Int::from(25),
        Int::from(-20) * &scale,
        Int::from(25) * &scale,
    ]);
    for (p, settled) in [
        (&pair * &linear(&Rat::from_frac(3, 4)), true),
        (&(&pair * &pair) * &linear(&Rat::from_frac(3, 4)), false),
    ] {
        let (found, undecided) = filtered_roots(&p);
        assert_eq!(!undecided, settled, "{p:?}");
        if settled {
            assert_eq!(found.len(), 1);
            assert!(
                found[0].lo() <= &Rat::from_frac(3, 4) && &Rat::from_frac(3, 4) <= found[0].hi()
            );
        }
    }
}

/// A filter-only isolation retries the convexity test every streak after
/// an open try (it never reaches the depth where an exact isolation's
/// throttle would let it retry): `3/13 ± 2^(−900)·i`, out of reach at the
/// first try (depth 13), is settled at a later one, and the root `1/5` is
/// the only one found.
#[test]
fn filtered_isolation_retries_after_an_open_try() {
    let p = &cluster(&Rat::from_frac(3, 13), 900, false) * &linear(&Rat::from_frac(1, 5));
    let (found, undecided) = filtered_roots(&p);
    assert!(!undecided);
    assert_eq!(found.len(), 1);
    assert!(found[0].lo() <= &Rat::from_frac(1, 5) && &Rat::from_frac(1, 5) <= found[0].hi());
}

/// The bound on exact work stops an isolation and says so; below it the
/// same isolation runs to the end and is not marked.
#[test]
fn exact_work_bound_stops_and_says_so() {
    let a = Rat::from_frac(1, 3);
    let p = product(&[(a.clone(), 1), (&a + &pow2(3000), 1)]);
    let mut bounded = isolate(&p, &Rat::zero(), &Rat::one())
        .expect("nonzero")
        .with_max_work(1_000);
    let found: Vec<_> = bounded.by_ref().collect();
    assert!(bounded.exhausted() && found.len() < 2, "{found:?}");
    let mut free = isolate(&p, &Rat::zero(), &Rat::one()).expect("nonzero");
    assert_eq!(free.by_ref().count(), 2);
    assert!(!free.exhausted() && free.work() > 1_000);
}

/// A constant (a degree-0 Bernstein form, e.g. `sr0` of a static pair) whose
/// one enclosure excludes zero has no roots, proven: the filter decides it
/// instead of giving up; an enclosure holding zero stays undecided.
#[test]
fn filtered_constant_is_decided() {
    let model = std::sync::Arc::new(crate::SignProbe::new(&ZPoly::from_i64s(&[-3])));
    let mut iter = crate::RootIter::filtered(
        model.clone(),
        &Rat::zero(),
        &Rat::one(),
        &[Interval { lo: -3.5, hi: -2.5 }],
    );
    assert_eq!(iter.by_ref().count(), 0);
    assert!(!iter.undecided());
    let mut iter = crate::RootIter::filtered(
        model,
        &Rat::zero(),
        &Rat::one(),
        &[Interval { lo: -1.0, hi: 0.5 }],
    );
    assert_eq!(iter.by_ref().count(), 0);
    assert!(iter.undecided());
}

/// A model that hides the double-word view of a [`crate::SignProbe`]
/// ([`crate::SignModel::ball_jet_at`] is `None`): with `big`, its only
/// view short of the exact jet is a multi-precision one
/// ([`crate::SignModel::big_jet_at`] by Horner's rule over
/// [`BigInterval`](ccd_arith::BigInterval)s of `q`'s exact coefficients,
/// rounded to the asked precision, on the exact jet's scale); without,
/// every step takes the exact jet.
/// It counts the exact signs and jets asked of it in `calls`; with
/// `marks_rounds` it notes that count whenever it is asked to enclose `q`
/// over an interval (each round of [`crate::RealRoot::sign_with`] starts
/// so), for a quantity sharing `calls` with the root's model.
#[derive(Clone, Debug)]
struct NoBalls {
    probe: std::sync::Arc<crate::SignProbe>,
    big: bool,
    calls: std::sync::Arc<Calls>,
    marks_rounds: bool,
}

/// What [`NoBalls`] models were asked for.
#[derive(Debug, Default)]
struct Calls {
    /// Exact signs and exact jets.
    exact: std::sync::atomic::AtomicUsize,
    /// `exact` at each enclosure asked of a model that marks rounds.
    marks: std::sync::Mutex<Vec<usize>>,
}

impl Calls {
    fn exact(&self) -> usize {
        self.exact.load(std::sync::atomic::Ordering::Relaxed)
    }
}

/// [`NoBalls`] with exact jets only.
#[allow(non_snake_case)]
fn ExactOnly(probe: std::sync::Arc<crate::SignProbe>) -> NoBalls {
    NoBalls {
        probe,
        big: false,
        calls: Default::default(),
        marks_rounds: false,
    }
}

/// [`NoBalls`] with multi-precision jets.
#[allow(non_snake_case)]
fn BigOnly(probe: std::sync::Arc<crate::SignProbe>) -> NoBalls {
    NoBalls {
        big: true,
        ..ExactOnly(probe)
    }
}

impl crate::SignModel for NoBalls {
    fn enclose(&self, x: Interval) -> Interval {
        if self.marks_rounds && x.lo < x.hi {
            let n = self.calls.exact();
            self.calls.marks.lock().expect("not poisoned").push(n);
        }
        self.probe.enclose(x)
    }
    fn enclose_second(&self, x: Interval) -> Interval {
        self.probe.enclose_second(x)
    }
    fn exact_jet_at(&self, m: &Rat) -> crate::ExactJet {
        self.calls
            .exact
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        self.probe.exact_jet_at(m)
    }
    fn big_jet_at(&self, m: &Rat, prec: u32) -> Option<crate::BallJet<ccd_arith::BigInterval>> {
        use ccd_arith::{BigInterval, Dyadic};
        if !self.big {
            return None;
        }
        let q = self.probe.exact();
        let k = m.dyadic_exponent()? as i64;
        let n = q.degree().unwrap_or(0) as i64;
        let jet = self.probe.exact_jet_at(m);
        let x = BigInterval::from_rat(m, prec);
        let coeffs: Vec<_> = q
            .coeffs()
            .iter()
            .map(|c| BigInterval::new(Dyadic::from_int(c), Dyadic::from_int(c), prec))
            .collect();
        let ccd_arith::Dual { v, d } = crate::ball_horner(&coeffs, &x);
        // σ = 2^(−shift) with value_exp = shift + k·n.
        let shift = jet.value_exp - k * n;
        Some(crate::BallJet {
            value: v.mul_pow2(-shift),
            slope: d.mul_pow2(-shift),
            value_exp: jet.value_exp,
            slope_exp: jet.slope_exp,
        })
    }
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64) {
        self.probe.approx_value_and_slope(x)
    }
    fn sign_at(&self, x: &Rat) -> i32 {
        self.calls
            .exact
            .fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        self.probe.sign_at(x)
    }
    fn admits_root_at(&self, x: &Rat) -> bool {
        self.probe.admits_root_at(x)
    }
    fn exact(&self) -> &ZPoly {
        self.probe.exact()
    }
}

/// Between two rounds of a sign decision the narrowing takes at most
/// `SIGN_NARROW_STEPS` steps, however many bits the round asked for: at
/// a root next to a tight cluster, `α = 1/3 + 2^(−1200)` of
/// `(3·2^1200·t − 2^1200)³ − 27` (its complex pair `2^(−1200)·√3` away),
/// where every step gains about a bit until the enclosure is far below
/// `2^(−1200)`, the sign of `t − c` with `c = α − 2^(−600)` is decided
/// right, and no round is followed by more than `3·SIGN_NARROW_STEPS + 2`
/// exact evaluations (a jump that does not halve the enclosure costs a jet,
/// two cut signs and a bisection, and is followed by at least three steps
/// of one sign each; plus the round's own jet of `q`, which shares the
/// count): about 70 a round, 1,190 in all, the
/// enclosure `2^(−641)` wide at the end. Without the budget the rounds
/// asking for 256 and 512 bits took 620 and 1,260, 2,446 in all, down to
/// `2^(−1045)`.
#[test]
fn sign_rounds_narrow_a_bounded_number_of_steps() {
    let k = 1200u64;
    let two_k = Int::one().shl(k);
    let cube = ZPoly::new(vec![-two_k.clone(), Int::from(3) * &two_k]).pow(3);
    let p = &cube - &ZPoly::from_i64s(&[27]);
    let alpha = &Rat::from_frac(1, 3) + &pow2(k);
    // [1/4, 1/2] isolates α, the only real root.
    let (lo, hi) = (Rat::from_frac(1, 4), Rat::from_frac(1, 2));
    assert!(p.sign_at(&lo) < 0 && p.sign_at(&hi) > 0);
    let base = ExactOnly(std::sync::Arc::new(crate::SignProbe::new(&p)));
    let mut r = crate::RealRoot::isolated(base.clone(), lo, hi, -1);
    let c = &alpha - &pow2(k / 2);
    let q = NoBalls {
        calls: base.calls.clone(),
        marks_rounds: true,
        ..ExactOnly(std::sync::Arc::new(crate::SignProbe::new(&linear(&c))))
    };
    assert_eq!(r.sign_with(&q), 1);
    let mut marks = base.calls.marks.lock().expect("not poisoned").clone();
    marks.push(base.calls.exact());
    let most = marks.windows(2).map(|w| w[1] - w[0]).max().unwrap_or(0);
    let steps = super::root::SIGN_NARROW_STEPS as usize;
    assert!((16..=64).contains(&steps), "a budget of a few dozen steps");
    assert!(marks.len() > 8, "{marks:?}");
    assert!(most <= 3 * steps + 2, "{most}: {marks:?}");
    assert!(r.lo() <= &alpha && &alpha <= r.hi());
}

/// Refining to `10^(−400)`, far past what one Newton step from the `f64`
/// Newton point reaches (about the square of its ulp): the roots of a
/// polynomial with 160-bit coefficients take at most 20 exact evaluations
/// each (jets and signs; 10 each, as before the step past the float
/// resolution existed). Found by review: tried at every target, that step
/// put both cuts on one side of the root, and the lopsided ends
/// (denominators past `2^1024`, whose `f64` enclosure is the whole line)
/// sent the exact steps to bisection: 909 evaluations for the first root.
#[test]
fn refining_past_the_double_word_reach_takes_the_exact_steps() {
    let (p, _) = near_roots(vec![(1, 3), (5, 7), (2, 9)], 100, 1, 0, 0);
    let target = Rat::new(Int::one(), Int::pow10(400)).unwrap();
    let roots = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(roots.len(), 3);
    for root in roots {
        let base = ExactOnly(std::sync::Arc::new(crate::SignProbe::new(root.poly())));
        let sign_lo = root.poly().sign_at(root.lo());
        let mut r =
            crate::RealRoot::isolated(base.clone(), root.lo().clone(), root.hi().clone(), sign_lo);
        r.refine_to(&target);
        assert!(r.width() <= target);
        assert!(p.sign_at(r.lo()) * p.sign_at(r.hi()) < 0);
        assert!(
            base.calls.exact() <= 20,
            "{} exact evaluations",
            base.calls.exact()
        );
    }
}

/// `n/2^k` plus a fraction of the next cell with a long denominator: an
/// end with about four times the bits its interval's width `2^(−k)` needs,
/// as Newton steps next to a cluster leave them.
fn long_end(n: i64, k: u64, s: u64) -> Rat {
    let j = (2 * k) as u32 + 1; // 3^j has about 3.2k bits
    let three = Int::from(3).pow(j);
    let frac = Rat::new(Int::from(s), three).expect("nonzero") * pow2(k + 2);
    &Rat::dyadic(Int::from(n), k) + &frac
}

/// Descartes' rule on the enclosure's ends rounded outward to a short grid
/// decides only where the exact ends would, and as they would: the wider
/// interval's ends enclose the exact ones, and its verdict, when it has
/// one, is the exact ends' (`descartes_sign` is always theirs).
#[test]
fn short_ends_decide_as_the_exact_ends_do() {
    let q = linear(&Rat::from_frac(1, 3));
    let (lo, hi) = (
        long_end(1 << 39, 40, 12345),
        long_end((1 << 39) + 1, 40, 777),
    );
    let width = &hi - &lo;
    let (l, h) = super::root::short_ends(&lo, &hi, &width).expect("markedly shorter");
    assert!(l <= lo && hi <= h, "{l} {lo} {hi} {h}");
    assert_eq!(super::root::descartes(&q, &l, &h), Some(1));
    assert_eq!(super::root::descartes(&q, &lo, &hi), Some(1));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]
    /// The same on random polynomials with rational roots near random
    /// intervals `2^(−k)` wide whose ends are four times longer than that.
    #[test]
    fn short_ends_never_decide_otherwise(
        roots in proptest::collection::vec((0i64..=40, 1i64..=41), 1..5),
        k in 6u64..=60, cell in 0.0f64..1.0, s1 in 1u64..1_000_000, s2 in 1u64..1_000_000,
        cells in 1i64..4,
    ) {
        use super::root::{descartes, descartes_sign, short_ends};
        let q = product(&roots.iter().map(|&(a, b)| (Rat::from_frac(a.min(b), b), 1)).collect::<Vec<_>>());
        let n = (cell * (1u64 << k) as f64) as i64;
        let (lo, hi) = (long_end(n, k, s1), long_end(n + cells, k, s2));
        let width = &hi - &lo;
        let exact = descartes(&q, &lo, &hi);
        if let Some((l, h)) = short_ends(&lo, &hi, &width) {
            prop_assert!(l <= lo && hi <= h);
            if let Some(s) = descartes(&q, &l, &h) {
                prop_assert_eq!(exact, Some(s));
            }
        }
        prop_assert_eq!(descartes_sign(&q, &lo, &hi, &width), exact);
    }
}

/// The model `M` at the scale `σ·2^(−FAINT)`: its values and enclosures
/// far below `f64`'s range, as a closed form's of long numbers can be
/// (the enclosures underflow to the smallest normal bounds, `f64` Newton
/// guesses to zero, and only the exact and multi-precision jets keep
/// their size).
#[derive(Clone, Debug)]
struct Faint<M>(M);

const FAINT: i64 = 3000;

/// An `f64` interval times `2^(−FAINT)`, rounded outward: a finite
/// nonzero end's scaled value lies strictly between 0 and
/// `±MIN_POSITIVE`, so it rounds to one of them.
fn faint(iv: Interval) -> Interval {
    let end = |x: f64, up: bool| {
        if x.is_infinite() || x == 0.0 {
            x
        } else if (x > 0.0) == up {
            f64::MIN_POSITIVE.copysign(x)
        } else {
            0.0
        }
    };
    Interval::new(end(iv.lo, false), end(iv.hi, true))
}

impl<M: crate::SignModel> crate::SignModel for Faint<M> {
    fn enclose(&self, x: Interval) -> Interval {
        faint(self.0.enclose(x))
    }
    fn enclose_second(&self, x: Interval) -> Interval {
        faint(self.0.enclose_second(x))
    }
    fn exact_jet_at(&self, m: &Rat) -> crate::ExactJet {
        let jet = self.0.exact_jet_at(m);
        crate::ExactJet {
            value_exp: jet.value_exp + FAINT,
            slope_exp: jet.slope_exp + FAINT,
            ..jet
        }
    }
    fn big_jet_at(&self, m: &Rat, prec: u32) -> Option<crate::BallJet<ccd_arith::BigInterval>> {
        let jet = self.0.big_jet_at(m, prec)?;
        Some(crate::BallJet {
            value: jet.value.mul_pow2(-FAINT),
            slope: jet.slope.mul_pow2(-FAINT),
            value_exp: jet.value_exp + FAINT,
            slope_exp: jet.slope_exp + FAINT,
        })
    }
    fn approx_value_and_slope(&self, x: f64) -> (f64, f64) {
        let (v, d) = self.0.approx_value_and_slope(x);
        (v * 0.0, d * 0.0)
    }
    fn sign_at(&self, x: &Rat) -> i32 {
        self.0.sign_at(x)
    }
    fn admits_root_at(&self, x: &Rat) -> bool {
        self.0.admits_root_at(x)
    }
    fn exact(&self) -> &ZPoly {
        self.0.exact()
    }
}

/// A polynomial with long coefficients (a big constant `3^scale` times
/// rational roots, nudged, so that its roots are irrational and near each
/// other) and two quantities at its roots: `q = (t − r)(1 + t + t²)·3^scale
/// + q_off`, nonzero at every simple root or vanishing at one, and `q2`,
/// positive with a positive curvature at `r` (decided by the one-sided
/// `f64` Taylor test where the symmetric one is still open).
fn near_roots(
    roots: Vec<(i64, i64)>,
    scale: u32,
    nudge: i64,
    q_root: usize,
    q_off: i64,
) -> (ZPoly, [ZPoly; 2]) {
    let mut factors: Vec<(Rat, u32)> = Vec::new();
    for (p, q) in roots {
        let r = Rat::from_frac(p.min(q - 1), q);
        if !factors.iter().any(|(x, _)| *x == r) {
            factors.push((r, 1));
        }
    }
    let big = Int::from(3).pow(scale);
    let p = &product(&factors).mul_int(&big) + &ZPoly::from_i64s(&[nudge]);
    let r = &factors[q_root % factors.len()].0;
    let q =
        &(&linear(r) * &ZPoly::from_i64s(&[1, 1, 1])).mul_int(&big) + &ZPoly::from_i64s(&[q_off]);
    let q2 = &(&linear(r).pow(2) * &ZPoly::from_i64s(&[1, 1])).mul_int(&big)
        + &ZPoly::from_i64s(&[q_off.abs() + 1]);
    (p, [q2, q])
}

/// Deciding the signs of `qs` at each root of `p` in `[0, 1]`, refining it
/// to `target`, and deciding the last one again, with the models `tiered`
/// makes give the very same enclosures and signs as with the models
/// `exact` makes, which take exact jets only.
fn tiers_change_no_step<T: crate::SignModel + Clone, E: crate::SignModel + Clone>(
    tiered: impl Fn(std::sync::Arc<crate::SignProbe>) -> T,
    exact: impl Fn(std::sync::Arc<crate::SignProbe>) -> E,
    p: &ZPoly,
    qs: &[ZPoly],
    target: &Rat,
) -> Result<(), TestCaseError> {
    /// The same root over `base`.
    fn like<M: crate::SignModel + Clone>(root: &crate::RealRoot, base: M) -> crate::RealRoot<M> {
        match root.exact_value() {
            Some(v) => crate::RealRoot::exact(base, v.clone()),
            None => {
                let s = root.poly().sign_at(root.lo());
                crate::RealRoot::isolated(base, root.lo().clone(), root.hi().clone(), s)
            }
        }
    }
    let probes: Vec<_> = qs
        .iter()
        .map(|q| std::sync::Arc::new(crate::SignProbe::new(q)))
        .collect();
    let last = probes.last().expect("a quantity");
    for root in all_roots(p, &Rat::zero(), &Rat::one()) {
        // The same (squarefree, primitive) polynomial under both models.
        let shared = std::sync::Arc::new(crate::SignProbe::new(root.poly()));
        let mut tiers = like(&root, tiered(shared.clone()));
        let mut exact_only = like(&root, exact(shared));
        let ends = |lo: &Rat, hi: &Rat| (lo.clone(), hi.clone());
        for (i, q) in probes.iter().chain([last]).enumerate() {
            if i == probes.len() {
                tiers.refine_to(target);
                exact_only.refine_to(target);
                prop_assert_eq!(
                    ends(tiers.lo(), tiers.hi()),
                    ends(exact_only.lo(), exact_only.hi())
                );
            }
            prop_assert_eq!(
                tiers.sign_with(&tiered(q.clone())),
                exact_only.sign_with(&exact(q.clone()))
            );
            prop_assert_eq!(
                ends(tiers.lo(), tiers.hi()),
                ends(exact_only.lo(), exact_only.hi())
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// Neither tier changes a step, on polynomials with coefficients of
    /// 1400–2200 bits: the double-word jets, the multi-precision jets
    /// alone (no double-word view), and those far below `f64`'s range
    /// ([`Faint`]), where double-word balls could not hold the values and
    /// every `f64` enclosure underflows.
    #[test]
    fn tiers_change_no_step_near_roots(
        roots in proptest::collection::vec((1i64..=997, 2i64..=998), 2..5),
        scale in 900u32..1400, nudge in -2i64..3, digits in 15u32..60,
        q_root in 0usize..4, q_off in -3i64..4,
    ) {
        let (p, qs) = near_roots(roots, scale, nudge, q_root, q_off);
        let target = Rat::new(Int::one(), Int::pow10(digits)).unwrap();
        tiers_change_no_step(|p| p, ExactOnly, &p, &qs, &target)?;
        tiers_change_no_step(BigOnly, ExactOnly, &p, &qs, &target)?;
        tiers_change_no_step(|p| Faint(BigOnly(p)), |p| Faint(ExactOnly(p)), &p, &qs, &target)?;
    }
}

/// Quantities that vanish at an irrational root (`q(α) = 0` for
/// `α = √2/3`, decided by the zero test in the very round the exact path
/// runs it) and ones that nearly do, through every tier: the same steps.
#[test]
fn tiers_change_no_step_at_vanishing_quantities() {
    let big = ZPoly::from_i64s(&[1]).mul_int(&Int::from(3).pow(1000));
    let shared = &big * &ZPoly::from_i64s(&[-2, 0, 9]); // 9t² − 2
    let p = &shared * &ZPoly::from_i64s(&[-1, 2]);
    let qs = [
        &shared * &ZPoly::from_i64s(&[1, 1]),
        &(&shared * &ZPoly::from_i64s(&[1, 1])) + &ZPoly::from_i64s(&[1]),
    ];
    let target = Rat::new(Int::one(), Int::pow10(40)).unwrap();
    let run = |r: Result<(), TestCaseError>| r.expect("the same steps");
    run(tiers_change_no_step(|p| p, ExactOnly, &p, &qs, &target));
    run(tiers_change_no_step(BigOnly, ExactOnly, &p, &qs, &target));
    run(tiers_change_no_step(
        |p| Faint(BigOnly(p)),
        |p| Faint(ExactOnly(p)),
        &p,
        &qs,
        &target,
    ));
    let mut roots = all_roots(&p, &Rat::zero(), &Rat::one());
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[0].sign_of(&qs[0]), 0);
}

/// A root below `f64`'s range (`α = √3·2^(−1100)`) and a quantity positive
/// on its whole enclosure but whose value at `t = 0` is negative: a ball
/// of the point `m` that flushed to 0 would decide with the sign at 0
/// (found by review; the balls now refuse such points).
#[test]
fn ball_jets_below_the_f64_range_decide_nothing_false() {
    let t = |k: u64| ZPoly::new(vec![Int::zero(), Int::one().shl(k)]);
    // p = 2^2200·t² − 3, q = 2^1498·t³ + 2^1100·t − 1.
    let p = &(&t(1100) * &t(1100)) + &ZPoly::from_i64s(&[-3]);
    let q = &(&(&t(0) * &t(0)) * &t(1498)) + &(&t(1100) + &ZPoly::from_i64s(&[-1]));
    let (lo, hi) = (pow2(1100), pow2(1099));
    let mut roots = isolate(&p, &lo, &hi).unwrap();
    let mut root = roots.next().expect("one root");
    assert!(roots.next().is_none());
    assert_eq!(q.sign_at(root.lo()), 1);
    assert_eq!(q.sign_at(root.hi()), 1);
    assert_eq!(root.sign_of(&q), 1);
}

/// The image proof of `q(α) ≠ 0` needs `p`'s degree kept modulo the prime:
/// here `lc(p)` is a multiple of [`Residues`]' prime, the images are
/// coprime although `p` and `q` share the root `1/P`, and the exact gcd
/// must decide (from the soundness review; without the degree check the
/// sign at the shared root is never decided).
#[test]
fn image_proof_needs_the_kept_degree() {
    use ccd_poly::Residues;
    let prime = Int::from_u64(0x3fff_ffff_feb0_0001); // Residues' field prime
    let lin = ZPoly::new(vec![Int::from(-1), prime]); // P·t − 1, root 1/P
    let p = &lin * &ZPoly::from_i64s(&[-3, 4]);
    let q = &lin * &ZPoly::from_i64s(&[5, 1]);
    assert!(Residues::of(&p).proves_coprime(&Residues::of(&q)));
    assert_ne!(Residues::of(&p).degree(), p.degree());
    let mut roots: Vec<_> = crate::isolate(&p, &Rat::zero(), &Rat::one())
        .unwrap()
        .collect();
    assert_eq!(roots.len(), 2);
    assert_eq!(roots[0].sign_of(&q), 0);
    assert_ne!(roots[1].sign_of(&q), 0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]
    /// `RealRoot::sign_within` gives the unbounded sign or `None`, and
    /// `None` only once its enclosure is narrower than the bound;
    /// `RealRoot::vanishes_with` is `sign_with(..) == 0`. The roots: `1/3`,
    /// `1/3 + 2^(−gap)`, `1/2` (exact: `lo = hi`) and `√2 − 1/2` (alone on
    /// a wide isolating interval, which the first round narrows before
    /// its Taylor forms: `WIDE_SIGN_LOG2`); the quantities: lines through
    /// points `2^(−off)` on either side of the root, through the root, and
    /// through the root's neighbour.
    #[test]
    fn bounded_signs_and_zero_tests_agree_with_the_signs(
        gap in 20u64..300,
        off in 1u64..300,
        k in 0usize..4,
        bound in 1i64..200,
    ) {
        let a = Rat::from_frac(1, 3);
        let roots = [a.clone(), &a + &pow2(gap), Rat::from_frac(1, 2)];
        // (t + 1/2)² − 2 = t² + t − 7/4, times 4.
        let far = ZPoly::from_i64s(&[-7, 4, 4]);
        let p = &product(&roots.iter().map(|r| (r.clone(), 1)).collect::<Vec<_>>()) * &far;
        let found = all_roots(&p, &Rat::zero(), &Rat::one());
        prop_assert_eq!(found.len(), 4);
        prop_assert!(found[3].width().mul_pow2(crate::root::WIDE_SIGN_LOG2) >= Rat::one());
        // √2 − 1/2 within 2^(−400), [lo, hi]: the lines' points are
        // rational (lo stands for the root).
        let (far_lo, far_hi) = {
            let mut r = found[3].clone();
            r.refine_to(&pow2(400));
            (r.lo().clone(), r.hi().clone())
        };
        let all = [roots[0].clone(), roots[1].clone(), roots[2].clone(), far_lo.clone()];
        let (alpha_lo, alpha_hi) = if k == 3 { (&far_lo, &far_hi) } else { (&all[k], &all[k]) };
        let alpha = &all[k];
        let neighbour = &all[(k + 1) % 4];
        for q in [
            linear(&(alpha + &pow2(off))),
            linear(&(alpha - &pow2(off))),
            linear(alpha),
            &linear(neighbour) * &linear(&Rat::from(3)),
        ] {
            let model = crate::SignProbe::new(&q);
            let exact = found[k].clone().sign_with(&model);
            // Ground truth: q is a line through a point at least 2^(−299)
            // from α, or through α itself (k < 3), or through the rational
            // just below √2 − 1/2 (k = 3): its sign at α is its sign at
            // alpha_hi.
            prop_assert_eq!(exact, q.sign_at(alpha_hi));
            let mut bounded = found[k].clone();
            match bounded.sign_within(&model, Some(bound)) {
                Some(s) => prop_assert_eq!(s, exact),
                None => prop_assert!(bounded.width() < pow2(bound as u64), "{bound}"),
            }
            prop_assert!(bounded.lo() <= alpha_hi && alpha_lo <= bounded.hi());
            prop_assert_eq!(found[k].vanishes_with(&model), exact == 0);
        }
    }
}

/// Newton's iteration in `f64` exactly as it ran before cycles were read
/// off: every step taken (the reference for `float_newton`).
fn every_newton_step(lo: f64, hi: f64, f: impl Fn(f64) -> (f64, f64)) -> Option<(f64, f64)> {
    let mut x = 0.5 * (lo + hi);
    let mut slope = 0.0;
    for _ in 0..12 {
        let (v, d) = f(x);
        if d == 0.0 || !v.is_finite() || !d.is_finite() {
            return None;
        }
        slope = d;
        let nx = (x - v / d).clamp(lo, hi);
        if nx == x {
            break;
        }
        x = nx;
    }
    Some((x, slope))
}

/// `2^scale · Π (x − r)` in `f64`: value and slope by Horner.
fn product_of_roots(roots: &[f64], scale: i32) -> impl Fn(f64) -> (f64, f64) {
    let mut coeffs = vec![2f64.powi(scale)];
    for r in roots {
        let mut next = vec![0.0; coeffs.len() + 1];
        for (i, c) in coeffs.iter().enumerate() {
            next[i + 1] += c;
            next[i] -= c * r;
        }
        coeffs = next;
    }
    move |x: f64| {
        let (mut v, mut d) = (0.0, 0.0);
        for &c in coeffs.iter().rev() {
            d = d * x + v;
            v = v * x + c;
        }
        (v, d)
    }
}

/// A Newton iteration over a given value-and-slope function.
type Newton<'a> = &'a dyn Fn(&dyn Fn(f64) -> (f64, f64)) -> Option<(f64, f64)>;

/// `float_newton` and every step, as bits (with the evaluations each took).
fn both_newtons(
    lo: f64,
    hi: f64,
    f: &impl Fn(f64) -> (f64, f64),
) -> [(Option<(u64, u64)>, usize); 2] {
    let counted = |run: Newton| {
        let calls = std::cell::Cell::new(0);
        let g = |x: f64| {
            calls.set(calls.get() + 1);
            f(x)
        };
        let out = run(&g).map(|(x, d)| (x.to_bits(), d.to_bits()));
        (out, calls.get())
    };
    [
        counted(&|g| crate::root::float_newton(lo, hi, g)),
        counted(&|g| every_newton_step(lo, hi, g)),
    ]
}

/// A cubic with a simple root at `r` inside `[0, 1]` and a root pair
/// elsewhere, for each `r = i/97`: the rounded steps near `r` settle into
/// a cycle on some of them (the branch that reads the cycle off runs, with
/// fewer evaluations), and on every one the point and slope are those of
/// every step.
#[test]
fn float_newton_reads_real_cycles_off() {
    let mut cycles = 0;
    for i in 1..97 {
        let r = f64::from(i) / 97.0;
        let f = product_of_roots(&[r, 1.3, 1.7], 0);
        let [(fast, fast_calls), (slow, slow_calls)] = both_newtons(0.0, 1.0, &f);
        assert_eq!(fast, slow, "root {r}");
        if fast_calls < slow_calls {
            cycles += 1;
        }
    }
    assert!(cycles > 0, "no cycle was read off");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2048))]
    /// The point and slope `float_newton` gives are the ones every step
    /// reaches, bit for bit, on polynomials with up to six roots drawn in
    /// `[0, 1]` (inside `[lo, hi]`, where the rounded steps may cycle, and
    /// outside it, where they may fail or stop at an end).
    #[test]
    fn float_newton_reads_the_cycle_off_exactly(
        roots in proptest::collection::vec(0.0f64..1.0, 1..7),
        scale in -40i32..40,
        (lo, hi) in (0.0f64..0.5, 0.5f64..1.0),
    ) {
        let f = product_of_roots(&roots, scale);
        let [(fast, _), (slow, _)] = both_newtons(lo, hi, &f);
        prop_assert_eq!(fast, slow);
    }
}
