//! [`Rat`]: exact rationals over [`Int`], always in lowest terms with a
//! positive denominator, and their arithmetic. Their text forms (parsing
//! and printing) are in [`text`], the simplest and the cheapest dyadic
//! point of an interval in [`simplest`].

pub(crate) mod simplest;
pub(crate) mod text;

use crate::Int;
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// An exact rational number `num / den`, `den > 0`, `gcd(num, den) = 1`.
///
/// ```
/// use ccd_arith::Rat;
/// let x: Rat = "0.1".parse().unwrap();
/// assert_eq!(x, Rat::from_frac(1, 10));
/// assert_eq!("-2.5e-3".parse::<Rat>().unwrap().to_string(), "-1/400");
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Rat {
    num: Int,
    den: Int,
}

impl Rat {
    /// `num / den` reduced; `None` when `den = 0`.
    pub fn new(num: Int, den: Int) -> Option<Rat> {
        if den.is_zero() {
            return None;
        }
        Some(Rat::reduce(num, den))
    }
    fn reduce(mut num: Int, mut den: Int) -> Rat {
        if den.is_negative() {
            num = -num;
            den = -den;
        }
        // Dyadic denominators (every subdivision point, every float) need no
        // gcd: strip the common power of two.
        let dz = den.trailing_zeros().unwrap_or(0);
        if den.bits() == dz + 1 {
            if num.is_zero() {
                return Rat {
                    num,
                    den: Int::one(),
                };
            }
            let k = num.trailing_zeros().unwrap_or(0).min(dz);
            if k > 0 {
                num = num.shr_floor(k);
                den = den.shr_floor(k);
            }
            return Rat { num, den };
        }
        let g = num.gcd(&den);
        if !g.is_one() && !g.is_zero() {
            num = num.div_exact(&g);
            den = den.div_exact(&g);
        }
        if num.is_zero() {
            den = Int::one();
        }
        Rat { num, den }
    }
    /// `p / q` for machine integers, `q ≠ 0`.
    pub fn from_frac(p: i64, q: i64) -> Rat {
        assert!(q != 0, "Rat::from_frac: zero denominator");
        Rat::reduce(Int::from(p), Int::from(q))
    }
    /// An integer as a rational.
    pub fn from_int(n: Int) -> Rat {
        Rat {
            num: n,
            den: Int::one(),
        }
    }
    /// `n / 2^k`.
    pub fn dyadic(n: Int, k: u64) -> Rat {
        Rat::reduce(n, Int::one().shl(k))
    }
    /// Zero.
    pub fn zero() -> Rat {
        Rat::from_int(Int::zero())
    }
    /// One.
    pub fn one() -> Rat {
        Rat::from_int(Int::one())
    }
    /// The numerator (carries the sign).
    pub fn numer(&self) -> &Int {
        &self.num
    }
    /// The denominator (positive).
    pub fn denom(&self) -> &Int {
        &self.den
    }
    /// `self == 0`.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }
    /// `self` is an integer.
    pub fn is_integer(&self) -> bool {
        self.den.is_one()
    }
    /// −1, 0 or 1.
    pub fn signum(&self) -> i32 {
        self.num.signum()
    }
    /// `|self|`.
    pub fn abs(&self) -> Rat {
        Rat {
            num: self.num.abs(),
            den: self.den.clone(),
        }
    }
    /// `1 / self`, `None` for zero.
    pub fn recip(&self) -> Option<Rat> {
        Rat::new(self.den.clone(), self.num.clone())
    }
    /// `⌊self⌋`.
    pub fn floor(&self) -> Int {
        self.num.div_floor(&self.den)
    }
    /// `(a + b) / 2`.
    pub fn midpoint(a: &Rat, b: &Rat) -> Rat {
        let s = a + b;
        Rat::reduce(s.num, s.den.shl(1))
    }
    /// The exponent `k` of a dyadic rational `m/2^k` in lowest terms, or
    /// `None` if the denominator is not a power of two.
    pub fn dyadic_exponent(&self) -> Option<u64> {
        // [`Int::exact_log2`] without its sign test (the denominator is
        // positive): comparisons and sums of rationals ask this first.
        let k = self.den.trailing_zeros().unwrap_or(0);
        (self.den.bits() == k + 1).then_some(k)
    }
    /// `self · 2^k` for a signed `k`.
    pub fn mul_pow2(&self, k: i64) -> Rat {
        if k >= 0 {
            Rat::reduce(self.num.shl(k as u64), self.den.clone())
        } else {
            Rat::reduce(self.num.clone(), self.den.shl(k.unsigned_abs()))
        }
    }
    /// The exact value of a finite `f64` (every finite float is a dyadic
    /// rational); `None` for infinities and NaN.
    pub fn from_f64_exact(x: f64) -> Option<Rat> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Rat::zero());
        }
        let (m, e) = f64_parts(x);
        // In lowest terms directly: m odd after stripping its trailing
        // zeros, so `m·2^e` is `m·2^e / 1` (e ≥ 0) or `m / 2^−e`.
        let tz = m.trailing_zeros();
        let (m, e) = (m >> tz, e + tz as i64);
        let num = Int::from_i64(if x < 0.0 { -(m as i64) } else { m as i64 });
        Some(if e >= 0 {
            Rat {
                num: num.shl(e as u64),
                den: Int::one(),
            }
        } else {
            Rat {
                num,
                den: Int::one().shl(e.unsigned_abs()),
            }
        })
    }
    /// A nearby `f64` (not certified).
    pub fn to_f64(&self) -> f64 {
        self.to_f64_short().unwrap_or_else(|| self.to_f64_scaled())
    }
    /// [`Rat::to_f64`] of `n/2^k` with `|n| < 2^53` and `k <= 1000` (the
    /// ends of most enclosures): `n` and `2^(−k)` are exact `f64`s, and so
    /// is their product, which is what the general path rounds to too.
    fn to_f64_short(&self) -> Option<f64> {
        let n = self.num.to_i64().filter(|n| n.unsigned_abs() < 1 << 53)?;
        let k = self.dyadic_exponent().filter(|k| *k <= 1000)?;
        Some(n as f64 * 2f64.powi(-(k as i32)))
    }
    /// [`Rat::to_f64`] in general.
    fn to_f64_scaled(&self) -> f64 {
        let (nb, db) = (self.num.bits() as i64, self.den.bits() as i64);
        // Scale so both parts fit comfortably in f64 before dividing.
        let s = (nb - db).clamp(-1100, 1100);
        // q = self·2^(60 − s) truncated: for a dyadic num/2^k one shift of
        // num by 60 − s − k (rounding towards zero), else a division.
        let q = match self.dyadic_exponent() {
            Some(k) => match 60 - s - k as i64 {
                e if e >= 0 => self.num.shl(e as u64),
                e => self.num.shr_round(e.unsigned_abs(), self.num.is_negative()),
            },
            None => {
                let shifted = self.mul_pow2(60 - s);
                shifted.num.div_trunc(&shifted.den)
            }
        };
        // `2^(s − 60)` in two factors, each a normal power of two (one
        // factor underflows or overflows where the value need not).
        let e = (s - 60) as i32;
        q.to_f64() * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
    }
}

impl From<i64> for Rat {
    fn from(v: i64) -> Rat {
        Rat::from_int(Int::from(v))
    }
}
impl From<Int> for Rat {
    fn from(v: Int) -> Rat {
        Rat::from_int(v)
    }
}

impl Ord for Rat {
    fn cmp(&self, o: &Rat) -> Ordering {
        if self.den == o.den {
            return self.num.cmp(&o.num);
        }
        if let (Some((a, b)), Some((c, d))) = (self.words(), o.words()) {
            // a/b against c/d, b, d > 0: a·d against c·b, each below 2^126.
            return (i128::from(a) * i128::from(d)).cmp(&(i128::from(c) * i128::from(b)));
        }
        if let (Some(a), Some(b)) = (self.dyadic_exponent(), o.dyadic_exponent()) {
            // x/2^a against y/2^b: signs first, then |x|·2^(−a) against
            // |y|·2^(−b) with no product and no shifted copy.
            let (sx, sy) = (self.num.signum(), o.num.signum());
            if sx != sy || sx == 0 {
                return sx.cmp(&sy);
            }
            let by_size = self.num.cmp_abs_scaled(-(a as i64), &o.num, -(b as i64));
            return if sx > 0 { by_size } else { by_size.reverse() };
        }
        (&self.num * &o.den).cmp(&(&o.num * &self.den))
    }
}
impl PartialOrd for Rat {
    fn partial_cmp(&self, o: &Rat) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Rat {
    /// `self + o` (`negate == false`) or `self − o`. Over a common
    /// denominator as is; with two dyadic denominators `2^a < 2^b`, over
    /// `2^b` after one shift of the other numerator (no products); else
    /// over the product of the denominators. [`Rat::reduce`] brings each
    /// to lowest terms, so all three give the one canonical result.
    fn sum(&self, o: &Rat, negate: bool) -> Rat {
        let combine = |x: &Int, y: &Int| if negate { x - y } else { x + y };
        if self.den == o.den {
            return Rat::reduce(combine(&self.num, &o.num), self.den.clone());
        }
        if let Some(short) = self.dyadic_sum_in_words(o, negate) {
            return short;
        }
        match (self.dyadic_exponent(), o.dyadic_exponent()) {
            (Some(a), Some(b)) if a < b => {
                Rat::reduce(combine(&self.num.shl(b - a), &o.num), o.den.clone())
            }
            (Some(a), Some(b)) => {
                Rat::reduce(combine(&self.num, &o.num.shl(a - b)), self.den.clone())
            }
            _ => Rat::reduce(
                combine(&(&self.num * &o.den), &(&o.num * &self.den)),
                &self.den * &o.den,
            ),
        }
    }
}

impl Rat {
    /// `(num, den)` as machine integers when both fit in an `i64` (the
    /// denominator, positive, as a `u64` below `2^63`): the ends of every
    /// root's narrowing and the points cut there, on every class of
    /// docs/table4.md (counted, session 40). The word paths of the order,
    /// the sum, the product and the decimal midpoint start here.
    #[inline]
    pub(crate) fn words(&self) -> Option<(i64, u64)> {
        Some((self.num.to_i64()?, self.den.to_i64()?.unsigned_abs()))
    }

    /// `self ± o` ([`Rat::sum`]) in `i128` for two dyadic rationals of
    /// 64-bit words, `a/2^p ± c/2^q` (`p, q ≤ 62`: a word denominator is at
    /// most `2^63 − 1`): both numerators over `2^max(p, q)` (each at most
    /// `2^125` in magnitude, their sum `2^126`), then in lowest terms as
    /// [`Rat::reduce`] gives them. From `Rat::sum` the levels differ, so
    /// the numerator over the larger one is odd and so is the sum: nothing
    /// to strike out. Called with equal levels (the tests do), the common
    /// power of two is struck out. `None` for any other pair.
    #[inline]
    fn dyadic_sum_in_words(&self, o: &Rat, negate: bool) -> Option<Rat> {
        let ((a, b), (c, d)) = (self.words()?, o.words()?);
        if !(b.is_power_of_two() && d.is_power_of_two()) {
            return None;
        }
        let (p, q) = (b.trailing_zeros(), d.trailing_zeros());
        let m = p.max(q);
        let (x, y) = (i128::from(a) << (m - p), i128::from(c) << (m - q));
        let sum = if negate { x - y } else { x + y };
        if sum == 0 {
            return Some(Rat::zero());
        }
        let k = sum.trailing_zeros().min(m);
        Some(Rat {
            num: Int::from_i128(sum >> k),
            den: Int::from_u64(1 << (m - k)),
        })
    }
}

impl Add<&Rat> for &Rat {
    type Output = Rat;
    fn add(self, o: &Rat) -> Rat {
        self.sum(o, false)
    }
}
impl Sub<&Rat> for &Rat {
    type Output = Rat;
    fn sub(self, o: &Rat) -> Rat {
        self.sum(o, true)
    }
}
impl Mul<&Rat> for &Rat {
    type Output = Rat;
    fn mul(self, o: &Rat) -> Rat {
        if let Some(product) = self.mul_words(o) {
            return product;
        }
        Rat::reduce(&self.num * &o.num, &self.den * &o.den)
    }
}

impl Rat {
    /// `self · o` in machine words when every part fits `i64` (a scene's
    /// short decimals): cross cancellation, `(a/b)·(c/d) = (a/g₁)(c/g₂) /
    /// ((b/g₂)(d/g₁))` with `g₁ = gcd(a, d)`, `g₂ = gcd(c, b)`, is already
    /// in lowest terms for reduced factors (whatever divided a numerator
    /// and the other denominator is gone, and each factor was coprime), so
    /// it is the very `Rat` of the general route, with two word gcds and
    /// no big-integer product or gcd. `None` when a part is longer.
    fn mul_words(&self, o: &Rat) -> Option<Rat> {
        let ((a, b), (c, d)) = (self.words()?, o.words()?);
        if a == 0 || c == 0 {
            return Some(Rat::zero());
        }
        // Each gcd divides a denominator, below 2^63, so it is also an
        // i64. A denominator 1 (integers, the usual weights) shares nothing.
        let gcd = |x: i64, y: u64| match y {
            1 => 1,
            _ => crate::gcd_u128(x.unsigned_abs().into(), y.into()) as u64,
        };
        let (g1, g2) = (gcd(a, d), gcd(c, b));
        let num = i128::from(a / g1 as i64) * i128::from(c / g2 as i64);
        let den = i128::from(b / g2) * i128::from(d / g1);
        Some(Rat {
            num: Int::from_i128(num),
            den: Int::from_i128(den),
        })
    }
}

impl Div<&Rat> for &Rat {
    type Output = Rat;
    /// Panics on division by zero; callers divide by values proven nonzero.
    fn div(self, o: &Rat) -> Rat {
        assert!(!o.is_zero(), "Rat: division by zero");
        Rat::reduce(&self.num * &o.den, &self.den * &o.num)
    }
}
impl Neg for &Rat {
    type Output = Rat;
    fn neg(self) -> Rat {
        Rat {
            num: -&self.num,
            den: self.den.clone(),
        }
    }
}
impl Neg for Rat {
    type Output = Rat;
    fn neg(self) -> Rat {
        Rat {
            num: -self.num,
            den: self.den,
        }
    }
}
macro_rules! owned_rat_ops {
    ($($tr:ident $m:ident),*) => {$(
        impl $tr<Rat> for Rat { type Output = Rat; fn $m(self, o: Rat) -> Rat { (&self).$m(&o) } }
        impl $tr<&Rat> for Rat { type Output = Rat; fn $m(self, o: &Rat) -> Rat { (&self).$m(o) } }
        impl $tr<Rat> for &Rat { type Output = Rat; fn $m(self, o: Rat) -> Rat { self.$m(&o) } }
    )*};
}
owned_rat_ops!(Add add, Sub sub, Mul mul, Div div);

/// `|x| = m·2^e` for a finite `f64` `x`: the significand with its hidden
/// bit (none for a subnormal) and the exponent of its last bit.
fn f64_parts(x: f64) -> (u64, i64) {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    if exp == 0 {
        (frac, -1074)
    } else {
        (frac | (1u64 << 52), exp - 1075)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn r(s: &str) -> Rat {
        s.parse().unwrap()
    }

    /// [`Rat::from_f64_exact`] as it was: the mantissa times a power of
    /// two, reduced by a gcd.
    fn from_f64_by_reduction(x: f64) -> Option<Rat> {
        if !x.is_finite() {
            return None;
        }
        if x == 0.0 {
            return Some(Rat::zero());
        }
        let (m, e) = f64_parts(x);
        let v = Rat::from_int(Int::from_u64(m)).mul_pow2(e);
        Some(if x < 0.0 { -v } else { v })
    }

    proptest! {
        /// Floats from their bits are the reduced products: every class
        /// (subnormal, integral, huge, infinite, NaN) and short mantissas
        /// (many trailing zeros).
        #[test]
        fn from_f64_exact_is_the_reduction(x in any::<f64>(), m in -4096i64..4096, e in -1100i32..1000) {
            prop_assert_eq!(Rat::from_f64_exact(x), from_f64_by_reduction(x));
            let y = m as f64 * 2f64.powi(e);
            prop_assert_eq!(Rat::from_f64_exact(y), from_f64_by_reduction(y));
        }
    }

    proptest! {
        /// The word product is the reduced general product: parts up to
        /// `i64`'s ends (so products past `i64`), shared factors across the
        /// factors, zeros, and one part past a word (no word product).
        #[test]
        fn word_products_are_the_reduction(
            parts in proptest::array::uniform4(prop_oneof![any::<i64>(), -100i64..100, Just(i64::MIN), Just(i64::MAX)]),
            shared in 1i64..1000,
            long in any::<bool>(),
        ) {
            let rat = |n: i64, d: i64| Rat::new(Int::from(n), Int::from(d.max(1))).expect("positive");
            let x = rat(parts[0], parts[1].saturating_abs());
            let y = rat(parts[2].saturating_mul(shared), parts[3].saturating_abs().saturating_mul(shared));
            let y = if long { &y * &Rat::from_int(Int::from(i64::MAX).pow(2)) } else { y };
            let general = Rat::reduce(&x.num * &y.num, &x.den * &y.den);
            prop_assert_eq!(x.mul_words(&y).is_some(), !long || y.num.is_zero());
            prop_assert_eq!(&x * &y, general.clone());
            prop_assert_eq!(&y * &x, general);
        }
    }

    proptest! {
        /// The short conversion is the general one, bit for bit: numerators
        /// up to and past 2^53, levels up to and past 1000, integers.
        #[test]
        fn to_f64_short_is_the_scaled_path(n in any::<i64>(), bits in 0u32..56, k in 0u64..1010) {
            let x = Rat::dyadic(Int::from(n >> (63 - bits.min(63))), k);
            if let Some(short) = x.to_f64_short() {
                prop_assert_eq!(short.to_bits(), x.to_f64_scaled().to_bits());
            }
        }
    }

    proptest! {
        #[test]
        fn field_identities(a in -1000i64..1000, b in 1i64..1000, c in -1000i64..1000, d in 1i64..1000) {
            let (x, y) = (Rat::from_frac(a, b), Rat::from_frac(c, d));
            prop_assert_eq!(&(&x + &y) - &y, x.clone());
            prop_assert_eq!(&x - &y, &x + &(-&y));
            prop_assert_eq!(&x - &x, Rat::zero());
            if !y.is_zero() { prop_assert_eq!(&(&x * &y) / &y, x.clone()); }
            prop_assert_eq!(x < y, (a as i128) * (d as i128) < (c as i128) * (b as i128));
            prop_assert!((x.to_f64() - a as f64 / b as f64).abs() < 1e-12);
            prop_assert_eq!(r(&x.to_string()), x.clone());
            let f = x.to_f64();
            prop_assert_eq!(Rat::from_f64_exact(f).map(|v| v.to_f64()), Some(f));
        }

        /// Sums and differences of dyadics (the shift path), of a dyadic
        /// and a non-dyadic, and over one denominator are the sums over the
        /// product of the denominators, in lowest terms.
        #[test]
        fn sums_are_over_the_product_of_denominators(
            a in any::<i64>(), ka in 0u64..200, b in any::<i64>(), kb in 0u64..200,
            big in 0u64..300, odd in 0i64..1000,
        ) {
            let x = Rat::dyadic(Int::from(a).shl(big) + Int::from(a), ka);
            let y = Rat::dyadic(Int::from(b), kb);
            let z = Rat::from_frac(b, 2 * odd + 3);
            let reference = |p: &Rat, q: &Rat, negate: bool| {
                let cross = &q.num * &p.den;
                let cross = if negate { -cross } else { cross };
                Rat::new(&p.num * &q.den + cross, &p.den * &q.den).expect("nonzero")
            };
            // to_f64 as it was: one truncating division of the scaled value.
            let approx = |p: &Rat| {
                let s = (p.num.bits() as i64 - p.den.bits() as i64).clamp(-1100, 1100);
                let shifted = p.mul_pow2(60 - s);
                let e = (s - 60) as i32;
                shifted.num.div_trunc(&shifted.den).to_f64() * 2f64.powi(e / 2) * 2f64.powi(e - e / 2)
            };
            for p in [&x, &y, &z, &-&x, &x.mul_pow2(-900), &y.mul_pow2(1200)] {
                prop_assert_eq!(p.to_f64().to_bits(), approx(p).to_bits());
            }
            let order = |p: &Rat, q: &Rat| (&p.num * &q.den).cmp(&(&q.num * &p.den));
            for (p, q) in [(&x, &y), (&y, &x), (&x, &z), (&z, &y), (&x, &x), (&y, &y.mul_pow2(1))] {
                prop_assert_eq!(p + q, reference(p, q, false));
                prop_assert_eq!(p - q, reference(p, q, true));
                prop_assert_eq!(p.cmp(q), order(p, q));
                prop_assert_eq!(p.cmp(&-q), order(p, &-q));
            }
        }
        /// The word paths are the general ones: sums of dyadics of 64-bit
        /// words (numerators to `i64`'s ends, levels up to 62, shared
        /// powers of two, sums that cancel) and the order of any rationals
        /// of 64-bit words, against the sum over the product of the
        /// denominators and the cross products in big integers.
        #[test]
        fn word_sums_and_orders_are_the_general_ones(
            a in prop_oneof![any::<i64>(), -64i64..64, Just(i64::MIN), Just(i64::MAX)],
            b in prop_oneof![any::<i64>(), -64i64..64, Just(i64::MIN), Just(i64::MAX)],
            ka in 0u64..63, kb in 0u64..63, shift in 0u64..62,
            da in 1i64..i64::MAX, db in prop_oneof![1i64..i64::MAX, 1i64..1000],
        ) {
            let x = Rat::dyadic(Int::from(a), ka);
            let y = Rat::dyadic(Int::from(b), kb);
            let shared = Rat::dyadic(Int::from(b).shl(shift.min(kb)), kb);
            let general = |p: &Rat, q: &Rat, negate: bool| {
                let cross = &q.num * &p.den;
                let cross = if negate { -cross } else { cross };
                Rat::new(&p.num * &q.den + cross, &p.den * &q.den).expect("nonzero")
            };
            for (p, q) in [(&x, &y), (&y, &x), (&x, &x), (&x, &shared), (&shared, &y)] {
                for negate in [false, true] {
                    let short = p.dyadic_sum_in_words(q, negate);
                    prop_assert!(short.is_some());
                    prop_assert_eq!(short, Some(general(p, q, negate)));
                }
            }
            let order = |p: &Rat, q: &Rat| (&p.num * &q.den).cmp(&(&q.num * &p.den));
            let (u, v) = (Rat::from_frac(a, da), Rat::from_frac(b, db));
            // Through the operators: a non-dyadic denominator (no word
            // sum), a level past a word (2^63: no words at all), and the
            // word sum reached from `Rat::sum` with the operands in order.
            let past = Rat::dyadic(Int::from(b | 1), 63);
            for (p, q) in [(&u, &x), (&x, &u), (&x, &past), (&past, &y), (&x, &y), (&y, &x)] {
                prop_assert_eq!(p + q, general(p, q, false));
                prop_assert_eq!(p - q, general(p, q, true));
            }
            prop_assert_eq!(past.words(), None);
            if !da.unsigned_abs().is_power_of_two() {
                prop_assert_eq!(u.dyadic_sum_in_words(&x, false).is_some(), u.den.exact_log2().is_some());
            }
            for (p, q) in [(&u, &v), (&v, &u), (&u, &x), (&y, &v), (&u, &-&u), (&u, &u)] {
                prop_assert_eq!(p.cmp(q), order(p, q));
            }
        }
        /// The direct construction in lowest terms is the reduced `m·2^e`
        /// (every finite float: normal, subnormal, zero, both signs).
        #[test]
        fn from_f64_exact_is_the_reduced_value(bits in any::<u64>()) {
            let x = f64::from_bits(bits);
            prop_assume!(x.is_finite());
            let exp = ((bits >> 52) & 0x7ff) as i64;
            let frac = bits & ((1u64 << 52) - 1);
            let (m, e) = if exp == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp - 1075) };
            let v = Rat::from_int(Int::from_u64(m)).mul_pow2(e);
            let reference = if x < 0.0 { -v } else { v };
            let got = Rat::from_f64_exact(x).unwrap();
            prop_assert_eq!(got.numer(), reference.numer());
            prop_assert_eq!(got.denom(), reference.denom());
        }
    }

    #[test]
    fn from_f64_exact_at_the_ends() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -0.75,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            3.0 * 2f64.powi(60),
        ] {
            let r = Rat::from_f64_exact(x).unwrap();
            assert_eq!(r.to_f64(), x, "{x}");
            assert!(r.denom().is_one() || r.numer().trailing_zeros() == Some(0));
        }
        assert!(Rat::from_f64_exact(f64::NAN).is_none());
    }
}
