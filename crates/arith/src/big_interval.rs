//! [`BigInterval`]: closed intervals with dyadic endpoints `m·2^e` rounded
//! outward to a chosen number of significant bits — the escalation type
//! used when an `f64` [`Interval`](crate::Interval) is too wide to
//! decide a sign or to reach the requested width of an enclosure.
//!
//! Every operation computes the exact dyadic result of the endpoint
//! formulas (sums and products of dyadics are dyadic) and then rounds the
//! lower end down and the upper end up to `prec` significant bits, so the
//! result contains the exact result for any points of the operands.
//! Divisions (by small integers, or by an interval excluding zero) round
//! the quotients of the endpoints outward in the same way. `prec == 0`
//! marks an exact value (small constants): no rounding at all; a binary
//! operation works at the larger precision of its operands.

use crate::{Dyadic, Int, Rat, RingOps};
use std::cmp::Ordering;

/// Precision used for divisions of exact (`prec == 0`) operands.
const DEFAULT_DIVISION_BITS: u32 = 64;

/// A closed interval `[lo, hi]` with dyadic ends kept to `prec` significant
/// bits by outward rounding (`prec == 0`: exact, never rounded).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BigInterval {
    /// Lower end.
    pub lo: Dyadic,
    /// Upper end.
    pub hi: Dyadic,
    /// Significant bits kept (0: exact).
    pub prec: u32,
}

fn min_d(a: Dyadic, b: Dyadic) -> Dyadic {
    if a.cmp_value(&b) == Ordering::Greater {
        b
    } else {
        a
    }
}
fn max_d(a: Dyadic, b: Dyadic) -> Dyadic {
    if a.cmp_value(&b) == Ordering::Less {
        b
    } else {
        a
    }
}

impl BigInterval {
    /// The exact point `x` (never rounded).
    pub fn point(x: Dyadic) -> BigInterval {
        BigInterval {
            lo: x.clone(),
            hi: x,
            prec: 0,
        }
    }
    /// `[lo, hi]` rounded outward to `prec` bits.
    pub fn new(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
        BigInterval {
            lo: lo.round(prec, false),
            hi: hi.round(prec, true),
            prec,
        }
    }
    /// The same interval, kept from now on to `prec` bits (rounded outward).
    pub fn with_prec(&self, prec: u32) -> BigInterval {
        BigInterval::new(self.lo.clone(), self.hi.clone(), prec)
    }
    /// An enclosure of the rational `q` with `prec` bits (exact when `q` is
    /// dyadic).
    pub fn from_rat(q: &Rat, prec: u32) -> BigInterval {
        if let Some(d) = Dyadic::from_rat_exact(q) {
            let mut p = BigInterval::point(d);
            p.prec = prec;
            return p;
        }
        let bits = prec.max(DEFAULT_DIVISION_BITS);
        let s = bits as i64 + 2 + q.denom().bits() as i64 - q.numer().bits() as i64;
        BigInterval {
            lo: Dyadic::quotient(q.numer(), q.denom(), s, false),
            hi: Dyadic::quotient(q.numer(), q.denom(), s, true),
            prec,
        }
    }
    /// An enclosure of `√q` for a rational `q >= 0`, to about `prec` bits.
    pub fn sqrt_rat(q: &Rat, prec: u32) -> BigInterval {
        let bits = prec.max(DEFAULT_DIVISION_BITS) as i64 + 4;
        // √q = √(n·d)/d; with N = ⌊n·d·4^k⌋, √q ∈ [isqrt(N), isqrt(N) + 1] / (d·2^k).
        let nd = q.numer() * q.denom();
        let k = (bits - nd.bits() as i64 / 2 + q.denom().bits() as i64).max(0);
        let big = nd.shl(2 * k as u64);
        let s = isqrt(&big);
        let exact = &s * &s == big;
        let den = q.denom().shl(k as u64);
        let lo = Dyadic::div(
            &Dyadic::from_int(&s),
            &Dyadic::from_int(&den),
            bits as u32,
            false,
        );
        let top = if exact { s } else { s + Int::one() };
        let hi = Dyadic::div(
            &Dyadic::from_int(&top),
            &Dyadic::from_int(&den),
            bits as u32,
            true,
        );
        BigInterval::new(lo, hi, prec)
    }
    /// Lower end as a rational.
    pub fn lo_rat(&self) -> Rat {
        self.lo.to_rat()
    }
    /// Upper end as a rational.
    pub fn hi_rat(&self) -> Rat {
        self.hi.to_rat()
    }
    /// Sign of every point: `Some(±1)`, `Some(0)` for the point zero, `None`
    /// when undecided.
    pub fn sign(&self) -> Option<i32> {
        if self.lo.signum() > 0 {
            Some(1)
        } else if self.hi.signum() < 0 {
            Some(-1)
        } else if self.lo.signum() == 0 && self.hi.signum() == 0 {
            Some(0)
        } else {
            None
        }
    }
    /// `lo <= 0 <= hi`.
    pub fn contains_zero(&self) -> bool {
        self.lo.signum() <= 0 && self.hi.signum() >= 0
    }
    /// Smallest interval holding both.
    pub fn hull(&self, o: &BigInterval) -> BigInterval {
        BigInterval {
            lo: min_d(self.lo.clone(), o.lo.clone()),
            hi: max_d(self.hi.clone(), o.hi.clone()),
            prec: self.prec.max(o.prec),
        }
    }
    /// The common part, if any.
    pub fn intersect(&self, o: &BigInterval) -> Option<BigInterval> {
        let lo = max_d(self.lo.clone(), o.lo.clone());
        let hi = min_d(self.hi.clone(), o.hi.clone());
        (lo.cmp_value(&hi) != Ordering::Greater).then(|| BigInterval {
            lo,
            hi,
            prec: self.prec.max(o.prec),
        })
    }
    /// `self ⊂ interior(o)`.
    pub fn strictly_inside(&self, o: &BigInterval) -> bool {
        self.lo.cmp_value(&o.lo) == Ordering::Greater && self.hi.cmp_value(&o.hi) == Ordering::Less
    }
    /// The exact midpoint (never rounded, so it always lies in the
    /// interval, as interval Newton requires), as a point carrying this
    /// precision.
    pub fn midpoint(&self) -> BigInterval {
        let s = self.lo.add(&self.hi);
        let mut p = BigInterval::point(Dyadic { m: s.m, e: s.e - 1 });
        p.prec = self.prec;
        p
    }
    /// `self / o` for an interval `o` that excludes zero (`None` otherwise).
    pub fn div(&self, o: &BigInterval) -> Option<BigInterval> {
        if o.contains_zero() {
            return None;
        }
        let prec = self.prec.max(o.prec).max(DEFAULT_DIVISION_BITS);
        let ends = [
            (&self.lo, &o.lo),
            (&self.lo, &o.hi),
            (&self.hi, &o.lo),
            (&self.hi, &o.hi),
        ];
        let lo = ends
            .iter()
            .map(|(a, b)| Dyadic::div(a, b, prec, false))
            .reduce(min_d)?;
        let hi = ends
            .iter()
            .map(|(a, b)| Dyadic::div(a, b, prec, true))
            .reduce(max_d)?;
        Some(BigInterval {
            lo,
            hi,
            prec: self.prec.max(o.prec),
        })
    }
    /// `self · 2^k`, exact (the ends' exponents move by `k`).
    pub fn mul_pow2(&self, k: i64) -> BigInterval {
        let shift = |d: &Dyadic| Dyadic {
            m: d.m.clone(),
            e: d.e + k,
        };
        BigInterval {
            lo: shift(&self.lo),
            hi: shift(&self.hi),
            prec: self.prec,
        }
    }
    /// A nearby `f64` of the midpoint (not certified).
    pub fn approx(&self) -> f64 {
        0.5 * (self.lo.to_f64() + self.hi.to_f64())
    }
    /// `hi − lo`, approximately.
    pub fn width_f64(&self) -> f64 {
        self.hi.sub(&self.lo).to_f64()
    }
    fn from_ends(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
        BigInterval::new(lo, hi, prec)
    }
}

/// The sign of an interval's points, for the case analysis of products.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Signs {
    /// `lo >= 0`.
    NonNegative,
    /// `hi <= 0` (and `lo < 0`).
    NonPositive,
    /// `lo < 0 < hi`.
    Mixed,
}

impl Signs {
    fn of(x: &BigInterval) -> Signs {
        if x.lo.signum() >= 0 {
            Signs::NonNegative
        } else if x.hi.signum() <= 0 {
            Signs::NonPositive
        } else {
            Signs::Mixed
        }
    }
}

/// The factors of the end product `cᵢ` of `a·b`, in the order
/// `c = [a₀b₀, a₀b₁, a₁b₀, a₁b₁]` (`a = [a₀, a₁]`, `b = [b₀, b₁]`).
fn factors<'x>(a: &'x BigInterval, b: &'x BigInterval, i: usize) -> (&'x Dyadic, &'x Dyadic) {
    let x = if i < 2 { &a.lo } else { &a.hi };
    let y = if i & 1 == 0 { &b.lo } else { &b.hi };
    (x, y)
}

/// Which of the end products `c = [a₀b₀, a₀b₁, a₁b₀, a₁b₁]` of `a·b`
/// (`a = [a₀, a₁]`, `b = [b₀, b₁]`) can be the first smallest or the first
/// largest of the four.
///
/// * A point factor (both ends the same dyadic, digit for digit) repeats
///   products: `c₂ = c₀` and `c₃ = c₁` when `a₀ = a₁`, so `c₀, c₁` hold
///   every value first; `c₁ = c₀`, `c₃ = c₂` when `b₀ = b₁`.
/// * Otherwise, for `a₀ <= a₁` and `b₀ <= b₁`, the classical analysis by
///   the signs of the factors names the product holding the minimum and
///   the one holding the maximum (all four when both factors straddle 0).
///   Another product can hold one of those values only in a tie, and then
///   it must be formed since it comes first when its index is smaller. A
///   product sharing a factor `f` with a named one ties with it iff
///   `f = 0` or the other factor's ends are equal; a product sharing none
///   with a named one (`c₀` against `c₃`, `c₁` against `c₂`, when the named
///   pair is a row or a column) can tie with it only when both are 0,
///   which forces the factor of known sign to be `[0, 0]` (the other one
///   straddles 0 strictly), so the test against the named product it
///   shares a factor with fires too.
/// * Reversed ends (`lo > hi`) fall back to all four.
fn product_candidates(a: &BigInterval, b: &BigInterval) -> [bool; 4] {
    if a.lo == a.hi {
        return [true, b.lo != b.hi, false, false];
    }
    if b.lo == b.hi {
        return [true, false, true, false];
    }
    let (oa, ob) = (a.lo.cmp_value(&a.hi), b.lo.cmp_value(&b.hi));
    if oa == Ordering::Greater || ob == Ordering::Greater {
        return [true; 4];
    }
    use Signs::*;
    // The minimum's product and the maximum's.
    let named = match (Signs::of(a), Signs::of(b)) {
        (Mixed, Mixed) => return [true; 4],
        (NonNegative, NonNegative) => [0, 3],
        (NonNegative, NonPositive) => [2, 1],
        (NonPositive, NonNegative) => [1, 2],
        (NonPositive, NonPositive) => [3, 0],
        (NonNegative, Mixed) => [2, 3],
        (NonPositive, Mixed) => [1, 0],
        (Mixed, NonNegative) => [1, 3],
        (Mixed, NonPositive) => [2, 0],
    };
    let ties = |j: usize, k: usize| {
        if j / 2 == k / 2 {
            factors(a, b, j).0.signum() == 0 || ob == Ordering::Equal
        } else if j % 2 == k % 2 {
            factors(a, b, j).1.signum() == 0 || oa == Ordering::Equal
        } else {
            false
        }
    };
    std::array::from_fn(|j| named.iter().any(|&k| k == j || ties(j, k)))
}

/// The first smallest and the first largest of the present values, in the
/// order given (a later value replaces the current one only when strictly
/// smaller, resp. larger), moved out of the array (cloned only when one
/// value is both).
fn first_extremes(mut c: [Option<Dyadic>; 4]) -> (Dyadic, Dyadic) {
    let (mut lo, mut hi): (Option<usize>, Option<usize>) = (None, None);
    for i in 0..c.len() {
        let Some(x) = &c[i] else { continue };
        let beats = |best: Option<usize>, wanted: Ordering| match best.and_then(|b| c[b].as_ref()) {
            Some(b) => b.cmp_value(x) == wanted.reverse(),
            None => true,
        };
        if beats(lo, Ordering::Less) {
            lo = Some(i);
        }
        if beats(hi, Ordering::Greater) {
            hi = Some(i);
        }
    }
    let (Some(lo), Some(hi)) = (lo, hi) else {
        return (Dyadic::zero(), Dyadic::zero());
    };
    let high = if lo == hi {
        c[hi].clone()
    } else {
        c[hi].take()
    };
    let low = c[lo].take();
    (
        low.unwrap_or_else(Dyadic::zero),
        high.unwrap_or_else(Dyadic::zero),
    )
}

/// `⌊√n⌋` for `n >= 0` (Newton's iteration on integers).
fn isqrt(n: &Int) -> Int {
    if n.signum() <= 0 {
        return Int::zero();
    }
    let mut x = Int::one().shl(n.bits().div_ceil(2));
    loop {
        let y = (&x + &n.div_floor(&x)).shr_floor(1);
        if y >= x {
            return x;
        }
        x = y;
    }
}

impl RingOps for BigInterval {
    fn zero() -> Self {
        BigInterval::point(Dyadic::zero())
    }
    fn one() -> Self {
        BigInterval::point(Dyadic::from_int(&Int::one()))
    }
    fn from_i64(v: i64) -> Self {
        BigInterval::point(Dyadic::from_int(&Int::from_i64(v)))
    }
    fn is_zero(&self) -> bool {
        self.lo.signum() == 0 && self.hi.signum() == 0
    }
    fn plus(&self, o: &Self) -> Self {
        BigInterval::from_ends(
            self.lo.add(&o.lo),
            self.hi.add(&o.hi),
            self.prec.max(o.prec),
        )
    }
    fn minus(&self, o: &Self) -> Self {
        BigInterval::from_ends(
            self.lo.sub(&o.hi),
            self.hi.sub(&o.lo),
            self.prec.max(o.prec),
        )
    }
    /// The smallest and the largest of the end products
    /// `c = [a₀b₀, a₀b₁, a₁b₀, a₁b₁]`, each the first one holding its value
    /// (ties go to the earlier product, as a left-to-right reduction with
    /// strict comparisons keeps them), rounded outward. Only the products
    /// that `product_candidates` cannot rule out are formed: two for
    /// intervals of known sign, as in the classical case analysis.
    fn times(&self, o: &Self) -> Self {
        let prec = self.prec.max(o.prec);
        let mut c: [Option<Dyadic>; 4] = Default::default();
        for (i, (slot, needed)) in c.iter_mut().zip(product_candidates(self, o)).enumerate() {
            if needed {
                let (a, b) = factors(self, o, i);
                *slot = Some(a.mul(b));
            }
        }
        let (lo, hi) = first_extremes(c);
        BigInterval::from_ends(lo, hi, prec)
    }
    fn negated(&self) -> Self {
        BigInterval {
            lo: self.hi.neg(),
            hi: self.lo.neg(),
            prec: self.prec,
        }
    }
    fn div_small(&self, k: i64) -> Self {
        // `k ≠ 0` is the trait's contract, so the division always exists.
        let d = BigInterval::from_i64(k);
        self.div(&d).unwrap_or_else(|| self.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn contains(i: &BigInterval, x: &Rat) -> bool {
        &i.lo_rat() <= x && x <= &i.hi_rat()
    }

    #[test]
    fn sqrt_encloses() {
        for (n, d) in [(2i64, 1i64), (1, 3), (49, 4), (10_000_000_019, 7)] {
            let q = Rat::from_frac(n, d);
            let s = BigInterval::sqrt_rat(&q, 100);
            let (lo, hi) = (s.lo_rat(), s.hi_rat());
            assert!(&lo * &lo <= q && q <= &hi * &hi, "{n}/{d}");
            assert!(s.width_f64() < 1e-25 * (n as f64 / d as f64).sqrt().max(1.0));
        }
        let exact = BigInterval::sqrt_rat(&Rat::from_frac(9, 4), 80);
        assert_eq!(exact.lo_rat(), Rat::from_frac(3, 2));
        assert_eq!(exact.hi_rat(), Rat::from_frac(3, 2));
    }

    /// The kernel as it was before the allocation-free routines, kept as
    /// the reference they must match digit for digit (mantissa and
    /// exponent, not only the value).
    mod reference {
        use super::super::{BigInterval, Dyadic};
        use crate::Int;
        use std::cmp::Ordering;

        fn aligned(a: &Dyadic, o: &Dyadic) -> (Int, Int, i64) {
            if a.m.is_zero() {
                return (Int::zero(), o.m.clone(), o.e);
            }
            if o.m.is_zero() {
                return (a.m.clone(), Int::zero(), a.e);
            }
            let e = a.e.min(o.e);
            (a.m.shl((a.e - e) as u64), o.m.shl((o.e - e) as u64), e)
        }
        pub fn add(a: &Dyadic, o: &Dyadic) -> Dyadic {
            let (x, y, e) = aligned(a, o);
            Dyadic { m: x + y, e }
        }
        pub fn sub(a: &Dyadic, o: &Dyadic) -> Dyadic {
            let (x, y, e) = aligned(a, o);
            Dyadic { m: x - y, e }
        }
        pub fn cmp(a: &Dyadic, o: &Dyadic) -> Ordering {
            let (x, y, _) = aligned(a, o);
            x.cmp(&y)
        }
        pub fn round(d: Dyadic, prec: u32, up: bool) -> Dyadic {
            if prec == 0 || d.m.bits() <= prec as u64 {
                return d;
            }
            let s = d.m.bits() - prec as u64;
            let m = if up {
                -(-&d.m).shr_floor(s)
            } else {
                d.m.shr_floor(s)
            };
            Dyadic {
                m,
                e: d.e + s as i64,
            }
        }
        fn min_d(a: Dyadic, b: Dyadic) -> Dyadic {
            if cmp(&a, &b) == Ordering::Greater {
                b
            } else {
                a
            }
        }
        fn max_d(a: Dyadic, b: Dyadic) -> Dyadic {
            if cmp(&a, &b) == Ordering::Less {
                b
            } else {
                a
            }
        }
        pub fn new(lo: Dyadic, hi: Dyadic, prec: u32) -> BigInterval {
            BigInterval {
                lo: round(lo, prec, false),
                hi: round(hi, prec, true),
                prec,
            }
        }
        pub fn plus(a: &BigInterval, o: &BigInterval) -> BigInterval {
            new(add(&a.lo, &o.lo), add(&a.hi, &o.hi), a.prec.max(o.prec))
        }
        pub fn minus(a: &BigInterval, o: &BigInterval) -> BigInterval {
            new(sub(&a.lo, &o.hi), sub(&a.hi, &o.lo), a.prec.max(o.prec))
        }
        pub fn times(a: &BigInterval, o: &BigInterval) -> BigInterval {
            let c = [
                a.lo.mul(&o.lo),
                a.lo.mul(&o.hi),
                a.hi.mul(&o.lo),
                a.hi.mul(&o.hi),
            ];
            let lo = c.iter().cloned().reduce(min_d).expect("four");
            let hi = c.into_iter().reduce(max_d).expect("four");
            new(lo, hi, a.prec.max(o.prec))
        }
        pub fn hull(a: &BigInterval, o: &BigInterval) -> BigInterval {
            BigInterval {
                lo: min_d(a.lo.clone(), o.lo.clone()),
                hi: max_d(a.hi.clone(), o.hi.clone()),
                prec: a.prec.max(o.prec),
            }
        }
        pub fn intersect(a: &BigInterval, o: &BigInterval) -> Option<BigInterval> {
            let lo = max_d(a.lo.clone(), o.lo.clone());
            let hi = min_d(a.hi.clone(), o.hi.clone());
            (cmp(&lo, &hi) != Ordering::Greater).then(|| BigInterval {
                lo,
                hi,
                prec: a.prec.max(o.prec),
            })
        }
        pub fn midpoint(a: &BigInterval) -> Dyadic {
            let s = add(&a.lo, &a.hi);
            Dyadic { m: s.m, e: s.e - 1 }
        }
        fn quotient(n: &Int, d: &Int, s: i64, up: bool) -> Dyadic {
            let (num, den) = if s >= 0 {
                (n.shl(s as u64), d.clone())
            } else {
                (n.clone(), d.shl(s.unsigned_abs()))
            };
            let m = if up {
                -(-&num).div_floor(&den)
            } else {
                num.div_floor(&den)
            };
            Dyadic { m, e: -s }
        }
        fn div_d(a: &Dyadic, b: &Dyadic, prec: u32, up: bool) -> Dyadic {
            let (bm, am) = if b.m.is_negative() {
                (-&b.m, -&a.m)
            } else {
                (b.m.clone(), a.m.clone())
            };
            let s = prec as i64 + 2 + bm.bits() as i64 - am.bits() as i64;
            let q = quotient(&am, &bm, s, up);
            round(
                Dyadic {
                    m: q.m,
                    e: q.e + a.e - b.e,
                },
                prec,
                up,
            )
        }
        pub fn from_rat(q: &crate::Rat, prec: u32) -> (Dyadic, Dyadic) {
            let bits = prec.max(64);
            let s = bits as i64 + 2 + q.denom().bits() as i64 - q.numer().bits() as i64;
            (
                quotient(q.numer(), q.denom(), s, false),
                quotient(q.numer(), q.denom(), s, true),
            )
        }
        pub fn div(a: &BigInterval, o: &BigInterval) -> BigInterval {
            let prec = a.prec.max(o.prec).max(64);
            let ends = [
                (&a.lo, &o.lo),
                (&a.lo, &o.hi),
                (&a.hi, &o.lo),
                (&a.hi, &o.hi),
            ];
            let lo = ends
                .iter()
                .map(|(x, y)| div_d(x, y, prec, false))
                .reduce(min_d);
            let hi = ends
                .iter()
                .map(|(x, y)| div_d(x, y, prec, true))
                .reduce(max_d);
            BigInterval {
                lo: lo.expect("four"),
                hi: hi.expect("four"),
                prec: a.prec.max(o.prec),
            }
        }
    }

    /// Mantissas of 0 to 2048 bits, either sign.
    fn mantissa() -> impl Strategy<Value = Int> {
        (
            any::<bool>(),
            prop::collection::vec(any::<u64>(), 1..=32),
            0u64..64,
        )
            .prop_map(|(neg, limbs, cut)| Int::from_u64_limbs(neg, &limbs).shr_floor(cut))
    }

    /// Dyadics with exponents small and huge, zeros with any exponent.
    fn dyadic() -> impl Strategy<Value = Dyadic> {
        let e = prop_oneof![-300i64..300, -100_000i64..100_000];
        prop_oneof![
            1 => e.clone().prop_map(|e| Dyadic { m: Int::zero(), e }),
            8 => (mantissa(), e).prop_map(|(m, e)| Dyadic { m, e }),
        ]
    }

    /// Intervals of every shape the case analysis distinguishes: arbitrary
    /// (possibly reversed) ends, ordered ends, points (one dyadic twice),
    /// equal values written differently (`m·2^k, e − k`), ends a few bits
    /// apart, and a zero end.
    fn interval() -> impl Strategy<Value = BigInterval> {
        (
            dyadic(),
            dyadic(),
            0u8..6,
            0u64..70,
            prop_oneof![Just(0u32), 2u32..600],
        )
            .prop_map(|(x, y, shape, k, prec)| {
                let ordered = |x: Dyadic, y: Dyadic| match reference::cmp(&x, &y) {
                    Ordering::Greater => (y, x),
                    _ => (x, y),
                };
                let (lo, hi) = match shape {
                    0 => (x, y),
                    1 => ordered(x, y),
                    2 => (x.clone(), x),
                    3 => {
                        let other = Dyadic {
                            m: x.m.shl(k),
                            e: x.e - k as i64,
                        };
                        ordered(x, other)
                    }
                    4 => {
                        let tiny = Dyadic {
                            m: y.m.abs().shr_floor(y.m.bits().saturating_sub(k % 8)),
                            e: x.e + x.m.bits() as i64 - 120 - k as i64,
                        };
                        ordered(reference::add(&x, &tiny), x)
                    }
                    _ => ordered(
                        x,
                        Dyadic {
                            m: Int::zero(),
                            e: y.e,
                        },
                    ),
                };
                BigInterval { lo, hi, prec }
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        /// Every rewritten operation gives exactly the old endpoints:
        /// the same mantissa and exponent, not only the same value.
        #[test]
        fn operations_match_the_reference_digit_for_digit(a in interval(), b in interval(), p in 2u32..600) {
            prop_assert_eq!(a.lo.cmp_value(&b.lo), reference::cmp(&a.lo, &b.lo));
            prop_assert_eq!(a.lo.cmp_value(&a.hi), reference::cmp(&a.lo, &a.hi));
            prop_assert_eq!(a.times(&b), reference::times(&a, &b));
            prop_assert_eq!(b.times(&a), reference::times(&b, &a));
            prop_assert_eq!(a.times(&a), reference::times(&a, &a));
            prop_assert_eq!(a.plus(&b), reference::plus(&a, &b));
            prop_assert_eq!(a.minus(&b), reference::minus(&a, &b));
            prop_assert_eq!(b.minus(&a), reference::minus(&b, &a));
            prop_assert_eq!(a.hull(&b), reference::hull(&a, &b));
            prop_assert_eq!(a.intersect(&b), reference::intersect(&a, &b));
            prop_assert_eq!(a.midpoint().lo, reference::midpoint(&a));
            prop_assert_eq!(
                a.with_prec(p),
                reference::new(a.lo.clone(), a.hi.clone(), p)
            );
            if let Some(q) = Rat::new(a.lo.m.clone(), b.hi.m.clone()) {
                if Dyadic::from_rat_exact(&q).is_none() {
                    let r = BigInterval::from_rat(&q, p);
                    prop_assert_eq!((r.lo, r.hi), reference::from_rat(&q, p));
                }
            }
            let narrow = |x: &BigInterval| x.with_prec(80);
            let proper = reference::cmp(&b.lo, &b.hi) != Ordering::Greater;
            if proper && !b.contains_zero() && b.lo.m.bits() + b.hi.m.bits() < 600 {
                let (na, nb) = (narrow(&a), narrow(&b));
                prop_assert_eq!(na.div(&nb), Some(reference::div(&na, &nb)));
            }
        }

        #[test]
        fn operations_enclose_exact_results(a in -10_000i64..10_000, b in 1i64..1000, c in -10_000i64..10_000, d in 1i64..1000, prec in 8u32..80) {
            let (x, y) = (Rat::from_frac(a, b), Rat::from_frac(c, d));
            let (ix, iy) = (BigInterval::from_rat(&x, prec), BigInterval::from_rat(&y, prec));
            prop_assert!(contains(&ix, &x) && contains(&iy, &y));
            prop_assert!(contains(&ix.plus(&iy), &(&x + &y)));
            prop_assert!(contains(&ix.minus(&iy), &(&x - &y)));
            prop_assert!(contains(&ix.times(&iy), &(&x * &y)));
            prop_assert!(contains(&ix.div_small(7), &(&x / &Rat::from(7))));
            prop_assert!(contains(&ix.div_small(-3), &(&x / &Rat::from(-3))));
            if c != 0 {
                let q = ix.div(&iy).expect("excludes zero");
                prop_assert!(contains(&q, &(&x / &y)));
            }
            let m = ix.hull(&iy).midpoint();
            prop_assert!(contains(&ix.hull(&iy), &m.lo_rat()));
        }
    }
}
