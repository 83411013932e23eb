//! Test fixtures for the quartic, shared by this crate's tests and
//! `ccd-classify`'s (through the feature `fixtures`): quartics with chosen
//! roots, and proptest strategies for small rationals. Not part of the API.

use crate::Quantity;
use ccd_arith::{Rat, RingOps};
use proptest::prelude::*;

/// The five quantities in the order of [`crate::QuarticInvariants`].
pub const QS: [Quantity; 5] = [
    Quantity::Sr22,
    Quantity::Sr20,
    Quantity::Sr11,
    Quantity::Sr10,
    Quantity::Sr0,
];

/// `p/q`.
pub fn r(p: i64, q: i64) -> Rat {
    Rat::from_frac(p, q)
}

/// Small rationals of either sign, zero included.
pub fn rat() -> impl Strategy<Value = Rat> {
    (-30i64..=30, 1i64..=9).prop_map(|(p, q)| r(p, q))
}
/// Small positive rationals.
pub fn positive() -> impl Strategy<Value = Rat> {
    (1i64..=40, 1i64..=8).prop_map(|(p, q)| r(p, q))
}
/// Small negative rationals.
pub fn negative() -> impl Strategy<Value = Rat> {
    positive().prop_map(|x| -x)
}
/// Small nonzero rationals of either sign.
pub fn nonzero() -> impl Strategy<Value = Rat> {
    (positive(), any::<bool>()).prop_map(|(x, neg)| if neg { -x } else { x })
}

/// `e · Π (λ − ρ)` over the given real roots times the given monic
/// quadratic factors `λ² + sλ + p` (as `(s, p)`), HIGH→LOW.
pub fn quartic(e: &Rat, roots: &[Rat], quadratics: &[(Rat, Rat)]) -> [Rat; 5] {
    let mut low = vec![e.clone()];
    let mut mul = |factor: &[Rat]| {
        let mut out = vec![Rat::zero(); low.len() + factor.len() - 1];
        for (i, x) in low.iter().enumerate() {
            for (j, y) in factor.iter().enumerate() {
                out[i + j] = out[i + j].plus(&x.times(y));
            }
        }
        low = out;
    };
    for root in roots {
        mul(&[-root.clone(), Rat::one()]);
    }
    for (s, p) in quadratics {
        mul(&[p.clone(), s.clone(), Rat::one()]);
    }
    assert_eq!(low.len(), 5, "not a quartic");
    std::array::from_fn(|k| low[4 - k].clone())
}

/// `λ² − 2uλ + u² + v²`, roots `u ± iv`.
pub fn complex_pair(u: &Rat, v: &Rat) -> (Rat, Rat) {
    (Rat::from(-2).times(u), u.times(u).plus(&v.times(v)))
}
