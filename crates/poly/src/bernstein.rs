//! [`Bernstein`]: a polynomial in the Bernstein basis of an interval, with
//! integer coefficients times one rational factor, and integer-only
//! conversion, degree elevation and de Casteljau subdivision.
//!
//! Two identities carry all conversions. For `P(u) = Σ_i b_i B_i^n(u)`,
//! `B_i^n(u) = C(n,i) u^i (1−u)^(n−i)`:
//!
//! * `(1+s)^n P(s/(1+s)) = Σ_i C(n,i) b_i s^i`, and in terms of the power
//!   coefficients `a_j` of `P` the left side is `Σ_j a_j s^j (1+s)^(n−j)`,
//!   i.e. reverse, Taylor shift by `1`, reverse. So the *binomially scaled*
//!   coefficients `c_i = C(n,i) b_i` come from the power basis with additions
//!   only, and back with a shift by `−1`.
//! * Degree elevation by `r` multiplies that generating polynomial by
//!   `(1+s)^r`: `Σ_k C(n+r,k) b'_k s^k = (1+s)^r Σ_i C(n,i) b_i s^i`.
//!
//! Dividing the `c_i` by the binomials is the only step leaving `Z`; it is
//! done once per conversion over a common denominator.
//!
//! **Which Bernstein form is for what.** This is the exact form, over `Q`:
//! the certified path's Bernstein coefficients (Descartes' rule of signs,
//! subdivision, enclosures) are these, and every sign read off them is
//! exact. The solver's `FilterBernstein` (in `ccd-solver`) is an `f64`
//! copy of one node's coefficients with proven error bounds, used only to
//! skip integer work where a float sign is already certain; the float
//! path's `BernsteinF64` (in `ccd-float`) is the paper's uncertified `f64`
//! arithmetic. Neither replaces this one where a sign is in doubt.

use crate::mul::mul_coeffs;
use crate::zpoly::eval::hom_horner;
use crate::zpoly::substitution::taylor_shift_in_place;
use crate::{QPoly, ZPoly};
use ccd_arith::{sign_variations, Int, Rat};

/// The Bernstein form of a polynomial of degree `≤ n` on `[lo, hi]`:
/// `value(t) = scale · Σ_i coeffs[i] · B_i^n((t − lo)/(hi − lo))`.
///
/// Normalised so that `scale > 0` (the coefficients carry the signs of the
/// true Bernstein coefficients) and the coefficients have content `1`
/// (for the zero polynomial: `scale = 1`, all coefficients `0`).
///
/// ```
/// use ccd_arith::Rat;
/// use ccd_poly::{Bernstein, ZPoly};
/// // t² − 2 on [1, 2]: Bernstein coefficients −1, 0, 2.
/// let b = Bernstein::from_power(&ZPoly::from_i64s(&[-2, 0, 1]), &Rat::from(1), &Rat::from(2));
/// assert_eq!(b.sign_variations(), 1);
/// let (l, r) = b.split_half();
/// assert_eq!((l.sign_variations(), r.sign_variations()), (1, 0)); // √2 < 1.5
/// ```
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Bernstein {
    lo: Rat,
    hi: Rat,
    scale: Rat,
    coeffs: Vec<Int>,
}

/// The shortest `p` (its longest coefficient's bits) whose substitutions
/// [`Bernstein::from_power_nested`] keeps: measured on the stability
/// scenes' Newton zooms (docs/table4.md, issue 17, session 45).
const NESTED_MIN_BITS: u64 = 1024;

/// `2^m·p(lo + (hi − lo)·u)` for an interval `[lo, hi]` with dyadic ends and
/// a width `2^(−k)`, its integer coefficients not all even: what
/// [`Bernstein::from_power_nested`] keeps to substitute into for the next
/// interval inside this one.
#[derive(Clone, Debug)]
pub struct Substitution {
    lo: Rat,
    hi: Rat,
    coeffs: ZPoly,
}

/// `d^n·q(a + b·u)` (`q.compose_affine_multiple(a, b)`, coefficients low
/// → high) with its common power of two taken out: cheap, and after a
/// substitution with a dyadic `b` the whole content in practice. An odd
/// common factor, if any, stays (as for the children of a split,
/// `normalised` with `content` unset): the gcd that would find it costs
/// more than the conversion on coefficients of thousands of bits.
fn substituted(q: &ZPoly, a: &Rat, b: &Rat) -> Vec<Int> {
    let mut c = q.compose_affine_multiple(a, b).into_coeffs();
    take_out_twos(&mut c);
    c
}

/// Divides `coeffs` by their common power of two `2^tz` and returns `tz`
/// (`None` when every one is 0).
fn take_out_twos(coeffs: &mut [Int]) -> Option<u64> {
    let tz = coeffs.iter().filter_map(Int::trailing_zeros).min()?;
    if tz > 0 {
        coeffs.iter_mut().for_each(|c| *c = c.shr_floor(tz));
    }
    Some(tz)
}

/// The power form `Σ_j a_j u^j` of `Σ_i b_i B_i^n(u)` (`n + 1 = b.len()`) on
/// `[0, 1]` for integer `b_i`: the `a_j` are integers, from
/// reverse–shift(−1)–reverse of `C(n,i)·b_i` (module docs; additions and
/// `n + 1` products only, no rationals). Zero for an empty `b`.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::{bernstein_to_power, ZPoly};
/// // 1·B_0^2 + 5·B_1^2 − 3·B_2^2 = 1 + 8u − 12u².
/// let p = bernstein_to_power(&[1, 5, -3].map(Int::from));
/// assert_eq!(p, ZPoly::from_i64s(&[1, 8, -12]));
/// ```
pub fn bernstein_to_power(b: &[Int]) -> ZPoly {
    if b.is_empty() {
        return ZPoly::zero();
    }
    ZPoly::new(reverse_shift_reverse(times_binomials(b), -1))
}

/// `C(n, 0), …, C(n, n)`.
///
/// ```
/// use ccd_arith::Int;
/// assert_eq!(ccd_poly::binomials(3), [1, 3, 3, 1].map(Int::from));
/// ```
pub fn binomials(n: usize) -> Vec<Int> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c = Int::one();
    for i in 0..=n {
        row.push(c.clone());
        if i < n {
            c = c
                .mul_i64((n - i) as i64)
                .div_exact(&Int::from((i + 1) as i64));
        }
    }
    row
}

/// `(β, f)` with `c_i / C(n, i) = f·β_i`, `f > 0` rational, `β` integer:
/// each `c_i / C(n,i)` is reduced, then brought over the lcm `L` of the
/// reduced denominators (which divides `lcm_i C(n,i)`), so `f = 1/L`.
fn divide_binomials(c: Vec<Int>) -> (Vec<Int>, Rat) {
    let n = c.len() - 1;
    let binom = binomials(n);
    let mut parts = Vec::with_capacity(n + 1);
    let mut l = Int::one();
    for (ci, bi) in c.into_iter().zip(&binom) {
        let g = ci.gcd(bi);
        let (num, den) = if g.is_zero() || g.is_one() {
            (ci, bi.clone())
        } else {
            (ci.div_exact(&g), bi.div_exact(&g))
        };
        let (num, den) = if num.is_zero() {
            (num, Int::one())
        } else {
            (num, den)
        };
        l = l.lcm(&den);
        parts.push((num, den));
    }
    let beta = parts
        .into_iter()
        .map(|(num, den)| {
            if den == l {
                num
            } else {
                num * l.div_exact(&den)
            }
        })
        .collect();
    (beta, Rat::new(Int::one(), l).expect("positive lcm"))
}

/// `β_i · C(n, i)`.
fn times_binomials(beta: &[Int]) -> Vec<Int> {
    beta.iter()
        .zip(binomials(beta.len() - 1))
        .map(|(b, c)| b * &c)
        .collect()
}

/// Reverse, Taylor shift by `s`, reverse (fixed length `n + 1`): maps the
/// power coefficients of `P` to `c_i = C(n,i) b_i` for `s = 1`, and back
/// for `s = −1`.
pub(crate) fn reverse_shift_reverse(mut v: Vec<Int>, s: i64) -> Vec<Int> {
    v.reverse();
    taylor_shift_in_place(&mut v, &Int::from(s));
    v.reverse();
    v
}

/// A multiplier of the de Casteljau triangle: `1`, `2^k`, or general.
enum Factor {
    One,
    Pow2(u64),
    Other(Int),
}

impl Factor {
    fn of(x: &Int) -> Factor {
        match x.exact_log2() {
            Some(0) => Factor::One,
            Some(k) => Factor::Pow2(k),
            None => Factor::Other(x.clone()),
        }
    }
    /// `x ← factor·x`.
    fn scale(&self, x: &mut Int) {
        match self {
            Factor::One => {}
            Factor::Pow2(k) => *x = x.shl(*k),
            Factor::Other(v) => *x *= v,
        }
    }
    /// `x ← x + factor·y`.
    fn add_scaled(&self, x: &mut Int, y: &Int) {
        match self {
            Factor::One => *x += y,
            Factor::Pow2(k) => *x += y.shl(*k),
            Factor::Other(v) => x.add_mul(y, v),
        }
    }
}

impl Bernstein {
    /// `scale · Σ coeffs[i] B_i^n` on `[lo, hi]`, normalised (see the type
    /// docs): the sign of `scale` moves into the coefficients, and their
    /// common power of two and content into `scale`. Panics unless
    /// `lo < hi` and `coeffs` is nonempty.
    pub fn from_parts(lo: Rat, hi: Rat, scale: Rat, coeffs: Vec<Int>) -> Bernstein {
        Bernstein::normalised(lo, hi, scale, coeffs, true)
    }

    /// [`Bernstein::from_parts`], with the odd part of the content removed
    /// only when `content` is set. A de Casteljau child of a normalised
    /// polynomial gains powers of two (the halvings) and almost never an odd
    /// common factor, and the gcd that would find one costs far more than
    /// the split itself once the coefficients have thousands of bits.
    fn normalised(lo: Rat, hi: Rat, scale: Rat, mut coeffs: Vec<Int>, content: bool) -> Bernstein {
        assert!(lo < hi, "Bernstein: empty interval");
        assert!(!coeffs.is_empty(), "Bernstein: no coefficients");
        let mut scale = scale;
        if scale.signum() <= 0 {
            if scale.is_zero() {
                coeffs.iter_mut().for_each(|c| *c = Int::zero());
                return Bernstein {
                    lo,
                    hi,
                    scale: Rat::one(),
                    coeffs,
                };
            }
            scale = -scale;
            coeffs.iter_mut().for_each(|c| *c = -&*c);
        }
        let Some(tz) = take_out_twos(&mut coeffs) else {
            return Bernstein {
                lo,
                hi,
                scale: Rat::one(),
                coeffs,
            };
        };
        if tz > 0 {
            scale = scale.mul_pow2(tz as i64);
        }
        let g = if content {
            crate::zpoly::division::content_of(&coeffs)
        } else {
            Int::one()
        };
        if !g.is_one() {
            coeffs.iter_mut().for_each(|c| *c = c.div_exact(&g));
            scale = &scale * &Rat::from_int(g);
        }
        Bernstein {
            lo,
            hi,
            scale,
            coeffs,
        }
    }

    /// The Bernstein form of `p` on `[lo, hi]` (`lo < hi`), of degree
    /// `deg p` (`0` for constants and zero). With `w = hi − lo`,
    /// `P = p.compose_affine(lo, w) = κ·p(lo + w u)`, `κ = lc(P)/(lc(p) w^n) > 0`;
    /// the Bernstein coefficients of `P` on `[0, 1]` are `c_i / C(n, i)` with
    /// `c` from reverse–shift–reverse (see the module docs); dividing by `κ`
    /// gives those of `p`.
    pub fn from_power(p: &ZPoly, lo: &Rat, hi: &Rat) -> Bernstein {
        assert!(lo < hi, "Bernstein::from_power: need lo < hi");
        if p.is_zero() {
            return Bernstein::from_parts(lo.clone(), hi.clone(), Rat::one(), vec![Int::zero()]);
        }
        Bernstein::from_substituted(p, substituted(p, lo, &(hi - lo)), lo, hi)
    }

    /// [`Bernstein::from_power`] on `[lo, hi]`, from the substitution kept
    /// in `last` where that holds the interval and costs less: for
    /// `[lo, hi] ⊂ [l, h]` with dyadic ends and `h − l = 2^(−k)`,
    /// `p(lo + w·u) = p(l + (h − l)·(a + b·u))` with the dyadic `a = (lo −
    /// l)/(h − l)` and `b = w/(h − l)`, whose denominators are short where
    /// the interval is deep (a root isolation's Newton zooms: `a` has the
    /// zoom's bits, `lo` those of the whole descent). The result is the
    /// very `Bernstein` of [`Bernstein::from_power`]: both substitutions
    /// give a power of two times `p(lo + w·u)`, whose integer multiple with
    /// an odd common content is unique. With `keep` (and dyadic ends, a
    /// width `2^(−k)`), `last` then holds this interval's substitution.
    ///
    /// Which substitution costs less: the Taylor shift's `n²/2` products by
    /// a shift of `s` bits, on coefficients growing from `B` bits by `s` a
    /// step, cost about `s·(B + n·s/2)`: `s` the bits of `lo`'s
    /// denominator and `B` those of `p`, against those of `a`'s and of the
    /// kept coefficients (longer than `p`'s by about `n` times the depth).
    ///
    /// ```
    /// use ccd_arith::Rat;
    /// use ccd_poly::{Bernstein, ZPoly};
    /// let p = ZPoly::from_i64s(&[-2, 0, 3, 1]);
    /// let (mut last, q) = (None, |n, k| Rat::dyadic(ccd_arith::Int::from(n), k));
    /// for (lo, hi) in [(q(0, 0), q(1, 0)), (q(1, 2), q(3, 2)), (q(9, 4), q(37, 6))] {
    ///     let nested = Bernstein::from_power_nested(&p, &lo, &hi, &mut last, true);
    ///     assert_eq!(nested, Bernstein::from_power(&p, &lo, &hi));
    /// }
    /// ```
    pub fn from_power_nested(
        p: &ZPoly,
        lo: &Rat,
        hi: &Rat,
        last: &mut Option<Substitution>,
        keep: bool,
    ) -> Bernstein {
        assert!(lo < hi, "Bernstein::from_power_nested: need lo < hi");
        let dyadic = lo.dyadic_exponent().is_some() && hi.dyadic_exponent().is_some();
        let Some(n) = p.degree().filter(|&n| n > 0 && dyadic) else {
            return Bernstein::from_power(p, lo, hi);
        };
        let (w, p_bits) = (hi - lo, p.max_bits());
        let cost = |s: u64, b: u64| s * (b + n as u64 * s / 2);
        let from_last = last
            .as_ref()
            .filter(|s| &s.lo <= lo && hi <= &s.hi)
            .map(|s| {
                let ws = &s.hi - &s.lo;
                (s, &(lo - &s.lo) / &ws, &w / &ws)
            })
            .filter(|(s, a, b)| {
                let bits = |x: &Rat, y: &Rat| x.denom().bits().max(y.denom().bits());
                cost(bits(a, b), s.coeffs.max_bits()) < cost(bits(lo, &w), p_bits)
            });
        let big_p = match from_last {
            Some((s, a, b)) => substituted(&s.coeffs, &a, &b),
            None => substituted(p, lo, &w),
        };
        // Kept where a nested interval's ratios stay dyadic (a width
        // `2^(−k)`) and `p` is long: on short coefficients the shorter
        // shift saves less than the copy and the ratios cost.
        if keep && w.numer().is_one() && p_bits >= NESTED_MIN_BITS {
            *last = Some(Substitution {
                lo: lo.clone(),
                hi: hi.clone(),
                coeffs: ZPoly::new(big_p.clone()),
            });
        }
        Bernstein::from_substituted(p, big_p, lo, hi)
    }

    /// The Bernstein form of `p` (degree `n`, nonzero) on `[lo, hi]` from
    /// `big_p = κ·p(lo + w·u)` (`w = hi − lo`, some `κ > 0`, coefficients
    /// low → high): `κ = lc(big_p)/(lc(p)·w^n)`; the Bernstein coefficients
    /// of `big_p` on `[0, 1]` are `c_i / C(n, i)` with `c` from
    /// reverse–shift–reverse (module docs); dividing by `κ` gives those of
    /// `p`.
    fn from_substituted(p: &ZPoly, big_p: Vec<Int>, lo: &Rat, hi: &Rat) -> Bernstein {
        let n = big_p.len() - 1;
        let w = hi - lo;
        // `w^n`: a shift where `w = 2^(−k)` (bisections and zooms).
        let wn = match w.dyadic_exponent().filter(|_| w.numer().is_one()) {
            Some(k) => Rat::one().mul_pow2(-((k * n as u64) as i64)),
            None => (0..n).fold(Rat::one(), |x, _| &x * &w),
        };
        let lc_exact = &Rat::from_int(p.leading().expect("nonzero").clone()) * &wn;
        let kappa = &Rat::from_int(big_p[n].clone()) / &lc_exact;
        let c = reverse_shift_reverse(big_p, 1);
        let (beta, f) = divide_binomials(c);
        Bernstein::normalised(lo.clone(), hi.clone(), &f / &kappa, beta, false)
    }
    /// The signs of `p`'s Bernstein coefficients on `[lo, hi]` (those of
    /// [`Bernstein::from_power`]'s coefficients), without `κ`, the division
    /// by the binomials or any content: the coefficients of
    /// `d^n·p(lo + w·u)` after reverse–shift–reverse are `C(n, i)·b_i`
    /// times a positive number.
    pub fn signs_of_power(p: &ZPoly, lo: &Rat, hi: &Rat) -> Vec<i32> {
        assert!(lo < hi, "Bernstein::signs_of_power: need lo < hi");
        if p.is_zero() {
            return vec![0];
        }
        let big_p = p.compose_affine_multiple(lo, &(hi - lo));
        reverse_shift_reverse(big_p.into_coeffs(), 1)
            .iter()
            .map(Int::signum)
            .collect()
    }
    /// The Bernstein form of a rational polynomial: that of its primitive
    /// part, times its scale.
    pub fn from_qpoly(p: &QPoly, lo: &Rat, hi: &Rat) -> Bernstein {
        let b = Bernstein::from_power(p.prim(), lo, hi);
        Bernstein::from_parts(b.lo, b.hi, &b.scale * p.scale(), b.coeffs)
    }
    /// The power form: `P(u) = Σ b_i B_i^n(u)` by reverse–shift(−1)–reverse
    /// of `C(n,i) b_i`, then `value(t) = scale·P((t − lo)/w)`.
    pub fn to_power(&self) -> QPoly {
        let a = reverse_shift_reverse(times_binomials(&self.coeffs), -1);
        let p = QPoly::from_parts(self.scale.clone(), ZPoly::new(a));
        if self.lo.is_zero() && self.hi == Rat::one() {
            return p;
        }
        let w = &self.hi - &self.lo;
        let inv_w = Rat::one() / &w;
        p.compose_affine(&(-&(&self.lo * &inv_w)), &inv_w)
    }
    /// The left end.
    pub fn lo(&self) -> &Rat {
        &self.lo
    }
    /// The right end.
    pub fn hi(&self) -> &Rat {
        &self.hi
    }
    /// The positive rational factor.
    pub fn scale(&self) -> &Rat {
        &self.scale
    }
    /// The integer coefficients (the true Bernstein coefficients divided by `scale`).
    pub fn coeffs(&self) -> &[Int] {
        &self.coeffs
    }
    /// The degree `n` of the basis (`coeffs.len() − 1`).
    pub fn degree(&self) -> usize {
        self.coeffs.len() - 1
    }
    /// The same polynomial in the basis of degree `n + by`:
    /// `C(n+by, k) b'_k = Σ_i C(n,i) b_i C(by, k−i)`.
    pub fn elevate(&self, by: usize) -> Bernstein {
        if by == 0 {
            return self.clone();
        }
        let c = mul_coeffs(&times_binomials(&self.coeffs), &binomials(by));
        let (beta, f) = divide_binomials(c);
        Bernstein::from_parts(self.lo.clone(), self.hi.clone(), &self.scale * &f, beta)
    }
    /// de Casteljau subdivision at the local parameter `r = p/q ∈ (0, 1)`:
    /// the children on `[lo, m]` and `[m, hi]`, `m = lo + (hi − lo)·r`.
    ///
    /// On integers: `b⁽⁰⁾ = coeffs`, `b⁽ᵏ⁾_i = (q−p)·b⁽ᵏ⁻¹⁾_i + p·b⁽ᵏ⁻¹⁾_{i+1}`
    /// (that is `q^k` times the rational triangle), then
    /// `left_k = q^(n−k) b⁽ᵏ⁾_0` and `right_k = q^k b⁽ⁿ⁻ᵏ⁾_k`, both `q^n` times
    /// the exact children, so each child has scale `scale/q^n` before
    /// normalisation. Multipliers equal to `1` or a power of two cost an
    /// addition or a shift (`r = 1/2`: additions and shifts only).
    pub fn split(&self, r: &Rat) -> (Bernstein, Bernstein) {
        assert!(
            r.signum() > 0 && *r < Rat::one(),
            "Bernstein::split: r must lie in (0, 1)"
        );
        let n = self.degree();
        let (p, q) = (r.numer(), r.denom());
        let (fp, fs) = (Factor::of(p), Factor::of(&(q - p)));
        let fq = Factor::of(q);
        // q^j as a factor: a shift for powers of two, else a cached power.
        let qpow: Vec<Int> = match fq {
            Factor::Other(_) => {
                let mut v = vec![Int::one()];
                for j in 1..=n {
                    let next = &v[j - 1] * q;
                    v.push(next);
                }
                v
            }
            _ => Vec::new(),
        };
        let times_qpow = |x: &Int, j: usize| -> Int {
            match &fq {
                Factor::One => x.clone(),
                Factor::Pow2(k) => x.shl(k * j as u64),
                Factor::Other(_) => x * &qpow[j],
            }
        };
        let mut v = self.coeffs.clone();
        let mut left = Vec::with_capacity(n + 1);
        let mut right = vec![Int::zero(); n + 1];
        left.push(times_qpow(&v[0], n));
        right[n] = times_qpow(&v[n], n);
        for k in 1..=n {
            for i in 0..=n - k {
                let (a, b) = v.split_at_mut(i + 1);
                fs.scale(&mut a[i]);
                fp.add_scaled(&mut a[i], &b[0]);
            }
            left.push(times_qpow(&v[0], n - k));
            right[n - k] = times_qpow(&v[n - k], n - k);
        }
        let qn = Rat::from_int(q.pow(n as u32));
        let child_scale = &self.scale / &qn;
        let m = &self.lo + &(&(&self.hi - &self.lo) * r);
        (
            Bernstein::normalised(self.lo.clone(), m.clone(), child_scale.clone(), left, false),
            Bernstein::normalised(m, self.hi.clone(), child_scale, right, false),
        )
    }
    /// [`Bernstein::split`] at `r = 1/2`.
    pub fn split_half(&self) -> (Bernstein, Bernstein) {
        self.split(&Rat::from_frac(1, 2))
    }
    /// The number of sign changes in the coefficient sequence, zeros
    /// skipped (the scale is positive). By Descartes' rule for the Bernstein
    /// basis it bounds the number of roots in `(lo, hi)` counted with
    /// multiplicity, and has the same parity; `0` and `1` are exact counts.
    pub fn sign_variations(&self) -> usize {
        sign_variations(self.coeffs.iter().map(Int::signum))
    }
    /// The exact value at the global parameter `t`: with
    /// `(t − lo)/(hi − lo) = x/y`, `value = scale·Σ C(n,i) β_i x^i (y − x)^(n−i) / y^n`.
    pub fn eval(&self, t: &Rat) -> Rat {
        let u = &(t - &self.lo) / &(&self.hi - &self.lo);
        let (x, y) = (u.numer(), u.denom());
        let num = hom_horner(&times_binomials(&self.coeffs), x, &(y - x));
        let den = y.pow(self.degree() as u32);
        &self.scale * &Rat::new(num, den).expect("positive denominator power")
    }
    /// The exact sign of the value at `lo` (the first coefficient's).
    pub fn sign_at_lo(&self) -> i32 {
        self.coeffs[0].signum()
    }
    /// The exact sign of the value at `hi` (the last coefficient's).
    pub fn sign_at_hi(&self) -> i32 {
        self.coeffs[self.degree()].signum()
    }
    /// `(min_i, max_i)` of the true Bernstein coefficients `scale·coeffs[i]`:
    /// by the convex-hull property every value on `[lo, hi]` lies between.
    pub fn enclosure(&self) -> (Rat, Rat) {
        let lo = self.coeffs.iter().min().expect("nonempty");
        let hi = self.coeffs.iter().max().expect("nonempty");
        (
            &self.scale * &Rat::from_int(lo.clone()),
            &self.scale * &Rat::from_int(hi.clone()),
        )
    }
}

/// [`ZPoly`]'s binomially scaled Bernstein coefficients on `[0, 1]`, kept
/// here with the other conversions (so `zpoly` needs nothing of this module).
impl ZPoly {
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
        match self.coeffs() {
            [] => return vec![Int::zero()],
            // A constant is its own (scaled) Bernstein coefficient.
            [c] => return vec![c.clone()],
            _ => {}
        }
        // The shift adds at most n bits (the entries are sums of at most
        // 2^n coefficients): machine integers when that fits in i128.
        if self.max_bits() as usize + self.coeffs().len() < 126 {
            let mut v: Vec<i128> = (self.coeffs().iter().rev())
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
        reverse_shift_reverse(self.coeffs().to_vec(), 1)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{rat, zpoly, zpoly_deg};
    use proptest::prelude::*;

    /// An interval `[lo, lo + w]` with `w > 0`.
    fn interval() -> impl Strategy<Value = (Rat, Rat)> {
        (rat(), 1i64..1000, 1i64..1000).prop_map(|(lo, n, d)| {
            let hi = &lo + &Rat::from_frac(n, d);
            (lo, hi)
        })
    }

    #[test]
    fn known_small_cases() {
        let z = ZPoly::from_i64s;
        let b = Bernstein::from_power(&z(&[-2, 0, 1]), &Rat::from(1), &Rat::from(2));
        assert_eq!(b.coeffs(), [Int::from(-1), Int::zero(), Int::from(2)]);
        assert_eq!(b.scale(), &Rat::one());
        assert_eq!((b.sign_at_lo(), b.sign_at_hi()), (-1, 1));
        assert_eq!(b.enclosure(), (Rat::from(-1), Rat::from(2)));
        let zero = Bernstein::from_power(&ZPoly::zero(), &Rat::zero(), &Rat::one());
        assert_eq!(
            (
                zero.degree(),
                zero.sign_variations(),
                zero.eval(&Rat::from(5))
            ),
            (0, 0, Rat::zero())
        );
        assert!(zero.to_power().is_zero());
        let c = Bernstein::from_qpoly(
            &QPoly::constant(Rat::from_frac(-3, 7)),
            &Rat::zero(),
            &Rat::one(),
        );
        assert_eq!(
            (c.coeffs(), c.scale()),
            (&[Int::from(-1)][..], &Rat::from_frac(3, 7))
        );
        assert_eq!(
            c.elevate(3).coeffs(),
            [Int::from(-1), Int::from(-1), Int::from(-1), Int::from(-1)]
        );
        let (l, r) = c.split(&Rat::from_frac(1, 3));
        assert_eq!(
            (l.hi(), r.lo(), l.lo(), r.hi()),
            (
                &Rat::from_frac(1, 3),
                &Rat::from_frac(1, 3),
                &Rat::zero(),
                &Rat::one()
            )
        );
    }

    #[test]
    fn positive_polynomial_loses_all_variations_under_subdivision() {
        // 100t² − 100t + 26 = 100(t − 1/2)² + 1 > 0 on [0, 1].
        let b = Bernstein::from_power(
            &ZPoly::from_i64s(&[26, -100, 100]),
            &Rat::zero(),
            &Rat::one(),
        );
        assert_eq!(b.sign_variations(), 2);
        let mut pieces = vec![b];
        for _ in 0..4 {
            pieces = pieces
                .iter()
                .flat_map(|p| {
                    let (l, r) = p.split_half();
                    [l, r]
                })
                .collect();
        }
        assert!(pieces
            .iter()
            .all(|p| p.sign_variations() == 0 && p.sign_at_lo() > 0));
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// The signs alone are those of the full conversion's coefficients.
        #[test]
        fn signs_of_power_are_the_coefficients_signs(p in zpoly(10, 150), (lo, hi) in interval()) {
            let b = Bernstein::from_power(&p, &lo, &hi);
            let signs = Bernstein::signs_of_power(&p, &lo, &hi);
            prop_assert_eq!(&signs, &b.coeffs.iter().map(Int::signum).collect::<Vec<_>>());
            prop_assert_eq!(sign_variations(signs.iter().copied()), b.sign_variations());
        }

        #[test]
        fn conversion_round_trip_and_values(p in zpoly(10, 150), (lo, hi) in interval(), t in rat()) {
            let b = Bernstein::from_power(&p, &lo, &hi);
            prop_assert_eq!(b.degree(), p.degree().unwrap_or(0));
            prop_assert!(b.scale().signum() > 0);
            prop_assert_eq!(b.to_power(), QPoly::from_zpoly(&p));
            prop_assert_eq!(b.eval(&t), p.eval_rat(&t));
            prop_assert_eq!(b.eval(&lo).signum(), b.sign_at_lo());
            prop_assert_eq!(b.eval(&hi).signum(), b.sign_at_hi());
            let (emin, emax) = b.enclosure();
            for k in 0..=4 {
                let s = &lo + &(&(&hi - &lo) * &Rat::from_frac(k, 4));
                let v = p.eval_rat(&s);
                prop_assert!(emin <= v && v <= emax);
            }
            let e = b.elevate(3);
            prop_assert_eq!(e.degree(), b.degree() + 3);
            prop_assert_eq!(e.eval(&t), b.eval(&t));
            let q = QPoly::from_zpoly(&p).mul_rat(&t);
            prop_assert_eq!(Bernstein::from_qpoly(&q, &lo, &hi).eval(&lo), q.eval_rat(&lo));
        }

        /// The nested conversion is the conversion, bit for bit, along a
        /// chain of intervals as a root isolation's zooms make them (each
        /// a dyadic subinterval `[i/2^s, (i + j)/2^s]` of the last, some of
        /// width `2^(−k)`, which are kept), with steps that must not use
        /// the kept substitution mixed in: an interval outside it, one
        /// with a non-dyadic end, one overlapping it.
        #[test]
        fn nested_conversion_is_the_conversion(
            p in zpoly(12, 300),
            steps in proptest::collection::vec((1u64..40, any::<u64>(), 1u64..5, 0u8..8), 1..7),
        ) {
            let mut last = None;
            let (mut lo, mut hi) = (Rat::zero(), Rat::one());
            for (s, i, j, kind) in steps {
                let total = 1u64 << s.min(62);
                let i = i % total;
                let j = j.min(total - i);
                let w = &hi - &lo;
                let at = |k: u64| &lo + &(&w * &Rat::dyadic(Int::from_u64(k), s.min(62)));
                let (a, b) = match kind {
                    // Outside: the next interval to the right, as wide.
                    0 => (hi.clone(), &hi + &w),
                    // A non-dyadic end.
                    1 => (at(i), &at(i) + &(&w * &Rat::from_frac(1, 3))),
                    // Overlapping the last on its left.
                    2 => (&lo - &(&w * &Rat::from_frac(1, 2)), at(i.max(1))),
                    _ => (at(i), at(i + j)),
                };
                let nested = Bernstein::from_power_nested(&p, &a, &b, &mut last, kind != 7);
                prop_assert_eq!(&nested, &Bernstein::from_power(&p, &a, &b));
                (lo, hi) = (a, b);
            }
        }

        #[test]
        fn split_children_agree_with_parent(p in zpoly(9, 120), (lo, hi) in interval(), k in 1i64..99, s in rat()) {
            let b = Bernstein::from_power(&p, &lo, &hi);
            let w = &hi - &lo;
            for r in [Rat::from_frac(1, 2), Rat::from_frac(1, 3), Rat::from_frac(7, 10), Rat::from_frac(k, 100)] {
                let (l, rt) = b.split(&r);
                let m = &lo + &(&w * &r);
                prop_assert_eq!((l.lo(), l.hi(), rt.lo(), rt.hi()), (&lo, &m, &m, &hi));
                for child in [&l, &rt] {
                    prop_assert_eq!(child.degree(), b.degree());
                    for j in 0..=3 {
                        let t = child.lo() + &(&(child.hi() - child.lo()) * &Rat::from_frac(j, 3));
                        prop_assert_eq!(child.eval(&t), b.eval(&t));
                    }
                    prop_assert_eq!(child.eval(&s), b.eval(&s));
                }
            }
            prop_assert_eq!(b.split_half(), b.split(&Rat::from_frac(1, 2)));
        }

        #[test]
        fn variations_bound_the_roots(roots in prop::collection::vec(-20i64..20, 1..7), other in zpoly_deg(0, 3, 20), lo in -25i64..0, w in 1i64..30) {
            // p = Π (t − r_i/2) · (other² + 1): the rational roots are exactly r_i/2.
            let mut p = ZPoly::one();
            for r in &roots {
                p = &p * &ZPoly::from_i64s(&[-r, 2]);
            }
            p = &p * &(&(&other * &other) + &ZPoly::one());
            let (lo, hi) = (Rat::from(lo), Rat::from(lo + w));
            let inside = roots.iter().filter(|&&r| Rat::from_frac(r, 2) > lo && Rat::from_frac(r, 2) < hi).count();
            let b = Bernstein::from_power(&p, &lo, &hi);
            let v = b.sign_variations();
            prop_assert!(v >= inside);
            // Roots are counted with multiplicity; with no root at an end the parity is exact.
            if b.sign_at_lo() != 0 && b.sign_at_hi() != 0 {
                prop_assert_eq!(v % 2, inside % 2);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The machine-integer Bernstein conversion agrees with the
        /// big-integer one, on both sides of the `i128` limit.
        #[test]
        fn scaled_bernstein_matches_the_exact_shift(p in zpoly_deg(0, 20, 120)) {
            let want = if p.is_zero() { vec![Int::zero()] } else { reverse_shift_reverse(p.coeffs().to_vec(), 1) };
            prop_assert_eq!(p.scaled_bernstein(), want);
        }
    }
}
