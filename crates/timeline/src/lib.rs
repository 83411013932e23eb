//! The result of a CCD query: instants with exact rational enclosures
//! (certified, or marked as not), segments of constant state, and the
//! timeline over the span. Every solving path (exact, float, interval)
//! answers in these types.

#![warn(missing_docs)]

use ccd_arith::Rat;
use ccd_classify::Configuration;

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
        Rat::midpoint_decimal(&self.lo, &self.hi, digits)
    }
}

/// A box `lo <= x <= hi` (componentwise) in world coordinates with exact
/// rational ends: a certified enclosure of a point or a vector when the
/// [`Geometry`] holding it says so.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Box3 {
    /// Lower ends.
    pub lo: [Rat; 3],
    /// Upper ends.
    pub hi: [Rat; 3],
}

impl Box3 {
    /// The box holding exactly the point `x`.
    pub fn point(x: [Rat; 3]) -> Box3 {
        Box3 {
            lo: x.clone(),
            hi: x,
        }
    }
    /// The midpoint of each coordinate.
    pub fn midpoint(&self) -> [Rat; 3] {
        std::array::from_fn(|i| Rat::midpoint(&self.lo[i], &self.hi[i]))
    }
    /// The largest width `hi − lo` over the three coordinates.
    pub fn width(&self) -> Rat {
        (0..3)
            .map(|i| &self.hi[i] - &self.lo[i])
            .max()
            .unwrap_or_else(Rat::zero)
    }
    /// The midpoint's coordinates as decimal strings with `digits` decimals.
    pub fn approx(&self, digits: u32) -> [String; 3] {
        std::array::from_fn(|i| Rat::midpoint_decimal(&self.lo[i], &self.hi[i], digits))
    }
}

/// Where and in which direction the bodies touch at an isolated contact
/// instant `t*`: the kernel of `λ*·A(t*) + B(t*)` for the positive double
/// root `λ*` of `f(λ; t*) = det(λA(t*) + B(t*))` (Wang et al. 2001).
// The large variant is the usual one (a point per contact): boxing it
// would add an allocation to every contact to shrink the rare others.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Geometry {
    /// The contact point and `A`'s outward normal there (pointing into
    /// `B`), scaled so that its component of largest magnitude is `±1`.
    Point {
        /// Encloses the contact point (world coordinates).
        point: Box3,
        /// Encloses the normal, `∇(XᵀA X)` at the point divided by the
        /// magnitude of its largest component (that component is exactly
        /// `±1`).
        normal: Box3,
        /// Whether both boxes are proven to hold the true point and normal
        /// (never, in float mode: there they are `f64` values, `lo == hi`).
        certified: bool,
    },
    /// The kernel of `λ*·A(t*) + B(t*)` was not found one-dimensional: every
    /// enclosure of the adjugate's last column holds 0 at the highest
    /// precision tried (the bodies may touch along a curve).
    NotASinglePoint,
    /// No point could be computed within the effort bound.
    Unknown {
        /// Why.
        reason: String,
    },
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
    /// Whether `state` is proven on the whole segment (always on the exact
    /// path; never in float mode; on the interval path when every sign that
    /// decided it was proven, see `docs/helical.md`).
    pub certified: bool,
}

/// A proven state at one exact instant inside a [`Gap`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Witness {
    /// The instant (an exact rational).
    pub t: Rat,
    /// The state there, proven.
    pub state: State,
}

/// A piece `[lo, hi]` of the span that the timeline does not cover: the
/// solver could not decide it within its documented effort budget
/// (`docs/helical.md`). Only the interval path produces gaps.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Gap {
    /// Start of the undecided piece (exact).
    pub lo: Rat,
    /// End of the undecided piece (exact).
    pub hi: Rat,
    /// Why it is undecided, in words.
    pub reason: String,
    /// A proven non-separate state at an instant inside, if one was found:
    /// a proof that the span is not collision-free.
    pub witness: Option<Witness>,
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
    /// Which arithmetic answered.
    pub path: Path,
    /// Which branch of Algorithm 1 ran (`None` when the query stopped at
    /// `t0` before choosing one).
    pub branch: Option<Branch>,
    /// Candidate instants examined.
    pub candidates: usize,
    /// The exact path formed `sr0` (or `sr11`) as a polynomial: its
    /// certified `f64` filter could not decide every sign, or `sr0 ≡ 0`.
    pub sr0_formed: bool,
}

/// The arithmetic that answered a query (`--arithmetic`, or the interval
/// path that non-rational motions take).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Path {
    /// Exact and certified (rational motions).
    #[default]
    Exact,
    /// `f64`, not certified (the paper's Table 3 setting).
    Float,
    /// Certified interval enclosures where they decide (helical motions).
    Interval,
    /// Certified by a ray cast into the Minkowski difference (bodies
    /// translating along straight lines, `--raycast`): no polynomial is
    /// formed, so the degrees read 0 and `None`.
    Raycast,
}

/// The branch of Algorithm 1 (Section 5) a query took.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Branch {
    /// `sr0 ≢ 0`: the candidates are the roots of `sr0` (Theorem 5.2).
    Sr0,
    /// `sr0 ≡ 0`, `sr11 ≢ 0`: the candidates are the roots of `sr11`, or
    /// the bodies touch throughout (Theorems 5.4, 5.5).
    Sr11,
    /// `sr0 ≡ sr11 ≡ 0`: the state at `t0` holds throughout (Theorem 5.6).
    Throughout,
    /// `sr0` was neither proven nonzero at a sample nor identically zero
    /// (interval path): the span is undecided.
    Sr0Undecided,
    /// `sr0 ≡ 0` was proven but `sr11` was neither proven nonzero at a
    /// sample nor identically zero (interval path).
    Sr11Undecided,
}

impl Branch {
    /// The name the reports and the JSON `stats.branch` use on `path`.
    pub fn name(self, path: Path) -> &'static str {
        match (path, self) {
            (Path::Interval, Branch::Sr0) => "interval: sr0",
            (Path::Interval, Branch::Sr0Undecided) => "interval: sr0 undecided",
            (Path::Interval, Branch::Sr11) => "interval: sr0 = 0 (structure), sr11",
            (Path::Interval, Branch::Sr11Undecided) => {
                "interval: sr0 = 0 (structure), sr11 undecided"
            }
            (Path::Interval, Branch::Throughout) => "interval: sr0 = 0 (structure), sr11 = 0",
            (_, Branch::Sr0 | Branch::Sr0Undecided) => "sr0",
            (_, Branch::Sr11 | Branch::Sr11Undecided) => "sr0=0, sr11",
            (_, Branch::Throughout) => "sr0=0, sr11=0",
        }
    }
}

impl Stats {
    /// [`Branch::name`] of the branch taken, `""` when none was.
    pub fn branch_name(&self) -> &'static str {
        if self.path == Path::Raycast {
            return "raycast";
        }
        self.branch.map_or("", |b| b.name(self.path))
    }
}

/// The answer of a CCD query over the span `[t0, t1]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// `[t0, t1]`.
    pub span: [Rat; 2],
    /// `true` exactly when the bodies are separate throughout the span —
    /// proven, except in float mode, whose answers are never proven. On the
    /// interval path `false` means a collision is proven unless
    /// [`Outcome::undecided`] says otherwise.
    pub collision_free: bool,
    /// `Some(reason)` when neither separation over the whole span nor a
    /// collision was proven (interval path only): the JSON writes
    /// `collision_free: null` and this as `collision_free_reason`.
    pub undecided: Option<String>,
    /// The earliest instant at which they are not separate.
    pub first_contact: Option<Instant>,
    /// The isolated instants of external touching, in order.
    pub contacts: Vec<Instant>,
    /// The span cut into segments, in order; without gaps when `complete`
    /// (otherwise it stops at the first contact, or skips the [`Gap`]s).
    pub timeline: Vec<Segment>,
    /// Pieces of the span the timeline leaves out, undecided (in order).
    pub gaps: Vec<Gap>,
    /// `true` exactly when the timeline covers the span from `t0` to `t1`
    /// with no gap: `false` when only the first contact was asked for (the
    /// timeline then stops there) or when [`Outcome::gaps`] is not empty.
    pub complete: bool,
    /// Degrees and counters.
    pub stats: Stats,
    /// The contact point and normal of each entry of `contacts`, in the
    /// same order (empty when not computed).
    pub geometry: Vec<Geometry>,
    /// The contact point and normal at the start and at the end of each
    /// entry of `timeline` that is a touch but not an isolated contact (a
    /// touching-throughout segment, Theorems 5.5 and 5.6, or the touch at
    /// `t0` where a first-contact query stops), in the same order as
    /// `timeline`; `None` for every other segment (empty when not
    /// computed). An end that is not an exact instant gets
    /// [`Geometry::Unknown`].
    pub segment_geometry: Vec<Option<[Geometry; 2]>>,
}

impl Outcome {
    /// The point and normal at the first contact when it is a touch: the
    /// geometry of the isolated contact it is, or of the start of the
    /// touch segment it starts (`None` otherwise, or when not computed).
    pub fn first_contact_geometry(&self) -> Option<&Geometry> {
        let first = self.first_contact.as_ref()?;
        if let Some(k) = self.contacts.iter().position(|c| c == first) {
            return self.geometry.get(k);
        }
        let same = |i: &Instant| i.lo == first.lo && i.hi == first.hi;
        self.timeline
            .iter()
            .zip(&self.segment_geometry)
            .find(|(s, g)| g.is_some() && same(&s.start))
            .and_then(|(_, g)| g.as_ref().map(|[start, _]| start))
    }

    /// Whether everything reported is proven: every segment and instant
    /// certified, no [`Gap`] and no [`Outcome::undecided`] verdict. (It does
    /// not say the timeline is complete: a first-contact query is certified
    /// but not complete.)
    pub fn certified(&self) -> bool {
        self.timeline
            .iter()
            .all(|s| s.certified && s.start.certified && s.end.certified)
            && self.contacts.iter().all(|c| c.certified)
            && self.first_contact.as_ref().is_none_or(|c| c.certified)
            && self.gaps.is_empty()
            && self.undecided.is_none()
    }
}
