//! [`FilterBernstein`], the certified filter of the exact isolation:
//! Bernstein coefficients in `f64`, each with its own error bound,
//! subdivided by de Casteljau's algorithm in plain `f64`.
//!
//! **Which Bernstein form is for what.** The exact path's Bernstein form is
//! [`ccd_poly::Bernstein`] (integers times one rational over a rational
//! interval): it is the truth, and every sign it gives is exact. A
//! `FilterBernstein` is a cheap stand-in for it at one node of
//! [`crate::RootIter`]'s subdivision: it answers a coefficient's sign only
//! when the sign is proven by the error bound, and otherwise the node is
//! redone with the exact `Bernstein`. (Not to be confused with
//! `ccd_float::BernsteinF64`, the uncertified float path's polynomials,
//! which carry magnitudes for tolerances, not proofs.)
//!
//! The exact integer coefficients are scaled by one common power of two so
//! that the largest fits comfortably in `f64`. A node holds approximations
//! `b̃_i` and bounds `e_i ≥ |b̃_i − b_i|` on their distance to the exact
//! scaled coefficients `b_i`; a coefficient with `|b̃_i| ≤ e_i` has an
//! undecided sign, and the caller falls back to exact integers for that
//! node. Every sign this module reports is proven.
//!
//! **The bounds of a split.** One de Casteljau step computes
//! `c̃ = fl(x̃ + ỹ)·½` (halving is exact above the subnormal range), so
//! `|c̃ − (x + y)/2| ≤ (e_x + e_y)/2 + 2^(−52)·|c̃| + 2^(−1075)`. The bound
//! itself is computed in `f64` as `(½(e_x + e_y) + 2^(−52)·|c̃| + 4·2^(−1074))`
//! times `(1 + 2^(−50))`, which covers the three roundings of its own
//! evaluation (each at most `2^(−53)` relative, and `(1 − u)⁴(1 + 8u) ≥ 1`)
//! and an underflowed `2^(−52)·|c̃|`. Per-coefficient bounds stay as tight
//! as outward-rounded intervals (each coefficient's error comes from the
//! coefficients it is a combination of, not from the node's largest) at a
//! fraction of the cost: no directed rounding, no `next_up`/`next_down`.

use ccd_arith::{Int, Interval, Rat};
use ccd_poly::{binomials, ZPoly};

/// Largest bit length kept in front of the binary point after scaling.
const TARGET_BITS: i64 = 900;

/// `2^(−52)`: the relative rounding of one `fl(x + y)·½`.
const ULP: f64 = f64::EPSILON;
/// `1 + 2^(−50)`: covers the roundings of the bound's own evaluation.
const SAFETY: f64 = 1.0 + 4.0 * f64::EPSILON;
/// `4·2^(−1074)`: subnormal halving and underflow.
const TINY: f64 = f64::from_bits(4);

/// A node's Bernstein coefficients (the exact values times one positive
/// factor) as `f64` approximations with error bounds.
#[derive(Clone, Debug)]
pub(crate) struct FilterBernstein {
    coeffs: Vec<f64>,
    /// `errs[i] ≥ |coeffs[i] − exact_i|` (`0.0 ± 0` marks a coefficient
    /// known to be exactly zero, e.g. at an end that is an exact root; de
    /// Casteljau copies the end coefficients, so the mark survives splits).
    errs: Vec<f64>,
}

/// The sign of every number within `e` of `b` (`None` if that interval
/// holds zero, except for the exact zero `0 ± 0`).
#[inline]
fn certified_sign(b: f64, e: f64) -> Option<i32> {
    if b > e {
        Some(1)
    } else if b < -e {
        Some(-1)
    } else if b == 0.0 && e == 0.0 {
        Some(0)
    } else {
        None
    }
}

impl FilterBernstein {
    /// From interval enclosures of the exact (scaled) coefficients: their
    /// midpoints and distances to the farther end.
    pub(crate) fn from_intervals(iv: &[Interval]) -> FilterBernstein {
        let coeffs: Vec<f64> = iv.iter().map(Interval::mid).collect();
        let errs = iv
            .iter()
            .zip(&coeffs)
            .map(|(i, &m)| {
                let e = (i.hi - m).max(m - i.lo);
                if e > 0.0 {
                    e.next_up()
                } else {
                    0.0
                }
            })
            .collect();
        FilterBernstein { coeffs, errs }
    }

    /// Encloses `sign · coeffs` scaled by a common power of two.
    pub(crate) fn from_exact(coeffs: &[Int], sign: i32) -> FilterBernstein {
        let max_bits = coeffs.iter().map(Int::bits).max().unwrap_or(0) as i64;
        let shift = (max_bits - TARGET_BITS).max(0);
        let iv: Vec<Interval> = coeffs
            .iter()
            .map(|c| {
                let i = Interval::from_int_scaled(c, shift);
                if sign < 0 {
                    -i
                } else {
                    i
                }
            })
            .collect();
        FilterBernstein::from_intervals(&iv)
    }

    /// Encloses the Bernstein coefficients of `p` over `[lo, hi]` (times a
    /// positive factor) without a single gcd: with `q(u) = p(lo + (hi − lo)·u)`
    /// (exact, up to a positive factor), the integers
    /// `c_i = C(n, i)·b_i` are the coefficients of `(1 + s)^n q(s/(1 + s))`,
    /// i.e. `reverse(shift₁(reverse(q)))` — additions only — and each `b_i` is
    /// then enclosed as `c_i / C(n, i)` with one rounding (no cancellation).
    /// The signs of the `c_i` are exact. Requires `p(lo) ≠ 0` and `p(hi) ≠ 0`
    /// (so the reversals keep the degree); `None` if a sign is undecided.
    pub(crate) fn from_power(p: &ZPoly, lo: &Rat, hi: &Rat) -> Option<FilterBernstein> {
        let n = p.degree()?;
        let c = if lo.is_zero() && *hi == Rat::one() {
            p.scaled_bernstein()
        } else {
            p.compose_affine(lo, &(hi - lo)).scaled_bernstein()
        };
        // The ends are p(lo), p(hi) (times positive factors).
        if c[0].is_zero() || c[n].is_zero() {
            return None;
        }
        let max_bits = c.iter().map(Int::bits).max().unwrap_or(0) as i64;
        let shift = (max_bits - TARGET_BITS).max(0);
        let iv: Vec<Interval> = c
            .iter()
            .zip(binomials(n))
            .map(|(ci, b)| {
                Interval::from_int_scaled(ci, shift).div_positive(Interval::from_int(&b))
            })
            .collect();
        let fb = FilterBernstein::from_intervals(&iv);
        fb.decided().then_some(fb)
    }

    /// The certified sign of coefficient `i` (`None` if undecided).
    pub(crate) fn sign(&self, i: usize) -> Option<i32> {
        certified_sign(self.coeffs[i], self.errs[i])
    }

    /// The certified sign of every coefficient in turn (`None` where
    /// undecided).
    pub(crate) fn signs(&self) -> impl Iterator<Item = Option<i32>> + '_ {
        self.coeffs
            .iter()
            .zip(&self.errs)
            .map(|(&b, &e)| certified_sign(b, e))
    }

    /// The sign variations of the coefficients and their first and last
    /// signs, when every sign is certified and none is zero (the usual
    /// node): one pass with no branch per coefficient, where a change is
    /// any neighbour of the other sign. `None` otherwise (an undecided
    /// sign or an exact zero: a pass over [`FilterBernstein::signs`]
    /// decides those).
    pub(crate) fn nonzero_variations(&self) -> Option<(usize, i32, i32)> {
        let sign = |(&b, &e): (&f64, &f64)| i32::from(b > e) - i32::from(b < -e);
        let mut signs = self.coeffs.iter().zip(&self.errs).map(sign);
        let first = signs.next()?;
        let (mut var, mut last, mut zero) = (0usize, first, first == 0);
        for s in signs {
            zero |= s == 0;
            var += usize::from(s != last);
            last = s;
        }
        (!zero).then_some((var, first, last))
    }

    /// Whether every coefficient's sign is certified.
    pub(crate) fn decided(&self) -> bool {
        self.signs().all(|s| s.is_some())
    }

    /// The certified sign of every second difference
    /// `b_{i+2} − 2·b_{i+1} + b_i` (`None` where undecided): outward-rounded
    /// intervals `b̃_i ± e_i` combined.
    pub(crate) fn second_difference_signs(&self) -> impl Iterator<Item = Option<i32>> + '_ {
        let at =
            |i: usize| Interval::point(self.coeffs[i]) + Interval::new(-self.errs[i], self.errs[i]);
        (0..self.coeffs.len().saturating_sub(2)).map(move |i| {
            let m = at(i + 1);
            (at(i + 2) - (m + m) + at(i)).sign()
        })
    }

    /// The certified sign at the node's right end (its last coefficient).
    pub(crate) fn sign_at_hi(&self) -> Option<i32> {
        self.sign(self.coeffs.len() - 1)
    }

    /// Marks the left (`at_hi = false`) or right end as an exact root.
    pub(crate) fn set_end_zero(&mut self, at_hi: bool) {
        let i = if at_hi { self.coeffs.len() - 1 } else { 0 };
        self.coeffs[i] = 0.0;
        self.errs[i] = 0.0;
    }

    /// Descartes' test on one child of a split at the local parameter
    /// `r ∈ (0, 1)`: the left one (`[lo, m]`, `left`) or the right one
    /// (`[m, hi]`), from de Casteljau's `(1 − r)·x + r·y` in outward-rounded
    /// intervals around the coefficients. `Some(true)`: every coefficient of
    /// the child is signed, without a sign change, and the one at `m` is
    /// nonzero (the exact child is root-free, and `m` is not a root);
    /// `Some(false)`: two signed coefficients differ, a sign change the
    /// exact child has too; `None`: undecided.
    pub(crate) fn side_root_free(&self, r: &Rat, left: bool) -> Option<bool> {
        let r = Interval::from_rat(r);
        let s = Interval::point(1.0) - r;
        let mut v: Vec<Interval> = self
            .coeffs
            .iter()
            .zip(&self.errs)
            .map(|(&b, &e)| Interval::point(b) + Interval::new(-e, e))
            .collect();
        let n = v.len() - 1;
        // The child's coefficients, the one at `m` last (the right child's
        // from `hi` down to `m`: Descartes' rule reads no order).
        let mut child = Vec::with_capacity(n + 1);
        child.push(v[if left { 0 } else { n }]);
        for k in 1..=n {
            for i in 0..=n - k {
                v[i] = v[i] * s + v[i + 1] * r;
            }
            child.push(v[if left { 0 } else { n - k }]);
        }
        let signs: Vec<Option<i32>> = child.iter().map(Interval::sign).collect();
        let mut nonzero = signs.iter().flatten().filter(|&&x| x != 0);
        if let Some(&first) = nonzero.next() {
            if nonzero.any(|&x| x != first) {
                return Some(false);
            }
        }
        (signs.iter().all(Option::is_some) && signs[n] != Some(0)).then_some(true)
    }

    /// De Casteljau at `1/2`: the coefficients over the two halves, with the
    /// error bounds of the module documentation. In place: level `k` of the
    /// triangle overwrites entries `0..=n − k` of level `k − 1` (entry `i`
    /// is read by steps `i − 1` and `i` before step `i` writes it), the
    /// left half collects each level's first entry, and what is left at
    /// the end, entry `i` of level `n − i`, is the right half.
    pub(crate) fn split_half(self) -> (FilterBernstein, FilterBernstein) {
        let FilterBernstein {
            coeffs: mut b,
            errs: mut e,
        } = self;
        let n = b.len() - 1;
        let mut left = FilterBernstein {
            coeffs: vec![0.0; n + 1],
            errs: vec![0.0; n + 1],
        };
        #[cfg(target_arch = "x86_64")]
        if std::arch::is_x86_feature_detected!("avx") {
            // SAFETY: the CPU has AVX (checked just above), the only
            // requirement of `triangle_avx`.
            unsafe { triangle_avx(&mut b, &mut e, &mut left.coeffs, &mut left.errs) };
            return (left, FilterBernstein { coeffs: b, errs: e });
        }
        triangle(&mut b, &mut e, &mut left.coeffs, &mut left.errs);
        (left, FilterBernstein { coeffs: b, errs: e })
    }
}

/// The in-place triangle of [`FilterBernstein::split_half`]: `b`, `e`
/// become the right half, `lb`, `le` (as long) receive the left half.
/// Every element is one independent `f64` expression of the level above,
/// so the compiler vectorises each level; the vector width changes no
/// result (IEEE operations, no contraction into fused multiply-adds).
#[inline(always)]
fn triangle(b: &mut [f64], e: &mut [f64], lb: &mut [f64], le: &mut [f64]) {
    let n = b.len() - 1;
    let (e, lb, le) = (&mut e[..=n], &mut lb[..=n], &mut le[..=n]);
    lb[0] = b[0];
    le[0] = e[0];
    for len in (1..=n).rev() {
        let (b, e) = (&mut b[..=len], &mut e[..=len]);
        for i in 0..len {
            let c = (b[i] + b[i + 1]) * 0.5;
            e[i] = (0.5 * (e[i] + e[i + 1]) + ULP * c.abs() + TINY) * SAFETY;
            b[i] = c;
        }
        lb[n + 1 - len] = b[0];
        le[n + 1 - len] = e[0];
    }
}

/// [`triangle`] compiled for AVX: four `f64` lanes instead of SSE2's two,
/// the same operations on each element.
///
/// # Safety
///
/// The CPU must support AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn triangle_avx(b: &mut [f64], e: &mut [f64], lb: &mut [f64], le: &mut [f64]) {
    triangle(b, e, lb, le)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_poly::Bernstein;

    #[test]
    fn split_encloses_exact_halves() {
        // p(u) = (u - 1/3)(u - 2/3) in Bernstein form over [0, 1]:
        // b = [2/9, -5/18, 2/9] -> times 18: [4, -5, 4].
        let fb = FilterBernstein::from_exact(&[Int::from(4), Int::from(-5), Int::from(4)], 1);
        assert_eq!(fb.signs().collect::<Option<Vec<_>>>(), Some(vec![1, -1, 1]));
        let (l, r) = fb.split_half();
        // Exact halves: left [4, -1/2, -1/4]·..., check signs only.
        assert_eq!(l.signs().collect::<Option<Vec<_>>>(), Some(vec![1, -1, -1]));
        assert_eq!(r.signs().collect::<Option<Vec<_>>>(), Some(vec![-1, -1, 1]));
    }

    #[test]
    fn side_tests_of_a_simple_split() {
        // (u − 3/4)² − 1/64 on [0, 1], roots 5/8 and 7/8: Bernstein
        // coefficients 35/64, −13/64, 3/64, times 64.
        let fb = FilterBernstein::from_exact(&[Int::from(35), Int::from(-13), Int::from(3)], 1);
        let r = |p: i64, q: i64| Rat::new(Int::from(p), Int::from(q)).expect("nonzero");
        assert_eq!(fb.side_root_free(&r(1, 2), true), Some(true));
        assert_eq!(fb.side_root_free(&r(1, 2), false), Some(false));
        assert_eq!(fb.side_root_free(&r(15, 16), false), Some(true));
        // At the root 5/8 the cut's coefficient is 0: never proven nonzero.
        assert_eq!(fb.side_root_free(&r(5, 8), true), None);
        // A coefficient the filter cannot sign leaves the side open even
        // where the signed ones agree: 1, [−1, 2], 1 (an exact child could
        // change sign twice).
        let open = FilterBernstein::from_intervals(&[
            Interval::point(1.0),
            Interval::new(-1.0, 2.0),
            Interval::point(1.0),
        ]);
        assert_eq!(open.side_root_free(&r(1, 2), true), None);
        assert_eq!(open.side_root_free(&r(1, 2), false), None);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(128))]
        /// What [`FilterBernstein::side_root_free`] proves is what the
        /// exact child says (no sign change and nonzero at the cut, or a
        /// sign change), on long coefficients and cuts of up to 60 bits;
        /// and it decides a child of one sign far from zero.
        #[test]
        fn side_tests_are_the_exact_ones(
            raw in proptest::collection::vec(-1000i64..1000, 2..14),
            big in 0u32..300,
            (p, k) in proptest::strategy::Strategy::prop_flat_map(1u64..60, |k| (1u64..(1 << k), proptest::prelude::Just(k))),
            left in proptest::prelude::any::<bool>(),
        ) {
            let scale = Int::from(3).pow(big);
            let c: Vec<Int> = raw.iter().map(|&x| &scale * &Int::from(x) + Int::from(x % 7)).collect();
            let r = Rat::new(Int::from_u64(p), Int::one().shl(k)).expect("nonzero");
            let exact = Bernstein::from_parts(Rat::zero(), Rat::one(), Rat::one(), c.clone());
            let (l, rt) = exact.split(&r);
            let (child, at_cut) = if left { (&l, l.sign_at_hi()) } else { (&rt, rt.sign_at_lo()) };
            let fb = FilterBernstein::from_exact(&c, 1);
            match fb.side_root_free(&r, left) {
                Some(true) => proptest::prop_assert!(child.sign_variations() == 0 && at_cut != 0),
                Some(false) => proptest::prop_assert!(child.sign_variations() != 0),
                None => {}
            }
            // A root at the cut itself, cuts of up to 123 bits (past f64's
            // 53): that side is never proven root-free.
            let cut = Rat::new(Int::from_u64(p).shl(64) + Int::from_u64(p ^ 0x9e37_79b9), Int::one().shl(k + 64)).expect("nonzero");
            let h = ccd_poly::ZPoly::new(raw.iter().map(|&x| Int::from(x.abs() + 1)).collect());
            let at_cut = &ccd_poly::ZPoly::new(vec![-cut.numer().clone(), cut.denom().clone()]) * &h;
            let b = Bernstein::from_power(&at_cut, &Rat::zero(), &Rat::one());
            let filter = FilterBernstein::from_exact(b.coeffs(), 1);
            proptest::prop_assert_ne!(filter.side_root_free(&cut, left), Some(true));
            let positive: Vec<Int> = raw.iter().map(|&x| &scale * &Int::from(x.abs() + 1)).collect();
            proptest::prop_assert_eq!(FilterBernstein::from_exact(&positive, 1).side_root_free(&r, left), Some(true));
        }
        /// Every second-difference sign the filter proves is the exact
        /// one, on coefficients long enough to be rounded (and after a
        /// split, whose errors it must carry).
        #[test]
        fn second_difference_signs_are_exact_ones(
            raw in proptest::collection::vec(-1000i64..1000, 3..12),
            big in 0u32..300,
        ) {
            let scale = Int::from(3).pow(big);
            let c: Vec<Int> = raw.iter().map(|&x| &scale * &Int::from(x) + Int::from(x % 7)).collect();
            let exact = |c: &[Int]| -> Vec<i32> {
                (0..c.len() - 2).map(|i| (&(&c[i + 2] - &c[i + 1]) - &(&c[i + 1] - &c[i])).signum()).collect()
            };
            let fb = FilterBernstein::from_exact(&c, 1);
            for (got, want) in fb.second_difference_signs().zip(exact(&c)) {
                proptest::prop_assert!(got.is_none_or(|g| g == want));
            }
            // The left half, exactly: de Casteljau's first entries, doubled
            // per level (the common factor 2^n keeps every sign).
            let mut level = c.clone();
            let mut left = vec![level[0].shl(c.len() as u64 - 1)];
            let mut scale2 = 0u64;
            while level.len() > 1 {
                level = level.windows(2).map(|w| &w[0] + &w[1]).collect();
                scale2 += 1;
                left.push(level[0].shl(c.len() as u64 - 1 - scale2));
            }
            let (l, _) = fb.split_half();
            for (got, want) in l.second_difference_signs().zip(exact(&left)) {
                proptest::prop_assert!(got.is_none_or(|g| g == want));
            }
        }
    }

    proptest::proptest! {
        /// The branch-free count is the count over the signs one by one:
        /// coefficients of every sign, undecided ones and exact zeros.
        #[test]
        fn nonzero_variations_count_the_sign_changes(
            raw in proptest::collection::vec((-3i32..4, 0u8..4), 1..40),
        ) {
            // (value, error): decided, undecided (error past the value), or
            // the exact zero 0 ± 0.
            let (coeffs, errs): (Vec<f64>, Vec<f64>) = raw
                .iter()
                .map(|&(v, e)| (f64::from(v), if e == 3 { f64::from(v.abs()) + 1.0 } else { f64::from(e) * 0.25 }))
                .map(|(v, e)| if v == 0.0 && e < 1.0 { (0.0, 0.0) } else { (v, e) })
                .unzip();
            let fb = FilterBernstein { coeffs, errs };
            let signs: Option<Vec<i32>> = fb.signs().collect();
            let expected = signs.filter(|s| s.iter().all(|&x| x != 0)).map(|s| {
                let var = s.windows(2).filter(|w| w[0] != w[1]).count();
                (var, s[0], s[s.len() - 1])
            });
            proptest::prop_assert_eq!(fb.nonzero_variations(), expected);
        }
    }

    #[test]
    fn interval_conversion_agrees_with_exact_signs() {
        // (3u − 1)(2u − 1)(u² + 1)·(5u + 7) on several intervals.
        let p = ZPoly::from_i64s(&[-1, 3])
            * ZPoly::from_i64s(&[-1, 2])
            * ZPoly::from_i64s(&[1, 0, 1])
            * ZPoly::from_i64s(&[7, 5]);
        for (lo, hi) in [
            (Rat::zero(), Rat::one()),
            (Rat::from_frac(-3, 2), Rat::from_frac(1, 5)),
            (Rat::from_frac(1, 7), Rat::from(4)),
        ] {
            let exact = Bernstein::from_power(&p, &lo, &hi);
            let float = FilterBernstein::from_power(&p, &lo, &hi).expect("well conditioned");
            let signs: Vec<i32> = exact.coeffs().iter().map(|c| c.signum()).collect();
            assert_eq!(float.signs().collect::<Option<Vec<_>>>(), Some(signs));
        }
    }

    /// Exact de Casteljau at ½ over the rationals.
    fn exact_halves(b: &[Rat]) -> (Vec<Rat>, Vec<Rat>) {
        let n = b.len() - 1;
        let mut b = b.to_vec();
        let (mut left, mut right) = (vec![b[0].clone()], vec![b[n].clone()]);
        for k in 1..=n {
            for i in 0..=n - k {
                b[i] = Rat::midpoint(&b[i], &b[i + 1]);
            }
            left.push(b[0].clone());
            right.push(b[n - k].clone());
        }
        right.reverse();
        (left, right)
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(64))]
        /// The bounds hold along random subdivision paths: every
        /// approximation is within its bound of the exact coefficient, so every
        /// sign the filter reports is the exact sign.
        #[test]
        fn running_bound_holds_along_subdivision_paths(
            raw in proptest::collection::vec((-1_000_000_007i64..1_000_000_007, 0u32..300), 2..40),
            path in proptest::collection::vec(proptest::bool::ANY, 1..10),
        ) {
            let ints: Vec<Int> = raw.iter().map(|(m, k)| Int::from(*m).shl(u64::from(*k))).collect();
            let mut exact: Vec<Rat> = ints.iter().map(|c| Rat::from(c.clone())).collect();
            let mut fb = FilterBernstein::from_exact(&ints, 1);
            for right in path {
                let (l, r) = fb.split_half();
                let (el, er) = exact_halves(&exact);
                (fb, exact) = if right { (r, er) } else { (l, el) };
                for (i, (a, e)) in fb.coeffs.iter().zip(&exact).enumerate() {
                    let err = Rat::from_f64_exact(fb.errs[i]).expect("finite");
                    let a = Rat::from_f64_exact(*a).expect("finite");
                    proptest::prop_assert!((&a - e).abs() <= err);
                    if let Some(s) = fb.sign(i) {
                        proptest::prop_assert_eq!(s, e.signum());
                    }
                }
            }
        }
    }

    /// The split as first written (two buffers per level, children
    /// assembled from the triangle's edges): the reference the in-place
    /// split must match bit for bit, so that every sign, and every output
    /// byte, stays as it was.
    fn reference_split(fb: &FilterBernstein) -> (FilterBernstein, FilterBernstein) {
        let n = fb.coeffs.len() - 1;
        let (mut b, mut e) = (fb.coeffs.clone(), fb.errs.clone());
        let mut left = (vec![b[0]], vec![e[0]]);
        let mut right = (vec![0.0; n + 1], vec![0.0; n + 1]);
        right.0[n] = b[n];
        right.1[n] = e[n];
        for k in 1..=n {
            let next: Vec<(f64, f64)> = (0..=n - k)
                .map(|i| {
                    let c = (b[i] + b[i + 1]) * 0.5;
                    let err = (0.5 * (e[i] + e[i + 1]) + ULP * c.abs() + TINY) * SAFETY;
                    (c, err)
                })
                .collect();
            (b, e) = next.into_iter().unzip();
            left.0.push(b[0]);
            left.1.push(e[0]);
            right.0[n - k] = b[n - k];
            right.1[n - k] = e[n - k];
        }
        let child = |(coeffs, errs)| FilterBernstein { coeffs, errs };
        (child(left), child(right))
    }

    fn bits(fb: &FilterBernstein) -> Vec<(u64, u64)> {
        fb.coeffs
            .iter()
            .zip(&fb.errs)
            .map(|(c, e)| (c.to_bits(), e.to_bits()))
            .collect()
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
        /// The in-place split gives the reference's halves bit for bit,
        /// portable and AVX alike, down random paths, on coefficients of
        /// every size (subnormal ones included) and with exact zeros
        /// marked at the ends.
        #[test]
        fn in_place_split_matches_the_reference(
            raw in proptest::collection::vec((-1_000_000_007i64..1_000_000_007, -1100i32..1000, 0.0f64..1e-10), 1..80),
            ends in (proptest::bool::ANY, proptest::bool::ANY),
            path in proptest::collection::vec(proptest::bool::ANY, 1..6),
        ) {
            let coeffs = raw.iter().map(|&(m, k, _)| m as f64 * 2f64.powi(k)).collect();
            let errs = raw.iter().map(|&(m, k, r)| (m as f64 * 2f64.powi(k)).abs() * r).collect();
            let mut fb = FilterBernstein { coeffs, errs };
            if ends.0 { fb.set_end_zero(false); }
            if ends.1 { fb.set_end_zero(true); }
            for right in path {
                let (rl, rr) = reference_split(&fb);
                // The portable triangle (SSE2), whatever the CPU has.
                let (mut b, mut e) = (fb.coeffs.clone(), fb.errs.clone());
                let (mut lb, mut le) = (vec![0.0; b.len()], vec![0.0; b.len()]);
                triangle(&mut b, &mut e, &mut lb, &mut le);
                let portable = |coeffs, errs| bits(&FilterBernstein { coeffs, errs });
                proptest::prop_assert_eq!(portable(lb, le), bits(&rl));
                proptest::prop_assert_eq!(portable(b, e), bits(&rr));
                // The split itself (AVX where the CPU has it).
                let (l, r) = fb.split_half();
                proptest::prop_assert_eq!(bits(&l), bits(&rl));
                proptest::prop_assert_eq!(bits(&r), bits(&rr));
                fb = if right { r } else { l };
            }
        }
    }

    #[test]
    fn huge_coefficients_keep_their_signs() {
        let big = Int::from(7).pow(1000);
        let fb = FilterBernstein::from_exact(&[big.clone(), -big.clone(), Int::from(1)], -1);
        assert_eq!(fb.sign(0), Some(-1));
        assert_eq!(fb.sign(1), Some(1));
        // 1 vanishes next to 7^1000 after scaling: undecided, never wrong.
        assert_eq!(fb.sign(2), None);
    }
}
