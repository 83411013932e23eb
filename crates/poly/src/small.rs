//! [`SmallPoly`]: polynomials with `i128` coefficients that detect
//! overflow, for exact computations whose numbers are usually small.
//!
//! Every [`RingOps`] operation is exact or marks the result as overflowed
//! (a coefficient leaving `i128`, or a degree above [`SmallPoly::MAX_DEGREE`]);
//! an overflowed value stays overflowed through every later operation, so a
//! caller runs a generic routine over `SmallPoly` and converts back with
//! [`SmallPoly::to_zpoly`], falling back to [`ZPoly`] on `None`. The
//! characteristic polynomial of two placed bodies (Plücker coordinates of
//! degree-2 placements with short decimal entries) is such a computation:
//! a product costs a few machine multiplications per term instead of
//! big-integer allocations.

use crate::ZPoly;
use ccd_arith::{Int, Ring, RingOps, SmallInt};

/// Coefficient slots: degrees up to [`SmallPoly::MAX_DEGREE`].
const CAP: usize = 17;

/// A polynomial in `ℤ[t]` with `i128` coefficients (low → high), or the
/// marker that an exact value did not fit (module docs). The slots past
/// the length are zero (every constructor keeps this), so operations read
/// them without bounds tests.
///
/// ```
/// use ccd_arith::RingOps;
/// use ccd_poly::{SmallPoly, ZPoly};
/// let p = SmallPoly::from_zpoly(&ZPoly::from_i64s(&[1, 2])).unwrap();
/// assert_eq!(p.times(&p).to_zpoly(), Some(ZPoly::from_i64s(&[1, 4, 4])));
/// let big = SmallPoly::from_i64(i64::MAX);
/// let huge = big.times(&big).times(&big); // about 2^189
/// assert_eq!(huge.to_zpoly(), None);
/// ```
#[derive(Clone, Debug)]
pub struct SmallPoly {
    c: [i128; CAP],
    /// Number of coefficients in use (no trailing zero); 0 for zero.
    len: usize,
    overflow: bool,
}

/// Equal values, both exact: an overflowed polynomial (whose coefficients
/// mean nothing) equals none, itself included, as a NaN.
impl PartialEq for SmallPoly {
    fn eq(&self, o: &SmallPoly) -> bool {
        !self.overflow && !o.overflow && self.c[..self.len] == o.c[..o.len]
    }
}

impl SmallPoly {
    /// Largest degree held.
    pub const MAX_DEGREE: usize = CAP - 1;

    fn overflowed() -> SmallPoly {
        SmallPoly {
            c: [0; CAP],
            len: 0,
            overflow: true,
        }
    }

    /// From coefficients (low → high); `None` marks an overflow.
    fn build(coeffs: impl Iterator<Item = Option<i128>>, len: usize) -> SmallPoly {
        if len > CAP {
            return SmallPoly::overflowed();
        }
        let mut c = [0; CAP];
        for (slot, v) in c.iter_mut().zip(coeffs) {
            match v {
                Some(v) => *slot = v,
                None => return SmallPoly::overflowed(),
            }
        }
        SmallPoly::from_array(c, len)
    }

    /// The polynomial `c[..len]` (the slots past `len` zero), trimmed.
    fn from_array(c: [i128; CAP], len: usize) -> SmallPoly {
        let mut p = SmallPoly {
            c,
            len,
            overflow: false,
        };
        p.trim();
        p
    }

    /// Drops trailing zero coefficients from the length.
    fn trim(&mut self) {
        while self.len > 0 && self.c[self.len - 1] == 0 {
            self.len -= 1;
        }
    }

    /// `p`, overflowed if its degree or a coefficient does not fit (so a
    /// computation on it reports the overflow at the end).
    pub fn lowered(p: &ZPoly) -> SmallPoly {
        SmallPoly::build(p.coeffs().iter().map(Int::to_i128), p.coeffs().len())
    }

    /// `*self = SmallPoly::lowered(p)` in `self`'s slots (no 288-byte
    /// value built elsewhere and copied over).
    pub fn set_lowered(&mut self, p: &ZPoly) {
        self.clear();
        let coeffs = p.coeffs();
        if coeffs.len() > CAP {
            *self = SmallPoly::overflowed();
            return;
        }
        for (slot, v) in self.c.iter_mut().zip(coeffs) {
            match v.to_i128() {
                Some(v) => *slot = v,
                None => {
                    *self = SmallPoly::overflowed();
                    return;
                }
            }
        }
        self.len = coeffs.len();
        self.trim();
    }

    /// `*self = SmallPoly::constant(x)` in `self`'s slots.
    pub fn set_constant(&mut self, x: &SmallInt) {
        self.clear();
        match x.to_i128() {
            Some(v) => {
                self.c[0] = v;
                self.len = 1;
                self.trim();
            }
            None => *self = SmallPoly::overflowed(),
        }
    }

    /// Zero, in place: only the slots in use are cleared (those past the
    /// length are zero already).
    fn clear(&mut self) {
        if self.overflow {
            *self = SmallPoly::zero();
        } else {
            self.c[..self.len].fill(0);
            self.len = 0;
        }
    }

    /// The constant `x` (overflowed when `x` is).
    pub fn constant(x: &SmallInt) -> SmallPoly {
        match x.to_i128() {
            Some(v) => {
                let mut c = [0; CAP];
                c[0] = v;
                SmallPoly::from_array(c, 1)
            }
            None => SmallPoly::overflowed(),
        }
    }

    /// `p` if its degree and coefficients fit.
    pub fn from_zpoly(p: &ZPoly) -> Option<SmallPoly> {
        let q = SmallPoly::lowered(p);
        (!q.overflow).then_some(q)
    }

    /// The exact polynomial, `None` if an operation overflowed.
    pub fn to_zpoly(&self) -> Option<ZPoly> {
        (!self.overflow).then(|| {
            ZPoly::new(
                self.c[..self.len]
                    .iter()
                    // The one-word constructor when it fits: much cheaper.
                    .map(|&v| i64::try_from(v).map_or_else(|_| Int::from_i128(v), Int::from_i64))
                    .collect(),
            )
        })
    }

    /// The exact polynomials of an array, `None` if any overflowed.
    pub fn to_zpolys<const N: usize>(ps: &[SmallPoly; N]) -> Option<[ZPoly; N]> {
        let v: Vec<ZPoly> = ps.iter().map(SmallPoly::to_zpoly).collect::<Option<_>>()?;
        v.try_into().ok()
    }

    /// Whether the value is exact (no operation overflowed).
    pub fn is_exact(&self) -> bool {
        !self.overflow
    }

    /// The degree (`None` for zero or an overflowed value).
    pub fn degree(&self) -> Option<usize> {
        (!self.overflow && self.len > 0).then(|| self.len - 1)
    }

    /// The bit length of the largest coefficient (`0` for zero; `128`
    /// for an overflowed value, which fits nothing).
    pub fn max_bits(&self) -> u64 {
        if self.overflow {
            return 128;
        }
        // The bitwise or of the magnitudes has the largest one's top bit.
        let m = self.c[..self.len]
            .iter()
            .fold(0u128, |m, v| m | v.unsigned_abs());
        u64::from(128 - m.leading_zeros())
    }

    /// `gcd(g, content)`: the gcd of `g` and the coefficients, `≥ 0` (so
    /// `gcd_with(0)` is the content, and folding it over several
    /// polynomials gives their common content); `None` for an overflowed
    /// value.
    pub fn gcd_with(&self, g: u128) -> Option<u128> {
        (!self.overflow).then(|| {
            // A gcd 1 stays 1.
            self.c[..self.len]
                .iter()
                .try_fold(g, |g, v| {
                    let g = ccd_arith::gcd_u128(g, v.unsigned_abs());
                    if g == 1 {
                        Err(g)
                    } else {
                        Ok(g)
                    }
                })
                .unwrap_or_else(|g| g)
        })
    }

    /// The exact quotient in `ℤ[t]`: `Some(q)` with `self = q·d`; `None`
    /// when `d` does not divide `self` (or `d = 0`); an overflowed `q` when
    /// either input is overflowed or a step leaves `i128` (then nothing is
    /// known). Long division from the top, as [`ZPoly::div_exact`]: the
    /// first inexact quotient coefficient or a nonzero remainder answers
    /// `None`.
    ///
    /// ```
    /// use ccd_poly::{SmallPoly, ZPoly};
    /// let s = |c: &[i64]| SmallPoly::from_zpoly(&ZPoly::from_i64s(c)).unwrap();
    /// // 3t² + 2 by 2t + 1: no.
    /// assert!(s(&[2, 0, 3]).div_exact(&s(&[1, 2])).is_none());
    /// // 2t² − t − 1 = (2t + 1)(t − 1).
    /// let q = s(&[-1, -1, 2]).div_exact(&s(&[1, 2])).unwrap();
    /// assert_eq!(q.to_zpoly(), Some(ZPoly::from_i64s(&[-1, 1])));
    /// ```
    pub fn div_exact(&self, d: &SmallPoly) -> Option<SmallPoly> {
        if self.overflow || d.overflow {
            return Some(SmallPoly::overflowed());
        }
        let dd = d.len.checked_sub(1)?;
        if self.len == 0 {
            return Some(self.clone());
        }
        if self.len < d.len {
            return None;
        }
        let dl = d.c[dd];
        let mut r = self.c;
        // The quotient is built in place (no copy of the slots on return).
        let mut q = SmallPoly::zero();
        for k in (0..self.len - dd).rev() {
            let top = r[k + dd];
            if top == 0 {
                continue;
            }
            // One division: `top = qk·dl` exactly iff the truncated
            // quotient multiplies back (|qk·dl| <= |top|, no overflow).
            let qk = match (i64::try_from(top), i64::try_from(dl)) {
                // Machine division when both fit a word (`dl ≠ 0`; a
                // divisor −1 goes the long way, i64::MIN / −1 overflows).
                (Ok(t), Ok(l)) if l != -1 => i128::from(t / l),
                _ => match top.checked_div(dl) {
                    Some(qk) => qk,
                    None => return Some(SmallPoly::overflowed()),
                },
            };
            if qk * dl != top {
                return None;
            }
            for (ri, &di) in r[k..k + dd].iter_mut().zip(&d.c) {
                match qk.checked_mul(di).and_then(|p| ri.checked_sub(p)) {
                    Some(v) => *ri = v,
                    None => return Some(SmallPoly::overflowed()),
                }
            }
            r[k + dd] = 0;
            q.c[k] = qk;
        }
        if r[..dd].iter().any(|&x| x != 0) {
            return None;
        }
        q.len = self.len - dd;
        q.trim();
        Some(q)
    }

    /// `self/k` for a `k ≠ 0` dividing every coefficient exactly; a
    /// coefficient `k` does not divide (or `k = 0`) marks the result
    /// overflowed (the exact value is not in `ℤ[t]`).
    ///
    /// ```
    /// use ccd_poly::{SmallPoly, ZPoly};
    /// let p = SmallPoly::from_zpoly(&ZPoly::from_i64s(&[6, -9])).unwrap();
    /// assert_eq!(p.div_exact_int(3).to_zpoly(), Some(ZPoly::from_i64s(&[2, -3])));
    /// assert!(!p.div_exact_int(4).is_exact());
    /// ```
    pub fn div_exact_int(&self, k: i128) -> SmallPoly {
        // One division: exact iff the truncated quotient multiplies back
        // (|q·k| <= |x|, no overflow).
        self.zip(&SmallPoly::zero(), move |x, _| {
            x.checked_div(k).filter(|&q| q * k == x)
        })
    }

    /// [`SmallPoly::div_exact_int`] in place (no 288-byte result copied
    /// over `self`).
    pub fn div_exact_int_assign(&mut self, k: i128) {
        if self.overflow {
            return;
        }
        for x in &mut self.c[..self.len] {
            match x.checked_div(k).filter(|&q| q * k == *x) {
                Some(q) => *x = q,
                None => {
                    *self = SmallPoly::overflowed();
                    return;
                }
            }
        }
    }

    /// The polynomial of degree below `values.len()` taking `values[i]` at
    /// `u = first + i`, when its coefficients are integers (as for the
    /// values of an integer polynomial of that degree): Newton's forward
    /// differences `Δᵏv₀`, each divided exactly by `k!` (for an integer
    /// polynomial `Δᵏ` of its values is a multiple of `k!`), then the
    /// falling-factorial form expanded by Horner. Marked overflowed when a
    /// number does not fit, a division is not exact (no integer
    /// polynomial takes these values) or there are more values than the
    /// capacity.
    ///
    /// ```
    /// use ccd_arith::{Int, SmallInt};
    /// use ccd_poly::{SmallPoly, ZPoly};
    /// let p = ZPoly::from_i64s(&[5, 0, -4, 1]);
    /// let values: Vec<SmallInt> = (-2..2).map(|u| SmallInt::of(&p.eval_int(&Int::from(u)))).collect();
    /// assert_eq!(SmallPoly::interpolate(-2, &values).to_zpoly(), Some(p));
    /// // (u² + u)/2 takes 0, 1, 3 at 0, 1, 2: not an integer polynomial.
    /// assert!(!SmallPoly::interpolate(0, &[0, 1, 3].map(SmallInt::from_i128)).is_exact());
    /// ```
    pub fn interpolate(first: i64, values: &[SmallInt]) -> SmallPoly {
        let n = values.len();
        if n == 0 {
            return SmallPoly::zero();
        }
        if n > CAP {
            return SmallPoly::overflowed();
        }
        // d[k] ← Δᵏv₀ / k!.
        let mut d = [SmallInt::zero(); CAP];
        d[..n].copy_from_slice(values);
        for k in 1..n {
            for i in (k..n).rev() {
                d[i] = d[i].minus(&d[i - 1]);
            }
        }
        let mut factorial = SmallInt::one();
        for (k, dk) in d.iter_mut().enumerate().take(n).skip(2) {
            factorial = factorial.times(&SmallInt::from_i64(k as i64));
            *dk = dk.div_exact(&factorial);
        }
        // Σ d[k]·Π_(j<k) (u − first − j), innermost first.
        let mut q = [SmallInt::zero(); CAP];
        q[0] = d[n - 1];
        for k in (0..n - 1).rev() {
            // q ← q·(u − (first + k)) + d[k]: degree n − 2 − k → n − 1 − k.
            let shift = SmallInt::from_i64(first + k as i64);
            let top = n - 1 - k;
            for i in (1..=top).rev() {
                q[i] = q[i - 1].minus(&q[i].times(&shift));
            }
            q[0] = d[k].minus(&q[0].times(&shift));
        }
        SmallPoly::build(q[..n].iter().map(SmallInt::to_i128), n)
    }

    /// `self ← self + s·q` for an integer `s`, checked: an overflow (of
    /// `s` itself included) marks the result.
    ///
    /// ```
    /// use ccd_arith::SmallInt;
    /// use ccd_poly::{SmallPoly, ZPoly};
    /// let mut p = SmallPoly::from_zpoly(&ZPoly::from_i64s(&[1, 2])).unwrap();
    /// let q = SmallPoly::from_zpoly(&ZPoly::from_i64s(&[0, 1, 1])).unwrap();
    /// p.add_scaled(&SmallInt::from_i128(-3), &q);
    /// assert_eq!(p.to_zpoly(), Some(ZPoly::from_i64s(&[1, -1, -3])));
    /// // −3·(2^127 − 1) does not fit.
    /// p.add_scaled(&SmallInt::from_i128(i128::MAX), &p.clone());
    /// assert!(!p.is_exact());
    /// ```
    pub fn add_scaled(&mut self, s: &SmallInt, q: &SmallPoly) {
        let Some(s) = s.to_i128().filter(|_| !self.overflow && !q.overflow) else {
            *self = SmallPoly::overflowed();
            return;
        };
        for (slot, &y) in self.c.iter_mut().zip(&q.c[..q.len]) {
            match y.checked_mul(s).and_then(|p| slot.checked_add(p)) {
                Some(v) => *slot = v,
                None => {
                    *self = SmallPoly::overflowed();
                    return;
                }
            }
        }
        self.len = self.len.max(q.len);
        self.trim();
    }

    /// Coefficientwise `op`, overflow propagated.
    fn zip(&self, o: &SmallPoly, op: impl Fn(i128, i128) -> Option<i128>) -> SmallPoly {
        if self.overflow || o.overflow {
            return SmallPoly::overflowed();
        }
        let mut out = SmallPoly::zero();
        out.len = self.len.max(o.len);
        for (slot, (&x, &y)) in out.c.iter_mut().zip(self.c.iter().zip(&o.c)).take(out.len) {
            match op(x, y) {
                Some(v) => *slot = v,
                None => return SmallPoly::overflowed(),
            }
        }
        out.trim();
        out
    }
}

impl RingOps for SmallPoly {
    fn zero() -> Self {
        SmallPoly {
            c: [0; CAP],
            len: 0,
            overflow: false,
        }
    }
    fn one() -> Self {
        SmallPoly::from_i64(1)
    }
    fn from_i64(v: i64) -> Self {
        let mut c = [0; CAP];
        c[0] = v as i128;
        SmallPoly::from_array(c, 1)
    }
    fn is_zero(&self) -> bool {
        !self.overflow && self.len == 0
    }
    fn plus(&self, o: &Self) -> Self {
        self.zip(o, i128::checked_add)
    }
    fn minus(&self, o: &Self) -> Self {
        self.zip(o, i128::checked_sub)
    }
    /// `0 + self·o` in place ([`RingOps::add_product`] on a zero built
    /// where the result lives: no copy of the slots on return).
    fn times(&self, o: &Self) -> Self {
        let mut out = SmallPoly::zero();
        out.accumulate(self, o, false);
        out
    }
    fn negated(&self) -> Self {
        self.zip(&SmallPoly::zero(), |x, _| x.checked_neg())
    }
    /// `Σ_k (2·Σ_(i<j, i+j=k) x_i·x_j + x_(k/2)²)·t^k`: half the products
    /// of [`RingOps::times`], the same value. Its sums are bounded by the
    /// product's (`Σ |x_i·x_j| < 2^126`), so where that bound holds no
    /// partial sum overflows; elsewhere [`RingOps::times`], checked.
    fn squared(&self) -> Self {
        let n = self.len;
        let b = self.max_bits();
        if self.overflow
            || n == 0
            || 2 * n - 1 > CAP
            || 2 * b + u64::from(usize::BITS - n.leading_zeros()) > 126
        {
            return self.times(self);
        }
        let mut out = SmallPoly::zero();
        let x = &self.c[..n];
        // The bound makes every coefficient shorter than 2^63 (`2·b < 126`):
        // one widening word multiplication per term.
        let mul = |p: i128, q: i128| i128::from(p as i64) * i128::from(q as i64);
        for (i, &xi) in x.iter().enumerate() {
            for (slot, &xj) in out.c[2 * i + 1..].iter_mut().zip(&x[i + 1..]) {
                *slot += mul(xi, xj);
            }
        }
        for (k, slot) in out.c[..2 * n - 1].iter_mut().enumerate() {
            *slot *= 2;
            if k % 2 == 0 {
                *slot += mul(x[k / 2], x[k / 2]);
            }
        }
        out.len = 2 * n - 1;
        out.trim();
        out
    }
    /// In place: `c_k ← c_k ± Σ_{i+j=k} x_i·y_j` on the slots themselves,
    /// without the product's 17-slot temporary. Plain machine arithmetic
    /// when the sizes bound every running sum below `2^127`
    /// (`|c_k| < 2^126` and `Σ |x_i·y_j| < 2^126`), checked otherwise;
    /// an overflow (or a product of degree above the capacity) marks the
    /// result, as `self.plus(&x.times(y))` would.
    fn add_product(&mut self, x: &Self, y: &Self, negate: bool) {
        self.accumulate(x, y, negate);
    }
    /// The product built in `self`'s slots: a product returned by value
    /// is built in a temporary and its 288 bytes copied (a `memcpy` call).
    fn set_product(&mut self, x: &Self, y: &Self) {
        self.clear();
        self.accumulate(x, y, false);
    }
    /// The sum built in `self`'s slots, as [`SmallPoly::set_product`].
    fn plus_assign(&mut self, o: &Self) {
        if self.overflow || o.overflow {
            *self = SmallPoly::overflowed();
            return;
        }
        let len = self.len.max(o.len);
        for (slot, &y) in self.c.iter_mut().zip(&o.c).take(len) {
            match slot.checked_add(y) {
                Some(v) => *slot = v,
                None => {
                    *self = SmallPoly::overflowed();
                    return;
                }
            }
        }
        self.len = len;
        self.trim();
    }
    /// Exact division; a coefficient `k` does not divide counts as an
    /// overflow (the exact value is not in `ℤ[t]`).
    fn div_small(&self, k: i64) -> Self {
        self.div_exact_int(k.into())
    }
}

impl SmallPoly {
    /// [`RingOps::add_product`], inlined into [`RingOps::times`] so that
    /// the product is built where it is returned.
    #[inline(always)]
    fn accumulate(&mut self, x: &Self, y: &Self, negate: bool) {
        if self.overflow || x.overflow || y.overflow {
            *self = SmallPoly::overflowed();
            return;
        }
        if x.len == 0 || y.len == 0 {
            return;
        }
        let len = x.len + y.len - 1;
        if len > CAP {
            *self = SmallPoly::overflowed();
            return;
        }
        let terms = x.len.min(y.len) as u32;
        let (xb, yb) = (x.max_bits(), y.max_bits());
        let safe = self.max_bits() <= 126 && xb + yb + u64::from(32 - terms.leading_zeros()) <= 126;
        // Factors below 2^63 in size: one widening word multiplication per
        // term rather than a full 128-bit one (the same products).
        let narrow = safe && xb <= 63 && yb <= 63;
        for (i, &xi) in x.c[..x.len].iter().enumerate() {
            if xi == 0 {
                continue;
            }
            if narrow {
                // |x_i| < 2^63: its negation fits i64.
                let xi = if negate { -xi } else { xi } as i64;
                for (slot, &yj) in self.c[i..].iter_mut().zip(&y.c[..y.len]) {
                    *slot += i128::from(xi) * i128::from(yj as i64);
                }
                continue;
            }
            if safe {
                // |x_i| < 2^126: its negation fits.
                let xi = if negate { -xi } else { xi };
                for (slot, &yj) in self.c[i..].iter_mut().zip(&y.c[..y.len]) {
                    *slot += xi * yj;
                }
                continue;
            }
            for (slot, &yj) in self.c[i..].iter_mut().zip(&y.c[..y.len]) {
                let next = xi.checked_mul(yj).and_then(|p| {
                    if negate {
                        slot.checked_sub(p)
                    } else {
                        slot.checked_add(p)
                    }
                });
                match next {
                    Some(v) => *slot = v,
                    None => {
                        *self = SmallPoly::overflowed();
                        return;
                    }
                }
            }
        }
        self.len = self.len.max(len);
        self.trim();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::zpoly;
    use proptest::prelude::*;

    proptest! {
        /// The symmetric squaring is the product by itself, overflow and
        /// all, at every coefficient size (across the word-sized and the
        /// overflow boundaries) and length (past half the capacity).
        #[test]
        fn squared_is_times(
            raw in proptest::collection::vec((proptest::num::u128::ANY, proptest::bool::ANY), 0..11),
            bits in 1u32..128,
        ) {
            // Magnitudes below 2^bits, the largest often exactly `bits` long.
            let c: Vec<i128> = raw
                .iter()
                .map(|&(v, negative)| {
                    let m = (v >> (128 - bits)) as i128;
                    if negative { -m } else { m }
                })
                .collect();
            let mut slots = [0i128; CAP];
            slots[..c.len()].copy_from_slice(&c);
            let p = SmallPoly::from_array(slots, c.len());
            prop_assert_eq!(p.squared().to_zpoly(), p.times(&p).to_zpoly());
        }

        /// Interpolating the values at `deg + 1 + extra` consecutive
        /// integers gives the polynomial back, whenever every number on
        /// the way fits, at
        /// every size up to past `i128` (then marked, never wrong); a
        /// perturbed value gives another polynomial or none.
        #[test]
        fn interpolation_inverts_evaluation(
            p in zpoly(10, 60),
            first in -8i64..8,
            extra in 0usize..4,
            bump in 0usize..14,
        ) {
            let n = (p.degree().unwrap_or(0) + 1 + extra).min(CAP);
            // The exact values, marked where they do not fit i128.
            let mut values: Vec<SmallInt> = (0..n)
                .map(|i| SmallInt::of(&p.eval_int(&Int::from(first + i as i64))))
                .collect();
            let back = SmallPoly::interpolate(first, &values);
            if back.is_exact() {
                prop_assert_eq!(back.to_zpoly(), Some(p.clone()));
            } else {
                prop_assert!(values.iter().any(|v| v.to_i128().is_none()) || p.max_bits() > 40);
            }
            if bump < n && values.iter().all(|v| v.to_i128().is_some()) {
                values[bump] = values[bump].plus(&SmallInt::one());
                let other = SmallPoly::interpolate(first, &values);
                prop_assert!(other.to_zpoly() != Some(p));
            }
        }

        /// Every operation agrees with `ZPoly` or reports an overflow, and
        /// small inputs never overflow.
        #[test]
        fn ring_ops_agree_with_zpoly(a in zpoly(6, 120), b in zpoly(6, 120)) {
            let (sa, sb) = (SmallPoly::from_zpoly(&a), SmallPoly::from_zpoly(&b));
            prop_assert_eq!(sa.is_some(), a.max_bits() <= 127);
            let (Some(sa), Some(sb)) = (sa, sb) else { return Ok(()) };
            let check = |s: SmallPoly, z: ZPoly, small: bool| -> Result<(), TestCaseError> {
                match s.to_zpoly() {
                    Some(p) => prop_assert_eq!(p, z),
                    None => prop_assert!(!small),
                }
                Ok(())
            };
            let small = a.max_bits() < 60 && b.max_bits() < 60;
            check(sa.plus(&sb), &a + &b, small)?;
            check(sa.minus(&sb), &a - &b, small)?;
            check(sa.times(&sb), &a * &b, small)?;
            check(sa.negated(), -&a, small)?;
            // In-place multiply-accumulate: a ± a·b against ZPoly.
            for negate in [false, true] {
                let mut acc = sa.clone();
                acc.add_product(&sa, &sb, negate);
                let z = if negate { &a - &(&a * &b) } else { &a + &(&a * &b) };
                check(acc, z, small)?;
            }
            // Exact division: the product by b divides back to a; a + 1
            // over b divides exactly when ZPoly says so.
            if !b.is_zero() {
                if let Some(q) = sa.times(&sb).div_exact(&sb) {
                    check(q, a.clone(), small)?;
                } else {
                    prop_assert!(false, "a·b / b must divide");
                }
                let a1 = &a + &ZPoly::one();
                if let Some(sa1) = SmallPoly::from_zpoly(&a1) {
                    match (sa1.div_exact(&sb), a1.div_exact(&b)) {
                        (None, z) => prop_assert!(z.is_none()),
                        (Some(q), Some(z)) => check(q, z, small)?,
                        (Some(q), None) => prop_assert!(!q.is_exact()),
                    }
                }
            }
            check(sa.times(&SmallPoly::from_i64(6)).div_small(3), &a * &ZPoly::from_i64s(&[2]), small)?;
        }

        /// The in-place operations are the by-value ones, whatever the
        /// slot held before (a longer value, an overflowed one): the same
        /// representation (slots, length, overflow marker), with operands
        /// and old slots that are overflowed or whose sums overflow part
        /// way through.
        #[test]
        fn in_place_operations_are_the_by_value_ones(
            a in zpoly(9, 127),
            b in zpoly(9, 127),
            old in zpoly(17, 127),
            overflowed in proptest::bool::ANY,
            operand_overflowed in 0u8..4,
            k in -40i128..40,
            wide in zpoly(20, 130),
        ) {
            let (Some(sa), Some(sb)) = (SmallPoly::from_zpoly(&a), SmallPoly::from_zpoly(&b)) else {
                return Ok(());
            };
            // An overflowed operand now and then (x, y or both).
            let (sa, sb) = match operand_overflowed {
                1 => (SmallPoly::overflowed(), sb),
                2 => (sa, SmallPoly::overflowed()),
                _ => (sa, sb),
            };
            let before = if overflowed {
                SmallPoly::overflowed()
            } else {
                SmallPoly::from_zpoly(&old).expect("i128 coefficients")
            };
            // The whole representation: slots, length and marker.
            let same = |x: &SmallPoly, y: &SmallPoly| {
                x.c == y.c && x.len == y.len && x.overflow == y.overflow
            };
            // Lowering and constants, past the capacity and past i128 too.
            let mut l = before.clone();
            l.set_lowered(&wide);
            prop_assert!(same(&l, &SmallPoly::lowered(&wide)), "set_lowered");
            let c = SmallInt::of(wide.coeffs().first().unwrap_or(&Int::zero()));
            let mut lc = before.clone();
            lc.set_constant(&c);
            prop_assert!(same(&lc, &SmallPoly::constant(&c)), "set_constant");
            let mut p = before.clone();
            p.set_product(&sa, &sb);
            prop_assert!(same(&p, &sa.times(&sb)), "set_product");
            // Sums of 127-bit coefficients overflow part way through.
            let mut q = sa.clone();
            q.plus_assign(&sb);
            prop_assert!(same(&q, &sa.plus(&sb)), "plus_assign");
            // Leading coefficients that cancel (the length must shrink).
            let cancel = sa.negated().plus(&sb.times(&SmallPoly::from_zpoly(&ZPoly::from_i64s(&[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1])).expect("t^10")));
            let mut z = sa.clone();
            z.plus_assign(&cancel);
            prop_assert!(same(&z, &sa.plus(&cancel)), "plus_assign that cancels");
            let mut r = before.clone();
            r.plus_assign(&sa);
            prop_assert!(same(&r, &before.plus(&sa)), "plus_assign onto the old slot");
            // Exact and inexact divisions, k = 0 and k = −1 included.
            for base in [sa.times(&SmallPoly::from_i64(3)), sa.clone(), before.clone()] {
                let mut d = base.clone();
                d.div_exact_int_assign(k);
                prop_assert!(same(&d, &base.div_exact_int(k)), "div_exact_int_assign");
            }
        }
    }

    #[test]
    fn overflow_is_sticky() {
        let big = SmallPoly::from_i64(i64::MAX);
        let over = big.times(&big).times(&big);
        assert!(over.to_zpoly().is_none() && !over.is_zero());
        assert!(over.minus(&over).to_zpoly().is_none());
        let x = SmallPoly::from_zpoly(&ZPoly::from_i64s(&[0, 1])).unwrap();
        let mut p = SmallPoly::one();
        for _ in 0..SmallPoly::MAX_DEGREE {
            p = p.times(&x);
        }
        assert!(p.to_zpoly().is_some());
        assert!(p.times(&x).to_zpoly().is_none(), "degree past the capacity");
    }
}
