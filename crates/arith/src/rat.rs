//! [`Rat`]: exact rationals over [`Int`], always in lowest terms with a
//! positive denominator, and their exact decimal parser.

use crate::Int;
use std::cmp::Ordering;
use std::ops::{Add, Div, Mul, Neg, Sub};

/// Why a decimal or fraction text is not an exact rational.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ParseRatError {
    /// The text is empty.
    #[error("empty number")]
    Empty,
    /// `inf` or `nan`: not a finite rational.
    #[error("`{0}` is not a finite number")]
    NotFinite(String),
    /// `p/0`.
    #[error("zero denominator in `{0}`")]
    ZeroDenominator(String),
    /// Longer than [`Rat::MAX_TEXT`] characters or an exponent beyond
    /// [`Rat::MAX_EXPONENT`]: refused rather than allocated.
    #[error("`{0}` is too large (at most {max_len} characters and |exponent| <= {max_exp})", max_len = Rat::MAX_TEXT, max_exp = Rat::MAX_EXPONENT)]
    TooLarge(String),
    /// Anything else.
    #[error("`{0}` is not a number (expected an integer, a decimal such as 0.125 or 1e-20, or a fraction p/q)")]
    Invalid(String),
}

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
    /// Longest number text, in bytes, accepted by the parser.
    pub const MAX_TEXT: usize = 4096;
    /// Largest magnitude of a written decimal exponent (`1e4096`, `1e-4096`)
    /// accepted by the parser.
    pub const MAX_EXPONENT: i64 = 4096;
    /// Most characters of input text quoted in an error message (see
    /// [`excerpt`]).
    pub const QUOTED_TEXT: usize = 64;

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
        // 0 < l <= h: the largest s with ⌊h/2^s⌋ > ⌊(l − 1)/2^s⌋.
        let below = &l - &Int::one();
        let (mut good, mut bad) = (0u64, h.bits() + 1);
        while bad - good > 1 {
            let mid = good + (bad - good) / 2;
            if h.shr_floor(mid) > below.shr_floor(mid) {
                good = mid;
            } else {
                bad = mid;
            }
        }
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
    /// The exponent `k` of a dyadic rational `m/2^k` in lowest terms, or
    /// `None` if the denominator is not a power of two.
    pub fn dyadic_exponent(&self) -> Option<u64> {
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
        let bits = x.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = bits & ((1u64 << 52) - 1);
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1u64 << 52), exp - 1075)
        };
        let v = Rat::from_int(Int::from_u64(m)).mul_pow2(e);
        Some(if x < 0.0 { -v } else { v })
    }
    /// A nearby `f64` (not certified).
    pub fn to_f64(&self) -> f64 {
        let (nb, db) = (self.num.bits() as i64, self.den.bits() as i64);
        // Scale so both parts fit comfortably in f64 before dividing.
        let s = (nb - db).clamp(-1000, 1000);
        let shifted = self.mul_pow2(60 - s);
        let q = shifted.num.div_trunc(&shifted.den);
        q.to_f64() * 2f64.powi((s - 60) as i32)
    }
    /// `self` correctly rounded to `digits` decimals (half away from zero),
    /// as text such as `0.539504286803`.
    pub fn to_decimal(&self, digits: u32) -> String {
        let scale = Int::pow10(digits);
        let scaled = &self.num.abs() * &scale;
        let twice = scaled.shl(1) + &self.den;
        let q = twice.div_floor(&self.den.shl(1));
        let mut s = q.to_string();
        if digits > 0 {
            let d = digits as usize;
            if s.len() <= d {
                s = format!("{}{}", "0".repeat(d + 1 - s.len()), s);
            }
            s.insert(s.len() - d, '.');
        }
        if self.num.is_negative() && q.signum() != 0 {
            s.insert(0, '-');
        }
        s
    }
    /// Parses an integer, a decimal (`0.125`, `-2.5e-3`, `1E5`, `+2`) or a
    /// fraction (`-7/2`) exactly.
    ///
    /// The grammar is strict: an optional sign `+` or `-` leads the number
    /// (a fraction's denominator has none), and no whitespace or `_`
    /// separator is accepted anywhere, so `" 2 "` and `"1 / 2"` are
    /// [`ParseRatError::Invalid`]. Limits, refused as
    /// [`ParseRatError::TooLarge`] before any big number is formed: at most
    /// [`Rat::MAX_TEXT`] bytes of text, and a written exponent (the digits
    /// after `e`) of magnitude at most [`Rat::MAX_EXPONENT`]. Texts quoted in
    /// errors are cut by [`excerpt`].
    pub fn parse_exact(t: &str) -> Result<Rat, ParseRatError> {
        if t.is_empty() {
            return Err(ParseRatError::Empty);
        }
        if t.len() > Rat::MAX_TEXT {
            return Err(ParseRatError::TooLarge(excerpt(t)));
        }
        let invalid = || ParseRatError::Invalid(excerpt(t));
        if t.chars().any(char::is_whitespace) {
            return Err(invalid());
        }
        let lower = t.to_ascii_lowercase();
        let unsigned = lower.strip_prefix(['+', '-']).unwrap_or(&lower);
        if unsigned == "inf" || unsigned == "nan" || unsigned == "infinity" {
            return Err(ParseRatError::NotFinite(excerpt(t)));
        }
        if let Some((p, q)) = t.split_once('/') {
            let num = Int::parse_decimal(p).ok_or_else(invalid)?;
            if q.starts_with(['+', '-']) {
                return Err(invalid());
            }
            let den = Int::parse_decimal(q).ok_or_else(invalid)?;
            return Rat::new(num, den).ok_or_else(|| ParseRatError::ZeroDenominator(excerpt(t)));
        }
        let (neg, body) = match t.as_bytes()[0] {
            b'-' => (true, &t[1..]),
            b'+' => (false, &t[1..]),
            _ => (false, t),
        };
        let (mantissa, exp) = match body.find(['e', 'E']) {
            Some(i) => {
                let e = &body[i + 1..];
                let ed = e.strip_prefix(['+', '-']).unwrap_or(e);
                if ed.is_empty() || !ed.bytes().all(|b| b.is_ascii_digit()) {
                    return Err(invalid());
                }
                // Leading zeros do not make an exponent large.
                let significant = ed.trim_start_matches('0');
                if significant.len() > 6 {
                    return Err(ParseRatError::TooLarge(excerpt(t)));
                }
                let magnitude: i64 = significant.parse().unwrap_or(0);
                if magnitude > Rat::MAX_EXPONENT {
                    return Err(ParseRatError::TooLarge(excerpt(t)));
                }
                let ev = if e.starts_with('-') {
                    -magnitude
                } else {
                    magnitude
                };
                (&body[..i], ev)
            }
            None => (body, 0),
        };
        let (ip, fp) = mantissa.split_once('.').unwrap_or((mantissa, ""));
        if (ip.is_empty() && fp.is_empty())
            || !ip.bytes().all(|b| b.is_ascii_digit())
            || !fp.bytes().all(|b| b.is_ascii_digit())
        {
            return Err(invalid());
        }
        // |exp| <= MAX_EXPONENT + MAX_TEXT: the text bounds the fraction digits.
        let exp = exp - fp.len() as i64;
        let digits = format!("{ip}{fp}");
        let mut num = Int::parse_decimal(&digits).ok_or_else(invalid)?;
        if neg {
            num = -num;
        }
        let p10 = Int::pow10(exp.unsigned_abs() as u32);
        Ok(if exp >= 0 {
            Rat::from_int(num * p10)
        } else {
            Rat::reduce(num, p10)
        })
    }
}

/// `t` as quoted in an error message: at most [`Rat::QUOTED_TEXT`]
/// characters, with `…` appended when it was cut. Shared by every message
/// that echoes input text (numbers here, keys and kinds in `ccd-scene`).
pub fn excerpt(t: &str) -> String {
    let mut chars = t.chars();
    let mut q: String = chars.by_ref().take(Rat::QUOTED_TEXT).collect();
    if chars.next().is_some() {
        q.push('…');
    }
    q
}

impl std::str::FromStr for Rat {
    type Err = ParseRatError;
    fn from_str(s: &str) -> Result<Rat, ParseRatError> {
        Rat::parse_exact(s)
    }
}

impl std::fmt::Display for Rat {
    /// `p` or `p/q` in lowest terms: the contract's exact time format.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.den.is_one() {
            write!(f, "{}", self.num)
        } else {
            write!(f, "{}/{}", self.num, self.den)
        }
    }
}
impl std::fmt::Debug for Rat {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        std::fmt::Display::fmt(self, f)
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
        (&self.num * &o.den).cmp(&(&o.num * &self.den))
    }
}
impl PartialOrd for Rat {
    fn partial_cmp(&self, o: &Rat) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

impl Add<&Rat> for &Rat {
    type Output = Rat;
    fn add(self, o: &Rat) -> Rat {
        if self.den == o.den {
            return Rat::reduce(&self.num + &o.num, self.den.clone());
        }
        Rat::reduce(&self.num * &o.den + &o.num * &self.den, &self.den * &o.den)
    }
}
impl Sub<&Rat> for &Rat {
    type Output = Rat;
    fn sub(self, o: &Rat) -> Rat {
        self + &(-o)
    }
}
impl Mul<&Rat> for &Rat {
    type Output = Rat;
    fn mul(self, o: &Rat) -> Rat {
        Rat::reduce(&self.num * &o.num, &self.den * &o.den)
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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn r(s: &str) -> Rat {
        s.parse().unwrap()
    }

    #[test]
    fn parses_the_contract_forms() {
        assert_eq!(r("3"), Rat::from(3));
        assert_eq!(r("0.1"), Rat::from_frac(1, 10));
        assert_eq!(r("-2.5e-3"), Rat::from_frac(-1, 400));
        assert_eq!(r("1/3"), Rat::from_frac(1, 3));
        assert_eq!(r("-7/2"), Rat::from_frac(-7, 2));
        assert_eq!(r("0.125"), Rat::from_frac(1, 8));
        assert_eq!(r("1e-20"), Rat::new(Int::one(), Int::pow10(20)).unwrap());
        assert_eq!(r("1E5"), Rat::from(100000));
        assert_eq!(r(".5"), Rat::from_frac(1, 2));
        assert_eq!(r("5."), Rat::from(5));
    }

    #[test]
    fn rejects_what_the_contract_rejects() {
        assert_eq!(Rat::parse_exact(""), Err(ParseRatError::Empty));
        assert!(matches!(
            Rat::parse_exact("inf"),
            Err(ParseRatError::NotFinite(_))
        ));
        assert!(matches!(
            Rat::parse_exact("-nan"),
            Err(ParseRatError::NotFinite(_))
        ));
        assert!(matches!(
            Rat::parse_exact("1/0"),
            Err(ParseRatError::ZeroDenominator(_))
        ));
        assert!(matches!(
            Rat::parse_exact("1e999999999"),
            Err(ParseRatError::TooLarge(_))
        ));
        // Over-long text cut for the message at a character boundary, not a byte.
        let long = format!("1{}", "é".repeat(3000));
        assert!(matches!(
            Rat::parse_exact(&long),
            Err(ParseRatError::TooLarge(_))
        ));
        for bad in [
            "abc", "1/-2", "1/+2", "1.2.3", "e5", "1e", "--1", "+-1", "1/2/3", "0x1", " 2", "2 ",
            " 2 ", "1 / 2", "1/ 2", "1 e5", "\t1", "1\n", "1_000", "+", "-",
        ] {
            assert!(
                matches!(Rat::parse_exact(bad), Err(ParseRatError::Invalid(_))),
                "{bad}"
            );
        }
    }

    #[test]
    fn a_leading_plus_is_a_sign() {
        assert_eq!(r("+2"), Rat::from(2));
        assert_eq!(r("+1/3"), Rat::from_frac(1, 3));
        assert_eq!(r("+2.5e+1"), Rat::from(25));
        assert!(matches!(
            Rat::parse_exact("+inf"),
            Err(ParseRatError::NotFinite(_))
        ));
    }

    #[test]
    fn the_exponent_limit_is_the_written_exponent() {
        let max = Rat::MAX_EXPONENT;
        assert_eq!(
            r(&format!("1e{max}")),
            Rat::from_int(Int::pow10(max as u32))
        );
        assert_eq!(
            r(&format!("1e-{max}")),
            Rat::new(Int::one(), Int::pow10(max as u32)).unwrap()
        );
        // Leading zeros do not count.
        assert_eq!(r(&format!("1e000000{max}")), r(&format!("1e{max}")));
        for over in [
            format!("1e{}", max + 1),
            format!("1e-{}", max + 1),
            format!("1e{}", 2 * max),
            "1E8192".to_string(),
            "-1e+8192".to_string(),
            "1e1000000".to_string(),
        ] {
            assert!(
                matches!(Rat::parse_exact(&over), Err(ParseRatError::TooLarge(_))),
                "{over}"
            );
        }
        // Fraction digits are bounded by the text length, not the exponent.
        let tiny = format!("0.{}1", "0".repeat(4000));
        assert_eq!(r(&tiny), Rat::new(Int::one(), Int::pow10(4001)).unwrap());
    }

    #[test]
    fn rejected_texts_are_quoted_cut() {
        let long = format!("{}x", "1".repeat(3000));
        let msg = Rat::parse_exact(&long).unwrap_err().to_string();
        assert!(msg.len() < 300, "{msg}");
        assert!(msg.contains('…'), "{msg}");
        let short = Rat::parse_exact("1.2.3").unwrap_err().to_string();
        assert!(short.contains("`1.2.3`") && !short.contains('…'), "{short}");
    }

    #[test]
    fn decimal_output_rounds_half_away() {
        assert_eq!(Rat::from_frac(1, 3).to_decimal(4), "0.3333");
        assert_eq!(Rat::from_frac(2, 3).to_decimal(4), "0.6667");
        assert_eq!(Rat::from_frac(-1, 8).to_decimal(2), "-0.13");
        assert_eq!(Rat::from(7).to_decimal(0), "7");
        assert_eq!(Rat::zero().to_decimal(3), "0.000");
    }

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

        #[test]
        fn field_identities(a in -1000i64..1000, b in 1i64..1000, c in -1000i64..1000, d in 1i64..1000) {
            let (x, y) = (Rat::from_frac(a, b), Rat::from_frac(c, d));
            prop_assert_eq!(&(&x + &y) - &y, x.clone());
            if !y.is_zero() { prop_assert_eq!(&(&x * &y) / &y, x.clone()); }
            prop_assert_eq!(x < y, (a as i128) * (d as i128) < (c as i128) * (b as i128));
            prop_assert!((x.to_f64() - a as f64 / b as f64).abs() < 1e-12);
            prop_assert_eq!(r(&x.to_string()), x.clone());
            let f = x.to_f64();
            prop_assert_eq!(Rat::from_f64_exact(f).map(|v| v.to_f64()), Some(f));
        }
    }
}
