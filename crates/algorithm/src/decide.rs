//! Theorem 3.10 read off any arithmetic: each quantity contributes the SET
//! of signs the arithmetic allows it at a point (one sign when it is
//! decided), and the decision tree of [`ccd_classify::classify_with`] is
//! walked down every branch those sets leave open. The configuration is
//! decided when every branch ends in the same one; otherwise the
//! [`Possible`] set says which remain — e.g. whether an undecided candidate
//! instant is *consistent with* an external touch.

use ccd_classify::{classify_with, Configuration};
use ccd_subres::Quantity;

/// A set of possible signs (a subset of {−1, 0, 1}).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SignSet(u8);

impl SignSet {
    const NEG: u8 = 1;
    const ZERO: u8 = 2;
    const POS: u8 = 4;

    /// Every sign: nothing is known.
    pub const ANY: SignSet = SignSet(7);

    /// The signs the points of `[lo, hi]` can have, from the signs of its
    /// ends (`lo <= hi`).
    pub fn of_ends(lo: i32, hi: i32) -> SignSet {
        let mut bits = 0;
        if lo < 0 {
            bits |= Self::NEG;
        }
        if hi > 0 {
            bits |= Self::POS;
        }
        if lo <= 0 && hi >= 0 {
            bits |= Self::ZERO;
        }
        SignSet(bits)
    }
    /// Exactly the sign of `s`.
    pub fn exactly(s: i32) -> SignSet {
        SignSet(match s.signum() {
            -1 => Self::NEG,
            0 => Self::ZERO,
            _ => Self::POS,
        })
    }
    /// The signs in the set, in increasing order.
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

/// A set of possible values of `Var(e, a, b, c, d)` (0 to 4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct VarSet(u8);

impl VarSet {
    /// Exactly `v`.
    pub fn exactly(v: usize) -> VarSet {
        VarSet(1 << v.min(4))
    }
    /// The set with `v` added.
    pub fn with(self, v: usize) -> VarSet {
        VarSet(self.0 | 1 << v.min(4))
    }
    /// The values in the set, in increasing order.
    pub fn values(self) -> impl Iterator<Item = i32> {
        (0..5).filter(move |v| self.0 & (1 << v) != 0)
    }
}

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
    /// Only `c` is possible.
    pub fn only(c: Configuration) -> Possible {
        let mut p = Possible::default();
        p.insert(c);
        p
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

/// The questions of one decision: the sign set of each quantity (asked at
/// most once, and only when the decision tree reaches it).
pub trait Signs {
    /// The possible signs of `q` (not [`Quantity::Var`]).
    fn sign(&mut self, q: Quantity) -> SignSet;
    /// The possible values of `Var(e, a, b, c, d)`.
    fn variations(&mut self) -> VarSet;
}

/// Every configuration of Theorem 3.10 that some combination of the signs
/// `signs` allows; `zero` lists quantities known to vanish (read as exactly
/// 0 without asking). With `touch_only`, `Var` is never asked: it is read
/// only on the way to "separate" or "overlap", so a branch that reaches it
/// is not a touch (both are inserted).
///
/// With one sign per quantity (exact and float arithmetic) this asks the
/// questions of [`classify_with`] in its order, each once.
///
/// ```
/// use ccd_algorithm::{possible_with, SignSet, Signs, VarSet};
/// use ccd_classify::Configuration;
/// use ccd_subres::Quantity;
/// struct Fixed;
/// impl Signs for Fixed {
///     fn sign(&mut self, q: Quantity) -> SignSet {
///         // sr22 > 0, sr11 > 0, sr10 < 0: a touch where sr0 = 0 (3.10(2a)).
///         SignSet::exactly(if q == Quantity::Sr10 { -1 } else { 1 })
///     }
///     fn variations(&mut self) -> VarSet { VarSet::exactly(2) }
/// }
/// let touch = possible_with(&mut Fixed, &[Quantity::Sr0], true);
/// assert_eq!(touch.single(), Some(Configuration::ExternalTouch));
/// let sample = possible_with(&mut Fixed, &[], false);
/// assert_eq!(sample.single(), Some(Configuration::Separate));
/// ```
pub fn possible_with(signs: &mut dyn Signs, zero: &[Quantity], touch_only: bool) -> Possible {
    /// The walk reached `Var` in a touch-only decision.
    struct AtVar;
    /// A path: the answers given so far, in the order asked (a decision
    /// asks at most five questions).
    type Answers = ([i8; 6], usize);
    // The values each quantity may take, asked once: bit `v + 1` for a sign
    // `v`, bit `v` for `Var = v`.
    let mut asked: [Option<u8>; 6] = [None; 6];
    let mut out = Possible::default();
    // Branches left to walk (allocated only when a set has several values).
    let mut pending: Vec<Answers> = Vec::new();
    let mut path: Answers = ([0; 6], 0);
    loop {
        let mut depth = 0;
        let answer = classify_with(|q| {
            let slot = match q {
                Quantity::Sr22 => 0,
                Quantity::Sr20 => 1,
                Quantity::Sr11 => 2,
                Quantity::Sr10 => 3,
                Quantity::Sr0 => 4,
                Quantity::Var => 5,
            };
            let (bits, offset) = if q == Quantity::Var {
                if touch_only {
                    return Err(AtVar);
                }
                (*asked[slot].get_or_insert_with(|| signs.variations().0), 0)
            } else if zero.contains(&q) {
                (SignSet::ZERO, 1)
            } else {
                (*asked[slot].get_or_insert_with(|| signs.sign(q).0), 1)
            };
            if depth == path.1 {
                let mut values = (0..8i8)
                    .filter(|v| bits & (1 << v) != 0)
                    .map(|v| v - offset);
                let first = values.next().unwrap_or(0);
                for alt in values {
                    let mut branch = path;
                    branch.0[branch.1] = alt;
                    branch.1 += 1;
                    pending.push(branch);
                }
                path.0[path.1] = first;
                path.1 += 1;
            }
            depth += 1;
            Ok(i32::from(path.0[depth - 1]))
        });
        match answer {
            Ok(c) => out.insert(c),
            Err(AtVar) => {
                out.insert(Configuration::Separate);
                out.insert(Configuration::Overlap);
            }
        }
        match pending.pop() {
            Some(p) => path = p,
            None => return out,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_classify::{classify, SignData};
    use proptest::prelude::*;

    struct Sets([SignSet; 5], VarSet);
    impl Signs for Sets {
        fn sign(&mut self, q: Quantity) -> SignSet {
            let i = [
                Quantity::Sr22,
                Quantity::Sr20,
                Quantity::Sr11,
                Quantity::Sr10,
                Quantity::Sr0,
            ]
            .iter()
            .position(|x| *x == q)
            .expect("a quantity");
            self.0[i]
        }
        fn variations(&mut self) -> VarSet {
            self.1
        }
    }

    fn set(bits: u8) -> SignSet {
        SignSet(bits.clamp(1, 7))
    }

    proptest! {
        /// The lazy walk finds exactly the configurations of the exhaustive
        /// enumeration of every combination of allowed signs.
        #[test]
        fn the_walk_equals_the_enumeration(bits in proptest::array::uniform5(1u8..8), vars in 1u8..32) {
            let sets = bits.map(set);
            let var = VarSet(vars);
            let mut want = Possible::default();
            for a in sets[0].values() { for b in sets[1].values() { for c in sets[2].values() {
                for d in sets[3].values() { for e in sets[4].values() { for v in var.values() {
                    want.insert(classify(&SignData { sr22: a, sr20: b, sr11: c, sr10: d, sr0: e, var: v as usize }));
                }}}}}}
            prop_assert_eq!(possible_with(&mut Sets(sets, var), &[], false), want);
            // Touch-only: the same answer to "is a touch possible / single?".
            let t = possible_with(&mut Sets(sets, var), &[], true);
            prop_assert_eq!(t.touch, want.touch);
            prop_assert_eq!(t.single() == Some(Configuration::ExternalTouch), want.single() == Some(Configuration::ExternalTouch));
        }
    }
}
