//! The simplest points of a rational interval: the simplest rational
//! (smallest denominator, by the Stern–Brocot descent) and the dyadic
//! rational with the smallest power of two.

use super::Rat;
use crate::Int;

impl Rat {
    /// The simplest rational in the closed interval `[lo, hi]` (smallest
    /// denominator, then smallest numerator magnitude), by the continued
    /// fraction (Stern–Brocot) descent. If `[lo, hi]` is narrower than
    /// `1/b²` and holds `a/b`, the answer is `a/b`: the way to recognise a
    /// rational root from a small enclosure.
    ///
    /// ```
    /// use ccd_arith::Rat;
    /// let (lo, hi) = (Rat::from_frac(3333, 10000), Rat::from_frac(3334, 10000));
    /// assert_eq!(Rat::simplest_in(&lo, &hi), Rat::from_frac(1, 3));
    /// ```
    pub fn simplest_in(lo: &Rat, hi: &Rat) -> Rat {
        debug_assert!(lo <= hi);
        if lo.signum() <= 0 && hi.signum() >= 0 {
            return Rat::zero();
        }
        if hi.signum() < 0 {
            return -Rat::simplest_in(&-hi, &-lo);
        }
        // 0 < a/b <= c/d. Descend the continued fractions of both ends at
        // once (integers only), accumulating the convergents h/k of the
        // common prefix: x = t0 + 1/(t1 + 1/(…)), each level being
        // `simplest(x) = t + 1/simplest(d/(c − t·d), b/(a − t·b))`.
        let (mut a, mut b) = (lo.num.clone(), lo.den.clone());
        let (mut c, mut d) = (hi.num.clone(), hi.den.clone());
        let (mut h1, mut h2) = (Int::one(), Int::zero());
        let (mut k1, mut k2) = (Int::zero(), Int::one());
        loop {
            let (t, r) = a.div_rem_trunc(&b);
            // The last term: lo is an integer here, or the next integer fits below hi.
            let last = if r.is_zero() {
                Some(t.clone())
            } else {
                let t1 = &t + &Int::one();
                (&t1 * &d <= c).then_some(t1)
            };
            let term = last.clone().unwrap_or_else(|| t.clone());
            let h = &(&term * &h1) + &h2;
            let k = &(&term * &k1) + &k2;
            if last.is_some() {
                // Convergents are in lowest terms with k > 0.
                return Rat { num: h, den: k };
            }
            (h2, h1, k2, k1) = (h1, h, k1, k);
            // Recurse on (d/(c − t·d), b/(a − t·b)): note the swap of ends.
            let (na, nb) = (d.clone(), &c - &(&t * &d));
            let (nc, nd) = (b, r);
            (a, b, c, d) = (na, nb, nc, nd);
        }
    }
    /// The dyadic rational `m/2^k` with the smallest `k` in `[lo, hi]`
    /// (`lo <= hi`): the cheapest point of an interval to evaluate at exactly.
    pub fn dyadic_in(lo: &Rat, hi: &Rat) -> Rat {
        // Either order: a reversed pair would never find a level.
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        match (lo.dyadic_exponent(), hi.dyadic_exponent()) {
            (Some(kl), Some(kh)) => Rat::dyadic_in_dyadic(lo, kl, hi, kh),
            _ => Rat::dyadic_in_search(lo, hi),
        }
    }
    /// [`Rat::dyadic_in`] for dyadic ends `lo = L/2^kl`, `hi = H/2^kh`: at
    /// the common level `k`, the multiple of the largest `2^s` in
    /// `[L·2^(k−kl), H·2^(k−kh)]`, found by shifts only.
    fn dyadic_in_dyadic(lo: &Rat, kl: u64, hi: &Rat, kh: u64) -> Rat {
        // As 0 <= l − 1 < h, the level is the highest bit where h and
        // l − 1 differ.
        Rat::dyadic_in_dyadic_by(lo, kl, hi, kh, |h, below| {
            h.highest_differing_bit(below)
                .expect("h > l − 1 differ somewhere")
        })
    }
    /// [`Rat::dyadic_in_dyadic`] with the level `s` found by `level(h, l − 1)`:
    /// the largest `s` with `⌊h/2^s⌋ > ⌊(l − 1)/2^s⌋` for `0 < l <= h`.
    #[inline]
    fn dyadic_in_dyadic_by(
        lo: &Rat,
        kl: u64,
        hi: &Rat,
        kh: u64,
        level: impl FnOnce(&Int, &Int) -> u64,
    ) -> Rat {
        let k = kl.max(kh);
        let (l, h) = (lo.num.shl(k - kl), hi.num.shl(k - kh));
        if l.signum() <= 0 && h.signum() >= 0 {
            // Zero is inside: the cheapest point of all (as the search picks).
            return Rat::zero();
        }
        // Mirror a negative interval to a positive one.
        let (l, h, negative) = if h.is_negative() {
            (-h, -l, true)
        } else {
            (l, h, false)
        };
        let below = &l - &Int::one();
        let good = level(&h, &below);
        if good >= k {
            // Integers inside: the least one, as the search below picks.
            return Rat::from_int(-(-&lo.num).shr_floor(kl));
        }
        let m = h.shr_floor(good).shl(good);
        Rat::dyadic(if negative { -m } else { m }, k)
    }
    /// [`Rat::dyadic_in`] for any rational ends.
    fn dyadic_in_search(lo: &Rat, hi: &Rat) -> Rat {
        // The smallest m with m/2^k >= lo, if m/2^k <= hi. Having a point at
        // level k implies one at k + 1, so the smallest level is found by
        // bisection below a level that surely has one (2^-k <= hi − lo).
        let (a, b, c, d) = (&lo.num, &lo.den, &hi.num, &hi.den);
        let at_level = |k: u64| -> Option<Int> {
            let m = -(-a.shl(k)).div_floor(b);
            (&m * d <= c.shl(k)).then_some(m)
        };
        // The cheap answers first: zero, then an integer.
        if lo.num.signum() <= 0 && hi.num.signum() >= 0 {
            return Rat::zero();
        }
        if let Some(m) = at_level(0) {
            return Rat::from_int(m);
        }
        let w = hi - lo;
        if w.is_zero() {
            return lo.clone();
        }
        let mut top = (w.den.bits() + 1).saturating_sub(w.num.bits()) + 1;
        while at_level(top).is_none() {
            top += 1;
        }
        let mut bottom = 0u64;
        // Invariant: no point at `bottom`, a point at `top`.
        while top - bottom > 1 {
            let mid = bottom + (top - bottom) / 2;
            if at_level(mid).is_some() {
                top = mid;
            } else {
                bottom = mid;
            }
        }
        let m = at_level(top).expect("a point at the top level");
        Rat::dyadic(m, top)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn dyadic_points() {
        let d = Rat::dyadic_in(&Rat::from_frac(1, 3), &Rat::from_frac(2, 5));
        assert_eq!(d, Rat::from_frac(3, 8));
        assert_eq!(d.dyadic_exponent(), Some(3));
        // Ends in either order (a reversed pair used to search forever).
        assert_eq!(
            Rat::dyadic_in(&Rat::from_frac(2, 5), &Rat::from_frac(1, 3)),
            Rat::from_frac(3, 8)
        );
        // Zero, when inside, is the cheapest point of all.
        assert_eq!(
            Rat::dyadic_in(&Rat::from_frac(-7, 3), &Rat::from(5)),
            Rat::zero()
        );
        assert_eq!(
            Rat::dyadic_in(&Rat::from_frac(7, 3), &Rat::from(5)),
            Rat::from(3)
        );
        assert_eq!(Rat::from_frac(1, 3).dyadic_exponent(), None);
        assert_eq!(Rat::from(4).dyadic_exponent(), Some(0));
    }

    #[test]
    fn simplest_rationals() {
        let s = |a: (i64, i64), b: (i64, i64)| {
            Rat::simplest_in(&Rat::from_frac(a.0, a.1), &Rat::from_frac(b.0, b.1))
        };
        assert_eq!(s((1, 3), (1, 2)), Rat::from_frac(1, 2));
        assert_eq!(s((-7, 2), (-3, 1)), Rat::from(-3));
        assert_eq!(s((-1, 2), (1, 3)), Rat::zero());
        assert_eq!(s((7, 10), (3, 4)), Rat::from_frac(3, 4));
        assert_eq!(s((22, 7), (22, 7)), Rat::from_frac(22, 7));
        assert_eq!(s((314, 100), (315, 100)), Rat::from_frac(22, 7));
    }

    /// The level search [`Rat::dyadic_in_dyadic`] replaced by a bit
    /// comparison: bisection for the largest `s` with
    /// `⌊h/2^s⌋ > ⌊(l − 1)/2^s⌋`, then the same point.
    fn dyadic_in_dyadic_bisection(lo: &Rat, kl: u64, hi: &Rat, kh: u64) -> Rat {
        Rat::dyadic_in_dyadic_by(lo, kl, hi, kh, |h, below| {
            let (mut good, mut bad) = (0u64, h.bits() + 1);
            while bad - good > 1 {
                let mid = good + (bad - good) / 2;
                if h.shr_floor(mid) > below.shr_floor(mid) {
                    good = mid;
                } else {
                    bad = mid;
                }
            }
            good
        })
    }

    /// A dyadic with a numerator of up to four 64-bit digits.
    fn long_dyadic() -> impl Strategy<Value = Rat> {
        (
            any::<bool>(),
            proptest::collection::vec(any::<u64>(), 0..4),
            0u64..300,
        )
            .prop_map(|(neg, limbs, k)| Rat::dyadic(Int::from_u64_limbs(neg, &limbs), k))
    }

    proptest! {
        /// The highest differing bit gives the bisection's point, for long
        /// ends of either sign and widths from zero up (nearby ends share
        /// long prefixes).
        #[test]
        fn dyadic_in_dyadic_is_the_bisection(lo in long_dyadic(), w in long_dyadic(), near in any::<bool>()) {
            let w = if near { w.mul_pow2(-200).abs() } else { w.abs() };
            let hi = &lo + &w;
            let (kl, kh) = (lo.dyadic_exponent().unwrap(), hi.dyadic_exponent().unwrap());
            prop_assert_eq!(
                Rat::dyadic_in_dyadic(&lo, kl, &hi, kh),
                dyadic_in_dyadic_bisection(&lo, kl, &hi, kh)
            );
        }
    }

    proptest! {
        /// The shift-only path for dyadic ends picks the same point as the
        /// general search.
        #[test]
        fn dyadic_in_fast_path_matches_search(a in -100_000i64..100_000, ka in 0u64..40, w in 0i64..100_000, kw in 0u64..40) {
            let lo = Rat::dyadic(Int::from(a), ka);
            let hi = &lo + &Rat::dyadic(Int::from(w), kw);
            prop_assert_eq!(Rat::dyadic_in(&lo, &hi), Rat::dyadic_in_search(&lo, &hi));
        }
    }

    proptest! {
        #[test]
        fn simplest_is_inside_and_recovers_small_fractions(a in -500i64..500, b in 1i64..500, w in 1i64..1000) {
            let x = Rat::from_frac(a, b);
            let eps = Rat::from_frac(1, 4 * b * b * w);
            let s = Rat::simplest_in(&(&x - &eps), &(&x + &eps));
            prop_assert_eq!(s, x);
        }

        #[test]
        fn simplest_is_simplest(a in -300i64..300, b in 1i64..60, c in 0i64..300, d in 1i64..60) {
            let lo = Rat::from_frac(a, b);
            let hi = &lo + &Rat::from_frac(c, d);
            let s = Rat::simplest_in(&lo, &hi);
            prop_assert!(lo <= s && s <= hi);
            // No rational with a smaller denominator lies in [lo, hi].
            let den = s.denom().to_i64().unwrap();
            for q in 1..den {
                let first = (&lo * &Rat::from(q)).numer().div_floor(&(&lo * &Rat::from(q)).denom().clone());
                for p in [first.clone(), &first + &Int::one()] {
                    let r = Rat::new(p, Int::from(q)).unwrap();
                    prop_assert!(!(lo <= r && r <= hi), "{} simpler than {} in [{}, {}]", r, s, lo, hi);
                }
            }
        }
    }
}
