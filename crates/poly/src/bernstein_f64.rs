//! [`BernsteinF64`]: `f64` polynomials on `[0, 1]` in (scaled) Bernstein
//! form, with a magnitude bound per coefficient, implementing
//! [`RingOps`] so that the Section 4 closed forms
//! (`ccd_subres::closed_forms`) run on them unchanged.
//!
//! The paper's float implementation (Section 5.3) keeps "polynomials …
//! in the Bernstein form in order to improve the robustness and accuracy of
//! the computations"; so does this one, from the characteristic polynomial's
//! coefficients to the `sr` polynomials whose roots are the candidates.
//!
//! # Representation
//! A polynomial of degree `n` is stored by its *scaled* Bernstein
//! coefficients `p̃_i = C(n, i)·b_i`:
//!
//! ```text
//! p(u) = Σ_i b_i C(n,i) u^i (1−u)^(n−i) = Σ_i p̃_i u^i (1−u)^(n−i),
//! ```
//!
//! i.e. as a homogeneous polynomial in `(u, 1 − u)`. Products are then plain
//! convolutions (the binomial weights of the Bernstein product formula are
//! absorbed), degree elevation by `r` is a convolution with the binomial row
//! `C(r, ·)` (multiplication by `(u + (1 − u))^r`), and the ordinary
//! coefficients `b_i` that de Casteljau subdivision needs are recovered once,
//! at the end ([`BernsteinF64::coefficients`]). Every operation is a sum of
//! products with nonnegative weights, as in the ordinary Bernstein product.
//!
//! # Magnitudes
//! Alongside each coefficient the same computation is carried out on the
//! absolute values of the inputs with every `−` replaced by `+` (as in
//! [`Approx`]): the magnitude polynomial bounds, coefficientwise and
//! pointwise on `[0, 1]`, the terms whose rounding errors make up the error
//! of the value. [`BernsteinF64::is_negligible`] compares against it.
//!
//! # Proven error bounds
//! Each polynomial also carries `N`, the largest number of roundings along
//! any path from an input to a coefficient, and `A`, a bound on what
//! underflow can add. Expanding a computation into terms, each term of the
//! value carries at most `N` factors `(1 + δ)`, `|δ| ≤ u = 2^(−53)`, and the
//! magnitude is the sum of the terms' absolute values, so
//! `|p̃_i − exact_i| ≤ γ_N·mag_i + A` with `γ_N = N·u/(1 − N·u)` (Higham,
//! *Accuracy and Stability of Numerical Algorithms*, §3.1); the computed
//! magnitude is itself within `γ_N` of the exact one. The counts: an input
//! carries two roundings (its 64 leading bits, then `f64`); a product of
//! coefficient sequences of lengths `l, m` adds `min(l, m)` (one product,
//! then a running sum); a sum adds one; division by a small integer one;
//! binomial rows are exact up to `n = 50` and carry `2n` roundings beyond.
//! [`BernsteinF64::enclosures`] turns this into certified intervals of the
//! ordinary Bernstein coefficients: the exact path's filter for `sr0`.
//!
//! # Limits
//! Scaled coefficients carry the factor `C(n, i)`, at most `C(n, n/2)`;
//! `f64` holds that up to `n ≈ 1000`, far above the degree 288 of `sr0` for
//! degree-4 affine motions (Table 3).

use ccd_arith::Approx;
use ccd_arith::{Interval, RingOps};

/// An `f64` polynomial on `[0, 1]` in scaled Bernstein form, with
/// magnitudes (module docs).
///
/// ```
/// use ccd_arith::RingOps;
/// use ccd_poly::BernsteinF64;
/// // (1 − 2u)² = 1 − 4u + 4u²: ordinary Bernstein coefficients [1, −1, 1].
/// let p = BernsteinF64::from_power(&[1.0, -2.0]);
/// let sq = p.times(&p);
/// assert_eq!(sq.degree(), 2);
/// assert_eq!(sq.coefficients(), vec![1.0, -1.0, 1.0]);
/// assert_eq!(sq.eval(0.5).value, 0.0);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BernsteinF64 {
    /// Scaled coefficients of the value.
    val: Coeffs,
    /// Scaled coefficients of the magnitude (all ≥ 0).
    mag: Coeffs,
    /// Roundings along any path to a coefficient (module docs).
    rounds: u64,
    /// What underflow can add to any coefficient (module docs).
    tiny: f64,
}

/// A coefficient sequence: a single coefficient inline, longer ones on the
/// heap. The closed forms of a constant `f` (a static pair) are some sixty
/// sums and products of constants, which would otherwise each allocate two
/// one-element vectors; the arithmetic is the same either way.
#[derive(Clone)]
enum Coeffs {
    One(f64),
    Many(Vec<f64>),
}

impl Coeffs {
    /// `n` zeros.
    fn zeros(n: usize) -> Coeffs {
        if n == 1 {
            Coeffs::One(0.0)
        } else {
            Coeffs::Many(vec![0.0; n])
        }
    }
}

impl std::ops::Deref for Coeffs {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        match self {
            Coeffs::One(x) => std::slice::from_ref(x),
            Coeffs::Many(v) => v,
        }
    }
}

impl std::ops::DerefMut for Coeffs {
    fn deref_mut(&mut self) -> &mut [f64] {
        match self {
            Coeffs::One(x) => std::slice::from_mut(x),
            Coeffs::Many(v) => v,
        }
    }
}

impl From<Vec<f64>> for Coeffs {
    fn from(v: Vec<f64>) -> Coeffs {
        match v[..] {
            [x] => Coeffs::One(x),
            _ => Coeffs::Many(v),
        }
    }
}

impl FromIterator<f64> for Coeffs {
    fn from_iter<I: IntoIterator<Item = f64>>(iter: I) -> Coeffs {
        let mut iter = iter.into_iter();
        let Some(first) = iter.next() else {
            return Coeffs::Many(Vec::new());
        };
        let Some(second) = iter.next() else {
            return Coeffs::One(first);
        };
        let mut v = Vec::with_capacity(2 + iter.size_hint().0);
        v.extend([first, second]);
        v.extend(iter);
        Coeffs::Many(v)
    }
}

impl<'a> IntoIterator for &'a Coeffs {
    type Item = &'a f64;
    type IntoIter = std::slice::Iter<'a, f64>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl PartialEq for Coeffs {
    fn eq(&self, o: &Coeffs) -> bool {
        **self == **o
    }
}

impl std::fmt::Debug for Coeffs {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        (**self).fmt(f)
    }
}

/// What one underflowing product can lose, rounded up from `2^(−1074)`
/// to the least normal float `2^(−1022)`: every underflow bound is then
/// zero or normal, never subnormal. A product with a subnormal factor or
/// result takes a microcode assist on x86_64 (about 80 cycles against
/// one), and the bounds enter every product and every enclosure; the
/// looser bound shows only beside coefficients below about `2^(−960)`.
const ETA: f64 = f64::MIN_POSITIVE;

/// Roundings in `C(n, ·)` from [`binomial_row`].
fn row_rounds(n: usize) -> u64 {
    if n <= 50 {
        0
    } else {
        2 * n as u64
    }
}

/// Largest entry.
fn max_of(v: &[f64]) -> f64 {
    v.iter().fold(0.0, |m, &x| m.max(x))
}

/// The underflow bound of a product of sequences of lengths `l, m` with
/// magnitudes at most `ma`, `mb` and underflow bounds `ta`, `tb`: each of
/// at most `min(l, m)` terms `x̂ŷ` is off by `|τ_x|·|ŷ| + |x|·|τ_y|` plus
/// its own underflow, with `|x| ≤ 3·ma` while `γ_N ≤ 1/2`. The factors
/// `3·m + τ` are counted as at least 1, so that a product with a bound
/// (zero or at least [`ETA`]) is zero or normal too.
fn product_tiny(len: usize, ma: f64, ta: f64, mb: f64, tb: f64) -> f64 {
    let at_least_one = |x: f64| x.max(1.0);
    2.0 * len as f64 * (ta * at_least_one(3.0 * mb + tb) + tb * at_least_one(3.0 * ma + ta) + ETA)
}

/// `C(n, 0..=n)` in `f64` (exact while the intermediate products stay below
/// `2^53`, e.g. for `n <= 50`; beyond, each entry carries at most `2n`
/// roundings).
pub fn binomial_row(n: usize) -> Vec<f64> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c = 1.0f64;
    row.push(c);
    for i in 0..n {
        c = c * (n - i) as f64 / (i + 1) as f64;
        row.push(c.round());
    }
    row
}

/// `a * b` as a convolution of coefficient sequences. A constant factor
/// (the closed forms' `12`, `−3`, `27`, …) takes one pass: each output is
/// then the single term the general sum adds to its `0` (`0 + x·y`, so
/// that a `−0` product still gives `+0`, and nothing for a zero `x`), the
/// same bits without the zeroed buffer and the loop nest.
fn convolve(a: &[f64], b: &[f64]) -> Coeffs {
    let term = |x: f64, y: f64| if x == 0.0 { 0.0 } else { 0.0 + x * y };
    match (a, b) {
        (&[x], _) => b.iter().map(|&y| term(x, y)).collect(),
        (_, &[y]) => a.iter().map(|&x| term(x, y)).collect(),
        _ => convolve_sums(a, b),
    }
}

/// [`convolve`] by the running sums: output `i + j` adds `a_i·b_j` for
/// `i` ascending (zero `a_i` skipped). Each output's sum is the same IEEE
/// operations in the same order at any vector width (no contraction into
/// fused multiply-adds), so the AVX build of the loop
/// ([`convolve_sums_avx`]) gives the same bits, four lanes at a time.
fn convolve_sums(a: &[f64], b: &[f64]) -> Coeffs {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx") {
        // SAFETY: the CPU has AVX (checked just above), the only
        // requirement of `convolve_sums_avx`.
        return unsafe { convolve_sums_avx(a, b) };
    }
    convolve_sums_with(a, b)
}

/// [`convolve_sums`] compiled for AVX.
///
/// # Safety
///
/// The CPU must support AVX.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx")]
unsafe fn convolve_sums_avx(a: &[f64], b: &[f64]) -> Coeffs {
    convolve_sums_with(a, b)
}

/// The loop of [`convolve_sums`], inlined into each build of it.
#[inline(always)]
fn convolve_sums_with(a: &[f64], b: &[f64]) -> Coeffs {
    let mut out = Coeffs::zeros(a.len() + b.len() - 1);
    for (i, &x) in a.iter().enumerate() {
        if x == 0.0 {
            continue;
        }
        for (o, &y) in out[i..].iter_mut().zip(b) {
            *o += x * y;
        }
    }
    out
}

/// `Σ_i c_i x^i (1 − x)^(n − i)` for scaled coefficients `c` (degree
/// `n = c.len() − 1`) at `x ∈ [0, 1]`: Horner in `x/(1 − x)` or `(1 − x)/x`,
/// whichever is at most 1, so `O(n)` and without overflow.
pub fn eval_scaled(c: &[f64], x: f64) -> f64 {
    let n = c.len() - 1;
    if x <= 0.5 {
        let (s, w) = (x / (1.0 - x), 1.0 - x);
        let acc = c.iter().rev().fold(0.0, |acc, &ci| acc * s + ci);
        acc * w.powi(n as i32)
    } else {
        let (s, w) = ((1.0 - x) / x, x);
        let acc = c.iter().fold(0.0, |acc, &ci| acc * s + ci);
        acc * w.powi(n as i32)
    }
}

impl BernsteinF64 {
    /// A polynomial given by its power-basis coefficients in `u`, constant
    /// term first (the magnitude of each input is its absolute value).
    /// Conversion: `u^j = Σ_k C(n − j, k − j) u^k (1 − u)^(n − k)`.
    pub fn from_power(power: &[f64]) -> BernsteinF64 {
        if power.is_empty() {
            return BernsteinF64::zero();
        }
        let n = power.len() - 1;
        let rounds = row_rounds(n) + n as u64 + 1;
        let mut val = Coeffs::zeros(n + 1);
        let mut mag = Coeffs::zeros(n + 1);
        for (j, &a) in power.iter().enumerate() {
            if a == 0.0 {
                continue;
            }
            let row = binomial_row(n - j);
            for (m, &c) in row.iter().enumerate() {
                val[j + m] += c * a;
                mag[j + m] += c * a.abs();
            }
        }
        BernsteinF64 {
            tiny: (n + 1) as f64 * ETA,
            val,
            mag,
            rounds,
        }
    }

    /// A polynomial given by its scaled Bernstein coefficients
    /// `p̃_i = C(n, i)·b_i` (module docs), each within two roundings of its
    /// exact value (so its magnitude is its absolute value).
    pub fn from_scaled(scaled: Vec<f64>) -> BernsteinF64 {
        if scaled.is_empty() {
            return BernsteinF64::zero();
        }
        let mag = scaled.iter().map(|c| c.abs()).collect();
        BernsteinF64 {
            val: scaled.into(),
            mag,
            rounds: 2,
            tiny: ETA,
        }
    }

    /// Certified enclosures of the ordinary Bernstein coefficients
    /// `b_i = p̃_i / C(n, i)` of the exact polynomial this one approximates
    /// (module docs): `p̃_i ± (γ_N·(1 + γ_N)·mag_i + 3A)`, rounded
    /// outward, over an enclosure of the binomial. Unbounded if the error analysis
    /// does not apply (`γ_N > 1/2`, or a value that is not finite).
    pub fn enclosures(&self) -> Vec<Interval> {
        let u = f64::EPSILON / 2.0;
        let nu = self.rounds as f64 * u;
        let whole = Interval {
            lo: f64::NEG_INFINITY,
            hi: f64::INFINITY,
        };
        if nu >= 0.5 {
            return vec![whole; self.val.len()];
        }
        // γ_N against the exact magnitude, which the computed one
        // undercuts by at most a factor 1 + γ_N; 2^(−50) covers this
        // line's own roundings.
        let g = nu / (1.0 - nu);
        let gamma = g * (1.0 + g) * (1.0 + 2f64.powi(-50));
        // C(n, i) enclosed: C(n, i + 1) = C(n, i)·(n − i)/(i + 1), rounded
        // outward.
        let n = self.degree();
        let binomials = (0..=n).scan(Interval::point(1.0), |c, i| {
            let here = *c;
            *c = (*c * Interval::point((n - i) as f64))
                .div_positive(Interval::point((i + 1) as f64));
            Some(here)
        });
        self.val
            .iter()
            .zip(&self.mag)
            .zip(binomials)
            .map(|((&v, &m), c)| {
                let e = (gamma * m + 3.0 * self.tiny).next_up();
                let iv = Interval {
                    lo: (v - e).next_down(),
                    hi: (v + e).next_up(),
                };
                if iv.lo.is_finite() && iv.hi.is_finite() {
                    iv.div_positive(c)
                } else {
                    whole
                }
            })
            .collect()
    }

    /// The nominal degree `n` of the Bernstein form (at least the true
    /// degree; products and sums of the closed forms are not checked for
    /// cancelling leading terms).
    pub fn degree(&self) -> usize {
        self.val.len() - 1
    }

    /// The ordinary Bernstein coefficients `b_i = p̃_i / C(n, i)` of the
    /// value: the control points de Casteljau subdivision works on.
    pub fn coefficients(&self) -> Vec<f64> {
        unscale(&self.val)
    }

    /// The ordinary Bernstein coefficients of the magnitude bound.
    pub fn magnitudes(&self) -> Vec<f64> {
        unscale(&self.mag)
    }

    /// The value and magnitude at `u ∈ [0, 1]` (`O(n)`).
    pub fn eval(&self, u: f64) -> Approx {
        Approx {
            value: eval_scaled(&self.val, u),
            magnitude: eval_scaled(&self.mag, u),
        }
    }

    /// Whether every coefficient is within `tol` (relative) of its
    /// magnitude: the polynomial cannot be told from the zero polynomial at
    /// that tolerance. This is how float mode decides `sr0 ≡ 0` and
    /// `sr11 ≡ 0` (Algorithm 1, Theorems 5.4–5.6).
    pub fn is_negligible(&self, tol: f64) -> bool {
        self.val
            .iter()
            .zip(&self.mag)
            .all(|(v, m)| v.abs() <= tol * m)
    }

    /// The same polynomial in degree `n` (`n >= self.degree()`).
    fn elevated(&self, n: usize) -> BernsteinF64 {
        let r = n - self.degree();
        if r == 0 {
            return self.clone();
        }
        let row = binomial_row(r);
        let len = row.len().min(self.val.len());
        BernsteinF64 {
            val: convolve(&self.val, &row),
            mag: convolve(&self.mag, &row),
            rounds: self.rounds + row_rounds(r) + len as u64,
            tiny: product_tiny(len, max_of(&row), 0.0, max_of(&self.mag), self.tiny),
        }
    }

    /// Coefficientwise `self ± o` at a common degree.
    fn add_signed(&self, o: &BernsteinF64, sign: f64) -> BernsteinF64 {
        let n = self.degree().max(o.degree());
        let (a, b);
        let (a, b) = match (self.degree() == n, o.degree() == n) {
            (true, true) => (self, o),
            (true, false) => {
                b = o.elevated(n);
                (self, &b)
            }
            _ => {
                a = self.elevated(n);
                (&a, o)
            }
        };
        BernsteinF64 {
            val: a
                .val
                .iter()
                .zip(&b.val)
                .map(|(x, y)| x + sign * y)
                .collect(),
            mag: a.mag.iter().zip(&b.mag).map(|(x, y)| x + y).collect(),
            rounds: a.rounds.max(b.rounds) + 1,
            tiny: 2.0 * (a.tiny + b.tiny),
        }
    }
}

/// `p̃_i / C(n, i)`.
fn unscale(scaled: &[f64]) -> Vec<f64> {
    let row = binomial_row(scaled.len() - 1);
    scaled.iter().zip(&row).map(|(c, b)| c / b).collect()
}

impl RingOps for BernsteinF64 {
    fn zero() -> Self {
        BernsteinF64::from_i64(0)
    }
    fn one() -> Self {
        BernsteinF64::from_i64(1)
    }
    fn from_i64(v: i64) -> Self {
        BernsteinF64 {
            val: Coeffs::One(v as f64),
            mag: Coeffs::One((v as f64).abs()),
            // Exact below 2^53 in magnitude, one rounding beyond.
            rounds: u64::from(v.unsigned_abs() > 1 << 53),
            tiny: 0.0,
        }
    }
    fn is_zero(&self) -> bool {
        self.val.iter().chain(&self.mag).all(|c| *c == 0.0)
    }
    fn plus(&self, o: &Self) -> Self {
        self.add_signed(o, 1.0)
    }
    fn minus(&self, o: &Self) -> Self {
        self.add_signed(o, -1.0)
    }
    fn times(&self, o: &Self) -> Self {
        let len = self.val.len().min(o.val.len());
        BernsteinF64 {
            val: convolve(&self.val, &o.val),
            mag: convolve(&self.mag, &o.mag),
            rounds: self.rounds + o.rounds + len as u64,
            tiny: product_tiny(len, max_of(&self.mag), self.tiny, max_of(&o.mag), o.tiny),
        }
    }
    fn negated(&self) -> Self {
        BernsteinF64 {
            val: self.val.iter().map(|c| -c).collect(),
            ..self.clone()
        }
    }
    fn div_small(&self, k: i64) -> Self {
        let k = k as f64;
        BernsteinF64 {
            val: self.val.iter().map(|c| c / k).collect(),
            mag: self.mag.iter().map(|c| c / k.abs()).collect(),
            rounds: self.rounds + 1,
            // `2·τ/|k| ≤ 2·τ` (`k` is a nonzero integer), kept normal.
            tiny: 2.0 * self.tiny + ETA,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn horner(p: &[f64], u: f64) -> f64 {
        p.iter().rev().fold(0.0, |acc, c| acc * u + c)
    }

    #[test]
    fn inline_constants_are_the_vectors_they_stand_for() {
        // One coefficient inline, others on the heap: the same sequences.
        for v in [vec![], vec![-0.0], vec![2.5], vec![1.0, -3.0, 0.5]] {
            let c: Coeffs = v.iter().copied().collect();
            assert_eq!(*c, v[..]);
            assert_eq!(matches!(c, Coeffs::One(_)), v.len() == 1);
            assert_eq!(Coeffs::from(v.clone()), c);
        }
        // Products of constants: the convolution's sum (+0 for a zero
        // factor, as the vectors it replaces gave).
        assert_eq!(*convolve(&[3.0], &[-0.5]), [-1.5]);
        assert!(convolve(&[0.0], &[-2.0])[0].is_sign_positive());
        assert!(convolve(&[-2.0], &[0.0])[0].is_sign_positive());
    }

    proptest::proptest! {
        /// A constant factor on either side gives the running sums' bits:
        /// zeros of both signs, infinities, subnormals and ordinary values.
        #[test]
        fn constant_factors_match_the_running_sums(
            k in proptest::sample::select(vec![0.0, -0.0, 12.0, -3.0, 27.0, f64::INFINITY, 5e-324, -1.5e300]),
            raw in proptest::collection::vec(proptest::sample::select(vec![0.0, -0.0, 1.0, -2.5, f64::NEG_INFINITY, 5e-324, 3.7e-310, 1e308, -7.25]), 1..12),
        ) {
            let bits = |c: &Coeffs| c.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            for (a, b) in [(&[k][..], &raw[..]), (&raw[..], &[k][..])] {
                let (fast, sums) = (convolve(a, b), convolve_sums(a, b));
                proptest::prop_assert_eq!(bits(&fast), bits(&sums));
                proptest::prop_assert_eq!(matches!(fast, Coeffs::One(_)), matches!(sums, Coeffs::One(_)));
            }
        }

        /// The running sums (the AVX build where the CPU has it) are the
        /// scalar loop's bits: the same operations in the same order per
        /// output, whatever the vector width (lengths past a vector, zeros
        /// skipped, signed zeros, subnormals, overflow).
        #[test]
        fn running_sums_are_the_scalar_loop(
            a in proptest::collection::vec(proptest::sample::select(vec![0.0, -0.0, 1.0, -2.5, 5e-324, 3.7e-310, 1e308, -7.25, 0.1, -1e-3]), 2..40),
            b in proptest::collection::vec(proptest::sample::select(vec![0.0, -0.0, 3.0, -0.3, 5e-324, 1e300, -1e300, 2.2e-308, 0.7]), 2..40),
        ) {
            let mut scalar = vec![0.0f64; a.len() + b.len() - 1];
            for (i, &x) in a.iter().enumerate() {
                if x == 0.0 {
                    continue;
                }
                for (j, &y) in b.iter().enumerate() {
                    scalar[i + j] = std::hint::black_box(scalar[i + j] + x * y);
                }
            }
            let bits = |c: &[f64]| c.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            proptest::prop_assert_eq!(bits(&convolve_sums(&a, &b)), bits(&scalar));
        }
    }

    /// Runs `f` with the SSE status flags cleared and tells whether it
    /// raised the denormal-operand or underflow flag: whether some
    /// operation of `f` read a subnormal or rounded a tiny result.
    #[cfg(target_arch = "x86_64")]
    #[allow(deprecated)] // `_mm_getcsr`: the flags have no other reader
    fn touches_subnormals<T>(f: impl FnOnce() -> T) -> (T, bool) {
        use std::arch::x86_64::{_mm_getcsr, _mm_setcsr};
        // SAFETY: clears the six sticky exception flags only.
        unsafe { _mm_setcsr(_mm_getcsr() & !0x3f) };
        let out = std::hint::black_box(f());
        // SAFETY: a read of the status register.
        let flags = unsafe { _mm_getcsr() };
        (out, flags & 0x12 != 0)
    }

    proptest::proptest! {
        /// Every underflow bound is zero or normal, and is formed without
        /// touching a subnormal (x86_64: the status flags), through
        /// products (with magnitudes below 1 too), sums, divisions and
        /// elevation: a subnormal operand or result costs each product a
        /// microcode assist.
        #[test]
        fn underflow_bounds_avoid_subnormals(
            len in 1usize..300,
            mags in proptest::array::uniform2(proptest::sample::select(vec![0.0, 1e-300, 1e-3, 0.7, 3.0, 1e50, 1e300])),
            tinies in proptest::array::uniform2(proptest::sample::select(vec![0.0, ETA, 7.0 * ETA, 1e-300, 1e-20])),
            k in 1i64..30,
        ) {
            let [ma, mb] = mags.map(std::hint::black_box);
            let [ta, tb] = tinies.map(std::hint::black_box);
            let normal = |t: f64| t == 0.0 || t >= f64::MIN_POSITIVE;
            #[cfg(target_arch = "x86_64")]
            {
                let (t, touched) = touches_subnormals(|| product_tiny(len, ma, ta, mb, tb));
                proptest::prop_assert!(normal(t) && !touched, "{} {}", t, touched);
            }
            let p = BernsteinF64 { val: vec![0.5; 3].into(), mag: vec![mb; 3].into(), rounds: 2, tiny: tb };
            let q = BernsteinF64 { val: vec![-2.0; 2].into(), mag: vec![ma; 2].into(), rounds: 2, tiny: ta };
            for r in [p.times(&q), p.plus(&q), p.minus(&q).div_small(k), q.elevated(4), BernsteinF64::from_power(&[0.0, 5e-324, 0.25])] {
                proptest::prop_assert!(normal(r.tiny), "{}", r.tiny);
            }
        }
    }

    #[test]
    fn binomials_are_exact_where_f64_can_be() {
        let row = binomial_row(10);
        assert_eq!(row[5], 252.0);
        assert_eq!(binomial_row(50)[25], 126410606437752.0);
        let big = binomial_row(288);
        assert!(big[144].is_finite() && big[144] > 1e84);
    }

    #[test]
    fn ring_ops_match_power_basis() {
        let p = [3.0, -1.0, 0.5, 2.0];
        let q = [-1.0, 4.0];
        let (bp, bq) = (BernsteinF64::from_power(&p), BernsteinF64::from_power(&q));
        let prod = bp.times(&bq).minus(&bq).plus(&BernsteinF64::from_i64(7));
        let sum = bq.plus(&bp).negated().div_small(2);
        for u in [0.0, 0.1, 0.37, 0.5, 0.81, 1.0] {
            let want = horner(&p, u) * horner(&q, u) - horner(&q, u) + 7.0;
            assert!((prod.eval(u).value - want).abs() < 1e-12, "{u}");
            let want = -(horner(&p, u) + horner(&q, u)) / 2.0;
            assert!((sum.eval(u).value - want).abs() < 1e-12, "{u}");
            assert!(prod.eval(u).magnitude >= prod.eval(u).value.abs());
        }
        assert_eq!(prod.degree(), 4);
    }

    #[test]
    fn cancellation_is_negligible_relative_to_magnitude() {
        let p = BernsteinF64::from_power(&[0.1, 0.7, -0.3]);
        let zero = p.times(&p).minus(&p.times(&p));
        assert!(zero.is_negligible(0.0));
        let one = BernsteinF64::one();
        let almost = one.minus(&one.plus(&BernsteinF64::from_power(&[1e-6])));
        assert!(almost.is_negligible(1e-5));
        assert!(!almost.is_negligible(1e-8));
        assert!(!p.is_negligible(1e-3));
        assert!(BernsteinF64::zero().is_zero() && !p.is_zero());
    }
}
