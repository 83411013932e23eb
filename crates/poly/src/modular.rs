//! The modular gcd in `Z[t]` (Brown / Collins): gcds modulo word primes,
//! combined by the Chinese remainder theorem, proven by trial division.
//!
//! Let `a, b` be primitive, `G = gcd(a, b)` (primitive, positive leading
//! coefficient), `γ = gcd(lc a, lc b)`. For a prime `p ∤ lc(a)·lc(b)`:
//!
//! 1. `G mod p` divides `gcd(a mod p, b mod p)`, so
//!    `deg gcd_p ≥ deg G`; equality fails ("unlucky" `p`) only for the
//!    finitely many primes dividing a certain subresultant. Keeping the
//!    images of the lowest degree seen discards every unlucky prime once a
//!    lucky one appears, and a degree-0 image proves `G = 1` at once.
//! 2. `lc(G) | γ`, so `H = (γ / lc G)·G ∈ Z[t]`, and for lucky `p` the
//!    image `γ·monic(gcd_p) ≡ H (mod p)`: normalising every image to leading
//!    coefficient `γ` makes them images of one integer polynomial, which CRT
//!    with symmetric residues recovers once `Π p > 2·max|H_i|`.
//! 3. Whatever the primes, a candidate `C = pp(h)` is accepted only after
//!    exact trial division `C | a` and `C | b` in `Z[t]`. Then `C | G`, so
//!    `deg C ≤ deg G`; and `deg C = deg gcd_p ≥ deg G` by (1). Hence `C` and
//!    `G` are associates, both primitive with positive leading coefficient:
//!    `C = G`. A failed verification only means more primes are needed.
//!
//! The images may be taken of non-primitive inputs: at a prime not dividing
//! their leading coefficients the contents are units modulo `p`, so the
//! monic image gcd is that of the primitive parts. So a degree-0 image
//! proves coprimality before any content is computed.
//!
//! Termination: all but finitely many primes are lucky, and after enough
//! lucky primes the reconstruction equals `H`, is stable, and verifies.
//!
//! [`ZPoly::gcd`] and [`ZPoly::squarefree_part`] are defined here.

use crate::ntt::{reduce_all, to_limbs};
use crate::prime::{ntt_prime, Fp};
use crate::ZPoly;
use ccd_arith::Int;

/// Drops trailing zeros.
fn trim(v: &mut Vec<u64>) {
    while v.last() == Some(&0) {
        v.pop();
    }
}

/// `a ← c·(a mod b)` in `F_p[t]` (Montgomery form) for some nonzero
/// constant `c`, `b` nonzero and trimmed: each step is `a ← lc(b)·a −
/// top(a)·t^j·b`, with no inversion. A gcd only needs remainders up to a
/// constant, and an inversion (Fermat: about 90 products) costs more than
/// the second product per coefficient it saves until degree ~90.
fn rem_in_place(a: &mut Vec<u64>, b: &[u64], f: &Fp) {
    let db = b.len() - 1;
    let lc = b[db];
    while a.len() > db {
        let top = a.pop().expect("a.len() > db >= 0");
        if top == 0 {
            continue;
        }
        let off = a.len() - db;
        let (low, high) = a.split_at_mut(off);
        for x in low {
            *x = f.mul(*x, lc);
        }
        for (x, &y) in high.iter_mut().zip(b) {
            *x = f.sub(f.mul(*x, lc), f.mul(top, y));
        }
    }
    trim(a);
}

/// The monic gcd of two polynomials over `F_p` (Montgomery form in and out)
/// by Euclid's algorithm (remainders up to constants); empty when both are
/// zero.
pub(crate) fn gcd_mod_p(mut a: Vec<u64>, mut b: Vec<u64>, f: &Fp) -> Vec<u64> {
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        rem_in_place(&mut a, &b, f);
        std::mem::swap(&mut a, &mut b);
    }
    if let Some(&lc) = a.last() {
        let inv = f.inv(lc);
        for x in a.iter_mut() {
            *x = f.mul(*x, inv);
        }
    }
    a
}

/// The residue `r ∈ [0, p)` as the integer of `(−p/2, p/2]`.
fn symmetric(r: u64, p: u64) -> Int {
    if r > p / 2 {
        Int::from_i64(r as i64 - p as i64)
    } else {
        Int::from_u64(r)
    }
}

/// Incremental CRT: the integer polynomial `h` with `|h_i| ≤ M/2` known
/// modulo `M`, extended by the image `r` modulo `p` (plain residues).
/// Returns whether any coefficient changed.
fn crt_extend(h: &mut [Int], modulus: &mut Int, r: &[u64], f: &Fp) -> bool {
    let m_inv = f.inv(f.enter(modulus.mod_u64(f.p)));
    let mut changed = false;
    let new_modulus = modulus.mul_i64(f.p as i64);
    let half = new_modulus.shr_floor(1);
    for (hi, &ri) in h.iter_mut().zip(r) {
        // δ = (r − h)·M^{-1} mod p; plain × Montgomery-form = plain.
        let delta = f.mul(f.sub(ri, hi.mod_u64(f.p)), m_inv);
        if delta == 0 {
            continue;
        }
        changed = true;
        hi.add_mul(modulus, &symmetric(delta, f.p));
        if *hi > half {
            *hi -= &new_modulus;
        } else if *hi < -&half {
            *hi += &new_modulus;
        }
    }
    *modulus = new_modulus;
    changed
}

/// The coefficients (as limbs) modulo `f.p`, in Montgomery form.
fn image(limbs: &[(bool, Vec<u64>)], f: &Fp, weights: &[u64]) -> Vec<u64> {
    let mut r = vec![0u64; limbs.len()];
    reduce_all(limbs, f, weights, &mut r);
    r.into_iter().map(|x| f.enter(x)).collect()
}

/// Whether `a` (degree ≥ 1) is proven squarefree by one word prime `p ∤ lc(a)`:
/// a repeated factor `g²` of `a` over ℚ reduces to one of `a mod p` (of the
/// same degree), so `gcd(a mod p, a′ mod p) = 1` rules it out. `false`
/// means "not proven" (a repeated factor, or an unlucky prime).
pub(crate) fn squarefree_by_prime(a: &ZPoly) -> bool {
    let Some(lc) = a.leading() else {
        return false;
    };
    let limbs = to_limbs(a.coeffs());
    let Some(f) = (0..4)
        .map(|index| Fp::new(ntt_prime(index).p))
        .find(|f| lc.mod_u64(f.p) != 0)
    else {
        return false;
    };
    let r = image(
        &limbs,
        &f,
        &f.limb_weights(crate::ntt::max_limbs(&limbs, &[])),
    );
    // a′ mod p: i·a_i for i ≥ 1 (degree < p, so its top coefficient survives).
    let d: Vec<u64> = r
        .iter()
        .enumerate()
        .skip(1)
        .map(|(i, &x)| f.mul(f.enter(i as u64), x))
        .collect();
    gcd_mod_p(r, d, &f).len() == 1
}

/// `gcd(a, b)` over `Q[t]`, primitive with positive leading coefficient;
/// see the module documentation for the algorithm and its proof.
pub(crate) fn gcd(a: &ZPoly, b: &ZPoly) -> ZPoly {
    let (Some(da), Some(db)) = (a.degree(), b.degree()) else {
        return if a.is_zero() {
            b.primitive_part()
        } else {
            a.primitive_part()
        };
    };
    if da == 0 || db == 0 {
        return ZPoly::one();
    }
    // The images are taken of `a` and `b` as given, at primes `p ∤ lc(a)·lc(b)`:
    // then `p` divides neither content, so the monic `gcd(a mod p, b mod p)`
    // is that of the primitive parts. Those (and `γ`) are formed only once
    // an image is not constant: a coprime pair, the common case of a zero
    // test, is proven by one prime without them.
    let (lca, lcb) = (a.leading().expect("nonzero"), b.leading().expect("nonzero"));
    let (sa, sb) = (to_limbs(a.coeffs()), to_limbs(b.coeffs()));
    let max_limbs = crate::ntt::max_limbs(&sa, &sb);
    let mut primitive: Option<(ZPoly, ZPoly, Int)> = None;
    // The current reconstruction: its degree, coefficients and modulus.
    let mut best: Option<(usize, Vec<Int>, Int)> = None;
    for index in 0.. {
        let f = Fp::new(ntt_prime(index).p);
        if lca.mod_u64(f.p) == 0 || lcb.mod_u64(f.p) == 0 {
            continue;
        }
        let weights = f.limb_weights(max_limbs);
        let g = gcd_mod_p(image(&sa, &f, &weights), image(&sb, &f, &weights), &f);
        let d = g.len() - 1;
        if d == 0 {
            return ZPoly::one();
        }
        let (pa, pb, gamma) = primitive.get_or_insert_with(|| {
            let (pa, pb) = (a.primitive_part(), b.primitive_part());
            let gamma = pa
                .leading()
                .expect("nonzero")
                .gcd(pb.leading().expect("nonzero"));
            (pa, pb, gamma)
        });
        // γ·monic(g), plain residues.
        let gamma_m = f.enter(gamma.mod_u64(f.p));
        let image: Vec<u64> = g.iter().map(|&x| f.leave(f.mul(x, gamma_m))).collect();
        match &mut best {
            Some((bd, h, modulus)) if *bd == d => {
                if crt_extend(h, modulus, &image, &f) {
                    continue;
                }
                let cand = ZPoly::new(h.clone()).primitive_part();
                if pa.div_exact(&cand).is_some() && pb.div_exact(&cand).is_some() {
                    return cand;
                }
            }
            Some((bd, _, _)) if *bd < d => continue,
            _ => {
                let h = image.iter().map(|&r| symmetric(r, f.p)).collect();
                best = Some((d, h, Int::from_u64(f.p)));
            }
        }
    }
    unreachable!("the prime loop only ends by returning")
}

/// The entry points on [`ZPoly`].
impl ZPoly {
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
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gcd_mod_small_prime() {
        // (t − 1)(t + 2) and (t − 1)(t + 3) modulo a table prime.
        let f = Fp::new(ntt_prime(0).p);
        let m = |v: &[i64]| {
            v.iter()
                .map(|&x| f.enter(x.rem_euclid(f.p as i64) as u64))
                .collect::<Vec<_>>()
        };
        let g = gcd_mod_p(m(&[-2, 1, 1]), m(&[-3, 2, 1]), &f);
        assert_eq!(g, m(&[-1, 1]));
        assert!(gcd_mod_p(vec![], vec![0], &f).is_empty());
    }

    #[test]
    fn crt_recovers_signed_values() {
        let vals = [
            Int::from(-5),
            Int::one().shl(100) + Int::from(7),
            -Int::one().shl(90),
        ];
        let mut h: Option<(Vec<Int>, Int)> = None;
        for i in 0..3 {
            let f = Fp::new(ntt_prime(i).p);
            let r: Vec<u64> = vals.iter().map(|v| v.mod_u64(f.p)).collect();
            match &mut h {
                None => {
                    h = Some((
                        r.iter().map(|&x| symmetric(x, f.p)).collect(),
                        Int::from_u64(f.p),
                    ))
                }
                Some((hv, m)) => {
                    crt_extend(hv, m, &r, &f);
                }
            }
        }
        assert_eq!(h.expect("three primes").0, vals.to_vec());
    }
}

#[cfg(test)]
mod gcd_tests {
    use crate::testutil::{zpoly, zpoly_deg};
    use crate::ZPoly;
    use ccd_arith::Int;
    use proptest::prelude::*;

    fn z(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
    }

    #[test]
    fn zero_and_constant_cases() {
        assert_eq!(ZPoly::zero().gcd(&ZPoly::zero()), ZPoly::zero());
        assert_eq!(z(&[-4, -6]).gcd(&ZPoly::zero()), z(&[2, 3]));
        assert_eq!(ZPoly::zero().gcd(&z(&[4, 6])), z(&[2, 3]));
        assert_eq!(z(&[7]).gcd(&z(&[1, 1])), ZPoly::one());
        assert_eq!(z(&[7]).gcd(&ZPoly::zero()), ZPoly::one());
    }

    #[test]
    fn squarefree_part_of_repeated_factors() {
        let (a, b, c) = (z(&[-1, 1]), z(&[2, 1]), z(&[1, 0, 1]));
        let p = &(&a.pow(3) * &b.pow(2)) * &c;
        assert_eq!(p.squarefree_part(), &(&a * &b) * &c);
        assert_eq!(p.mul_int(&Int::from(-6)).squarefree_part(), &(&a * &b) * &c);
        assert_eq!(z(&[5]).squarefree_part(), ZPoly::one());
        assert_eq!(ZPoly::zero().squarefree_part(), ZPoly::zero());
    }

    #[test]
    fn squarefree_proof_by_one_prime() {
        use super::squarefree_by_prime;
        let (a, b) = (z(&[-1, 1]), z(&[2, 0, 1]));
        assert!(squarefree_by_prime(&(&a * &b)));
        assert!(!squarefree_by_prime(&(&a.pow(2) * &b)));
        // t² − p0² is squarefree but ≡ t² modulo p0: unproven there, so
        // another prime decides it (t² − p0² has roots ±p0).
        let p0 = Int::from_u64(crate::prime::ntt_prime(0).p);
        let unlucky = ZPoly::new(vec![-(&p0 * &p0), Int::zero(), Int::one()]);
        assert!(!squarefree_by_prime(&unlucky));
        assert_eq!(unlucky.squarefree_part(), unlucky);
    }

    #[test]
    fn contents_do_not_change_the_gcd() {
        let (u, v, w) = (z(&[-1, 1]), z(&[2, 1]), z(&[3, 1]));
        let a = (&u * &v).mul_int(&Int::from(6));
        assert_eq!(a.gcd(&w.mul_int(&Int::from(-10))), ZPoly::one());
        assert_eq!(a.gcd(&(&u * &w).mul_int(&Int::from(4))), u);
        // A content divisible by the first prime: that prime is skipped.
        let p0 = Int::from_u64(crate::prime::ntt_prime(0).p);
        assert_eq!(a.mul_int(&p0).gcd(&(&v * &w).mul_int(&p0)), v);
    }

    #[test]
    fn unlucky_and_skipped_primes() {
        let p0 = Int::from_u64(crate::prime::ntt_prime(0).p);
        let t = ZPoly::x();
        // t and t − p0 agree modulo the first prime: an unlucky degree-1 image.
        let shifted = ZPoly::new(vec![-&p0, Int::one()]);
        assert_eq!(t.gcd(&shifted), ZPoly::one());
        let g = z(&[1, 1]);
        assert_eq!((&g * &t).gcd(&(&g * &shifted)), g);
        // Leading coefficient divisible by the first prime: that prime is skipped.
        let a = ZPoly::new(vec![Int::from(3), p0.clone()]);
        assert_eq!((&a * &g).gcd(&(&g * &z(&[5, 1]))), g);
    }

    #[test]
    fn large_common_factor_needs_many_primes() {
        // Deterministic pseudo-random 600-bit coefficients.
        let mut s = 0x2545F4914F6CDD1Du64;
        let mut coeffs = |n: usize| {
            ZPoly::new(
                (0..n)
                    .map(|_| {
                        let limbs: Vec<u64> = (0..10)
                            .map(|_| {
                                s ^= s << 13;
                                s ^= s >> 7;
                                s ^= s << 17;
                                s
                            })
                            .collect();
                        Int::from_u64_limbs(s & 1 == 1, &limbs)
                    })
                    .collect(),
            )
        };
        let (g, u, v) = (coeffs(11), coeffs(31), coeffs(29));
        let expect = g.primitive_part();
        assert_eq!((&g * &u).gcd(&(&g * &v)), expect);
        assert_eq!((&g * &u).gcd(&(&g.pow(2) * &v)), expect);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn common_factor_is_found(a in zpoly(7, 120), b in zpoly(7, 120), g in zpoly_deg(0, 6, 120)) {
            let expect = (&g * &a.gcd(&b)).primitive_part();
            let got = (&a * &g).gcd(&(&b * &g));
            if a.is_zero() && b.is_zero() {
                prop_assert!(got.is_zero());
            } else {
                prop_assert_eq!(got, expect);
            }
        }

        #[test]
        fn consecutive_polynomials_are_coprime(a in zpoly_deg(1, 12, 300), c in 1i64..1000) {
            // Any common divisor of a and a + c divides the constant c.
            prop_assert_eq!(a.gcd(&(&a + &z(&[c]))), ZPoly::one());
        }

        #[test]
        fn gcd_divides_both(a in zpoly_deg(1, 9, 200), b in zpoly_deg(1, 9, 200)) {
            let g = a.gcd(&b);
            prop_assert!(a.div_exact(&g).is_some() && b.div_exact(&g).is_some());
            prop_assert_eq!(g.clone(), b.gcd(&a));
            let sf = (&a * &a).squarefree_part();
            prop_assert_eq!(sf.gcd(&sf.derivative()), ZPoly::one());
        }
    }
}
