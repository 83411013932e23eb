//! The result of a CCD query: instants with exact rational enclosures
//! (certified, or marked as not), segments of constant state, and the
//! timeline over the span. Every solving path (exact, float, interval)
//! answers in these types.

#![warn(missing_docs)]

use ccd_arith::Rat;
use ccd_subres::Configuration;

/// The configuration of the two ellipsoids on a segment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum State {
    /// No common point.
    Separate,
    /// The surfaces meet, the interiors do not (external touching).
    Touch,
    /// The interiors share a point.
    Overlap,
}

impl From<Configuration> for State {
    fn from(c: Configuration) -> State {
        match c {
            Configuration::Separate => State::Separate,
            Configuration::ExternalTouch => State::Touch,
            Configuration::Overlap => State::Overlap,
        }
    }
}

impl State {
    /// The contract's name: `separate`, `touch` or `overlap`.
    pub fn name(self) -> &'static str {
        match self {
            State::Separate => "separate",
            State::Touch => "touch",
            State::Overlap => "overlap",
        }
    }
}

/// An instant `t` known by a certified enclosure `lo <= t <= hi` with exact
/// rational ends (`lo == hi` when it is known exactly).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Instant {
    /// Lower bound.
    pub lo: Rat,
    /// Upper bound.
    pub hi: Rat,
    /// Whether the enclosure is proven (always, on the exact path).
    pub certified: bool,
}

impl Instant {
    /// An instant known exactly.
    pub fn exact(t: Rat) -> Instant {
        Instant {
            lo: t.clone(),
            hi: t,
            certified: true,
        }
    }
    /// The midpoint of the enclosure.
    pub fn midpoint(&self) -> Rat {
        Rat::midpoint(&self.lo, &self.hi)
    }
    /// `hi − lo`.
    pub fn width(&self) -> Rat {
        &self.hi - &self.lo
    }
    /// The midpoint as a decimal string with `digits` decimals.
    pub fn approx(&self, digits: u32) -> String {
        self.midpoint().to_decimal(digits)
    }
}

/// A maximal piece of the span with one state; an isolated contact instant
/// is a `Touch` segment whose start and end are the same instant.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Segment {
    /// The state throughout the segment (on its interior, for an interval).
    pub state: State,
    /// Where it starts.
    pub start: Instant,
    /// Where it ends.
    pub end: Instant,
}

/// Counters and degrees of one run, for reports and benchmarks.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// `deg_t f(λ; t)` after normalisation.
    pub deg_f: usize,
    /// `deg sr0(t)`, `None` when `sr0 ≡ 0`.
    pub deg_sr0: Option<usize>,
    /// Degree of the polynomial whose roots were the candidates.
    pub deg_candidates: Option<usize>,
    /// Which branch of Algorithm 1 ran.
    pub branch: &'static str,
    /// Candidate instants examined.
    pub candidates: usize,
}

/// The answer of a CCD query over the span `[t0, t1]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// `[t0, t1]`.
    pub span: [Rat; 2],
    /// `true` exactly when the bodies are separate throughout the span.
    pub collision_free: bool,
    /// The earliest instant at which they are not separate.
    pub first_contact: Option<Instant>,
    /// The isolated instants of external touching, in order.
    pub contacts: Vec<Instant>,
    /// The span cut into segments, in order and without gaps (up to the
    /// first contact only, when `complete` is false).
    pub timeline: Vec<Segment>,
    /// `false` when only the first contact was asked for: the timeline then
    /// stops there.
    pub complete: bool,
    /// Degrees and counters.
    pub stats: Stats,
}
