//! Word-size prime fields: Montgomery arithmetic modulo 62-bit primes, a
//! deterministic Miller–Rabin test, and the table of NTT-friendly primes
//! `p = c·2^20 + 1 < 2^62` shared by the multimodular product and the
//! modular gcd.
//!
//! Montgomery form: with `R = 2^64`, an element `x` of `Z/p` is held as
//! `x·R mod p`; the product of two held values is `REDC(a·b) = a·b·R^{-1}`,
//! which costs two word multiplications and no division.

use std::sync::Mutex;

/// The 2-adic order of `p − 1` guaranteed for every table prime: NTTs of
/// length up to `2^MAX_LOG_LEN` exist modulo each of them.
pub(crate) const MAX_LOG_LEN: u32 = 20;

/// `x mod p` for `x < 2p`, without a branch: `x − p` wraps above `2^63`
/// exactly when `x < p` (`p < 2^62`), so the minimum is the reduced value.
#[inline(always)]
fn reduce_once(x: u64, p: u64) -> u64 {
    x.min(x.wrapping_sub(p))
}

/// Arithmetic modulo an odd `p < 2^62` in Montgomery form (`R = 2^64`).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Fp {
    /// The modulus.
    pub p: u64,
    /// `−p^{-1} mod 2^64`.
    pinv_neg: u64,
    /// `R mod p`: the Montgomery form of 1.
    pub one: u64,
    /// `R² mod p`: converts into Montgomery form.
    r2: u64,
    /// `R³ mod p`.
    r3: u64,
}

impl Fp {
    /// The field (ring, for composite odd `p`) of residues modulo odd `p < 2^62`.
    pub fn new(p: u64) -> Fp {
        assert!(
            p % 2 == 1 && p < (1 << 62),
            "Fp: modulus must be odd and below 2^62"
        );
        // Newton iteration for p^{-1} mod 2^64: each step doubles the correct bits.
        let mut inv: u64 = 1;
        for _ in 0..6 {
            inv = inv.wrapping_mul(2u64.wrapping_sub(p.wrapping_mul(inv)));
        }
        let one = ((1u128 << 64) % p as u128) as u64;
        let r2 = ((one as u128 * one as u128) % p as u128) as u64;
        let r3 = ((r2 as u128 * one as u128) % p as u128) as u64;
        Fp {
            p,
            pinv_neg: inv.wrapping_neg(),
            one,
            r2,
            r3,
        }
    }

    /// `REDC(t) = t·R^{-1} mod p` for `t < p·R`; the result is in `[0, p)`.
    #[inline(always)]
    pub fn redc(&self, t: u128) -> u64 {
        let lo = t as u64;
        let m = lo.wrapping_mul(self.pinv_neg);
        let mp = m as u128 * self.p as u128;
        // lo + (mp mod R) ≡ 0 (mod R), so the low word carries exactly when lo ≠ 0.
        let u = (t >> 64) as u64 + (mp >> 64) as u64 + (lo != 0) as u64;
        reduce_once(u, self.p)
    }
    /// Montgomery product `a·b·R^{-1} mod p` (inputs below `2p` are fine).
    #[inline(always)]
    pub fn mul(&self, a: u64, b: u64) -> u64 {
        self.redc(a as u128 * b as u128)
    }
    /// `a + b mod p` for `a, b < p`.
    #[inline(always)]
    pub fn add(&self, a: u64, b: u64) -> u64 {
        reduce_once(a + b, self.p)
    }
    /// `a − b mod p` for `a, b < p`.
    #[inline(always)]
    pub fn sub(&self, a: u64, b: u64) -> u64 {
        // a − b wraps above 2^63 exactly when a < b; then adding p is right.
        let d = a.wrapping_sub(b);
        d.min(d.wrapping_add(self.p))
    }
    /// `−a mod p` for `a < p`.
    #[inline(always)]
    pub fn neg(&self, a: u64) -> u64 {
        if a == 0 {
            0
        } else {
            self.p - a
        }
    }
    /// The Montgomery form `x·R mod p` of `x < p`.
    #[inline(always)]
    pub fn enter(&self, x: u64) -> u64 {
        self.mul(x, self.r2)
    }
    /// Shoup's companion `⌊w·2^64/p⌋` of the residue `w` whose Montgomery
    /// form `w_m = w·2^64 mod p` is given: `w·2^64 − w_m` is an exact
    /// multiple of `p`, so the quotient is `−w_m·p^{-1} mod 2^64`.
    #[inline]
    pub fn shoup(&self, w_m: u64) -> u64 {
        w_m.wrapping_mul(self.pinv_neg)
    }
    /// The plain residue of a Montgomery-form value.
    #[inline(always)]
    pub fn leave(&self, x: u64) -> u64 {
        self.redc(x as u128)
    }
    /// `x^e` with `x` and the result in Montgomery form.
    pub fn pow(&self, x: u64, mut e: u64) -> u64 {
        let (mut base, mut acc) = (x, self.one);
        while e > 0 {
            if e & 1 == 1 {
                acc = self.mul(acc, base);
            }
            base = self.mul(base, base);
            e >>= 1;
        }
        acc
    }
    /// `x^{-1}` (Fermat: `x^{p−2}`), Montgomery form in and out; `p` prime, `x ≠ 0`.
    pub fn inv(&self, x: u64) -> u64 {
        debug_assert!(x != 0, "Fp::inv of zero");
        self.pow(x, self.p - 2)
    }
    /// `2^{64j} mod p` for `j < n`: the weights that reduce a limb vector.
    pub fn limb_weights(&self, n: usize) -> Vec<u64> {
        let mut w = Vec::with_capacity(n);
        let mut x = 1 % self.p;
        // Plain residues: multiplying a plain value by R in Montgomery form
        // (R² mod p) gives the plain value times R.
        for _ in 0..n {
            w.push(x);
            x = self.mul(x, self.r2);
        }
        w
    }
    /// `Σ limbs[j]·2^{64j} mod p` (plain residue) given `weights` from
    /// [`Fp::limb_weights`] of at least the same length.
    #[inline]
    pub fn reduce_limbs(&self, limbs: &[u64], weights: &[u64]) -> u64 {
        let (lo, hi, top) = dot(limbs, weights);
        self.reduce192(lo, hi, top)
    }
    /// `(top·2^128 + hi·2^64 + lo) mod p` (plain residue), for `top < p`.
    #[inline]
    pub fn reduce192(&self, lo: u64, hi: u64, top: u64) -> u64 {
        // y = top·2^64 + hi < p·R, so REDC(y) = y·R^{-1}; times R² (Montgomery) gives y·R.
        let y = self.redc(((top as u128) << 64) | hi as u128);
        let y_r = self.mul(y, self.r3);
        self.add(y_r, lo % self.p)
    }
}

/// `Σ a_j·b_j` over the common length as a 192-bit `(lo, hi, top)`
/// (exact while the sum stays below `2^192`). Two interleaved accumulators
/// keep the carry chains independent.
#[inline]
pub(crate) fn dot(a: &[u64], b: &[u64]) -> (u64, u64, u64) {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let (mut s0, mut t0, mut s1, mut t1) = (0u128, 0u64, 0u128, 0u64);
    let (ca, cb) = (a.chunks_exact(2), b.chunks_exact(2));
    let (ra, rb) = (ca.remainder(), cb.remainder());
    for (x, y) in ca.zip(cb) {
        let (u, o) = s0.overflowing_add(x[0] as u128 * y[0] as u128);
        s0 = u;
        t0 += o as u64;
        let (u, o) = s1.overflowing_add(x[1] as u128 * y[1] as u128);
        s1 = u;
        t1 += o as u64;
    }
    for (&x, &y) in ra.iter().zip(rb) {
        let (u, o) = s0.overflowing_add(x as u128 * y as u128);
        s0 = u;
        t0 += o as u64;
    }
    let (s, o) = s0.overflowing_add(s1);
    (s as u64, (s >> 64) as u64, t0 + t1 + o as u64)
}

/// Deterministic Miller–Rabin for `n < 2^62`: the first twelve prime bases
/// are a proven witness set for all `n < 3.3·10^24`.
pub(crate) fn is_prime(n: u64) -> bool {
    const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
    if n < 2 {
        return false;
    }
    for &b in &BASES {
        if n.is_multiple_of(b) {
            return n == b;
        }
    }
    let f = Fp::new(n);
    let s = (n - 1).trailing_zeros();
    let d = (n - 1) >> s;
    let minus_one = f.neg(f.one);
    'bases: for &b in &BASES {
        let mut x = f.pow(f.enter(b % n), d);
        if x == f.one || x == minus_one {
            continue;
        }
        for _ in 1..s {
            x = f.mul(x, x);
            if x == minus_one {
                continue 'bases;
            }
        }
        return false;
    }
    true
}

/// A table prime with a primitive `2^MAX_LOG_LEN`-th root of unity.
#[derive(Clone, Copy, Debug)]
pub(crate) struct NttPrime {
    /// `p = c·2^MAX_LOG_LEN + 1`, `2^61 < p < 2^62`.
    pub p: u64,
    /// A primitive `2^MAX_LOG_LEN`-th root of unity mod `p`, plain residue.
    pub root: u64,
}

static PRIMES: Mutex<Vec<NttPrime>> = Mutex::new(Vec::new());

/// The first table primes, as [`next_prime`] finds them (a test checks
/// it): a process needs no Miller–Rabin search for its first 48 primes
/// (the search cost a CLI run forming `sr11` for Example 5.1 about 0.1M
/// instructions, once per process).
const FIRST: [NttPrime; 48] = [
    NttPrime {
        p: 0x3ffffffffeb00001,
        root: 0x25f89e017e7ce1ca,
    },
    NttPrime {
        p: 0x3ffffffffa000001,
        root: 0x146621ea4c40b146,
    },
    NttPrime {
        p: 0x3ffffffff9f00001,
        root: 0x1984e856df0ee329,
    },
    NttPrime {
        p: 0x3ffffffff9000001,
        root: 0x2aa8e2e75c02c01c,
    },
    NttPrime {
        p: 0x3ffffffff7b00001,
        root: 0x1c6d45960b3fcd33,
    },
    NttPrime {
        p: 0x3ffffffff7600001,
        root: 0x1ff6c4eb0712f0c8,
    },
    NttPrime {
        p: 0x3ffffffff6700001,
        root: 0x90cca1d5b04f18a,
    },
    NttPrime {
        p: 0x3ffffffff5e00001,
        root: 0x8e5c78d440db306,
    },
    NttPrime {
        p: 0x3ffffffff4f00001,
        root: 0x1adfc21c4970e0ac,
    },
    NttPrime {
        p: 0x3ffffffff4600001,
        root: 0x25fd3235be219098,
    },
    NttPrime {
        p: 0x3ffffffff3700001,
        root: 0x3cab0b83f135af12,
    },
    NttPrime {
        p: 0x3ffffffff1b00001,
        root: 0x1cdfd8fe5019f221,
    },
    NttPrime {
        p: 0x3ffffffff0c00001,
        root: 0x1caa7581754892c8,
    },
    NttPrime {
        p: 0x3fffffffece00001,
        root: 0x2c838c0df60c011a,
    },
    NttPrime {
        p: 0x3fffffffeaf00001,
        root: 0xc15f0f0bf40f1fb,
    },
    NttPrime {
        p: 0x3fffffffea300001,
        root: 0x2c2783f0fa38ab73,
    },
    NttPrime {
        p: 0x3fffffffea000001,
        root: 0xf9a7dfcd359d6aa,
    },
    NttPrime {
        p: 0x3fffffffe9a00001,
        root: 0x31763c3e1e3c42c0,
    },
    NttPrime {
        p: 0x3fffffffe9500001,
        root: 0x130103eebc59829,
    },
    NttPrime {
        p: 0x3fffffffe5000001,
        root: 0x6a734213fa856b8,
    },
    NttPrime {
        p: 0x3fffffffe3b00001,
        root: 0x3dec66e9694b266d,
    },
    NttPrime {
        p: 0x3fffffffe2b00001,
        root: 0x22d7cfbe4a0bf80a,
    },
    NttPrime {
        p: 0x3fffffffe2900001,
        root: 0x4baa8e38ec1a5e9,
    },
    NttPrime {
        p: 0x3fffffffe2300001,
        root: 0x1111ff880a4a77ad,
    },
    NttPrime {
        p: 0x3fffffffdf900001,
        root: 0x2f2735d94d319001,
    },
    NttPrime {
        p: 0x3fffffffdf500001,
        root: 0x25297a1984cc0ee6,
    },
    NttPrime {
        p: 0x3fffffffdb600001,
        root: 0x36f263ac50b327fc,
    },
    NttPrime {
        p: 0x3fffffffda100001,
        root: 0x143fc91897e1f9de,
    },
    NttPrime {
        p: 0x3fffffffd9800001,
        root: 0x322657d177e2fd19,
    },
    NttPrime {
        p: 0x3fffffffd9000001,
        root: 0x36d719c3788820d6,
    },
    NttPrime {
        p: 0x3fffffffd6900001,
        root: 0x27fa949957d55ffa,
    },
    NttPrime {
        p: 0x3fffffffd5900001,
        root: 0x359baacef8f82b10,
    },
    NttPrime {
        p: 0x3fffffffd3600001,
        root: 0x1066c4ec47b040c6,
    },
    NttPrime {
        p: 0x3fffffffd2a00001,
        root: 0x3c6866bf7437ade9,
    },
    NttPrime {
        p: 0x3fffffffd1800001,
        root: 0x38e9400a7e325e43,
    },
    NttPrime {
        p: 0x3fffffffd1500001,
        root: 0x2905f2a12ab5484e,
    },
    NttPrime {
        p: 0x3fffffffce200001,
        root: 0x27760a74ceadfe78,
    },
    NttPrime {
        p: 0x3fffffffcc000001,
        root: 0x22324ae1ea6544a4,
    },
    NttPrime {
        p: 0x3fffffffca800001,
        root: 0x2ad929e0f5fe0659,
    },
    NttPrime {
        p: 0x3fffffffc9c00001,
        root: 0xc5324193c613555,
    },
    NttPrime {
        p: 0x3fffffffc9100001,
        root: 0x35271c1772cda34e,
    },
    NttPrime {
        p: 0x3fffffffc8d00001,
        root: 0xdd84ceb54aa9e38,
    },
    NttPrime {
        p: 0x3fffffffc8800001,
        root: 0x2890a58a5144e368,
    },
    NttPrime {
        p: 0x3fffffffc8700001,
        root: 0x283f55f8eaf02dbd,
    },
    NttPrime {
        p: 0x3fffffffc8200001,
        root: 0x113dd545ef0c50fa,
    },
    NttPrime {
        p: 0x3fffffffc7b00001,
        root: 0x23c530d188a30d23,
    },
    NttPrime {
        p: 0x3fffffffc7900001,
        root: 0x110c8f62918e88ec,
    },
    NttPrime {
        p: 0x3fffffffc5d00001,
        root: 0x1ff9ca1636ad54ad,
    },
];

/// The table with at least `count` primes.
fn table(count: usize) -> std::sync::MutexGuard<'static, Vec<NttPrime>> {
    let mut table = PRIMES.lock().unwrap_or_else(|e| e.into_inner());
    if table.is_empty() {
        table.extend_from_slice(&FIRST);
    }
    while table.len() < count {
        let prev = table.last().map_or(1u64 << 62, |q| q.p);
        let next = next_prime(prev);
        table.push(next);
    }
    table
}

/// The next table prime below `p_prev`, found by testing `c·2^20 + 1` for
/// decreasing `c`.
fn next_prime(p_prev: u64) -> NttPrime {
    let step = 1u64 << MAX_LOG_LEN;
    let mut c = (p_prev - 1) / step - 1;
    loop {
        let p = c * step + 1;
        assert!(p > 1 << 61, "prime table exhausted");
        if is_prime(p) {
            let f = Fp::new(p);
            // a^((p−1)/2^20) has order exactly 2^20 iff a is a non-residue.
            for a in 2.. {
                let w = f.pow(f.enter(a), (p - 1) >> MAX_LOG_LEN);
                let half = f.pow(w, 1 << (MAX_LOG_LEN - 1));
                if half != f.one {
                    return NttPrime {
                        p,
                        root: f.leave(w),
                    };
                }
            }
        }
        c -= 1;
    }
}

/// The first `count` table primes (descending from `2^62`): the known
/// ones, then generated on first use and cached for the life of the process.
pub(crate) fn ntt_primes(count: usize) -> Vec<NttPrime> {
    table(count)[..count].to_vec()
}

/// The `i`-th table prime.
pub(crate) fn ntt_prime(i: usize) -> NttPrime {
    FIRST.get(i).copied().unwrap_or_else(|| table(i + 1)[i])
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Int;
    use proptest::prelude::*;

    fn naive_prime(n: u64) -> bool {
        n >= 2
            && (2..)
                .take_while(|d| d * d <= n)
                .all(|d| !n.is_multiple_of(d))
    }

    /// The built-in primes are the ones the search finds, in order, each
    /// with a root of unity of order exactly `2^MAX_LOG_LEN`.
    #[test]
    fn built_in_primes_are_the_searched_ones() {
        let mut prev = 1u64 << 62;
        for q in FIRST {
            let found = next_prime(prev);
            assert_eq!((q.p, q.root), (found.p, found.root));
            let f = Fp::new(q.p);
            let w = f.enter(q.root);
            assert_ne!(f.pow(w, 1 << (MAX_LOG_LEN - 1)), f.one);
            assert_eq!(f.pow(w, 1 << MAX_LOG_LEN), f.one);
            prev = q.p;
        }
        assert_eq!(
            ntt_primes(50)[..48].iter().map(|q| q.p).collect::<Vec<_>>(),
            FIRST.map(|q| q.p)
        );
        assert_eq!(ntt_prime(49).p, ntt_primes(50)[49].p);
    }

    #[test]
    fn miller_rabin_matches_trial_division() {
        for n in 0..5000u64 {
            assert_eq!(is_prime(n), naive_prime(n), "{n}");
        }
        // Strong pseudoprimes to several small bases.
        for n in [
            3215031751u64,
            2152302898747,
            3474749660383,
            341550071728321,
            3825123056546413051,
        ] {
            if n < 1 << 62 {
                assert!(!is_prime(n), "{n}");
            }
        }
        assert!(is_prime((1 << 61) - 1));
    }

    #[test]
    fn table_primes_have_roots_of_unity() {
        let ps = ntt_primes(4);
        for w in ps.windows(2) {
            assert!(w[0].p > w[1].p);
        }
        for q in ps {
            assert!(is_prime(q.p) && q.p % (1 << MAX_LOG_LEN) == 1 && q.p > 1 << 61);
            let f = Fp::new(q.p);
            let w = f.enter(q.root);
            assert_eq!(f.pow(w, 1 << MAX_LOG_LEN), f.one);
            assert_ne!(f.pow(w, 1 << (MAX_LOG_LEN - 1)), f.one);
        }
    }

    proptest! {
        #[test]
        fn montgomery_matches_u128(a in any::<u64>(), b in any::<u64>(), k in 0usize..3) {
            let p = ntt_prime(k).p;
            let f = Fp::new(p);
            let (x, y) = (a % p, b % p);
            let prod = f.leave(f.mul(f.enter(x), f.enter(y)));
            prop_assert_eq!(prod as u128, x as u128 * y as u128 % p as u128);
            prop_assert_eq!(f.add(x, y) as u128, (x as u128 + y as u128) % p as u128);
            prop_assert_eq!(f.add(f.sub(x, y), y), x);
            if x != 0 {
                prop_assert_eq!(f.mul(f.inv(f.enter(x)), f.enter(x)), f.one);
            }
        }

        #[test]
        fn limb_reduction_matches_int(limbs in prop::collection::vec(any::<u64>(), 0..40)) {
            let p = ntt_prime(1).p;
            let f = Fp::new(p);
            let w = f.limb_weights(limbs.len());
            let x = Int::from_u64_limbs(false, &limbs);
            prop_assert_eq!(f.reduce_limbs(&limbs, &w), x.mod_u64(p));
        }
    }
}
