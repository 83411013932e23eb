//! Kronecker substitution: a polynomial product as one big-integer product.
//!
//! With a slot width of `w` bits such that every product coefficient
//! satisfies `|c_k| < 2^(w−1)`, the integers `A = a(2^w)` and `B = b(2^w)`
//! determine `c = ab` through `C = A·B = Σ c_k 2^(wk)`: the coefficients are
//! the signed base-`2^w` digits of `C`.
//!
//! Packing writes the magnitudes of the positive and of the negative
//! coefficients into two disjoint bit fields, so `A = P − N` costs one
//! subtraction. Unpacking reads `w`-bit digits of `|C|` and turns them into
//! balanced digits in `(−2^(w−1), 2^(w−1))` with a borrow into the next slot.

use ccd_arith::Int;

/// ORs `limbs · 2^offset` into `buf` (the bits must be clear there).
fn or_shifted(buf: &mut [u64], limbs: &[u64], offset: u64) {
    let (word, sh) = ((offset / 64) as usize, (offset % 64) as u32);
    for (j, &l) in limbs.iter().enumerate() {
        buf[word + j] |= l << sh;
        if sh > 0 {
            buf[word + j + 1] |= l >> (64 - sh);
        }
    }
}

/// `Σ c_i 2^(w·i)` for coefficients with `|c_i| < 2^(w−1)`.
fn pack(c: &[Int], w: u64) -> Int {
    let words = ((c.len() as u64 * w) / 64 + 2) as usize;
    let (mut pos, mut neg) = (vec![0u64; words], vec![0u64; words]);
    for (i, x) in c.iter().enumerate() {
        let (negative, limbs) = x.to_u64_limbs();
        let buf = if negative { &mut neg } else { &mut pos };
        or_shifted(buf, &limbs, i as u64 * w);
    }
    Int::from_u64_limbs(false, &pos) - Int::from_u64_limbs(false, &neg)
}

/// Bits `[offset, offset + w)` of `src` (zero beyond its end) into `dst`.
fn extract(src: &[u64], offset: u64, w: u64, dst: &mut [u64]) {
    let (word, sh) = ((offset / 64) as usize, (offset % 64) as u32);
    let at = |i: usize| src.get(i).copied().unwrap_or(0);
    for (j, d) in dst.iter_mut().enumerate() {
        let lo = at(word + j) >> sh;
        let hi = if sh > 0 {
            at(word + j + 1) << (64 - sh)
        } else {
            0
        };
        *d = lo | hi;
    }
    mask(dst, w);
}

/// Clears the bits of `d` from bit `w` upward.
fn mask(d: &mut [u64], w: u64) {
    let full = (w / 64) as usize;
    if full < d.len() {
        d[full] &= (1u64 << (w % 64)) - 1;
        d[full + 1..].fill(0);
    }
}

/// The `count` balanced base-`2^w` digits of `c` (see the module docs).
fn unpack(c: &Int, w: u64, count: usize) -> Vec<Int> {
    let (negative, limbs) = c.to_u64_limbs();
    let nl = w.div_ceil(64) as usize;
    let mut digit = vec![0u64; nl];
    let mut borrow = false;
    let top_bit = |d: &[u64]| (d[((w - 1) / 64) as usize] >> ((w - 1) % 64)) & 1 == 1;
    (0..count)
        .map(|k| {
            extract(&limbs, k as u64 * w, w, &mut digit);
            if borrow {
                // digit += 1 (mod 2^w)
                for d in digit.iter_mut() {
                    let (s, o) = d.overflowing_add(1);
                    *d = s;
                    if !o {
                        break;
                    }
                }
                mask(&mut digit, w);
            }
            let is_zero = digit.iter().all(|&d| d == 0);
            let low_negative = if top_bit(&digit) {
                // The digit is d − 2^w: magnitude 2^w − d (two's complement in w bits).
                let mut carry = true;
                for d in digit.iter_mut() {
                    let (s, o) = (!*d).overflowing_add(carry as u64);
                    *d = s;
                    carry = o;
                }
                mask(&mut digit, w);
                borrow = true;
                true
            } else {
                // A zero digit keeps the sign of the lower part, hence the borrow.
                borrow = borrow && is_zero;
                false
            };
            Int::from_u64_limbs(low_negative != negative, &digit)
        })
        .collect()
}

/// Product of two nonempty coefficient vectors by Kronecker substitution.
pub(crate) fn mul_kronecker(a: &[Int], b: &[Int]) -> Vec<Int> {
    debug_assert!(!a.is_empty() && !b.is_empty());
    let abits = a.iter().map(Int::bits).max().unwrap_or(0);
    let bbits = b.iter().map(Int::bits).max().unwrap_or(0);
    let terms = a.len().min(b.len()) as u64;
    // |c_k| ≤ terms·2^(abits+bbits) < 2^(w−1).
    let w = abits + bbits + (64 - terms.leading_zeros()) as u64 + 1;
    let c = pack(a, w) * pack(b, w);
    unpack(&c, w, a.len() + b.len() - 1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #[test]
        fn pack_unpack_round_trip(v in prop::collection::vec(any::<i64>(), 1..20), extra in 0u64..130) {
            let c: Vec<Int> = v.iter().map(|&x| Int::from(x)).collect();
            let w = 65 + extra;
            prop_assert_eq!(unpack(&pack(&c, w), w, c.len()), c.clone());
            let negated: Vec<Int> = c.iter().map(|x| -x).collect();
            prop_assert_eq!(unpack(&-pack(&c, w), w, c.len()), negated);
        }
    }
}
