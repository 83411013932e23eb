//! [`Dyadic`]: exact dyadic rationals `m·2^e`, the numbers of the
//! certified enclosures ([`BigInterval`](crate::BigInterval)'s ends) and of the
//! solver's exact convexity test: sums, differences and products stay
//! dyadic and need no gcd, unlike [`Rat`]; the rounding operations
//! ([`Dyadic::round`], [`Dyadic::div`]) are for outward-rounded intervals.

use crate::{Int, Rat};
use std::cmp::Ordering;

/// The dyadic rational `m · 2^e`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dyadic {
    /// Mantissa.
    pub m: Int,
    /// Binary exponent.
    pub e: i64,
}

impl Dyadic {
    /// Zero.
    pub fn zero() -> Dyadic {
        Dyadic {
            m: Int::zero(),
            e: 0,
        }
    }
    /// The integer `k`.
    pub fn from_int(k: &Int) -> Dyadic {
        Dyadic { m: k.clone(), e: 0 }
    }
    /// The exact rational value.
    pub fn to_rat(&self) -> Rat {
        Rat::from_int(self.m.clone()).mul_pow2(self.e)
    }
    /// The exact value of a finite `f64`, `None` otherwise.
    pub fn from_f64(x: f64) -> Option<Dyadic> {
        let r = Rat::from_f64_exact(x)?;
        Dyadic::from_rat_exact(&r)
    }
    /// The value of a rational with a power-of-two denominator.
    pub fn from_rat_exact(r: &Rat) -> Option<Dyadic> {
        let den = r.denom();
        let tz = den.trailing_zeros()?;
        if den.bits() != tz + 1 {
            return None;
        }
        Some(Dyadic {
            m: r.numer().clone(),
            e: -(tz as i64),
        })
    }
    /// A nearby `f64` (not certified).
    pub fn to_f64(&self) -> f64 {
        let (mm, ee) = self.m.top_bits();
        let scale = self.e + ee as i64;
        let v = (mm as f64) * 2f64.powi(scale.clamp(-1100, 1100) as i32);
        if self.m.is_negative() {
            -v
        } else {
            v
        }
    }
    /// The sign of the value.
    pub fn signum(&self) -> i32 {
        self.m.signum()
    }
    /// `self + o` (`sign == 1`) or `self − o` (`sign == −1`), exact: the
    /// mantissas over the common exponent `min(e)` (a zero operand gives
    /// the other one, with its exponent). Only the operand with the larger
    /// exponent is shifted; the other is added in place.
    pub fn add_signed(&self, o: &Dyadic, sign: i32) -> Dyadic {
        let sub = sign < 0;
        if self.m.is_zero() {
            let m = if sub { -&o.m } else { o.m.clone() };
            return Dyadic { m, e: o.e };
        }
        if o.m.is_zero() {
            return self.clone();
        }
        let m = match self.e.cmp(&o.e) {
            Ordering::Equal if sub => &self.m - &o.m,
            Ordering::Equal => &self.m + &o.m,
            Ordering::Greater => {
                let mut m = self.m.shl((self.e - o.e) as u64);
                if sub {
                    m -= &o.m;
                } else {
                    m += &o.m;
                }
                m
            }
            Ordering::Less => {
                let mut m = o.m.shl((o.e - self.e) as u64);
                if sub {
                    m = -m;
                }
                m += &self.m;
                m
            }
        };
        Dyadic {
            m,
            e: self.e.min(o.e),
        }
    }
    /// `self + o`, exact.
    pub fn add(&self, o: &Dyadic) -> Dyadic {
        self.add_signed(o, 1)
    }
    /// `self − o`, exact.
    pub fn sub(&self, o: &Dyadic) -> Dyadic {
        self.add_signed(o, -1)
    }
    /// `self · o`, exact.
    pub fn mul(&self, o: &Dyadic) -> Dyadic {
        Dyadic {
            m: &self.m * &o.m,
            e: self.e + o.e,
        }
    }
    /// `−self`.
    pub fn neg(&self) -> Dyadic {
        Dyadic {
            m: -&self.m,
            e: self.e,
        }
    }
    /// The order of the values: signs first, then, for equal non-zero
    /// signs, the magnitudes (reversed when negative).
    pub fn cmp_value(&self, o: &Dyadic) -> Ordering {
        let (a, b) = (self.signum(), o.signum());
        if a != b || a == 0 {
            return a.cmp(&b);
        }
        let magnitude = self.m.cmp_abs_scaled(self.e, &o.m, o.e);
        if a > 0 {
            magnitude
        } else {
            magnitude.reverse()
        }
    }
    /// Rounded to `prec` significant bits, down (`up == false`) or up:
    /// `⌊m·2^(−s)⌋·2^(e+s)` (resp. `⌈⌉`) with `s = bits(m) − prec`
    /// ([`Int::shr_round`]).
    pub fn round(self, prec: u32, up: bool) -> Dyadic {
        if prec == 0 {
            return self;
        }
        let bits = self.m.bits();
        if bits <= prec as u64 {
            return self;
        }
        let s = bits - prec as u64;
        Dyadic {
            m: self.m.shr_round(s, up),
            e: self.e + s as i64,
        }
    }
    /// `⌊n·2^s / d⌋·2^(−s)` (down) or with `⌈⌉` (up), for `d ≠ 0`: one
    /// truncated division, the quotient stepped by one when the remainder
    /// is not zero and its sign (the dividend's) says the truncation went
    /// the wrong way (up for `⌊⌋` when it differs from the divisor's, down
    /// for `⌈⌉` when it agrees).
    pub fn quotient(n: &Int, d: &Int, s: i64, up: bool) -> Dyadic {
        let (q, r) = if s >= 0 {
            n.shl(s as u64).div_rem_trunc(d)
        } else {
            n.div_rem_trunc(&d.shl(s.unsigned_abs()))
        };
        let m = match (r.signum() * d.signum(), up) {
            (1, true) => q + Int::one(),
            (-1, false) => q - Int::one(),
            _ => q,
        };
        Dyadic { m, e: -s }
    }
    /// An outward rounding of `a / b` (`b ≠ 0`) to about `prec` bits.
    pub fn div(a: &Dyadic, b: &Dyadic, prec: u32, up: bool) -> Dyadic {
        let s = prec as i64 + 2 + b.m.bits() as i64 - a.m.bits() as i64;
        let q = Dyadic::quotient(&a.m, &b.m, s, up);
        Dyadic {
            m: q.m,
            e: q.e + a.e - b.e,
        }
        .round(prec, up)
    }
}
