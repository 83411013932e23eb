//! The sign sets of the quantities Theorem 3.10 reads, from enclosures of
//! `f`'s coefficients and of the closed forms over a box of times (the
//! decision itself is `ccd_algorithm::possible_with`, shared by every
//! arithmetic).

use ccd_algorithm::{SignSet, VarSet};
use ccd_classify::sign_variations;
use ccd_enclosure::real::Real;
use ccd_subres::{Quantity, QuarticInvariants};

/// The signs the points of an enclosure can have.
fn signs_of<R: Real>(x: &R) -> SignSet {
    let (l, h) = x.end_signs();
    SignSet::of_ends(l, h)
}

/// The possible signs of everything Theorem 3.10 reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Readings {
    /// `sr22, sr20, sr11, sr10, sr0`.
    pub quantities: [SignSet; 5],
    /// `e, a, b, c, d` (for `Var`).
    pub coefficients: [SignSet; 5],
}

/// The order of [`Readings::quantities`].
pub const QUANTITIES: [Quantity; 5] = [
    Quantity::Sr22,
    Quantity::Sr20,
    Quantity::Sr11,
    Quantity::Sr10,
    Quantity::Sr0,
];

impl Readings {
    /// Sign sets of evaluated coefficients and invariants.
    pub fn of<R: Real>(coeffs: &[R; 5], inv: &QuarticInvariants<R>) -> Readings {
        Readings {
            quantities: QUANTITIES.map(|q| inv.get(q).map_or(SignSet::exactly(0), signs_of)),
            coefficients: coeffs.each_ref().map(signs_of),
        }
    }
    /// The same with quantity `q` known to be zero (e.g. at a root of it).
    pub fn with_zero(mut self, q: Quantity) -> Readings {
        if let Some(i) = QUANTITIES.iter().position(|x| *x == q) {
            self.quantities[i] = SignSet::exactly(0);
        }
        self
    }
    /// The possible signs of `q` (not [`Quantity::Var`]).
    pub fn quantity(&self, q: Quantity) -> SignSet {
        QUANTITIES
            .iter()
            .position(|x| *x == q)
            .map_or(SignSet::exactly(0), |i| self.quantities[i])
    }
    /// The possible values of `Var(e, a, b, c, d)` over every choice of the
    /// coefficients' signs.
    pub fn variations(&self) -> VarSet {
        let mut out = VarSet::default();
        for_each_combination(&self.coefficients, &mut |signs| {
            out = out.with(sign_variations(signs));
        });
        out
    }
}

/// Calls `f` with every choice of one sign from each set.
fn for_each_combination(sets: &[SignSet; 5], f: &mut impl FnMut(&[i32; 5])) {
    fn rec(sets: &[SignSet; 5], k: usize, cur: &mut [i32; 5], f: &mut impl FnMut(&[i32; 5])) {
        if k == 5 {
            f(cur);
            return;
        }
        for s in sets[k].values() {
            cur[k] = s;
            rec(sets, k + 1, cur, f);
        }
    }
    rec(sets, 0, &mut [0; 5], f);
}
