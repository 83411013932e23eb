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
//! 3. The same images, left monic, are images of `G/lc(G) ∈ Q[t]`, whose
//!    coefficients are fractions `n/d` with `|n|, d ≤ ‖G‖∞`. Rational
//!    reconstruction (Wang) recovers them from a modulus `M > 2·B²` with
//!    `B ≥ ‖G‖∞`, so about twice the bits of `G`'s own coefficients
//!    suffice, however long `γ` is. (2) needs `M > 2·‖H‖∞`, which is
//!    `γ/lc(G)` times more: a small gcd of polynomials with long leading
//!    coefficients took thousands of primes that way. Both candidates are
//!    formed from the same images; the first verified wins.
//! 4. Whatever the primes, a candidate `C = pp(h)` of degree `deg gcd_p` is
//!    accepted only after exact trial division `C | a` and `C | b` in
//!    `Z[t]`. Then `C | G`, so `deg C ≤ deg G`; and `deg C = deg gcd_p ≥
//!    deg G` by (1). Hence `C` and `G` are associates, both primitive with
//!    positive leading coefficient: `C = G`. A failed verification only
//!    means more primes are needed.
//!
//! The images may be taken of non-primitive inputs: at a prime not dividing
//! their leading coefficients the contents are units modulo `p`, so the
//! monic image gcd is that of the primitive parts. So a degree-0 image
//! proves coprimality before any content is computed.
//!
//! Termination: all but finitely many primes are lucky, and after enough
//! lucky primes the reconstruction (2) equals `H`, is stable, and verifies.
//!
//! [`ZPoly::gcd`] and [`ZPoly::squarefree_part`] are defined here.

use crate::ntt::{reduce_all, to_limbs};
use crate::prime::{ntt_prime, Fp};
use crate::{Residues, ZPoly};
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
    match a[..] {
        // A constant gcd (a coprime pair, the usual answer) is monic 1:
        // no inverse (an exponentiation) to find that.
        [_] => a[0] = f.enter(1),
        [.., lc] => {
            let inv = f.inv(lc);
            for x in a.iter_mut() {
                *x = f.mul(*x, inv);
            }
        }
        [] => {}
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

/// One step of incremental CRT, from the modulus `M` to `M·p`: the
/// integer polynomials with `|h_i| ≤ M/2` known modulo `M`, extended by
/// their images modulo `p`.
struct CrtStep<'a> {
    /// `M`.
    modulus: &'a Int,
    /// `M·p`.
    next: Int,
    /// `⌊M·p/2⌋`.
    half: Int,
    /// `M^{-1} mod p`, Montgomery form.
    m_inv: u64,
}

impl<'a> CrtStep<'a> {
    fn new(modulus: &'a Int, f: &Fp) -> CrtStep<'a> {
        let next = modulus.mul_i64(f.p as i64);
        CrtStep {
            modulus,
            half: next.shr_floor(1),
            next,
            m_inv: f.inv(f.enter(modulus.mod_u64(f.p))),
        }
    }

    /// `h` (known modulo `M`) extended by its image `r` modulo `p` (plain
    /// residues) to the one of `(−M·p/2, M·p/2]`. Returns whether any
    /// coefficient changed.
    fn extend(&self, h: &mut [Int], r: &[u64], f: &Fp) -> bool {
        let mut changed = false;
        for (hi, &ri) in h.iter_mut().zip(r) {
            // δ = (r − h)·M^{-1} mod p; plain × Montgomery-form = plain.
            let delta = f.mul(f.sub(ri, hi.mod_u64(f.p)), self.m_inv);
            if delta == 0 {
                continue;
            }
            changed = true;
            hi.add_mul(self.modulus, &symmetric(delta, f.p));
            if *hi > self.half {
                *hi -= &self.next;
            } else if *hi < -&self.half {
                *hi += &self.next;
            }
        }
        changed
    }
}

/// Moduli up to this many bits are tried by rational reconstruction
/// ([`rational_candidate`], module docs (3)); past it the scaled
/// reconstruction (2) goes on alone. A small gcd is found far below it.
const RATIONAL_MAX_BITS: u64 = 1 << 16;

/// The most images rational reconstruction is tried from, for inputs whose
/// images cost `image_words` word products a prime
/// (`limbs·(deg a + deg b + 2)`) and `γ` of `gamma_bits` bits: a cost rule
/// only (the candidate is proven by trial division either way). The scaled
/// lift (2) needs `M > 2·‖H‖∞ ≥ 2·γ`, so at least `P = bits(γ)/62`
/// primes, `P` images.
/// An attempt from `k` images costs about as much as `285·k²` image words
/// (the Euclidean algorithm on `62·k`-bit numbers, [`wang`]: ~2,000
/// instructions per `k²` against ~7 per image word, measured at 500 bits on
/// `graze-turned-k100-miss`), and the attempts up to `k` (geometric, see
/// [`try_rational_at`]) about 2.5 times the last; so they stop at `k² ≤
/// P·image_words/20000`, a thirtieth of those `P` images (a tenth cost
/// `graze-turned-k100-miss`, whose gcd needs 56 primes one way and 48 the
/// other, 1.1 % of its query). Never past [`RATIONAL_MAX_BITS`] of modulus.
fn rational_until(gamma_bits: u64, image_words: u64) -> usize {
    let budget = (gamma_bits / 62).saturating_mul(image_words) / 20000;
    let k = (budget as f64).sqrt() as u64;
    k.min(RATIONAL_MAX_BITS / 62) as usize
}

/// Whether `count` images are a point to try rational reconstruction: 1, 2,
/// 3, 4, 6, 8, 12, … (a power of two or three times one), so the attempts
/// cost a constant factor over the last one.
fn try_rational_at(count: usize) -> bool {
    debug_assert!(count > 0, "images are counted from one");
    let odd = count >> count.trailing_zeros();
    odd == 1 || odd == 3
}

/// Wang's rational reconstruction: for `0 ≤ x < m`, the fraction `n/d`
/// with `n ≡ d·x (mod m)`, `|n| ≤ b` and `0 < d ≤ b`, from the extended
/// Euclidean algorithm on `(m, x)` stopped at the first remainder `≤ b`
/// (the remainder is `n`, its cofactor of `x` is `d` up to sign). When
/// `2·b² < m` such a fraction is unique, so this is it; `None` when there is
/// none.
fn wang(x: &Int, m: &Int, b: &Int) -> Option<(Int, Int)> {
    let (mut r0, mut r1) = (m.clone(), x.clone());
    let (mut t0, mut t1) = (Int::zero(), Int::one());
    while r1 > *b {
        let (q, r) = r0.div_rem_trunc(&r1);
        let t = &t0 - &(&q * &t1);
        (r0, r1, t0, t1) = (r1, r, t1, t);
    }
    if t1.is_zero() || t1.abs() > *b {
        return None;
    }
    Some(if t1.is_negative() {
        (-r1, -t1)
    } else {
        (r1, t1)
    })
}

/// The primitive integer polynomial whose monic form has the residues
/// `monic` (symmetric, modulo `modulus`), by rational reconstruction
/// (module docs (3)): with `B = 2^⌊(bits M − 2)/2⌋` (so `2·B² < M`), each
/// coefficient times the common denominator `D` found so far is a residue
/// `x`, taken as the fraction `n/d` of [`wang`] (`d = 1` for an `x`
/// within `B` of a multiple of `M`), with `D·d ≤ B`. `None` when a
/// coefficient has no such fraction (more primes needed). A candidate
/// only: the caller proves it by trial division.
fn rational_candidate(monic: &[Int], modulus: &Int) -> Option<ZPoly> {
    let bound = Int::one().shl(modulus.bits().saturating_sub(2) / 2);
    let mut den = Int::one();
    let mut nums: Vec<Int> = Vec::with_capacity(monic.len());
    for c in monic {
        let scaled = c * &den;
        let x = &scaled - &(&scaled.div_floor(modulus) * modulus);
        let (n, d) = wang(&x, modulus, &bound)?;
        if !d.is_one() {
            den = &den * &d;
            if den > bound {
                return None;
            }
            for v in &mut nums {
                *v = &*v * &d;
            }
        }
        nums.push(n);
    }
    Some(ZPoly::new(nums).primitive_part())
}

/// [`image`] of a polynomial whose coefficients all fit an `i64` (a
/// scene's motions), straight from the words (`enter` gives the canonical
/// residue, so the same values): `None` when one is longer.
fn word_image(a: &ZPoly, f: &Fp) -> Option<Vec<u64>> {
    // p < 2^62: a positive i64.
    let p = f.p as i64;
    a.coeffs()
        .iter()
        .map(|c| Some(f.enter(c.to_i64()?.rem_euclid(p) as u64)))
        .collect()
}

/// The coefficients (as limbs) modulo `f.p`, in Montgomery form.
fn image(limbs: &[(bool, Vec<u64>)], f: &Fp, weights: &[u64]) -> Vec<u64> {
    let mut r = vec![0u64; limbs.len()];
    reduce_all(limbs, f, weights, &mut r);
    r.into_iter().map(|x| f.enter(x)).collect()
}

/// A polynomial's coefficients ready for their images modulo word primes:
/// the coefficients themselves when each fits an `i64` (a scene's
/// motions: [`word_image`], one remainder each), else their limbs
/// ([`image`]).
enum Source<'a> {
    Words(&'a ZPoly),
    Limbs(Vec<(bool, Vec<u64>)>),
}

impl<'a> Source<'a> {
    fn new(a: &'a ZPoly) -> Source<'a> {
        if a.coeffs().iter().all(|c| c.to_i64().is_some()) {
            Source::Words(a)
        } else {
            Source::Limbs(to_limbs(a.coeffs()))
        }
    }

    /// The limbs [`Source::image`]'s weights must cover: the most limbs of
    /// a coefficient, none for words (no weights formed).
    fn limbs(&self) -> usize {
        match self {
            Source::Words(_) => 0,
            Source::Limbs(limbs) => crate::ntt::max_limbs(limbs, &[]),
        }
    }

    /// The coefficients modulo `f.p`, in Montgomery form (`weights` from
    /// [`Fp::limb_weights`] for at least [`Source::limbs`] limbs).
    fn image(&self, f: &Fp, weights: &[u64]) -> Vec<u64> {
        match self {
            Source::Words(a) => word_image(a, f).expect("every coefficient a word"),
            Source::Limbs(limbs) => image(limbs, f, weights),
        }
    }
}

/// Whether `a` (degree ≥ 1) is proven squarefree by one word prime `p ∤ lc(a)`:
/// a repeated factor `g²` of `a` over ℚ reduces to one of `a mod p` (of the
/// same degree), so `gcd(a mod p, a′ mod p) = 1` rules it out. `false`
/// means "not proven" (a repeated factor, or an unlucky prime).
pub(crate) fn squarefree_by_prime(a: &ZPoly) -> bool {
    let Some(lc) = a.leading() else {
        return false;
    };
    let Some(f) = (0..4)
        .map(|index| Fp::new(ntt_prime(index).p))
        .find(|f| lc.mod_u64(f.p) != 0)
    else {
        return false;
    };
    let source = Source::new(a);
    let r = source.image(&f, &f.limb_weights(source.limbs()));
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
    gcd_counted(a, b).0
}

/// [`gcd`] and the number of primes whose images it took.
fn gcd_counted(a: &ZPoly, b: &ZPoly) -> (ZPoly, usize) {
    let (g, used, _) = gcd_given(a, b, false);
    (g, used)
}

/// [`gcd_counted`], told whether its inputs' contents need not be taken
/// (`contents_known`: `a` is primitive, and `b` may keep its content, as
/// the squarefree part's `b = a′` does; a gcd of long coefficients each),
/// and with the cofactor `pp(a)/gcd` when the trial division formed it (a
/// lifted gcd of positive degree). `G` is primitive, so `G | b` exactly
/// when `G | pp(b)` (Gauss's lemma: the trial division holds either way),
/// and `lc(G)` divides `lc(b)` as it divides `lc(pp(b))`:
/// `γ = gcd(lc a, lc b)`, a multiple of the primitive parts'
/// by at most `b`'s content, still makes `H = (γ/lc G)·G` integral (module
/// docs (2)), which only needs as many more bits of modulus. The content
/// of `a′` is usually one or small, and its gcd of long coefficients costs
/// about a third of the lift's set-up.
fn gcd_given(a: &ZPoly, b: &ZPoly, contents_known: bool) -> (ZPoly, usize, Option<ZPoly>) {
    let (Some(da), Some(db)) = (a.degree(), b.degree()) else {
        let g = if a.is_zero() {
            b.primitive_part()
        } else {
            a.primitive_part()
        };
        return (g, 0, None);
    };
    if da == 0 || db == 0 {
        return (ZPoly::one(), 0, None);
    }
    // The images are taken of `a` and `b` as given, at primes `p ∤ lc(a)·lc(b)`:
    // then `p` divides neither content, so the monic `gcd(a mod p, b mod p)`
    // is that of the primitive parts. Those (and `γ`) are formed only once
    // an image is not constant: a coprime pair, the common case of a zero
    // test, is proven by one prime without them.
    let (lca, lcb) = (a.leading().expect("nonzero"), b.leading().expect("nonzero"));
    // Short coefficients (a scene's motions) give their images from the
    // words, without the limb conversion ([`Source`]).
    let (sa, sb) = (Source::new(a), Source::new(b));
    let weight_limbs = sa.limbs().max(sb.limbs());
    // The longest coefficient in words (a word coefficient is one).
    let max_limbs = weight_limbs.max(1);
    let until = |gamma: &Int| rational_until(gamma.bits(), max_limbs as u64 * (da + db + 2) as u64);
    let mut primitive: Option<Oriented> = None;
    // The images of the lowest degree seen, lifted both ways.
    let mut best: Option<Images> = None;
    let mut used = 0;
    for index in 0.. {
        let f = Fp::new(ntt_prime(index).p);
        if lca.mod_u64(f.p) == 0 || lcb.mod_u64(f.p) == 0 {
            continue;
        }
        let weights = f.limb_weights(weight_limbs);
        let g = gcd_mod_p(sa.image(&f, &weights), sb.image(&f, &weights), &f);
        used += 1;
        let d = g.len() - 1;
        if d == 0 {
            return (ZPoly::one(), used, None);
        }
        let oriented = primitive.get_or_insert_with(|| Oriented::new(a, b, contents_known, until));
        // Once the monic lift is given up, the scaled one may go on
        // reversed, from new images, when that needs fewer primes.
        if let Some(images) = best.as_ref().filter(|i| i.monic.is_none()) {
            if let Some(reversed) = oriented.reversal(images.count, until) {
                *oriented = reversed;
                best = None;
            }
        }
        let Some(g) = oriented.image(g, &f) else {
            continue;
        };
        let Oriented {
            pa,
            pb,
            gamma,
            until,
            ..
        } = &*oriented;
        let until = *until;
        // monic(g) (while rational reconstruction is tried) and γ·monic(g),
        // plain residues.
        let monic: Vec<u64> = match until {
            0 => Vec::new(),
            _ => g.iter().map(|&x| f.leave(x)).collect(),
        };
        let gamma_m = f.enter(gamma.mod_u64(f.p));
        let scaled: Vec<u64> = g.iter().map(|&x| f.leave(f.mul(x, gamma_m))).collect();
        // `pa/c` when `c` divides both.
        let divides = |c: &ZPoly| pa.div_exact(c).filter(|_| pb.div_exact(c).is_some());
        let (images, first) = match &mut best {
            Some(images) if images.degree == d => (images, false),
            Some(images) if images.degree < d => continue,
            _ => {
                let monic = (until > 0).then_some(&monic[..]);
                (best.insert(Images::new(d, monic, &scaled, f.p)), true)
            }
        };
        // The scaled lift is tried once an image no longer changes it.
        if !first {
            let monic = (images.count < until).then_some(&monic[..]);
            if !images.extend(monic, &scaled, &f) {
                let cand = ZPoly::new(images.scaled.clone()).primitive_part();
                if let Some(cofactor) = divides(&cand) {
                    let (g, cofactor) = oriented.finish(cand, cofactor);
                    return (g, used, Some(cofactor));
                }
                images.tried = Some(cand);
            }
        }
        // While the monic lift is kept (up to `until` images).
        if try_rational_at(images.count) {
            let cand = images
                .monic
                .as_ref()
                .and_then(|m| rational_candidate(m, &images.modulus));
            if let Some(cand) = cand.filter(|c| images.tried.as_ref() != Some(c)) {
                if let Some(cofactor) = divides(&cand) {
                    let (g, cofactor) = oriented.finish(cand, cofactor);
                    return (g, used, Some(cofactor));
                }
                images.tried = Some(cand);
            }
        }
    }
    unreachable!("the prime loop only ends by returning")
}

/// The primitive parts `a`, `b` whose gcd is lifted (as given where
/// [`gcd_given`] is told their contents are known), and their `γ`, as
/// given or reversed (`t ↦ 1/t`). The scaled lift (module docs (2)) needs a
/// modulus past `2·γ/lc(G)·‖G‖∞`: for a squarefree part, `b = a′`, so
/// `γ = gcd(lc a, lc a′)` is `lc a` up to `deg a`, as long as `a`'s
/// coefficients, while at the other end `gcd(a(0), a′(0))` is usually about
/// `G(0)`. For `a(0), b(0) ≠ 0` the reversal maps `gcd(a, b)` to
/// `gcd(rev a, rev b)` (`rev` keeps the degree of every divisor, whose
/// constant term divides `a(0) ≠ 0`), and back; both are determined up to
/// sign, so [`Oriented::finish`] returns the same polynomial either way.
struct Oriented {
    pa: ZPoly,
    pb: ZPoly,
    /// `gcd(lc pa, lc pb)` in this orientation.
    gamma: Int,
    /// [`rational_until`] for `gamma`.
    until: usize,
    /// Reversed, or the reversal decided against.
    decided: bool,
    reversed: bool,
}

impl Oriented {
    fn new(a: &ZPoly, b: &ZPoly, contents_known: bool, until: impl Fn(&Int) -> usize) -> Oriented {
        let (pa, pb) = if contents_known {
            (a.clone(), b.clone())
        } else {
            (a.primitive_part(), b.primitive_part())
        };
        let gamma = (pa.leading().expect("nonzero")).gcd(pb.leading().expect("nonzero"));
        Oriented {
            until: until(&gamma),
            pa,
            pb,
            gamma,
            decided: false,
            reversed: false,
        }
    }

    /// The reversed orientation, when the scaled lift, `count` images into
    /// this one, needs more primes than it would need from none reversed
    /// (`γ`'s bits decide, at 62 bits a prime; `G`'s own are the same
    /// either way). Asked once; the reversed `γ` (a gcd of the constant
    /// terms, as long as the leading ones) is taken only where the lift
    /// has at least two primes of `γ` left to go.
    fn reversal(&mut self, count: usize, until: impl Fn(&Int) -> usize) -> Option<Oriented> {
        let left = (self.gamma.bits() / 62).saturating_sub(count as u64);
        if std::mem::replace(&mut self.decided, true) || left < 2 {
            return None;
        }
        let (ta, tb) = (&self.pa.coeffs()[0], &self.pb.coeffs()[0]);
        if ta.is_zero() || tb.is_zero() {
            return None;
        }
        let gamma = ta.gcd(tb);
        (gamma.bits() / 62 < left).then(|| Oriented {
            pa: self.pa.reverse(),
            pb: self.pb.reverse(),
            until: until(&gamma),
            gamma,
            decided: true,
            reversed: true,
        })
    }

    /// The monic `gcd(a mod p, b mod p)` in this orientation, or `None` at
    /// a prime dividing a leading coefficient here (the original's were
    /// excluded before): reversed and made monic, its constant term is
    /// nonzero because `p ∤ a(0)`.
    fn image(&self, g: Vec<u64>, f: &Fp) -> Option<Vec<u64>> {
        if !self.reversed {
            return Some(g);
        }
        let divides_lead = |x: &ZPoly| x.leading().expect("nonzero").mod_u64(f.p) == 0;
        if divides_lead(&self.pa) || divides_lead(&self.pb) {
            return None;
        }
        let inv = f.inv(g[0]);
        Some(g.iter().rev().map(|&x| f.mul(x, inv)).collect())
    }

    /// The gcd found in this orientation and `pa`'s cofactor, in the
    /// original one: the gcd primitive with a positive leading coefficient
    /// (`rev pa = C·Q` gives `pa = rev C·rev Q`, every constant term
    /// nonzero).
    fn finish(&self, g: ZPoly, cofactor: ZPoly) -> (ZPoly, ZPoly) {
        if !self.reversed {
            return (g, cofactor);
        }
        let (g, cofactor) = (g.reverse(), cofactor.reverse());
        if g.leading().is_some_and(Int::is_negative) {
            (-g, -cofactor)
        } else {
            (g, cofactor)
        }
    }
}

/// The images of `gcd(a, b)` of one degree, lifted by CRT both ways of the
/// module docs: `γ·monic` to integers (2), `monic` for rational
/// reconstruction (3).
struct Images {
    degree: usize,
    /// `γ·monic(gcd_p)`, symmetric residues modulo `modulus`.
    scaled: Vec<Int>,
    /// `monic(gcd_p)`, symmetric residues modulo `modulus`, while rational
    /// reconstruction is still tried ([`rational_until`]); `None` after.
    monic: Option<Vec<Int>>,
    /// The product of the primes of these images.
    modulus: Int,
    /// How many primes.
    count: usize,
    /// The last candidate that failed trial division.
    tried: Option<ZPoly>,
}

impl Images {
    /// The first image, modulo `p` (plain residues); `monic` only while
    /// rational reconstruction is tried.
    fn new(degree: usize, monic: Option<&[u64]>, scaled: &[u64], p: u64) -> Images {
        let lift = |r: &[u64]| -> Vec<Int> { r.iter().map(|&x| symmetric(x, p)).collect() };
        Images {
            degree,
            scaled: lift(scaled),
            monic: monic.map(lift),
            modulus: Int::from_u64(p),
            count: 1,
            tried: None,
        }
    }
    /// One more image, modulo `f.p`: whether the scaled lift changed. The
    /// monic lift goes on with `monic`, and is dropped without it (so it
    /// can never be read behind the modulus).
    fn extend(&mut self, monic: Option<&[u64]>, scaled: &[u64], f: &Fp) -> bool {
        let step = CrtStep::new(&self.modulus, f);
        let changed = step.extend(&mut self.scaled, scaled, f);
        match (&mut self.monic, monic) {
            (Some(lift), Some(r)) => {
                step.extend(lift, r, f);
            }
            _ => self.monic = None,
        }
        self.modulus = step.next;
        self.count += 1;
        changed
    }
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
        self.squarefree_part_given(None)
    }
    /// `pp(p / gcd(p, p′))`, for a `p` of degree at least 1.
    fn squarefree_by_gcd(&self) -> ZPoly {
        // `p/g` of a primitive `p` by a primitive `g` is primitive (Gauss's
        // lemma), with a positive leading coefficient: `p`'s content is
        // taken once, for the gcd and the result.
        let p = self.primitive_part();
        let (g, _, cofactor) = gcd_given(&p, &p.derivative(), true);
        if g.degree() == Some(0) {
            return p;
        }
        // Of positive degree, the gcd was lifted: its trial division
        // formed `p/g`.
        cofactor.expect("a lifted gcd comes with its cofactor")
    }
    /// The squarefree part, given a factor `square` whose square is
    /// expected to divide `self` (a hint, proven here or dropped; `None`:
    /// [`ZPoly::squarefree_part`]). After a word-prime test (which settles
    /// a squarefree `self` at once): `g` the squarefree part of `square`,
    /// `self = g^k·q` with `k ≥ 2` as large as exact division allows, and
    /// once one word prime that keeps `g`'s degree proves `gcd(g, q) = 1`
    /// ([`Residues::proves_coprime`]), `pp(g·q′)` with `q′` the squarefree
    /// part of `q` (by the gcd of `q` and `q′`, shorter than `self`'s, when
    /// a word prime does not prove `q` squarefree). With `g`
    /// squarefree and coprime to `q`, `g·q′` has exactly the distinct
    /// irreducible factors of `self`, each once, so `pp(g·q′)` is the
    /// polynomial `squarefree_part` returns (primitive with a positive
    /// leading coefficient, hence unique). Otherwise the gcd of `self` and
    /// `self′`, as there. It saves that gcd where the repeated factor is
    /// known from elsewhere.
    ///
    /// ```
    /// use ccd_poly::ZPoly;
    /// // (t² + 1)³·(t − 2)·(t + 5), with the hint t² + 1.
    /// let g = ZPoly::from_i64s(&[1, 0, 1]);
    /// let p = &(&g.pow(3) * &ZPoly::from_i64s(&[-2, 1])) * &ZPoly::from_i64s(&[5, 1]);
    /// assert_eq!(p.squarefree_part_given(Some(&g)), p.squarefree_part());
    /// // A wrong hint is dropped: t − 2 divides p only once.
    /// assert_eq!(p.squarefree_part_given(Some(&ZPoly::from_i64s(&[-2, 1]))), p.squarefree_part());
    /// ```
    pub fn squarefree_part_given(&self, square: Option<&ZPoly>) -> ZPoly {
        if self.degree().is_none_or(|n| n == 0) || squarefree_by_prime(self) {
            return self.primitive_part();
        }
        let proven = |square: &ZPoly| -> Option<ZPoly> {
            if square.degree()? == 0 {
                return None;
            }
            // Its own repeated factors (a touch there) removed first: a
            // gcd of the short hint.
            let g = square.squarefree_part();
            let mut q = self.div_exact(&g)?.div_exact(&g)?;
            while let Some(r) = q.div_exact(&g) {
                q = r;
            }
            let (image, kept) = Residues::image(&g);
            if !(kept && image.proves_coprime(&Residues::of(&q))) {
                return None;
            }
            // q's own repeated factors (a touch), from the shorter q.
            Some((&g * &q.squarefree_part()).primitive_part())
        };
        square
            .and_then(proven)
            .unwrap_or_else(|| self.squarefree_by_gcd())
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

    /// `c·t^n + rest` with a long `c`.
    fn long_leading(c: &Int, rest: &[i64]) -> ZPoly {
        let mut v: Vec<Int> = rest.iter().map(|&x| Int::from(x)).collect();
        v.push(c.clone());
        ZPoly::new(v)
    }

    #[test]
    fn rational_candidate_recovers_fractions() {
        // t² + t/3 − 5/7 modulo a product of two table primes.
        let (p, q) = (ntt_prime(0).p, ntt_prime(1).p);
        let m = Int::from_u64(p).mul_i64(q as i64);
        let residue = |n: i64, d: i64, primes: &[u64]| -> Int {
            // n·d^(−1) modulo the primes' product, symmetric, by CRT.
            let mut h = vec![Int::zero()];
            let mut modulus = Int::one();
            for &r in primes {
                let f = Fp::new(r);
                let x = f.mul(
                    f.enter(n.rem_euclid(r as i64) as u64),
                    f.inv(f.enter(d.rem_euclid(r as i64) as u64)),
                );
                let step = CrtStep::new(&modulus, &f);
                step.extend(&mut h, &[f.leave(x)], &f);
                modulus = step.next;
            }
            h.pop().expect("one value")
        };
        let monic = [residue(-5, 7, &[p, q]), residue(1, 3, &[p, q]), Int::one()];
        assert_eq!(
            rational_candidate(&monic, &m),
            Some(ZPoly::from_i64s(&[-15, 7, 21]))
        );
        // A fraction of 32-bit terms: past B = 2^30 (one prime), this residue
        // happens to have no other candidate; found with two (B = 2^61).
        let long = |primes: &[u64]| [residue(4_000_000_007, 3_999_999_979, primes), Int::one()];
        assert_eq!(rational_candidate(&long(&[p]), &Int::from_u64(p)), None);
        assert_eq!(
            rational_candidate(&long(&[p, q]), &m),
            Some(ZPoly::from_i64s(&[4_000_000_007, 3_999_999_979]))
        );
    }

    #[test]
    fn a_small_gcd_of_long_leading_coefficients_takes_few_primes() {
        // γ = gcd(lc a, lc b) = 2^20000 + 1 while G = t² + 3t − 7: the
        // scaled lift alone needs ~330 primes, the rational one one.
        let big = Int::one().shl(20_000) + Int::one();
        let g = ZPoly::from_i64s(&[-7, 3, 1]);
        let a = &g * &long_leading(&big, &[1, 5, 0]);
        let b = &g * &long_leading(&big, &[-2, 0]);
        let (got, used) = gcd_counted(&a, &b);
        assert_eq!(got, g);
        assert!(used <= 4, "{used} primes");
        // And with a fractional monic form: G = 3t² − 2.
        let g = ZPoly::from_i64s(&[-2, 0, 3]);
        let (got, used) = gcd_counted(
            &(&g * &long_leading(&big, &[4, 1])),
            &(&g * &long_leading(&(&big + &big), &[-1, 0, 9])),
        );
        assert_eq!(got, g);
        assert!(used <= 4, "{used} primes");
    }

    #[test]
    fn a_wider_gcd_is_reconstructed_from_several_primes() {
        // G with ~150-bit coefficients under a 25,000-bit γ: its monic form
        // needs a modulus past 2^300 (five or six primes, attempts at 1, 2,
        // 3, 4, 6), the scaled lift ~400 primes.
        let c = |k: u64, v: i64| Int::one().shl(k) + Int::from(v);
        let g = ZPoly::new(vec![c(150, -7), c(149, 3), c(151, 5)]);
        let big = Int::one().shl(25_000) + Int::one();
        let a = &g * &long_leading(&big, &[1, 5, 0]);
        let b = &g * &long_leading(&big, &[-2, 0]);
        let (got, used) = gcd_counted(&a, &b);
        assert_eq!(got, g);
        assert!((2..=8).contains(&used), "{used} primes");
        // With the first table prime unlucky: t + 1 and t + 1 + p divide
        // a and b, coprime over Z but equal modulo p, so the first image
        // has degree 3 and the lifts restart at the second prime.
        let p = Int::from_u64(ntt_prime(0).p);
        let (a, b) = (
            &a * &ZPoly::new(vec![Int::one(), Int::one()]),
            &b * &ZPoly::new(vec![&p + &Int::one(), Int::one()]),
        );
        let (got, used) = gcd_counted(&a, &b);
        assert_eq!(got, g);
        assert!((3..=9).contains(&used), "{used} primes");
    }

    #[test]
    fn a_squarefree_part_under_a_long_leading_coefficient_takes_few_primes() {
        // p = G²·h with G of ~400-bit coefficients (G(0) < 0 < lc G) and
        // lc h = 2^20000 + 1: γ = gcd(lc p, lc p′) has 20,000 bits, so the
        // scaled lift needs ~330 primes, and the monic one more than its
        // attempts allow (up to 8 images here); gcd(p(0), p′(0)) is about
        // G(0), so reversed after those, the scaled lift takes ~9 more.
        let c = |k: u64, v: i64| Int::one().shl(k) + Int::from(v);
        let g = ZPoly::new(vec![-c(400, -7), c(399, 3), c(401, 5)]);
        let big = Int::one().shl(20_000) + Int::one();
        let p = &g.pow(2) * &long_leading(&big, &[1, -3, 2]);
        let (got, used) = gcd_counted(&p, &p.derivative());
        assert_eq!(got, g);
        assert!(used <= 20, "{used} primes");
        assert_eq!(
            p.squarefree_part(),
            (&g * &long_leading(&big, &[1, -3, 2])).primitive_part()
        );
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
                    let step = CrtStep::new(m, &f);
                    step.extend(hv, &r, &f);
                    *m = step.next;
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

    /// That `got` is `gcd(a, b)` for `a`, `b` multiples of `g`,
    /// independently of the gcd under test: primitive with a positive
    /// leading coefficient, `g` divides it, it divides both, and the
    /// cofactors share no factor of positive degree (proven by one prime
    /// image of degree 0, or not at all).
    fn is_the_gcd(got: &ZPoly, a: &ZPoly, b: &ZPoly, g: &ZPoly) -> Result<(), TestCaseError> {
        prop_assert_eq!(got, &got.primitive_part());
        prop_assert!(got.leading().is_some_and(|l| !l.is_negative()));
        prop_assert!(got.div_exact(&g.primitive_part()).is_some());
        let (qa, qb) = (a.div_exact(got), b.div_exact(got));
        prop_assert!(qa.is_some() && qb.is_some());
        prop_assert_eq!(
            qa.expect("divides").gcd(&qb.expect("divides")),
            ZPoly::one()
        );
        Ok(())
    }

    /// `x` with its constant term made nonzero (the reversal's condition),
    /// so that strategies need not reject.
    fn nonzero_constant(x: ZPoly) -> ZPoly {
        let mut c = x.coeffs().to_vec();
        if c[0].is_zero() {
            c[0] = Int::one();
        }
        ZPoly::new(c)
    }

    #[test]
    fn zero_and_constant_cases() {
        assert_eq!(ZPoly::zero().gcd(&ZPoly::zero()), ZPoly::zero());
        assert_eq!(z(&[-4, -6]).gcd(&ZPoly::zero()), z(&[2, 3]));
        assert_eq!(ZPoly::zero().gcd(&z(&[4, 6])), z(&[2, 3]));
        assert_eq!(z(&[7]).gcd(&z(&[1, 1])), ZPoly::one());
        assert_eq!(z(&[7]).gcd(&ZPoly::zero()), ZPoly::one());
    }

    /// A hint whose leading coefficient the word prime divides: its image
    /// drops the factor `p·t + 1`, so coprimality modulo `p` proves
    /// nothing about it (found by review; the hinted result then kept
    /// `(p·t + 1)²`).
    #[test]
    fn a_hint_with_the_prime_in_its_leading_coefficient_is_not_trusted() {
        let p = Int::from_u64(crate::Residues::modulus());
        let a = z(&[2, 1]);
        let c = ZPoly::new(vec![Int::one(), p]);
        let s = &a.pow(2) * &c.pow(3);
        assert_eq!(
            s.squarefree_part_given(Some(&(&a * &c))),
            s.squarefree_part()
        );
    }

    #[test]
    fn squarefree_part_of_repeated_factors() {
        let (a, b, c) = (z(&[-1, 1]), z(&[2, 1]), z(&[1, 0, 1]));
        let p = &(&a.pow(3) * &b.pow(2)) * &c;
        assert_eq!(p.squarefree_part(), &(&a * &b) * &c);
        assert_eq!(p.mul_int(&Int::from(-6)).squarefree_part(), &(&a * &b) * &c);
        // A long content: taken once, the quotient by the gcd primitive.
        let long = -Int::from(3).pow(150);
        assert_eq!(p.mul_int(&long).squarefree_part(), &(&a * &b) * &c);
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

    /// `gcd(a·g, b·g) = pp(g·gcd(a, b))` (zero for `a = b = 0`).
    fn common_factor_gcd(a: &ZPoly, b: &ZPoly, g: &ZPoly) -> Result<(), TestCaseError> {
        let got = (a * g).gcd(&(b * g));
        if a.is_zero() && b.is_zero() {
            prop_assert!(got.is_zero());
        } else {
            prop_assert_eq!(got, (g * &a.gcd(b)).primitive_part());
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn common_factor_is_found(a in zpoly(7, 120), b in zpoly(7, 120), g in zpoly_deg(0, 6, 120)) {
            common_factor_gcd(&a, &b, &g)?;
        }

        /// Word images are the limb images (coefficients anywhere in
        /// `i64`, its ends included; none past it), and short polynomials,
        /// whose gcd takes the word images first, have the gcd the common
        /// factor makes.
        #[test]
        fn short_polynomials_take_word_images(
            a in zpoly(6, 40),
            b in zpoly(6, 40),
            g in zpoly_deg(0, 3, 20),
            end in prop_oneof![Just(i64::MIN), Just(i64::MAX), any::<i64>()],
        ) {
            use super::{image, ntt_prime, to_limbs, word_image, Fp};
            let f = Fp::new(ntt_prime(0).p);
            // a·t + end: `end` itself as the constant coefficient.
            let extreme = &(&a * &z(&[0, 1])) + &z(&[end]);
            let long = &(&a * &z(&[0, 1])) + &ZPoly::new(vec![Int::from(i64::MAX) + Int::one()]);
            for p in [&a, &b, &extreme, &long] {
                let limbs = to_limbs(p.coeffs());
                let weights = f.limb_weights(crate::ntt::max_limbs(&limbs, &[]));
                let words = p.coeffs().iter().all(|c| c.to_i64().is_some());
                prop_assert_eq!(word_image(p, &f), words.then(|| image(&limbs, &f, &weights)));
            }
            common_factor_gcd(&a, &b, &g)?;
            prop_assert_eq!(extreme.gcd(&(&extreme + &z(&[1]))), ZPoly::one());
        }

        #[test]
        fn consecutive_polynomials_are_coprime(a in zpoly_deg(1, 12, 300), c in 1i64..1000) {
            // Any common divisor of a and a + c divides the constant c.
            prop_assert_eq!(a.gcd(&(&a + &z(&[c]))), ZPoly::one());
        }

        /// Cofactors whose leading coefficients share a long factor `L`, so
        /// that `γ` is long: a short `G` comes from the rational lift at
        /// once; a longer one, past the rational attempts, from the scaled
        /// lift reversed (`γ` about `G(0)` at that end, the shape of a
        /// squarefree part's `gcd(p, p′)`), in fewer primes than `bits(γ)/62`.
        #[test]
        fn common_factor_under_long_leading_coefficients(
            a in zpoly_deg(1, 5, 60),
            b in zpoly_deg(1, 5, 60),
            g in zpoly_deg(1, 4, 300),
            shift in 500u64..4000,
        ) {
            let long = Int::one().shl(shift) + Int::from(3);
            let lead = |p: &ZPoly| {
                let mut c = nonzero_constant(p.clone()).coeffs().to_vec();
                c.push(long.clone());
                ZPoly::new(c)
            };
            let g = nonzero_constant(g);
            let (a, b) = (&lead(&a) * &g, &lead(&b) * &g);
            let (got, used) = super::gcd_counted(&a, &b);
            is_the_gcd(&got, &a, &b, &g)?;
            prop_assert!(used <= 16, "{} primes", used);
        }

        /// The hinted squarefree part is the plain one, whatever the hint:
        /// `p = (a·b)^k·a^j·q·r²` with the hint `a·b·s` (`s = 1`: the
        /// hint's square divides `p` for `k ≥ 2`; a factor `a` left over
        /// with `j ≥ 1`, so that the hint is not coprime to the rest; `s`
        /// random: the hint's square usually does not divide), `r²` a
        /// repeated factor the hint does not know.
        #[test]
        fn hinted_squarefree_part_is_the_squarefree_part(
            a in zpoly_deg(1, 2, 60),
            b in zpoly_deg(0, 2, 60),
            q in zpoly_deg(0, 4, 60),
            r in zpoly_deg(0, 2, 30),
            s in zpoly_deg(1, 2, 30),
            k in 1u32..4,
            j in 0u32..2,
            exact in any::<bool>(),
        ) {
            let g = &a * &b;
            let hint = if exact { g.clone() } else { &g * &s };
            let p = &(&(&g.pow(k) * &a.pow(j)) * &q) * &r.pow(2);
            prop_assume!(!p.is_zero() && !hint.is_zero());
            prop_assert_eq!(p.squarefree_part_given(Some(&hint)), p.squarefree_part());
        }

        /// The squarefree part of `g²·h` with `lc h` long (the shape of
        /// `graze-spin-k100-overlap`'s `sr0`), where `g·h` is proven
        /// squarefree by one prime (no gcd): `pp(g·h)`, through the
        /// reversed lift and the cofactor its trial division formed.
        #[test]
        fn a_reversed_squarefree_part(
            g in zpoly_deg(1, 3, 300),
            h in zpoly_deg(1, 4, 40),
            k in 2_000u64..4_000,
        ) {
            let [g, h] = [g, h].map(nonzero_constant);
            let mut c = h.coeffs().to_vec();
            let top = c.len() - 1;
            c[top] = &c[top] * &(Int::one().shl(k) + Int::one());
            let h = ZPoly::new(c);
            let expected = (&g * &h).primitive_part();
            prop_assume!(super::squarefree_by_prime(&expected));
            let p = &g.pow(2) * &h;
            prop_assert_eq!(p.squarefree_part(), expected);
        }

        /// `b` kept with its content (`contents_known`, as for `a′` in the
        /// squarefree part): the same gcd and cofactor as from `pp(b)`, for a
        /// content coprime to everything or a multiple of `lc(a)` (which
        /// makes `γ` that much longer).
        #[test]
        fn b_as_given_gives_the_same_gcd(
            (a, b, g) in (zpoly_deg(1, 6, 200), zpoly_deg(1, 6, 200), zpoly_deg(1, 3, 100)),
            (c, shared) in (2i64..100_000, any::<bool>()),
        ) {
            let g = nonzero_constant(g);
            let (a, b) = (&nonzero_constant(a) * &g, &nonzero_constant(b) * &g);
            let lc = a.leading().expect("nonzero").clone();
            let content = if shared { &lc * &Int::from(c) } else { Int::from(c) };
            let (want, _, cofactor) = super::gcd_given(&a, &b.primitive_part(), false);
            let (got, _, got_cofactor) = super::gcd_given(&a.primitive_part(), &b.mul_int(&content), true);
            prop_assert_eq!(&got, &want);
            prop_assert_eq!(got_cofactor, cofactor);
            is_the_gcd(&got, &a, &b, &g)?;
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
