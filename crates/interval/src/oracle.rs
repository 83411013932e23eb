//! The interval arithmetic's answers to Algorithm 1 (`ccd-algorithm`),
//! for any motion kinds and in particular `helical`: candidate instants
//! from the certified isolation of `sr0(t)` (or of `sr11(t)` when
//! `sr0 ≡ 0` is proven by structure), signs of Theorem 3.10 from
//! enclosures, escalated to multi-precision while undecided, and the gaps
//! the effort budget leaves filled by sphere certificates where they prove
//! something (`docs/helical.md`).

use crate::signs::Readings;
use crate::spheres::settle_gaps;
use crate::structure::{sr0_vanishes_by_structure, without_invisible_spin};
use ccd_algorithm::{
    At, Candidates, CcdError, Decided, Found, Item, Options, Oracle, SignSet, Signs, Vanishing,
    VarSet,
};
use ccd_arith::{Int, Interval, Rat};
use ccd_classify::{classify, SignData};
use ccd_contact::{enclose, Case, Goal};
use ccd_enclosure::isolate::{isolate, refine, width_rat, Found as Isolated, Limits, Problem};
use ccd_enclosure::placement::invariants_at;
use ccd_enclosure::real::Real;
use ccd_enclosure::BigInterval;
use ccd_motion::{Body, Motion};
use ccd_subres::{closed_form, Quantity};
use ccd_timeline::{Geometry, Instant, Path, State, Stats};
use std::cell::Cell;

/// Precisions (bits) tried, in order, when an `f64` enclosure cannot decide
/// a configuration at a point or on a box — on top of `Intervals::extra_bits`,
/// the bits of the largest angle `|rate·t|`, `|frequency·t|`.
const DECISION_PRECISIONS: [u32; 2] = [128, 512];
/// Evenly spaced samples used to test whether a quantity vanishes
/// identically.
const ZERO_TEST_SAMPLES: usize = 17;
/// Bits used to confirm that a quantity is not identically zero (plus the
/// angle's bits).
const ZERO_TEST_BITS: u32 = 256;
/// Minimal box width of the subdivision, relative to the span: `2^−36`.
const MIN_WIDTH_LOG2: i32 = -36;
/// The isolation domain extends the span by `2^−20` of its length on each
/// side, so that roots at the ends are strictly inside some box.
const MARGIN_LOG2: i32 = -20;
/// Effort budget: at most this many `f64` boxes are examined in the
/// isolation of the contacts; the boxes left are undecided gaps.
const MAX_BOXES: usize = 20_000;
/// Bits of the multi-precision subdivision of an `f64` cluster (plus the
/// angle's bits).
const CLUSTER_BITS: u32 = 128;
/// At most this many boxes are examined when subdividing one cluster again.
const MAX_CLUSTER_BOXES: usize = 400;
/// Effort budget over all the clusters of a query, in units of one box at
/// [`CLUSTER_BITS`] bits (a box at `b` bits costs `⌈b/128⌉²` units);
/// later clusters are reported unsubdivided.
const MAX_CLUSTER_BOXES_TOTAL: usize = 500;
/// Effort budget: at most this many candidate roots are decided and
/// refined; the span after the last one is an undecided gap.
const MAX_ROOTS: usize = 300;
/// Largest precision tried when refining a certified root.
const MAX_REFINEMENT_BITS: u32 = 1 << 15;
/// Effort budget of the sphere certificates in the gaps: boxes in all.
pub(crate) const MAX_SPHERE_BOXES: usize = 4_096;
/// Sphere-certificate boxes are not narrower than `2^−14` of their gap.
pub(crate) const SPHERE_MIN_WIDTH_LOG2: i64 = -14;
/// Effort budget: instants probed for a proven non-separate state inside
/// the gaps, in all.
pub(crate) const MAX_WITNESS_PROBES: usize = 16;
/// The angle's bits are capped here (an angle above `2^4096`, e.g. a rate
/// of `1e4000`, is evaluated with 4096 extra bits only: its `sin`/`cos`
/// stay wide and its pieces are decided by the sphere certificates or left
/// as gaps; multi-precision work at more bits grows too fast to stay within
/// seconds).
const MAX_EXTRA_BITS: u32 = 1 << 12;

/// An upper bound on `log2 |x|` (0 for `|x| <= 1`).
fn log2_bound(x: &Rat) -> u64 {
    if x.signum() == 0 {
        return 0;
    }
    (x.numer().bits() + 1).saturating_sub(x.denom().bits().saturating_sub(1))
}

/// Bits of the largest angle `|rate·t|` or `|frequency·t|` of a helical
/// body on the span (capped at [`MAX_EXTRA_BITS`]; 0 below `2^16`): the
/// extra working precision that keeps `sin` and `cos` of the angle tight
/// (an angle near `2^M` computed with `p` bits is known to about `2^(M−p)`).
fn angle_bits(bodies: [&Body; 2], span: &[Rat; 2]) -> u32 {
    let t = log2_bound(&span[0]).max(log2_bound(&span[1]));
    let mut bits = 0u64;
    for body in bodies {
        if let Motion::Helical { rate, center, .. } = &body.motion {
            bits = bits.max(log2_bound(rate) + t);
            bits = bits.max(log2_bound(&center.frequency) + t);
        }
    }
    // Angles below 2^16 cost at most 16 of the ≥ 128 multi-precision bits.
    if bits <= 16 {
        return 0;
    }
    bits.min(u64::from(MAX_EXTRA_BITS)) as u32
}

/// Evenly spaced dyadic samples strictly inside the span.
fn samples(span: &[Rat; 2], n: usize) -> Vec<Rat> {
    let dt = &span[1] - &span[0];
    (0..n)
        .map(|i| &span[0] + &(&dt * &Rat::from_frac(2 * i as i64 + 1, 2 * n as i64)))
        .collect()
}

/// Whether `q` is proven nonzero at some sample (f64, then multi-precision
/// with `extra_bits` more bits).
fn nonzero_somewhere(p: &Problem<'_>, span: &[Rat; 2], extra_bits: u32) -> Option<Rat> {
    let pts = samples(span, ZERO_TEST_SAMPLES);
    for t in &pts {
        if p.value(&Interval::from_rat(t), 53)
            .sign()
            .is_some_and(|s| s != 0)
        {
            return Some(t.clone());
        }
    }
    let bits = ZERO_TEST_BITS + extra_bits;
    for t in pts.iter().step_by(4) {
        let v = p.value(&BigInterval::from_rat(t, bits), bits);
        if v.sign().is_some_and(|s| s != 0) {
            return Some(t.clone());
        }
    }
    None
}

/// A candidate's box, in the precision it was isolated at.
#[derive(Clone, Debug)]
enum Boxed {
    F64(Interval),
    Big(BigInterval),
}

/// A candidate of the interval path: its box and exact rational ends.
#[derive(Clone, Debug)]
pub struct IntervalRoot {
    lo: Rat,
    hi: Rat,
    boxed: Boxed,
}

/// The interval arithmetic for two bodies over a span (parameter: `t`
/// itself).
pub struct Intervals<'s> {
    /// The bodies with any invisible spin removed (the quantities).
    pub(crate) a: Body,
    pub(crate) b: Body,
    /// The bodies as given (the contact geometry).
    scene: (&'s Body, &'s Body),
    pub(crate) span: [Rat; 2],
    /// `sr0 ≡ 0` by the structure of the scene (Note 2 of the paper, and
    /// its generalisation: the quadratic parts of `A(t)` and `B(t)` are
    /// proportional for all t, so `λA + B` drops rank by 2 at one λ).
    sr0_zero: bool,
    digits: u32,
    /// Bits of the largest angle `|rate·t|`, `|frequency·t|` on the span,
    /// added to every multi-precision evaluation, so that `sin(1e300·t)`
    /// is enclosed tightly at a rational `t`.
    extra_bits: u32,
    /// Multi-precision cluster boxes left (`MAX_CLUSTER_BOXES_TOTAL`).
    cluster_boxes: Cell<usize>,
}

impl<'s> Intervals<'s> {
    /// The interval arithmetic of `a` and `b` on `span` (validated: the
    /// rational kinds exactly, as the exact path does).
    ///
    /// # Errors
    ///
    /// [`CcdError::Motion`] when a rational motion degenerates on the span.
    pub fn new(
        a: &'s Body,
        b: &'s Body,
        span: &[Rat; 2],
        opts: &Options,
    ) -> Result<Intervals<'s>, CcdError> {
        for (name, body) in [("a", a), ("b", b)] {
            // The rational kinds are checked exactly (vanishing weights or
            // quaternion curves, singular affine maps); placing a body
            // validates it.
            if !matches!(body.motion, Motion::Static { .. } | Motion::Helical { .. }) {
                ccd_motion::placed_quadric(body, span).map_err(|e| CcdError::motion(name, e))?;
            }
        }
        let (qa, qb) = (without_invisible_spin(a), without_invisible_spin(b));
        let extra_bits = angle_bits([&qa, &qb], span);
        let sr0_zero = sr0_vanishes_by_structure(&qa, &qb);
        Ok(Intervals {
            a: qa,
            b: qb,
            scene: (a, b),
            span: span.clone(),
            sr0_zero,
            digits: opts.digits,
            extra_bits,
            cluster_boxes: Cell::new(MAX_CLUSTER_BOXES_TOTAL),
        })
    }

    fn problem(&self, target: Quantity) -> Problem<'_> {
        Problem {
            a: &self.a,
            b: &self.b,
            span: &self.span,
            target,
        }
    }

    /// The readings of Theorem 3.10 over `[lo, hi]` at precision `level`:
    /// `f64` (level 0), then [`DECISION_PRECISIONS`] (plus the angle's
    /// bits).
    fn readings(&self, lo: &Rat, hi: &Rat, level: usize) -> Readings {
        let mut r = if level == 0 {
            let t = Interval::from_rat(lo).hull(&Interval::from_rat(hi));
            let (f, inv) = invariants_at(&self.a, &self.b, &self.span, &t, t.precision());
            Readings::of(&f, &inv)
        } else {
            let bits = DECISION_PRECISIONS[level - 1] + self.extra_bits;
            let t = BigInterval::from_rat(lo, bits).hull(&BigInterval::from_rat(hi, bits));
            let (f, inv) = invariants_at(&self.a, &self.b, &self.span, &t, t.precision());
            Readings::of(&f, &inv)
        };
        if self.sr0_zero {
            r = r.with_zero(Quantity::Sr0);
        }
        r
    }

    /// Bits for refining an enclosure to the target width on this span.
    fn refinement_bits(&self) -> u32 {
        let dt = (&self.span[1] - &self.span[0]).to_f64();
        let scale = self.span[0]
            .to_f64()
            .abs()
            .max(self.span[1].to_f64().abs())
            .max(dt);
        let ratio = (scale / dt).log2().max(0.0);
        // A span too narrow for `f64` beside its ends makes `ratio`
        // infinite: the cast saturates, and so does the sum.
        ((self.digits as f64 * std::f64::consts::LOG2_10 + ratio + 96.0).ceil() as u32)
            .saturating_add(self.extra_bits)
    }

    /// `(t1 − t0)·10^−digits`.
    fn width(&self) -> Rat {
        &(&self.span[1] - &self.span[0]) / &Rat::from_int(Int::pow10(self.digits))
    }

    /// A box of the isolation as a candidate stream item.
    fn found<R: Real>(&self, f: Isolated<R>, wrap: fn(R) -> Boxed) -> Option<Found<IntervalRoot>> {
        let root = |x: R| -> Option<IntervalRoot> {
            Some(IntervalRoot {
                lo: x.lo_rat()?,
                hi: x.hi_rat()?,
                boxed: wrap(x),
            })
        };
        Some(match f {
            Isolated::Root(x) => Found::Root(root(x)?),
            Isolated::Cluster(x) => match root(x) {
                Some(r) => Found::Cluster(r),
                None => Found::Gap {
                    lo: self.span[0].clone(),
                    hi: self.span[1].clone(),
                    reason: "enclosures unbounded",
                },
            },
            Isolated::Undecided(x) => {
                let (lo, hi) = ends_of(&Isolated::Undecided(x))
                    .unwrap_or_else(|| (self.span[0].clone(), self.span[1].clone()));
                Found::Gap {
                    lo,
                    hi,
                    reason: "effort budget reached before the roots were isolated",
                }
            }
        })
    }
}

/// The exact ends of a found box.
fn ends_of<R: Real>(f: &Isolated<R>) -> Option<(Rat, Rat)> {
    let x = match f {
        Isolated::Root(x) | Isolated::Cluster(x) | Isolated::Undecided(x) => x,
    };
    Some((x.lo_rat()?, x.hi_rat()?))
}

/// Sign sets over `[lo, hi]` at one level, evaluated on first need.
struct BoxSigns<'a, 's> {
    oracle: &'a Intervals<'s>,
    lo: Rat,
    hi: Rat,
    level: usize,
    readings: Option<Readings>,
}

impl BoxSigns<'_, '_> {
    fn readings(&mut self) -> &Readings {
        let (o, lo, hi, level) = (self.oracle, &self.lo, &self.hi, self.level);
        self.readings
            .get_or_insert_with(|| o.readings(lo, hi, level))
    }
}

impl Signs for BoxSigns<'_, '_> {
    fn sign(&mut self, q: Quantity) -> SignSet {
        self.readings().quantity(q)
    }
    fn variations(&mut self) -> VarSet {
        self.readings().variations()
    }
}

/// Theorem 3.10 on the multi-precision midpoints of every quantity at `t`
/// (a guess, for a sample no level decided).
fn midpoint_state(o: &Intervals<'_>, t: &Rat) -> State {
    let bits = DECISION_PRECISIONS[DECISION_PRECISIONS.len() - 1] + o.extra_bits;
    let tt = BigInterval::from_rat(t, bits);
    let (f, inv) = invariants_at(&o.a, &o.b, &o.span, &tt, bits);
    let sign = |x: &BigInterval| {
        let v = x.approx();
        if v > 0.0 {
            1
        } else if v < 0.0 {
            -1
        } else {
            0
        }
    };
    let mut s = SignData::from_invariants(&inv, &f, sign);
    if o.sr0_zero {
        s.sr0 = 0;
    }
    State::from(classify(&s))
}

impl Intervals<'_> {
    /// The contact geometry enclosed over the time enclosure `c` (the
    /// quantities `zeros` vanish there): the case from `sr11`'s enclosure
    /// (case (2b), certified only when `sr11` is known to vanish), then
    /// [`enclose`] at every precision.
    fn enclose_at(&self, zeros: &[Quantity], c: &Instant) -> Geometry {
        let (a, b) = self.scene;
        let goal = Goal::new(a, b, self.digits);
        let t = Interval::from_rat(&c.lo).hull(&Interval::from_rat(&c.hi));
        let (_, qa, qb) = ccd_enclosure::centred_quadrics(a, b, &self.span, &t, 53);
        let f = ccd_quadric::characteristic(&qa, &qb);
        let sr11_nonzero = closed_form(&f, Quantity::Sr11).is_some_and(|s| !s.contains_zero());
        let (case, proven) = if sr11_nonzero {
            (Case::Simple, true)
        } else {
            (Case::TwoDouble, zeros.contains(&Quantity::Sr11))
        };
        let certified = c.certified && proven;
        let all = &ccd_contact::PRECISIONS;
        enclose(
            (a, b, &self.span),
            (&c.lo, &c.hi),
            case,
            &goal,
            certified,
            all,
        )
        .unwrap_or_else(ccd_contact::failed)
    }
}

impl Oracle for Intervals<'_> {
    type Root = IntervalRoot;
    const PATH: Path = Path::Interval;
    const LEVELS: usize = 1 + DECISION_PRECISIONS.len();

    fn domain(&self) -> &[Rat; 2] {
        &self.span
    }

    fn time(&self, t: &Rat) -> Rat {
        t.clone()
    }

    fn signs<'a>(&'a self, at: At<'a, IntervalRoot>, level: usize) -> Box<dyn Signs + 'a> {
        let (lo, hi) = match at {
            At::Sample(t) => (t.clone(), t.clone()),
            At::Root(r) => (r.lo.clone(), r.hi.clone()),
        };
        Box::new(BoxSigns {
            oracle: self,
            lo,
            hi,
            level,
            readings: None,
        })
    }

    fn guess(&self, t: &Rat) -> State {
        midpoint_state(self, t)
    }

    /// `sr0`: proven zero by structure, or proven nonzero at a sample, or
    /// neither; `sr11` (asked only when `sr0 ≡ 0` is proven): proven
    /// nonzero at a sample, or undecided — `sr11 ≡ 0` is never assumed.
    fn vanishes(&mut self, q: Quantity) -> Vanishing {
        if q == Quantity::Sr0 && self.sr0_zero {
            return Vanishing::Identically;
        }
        match nonzero_somewhere(&self.problem(q), &self.span, self.extra_bits) {
            Some(t) => Vanishing::Not(Some(t)),
            None => Vanishing::Unknown,
        }
    }

    fn candidates(&self, q: Quantity, attempt: usize) -> Option<Candidates<'_, IntervalRoot>> {
        if attempt > 0 {
            return None;
        }
        let (t0, t1) = (&self.span[0], &self.span[1]);
        let dt = (t1 - t0).to_f64();
        let margin = dt * 2f64.powi(MARGIN_LOG2);
        let domain = Interval::new(
            Interval::from_rat(t0).lo - margin,
            Interval::from_rat(t1).hi + margin,
        );
        let limits = Limits {
            min_width: dt * 2f64.powi(MIN_WIDTH_LOG2),
            max_boxes: MAX_BOXES,
            pieces: 32,
        };
        let (all, _) = isolate(&self.problem(q), &domain, &limits);
        let mut all = all.into_iter();
        let mut roots = 0usize;
        let stream = std::iter::from_fn(move || loop {
            let f = all.next()?;
            if roots >= MAX_ROOTS && !matches!(f, Isolated::Undecided(_)) {
                // Budget of decided roots spent: the rest is one gap.
                let lo = ends_of(&f).map_or_else(|| t0.clone(), |(lo, _)| lo);
                let hi = all
                    .by_ref()
                    .last()
                    .and_then(|l| ends_of(&l).map(|(_, hi)| hi))
                    .or_else(|| ends_of(&f).map(|(_, hi)| hi))
                    .unwrap_or_else(|| t1.clone());
                return Some(Found::Gap {
                    lo,
                    hi,
                    reason: "effort budget of decided roots reached",
                });
            }
            if matches!(f, Isolated::Root(_)) {
                roots += 1;
            }
            if let Some(found) = self.found(f, Boxed::F64) {
                return Some(found);
            }
        });
        Some(Candidates {
            degree: None,
            roots: Box::new(stream),
        })
    }

    fn ends(&self, r: &IntervalRoot) -> (Rat, Rat) {
        (r.lo.clone(), r.hi.clone())
    }

    /// The cluster subdivided again in multi-precision, within the budget
    /// of all clusters (`MAX_CLUSTER_BOXES_TOTAL`).
    fn split(&self, r: &IntervalRoot, q: Quantity) -> Option<Vec<Found<IntervalRoot>>> {
        let left = self.cluster_boxes.get();
        if left == 0 {
            return None;
        }
        let dt = &self.span[1] - &self.span[0];
        let bits = CLUSTER_BITS + self.extra_bits;
        let cost = (bits.div_ceil(CLUSTER_BITS) as usize).pow(2);
        let bx = BigInterval::from_rat(&r.lo, bits).hull(&BigInterval::from_rat(&r.hi, bits));
        let limits = Limits {
            min_width: dt.to_f64() * 2f64.powi(-(CLUSTER_BITS as i32) + 24),
            max_boxes: MAX_CLUSTER_BOXES.min(left / cost).max(1),
            pieces: 2,
        };
        let (found, used) = isolate(&self.problem(q), &bx, &limits);
        self.cluster_boxes.set(left.saturating_sub(used * cost));
        Some(
            found
                .into_iter()
                .filter_map(|f| self.found(f, Boxed::Big))
                .collect(),
        )
    }

    /// Interval Newton in the box's precision, then in multi-precision at
    /// doubling bits while the enclosure is wider than the target.
    fn refine(&self, r: &mut IntervalRoot, q: Quantity) -> Instant {
        let p = self.problem(q);
        let width = self.width();
        let fine = match &r.boxed {
            Boxed::F64(x) => {
                let f = refine(&p, *x, &width);
                f.lo_rat().zip(f.hi_rat()).map(|e| (e, f.precision()))
            }
            Boxed::Big(x) => {
                let f = refine(&p, x.clone(), &width);
                let prec = f.precision();
                Some(((f.lo_rat(), f.hi_rat()), prec))
            }
        };
        if let Some(((mut lo, mut hi), prec)) = fine {
            let mut bits = self.refinement_bits().max(prec);
            while &hi - &lo > width && bits <= MAX_REFINEMENT_BITS + self.extra_bits {
                let start =
                    BigInterval::from_rat(&lo, bits).hull(&BigInterval::from_rat(&hi, bits));
                let big = refine(&p, start, &width);
                let w = width_rat(&big).unwrap_or_else(|| &hi - &lo);
                if w < &hi - &lo {
                    (lo, hi) = (big.lo_rat(), big.hi_rat());
                }
                bits *= 2;
            }
            (r.lo, r.hi) = (lo, hi);
        }
        Instant {
            lo: r.lo.clone(),
            hi: r.hi.clone(),
            certified: true,
        }
    }

    /// The contact's time enclosure as it stands, evaluated at increasing
    /// precision. Case (2a) is proven when `sr11` excludes 0 on the
    /// enclosure, case (2b) when the contacts are the roots of `sr11` with
    /// `sr0 ≡ 0` proven by structure; otherwise, and for an uncertified
    /// instant, the boxes are computed but marked `certified: false`.
    fn geometry(&self, _r: &mut IntervalRoot, zeros: &[Quantity], c: &Instant) -> Geometry {
        self.enclose_at(zeros, c)
    }

    /// At the point instant `t` (its time parameter is time itself).
    fn geometry_at(&self, t: &Rat, zeros: &[Quantity]) -> Geometry {
        self.enclose_at(zeros, &Instant::exact(t.clone()))
    }

    /// A sample is never at a candidate root; an enclosure that allows a
    /// touch there is reported as it is.
    fn touch_between_contacts(&self, _t: &Rat, d: Decided) -> Result<Decided, CcdError> {
        Ok(d)
    }

    fn settle(&self, items: Vec<Item>) -> Vec<Item> {
        settle_gaps(self, items)
    }

    fn stats(&self, _stats: &mut Stats) {}
}

/// Runs continuous collision detection for two bodies over `span` on the
/// interval path (any motion kinds, in particular `helical`): Algorithm 1
/// (`ccd_algorithm::run`) over [`Intervals`].
///
/// Contact instants come with exact rational enclosures, certified when
/// the root of `sr0` (or `sr11`) is proven simple and unique in its
/// enclosure by interval Newton and Theorem 3.10(2) is decided on the
/// enclosure; otherwise they are reported with `certified: false`. The
/// effort is bounded (the budgets of `docs/helical.md`): what is not decided
/// within it is an [`ccd_timeline::Gap`], filled where possible by sphere
/// certificates, and the outcome is then not `complete`; `collision_free`
/// is `true` only when separation over the whole span is proven, and
/// `Outcome::undecided` says why when neither separation nor a collision
/// is proven.
///
/// # Errors
///
/// [`CcdError::Motion`] when a rational motion degenerates on the span.
pub fn run(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    opts: &Options,
) -> Result<ccd_timeline::Outcome, CcdError> {
    ccd_algorithm::run(Intervals::new(a, b, span, opts)?, opts)
}

#[cfg(test)]
mod tests {
    use super::*;
    use ccd_motion::HelicalCenter;

    fn spinning(rate: Rat, frequency: Rat) -> Body {
        let z = || [Rat::zero(), Rat::zero(), Rat::zero()];
        Body {
            radii: [Rat::from(2), Rat::from(1), Rat::from(1)],
            motion: Motion::Helical {
                orientation: Motion::identity(),
                axis: [Rat::zero(), Rat::zero(), Rat::one()],
                rate,
                center: HelicalCenter {
                    base: z(),
                    velocity: z(),
                    cos: [Rat::one(), Rat::zero(), Rat::zero()],
                    sin: z(),
                    frequency,
                },
            },
        }
    }

    #[test]
    fn log2_bound_is_an_upper_bound() {
        for (p, q) in [
            (1i64, 1i64),
            (3, 2),
            (1, 3),
            (1000, 1),
            (1 << 40, 3),
            (7, 1 << 20),
        ] {
            let x = Rat::from_frac(p, q);
            assert!(2f64.powi(log2_bound(&x) as i32) >= x.to_f64(), "{x}");
        }
        assert_eq!(log2_bound(&Rat::zero()), 0);
    }

    #[test]
    fn angle_bits_follow_the_largest_angle() {
        let span = [Rat::zero(), Rat::from(2)];
        let still = Body {
            radii: [Rat::one(), Rat::one(), Rat::one()],
            motion: Motion::at_origin(),
        };
        let big = |k: u32| Rat::from_int(Int::pow10(k));
        // Small angles add nothing; 1e300·2 needs about 998 bits.
        assert_eq!(
            angle_bits([&spinning(Rat::from(3), Rat::zero()), &still], &span),
            0
        );
        let bits = angle_bits([&still, &spinning(big(300), Rat::zero())], &span);
        assert!((998..=1010).contains(&bits), "{bits}");
        let bits = angle_bits([&spinning(Rat::zero(), big(10)), &still], &span);
        assert!((35..=40).contains(&bits), "{bits}");
        assert_eq!(
            angle_bits([&spinning(big(4000), Rat::zero()), &still], &span),
            MAX_EXTRA_BITS
        );
    }
}
