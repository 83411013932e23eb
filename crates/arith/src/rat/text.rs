//! [`Rat`] as text: the exact decimal and fraction parser
//! ([`Rat::parse_exact`], `FromStr`) with its limits and errors, and the
//! output forms (`Display`'s `p/q`, [`Rat::to_decimal`]).

use super::Rat;
use crate::Int;

/// Why a decimal or fraction text is not an exact rational.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
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

impl Rat {
    /// Longest number text, in bytes, accepted by the parser.
    pub const MAX_TEXT: usize = 4096;
    /// Largest magnitude of a written decimal exponent (`1e4096`, `1e-4096`)
    /// accepted by the parser.
    pub const MAX_EXPONENT: i64 = 4096;
    /// Most characters of input text quoted in an error message (see
    /// [`excerpt`]).
    pub const QUOTED_TEXT: usize = 64;

    /// `self` correctly rounded to `digits` decimals (half away from zero),
    /// as text such as `0.539504286803`.
    pub fn to_decimal(&self, digits: u32) -> String {
        // `q = ⌊(2·|num|·10^digits + den) / (2·den)⌋`: in `u128` when every
        // step fits (the usual output of a query), else in big integers.
        let small = || {
            let n = self.num.to_i128()?.unsigned_abs();
            let d = u128::try_from(self.den.to_i128()?).ok()?;
            rounded(n, d, digits)
        };
        let (s, zero) = match small() {
            Some(q) => (q.to_string(), q == 0),
            None => {
                let scale = Int::pow10(digits);
                let scaled = &self.num.abs() * &scale;
                let twice = scaled.shl(1) + &self.den;
                let q = twice.div_floor(&self.den.shl(1));
                (q.to_string(), q.signum() == 0)
            }
        };
        decimal_text(s, self.num.is_negative() && !zero, digits)
    }
    /// `Rat::midpoint(lo, hi).to_decimal(digits)`, without forming the
    /// midpoint in big integers when both ends are machine fractions (the
    /// rounding depends only on the value, not on its lowest terms).
    pub fn midpoint_decimal(lo: &Rat, hi: &Rat, digits: u32) -> String {
        let small = || {
            let ((a, b), (c, d)) = (lo.words()?, hi.words()?);
            // (a/b + c/d)/2 = n/(2l) over l = lcm(b, d).
            let l = (b / gcd(b, d)).checked_mul(d)?;
            let n = i128::from(a)
                .checked_mul(i128::from(l / b))?
                .checked_add(i128::from(c).checked_mul(i128::from(l / d))?)?;
            let q = rounded(n.unsigned_abs(), u128::from(l) * 2, digits)?;
            Some(decimal_text(q.to_string(), n < 0 && q != 0, digits))
        };
        small().unwrap_or_else(|| Rat::midpoint(lo, hi).to_decimal(digits))
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
        let unsigned = t.strip_prefix(['+', '-']).unwrap_or(t);
        if ["inf", "nan", "infinity"]
            .iter()
            .any(|w| unsigned.eq_ignore_ascii_case(w))
        {
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
        if let Some(r) = small_decimal(neg, ip, fp, exp) {
            return Ok(r);
        }
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

/// `⌊(2·n·10^digits + d) / (2·d)⌋` (`n/d` rounded half up to `digits`
/// decimals, as an integer), if every step fits in `u128`.
fn rounded(n: u128, d: u128, digits: u32) -> Option<u128> {
    let twice = n
        .checked_mul(10u128.checked_pow(digits)?)?
        .checked_mul(2)?
        .checked_add(d)?;
    Some(twice / d.checked_mul(2)?)
}

/// The digits of `q` with the point `digits` places from the right
/// (zeros padded before it) and a `-` when `negative`.
fn decimal_text(mut s: String, negative: bool, digits: u32) -> String {
    if digits > 0 {
        let d = digits as usize;
        if s.len() <= d {
            s = format!("{}{}", "0".repeat(d + 1 - s.len()), s);
        }
        s.insert(s.len() - d, '.');
    }
    if negative {
        s.insert(0, '-');
    }
    s
}

/// `±(ip fp) · 10^exp` (the digits already checked) in machine integers
/// when at most 18 digits and `|exp| <= 18`: the value and lowest terms of
/// the big-integer path, without its allocations.
fn small_decimal(neg: bool, ip: &str, fp: &str, exp: i64) -> Option<Rat> {
    if ip.len() + fp.len() > 18 || exp.unsigned_abs() > 18 {
        return None;
    }
    let digits = ip.bytes().chain(fp.bytes());
    let n = digits.fold(0u64, |n, b| n * 10 + u64::from(b - b'0'));
    let p10 = 10u64.pow(exp.unsigned_abs() as u32);
    let (num, den) = if exp >= 0 {
        (u128::from(n) * u128::from(p10), 1)
    } else {
        let g = gcd(n, p10);
        (u128::from(n / g), p10 / g)
    };
    let num = i128::try_from(num).ok()?;
    Some(Rat {
        num: Int::from_i128(if neg { -num } else { num }),
        den: Int::from_u64(den),
    })
}

/// Euclid's gcd (`gcd(0, b) = b`).
fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
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
        // Machine integers print the same digits, without the big-integer
        // radix conversion.
        if let (Some(n), Some(d)) = (self.num.to_i64(), self.den.to_i64()) {
            return if d == 1 {
                write!(f, "{n}")
            } else {
                write!(f, "{n}/{d}")
            };
        }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn r(s: &str) -> Rat {
        s.parse().unwrap()
    }

    #[test]
    fn midpoint_decimal_is_the_midpoint_to_decimal() {
        let ends = [
            (
                "151856956556597/281474976710656",
                "2429711304905555/4503599627370496",
            ),
            (
                "-8295553289859881/9007199254740992",
                "-8295553289859663/9007199254740992",
            ),
            ("-1/3", "1/3"),
            ("-1/2000000000000", "1/3000000000000"),
            ("0", "0"),
            ("-1", "-1"),
            ("9223372036854775807", "9223372036854775807"),
            ("-9223372036854775807/9223372036854775806", "1/3"),
            ("123456789012345678901234567890", "1/7"),
        ];
        for (lo, hi) in ends {
            for digits in [0, 1, 12, 15, 16, 30] {
                let (lo, hi) = (r(lo), r(hi));
                assert_eq!(
                    Rat::midpoint_decimal(&lo, &hi, digits),
                    Rat::midpoint(&lo, &hi).to_decimal(digits),
                    "{lo} {hi} {digits}"
                );
            }
        }
    }

    #[test]
    fn small_decimals_match_the_big_integer_path() {
        for (neg, ip, fp, exp) in [
            (false, "0", "", 0i64),
            (true, "0", "000", -3),
            (false, "1", "2", -1),
            (true, "12", "50", -2),
            (false, "999999999", "999999999", -9),
            (false, "1", "", 18),
            (true, "999999999999999999", "", 18),
            (false, "", "000000000000000008", -18),
            (false, "3", "", -18),
        ] {
            let digits = format!("{ip}{fp}");
            let mut num = Int::parse_decimal(&digits).unwrap();
            if neg {
                num = -num;
            }
            let p10 = Int::pow10(exp.unsigned_abs() as u32);
            let big = if exp >= 0 {
                Rat::from_int(num * p10)
            } else {
                Rat::new(num, p10).unwrap()
            };
            let small = small_decimal(neg, ip, fp, exp).unwrap();
            assert_eq!(
                (&small.num, &small.den),
                (&big.num, &big.den),
                "{ip}.{fp}e{exp}"
            );
        }
        assert!(small_decimal(false, "1", "", 19).is_none());
        assert!(small_decimal(false, "1234567890", "123456789", 0).is_none());
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
}
