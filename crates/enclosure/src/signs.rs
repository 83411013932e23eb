//! Reading Theorem 3.10 off enclosures: each quantity contributes the SET
//! of signs its enclosure allows, and the configuration is decided when
//! every combination of allowed signs gives the same answer of
//! [`ccd_classify::classify`] (one decision tree shared with the exact path).
//! When several configurations remain possible, the set says which ones —
//! e.g. whether an undecided candidate instant is *consistent with* an
//! external touch.

use crate::real::Real;
use ccd_classify::{classify, sign_variations, Configuration, SignData};
use ccd_subres::{Quantity, QuarticInvariants};

/// A set of possible signs (subset of {−1, 0, 1}).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignSet(u8);

impl SignSet {
    const NEG: u8 = 1;
    const ZERO: u8 = 2;
    const POS: u8 = 4;

    /// The signs the points of an enclosure can have.
    pub fn of<R: Real>(x: &R) -> SignSet {
        let (l, h) = x.end_signs();
        let mut bits = 0;
        if l < 0 {
            bits |= Self::NEG;
        }
        if h > 0 {
            bits |= Self::POS;
        }
        if l <= 0 && h >= 0 {
            bits |= Self::ZERO;
        }
        SignSet(bits)
    }
    /// Exactly the sign `s`.
    pub fn exactly(s: i32) -> SignSet {
        SignSet(match s.signum() {
            -1 => Self::NEG,
            0 => Self::ZERO,
            _ => Self::POS,
        })
    }
    /// The signs in the set.
    pub fn values(self) -> impl Iterator<Item = i32> {
        [(Self::NEG, -1), (Self::ZERO, 0), (Self::POS, 1)]
            .into_iter()
            .filter(move |(b, _)| self.0 & b != 0)
            .map(|(_, s)| s)
    }
    /// The sign when it is the only one.
    pub fn single(self) -> Option<i32> {
        let mut v = self.values();
        let first = v.next()?;
        v.next().is_none().then_some(first)
    }
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

/// A set of configurations.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Possible {
    /// Separate is possible.
    pub separate: bool,
    /// External touching is possible.
    pub touch: bool,
    /// Overlapping is possible.
    pub overlap: bool,
}

impl Possible {
    fn insert(&mut self, c: Configuration) {
        match c {
            Configuration::Separate => self.separate = true,
            Configuration::ExternalTouch => self.touch = true,
            Configuration::Overlap => self.overlap = true,
        }
    }
    /// The configuration when it is the only possible one.
    pub fn single(self) -> Option<Configuration> {
        match (self.separate, self.touch, self.overlap) {
            (true, false, false) => Some(Configuration::Separate),
            (false, true, false) => Some(Configuration::ExternalTouch),
            (false, false, true) => Some(Configuration::Overlap),
            _ => None,
        }
    }
}

impl Readings {
    /// Sign sets of evaluated coefficients and invariants.
    pub fn of<R: Real>(coeffs: &[R; 5], inv: &QuarticInvariants<R>) -> Readings {
        Readings {
            quantities: QUANTITIES.map(|q| inv.get(q).map_or(SignSet::exactly(0), SignSet::of)),
            coefficients: coeffs.each_ref().map(SignSet::of),
        }
    }
    /// The same with quantity `q` known to be zero (e.g. at a root of it).
    pub fn with_zero(mut self, q: Quantity) -> Readings {
        if let Some(i) = QUANTITIES.iter().position(|x| *x == q) {
            self.quantities[i] = SignSet::exactly(0);
        }
        self
    }
    /// Every configuration some combination of allowed signs gives.
    pub fn possible(&self) -> Possible {
        let mut vars: Vec<usize> = Vec::new();
        for_each_combination(&self.coefficients, &mut |signs| {
            let v = sign_variations(signs);
            if !vars.contains(&v) {
                vars.push(v);
            }
        });
        let mut out = Possible::default();
        for_each_combination(&self.quantities, &mut |s| {
            for &var in &vars {
                out.insert(classify(&SignData {
                    sr22: s[0],
                    sr20: s[1],
                    sr11: s[2],
                    sr10: s[3],
                    sr0: s[4],
                    var,
                }));
            }
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

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_arith::Interval;

    #[test]
    fn decided_and_undecided_readings() {
        let pos = SignSet::exactly(1);
        let neg = SignSet::exactly(-1);
        let any = SignSet::of(&Interval::new(-1.0, 1.0));
        assert_eq!(any.values().count(), 3);
        // sr22 > 0, sr11 > 0, sr10 < 0, sr0 = 0: touch (3.10(2a)).
        let touch = Readings {
            quantities: [pos, any, pos, neg, SignSet::exactly(0)],
            coefficients: [neg, pos, neg, pos, neg],
        };
        assert_eq!(
            touch.possible().single(),
            Some(Configuration::ExternalTouch)
        );
        // sr0 undecided: separate (Var = 4 → overlap here) or touch or overlap.
        let open = Readings {
            quantities: [pos, any, pos, neg, any],
            ..touch
        };
        let p = open.possible();
        assert!(p.touch && p.overlap && p.single().is_none());
        assert_eq!(open.with_zero(Quantity::Sr0).possible(), touch.possible());
    }
}
