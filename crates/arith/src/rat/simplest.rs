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
        Rat::simplest_by(lo, hi, true)
    }

    /// [`Rat::simplest_in`], with the faster routes of [`Descent`]
    /// (`fast`) or one exact level at a time (the tests' reference).
    fn simplest_by(lo: &Rat, hi: &Rat, fast: bool) -> Rat {
        debug_assert!(lo <= hi);
        if lo.signum() <= 0 && hi.signum() >= 0 {
            return Rat::zero();
        }
        if hi.signum() < 0 {
            return -Rat::simplest_by(&-hi, &-lo, fast);
        }
        // 0 < a/b <= c/d. Descend the continued fractions of both ends at
        // once: short ends in `i128` to the end, long ones many levels at a
        // time from their leading bits, else one level exactly.
        let mut descent = Descent {
            ends: [
                lo.num.clone(),
                lo.den.clone(),
                hi.num.clone(),
                hi.den.clone(),
            ],
            convergents: [Int::one(), Int::zero(), Int::zero(), Int::one()],
        };
        loop {
            if fast {
                if let Some(r) = descent.finish_short() {
                    return r;
                }
                if descent.batch() {
                    continue;
                }
            }
            if let Some(r) = descent.step() {
                return r;
            }
        }
    }
    /// The dyadic rational `m/2^k` with the smallest `k` in `[lo, hi]`
    /// (`lo <= hi`): the cheapest point of an interval to evaluate at exactly.
    pub fn dyadic_in(lo: &Rat, hi: &Rat) -> Rat {
        // Either order: a reversed pair would never find a level.
        let (lo, hi) = if lo <= hi { (lo, hi) } else { (hi, lo) };
        match (lo.dyadic_exponent(), hi.dyadic_exponent()) {
            (Some(kl), Some(kh)) => Rat::dyadic_in_short(lo, kl, hi, kh)
                .unwrap_or_else(|| Rat::dyadic_in_dyadic(lo, kl, hi, kh)),
            _ => Rat::dyadic_in_search(lo, hi),
        }
    }
    /// [`Rat::dyadic_in_dyadic`] in `i128` when both ends, brought to the
    /// common level `k <= 120`, fit (the usual case: ends of a refinement
    /// to `f64`'s resolution); the same point. `None` otherwise.
    fn dyadic_in_short(lo: &Rat, kl: u64, hi: &Rat, kh: u64) -> Option<Rat> {
        let k = kl.max(kh);
        if k > 120 {
            return None;
        }
        let (ln, hn) = (lo.num.to_i128()?, hi.num.to_i128()?);
        let (l, h) = (
            ln.checked_mul(1 << (k - kl))?,
            hn.checked_mul(1 << (k - kh))?,
        );
        if l <= 0 && h >= 0 {
            return Some(Rat::zero());
        }
        let (l, h, negative) = if h < 0 { (-h, -l, true) } else { (l, h, false) };
        // The highest bit where h and l − 1 differ (0 <= l − 1 < h).
        let good = u64::from(127 - (h ^ (l - 1)).leading_zeros());
        if good >= k {
            // ⌈lo⌉, as the general path: `>>` on i128 rounds down.
            return Some(Rat::from_int(Int::from_i128(-((-ln) >> kl))));
        }
        let m = (h >> good) << good;
        let m = if negative { -m } else { m };
        // In lowest terms: m·2^(−k) with the common twos stripped.
        let tz = u64::from(m.trailing_zeros()).min(k);
        Some(Rat {
            num: Int::from_i128(m >> tz),
            den: Int::one().shl(k - tz),
        })
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

/// The state of [`Rat::simplest_in`]'s descent on `0 < a/b <= c/d`: the
/// ends `[a, b, c, d]` left after the common prefix `t0, t1, …` of their
/// continued fractions, and the last two convergents `h1/k1`, `h2/k2` of
/// that prefix as `[h1, h2, k1, k2]`. Each level is
/// `simplest(x) = t + 1/simplest(d/(c − t·d), b/(a − t·b))` with
/// `t = ⌊a/b⌋`: both ends take the Euclidean step `(x, y) → (y, x − t·y)`
/// and swap roles, and the convergents `(h1, h2) → (t·h1 + h2, h1)`. The
/// descent stops where the expansions part: `a/b` is the integer `t`, or
/// `t + 1 <= c/d`; the answer is then `(s·h1 + h2)/(s·k1 + k2)` with `s`
/// that last term (`t`, or `t + 1`).
///
/// [`Descent::step`] takes one level exactly. The two faster routes take
/// the very same levels, so every route gives the same answer:
/// [`Descent::finish_short`] runs them in `i128` when the ends are short,
/// and [`Descent::batch`] proposes many levels from the ends' leading bits
/// and keeps them only once proven on the exact ends.
struct Descent {
    ends: [Int; 4],
    convergents: [Int; 4],
}

/// Ends of at most this many bits go to `i128` ([`Descent::finish_short`]);
/// [`Descent::batch`] reads this many leading bits of longer ones.
const SHORT_BITS: u64 = 124;

/// [`Descent::batch`] proposes levels while both truncated remainders keep
/// this many bits (their error grows with the convergents, which stay
/// below `2^(SHORT_BITS − LEHMER_FLOOR)`).
const LEHMER_FLOOR: u32 = 64;

/// One level of [`Descent`] on ends in `i128`.
enum Level {
    /// The expansions part here; the last term.
    Last(i128),
    /// A common term; the ends have taken its step.
    Term(i128),
}

/// One level of [`Descent::step`] on `[a, b, c, d]` in `i128` (`b > 0`);
/// `None` if `t·d` overflows (the truncated ends of [`Descent::batch`]
/// need not keep their order). `(t + 1)·d` overflowing means it exceeds
/// `c`.
fn short_level(ends: &mut [i128; 4]) -> Option<Level> {
    let [a, b, c, d] = *ends;
    let (t, r) = (a / b, a % b);
    let td = t.checked_mul(d)?;
    if r == 0 {
        return Some(Level::Last(t));
    }
    if td.checked_add(d).is_some_and(|x| x <= c) {
        return Some(Level::Last(t + 1));
    }
    *ends = [d, c - td, b, r];
    Some(Level::Term(t))
}

impl Descent {
    /// One level exactly; the answer if the expansions part here.
    fn step(&mut self) -> Option<Rat> {
        let [a, b, c, d] = &self.ends;
        let (t, r) = a.div_rem_trunc(b);
        // The last term: lo is an integer here, or the next integer fits below hi.
        let last = if r.is_zero() {
            Some(t.clone())
        } else {
            let t1 = &t + &Int::one();
            (&t1 * d <= *c).then_some(t1)
        };
        let [h1, h2, k1, k2] = &self.convergents;
        let term = last.as_ref().unwrap_or(&t);
        let h = &(term * h1) + h2;
        let k = &(term * k1) + k2;
        if last.is_some() {
            // Convergents are in lowest terms with k > 0.
            return Some(Rat { num: h, den: k });
        }
        // Recurse on (d/(c − t·d), b/(a − t·b)): note the swap of ends.
        let (nb, nd) = (c - &(&t * d), r);
        self.ends = [d.clone(), nb, b.clone(), nd];
        self.convergents = [h, h1.clone(), k, k1.clone()];
        None
    }

    /// The rest of the descent in `i128` when every end has at most
    /// [`SHORT_BITS`] bits: the levels' product `P = Π [[t, 1], [1, 0]]`
    /// and the last term `s` give `(h, k) = (h1, h2; k1, k2)·P·(s, 1)ᵀ`.
    /// `None` (nothing changed) for longer ends or if a product would
    /// overflow.
    fn finish_short(&self) -> Option<Rat> {
        if self.ends.iter().any(|x| x.bits() > SHORT_BITS) {
            return None;
        }
        let mut ends = self.ends.each_ref().map(|x| x.to_i128().expect("short"));
        // P, as its two columns' entries (p00, p01; p10, p11).
        let (mut p00, mut p01, mut p10, mut p11) = (1i128, 0i128, 0i128, 1i128);
        let (s0, s1) = loop {
            match short_level(&mut ends)? {
                // P·(s, 1)ᵀ.
                Level::Last(s) => {
                    break (
                        p00.checked_mul(s)?.checked_add(p01)?,
                        p10.checked_mul(s)?.checked_add(p11)?,
                    )
                }
                // P ← P·[[t, 1], [1, 0]].
                Level::Term(t) => {
                    (p00, p01) = (p00.checked_mul(t)?.checked_add(p01)?, p00);
                    (p10, p11) = (p10.checked_mul(t)?.checked_add(p11)?, p10);
                }
            }
        };
        let [h1, h2, k1, k2] = &self.convergents;
        let (s0, s1) = (Int::from_i128(s0), Int::from_i128(s1));
        Some(Rat {
            num: &(h1 * &s0) + &(h2 * &s1),
            den: &(k1 * &s0) + &(k2 * &s1),
        })
    }

    /// Many levels at once (Lehmer's idea) for long ends: the levels are
    /// proposed by running the descent on the ends' leading
    /// [`SHORT_BITS`] bits, then proven on the exact ends. With
    /// `E = Π [[0, 1], [1, −t]]` (the Euclidean steps) each exact pair
    /// becomes `E·(x, y)`; if both tails `x′/y′` exceed 1 (and every term
    /// after the first is at least 1), the proposed terms are the first
    /// terms of both expansions (a continued fraction with a tail above 1
    /// is unique), and no level among them ends the descent: the exact
    /// [`Descent::step`] would have taken the same ones. `false` (nothing
    /// changed) when nothing was proposed or proven.
    fn batch(&mut self) -> bool {
        let [a, b, c, d] = &self.ends;
        if a.bits().max(b.bits()).min(c.bits().max(d.bits())) <= SHORT_BITS {
            return false;
        }
        // Leading bits of each pair, shifted alike (the ratio is kept).
        let lead = |x: &Int, y: &Int| {
            let s = x.bits().max(y.bits()).saturating_sub(SHORT_BITS);
            (x.shr_floor(s).to_i128(), y.shr_floor(s).to_i128())
        };
        let ((Some(a), Some(b)), (Some(c), Some(d))) = (lead(a, b), lead(c, d)) else {
            return false;
        };
        let mut ends = [a, b, c, d];
        let mut terms: Vec<i128> = Vec::new();
        while ends[1] >> LEHMER_FLOOR > 0 && ends[3] >> LEHMER_FLOOR > 0 {
            match short_level(&mut ends) {
                Some(Level::Term(t)) if t > 0 || terms.is_empty() => terms.push(t),
                _ => break,
            }
        }
        // Prove the proposal, or its first half.
        while !terms.is_empty() {
            if self.apply(&terms) {
                return true;
            }
            terms.truncate(terms.len() / 2);
        }
        false
    }

    /// Takes the levels `terms` if proven on the exact ends
    /// ([`Descent::batch`]); `false` (nothing changed) if not.
    fn apply(&mut self, terms: &[i128]) -> bool {
        // E = Π [[0, 1], [1, −t]] (last level leftmost) and
        // P = Π [[t, 1], [1, 0]] (first level leftmost).
        let (mut e, mut p) = ([1i128, 0, 0, 1], [1i128, 0, 0, 1]);
        for &t in terms {
            // u − t·v and t·u + v, `None` on overflow.
            let sub = |u: i128, v: i128| t.checked_mul(v).and_then(|x| u.checked_sub(x));
            let add = |u: i128, v: i128| t.checked_mul(u).and_then(|x| x.checked_add(v));
            let (Some(e2), Some(e3), Some(p0), Some(p2)) = (
                sub(e[0], e[2]),
                sub(e[1], e[3]),
                add(p[0], p[1]),
                add(p[2], p[3]),
            ) else {
                return false;
            };
            e = [e[2], e[3], e2, e3];
            p = [p0, p[0], p2, p[2]];
        }
        let e = e.map(Int::from_i128);
        let tail = |x: &Int, y: &Int| {
            let x1 = &(&e[0] * x) + &(&e[1] * y);
            let y1 = &(&e[2] * x) + &(&e[3] * y);
            (y1.is_positive() && x1 > y1).then_some((x1, y1))
        };
        let [a, b, c, d] = &self.ends;
        let (Some((a1, b1)), Some((c1, d1))) = (tail(a, b), tail(c, d)) else {
            return false;
        };
        // Each level swaps the ends' roles.
        self.ends = if terms.len().is_multiple_of(2) {
            [a1, b1, c1, d1]
        } else {
            [c1, d1, a1, b1]
        };
        let p = p.map(Int::from_i128);
        let [h1, h2, k1, k2] = &self.convergents;
        self.convergents = [
            &(h1 * &p[0]) + &(h2 * &p[2]),
            &(h1 * &p[1]) + &(h2 * &p[3]),
            &(k1 * &p[0]) + &(k2 * &p[2]),
            &(k1 * &p[1]) + &(k2 * &p[3]),
        ];
        true
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
        /// The `i128` path picks the general path's point: ends of up to
        /// 100 bits at levels up to 130 (past the `i128` bound), either
        /// sign, apart or nearly equal.
        #[test]
        fn dyadic_in_short_is_the_general_path(
            a in any::<i64>(), a_hi in -(1i64 << 36)..(1i64 << 36), ka in 0u64..130,
            w in any::<u64>(), kw in 0u64..130, near in any::<bool>(),
        ) {
            let lo = Rat::dyadic(&Int::from(a_hi).shl(64) + &Int::from(a), ka);
            let w = Rat::dyadic(Int::from(w), if near { kw + 60 } else { kw });
            let hi = &lo + &w;
            let (kl, kh) = (lo.dyadic_exponent().unwrap(), hi.dyadic_exponent().unwrap());
            if let Some(short) = Rat::dyadic_in_short(&lo, kl, &hi, kh) {
                prop_assert_eq!(short, Rat::dyadic_in_dyadic(&lo, kl, &hi, kh));
            }
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

    /// The descent one exact level at a time (the implementation before
    /// [`Descent::finish_short`] and [`Descent::batch`]): the reference
    /// the faster routes must agree with.
    fn simplest_by_single_levels(lo: &Rat, hi: &Rat) -> Rat {
        Rat::simplest_by(lo, hi, false)
    }

    /// A rational with a numerator and a denominator of up to `limbs`
    /// 64-bit digits.
    fn long_rat(limbs: usize) -> impl Strategy<Value = Rat> {
        (
            any::<bool>(),
            proptest::collection::vec(any::<u64>(), 1..=limbs),
            proptest::collection::vec(any::<u64>(), 1..=limbs),
        )
            .prop_filter_map("a zero denominator", |(neg, n, d)| {
                Rat::new(Int::from_u64_limbs(neg, &n), Int::from_u64_limbs(false, &d))
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(2000))]
        /// Short, long and very long ends, apart or sharing a long prefix of
        /// their expansions (`hi = lo + w·2^(−shift)`): the batched descent
        /// gives the single levels' answer.
        #[test]
        fn batched_descent_is_the_single_levels(
            lo in long_rat(30),
            w in long_rat(3),
            shift in 0i64..3000,
        ) {
            let hi = &lo + &w.abs().mul_pow2(-shift);
            prop_assert_eq!(Rat::simplest_in(&lo, &hi), simplest_by_single_levels(&lo, &hi));
        }

        /// Long ends around a rational `p/q` (a root the refinement may
        /// meet): the descent ends inside a batch's reach, at `p/q` when
        /// the interval is narrower than `1/q²`, else earlier.
        #[test]
        fn batched_descent_stops_where_the_expansions_part(
            x in long_rat(4),
            below in long_rat(2),
            above in long_rat(2),
            shift in 0i64..2000,
            end in 0u8..3,
        ) {
            // `p/q` strictly inside, or at one end.
            let (lo, hi) = (
                if end == 1 { x.clone() } else { &x - &below.abs().mul_pow2(-shift) },
                if end == 2 { x.clone() } else { &x + &above.abs().mul_pow2(-shift) },
            );
            let s = Rat::simplest_in(&lo, &hi);
            prop_assert_eq!(&s, &simplest_by_single_levels(&lo, &hi));
            prop_assert!(lo <= s && s <= hi);
            let q = x.denom().bits() as i64;
            let w = &hi - &lo;
            if (w.numer().bits() as i64) - (w.denom().bits() as i64) < -2 * q - 2 {
                prop_assert_eq!(s, x);
            }
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
