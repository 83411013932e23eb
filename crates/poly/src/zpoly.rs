//! [`ZPoly`]: dense polynomials in `Z[t]` in the power basis.

use crate::mul::mul_coeffs;
use ccd_arith::{Int, Interval, Rat, Ring};
use std::ops::{Add, AddAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A dense integer polynomial `p(t) = Σ_i coeffs[i]·t^i` in the power basis,
/// with no trailing zero coefficients (the zero polynomial has none).
///
/// ```
/// use ccd_poly::ZPoly;
/// let p = ZPoly::from_i64s(&[-1, 0, 1]); // t² − 1
/// let q = ZPoly::from_i64s(&[1, 1]); //     t + 1
/// assert_eq!(p.div_exact(&q), Some(ZPoly::from_i64s(&[-1, 1])));
/// assert_eq!(p.gcd(&ZPoly::from_i64s(&[2, 2, 0, 0])), q);
/// ```
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct ZPoly {
    c: Vec<Int>,
}

/// Drops trailing zero coefficients.
fn trim(c: &mut Vec<Int>) {
    while c.last().is_some_and(Int::is_zero) {
        c.pop();
    }
}

/// `Σ_i c_i x^i y^(n−i)` with `n = len − 1`: the homogenized Horner scheme
/// (`0` for an empty slice). With `y = q > 0` and `x = p` it is
/// `q^n·f(p/q)` for `f = Σ c_i t^i`, so it carries the exact sign of `f(p/q)`.
pub(crate) fn hom_horner(c: &[Int], x: &Int, y: &Int) -> Int {
    hom_horner_impl::<false>(c, x, y).0
}

/// [`hom_horner`] together with the homogeneous derivative
/// `Σ_{i≥1} i·c_i x^(i−1) y^(n−i) = y^(n−1)·f′(x/y)`, in one pass and
/// without forming `f′`: the Horner partial sums `A_i = y^(n−i)·B_i`
/// (`B_i = Σ_{l≥i} c_l (x/y)^(l−i)`) give `y^(n−1)·f′(x/y) = Σ_{i≥1} A_i x^(i−1)`,
/// a second Horner run in `x` over them.
pub(crate) fn hom_horner_with_derivative(c: &[Int], x: &Int, y: &Int) -> (Int, Int) {
    hom_horner_impl::<true>(c, x, y)
}

fn hom_horner_impl<const DERIVATIVE: bool>(c: &[Int], x: &Int, y: &Int) -> (Int, Int) {
    let Some((last, rest)) = c.split_last() else {
        return (Int::zero(), Int::zero());
    };
    let mut acc = last.clone();
    let mut dacc = Int::zero();
    // acc ← acc·x + term, with `add` adding the term in place (and the
    // derivative's Horner run on the old acc first).
    let mut step = |acc: &mut Int, add: &dyn Fn(&mut Int)| {
        if DERIVATIVE {
            dacc = &dacc * x + &*acc;
        }
        *acc = &*acc * x;
        add(acc);
    };
    let k = y.trailing_zeros().unwrap_or(0);
    if y.is_one() {
        for ci in rest.iter().rev() {
            step(&mut acc, &|a| *a += ci);
        }
    } else if y.bits() == k + 1 {
        // y = 2^k (every dyadic point): c_i·y^(n−i) is a shift, so each
        // step costs time linear in the size of the numbers, not a product.
        for (j, ci) in rest.iter().rev().enumerate() {
            step(&mut acc, &|a| *a += ci.shl(k * (j as u64 + 1)));
        }
    } else {
        let mut ypow = Int::one();
        for ci in rest.iter().rev() {
            ypow *= y;
            let yp = &ypow;
            step(&mut acc, &|a| a.add_mul(ci, yp));
        }
    }
    (acc, dacc)
}

/// Replaces `c` (a coefficient vector, zeros allowed anywhere) by the
/// coefficients of `f(t + s)`: `n(n−1)/2` steps `c_j += s·c_{j+1}`; for
/// `s = ±1` these are additions.
pub(crate) fn taylor_shift_in_place(c: &mut [Int], s: &Int) {
    let n = c.len();
    if n < 2 || s.is_zero() {
        return;
    }
    let sign = if s.is_one() {
        1
    } else if s.abs().is_one() {
        -1
    } else {
        0
    };
    for i in 0..n - 1 {
        for j in (i..n - 1).rev() {
            let (lo, hi) = c.split_at_mut(j + 1);
            match sign {
                1 => lo[j] += &hi[0],
                -1 => lo[j] -= &hi[0],
                _ => lo[j].add_mul(&hi[0], s),
            }
        }
    }
}

/// Binary gcd (`gcd(0, 0) = 0`).
fn gcd_u128(mut a: u128, mut b: u128) -> u128 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

/// `gcd` of the entries, `≥ 0` (`0` when all vanish), stopping as soon as
/// the running gcd is `1`.
pub(crate) fn content_of(c: &[Int]) -> Int {
    // Machine integers when every entry fits (the usual case for the
    // characteristic polynomial of decimal scenes).
    let mut g = Some(0u128);
    for x in c {
        g = g
            .zip(x.to_i128())
            .map(|(g, v)| gcd_u128(g, v.unsigned_abs()));
        if g.is_none_or(|g| g == 1) {
            break;
        }
    }
    if let Some(g) = g {
        return Int::from_i128(g as i128);
    }
    // Start from the smallest coefficient (the gcd divides it), and reduce
    // each larger coefficient modulo the running gcd before the gcd itself:
    // one division instead of a binary gcd on full-size numbers.
    let Some(smallest) = c.iter().filter(|x| !x.is_zero()).min_by_key(|x| x.bits()) else {
        return Int::zero();
    };
    let mut g = smallest.abs();
    for x in c {
        if g.is_one() {
            break;
        }
        if x.is_zero() {
            continue;
        }
        let r = if x.bits() > g.bits() + 64 {
            x.div_rem_trunc(&g).1
        } else {
            x.clone()
        };
        g = g.gcd(&r);
    }
    g
}

impl ZPoly {
    /// The polynomial with the given coefficients (`coeffs[i]` of `t^i`);
    /// trailing zeros are dropped.
    pub fn new(mut coeffs: Vec<Int>) -> ZPoly {
        trim(&mut coeffs);
        ZPoly { c: coeffs }
    }
    /// From machine-integer coefficients, constant term first.
    pub fn from_i64s(c: &[i64]) -> ZPoly {
        ZPoly::new(c.iter().map(|&x| Int::from(x)).collect())
    }
    /// `0`.
    pub fn zero() -> ZPoly {
        ZPoly { c: Vec::new() }
    }
    /// `1`.
    pub fn one() -> ZPoly {
        ZPoly {
            c: vec![Int::one()],
        }
    }
    /// The constant polynomial `c`.
    pub fn constant(c: Int) -> ZPoly {
        ZPoly::new(vec![c])
    }
    /// The variable `t`.
    pub fn x() -> ZPoly {
        ZPoly {
            c: vec![Int::zero(), Int::one()],
        }
    }
    /// `c·t^k`.
    pub fn monomial(c: Int, k: usize) -> ZPoly {
        if c.is_zero() {
            return ZPoly::zero();
        }
        let mut v = vec![Int::zero(); k + 1];
        v[k] = c;
        ZPoly { c: v }
    }
    /// The coefficients, constant term first, without trailing zeros.
    pub fn coeffs(&self) -> &[Int] {
        &self.c
    }
    /// The coefficient vector, constant term first.
    pub fn into_coeffs(self) -> Vec<Int> {
        self.c
    }
    /// The coefficient of `t^i` (zero beyond the degree).
    pub fn coeff(&self, i: usize) -> Int {
        self.c.get(i).cloned().unwrap_or_default()
    }
    /// The degree; `None` for the zero polynomial.
    pub fn degree(&self) -> Option<usize> {
        self.c.len().checked_sub(1)
    }
    /// `self == 0`.
    pub fn is_zero(&self) -> bool {
        self.c.is_empty()
    }
    /// The leading coefficient; `None` for zero.
    pub fn leading(&self) -> Option<&Int> {
        self.c.last()
    }
    /// `max_i bits(|c_i|)` (0 for the zero polynomial).
    pub fn max_bits(&self) -> u64 {
        self.c.iter().map(Int::bits).max().unwrap_or(0)
    }
    /// `c·p`.
    pub fn mul_int(&self, c: &Int) -> ZPoly {
        if c.is_zero() {
            return ZPoly::zero();
        }
        ZPoly {
            c: self.c.iter().map(|x| x * c).collect(),
        }
    }
    /// `p / c` coefficientwise; the caller guarantees `c ≠ 0` divides every
    /// coefficient (checked in debug builds).
    pub fn div_exact_int(&self, c: &Int) -> ZPoly {
        if c.is_one() {
            return self.clone();
        }
        ZPoly {
            c: self.c.iter().map(|x| x.div_exact(c)).collect(),
        }
    }

    /// The exact quotient `q ∈ Z[t]` with `self = q·d`, or `None` when `d`
    /// does not divide `self` in `Z[t]` (or `d = 0`).
    ///
    /// Long division from the top: each quotient coefficient is the exact
    /// integer quotient of the current top coefficient by `lc(d)`; the first
    /// inexact step (or a nonzero remainder) answers `None` at once. Since
    /// the quotient of a division in `Q[t]` is unique, this decides
    /// divisibility in `Z[t]`; for primitive `d` it also decides
    /// divisibility in `Q[t]` (Gauss's lemma).
    pub fn div_exact(&self, d: &ZPoly) -> Option<ZPoly> {
        let (dl, dd) = (d.leading()?, d.degree()?);
        let Some(n) = self.degree() else {
            return Some(ZPoly::zero());
        };
        if n < dd {
            return None;
        }
        // Cheap necessary condition on the lowest terms: t^v ‖ d forces
        // t^v | self and d_v | self_v.
        let v = d.c.iter().position(|x| !x.is_zero()).unwrap_or(0);
        if self.c[..v].iter().any(|x| !x.is_zero()) || !self.c[v].is_divisible_by(&d.c[v]) {
            return None;
        }
        let unit = dl.abs().is_one();
        let mut r = self.c.clone();
        let mut q = vec![Int::zero(); n - dd + 1];
        for k in (0..=n - dd).rev() {
            let top = &r[k + dd];
            if top.is_zero() {
                continue;
            }
            let qk = if unit {
                if dl.is_one() {
                    top.clone()
                } else {
                    -top
                }
            } else {
                let (qk, rem) = top.div_rem_trunc(dl);
                if !rem.is_zero() {
                    return None;
                }
                qk
            };
            let neg = -&qk;
            for (ri, di) in r[k..k + dd].iter_mut().zip(&d.c) {
                ri.add_mul(&neg, di);
            }
            r[k + dd] = Int::zero();
            q[k] = qk;
        }
        if r[..dd].iter().any(|x| !x.is_zero()) {
            return None;
        }
        Some(ZPoly::new(q))
    }

    /// Pseudo-division: `(q, r)` with `lc(d)^(deg self − deg d + 1)·self = q·d + r`
    /// and `deg r < deg d` (for `deg self < deg d`: `q = 0`, `r = self`).
    /// Panics if `d = 0`.
    pub fn pseudo_div_rem(&self, d: &ZPoly) -> (ZPoly, ZPoly) {
        let (dl, dd) = (
            d.leading()
                .expect("pseudo_div_rem: division by the zero polynomial"),
            d.c.len() - 1,
        );
        let Some(n) = self.degree().filter(|&n| n >= dd) else {
            return (ZPoly::zero(), self.clone());
        };
        let mut r = self.c.clone();
        let mut q = vec![Int::zero(); n - dd + 1];
        for k in (0..=n - dd).rev() {
            // r ← lc(d)·r − r_top·t^k·d, q ← lc(d)·q + r_top·t^k.
            let top = std::mem::take(&mut r[k + dd]);
            for x in q.iter_mut().chain(r[..k + dd].iter_mut()) {
                *x *= dl;
            }
            let neg = -&top;
            for (ri, di) in r[k..k + dd].iter_mut().zip(&d.c) {
                ri.add_mul(&neg, di);
            }
            q[k] = top;
        }
        r.truncate(dd);
        (ZPoly::new(q), ZPoly::new(r))
    }

    /// The derivative `p'(t) = Σ i·c_i t^(i−1)`.
    pub fn derivative(&self) -> ZPoly {
        ZPoly::new(
            self.c
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, x)| x.mul_i64(i as i64))
                .collect(),
        )
    }
    /// `p^e` by repeated squaring (`p^0 = 1`).
    pub fn pow(&self, mut e: u32) -> ZPoly {
        let (mut base, mut acc) = (self.clone(), ZPoly::one());
        while e > 0 {
            if e & 1 == 1 {
                acc = &acc * &base;
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        acc
    }
    /// `p(x)` by Horner's scheme.
    pub fn eval_int(&self, x: &Int) -> Int {
        hom_horner(&self.c, x, &Int::one())
    }
    /// `p(x)` exactly: `Σ c_i a^i b^(n−i) / b^n` for `x = a/b`.
    pub fn eval_rat(&self, x: &Rat) -> Rat {
        let n = self.c.len().saturating_sub(1) as u32;
        let num = hom_horner(&self.c, x.numer(), x.denom());
        Rat::new(num, x.denom().pow(n)).expect("a power of a positive denominator is nonzero")
    }
    /// `p(x)·b^n` for `x = a/b` (`b > 0`, `n` the degree) as the integer
    /// `Σ c_i a^i b^(n−i)`: the exact value without a gcd; for a dyadic
    /// `x = a/2^k` it is `p(x)·2^(k·n)`.
    pub fn eval_homogeneous(&self, x: &Rat) -> Int {
        hom_horner(&self.c, x.numer(), x.denom())
    }
    /// `(bⁿ·p(x), bⁿ⁻¹·p′(x))` for `x = a/b`, `n = deg p`: the homogeneous
    /// value and derivative in one Horner pass, without forming `p′`.
    ///
    /// ```
    /// use ccd_arith::{Int, Rat};
    /// use ccd_poly::ZPoly;
    /// let p = ZPoly::from_i64s(&[1, 0, 3]); // 3t² + 1
    /// let x = Rat::from_frac(1, 2);
    /// // 4·p(1/2) = 7, 2·p′(1/2) = 2·3 = 6
    /// assert_eq!(p.eval_homogeneous_with_derivative(&x), (Int::from(7), Int::from(6)));
    /// ```
    pub fn eval_homogeneous_with_derivative(&self, x: &Rat) -> (Int, Int) {
        hom_horner_with_derivative(&self.c, x.numer(), x.denom())
    }
    /// The integers `C(n, i)·bᵢ` for the Bernstein coefficients `bᵢ` of `p`
    /// over `[0, 1]` in degree `n = deg p` (`[0]` for the zero polynomial):
    /// reverse, Taylor shift by 1, reverse, at fixed length — additions
    /// only, no rounding, no gcd.
    ///
    /// ```
    /// use ccd_arith::Int;
    /// use ccd_poly::ZPoly;
    /// // 2 + t = 2·B₀ + 3·B₁; t² = B₂ (its zero constant term is kept).
    /// assert_eq!(ZPoly::from_i64s(&[2, 1]).scaled_bernstein(), [2, 3].map(Int::from));
    /// assert_eq!(ZPoly::from_i64s(&[0, 0, 1]).scaled_bernstein(), [0, 0, 1].map(Int::from));
    /// ```
    pub fn scaled_bernstein(&self) -> Vec<Int> {
        if self.c.is_empty() {
            return vec![Int::zero()];
        }
        // The shift adds at most n bits (the entries are sums of at most
        // 2^n coefficients): machine integers when that fits in i128.
        if self.max_bits() as usize + self.c.len() < 126 {
            let mut v: Vec<i128> = (self.c.iter().rev())
                .map(|c| c.to_i128().expect("fits: guarded by max_bits"))
                .collect();
            let n = v.len();
            for i in 0..n {
                for j in (i..n - 1).rev() {
                    v[j] += v[j + 1];
                }
            }
            return v.into_iter().rev().map(Int::from_i128).collect();
        }
        crate::bernstein::reverse_shift_reverse(self.c.clone(), 1)
    }
    /// Whether `x` passes the rational root theorem for `p = Σ cᵢ tⁱ`: a
    /// root `a/b` in lowest terms has `b | c_n` and `a | c_0`. `false` proves
    /// `p(x) ≠ 0` with two divisibility tests instead of an evaluation.
    ///
    /// ```
    /// use ccd_arith::Rat;
    /// use ccd_poly::ZPoly;
    /// let p = ZPoly::from_i64s(&[-2, 3]); // 3t − 2
    /// assert!(p.admits_rational_root(&Rat::from_frac(2, 3)));
    /// assert!(!p.admits_rational_root(&Rat::from_frac(1, 2)));
    /// assert!(!p.admits_rational_root(&Rat::zero()));
    /// ```
    pub fn admits_rational_root(&self, x: &Rat) -> bool {
        let (Some(first), Some(last)) = (self.c.first(), self.c.last()) else {
            return true;
        };
        if x.numer().is_zero() {
            return first.is_zero();
        }
        last.is_divisible_by(x.denom()) && (first.is_zero() || first.is_divisible_by(x.numer()))
    }
    /// The exact sign of `p(x)`: the sign of the integer `Σ c_i a^i b^(n−i)`
    /// for `x = a/b`, `b > 0` (no gcds, no rationals).
    pub fn sign_at(&self, x: &Rat) -> i32 {
        hom_horner(&self.c, x.numer(), x.denom()).signum()
    }
    /// A certified enclosure of `p(x)` for every `x` in the interval: Horner's
    /// scheme in outward-rounded interval arithmetic. Coefficients wider than
    /// `f64` are first scaled by a common `2^(−s)` and the result scaled back
    /// (an overflowing bound is kept finite on the side that must stay finite,
    /// so the sign survives); it may be wide.
    pub fn eval_interval(&self, x: Interval) -> Interval {
        if self.c.is_empty() {
            return Interval::point(0.0);
        }
        let s = self.max_bits().saturating_sub(900);
        let mut acc = Interval::point(0.0);
        for ci in self.c.iter().rev() {
            acc = acc * x + Interval::from_int_scaled(ci, s as i64);
        }
        scale_up(acc, s)
    }
    /// The content: `gcd` of the coefficients, `≥ 0` (`0` for the zero
    /// polynomial); stops as soon as the running gcd is `1`.
    pub fn content(&self) -> Int {
        content_of(&self.c)
    }
    /// `p / (±content)`, with positive leading coefficient; zero stays zero.
    pub fn primitive_part(&self) -> ZPoly {
        let Some(lc) = self.leading() else {
            return ZPoly::zero();
        };
        let g = self.content();
        let g = if lc.is_negative() { -g } else { g };
        self.div_exact_int(&g)
    }
    /// `p(t + c)`.
    pub fn taylor_shift(&self, c: &Int) -> ZPoly {
        let mut v = self.c.clone();
        taylor_shift_in_place(&mut v, c);
        ZPoly::new(v)
    }
    /// The primitive integer polynomial `P(u) = κ·p(a + b·u)` for some
    /// rational `κ > 0` (the sign of `p(a + b·u)` is kept; `b ≠ 0` keeps the
    /// degree). With `d = lcm(den a, den b)`, `a = α/d`, `b = β/d`:
    /// `d^n p((α + βu)/d) = Σ_i [shift_α (Σ_j c_j d^(n−j) t^j)]_i β^i u^i`.
    pub fn compose_affine(&self, a: &Rat, b: &Rat) -> ZPoly {
        let Some(n) = self.degree() else {
            return ZPoly::zero();
        };
        let d = a.denom().lcm(b.denom());
        let alpha = a.numer() * &d.div_exact(a.denom());
        let beta = b.numer() * &d.div_exact(b.denom());
        let mut v = self.c.clone();
        if !d.is_one() {
            // c_j d^(n−j), from the top.
            let mut dp = Int::one();
            for x in v[..n].iter_mut().rev() {
                dp *= &d;
                *x *= &dp;
            }
        }
        taylor_shift_in_place(&mut v, &alpha);
        if !beta.is_one() {
            let mut bp = Int::one();
            for x in v[1..].iter_mut() {
                bp *= &beta;
                *x *= &bp;
            }
        }
        let p = ZPoly::new(v);
        p.div_exact_int(&p.content())
    }
    /// `t^n p(1/t)` with `n = deg p`: the coefficients reversed (the degree
    /// drops by the multiplicity of the root `0`).
    pub fn reverse(&self) -> ZPoly {
        ZPoly::new(self.c.iter().rev().cloned().collect())
    }
    /// The greatest common divisor over `Q[t]`, returned primitive with a
    /// positive leading coefficient (`gcd(0, 0) = 0`, `gcd(p, 0) = pp(p)`);
    /// computed by the modular algorithm of [`crate::modular`].
    pub fn gcd(&self, other: &ZPoly) -> ZPoly {
        crate::modular::gcd(self, other)
    }
    /// The squarefree part `pp(p / gcd(p, p'))`: the product of the distinct
    /// irreducible factors of `p`, primitive with positive leading coefficient.
    pub fn squarefree_part(&self) -> ZPoly {
        if self.degree().is_none_or(|n| n == 0) || crate::modular::squarefree_by_prime(self) {
            return self.primitive_part();
        }
        let g = self.gcd(&self.derivative());
        if g.degree() == Some(0) {
            return self.primitive_part();
        }
        self.div_exact(&g)
            .expect("gcd(p, p') divides p in Z[t] (primitive divisor)")
            .primitive_part()
    }
    /// Approximate `f64` coefficients (not certified), constant term first.
    pub fn to_f64(&self) -> Vec<f64> {
        self.c.iter().map(Int::to_f64).collect()
    }
}

/// `x·2^s` as a certified enclosure: a bound that overflows is replaced by
/// `±f64::MAX` on the side where it must stay a valid bound, and `±∞` on
/// the other.
fn scale_up(x: Interval, s: u64) -> Interval {
    if s == 0 {
        return x;
    }
    let f = |v: f64| {
        let mut r = v;
        let mut k = s;
        while k > 0 && r.is_finite() {
            let step = k.min(1000);
            r *= 2f64.powi(step as i32);
            k -= step;
        }
        r
    };
    let (lo, hi) = (f(x.lo), f(x.hi));
    // A finite lower bound that overflowed to +∞ stays a valid bound as MAX.
    let lo = if lo == f64::INFINITY { f64::MAX } else { lo };
    let hi = if hi == f64::NEG_INFINITY {
        f64::MIN
    } else {
        hi
    };
    Interval::new(lo, hi)
}

/// Coefficientwise `a + sign·b`.
fn add_signed(a: &ZPoly, b: &ZPoly, negate_b: bool) -> ZPoly {
    let n = a.c.len().max(b.c.len());
    let v = (0..n)
        .map(|i| match (a.c.get(i), b.c.get(i)) {
            (Some(x), Some(y)) if negate_b => x - y,
            (Some(x), Some(y)) => x + y,
            (Some(x), None) => x.clone(),
            (None, Some(y)) if negate_b => -y,
            (None, Some(y)) => y.clone(),
            (None, None) => unreachable!("index below the longer length"),
        })
        .collect();
    ZPoly::new(v)
}

impl Add<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    fn add(self, o: &ZPoly) -> ZPoly {
        add_signed(self, o, false)
    }
}
impl Sub<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    fn sub(self, o: &ZPoly) -> ZPoly {
        add_signed(self, o, true)
    }
}
impl Mul<&ZPoly> for &ZPoly {
    type Output = ZPoly;
    /// The product, by [`crate::mul::mul_coeffs`] (schoolbook, Kronecker or
    /// multimodular by size).
    fn mul(self, o: &ZPoly) -> ZPoly {
        ZPoly::new(mul_coeffs(&self.c, &o.c))
    }
}
impl Neg for &ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        ZPoly {
            c: self.c.iter().map(|x| -x).collect(),
        }
    }
}
impl Neg for ZPoly {
    type Output = ZPoly;
    fn neg(self) -> ZPoly {
        ZPoly {
            c: self.c.into_iter().map(|x| -x).collect(),
        }
    }
}

/// The owned and mixed operator forms, and the compound assignments,
/// delegating to the `&T op &T` implementations.
macro_rules! forward_binops {
    ($t:ty) => {
        forward_binops!(@one $t, Add, add, AddAssign, add_assign);
        forward_binops!(@one $t, Sub, sub, SubAssign, sub_assign);
        forward_binops!(@one $t, Mul, mul, MulAssign, mul_assign);
    };
    (@one $t:ty, $tr:ident, $m:ident, $tra:ident, $ma:ident) => {
        impl $tr<$t> for $t {
            type Output = $t;
            fn $m(self, o: $t) -> $t {
                (&self).$m(&o)
            }
        }
        impl $tr<&$t> for $t {
            type Output = $t;
            fn $m(self, o: &$t) -> $t {
                (&self).$m(o)
            }
        }
        impl $tr<$t> for &$t {
            type Output = $t;
            fn $m(self, o: $t) -> $t {
                self.$m(&o)
            }
        }
        impl $tra<&$t> for $t {
            fn $ma(&mut self, o: &$t) {
                *self = (&*self).$m(o);
            }
        }
    };
}
pub(crate) use forward_binops;
forward_binops!(ZPoly);

ccd_arith::ring_ops_via_operators!(ZPoly, zero: ZPoly::zero(), one: ZPoly::one(), from_i64: |v| ZPoly::constant(Int::from(v)), is_zero: |x| ZPoly::is_zero(x), div_small: |a, k| a.div_exact_int(&Int::from(k)));

impl Ring for ZPoly {
    /// The exact quotient in `Z[t]`; panics if `o` does not divide `self`.
    fn div_exact(&self, o: &Self) -> Self {
        ZPoly::div_exact(self, o)
            .expect("Ring::div_exact for ZPoly: the divisor does not divide exactly")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{f64_to_rat, rat, zpoly, zpoly_deg};
    use ccd_arith::RingOps;
    use proptest::prelude::*;

    fn z(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    #[test]
    fn construction_trims_and_reports() {
        let p = ZPoly::new(vec![Int::from(3), Int::zero(), Int::from(-5), Int::zero()]);
        assert_eq!(p.degree(), Some(2));
        assert_eq!(p.leading(), Some(&Int::from(-5)));
        assert_eq!(p.coeff(7), Int::zero());
        assert_eq!(p.max_bits(), 3);
        assert_eq!(ZPoly::zero().degree(), None);
        assert_eq!(ZPoly::monomial(Int::from(4), 3), z(&[0, 0, 0, 4]));
        assert!(ZPoly::monomial(Int::zero(), 3).is_zero());
        assert_eq!(ZPoly::constant(Int::zero()), ZPoly::zero());
        assert_eq!(ZPoly::x().pow(3), z(&[0, 0, 0, 1]));
        assert_eq!(z(&[1, 1]).pow(0), ZPoly::one());
        assert_eq!(z(&[0, 1, 1]).reverse(), z(&[1, 1]));
        assert_eq!(<ZPoly as ccd_arith::RingOps>::from_i64(-2), z(&[-2]));
        assert_eq!(ZPoly::default(), ZPoly::zero());
        assert_eq!(
            z(&[6, -4, 2])
                .mul_int(&Int::from(3))
                .div_exact_int(&Int::from(6)),
            z(&[3, -2, 1])
        );
    }

    #[test]
    fn exact_division_fails_fast_on_non_divisors() {
        let (t1, t2) = (z(&[1, 1]), z(&[2, 2]));
        assert_eq!(t2.div_exact(&t1), Some(z(&[2])));
        assert_eq!(t1.div_exact(&t2), None); // quotient 1/2 ∉ Z[t]
        assert_eq!(t1.div_exact(&ZPoly::zero()), None);
        assert_eq!(ZPoly::zero().div_exact(&t1), Some(ZPoly::zero()));
        assert_eq!(z(&[1]).div_exact(&t1), None);
        assert_eq!(z(&[0, 0, 3, 3]).div_exact(&z(&[0, 1, 1])), Some(z(&[0, 3])));
        assert_eq!(z(&[1, 0, 3, 3]).div_exact(&z(&[0, 1, 1])), None);
        let (q, r) = z(&[1, 2, 3, 4]).pseudo_div_rem(&z(&[1, 2]));
        // 2³·(4t³ + 3t² + 2t + 1) = q·(2t + 1) + r
        assert_eq!(&(&q * &z(&[1, 2])) + &r, z(&[8, 16, 24, 32]));
        assert_eq!(r.degree(), Some(0));
    }

    #[test]
    fn interval_evaluation_of_huge_coefficients_keeps_the_sign() {
        let big = Int::one().shl(3000);
        let p = ZPoly::new(vec![-&big, Int::zero(), big.clone()]); // 2^3000 (t² − 1)
        let at = |x: f64| p.eval_interval(Interval::point(x));
        assert_eq!(at(2.0).sign(), Some(1));
        assert_eq!(at(0.5).sign(), Some(-1));
        assert!(at(1.0).contains_zero());
        assert_eq!(
            ZPoly::zero().eval_interval(Interval::point(3.0)).sign(),
            Some(0)
        );
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        #[test]
        fn ring_identities(a in zpoly(12, 300), b in zpoly(12, 300), c in zpoly(12, 300)) {
            prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
            prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
            prop_assert_eq!(&a * &b, &b * &a);
            prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
            prop_assert!((&a - &a).is_zero());
            prop_assert_eq!(-(-a.clone()), a.clone());
            prop_assert_eq!(&a * &ZPoly::one(), a.clone());
            let mut s = a.clone();
            s += &b;
            s -= &c;
            prop_assert_eq!(s, a.plus(&b).minus(&c));
            prop_assert_eq!(a.times(&b).negated(), -(a.clone() * b.clone()));
        }

        #[test]
        fn exact_division_inverts_products(a in zpoly(10, 200), b in zpoly_deg(0, 8, 200), c in any::<i64>()) {
            let ab = &a * &b;
            prop_assert_eq!(ab.div_exact(&b), Some(a.clone()));
            prop_assert_eq!(<ZPoly as Ring>::div_exact(&ab, &b), a.clone());
            // Adding a nonzero constant when deg b ≥ 1 breaks divisibility.
            if b.degree() >= Some(1) && c != 0 {
                prop_assert_eq!((&ab + &z(&[c])).div_exact(&b), None);
            }
        }

        #[test]
        fn evaluation_is_consistent(p in zpoly(10, 200), q in zpoly(6, 100), x in rat(), n in any::<i32>()) {
            let v = p.eval_rat(&x);
            prop_assert_eq!(p.sign_at(&x), v.signum());
            prop_assert_eq!(Rat::from_int(p.eval_int(&Int::from(n))), p.eval_rat(&Rat::from(n as i64)));
            prop_assert_eq!((&p * &q).eval_rat(&x), &v * &q.eval_rat(&x));
            // Product rule and the Taylor coefficient: [p(t + c)]_1 = p'(c).
            prop_assert_eq!((&p * &q).derivative(), &(&p.derivative() * &q) + &(&p * &q.derivative()));
            let c = Int::from(n % 1000);
            prop_assert_eq!(p.taylor_shift(&c).coeff(1), p.derivative().eval_int(&c));
            prop_assert_eq!(p.taylor_shift(&c).eval_rat(&x), p.eval_rat(&(&x + &Rat::from_int(c))));
            let iv = p.eval_interval(ccd_arith::Interval::from_rat(&x));
            if iv.lo.is_finite() { prop_assert!(f64_to_rat(iv.lo) <= v); }
            if iv.hi.is_finite() { prop_assert!(v <= f64_to_rat(iv.hi)); }
            let f = p.to_f64();
            prop_assert_eq!(f.len(), p.coeffs().len());
        }

        #[test]
        fn content_and_primitive_part(p in zpoly_deg(0, 10, 200), c in 1i64..10_000, neg in any::<bool>()) {
            let c = Int::from(if neg { -c } else { c });
            let pp = p.primitive_part();
            prop_assert!(pp.leading().is_some_and(|l| l.is_positive()));
            prop_assert!(pp.content().is_one());
            let scaled = p.mul_int(&c);
            prop_assert_eq!(scaled.content(), &p.content() * &c.abs());
            prop_assert_eq!(scaled.primitive_part(), pp.clone());
            prop_assert_eq!(pp.mul_int(&p.content()), if p.leading().is_some_and(|l| l.is_negative()) { -p.clone() } else { p.clone() });
        }

        /// The machine-integer Bernstein conversion agrees with the
        /// big-integer one, on both sides of the `i128` limit.
        #[test]
        fn scaled_bernstein_matches_the_exact_shift(p in zpoly_deg(0, 20, 120)) {
            let want = if p.is_zero() { vec![Int::zero()] } else { crate::bernstein::reverse_shift_reverse(p.coeffs().to_vec(), 1) };
            prop_assert_eq!(p.scaled_bernstein(), want);
        }

        /// The machine-integer content agrees with big-integer gcds, on
        /// both sides of the `i128` limit.
        #[test]
        fn content_matches_pairwise_gcds(p in zpoly_deg(0, 10, 140), c in 1i64..1_000_000) {
            let scaled = p.mul_int(&Int::from(c));
            let want = scaled.coeffs().iter().fold(Int::zero(), |g, x| g.gcd(x));
            prop_assert_eq!(scaled.content(), want);
        }

        #[test]
        fn affine_composition(p in zpoly_deg(0, 9, 150), a in rat(), b in rat(), u in rat()) {
            prop_assume!(!b.is_zero());
            let q = p.compose_affine(&a, &b);
            let n = p.degree().unwrap_or(0);
            prop_assert_eq!(q.degree(), p.degree());
            prop_assert!(q.content().is_one());
            let mut bn = Rat::one();
            for _ in 0..n { bn = &bn * &b; }
            let kappa = &Rat::from_int(q.leading().cloned().unwrap_or_default()) / &(&Rat::from_int(p.leading().cloned().unwrap_or_default()) * &bn);
            prop_assert!(kappa.signum() > 0);
            prop_assert_eq!(q.eval_rat(&u), &kappa * &p.eval_rat(&(&a + &(&b * &u))));
        }

        #[test]
        fn reverse_is_reciprocal(p in zpoly_deg(0, 10, 100), x in rat()) {
            prop_assume!(!x.is_zero() && !p.coeff(0).is_zero());
            let n = p.degree().unwrap_or(0);
            let mut xn = Rat::one();
            for _ in 0..n { xn = &xn * &x; }
            prop_assert_eq!(p.reverse().eval_rat(&x), &xn * &p.eval_rat(&(Rat::one() / &x)));
        }

        /// The rational root theorem filter never rejects a root, and a
        /// rejection always means a nonzero value.
        #[test]
        fn rational_root_filter_is_sound(q in zpoly(6, 40), a in -50i64..50, b in 1i64..50) {
            let x = Rat::from_frac(a, b);
            let root = ZPoly::from_i64s(&[-a, b]) * q.clone();
            prop_assert!(q.is_zero() || root.admits_rational_root(&x));
            if !q.admits_rational_root(&x) {
                prop_assert!(q.sign_at(&x) != 0);
            }
        }

        /// One pass gives the homogeneous value and the homogeneous value of
        /// the derivative, at integer, dyadic and general rational points.
        #[test]
        fn value_with_derivative_matches_separate_passes(p in zpoly(9, 60), a in -300i64..300, b in 1i64..300, dyadic in proptest::bool::ANY) {
            let x = if dyadic { Rat::dyadic(Int::from(a), (b % 40) as u64) } else { Rat::from_frac(a, b) };
            prop_assert_eq!(
                p.eval_homogeneous_with_derivative(&x),
                (p.eval_homogeneous(&x), p.derivative().eval_homogeneous(&x))
            );
        }
    }
}
