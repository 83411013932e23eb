//! Multimodular polynomial product: reduce both factors modulo enough
//! NTT-friendly 62-bit primes, multiply each image by a number-theoretic
//! transform (cyclic convolution of length `N = 2^k ≥ deg(ab) + 1`, so no
//! wrap-around), and lift the coefficients back to `Z` by the Chinese
//! remainder theorem.
//!
//! If `|c_k| ≤ B` for every product coefficient and `M = Π p_j > 4B`, the
//! residues determine each `c_k` as the unique integer of `(−M/2, M/2)` in
//! its class. The lift uses `X = Σ_j y_j·(M/p_j)` with
//! `y_j = r_j·(M/p_j)^{-1} mod p_j`, so `X ≡ c_k (mod M)`, `0 ≤ X < m·M` and
//! `X/M = Σ_j y_j/p_j`; because `|c_k|/M < 1/4`, rounding that sum (computed
//! in `f64`, error far below `1/4`) gives the exact `q` with `c_k = X − q·M`.

use crate::prime::{dot, ntt_primes, Fp, NttPrime, MAX_LOG_LEN};
use ccd_arith::Int;

/// Per-level twiddle factors for transforms of length `n`, as plain
/// residues `w` with Shoup's companions `⌊w·2^64/p⌋` ([`Fp::shoup`]): the level whose
/// butterflies span `2h` entries uses `ω_{2h}^j`, `j < h`, stored
/// contiguously from index `h − 1`.
struct Twiddles {
    fwd: Vec<u64>,
    fwd_shoup: Vec<u64>,
    inv: Vec<u64>,
    inv_shoup: Vec<u64>,
}

/// `x·w mod p` up to one multiple of `p` (a value in `[0, 2p)`), for any
/// `x < 2^64`, by Shoup's method with `ws = ⌊w·2^64/p⌋`.
#[inline(always)]
fn mul_shoup(x: u64, w: u64, ws: u64, p: u64) -> u64 {
    let q = ((x as u128 * ws as u128) >> 64) as u64;
    x.wrapping_mul(w).wrapping_sub(q.wrapping_mul(p))
}

/// `x` reduced once by `m`: `x − m` if `x ≥ m` (for `x < 2m ≤ 2^63`).
#[inline(always)]
fn sub_if_ge(x: u64, m: u64) -> u64 {
    x.min(x.wrapping_sub(m))
}

impl Twiddles {
    fn new(f: &Fp, prime: &NttPrime, log_n: u32) -> Twiddles {
        let n = 1usize << log_n;
        let half = n / 2;
        // ω_n = root^(2^(MAX − log_n)); powers ω_n^k for k < n/2 in four
        // interleaved chains (Montgomery form) so the multiplications overlap.
        let w = f.pow(f.enter(prime.root), 1u64 << (MAX_LOG_LEN - log_n));
        let mut base = vec![f.one; half.max(1)];
        for k in 1..half.min(4) {
            base[k] = f.mul(base[k - 1], w);
        }
        if half > 4 {
            let w4 = f.pow(w, 4);
            for k in 4..half {
                base[k] = f.mul(base[k - 4], w4);
            }
        }
        // ω^{−k} = −ω^{n/2 − k} since ω^{n/2} = −1.
        let inv_base: Vec<u64> = (0..half)
            .map(|k| if k == 0 { f.one } else { f.neg(base[half - k]) })
            .collect();
        let mut tw = Twiddles {
            fwd: Vec::with_capacity(n),
            fwd_shoup: Vec::new(),
            inv: Vec::with_capacity(n),
            inv_shoup: Vec::new(),
        };
        let mut h = 1;
        while h <= half {
            let stride = half / h;
            tw.fwd.extend((0..h).map(|j| base[j * stride]));
            tw.inv.extend((0..h).map(|j| inv_base[j * stride]));
            h *= 2;
        }
        tw.fwd_shoup = tw.fwd.iter().map(|&x| f.shoup(x)).collect();
        tw.inv_shoup = tw.inv.iter().map(|&x| f.shoup(x)).collect();
        for x in tw.fwd.iter_mut().chain(tw.inv.iter_mut()) {
            *x = f.leave(*x);
        }
        tw
    }
}

/// Forward transform, decimation in frequency: natural order in,
/// bit-reversed order out. Lazy (Harvey) butterflies: entries stay in
/// `[0, 2p)` throughout.
fn forward(a: &mut [u64], tw: &Twiddles, p: u64) {
    let p2 = 2 * p;
    let mut h = a.len() / 2;
    while h >= 1 {
        let (w, ws) = (&tw.fwd[h - 1..2 * h - 1], &tw.fwd_shoup[h - 1..2 * h - 1]);
        for block in a.chunks_exact_mut(2 * h) {
            let (lo, hi) = block.split_at_mut(h);
            for (((x, y), &wj), &sj) in lo.iter_mut().zip(hi.iter_mut()).zip(w).zip(ws) {
                let (u, v) = (*x, *y);
                *x = sub_if_ge(u + v, p2);
                *y = mul_shoup(u + p2 - v, wj, sj, p);
            }
        }
        h /= 2;
    }
}

/// Inverse transform without the `1/N` factor, decimation in time:
/// bit-reversed order in (entries below `2p`), natural order out, fully
/// reduced. Lazy butterflies keep entries in `[0, 4p)`.
fn inverse(a: &mut [u64], tw: &Twiddles, p: u64) {
    let (n, p2) = (a.len(), 2 * p);
    let mut h = 1;
    while h < n {
        let (w, ws) = (&tw.inv[h - 1..2 * h - 1], &tw.inv_shoup[h - 1..2 * h - 1]);
        for block in a.chunks_exact_mut(2 * h) {
            let (lo, hi) = block.split_at_mut(h);
            for (((x, y), &wj), &sj) in lo.iter_mut().zip(hi.iter_mut()).zip(w).zip(ws) {
                let u = sub_if_ge(*x, p2);
                let v = mul_shoup(*y, wj, sj, p);
                *x = u + v;
                *y = u + p2 - v;
            }
        }
        h *= 2;
    }
    for x in a.iter_mut() {
        *x = sub_if_ge(sub_if_ge(*x, p2), p);
    }
}

/// Sign and magnitude limbs of each coefficient.
pub(crate) fn to_limbs(c: &[Int]) -> Vec<(bool, Vec<u64>)> {
    c.iter().map(Int::to_u64_limbs).collect()
}

/// The length of the longest limb vector among two limb lists.
pub(crate) fn max_limbs(a: &[(bool, Vec<u64>)], b: &[(bool, Vec<u64>)]) -> usize {
    a.iter().chain(b).map(|(_, l)| l.len()).max().unwrap_or(0)
}

/// Residues of the coefficients modulo `f.p` into `out` (plain form).
pub(crate) fn reduce_all(src: &[(bool, Vec<u64>)], f: &Fp, weights: &[u64], out: &mut [u64]) {
    for ((neg, limbs), o) in src.iter().zip(out.iter_mut()) {
        let r = f.reduce_limbs(limbs, weights);
        *o = if *neg { f.neg(r) } else { r };
    }
}

/// The number of table primes whose product exceeds `2^bits`.
pub(crate) fn primes_for_bits(bits: u64) -> usize {
    let mut need = bits as f64;
    let mut m = 0;
    // Table primes lie in (2^61, 2^62); count conservatively with 61.9 bits
    // (checked against the actual primes in the tests).
    while need > 0.0 {
        need -= 61.9;
        m += 1;
    }
    m
}

/// The CRT data for a set of primes: `M = Π p_j`, the cofactors `M/p_j`
/// (transposed: `cof[l·m + j]` is limb `l` of `M/p_j`) and
/// `(M/p_j)^{-1} mod p_j` in Montgomery form.
struct Crt {
    m_limbs: Vec<u64>,
    cof: Vec<u64>,
    cof_inv: Vec<u64>,
    inv_p: Vec<f64>,
}

impl Crt {
    fn new(fields: &[Fp]) -> Crt {
        let m = fields.len();
        let mut big = Int::one();
        for f in fields {
            big = big.mul_i64(f.p as i64);
        }
        let mut m_limbs = big.to_u64_limbs().1;
        m_limbs.resize(m, 0);
        let mut cof = vec![0u64; m * m];
        let mut cof_inv = Vec::with_capacity(m);
        for (j, f) in fields.iter().enumerate() {
            let c = big.div_exact(&Int::from_u64(f.p));
            let limbs = c.to_u64_limbs().1;
            for (l, &x) in limbs.iter().enumerate() {
                cof[l * m + j] = x;
            }
            let r = f.reduce_limbs(&limbs, &f.limb_weights(limbs.len()));
            cof_inv.push(f.inv(f.enter(r)));
        }
        // M/p_j < 2^{62(m−1)} fits in m limbs; M itself in m limbs too.
        let inv_p = fields.iter().map(|f| 1.0 / f.p as f64).collect();
        Crt {
            m_limbs,
            cof,
            cof_inv,
            inv_p,
        }
    }

    /// The integer in `(−M/2, M/2)` with the given residues `r[j]`
    /// (provided `|value| < M/4`).
    fn lift(&self, fields: &[Fp], r: &[u64], y: &mut [u64], x: &mut Vec<u64>) -> Int {
        let m = fields.len();
        let mut frac = 0.0f64;
        for j in 0..m {
            y[j] = fields[j].mul(r[j], self.cof_inv[j]);
            frac += y[j] as f64 * self.inv_p[j];
        }
        // X = Σ y_j·cof_j by product scanning: column l sums y_j·cof_j[l].
        x.clear();
        let mut carry = 0u128;
        for l in 0..m {
            let (lo, hi, top) = dot(y, &self.cof[l * m..(l + 1) * m]);
            // column + carry: carry < 2^128 and the column < m·2^124.
            let (s, o) = ((lo as u128) | ((hi as u128) << 64)).overflowing_add(carry);
            x.push(s as u64);
            carry = (s >> 64) | (((top + o as u64) as u128) << 64);
        }
        let acc = carry;
        x.push(acc as u64);
        x.push((acc >> 64) as u64);
        // c = X − q·M.
        let q = frac.round() as u64;
        let mut qm = Vec::with_capacity(m + 2);
        let mut carry = 0u128;
        for &ml in &self.m_limbs {
            let t = ml as u128 * q as u128 + carry;
            qm.push(t as u64);
            carry = t >> 64;
        }
        qm.push(carry as u64);
        qm.push(0);
        let (neg, big, small) = if cmp_limbs(x, &qm) == std::cmp::Ordering::Less {
            (true, &qm, &*x)
        } else {
            (false, &*x, &qm)
        };
        let mut diff = Vec::with_capacity(big.len());
        let mut borrow = false;
        for (i, &bl) in big.iter().enumerate() {
            let sl = small.get(i).copied().unwrap_or(0);
            let (d1, b1) = bl.overflowing_sub(sl);
            let (d2, b2) = d1.overflowing_sub(borrow as u64);
            diff.push(d2);
            borrow = b1 || b2;
        }
        Int::from_u64_limbs(neg, &diff)
    }
}

fn cmp_limbs(a: &[u64], b: &[u64]) -> std::cmp::Ordering {
    debug_assert_eq!(a.len(), b.len());
    a.iter().rev().cmp(b.iter().rev())
}

/// Product of two nonempty coefficient vectors by the multimodular NTT
/// method; see the module documentation. Falls back to `None` when the
/// product length exceeds the largest supported transform (`2^20`).
pub(crate) fn mul_ntt(a: &[Int], b: &[Int]) -> Option<Vec<Int>> {
    let (la, lb) = (a.len(), b.len());
    debug_assert!(la > 0 && lb > 0);
    let out_len = la + lb - 1;
    let log_n = out_len.next_power_of_two().trailing_zeros();
    if log_n > MAX_LOG_LEN {
        return None;
    }
    let n = 1usize << log_n;
    let abits = a.iter().map(Int::bits).max().unwrap_or(0);
    let bbits = b.iter().map(Int::bits).max().unwrap_or(0);
    if abits == 0 || bbits == 0 {
        return Some(vec![Int::zero(); out_len]);
    }
    // |c_k| ≤ min(la, lb)·2^(abits+bbits); need M > 4·that.
    let bound_bits = abits + bbits + (usize::BITS - la.min(lb).leading_zeros()) as u64 + 2;
    let primes = ntt_primes(primes_for_bits(bound_bits));
    let fields: Vec<Fp> = primes.iter().map(|q| Fp::new(q.p)).collect();
    let (sa, sb) = (to_limbs(a), to_limbs(b));
    let max_limbs = max_limbs(&sa, &sb);
    let m = fields.len();
    let mut residues = vec![0u64; m * out_len];
    let (mut fa, mut fb) = (vec![0u64; n], vec![0u64; n]);
    for (j, (f, q)) in fields.iter().zip(&primes).enumerate() {
        let weights = f.limb_weights(max_limbs);
        fa.fill(0);
        fb.fill(0);
        reduce_all(&sa, f, &weights, &mut fa);
        reduce_all(&sb, f, &weights, &mut fb);
        let tw = Twiddles::new(f, q, log_n);
        forward(&mut fa, &tw, f.p);
        forward(&mut fb, &tw, f.p);
        // Montgomery products of entries below 2p: (A·B·R^{-1})·(R²/N)·R^{-1}
        // = A·B/N, which the unscaled inverse turns into the convolution.
        let scale = f.enter(f.inv(f.enter(n as u64 % f.p)));
        for (x, &y) in fa.iter_mut().zip(&fb) {
            *x = f.mul(f.mul(*x, y), scale);
        }
        inverse(&mut fa, &tw, f.p);
        residues[j * out_len..(j + 1) * out_len].copy_from_slice(&fa[..out_len]);
    }
    let crt = Crt::new(&fields);
    let (mut r, mut y, mut x) = (vec![0u64; m], vec![0u64; m], Vec::with_capacity(m + 2));
    Some(
        (0..out_len)
            .map(|k| {
                for (j, rj) in r.iter_mut().enumerate() {
                    *rj = residues[j * out_len + k];
                }
                crt.lift(&fields, &r, &mut y, &mut x)
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::prime::ntt_prime;

    #[test]
    fn prime_count_is_conservative() {
        for bits in [1u64, 61, 62, 124, 1000, 5000] {
            let m = primes_for_bits(bits);
            let log_m: f64 = (0..m).map(|i| (ntt_prime(i).p as f64).log2()).sum();
            assert!(log_m > bits as f64, "{bits}: {log_m}");
        }
    }

    #[test]
    fn transform_round_trip() {
        let q = ntt_prime(0);
        let f = Fp::new(q.p);
        for log_n in 0..6 {
            let tw = Twiddles::new(&f, &q, log_n);
            let n = 1usize << log_n;
            let v: Vec<u64> = (0..n as u64).map(|i| i * i + 3).collect();
            let mut w = v.clone();
            forward(&mut w, &tw, f.p);
            inverse(&mut w, &tw, f.p);
            let n_mod = n as u64;
            assert_eq!(w, v.iter().map(|x| (x * n_mod) % q.p).collect::<Vec<_>>());
        }
    }
}
