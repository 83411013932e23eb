//! Dividing [`ZPoly`]s: by an integer, exact division and pseudo-division
//! by a polynomial, and the content and primitive part.

use super::ZPoly;
use ccd_arith::{gcd_u128, Int};

/// `gcd` of the entries, `≥ 0` (`0` when all vanish), stopping as soon as
/// the running gcd is `1`.
pub(crate) fn content_of<'a>(c: impl IntoIterator<Item = &'a Int, IntoIter: Clone>) -> Int {
    let c = c.into_iter();
    // Machine integers when every entry fits (the usual case for the
    // characteristic polynomial of decimal scenes).
    let mut g = Some(0u128);
    for x in c.clone() {
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
    // The power of two apart: after a substitution `t = (a + w·u)/2^k` (a
    // Bernstein conversion on a dyadic interval) the content is a large
    // power of two, where the running gcd below would never reach 1 and
    // every coefficient would cost a full gcd. The odd parts' gcd usually
    // reaches 1 within two coefficients.
    let Some(twos) = c.clone().filter_map(Int::trailing_zeros).min() else {
        return Int::zero();
    };
    let odd = |x: &Int| x.abs().shr_floor(x.trailing_zeros().unwrap_or(0));
    // Start from the smallest coefficient (the gcd divides it), and reduce
    // each larger coefficient modulo the running gcd before the gcd itself:
    // one division instead of a binary gcd on full-size numbers.
    let Some(smallest) = c.clone().filter(|x| !x.is_zero()).min_by_key(|x| x.bits()) else {
        return Int::zero();
    };
    let mut g = odd(smallest);
    for x in c {
        if g.is_one() {
            break;
        }
        if x.is_zero() {
            continue;
        }
        let x = odd(x);
        let r = if x.bits() > g.bits() + 64 {
            x.div_rem_trunc(&g).1
        } else {
            x
        };
        g = g.gcd(&r);
    }
    g.shl(twos)
}

/// The content `g` of the entries ([`content_of`]) and the entries divided
/// by it, in one pass; `None` when `g` is `0` or `1` (nothing to divide).
/// Each entry's remainder by the running gcd comes with its quotient, kept
/// while the gcd stays; an entry read before the gcd last shrank is
/// corrected by the shrink factor (`q·(g_then/g)`), one not divided (its
/// remainder shrank the gcd) is divided at the end. Where the content is
/// long (a set-up's common factors) this halves the long divisions of
/// [`content_of`] followed by a division of every entry. For long entries
/// ([`ZPoly::divide_common_content`] takes machine-size ones itself).
fn content_and_quotients(c: &[&Int]) -> Option<(Int, Vec<Int>)> {
    let smallest = c.iter().filter(|x| !x.is_zero()).min_by_key(|x| x.bits())?;
    // The running gcd's values; an entry's quotient is by `versions[v]`,
    // `v = usize::MAX` for an entry not divided.
    let mut versions = vec![smallest.abs()];
    let mut quotients: Vec<(Int, usize)> = Vec::with_capacity(c.len());
    for x in c {
        let (v, g) = (versions.len() - 1, &versions[versions.len() - 1]);
        if g.is_one() {
            return None;
        }
        if x.is_zero() {
            quotients.push((Int::zero(), v));
            continue;
        }
        let (q, r) = x.div_rem_trunc(g);
        if r.is_zero() {
            quotients.push((q, v));
        } else {
            let next = g.gcd(&r);
            versions.push(next);
            quotients.push((Int::zero(), usize::MAX));
        }
    }
    let last = versions.len() - 1;
    let g = versions[last].clone();
    if g.is_one() {
        return None;
    }
    let shrink: Vec<Int> = versions[..last].iter().map(|h| h.div_exact(&g)).collect();
    let q = quotients
        .into_iter()
        .zip(c)
        .map(|((q, v), x)| match v {
            usize::MAX => x.div_exact(&g),
            v if v == last => q,
            v => &q * &shrink[v],
        })
        .collect();
    Some((g, q))
}

impl ZPoly {
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
    /// The content: `gcd` of the coefficients, `≥ 0` (`0` for the zero
    /// polynomial); stops as soon as the running gcd is `1`.
    pub fn content(&self) -> Int {
        content_of(&self.c)
    }
    /// The common content of several polynomials: the gcd of all their
    /// coefficients, `≥ 0` (`0` when all vanish), equal to the gcd of
    /// their [`ZPoly::content`]s but formed in one pass that starts from
    /// the shortest coefficient and stops at `1`.
    ///
    /// ```
    /// use ccd_poly::ZPoly;
    /// let (p, q) = (ZPoly::from_i64s(&[12, 18]), ZPoly::from_i64s(&[0, 8]));
    /// assert_eq!(ZPoly::common_content(&[p, q]), ccd_arith::Int::from(2));
    /// ```
    pub fn common_content(polys: &[ZPoly]) -> Int {
        content_of(polys.iter().flat_map(|p| p.c.iter()))
    }
    /// The polynomials divided by their common content `g`
    /// ([`ZPoly::common_content`]), and `g`; `None` when `g` is `0` or `1`.
    /// One pass: each coefficient is divided once, not once for the gcd
    /// and again for the quotient.
    ///
    /// ```
    /// use ccd_poly::ZPoly;
    /// let (p, q) = (ZPoly::from_i64s(&[12, 18]), ZPoly::from_i64s(&[0, 8]));
    /// let (g, parts) = ZPoly::divide_common_content(&[p, q]).expect("content 2");
    /// assert_eq!(g, ccd_arith::Int::from(2));
    /// assert_eq!(parts, vec![ZPoly::from_i64s(&[6, 9]), ZPoly::from_i64s(&[0, 4])]);
    /// assert_eq!(ZPoly::divide_common_content(&[ZPoly::from_i64s(&[2, 3])]), None);
    /// ```
    pub fn divide_common_content(polys: &[ZPoly]) -> Option<(Int, Vec<ZPoly>)> {
        // Machine-size coefficients: the gcd in `u128`, then one division.
        if polys.iter().all(|p| p.c.iter().all(|x| x.bits() <= 127)) {
            let g = ZPoly::common_content(polys);
            return (!g.is_zero() && !g.is_one()).then(|| {
                (
                    g.clone(),
                    polys.iter().map(|p| p.div_exact_int(&g)).collect(),
                )
            });
        }
        let entries: Vec<&Int> = polys.iter().flat_map(|p| p.c.iter()).collect();
        let (g, mut q) = content_and_quotients(&entries)?;
        let mut parts = Vec::with_capacity(polys.len());
        for p in polys.iter().rev() {
            let c = q.split_off(q.len() - p.c.len());
            parts.push(ZPoly { c });
        }
        parts.reverse();
        Some((g, parts))
    }
    /// `p / (±content)`, with positive leading coefficient; zero stays zero.
    pub fn primitive_part(&self) -> ZPoly {
        let Some(lc) = self.leading() else {
            return ZPoly::zero();
        };
        let sign = |g: Int| if lc.is_negative() { -g } else { g };
        // Machine-size coefficients: one division by `±content` (no
        // separate negation pass, no part vector: this is the hot case).
        if self.c.iter().all(|x| x.bits() <= 127) {
            return self.div_exact_int(&sign(self.content()));
        }
        match ZPoly::divide_common_content(std::slice::from_ref(self)) {
            Some((_, mut parts)) if !lc.is_negative() => parts.pop().expect("one part"),
            Some((_, mut parts)) => -&parts.pop().expect("one part"),
            None => self.div_exact_int(&sign(Int::one())),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::testutil::{zpoly, zpoly_deg};
    use ccd_arith::Ring;
    use proptest::prelude::*;

    fn z(c: &[i64]) -> ZPoly {
        ZPoly::from_i64s(c)
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

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The machine gcd (with its first Euclid step on operands of very
        /// different lengths) against the big-integer one.
        #[test]
        fn machine_gcd_agrees(a in any::<u128>(), b in any::<u128>(), sa in 0u32..128, sb in 0u32..128, k in 1u64..1000) {
            let (a, b) = (a >> sa, b >> sb);
            for (x, y) in [(a, b), (b, a), (a, a.wrapping_mul(u128::from(k)) >> 10), (u128::from(k), b), (1, b), (0, b)] {
                let g = gcd_u128(x, y);
                let expect = Int::from_i128(x as i128).gcd(&Int::from_i128(y as i128));
                if x >> 127 == 0 && y >> 127 == 0 {
                    prop_assert_eq!(Int::from_i128(g as i128), expect);
                }
            }
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

        /// One pass of content and quotients: a long common factor `g`
        /// (up to ~600 bits), the first polynomial with an extra factor
        /// `h` (so the running gcd can shrink after quotients were taken),
        /// short and long coefficients.
        #[test]
        fn common_content_divided_in_one_pass(
            ps in prop::collection::vec(zpoly(6, 300), 1..4),
            c in 1i64..1000,
            e in 0u32..200,
            h in 1i64..1000,
        ) {
            let g = &Int::from(c) * &Int::from(7).pow(e);
            let scaled: Vec<ZPoly> = ps
                .iter()
                .enumerate()
                .map(|(i, p)| p.mul_int(&if i == 0 { &g * &Int::from(h) } else { g.clone() }))
                .collect();
            let want = ZPoly::common_content(&scaled);
            match ZPoly::divide_common_content(&scaled) {
                None => prop_assert!(want.is_zero() || want.is_one()),
                Some((got, parts)) => {
                    prop_assert_eq!(&got, &want);
                    prop_assert_eq!(parts.len(), scaled.len());
                    for (q, p) in parts.iter().zip(&scaled) {
                        prop_assert_eq!(&q.mul_int(&got), p);
                    }
                }
            }
        }

        /// The machine-integer content agrees with big-integer gcds, on
        /// both sides of the `i128` limit.
        #[test]
        fn content_matches_pairwise_gcds(p in zpoly_deg(0, 10, 140), c in 1i64..1_000_000) {
            let scaled = p.mul_int(&Int::from(c));
            let want = scaled.coeffs().iter().fold(Int::zero(), |g, x| g.gcd(x));
            prop_assert_eq!(scaled.content(), want);
        }

        /// A long power of two in the content (a Bernstein conversion on a
        /// dyadic interval) with an odd factor beside it, and coefficients
        /// with more twos than the content: the content is still the gcd.
        #[test]
        fn content_with_a_long_power_of_two(
            p in zpoly_deg(1, 8, 300),
            odd in 0i64..500,
            twos in 0u64..900,
            extra in prop::collection::vec(0u64..64, 9),
        ) {
            let odd = Int::from(2 * odd + 1);
            let c: Vec<Int> = p
                .coeffs()
                .iter()
                .zip(&extra)
                .map(|(x, e)| (x * &odd).shl(twos + e))
                .collect();
            let want = c.iter().fold(Int::zero(), |g, x| g.gcd(x));
            prop_assert_eq!(content_of(&c), want);
        }
    }
}
