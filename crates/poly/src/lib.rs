//! Univariate polynomials in `t` with exact coefficients, for the exact
//! continuous-collision-detection engine (Jia–Choi–Mourrain–Wang, CAGD 2011).
//!
//! * [`ZPoly`]: dense polynomials in `Z[t]` (power basis) with fast products
//!   ([`mul`]: schoolbook, Kronecker substitution, multimodular NTT) and a
//!   modular gcd ([`modular`]);
//! * [`QPoly`]: polynomials over `Q` as `rational · primitive integer
//!   polynomial`;
//! * [`SmallPoly`]: `i128` coefficients with overflow detection, for
//!   products whose numbers are usually small;
//! * [`Bernstein`]: the Bernstein form on a rational interval, converted and
//!   subdivided with integer arithmetic only.
//!
//! Every operation is exact except the explicitly approximate
//! [`ZPoly::to_f64`] and the certified enclosure [`ZPoly::eval_interval`].

#![warn(missing_docs)]

mod bernstein;
pub mod bernstein_f64;
mod kronecker;
pub mod modular;
pub mod mul;
mod ntt;
mod prime;
mod qpoly;
mod residue;
mod small;
mod zpoly;

pub use bernstein::{bernstein_to_power, binomials, Bernstein, Substitution};
pub use bernstein_f64::BernsteinF64;
pub use qpoly::QPoly;
pub use residue::Residues;
pub use small::SmallPoly;
pub use zpoly::ZPoly;

#[cfg(test)]
pub(crate) mod testutil {
    //! Shared proptest strategies.
    use crate::ZPoly;
    use ccd_arith::{Int, Rat};
    use proptest::prelude::*;

    /// Integers with up to about `max_bits` bits, often small or zero.
    pub fn int(max_bits: u64) -> impl Strategy<Value = Int> {
        (any::<i64>(), 0..=max_bits, 0u8..5).prop_map(|(x, s, kind)| match kind {
            0 => Int::zero(),
            1 => Int::from(x % 10),
            _ => Int::from(x).shl(s.saturating_sub(63)) + Int::from(x >> 7),
        })
    }

    /// Polynomials of degree below `max_len` (possibly zero).
    pub fn zpoly(max_len: usize, max_bits: u64) -> impl Strategy<Value = ZPoly> {
        prop::collection::vec(int(max_bits), 0..=max_len).prop_map(ZPoly::new)
    }

    /// Nonzero polynomials of degree at least `min_deg`.
    pub fn zpoly_deg(
        min_deg: usize,
        max_len: usize,
        max_bits: u64,
    ) -> impl Strategy<Value = ZPoly> {
        (
            prop::collection::vec(int(max_bits), min_deg..max_len),
            1i64..1000,
            any::<bool>(),
        )
            .prop_map(|(mut c, lead, neg)| {
                c.push(Int::from(if neg { -lead } else { lead }));
                ZPoly::new(c)
            })
    }

    /// Rationals with numerators and denominators of up to ~40 bits.
    pub fn rat() -> impl Strategy<Value = Rat> {
        (any::<i64>(), 1i64..(1 << 40)).prop_map(|(n, d)| Rat::from_frac(n >> 24, d))
    }

    /// The exact value of a finite `f64`.
    pub fn f64_to_rat(v: f64) -> Rat {
        if v == 0.0 {
            return Rat::zero();
        }
        let bits = v.to_bits();
        let exp = ((bits >> 52) & 0x7ff) as i64;
        let frac = (bits & ((1u64 << 52) - 1)) as i64;
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | (1i64 << 52), exp - 1075)
        };
        let m = if bits >> 63 == 1 { -m } else { m };
        Rat::from(m).mul_pow2(e)
    }
}
