//! Products of integer coefficient vectors (`c_k = Σ_{i+j=k} a_i b_j`) and
//! the choice among the three methods:
//!
//! * schoolbook: `la·lb` big-integer products, best when one factor is short;
//! * Kronecker substitution ([`mul_kronecker`]): one big-integer product of
//!   the packed vectors, so the big-integer kernel's fast multiplication does
//!   the work;
//! * multimodular NTT ([`mul_multimodular`]): images modulo word primes
//!   multiplied by number-theoretic transforms, lifted by CRT; independent of
//!   the kernel and the fastest for long vectors of large coefficients.
//!
//! [`mul_coeffs`] dispatches with thresholds measured on this crate's bench.

use ccd_arith::Int;

/// `Σ_{i+j=k} a_i b_j` by the schoolbook method (`la·lb` products).
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::mul::mul_schoolbook;
/// let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// assert_eq!(mul_schoolbook(&v(&[1, 1]), &v(&[-1, 1])), v(&[-1, 0, 1]));
/// ```
pub fn mul_schoolbook(a: &[Int], b: &[Int]) -> Vec<Int> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    let mut c = vec![Int::zero(); a.len() + b.len() - 1];
    accumulate_schoolbook(&mut c, a, b, false);
    c
}

/// `acc ← acc ± a·b` by the schoolbook method, in `acc`'s own slots
/// (`acc` has at least `la + lb − 1` of them).
fn accumulate_schoolbook(acc: &mut [Int], a: &[Int], b: &[Int], negate: bool) {
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        let negated;
        let x = if negate {
            negated = -x;
            &negated
        } else {
            x
        };
        for (slot, y) in acc[i..].iter_mut().zip(b) {
            slot.add_mul(x, y);
        }
    }
}

/// `Σ_{i+j=k} a_i b_j` by Kronecker substitution: one product of the
/// integers `a(2^w)·b(2^w)`, `w` wide enough for every `c_k`.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::mul::mul_kronecker;
/// let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// assert_eq!(mul_kronecker(&v(&[2, -3]), &v(&[5, 0, 7])), v(&[10, -15, 14, -21]));
/// ```
pub fn mul_kronecker(a: &[Int], b: &[Int]) -> Vec<Int> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    crate::kronecker::mul_kronecker(a, b)
}

/// `Σ_{i+j=k} a_i b_j` by the multimodular method: NTTs modulo enough
/// 62-bit primes `p_j` that `Π p_j > 4·min(la, lb)·max|a_i|·max|b_j|`, then
/// CRT (falls back to Kronecker beyond transform length `2^20`).
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::mul::mul_multimodular;
/// let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// assert_eq!(mul_multimodular(&v(&[2, -3]), &v(&[5, 0, 7])), v(&[10, -15, 14, -21]));
/// ```
pub fn mul_multimodular(a: &[Int], b: &[Int]) -> Vec<Int> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    crate::ntt::mul_ntt(a, b).unwrap_or_else(|| crate::kronecker::mul_kronecker(a, b))
}

/// Which method [`mul_coeffs`] uses for factors of `la` and `lb`
/// coefficients of at most `abits` and `bbits` bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// [`mul_schoolbook`].
    Schoolbook,
    /// [`mul_kronecker`].
    Kronecker,
    /// [`mul_multimodular`].
    Multimodular,
}

/// The method [`mul_coeffs`] picks for factors of `la` and `lb`
/// coefficients of at most `abits` and `bbits` bits.
///
/// Measured on the project machine (medians; num-bigint / GMP kernels):
/// schoolbook wins only up to about 8 coefficients in the shorter factor.
/// With GMP, whose FFT multiplication makes Kronecker substitution
/// near-linear, Kronecker is as fast as or faster than the multimodular
/// product almost everywhere (217 × 2000 bits: 1.9–2.5 ms vs 2.4 ms;
/// 300 × 3000 bits: 5.2 ms vs 8.8 ms) and is always chosen. With num-bigint
/// (Toom-3 at best) the multimodular product wins once both factors are
/// long and the coefficients wide: 217 × 2000 bits 2.5 ms vs 9.3 ms,
/// 64 × 300 bits 76 μs vs 102 μs, while 50 × 200 bits (43 vs 53 μs) and
/// 20 × 2000 bits (259 vs 327 μs) stay with Kronecker; the rule below
/// separates those points. dashu (the default kernel) multiplies long
/// integers by a number-theoretic transform, so Kronecker substitution
/// wins again once the coefficients are wide, where the multimodular lift
/// (quadratic in the number of primes) dominates: two factors of `n`
/// coefficients of `b` bits each, best of three (Kronecker / multimodular,
/// ms): n = 32: b = 10,000 7.5 / 6.1, 14,000 7.8 / 11.5, 20,000 15.6 /
/// 22.5, 30,000 17.9 / 53.8; n = 64: 15.4 / 10.9, 16.3 / 20.8, 33.2 /
/// 41.1, 38.9 / 96.6; n = 128: 34.1 / 20.9, 35.3 / 39.2, 84.9 / 77.3. So
/// with dashu the multimodular product stops at 24,576 bits (the factors'
/// coefficient bits together).
///
/// Wide coefficients keep the schoolbook product longer with dashu: its
/// products of a few hundred bits are cheap next to Kronecker's packed
/// product of the whole vectors. Measured on the project machine (best of
/// five, µs, schoolbook / Kronecker, `n × n` coefficients of `L` limbs):
/// n = 9: L = 6 14.1 / 9.5, L = 8 10.8 / 13.9, L = 32 82 / 99; n = 13:
/// L = 8 23.2 / 23.7, L = 16 54.6 / 66.4; n = 17: L = 11 55.4 / 57.3,
/// L = 32 284 / 274; n = 21: L = 11 83.4 / 77.2. Squares, where the
/// schoolbook method needs only half the products
/// ([`choose_square_method`]), keep it longer still: n = 9, L = 6:
/// 5.4 / 7.4; n = 17, L = 6: 17.6 / 18.8; n = 21, L = 6: 26.5 / 24.7;
/// n = 25, L = 8: 47.7 / 52.1, L = 32: 319 / 365; n = 24 against the
/// multimodular product: L = 8 40.4 / 90.3, L = 32 290 / 544. Unequal
/// lengths (`16 × 64`, `16 × 128`, `12 × 200`; L = 8, 16, 32) stay within 7 %
/// of Kronecker substitution or beat it (`12 × 200`, L = 16: 735 / 1,048).
pub fn choose_method(la: usize, lb: usize, abits: u64, bbits: u64) -> Method {
    choose(la, lb, abits, bbits, false)
}

/// The method [`sqr_coeffs`] picks for a square of `len` coefficients of at
/// most `bits` bits (see [`choose_method`] for the measurements).
pub fn choose_square_method(len: usize, bits: u64) -> Method {
    choose(len, len, bits, bits, true)
}

/// The method for `a·b` (`a = b` when `square`): the widths are read only
/// past [`SCHOOLBOOK_MAX_LEN`] (most products of a query are shorter).
fn method_for(a: &[Int], b: &[Int], square: bool) -> Method {
    if a.len().min(b.len()) as u64 <= SCHOOLBOOK_MAX_LEN {
        return Method::Schoolbook;
    }
    let width = |v: &[Int]| v.iter().map(Int::bits).max().unwrap_or(0);
    let abits = width(a);
    let bbits = if square { abits } else { width(b) };
    choose(a.len(), b.len(), abits, bbits, square)
}

/// [`choose_method`], for a square when `square`.
fn choose(la: usize, lb: usize, abits: u64, bbits: u64, square: bool) -> Method {
    let short = la.min(lb) as u64;
    if short <= schoolbook_max_len(abits.min(bbits), square) {
        return Method::Schoolbook;
    }
    let bits = abits + bbits;
    let multimodular = match KERNEL {
        Kernel::Gmp => false,
        Kernel::Dashu => bits < MULTIMODULAR_MAX_BITS,
        Kernel::NumBigint => true,
    };
    if multimodular && short >= 24 && bits >= 256 && short * bits >= 32_768 {
        return Method::Multimodular;
    }
    Method::Kronecker
}

/// With the dashu kernel, factors whose coefficient bits add up to this
/// many or more are multiplied by Kronecker substitution ([`choose_method`]).
const MULTIMODULAR_MAX_BITS: u64 = 24_576;

/// Factors whose shorter one has at most this many coefficients are
/// multiplied schoolbook (at any width).
const SCHOOLBOOK_MAX_LEN: u64 = 8;

/// The longest shorter factor multiplied schoolbook, when the narrower
/// factor's widest coefficient has `bits` bits: [`SCHOOLBOOK_MAX_LEN`], and
/// longer for wide coefficients: with dashu more than 5 limbs for a
/// square, more than 7 for a product ([`choose_method`]); with GMP, whose
/// products favour Kronecker substitution from 9 coefficients at every
/// width, squares of up to 13 coefficients of more than 5 limbs (n = 9,
/// L = 11: 8.7 / 13.7 µs; n = 13, L = 11: 18.0 / 25.4; n = 17, L = 16:
/// 118 / 100).
fn schoolbook_max_len(bits: u64, square: bool) -> u64 {
    match (KERNEL, square, bits) {
        (Kernel::Dashu, true, 449..) => 24,
        (Kernel::Dashu, true, 321..) | (Kernel::Dashu, false, 449..) => 16,
        (Kernel::Gmp, true, 321..) => 13,
        _ => SCHOOLBOOK_MAX_LEN,
    }
}

/// [`ccd_arith::BACKEND`] as a compile-time constant, for the dispatch's
/// matches.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kernel {
    Dashu,
    Gmp,
    NumBigint,
}

const KERNEL: Kernel = {
    let name = ccd_arith::BACKEND.as_bytes();
    match name {
        b"dashu" => Kernel::Dashu,
        b"gmp" => Kernel::Gmp,
        _ => Kernel::NumBigint,
    }
};

/// `Σ_{i+j=k} a_i b_j` by the method [`choose_method`] picks.
pub fn mul_coeffs(a: &[Int], b: &[Int]) -> Vec<Int> {
    if a.is_empty() || b.is_empty() {
        return Vec::new();
    }
    match method_for(a, b, false) {
        Method::Schoolbook => mul_schoolbook(a, b),
        Method::Kronecker => mul_kronecker(a, b),
        Method::Multimodular => mul_multimodular(a, b),
    }
}

/// `acc ← acc ± a·b` (coefficient vectors; `−` when `negate`): where
/// [`choose_method`] picks the schoolbook product, accumulated in `acc`'s
/// own coefficients (no product vector, no sum vector); otherwise the
/// product by [`mul_coeffs`], added. Trailing zeros are the caller's.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::mul::add_mul_coeffs;
/// let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// let mut acc = v(&[1]);
/// add_mul_coeffs(&mut acc, &v(&[1, 1]), &v(&[-1, 1]), true); // 1 − (t² − 1)
/// assert_eq!(acc, v(&[2, 0, -1]));
/// ```
pub fn add_mul_coeffs(acc: &mut Vec<Int>, a: &[Int], b: &[Int], negate: bool) {
    if a.is_empty() || b.is_empty() {
        return;
    }
    let len = a.len() + b.len() - 1;
    if acc.len() < len {
        acc.resize(len, Int::zero());
    }
    if method_for(a, b, false) != Method::Schoolbook {
        for (slot, c) in acc.iter_mut().zip(mul_coeffs(a, b)) {
            *slot = if negate { &*slot - &c } else { &*slot + &c };
        }
        return;
    }
    accumulate_schoolbook(acc, a, b, negate);
}

/// `Σ_{i+j=k} a_i a_j`, the square of one coefficient vector: where
/// [`choose_square_method`] picks the schoolbook product, each cross product
/// `a_i·a_j` (`i < j`) once and doubled, then the diagonal `a_i²` (about
/// half the products); otherwise the other method it picks.
///
/// ```
/// use ccd_arith::Int;
/// use ccd_poly::mul::{mul_schoolbook, sqr_coeffs};
/// let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
/// assert_eq!(sqr_coeffs(&v(&[3, -1, 2])), mul_schoolbook(&v(&[3, -1, 2]), &v(&[3, -1, 2])));
/// ```
pub fn sqr_coeffs(a: &[Int]) -> Vec<Int> {
    if a.is_empty() {
        return Vec::new();
    }
    match method_for(a, a, true) {
        Method::Schoolbook => {}
        Method::Kronecker => return mul_kronecker(a, a),
        Method::Multimodular => return mul_multimodular(a, a),
    }
    let mut c = vec![Int::zero(); 2 * a.len() - 1];
    for (i, x) in a.iter().enumerate() {
        if x.is_zero() {
            continue;
        }
        for (cij, y) in c[2 * i + 1..].iter_mut().zip(&a[i + 1..]) {
            cij.add_mul(x, y);
        }
    }
    for (k, ck) in c.iter_mut().enumerate() {
        if !ck.is_zero() {
            *ck = ck.shl(1);
        }
        if k % 2 == 0 {
            let x = &a[k / 2];
            ck.add_mul(x, x);
        }
    }
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Coefficients of mixed sign and size: zeros, small, and up to ~`max_bits`.
    fn coeffs(max_len: usize, max_bits: u64) -> impl Strategy<Value = Vec<Int>> {
        prop::collection::vec((any::<i64>(), 0..=max_bits, 0u8..4), 1..=max_len).prop_map(|v| {
            v.into_iter()
                .map(|(x, s, kind)| match kind {
                    0 => Int::zero(),
                    1 => Int::from(x % 7),
                    _ => Int::from(x).shl(s) + Int::from(x),
                })
                .collect()
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn fast_products_match_schoolbook(a in coeffs(40, 400), b in coeffs(40, 400)) {
            let expect = mul_schoolbook(&a, &b);
            prop_assert_eq!(&mul_kronecker(&a, &b), &expect);
            prop_assert_eq!(&mul_multimodular(&a, &b), &expect);
            prop_assert_eq!(&mul_coeffs(&a, &b), &expect);
            prop_assert_eq!(sqr_coeffs(&a), mul_schoolbook(&a, &a));
            for negate in [false, true] {
                let mut acc = b.clone();
                add_mul_coeffs(&mut acc, &a, &b, negate);
                let product = mul_schoolbook(&a, &b);
                let expect: Vec<Int> = (0..acc.len().max(product.len()))
                    .map(|k| {
                        let (x, y) = (b.get(k).cloned().unwrap_or_else(Int::zero), product.get(k).cloned().unwrap_or_else(Int::zero));
                        if negate { &x - &y } else { &x + &y }
                    })
                    .collect();
                prop_assert_eq!(acc, expect);
            }
        }

        #[test]
        fn huge_coefficients(a in coeffs(6, 3000), b in coeffs(6, 3000)) {
            let expect = mul_schoolbook(&a, &b);
            prop_assert_eq!(&mul_kronecker(&a, &b), &expect);
            prop_assert_eq!(&mul_multimodular(&a, &b), &expect);
        }
    }

    #[test]
    fn dispatch_covers_every_method() {
        let mut s = 0x9E37_79B9_7F4A_7C15u64;
        let mut v = |len: usize, limbs: usize| -> Vec<Int> {
            (0..len)
                .map(|_| {
                    let l: Vec<u64> = (0..limbs)
                        .map(|_| {
                            s ^= s << 13;
                            s ^= s >> 7;
                            s ^= s << 17;
                            s
                        })
                        .collect();
                    Int::from_u64_limbs(s & 1 == 1, &l)
                })
                .collect()
        };
        for (la, lb, limbs) in [(3, 50, 4), (30, 20, 1), (70, 65, 10)] {
            let (a, b) = (v(la, limbs), v(lb, limbs));
            assert_eq!(
                mul_coeffs(&a, &b),
                mul_schoolbook(&a, &b),
                "{la}×{lb}, {limbs} limbs"
            );
        }
        assert_eq!(choose_method(3, 50, 256, 256), Method::Schoolbook);
        let big = choose_method(70, 65, 640, 640);
        assert_eq!(
            big,
            if ccd_arith::BACKEND == "gmp" {
                Method::Kronecker
            } else {
                Method::Multimodular
            }
        );
        // Wide coefficients: dashu's transform multiplication makes
        // Kronecker substitution the cheaper one again, from 24,576 bits.
        let wide = |abits, bbits| choose_method(64, 64, abits, bbits);
        let (narrow, at) = match ccd_arith::BACKEND {
            "dashu" => (Method::Multimodular, Method::Kronecker),
            "gmp" => (Method::Kronecker, Method::Kronecker),
            _ => (Method::Multimodular, Method::Multimodular),
        };
        assert_eq!(wide(12_287, 12_288), narrow);
        assert_eq!(wide(12_288, 12_288), at);
        // And the product there is exact (24 × 24 coefficients of 12,288 bits).
        let (a, b) = (v(24, 192), v(24, 192));
        assert_eq!(mul_coeffs(&a, &b), mul_schoolbook(&a, &b));
        // Wide but few coefficients: schoolbook with dashu, longer for squares.
        let dashu = |wide: bool| {
            if wide && ccd_arith::BACKEND == "dashu" {
                Method::Schoolbook
            } else {
                Method::Kronecker
            }
        };
        assert_eq!(choose_method(16, 40, 449, 2000), dashu(true));
        assert_eq!(choose_method(16, 40, 448, 2000), dashu(false));
        assert_eq!(choose_method(17, 17, 2000, 2000), dashu(false));
        assert_eq!(choose_square_method(16, 321), dashu(true));
        assert_eq!(choose_square_method(17, 321), dashu(false));
        assert_eq!(choose_square_method(24, 449), dashu(true));
        assert_eq!(choose_square_method(25, 449), dashu(false));
        assert_eq!(choose_square_method(9, 320), dashu(false));
        assert_eq!(
            choose_square_method(13, 321),
            if ccd_arith::BACKEND == "num-bigint" {
                Method::Kronecker
            } else {
                Method::Schoolbook
            }
        );
        // The dispatch itself: a square of 20 wide coefficients is
        // schoolbook with dashu, their product by another such vector not.
        let wide = v(20, 9);
        assert_eq!(method_for(&wide, &wide, true), dashu(true));
        assert_eq!(method_for(&wide, &wide, false), dashu(false));
        assert_eq!(method_for(&wide[..8], &wide, false), Method::Schoolbook);
        let (a, b) = (v(13, 9), v(16, 9));
        assert_eq!(mul_coeffs(&a, &b), mul_kronecker(&a, &b));
        assert_eq!(sqr_coeffs(&b), mul_kronecker(&b, &b));
    }

    #[test]
    fn degenerate_shapes() {
        let v = |c: &[i64]| c.iter().map(|&x| Int::from(x)).collect::<Vec<_>>();
        for (a, b) in [
            (v(&[0]), v(&[0, 0, 5])),
            (v(&[-3]), v(&[4])),
            (v(&[i64::MIN]), v(&[i64::MIN, i64::MAX])),
        ] {
            let expect = mul_schoolbook(&a, &b);
            assert_eq!(mul_kronecker(&a, &b), expect);
            assert_eq!(mul_multimodular(&a, &b), expect);
        }
        assert!(mul_coeffs(&[], &v(&[1])).is_empty());
        // Extremal signs: all coefficients ±(2^k − 1) make every digit maximal.
        let big = Int::one().shl(200) - Int::one();
        let a: Vec<Int> = (0..30)
            .map(|i| if i % 3 == 0 { -&big } else { big.clone() })
            .collect();
        let expect = mul_schoolbook(&a, &a);
        assert_eq!(mul_kronecker(&a, &a), expect);
        assert_eq!(mul_multimodular(&a, &a), expect);
    }
}
