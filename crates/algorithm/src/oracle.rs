//! What Algorithm 1 asks of an arithmetic: the one small trait the exact,
//! float and interval arithmetics implement.

use crate::decide::Signs;
use crate::CcdError;
use ccd_arith::Rat;
use ccd_subres::Quantity;
use ccd_timeline::{Geometry, Instant, Path, Segment, State, Stats};

/// Where the signs of a decision are read.
pub enum At<'r, R> {
    /// A rational parameter value: a piece's sample, `t0`, or Theorem
    /// 5.5's non-root `δ`.
    Sample(&'r Rat),
    /// A candidate root, over its current enclosure (the arithmetic may
    /// narrow it to decide a sign).
    Root(&'r mut R),
}

/// A state at one instant and whether it is proven.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Decided {
    /// The state.
    pub state: State,
    /// Whether every sign that decided it was proven.
    pub certified: bool,
}

/// What an arithmetic knows about `q ≡ 0` on the whole span (the branches
/// of Algorithm 1: Theorems 5.2, 5.4–5.6).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Vanishing {
    /// `q ≢ 0`, with a non-root of `q` when the arithmetic has one at hand
    /// (always for `sr11`: Theorem 5.5 reads the state there).
    Not(Option<Rat>),
    /// `q ≡ 0`, proven (or, in float arithmetic, to its tolerance).
    Identically,
    /// Neither could be proven (interval arithmetic): the span is left
    /// undecided.
    Unknown,
}

/// One item of a candidate stream, in increasing order.
pub enum Found<R> {
    /// An isolated root (one root of the candidate polynomial in it, or a
    /// float estimate).
    Root(R),
    /// Roots not separated from each other (interval arithmetic):
    /// subdivided again by [`Oracle::split`] or reported as they are.
    Cluster(R),
    /// A piece where the roots were not isolated within the effort budget.
    Gap {
        /// Start (in the oracle's parameter).
        lo: Rat,
        /// End.
        hi: Rat,
        /// Why, in words.
        reason: &'static str,
    },
    /// The stream could not prove a sign (a filter that gave up): what it
    /// found is dropped and the next, costlier attempt starts over.
    GaveUp,
    /// A documented effort bound was reached.
    Failed(CcdError),
}

/// The candidate instants of one attempt: the roots of `sr0` (or `sr11`).
pub struct Candidates<'a, R> {
    /// Degree of the polynomial whose roots they are, when known.
    pub degree: Option<usize>,
    /// The roots in increasing order.
    pub roots: Box<dyn Iterator<Item = Found<R>> + 'a>,
}

/// One entry of a timeline under construction, in time order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Item {
    /// A piece (or an instant) of constant state.
    Segment(Segment),
    /// A piece left undecided.
    Gap(ccd_timeline::Gap),
}

/// The time `t0 + u·(t1 − t0)` of the parameter `u ∈ [0, 1]` on the span
/// `[t0, t1]` (the rational paths' [`Oracle::time`]); the ends `u = 0, 1`,
/// which every timeline has, and every `u` on the unit span `[0, 1]`
/// (`t = u`), without arithmetic.
pub fn time_on(span: &[Rat; 2], u: &Rat) -> Rat {
    let [t0, t1] = span;
    if u.is_zero() {
        t0.clone()
    } else if u.is_integer() && u.numer().is_one() {
        t1.clone()
    } else if t0.is_zero() && t1.is_integer() && t1.numer().is_one() {
        // The unit span: t = u.
        u.clone()
    } else {
        t0 + &(u * &(t1 - t0))
    }
}

/// The questions Algorithm 1 ([`crate::run`]) asks, answered by one
/// arithmetic: exact (`ccd-exact-arith`, certified), float (`ccd-float`,
/// not certified) or interval (`ccd-interval`, certified where its
/// enclosures decide).
///
/// Everything is given in the oracle's parameter on [`Oracle::domain`]
/// (`u ∈ [0, 1]` for the rational paths, `t` itself for the interval path)
/// and mapped to time by [`Oracle::time`] at the end.
pub trait Oracle {
    /// A candidate instant with its enclosure.
    type Root;
    /// Which arithmetic this is (`Path::Float` marks every answer
    /// uncertified).
    const PATH: Path;
    /// Precision levels a decision escalates through while undecided
    /// ([`Oracle::signs`]); 1 when signs are final.
    const LEVELS: usize = 1;
    /// Whether a piece between contacts may be read at an end of its
    /// closure that is not a root (exact signs decide any non-root; an
    /// enclosure next to a root does not).
    const SAMPLE_AT_ENDS: bool = false;
    /// The level of [`Oracle::signs`] before which the touch test at an
    /// isolated root tries its other certificates (the states on both
    /// sides, [`Oracle::interiors_meet`]; `crate::run`): `Some` only
    /// where every [`Found::Root`] (from a stream or from
    /// [`Oracle::split`]) holds exactly one root of the candidate
    /// polynomial in its enclosure `[lo, hi]`, with `lo` and `hi` not roots
    /// unless `lo = hi`, and samples are classified exactly; the levels
    /// before it should be the cheap ones.
    const CERTIFICATES_BEFORE_LEVEL: Option<usize> = None;

    /// The parameter interval `[lo, hi]` of the span.
    fn domain(&self) -> &[Rat; 2];
    /// The time of parameter value `x`.
    fn time(&self, x: &Rat) -> Rat;
    /// The signs Theorem 3.10 reads at `at`, at precision `level <
    /// LEVELS`; quantities proven identically zero read as 0.
    fn signs<'s>(&'s self, at: At<'s, Self::Root>, level: usize) -> Box<dyn Signs + 's>;
    /// A best guess of the state at `x` when no level decides it (marked
    /// uncertified).
    fn guess(&self, x: &Rat) -> State;
    /// The set-up that only a query going past `t0` needs (the exact path
    /// forms `f(λ; t)` here).
    fn prepare(&mut self) -> Result<(), CcdError> {
        Ok(())
    }
    /// Whether `q` (`sr0` or `sr11`) vanishes on the whole span.
    fn vanishes(&mut self, q: Quantity) -> Vanishing;
    /// The roots of `q` in the domain; `attempt` counts the attempts that
    /// gave up ([`Found::GaveUp`]); `None`: no further attempt exists.
    fn candidates(&self, q: Quantity, attempt: usize) -> Option<Candidates<'_, Self::Root>>;
    /// The enclosure `[lo, hi]` of a candidate.
    fn ends(&self, r: &Self::Root) -> (Rat, Rat);
    /// A cluster subdivided again, within the effort budget (`None`: not
    /// subdivided).
    fn split(&self, _cluster: &Self::Root, _q: Quantity) -> Option<Vec<Found<Self::Root>>> {
        None
    }
    /// Whether the bodies' interiors provably meet at every instant of the
    /// root's enclosure (at each instant, a point of both interiors), which
    /// rules out an external touch there; the default knows none.
    fn interiors_meet(&self, _r: &Self::Root) -> bool {
        false
    }
    /// The root's enclosure narrowed to the query's width, as an instant
    /// (`certified` when its enclosure is proven to hold one root).
    fn refine(&self, r: &mut Self::Root, q: Quantity) -> Instant;
    /// The contact point and normal at the contact `r` (an external touch
    /// at `instant`, in the parameter), the quantities `zeros` vanishing
    /// there.
    fn geometry(&self, r: &mut Self::Root, zeros: &[Quantity], instant: &Instant) -> Geometry;
    /// The contact point and normal at the rational parameter `x`, where
    /// the bodies touch without an isolated contact to read it from (an end
    /// of a touching-throughout segment, or `t0` where a first-contact
    /// query stops); the quantities `zeros` vanish identically on the span
    /// (`sr11 ≡ 0` decides case (2b) of Theorem 3.10). Evaluated at the
    /// point `x` itself: exactly on the exact path.
    fn geometry_at(&self, x: &Rat, zeros: &[Quantity]) -> Geometry;
    /// The state a sample between contacts gave `Touch`, which Theorem 5.1
    /// rules out: the arithmetic's answer (an error on the exact path).
    fn touch_between_contacts(&self, x: &Rat, d: Decided) -> Result<Decided, CcdError>;
    /// The timeline's gaps filled by what other certificates prove
    /// (interval arithmetic); the default leaves them.
    fn settle(&self, items: Vec<Item>) -> Vec<Item> {
        items
    }
    /// The arithmetic's own statistics (degrees, what was formed).
    fn stats(&self, stats: &mut Stats);
}

#[cfg(test)]
mod tests {
    use super::time_on;
    use ccd_arith::Rat;
    use proptest::prelude::*;

    proptest! {
        /// Every shortcut of `time_on` is `t0 + u·(t1 − t0)`.
        #[test]
        fn time_on_is_the_affine_map(
            u in (0i64..=64, 1i64..=64),
            t0 in (-5i64..5, 1i64..4),
            len in (1i64..5, 1i64..4),
            unit in any::<bool>(),
        ) {
            let u = Rat::from_frac(u.0.min(u.1), u.1);
            let span = if unit {
                [Rat::zero(), Rat::one()]
            } else {
                let t0 = Rat::from_frac(t0.0, t0.1);
                let t1 = &t0 + &Rat::from_frac(len.0, len.1);
                [t0, t1]
            };
            let want = &span[0] + &(&u * &(&span[1] - &span[0]));
            prop_assert_eq!(time_on(&span, &u), want);
        }
    }
}
