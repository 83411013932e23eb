//! [`Local`]: an explicit polynomial re-centred at a short dyadic `c`,
//! `q(c + y) = Σ_k T_k·y^k` with `T_k = q^(k)(c)/k!` exact, so that its sign
//! and jet at points next to `c` cost one multi-precision Horner pass over
//! numbers far shorter than an exact pass over `q`'s own coefficients.
//!
//! Next to a tight cluster of roots the power-basis coefficients of `q`
//! cancel by tens of thousands of bits: an interval Horner pass over them
//! needed 16,000 to 262,144 bits there (docs/table4.md, session 15), so the
//! exact pass was cheaper. In the local basis the terms `T_k·y^k` are
//! about as large as the values of `q` around `c`, and cancel only by
//! about as many bits as the point is closer to a root than `c` is. The
//! identity is exact (a Taylor shift), so no remainder is bounded: every
//! enclosure is Horner's scheme in outward-rounded intervals.

use crate::model::ball_horner;
use ccd_arith::{BigInterval, Dual, Dyadic, Int, Rat};
use ccd_poly::ZPoly;

/// The cost of an exact evaluation (coefficients times the bits of
/// Horner's partial sums, `(n + 1)·(bits q + n·bits x)`) from which a
/// re-centred model is tried first. The seed-73 fuzz find (degree 96,
/// 80,000-bit coefficients, 5,000-bit points) is at 5·10^7, the slow
/// regression `affine-degree4-entry-1e-301` at 4·10^6 (degree 59, 8,000
/// bits, 1,000-bit points). No shipped scene reaches it: their largest,
/// `ratio-needle-k0064-overlap`, is at 2.9·10^5, and there a lower
/// threshold costs more than it saves (110M → 142M instructions at
/// `2^17`: a short polynomial's exact pass is cheap).
pub const LOCAL_WORTH: u64 = 1 << 21;

/// The first precision at which a re-centred model is asked for a sign.
const FIRST_BITS: u32 = 128;

/// `q` around the dyadic centre `c = a/2^e`: `T_k = q^(k)(c)/k!`, exact.
#[derive(Clone, Debug)]
pub(crate) struct Local {
    centre: Rat,
    terms: Vec<Dyadic>,
}

impl Local {
    /// The model of `q` at the dyadic `centre` (one Taylor shift: `n²/2`
    /// products by `a`): `2^(e·n)·q(c + y) = Σ_k r_k·y^k`, so
    /// `T_k = r_k·2^(−e·n)`. `None` for a centre that is not dyadic, or
    /// a zero `q`.
    pub(crate) fn new(q: &ZPoly, centre: Rat) -> Option<Local> {
        let e = centre.dyadic_exponent()? as i64;
        let n = q.degree()? as i64;
        let shifted = q.compose_affine_multiple(&centre, &Rat::one());
        let terms = shifted
            .coeffs()
            .iter()
            .map(|r| Dyadic {
                m: r.clone(),
                e: -e * n,
            })
            .collect();
        Some(Local { centre, terms })
    }

    /// The model of `q` next to `[lo, hi]`, a dyadic interval (or point)
    /// `2^(−k)` wide or with `k`-bit ends: centred at the shortest dyadic
    /// within `2^(−k/2)` of it, about half as long as the points (the
    /// Taylor shift's cost grows with the square of the centre's bits, and
    /// the local basis's cancellation only with the bits from the centre
    /// to the points).
    pub(crate) fn near(q: &ZPoly, lo: &Rat, hi: &Rat, k: u64) -> Option<Local> {
        let slack = Rat::dyadic(Int::one(), k / 2);
        Local::new(q, Rat::dyadic_in(&(lo - &slack), &(hi + &slack)))
    }

    /// Horner's scheme over the `T_k` rounded to `y`'s precision, at `y`
    /// (value and derivative).
    fn horner(&self, y: &BigInterval) -> Dual<BigInterval> {
        let terms: Vec<BigInterval> = self
            .terms
            .iter()
            .map(|t| BigInterval::new(t.clone(), t.clone(), y.prec))
            .collect();
        ball_horner(&terms, y)
    }

    /// Enclosures of `q(x)` and `q′(x)` in intervals of `prec` bits, at
    /// `y = x − c` (exact for a dyadic `x`, rounded outward otherwise).
    pub(crate) fn jet(&self, x: &Rat, prec: u32) -> (BigInterval, BigInterval) {
        let jet = self.horner(&BigInterval::from_rat(&(x - &self.centre), prec));
        (jet.v, jet.d)
    }

    /// The sign of `q(x)` when an enclosure at one of `precisions` excludes
    /// zero.
    pub(crate) fn sign(&self, x: &Rat, precisions: impl IntoIterator<Item = u32>) -> Option<i32> {
        precisions
            .into_iter()
            .find_map(|prec| self.jet(x, prec).0.sign().filter(|s| *s != 0))
    }

    /// The sign of `q` over `[lo, hi]` when an enclosure at one of
    /// `precisions` excludes zero: Horner's scheme on `[lo − c, hi − c]`
    /// (outward-rounded ends).
    pub(crate) fn sign_over(
        &self,
        lo: &Rat,
        hi: &Rat,
        precisions: impl IntoIterator<Item = u32>,
    ) -> Option<i32> {
        precisions.into_iter().find_map(|prec| {
            let y = BigInterval::from_rat(&(lo - &self.centre), prec)
                .hull(&BigInterval::from_rat(&(hi - &self.centre), prec));
            self.horner(&y).v.sign().filter(|s| *s != 0)
        })
    }

    /// Whether `q` is proven to change sign between `lo` and `hi` (then it
    /// has a root in between, and no test can show it has none).
    pub(crate) fn changes_sign(
        &self,
        lo: &Rat,
        hi: &Rat,
        precisions: impl IntoIterator<Item = u32> + Clone,
    ) -> bool {
        matches!(
            (self.sign(lo, precisions.clone()), self.sign(hi, precisions)),
            (Some(a), Some(b)) if a != b
        )
    }
}

/// The size of an exact evaluation of a polynomial of degree `n` and
/// coefficients of up to `bits` bits (formed once per polynomial: its
/// costly points are asked for often).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Cost {
    n: u64,
    bits: u64,
}

impl Cost {
    /// `q`'s.
    pub(crate) fn of(q: &ZPoly) -> Cost {
        Cost {
            n: q.degree().unwrap_or(0) as u64,
            bits: q.max_bits(),
        }
    }

    /// The bits of Horner's last partial sums at a point of `x`'s length
    /// (`bits q + n·bits x`).
    fn size(self, x: &Rat) -> u64 {
        let x_bits = x.numer().bits().max(x.denom().bits());
        self.bits.saturating_add(self.n.saturating_mul(x_bits))
    }

    /// Whether the exact evaluation at a point of `x`'s length costs
    /// [`LOCAL_WORTH`] or more (`n + 1` partial sums of that size).
    pub(crate) fn costly(self, x: &Rat) -> bool {
        (self.n + 1).saturating_mul(self.size(x)) >= LOCAL_WORTH
    }

    /// The precisions at which a re-centred model is asked about a point
    /// of `x`'s length, from `first`: four times more each try, while an
    /// interval product costs less than the exact pass's (an eighth of its
    /// numbers' bits, but at least 512).
    pub(crate) fn ladder(self, x: &Rat, first: u32) -> impl Iterator<Item = u32> + Clone {
        let cap = (self.size(x) / 8).clamp(512, u32::MAX as u64) as u32;
        // Never 0 (exact intervals): a ladder that cannot climb.
        std::iter::successors(Some(first.clamp(1, cap)), move |&p| {
            p.checked_mul(4).filter(|&next| next <= cap)
        })
    }

    /// [`Cost::ladder`] from the first precision of a sign.
    pub(crate) fn sign_ladder(self, x: &Rat) -> impl Iterator<Item = u32> + Clone {
        self.ladder(x, FIRST_BITS)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn contains(i: &BigInterval, x: &Rat) -> bool {
        &i.lo_rat() <= x && x <= &i.hi_rat()
    }

    /// (t − a)(t − a − δ)·(t² + 1)·(t − 1/3)^2 with a tight pair at a: the
    /// model at a point next to the pair decides signs the power basis
    /// cancels over.
    fn clustered(a: &Rat, delta: &Rat) -> ZPoly {
        let lin = |r: &Rat| ZPoly::new(vec![-r.numer().clone(), r.denom().clone()]);
        let third = ZPoly::from_i64s(&[-1, 3]);
        &(&(&lin(a) * &lin(&(a + delta))) * &ZPoly::from_i64s(&[1, 0, 1])) * &(&third * &third)
    }

    #[test]
    fn decides_signs_between_a_tight_pair() {
        let a = Rat::dyadic(Int::from(0x1234_5678_9abc_i64), 47);
        let delta = Rat::dyadic(Int::one(), 2000);
        let q = clustered(&a, &delta);
        let local = Local::new(&q, a.clone()).expect("a dyadic centre");
        // Between the two roots, below and above them.
        let inside = &a + &delta.mul_pow2(-1);
        let below = &a - &delta;
        let above = &a + &delta.mul_pow2(1);
        for x in [&inside, &below, &above] {
            assert_eq!(local.sign(x, [128]), Some(q.sign_at(x)));
        }
        assert_eq!(q.sign_at(&inside), -q.sign_at(&below));
        // Horner's scheme over q's own coefficients cancels by some 4,000
        // bits there: 1,024 are not enough.
        let prec = 1024;
        let coeffs: Vec<BigInterval> = q
            .coeffs()
            .iter()
            .map(|c| BigInterval::new(Dyadic::from_int(c), Dyadic::from_int(c), prec))
            .collect();
        let power = ball_horner(&coeffs, &BigInterval::from_rat(&inside, prec)).v;
        assert!(power.contains_zero());
        // Over an interval next to the pair, and across one of its roots.
        let (lo, hi) = (&a + &delta.mul_pow2(2), &a + &delta.mul_pow2(3));
        assert_eq!(local.sign_over(&lo, &hi, [128]), Some(q.sign_at(&lo)));
        assert_eq!(local.sign_over(&below, &inside, [128, 4096]), None);
        assert!(local.changes_sign(&below, &inside, [128]));
        assert!(!local.changes_sign(&lo, &hi, [128]));
    }

    /// A random polynomial with coefficients of up to ~460 bits, a centre
    /// and a point or an interval at any distance from it (up to 1).
    fn case() -> impl Strategy<Value = (ZPoly, Rat, Rat, Rat)> {
        (
            prop::collection::vec(any::<i64>(), 1..14),
            0u64..400,
            any::<i32>(),
            (any::<i32>(), 1u64..300),
            (1u32..u32::MAX, 0u64..200),
        )
            .prop_map(|(coeffs, scale, centre, (offset, far), (width, narrow))| {
                let q = ZPoly::new(coeffs.iter().map(|&v| Int::from(v).shl(scale)).collect());
                let c = Rat::dyadic(Int::from(centre), 31);
                let x = &c + &Rat::dyadic(Int::from(offset), 31 + far);
                let w = Rat::dyadic(Int::from(width as i64), 63 + far + narrow);
                (q, c, x, w)
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The jet encloses the exact value and slope, at dyadic points and
        /// at rational ones; every sign it gives is the exact one.
        #[test]
        fn jets_enclose_the_exact_values((q, c, x, w) in case(), prec in 64u32..400) {
            prop_assume!(!q.is_zero());
            let local = Local::new(&q, c).expect("a dyadic centre");
            for x in [x.clone(), &x + &(&w / &Rat::from(3))] {
                let (v, s) = local.jet(&x, prec);
                prop_assert!(contains(&v, &q.eval_rat(&x)));
                prop_assert!(contains(&s, &q.derivative().eval_rat(&x)));
                if let Some(sign) = local.sign(&x, [prec]) {
                    prop_assert_eq!(sign, q.sign_at(&x));
                }
            }
        }

        /// A sign over an interval is the exact sign at its ends and
        /// inside.
        #[test]
        fn signs_over_intervals_are_exact((q, c, lo, w) in case(), prec in 64u32..400) {
            prop_assume!(!q.is_zero());
            let local = Local::new(&q, c).expect("a dyadic centre");
            let hi = &lo + &w;
            if let Some(sign) = local.sign_over(&lo, &hi, [prec]) {
                for x in [&lo, &hi, &(&lo + &(&w / &Rat::from(3)))] {
                    prop_assert_eq!(q.sign_at(x), sign);
                }
            }
        }

        /// `g·(t − r)` with `g > 0` near the interval and a simple root `r`
        /// inside it: the sign change is proven, and Descartes' test over
        /// the interval (which the change lets `RealRoot::sign_with` skip)
        /// could not have decided; none is claimed for `g` alone.
        #[test]
        fn sign_changes_are_roots((g, c, lo, w) in case(), prec in 64u32..400) {
            // g + 1 + Σ|g_i|·2^i > 0 on [−2, 2], where the interval lies.
            let margin = g.coeffs().iter().enumerate().fold(Int::one(), |acc, (i, gi)| {
                &acc + &gi.abs().shl(i as u64)
            });
            let g = &g + &ZPoly::new(vec![margin]);
            let hi = &lo + &w;
            let r = &lo + &(&w / &Rat::from(3));
            let q = &g * &ZPoly::new(vec![-r.numer().clone(), r.denom().clone()]);
            let ladder = [prec, 4 * prec, 16 * prec, 64 * prec];
            let local = Local::new(&q, c.clone()).expect("a dyadic centre");
            prop_assert!(local.changes_sign(&lo, &hi, ladder));
            prop_assert_eq!(crate::root::descartes(&q, &lo, &hi), None);
            let positive = Local::new(&g, c).expect("a dyadic centre");
            prop_assert!(!positive.changes_sign(&lo, &hi, ladder));
        }
    }
}
