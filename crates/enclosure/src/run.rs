//! Algorithm 1 of the paper (Section 5) on the interval path: candidate
//! instants from the certified isolation of `sr0(t)` (or of `sr11(t)` when
//! `sr0 ≡ 0`, Theorems 5.4–5.6), each decided by Theorem 3.10(2) on its
//! enclosure, and the state of every piece between contacts read at a
//! rational sample (Theorem 5.1).

use crate::dyadic::BigInterval;
use crate::error::EnclosureError;
use crate::isolate::{isolate, refine, width_rat, Found, Limits, Problem};
use crate::placement::{center_at, invariants_at};
use crate::real::Real;
use crate::signs::{Possible, Readings};
use crate::trig::Trig;
use ccd_arith::{Int, Interval, Rat, RingOps};
use ccd_classify::{classify, Configuration, SignData};
use ccd_motion::{Body, Motion, Quat};
use ccd_quadric::rotation_numerator;
use ccd_subres::Quantity;
use ccd_timeline::{Gap, Instant, Outcome, Segment, State, Stats, Witness};
use std::cell::Cell;

/// What a query asks for (the same fields as the exact path's options).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Options {
    /// Enclosures of contact instants get `hi − lo <= 10^(−digits)·(t1 − t0)`.
    pub digits: u32,
    /// Stop at the earliest instant at which the bodies are not separate.
    pub first_contact_only: bool,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            digits: 15,
            first_contact_only: false,
        }
    }
}

impl Options {
    /// Largest `digits` accepted.
    pub const MAX_DIGITS: u32 = 1000;
}

/// Precisions (bits) tried, in order, when an `f64` enclosure cannot decide
/// a configuration at a point or on a box — on top of [`Query::extra_bits`],
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
/// A cluster wider than `2^−16` of the span is not reported as one contact
/// candidate but as an undecided gap (its roots were not separated).
const CLUSTER_GAP_LOG2: i32 = -16;
/// Largest precision tried when refining a certified root.
const MAX_REFINEMENT_BITS: u32 = 1 << 15;
/// Effort budget of the sphere certificates in the gaps: boxes in all.
const MAX_SPHERE_BOXES: usize = 4_096;
/// Sphere-certificate boxes are not narrower than `2^−14` of their gap.
const SPHERE_MIN_WIDTH_LOG2: i64 = -14;
/// Effort budget: instants probed for a proven non-separate state inside
/// the gaps, in all.
const MAX_WITNESS_PROBES: usize = 16;
/// The angle's bits are capped here (an angle above `2^4096`, e.g. a rate
/// of `1e4000`, is evaluated with 4096 extra bits only: its `sin`/`cos`
/// stay wide and its pieces are decided by the sphere certificates or left
/// as gaps; multi-precision work at more bits grows too fast to stay within
/// seconds).
const MAX_EXTRA_BITS: u32 = 1 << 12;

/// What is known about `sr0 ≡ 0`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sr0 {
    /// `sr0` is not identically zero (proven at a sample).
    NotZero,
    /// `sr0 ≡ 0` by the structure of the scene (Note 2 of the paper, and its
    /// generalisation: the quadratic parts of `A(t)` and `B(t)` are
    /// proportional for all t, so `λA + B` drops rank by 2 at one λ).
    Proven,
    /// `sr0` encloses zero at every sample, even in multi-precision, and no
    /// structure proves `sr0 ≡ 0`: undecided. Nothing is assumed; the span
    /// is a gap (filled only by the sphere certificates).
    Undecided,
}

/// A contact candidate with its decision.
#[derive(Clone, Debug)]
struct Contact {
    lo: Rat,
    hi: Rat,
    certified: bool,
}

/// What the isolation leaves between the pieces of constant state: a
/// contact candidate, or a piece where the roots of the quantity were not
/// separated within the effort budget.
#[derive(Clone, Debug)]
enum Break {
    Contact(Contact),
    Gap(Rat, Rat, &'static str),
}

impl Break {
    fn lo(&self) -> &Rat {
        match self {
            Break::Contact(c) => &c.lo,
            Break::Gap(lo, _, _) => lo,
        }
    }
    fn hi(&self) -> &Rat {
        match self {
            Break::Contact(c) => &c.hi,
            Break::Gap(_, hi, _) => hi,
        }
    }
}

/// The configuration at one instant and whether it is proven.
#[derive(Clone, Copy, Debug)]
struct Decided {
    state: State,
    certified: bool,
}

/// One CCD query: bodies, span, the knowledge about `sr0`, the options and
/// what is left of the effort budget.
struct Query<'a> {
    a: &'a Body,
    b: &'a Body,
    span: &'a [Rat; 2],
    sr0: Sr0,
    options: &'a Options,
    /// Bits of the largest angle `|rate·t|`, `|frequency·t|` on the span,
    /// added to every multi-precision evaluation, so that `sin(1e300·t)`
    /// is enclosed tightly at a rational `t`.
    extra_bits: u32,
    /// Multi-precision cluster boxes left ([`MAX_CLUSTER_BOXES_TOTAL`]).
    cluster_boxes: Cell<usize>,
}

fn validate(a: &Body, b: &Body, span: &[Rat; 2], options: &Options) -> Result<(), EnclosureError> {
    if options.digits > Options::MAX_DIGITS {
        return Err(EnclosureError::Digits {
            max: Options::MAX_DIGITS,
            got: options.digits,
        });
    }
    if span[0] >= span[1] {
        return Err(EnclosureError::Span);
    }
    for (name, body) in [("a", a), ("b", b)] {
        if body.radii.iter().any(|r| r.signum() <= 0) {
            return Err(EnclosureError::Radius { body: name });
        }
        let zero_quat = |q: &Quat| q.iter().all(|x| x.signum() == 0);
        match &body.motion {
            Motion::Helical {
                orientation, axis, ..
            } => {
                if zero_quat(orientation) {
                    return Err(EnclosureError::Zero {
                        body: name,
                        field: "orientation",
                    });
                }
                if axis.iter().all(|x| x.signum() == 0) {
                    return Err(EnclosureError::Zero {
                        body: name,
                        field: "axis",
                    });
                }
            }
            Motion::Static { orientation, .. } | Motion::Translation { orientation, .. }
                if zero_quat(orientation) =>
            {
                return Err(EnclosureError::Zero {
                    body: name,
                    field: "orientation",
                });
            }
            other => {
                // The rational kinds are checked exactly (vanishing weights
                // or quaternion curves, singular affine maps).
                // (placing a body validates it; no matrix is formed).
                if !matches!(other, Motion::Static { .. }) {
                    ccd_motion::placed_quadric(body, span)
                        .map_err(|source| EnclosureError::Motion { body: name, source })?;
                }
            }
        }
    }
    Ok(())
}

/// The orientation quaternion of a body whose orientation never changes.
fn fixed_orientation(m: &Motion) -> Option<&Quat> {
    match m {
        Motion::Static { orientation, .. } | Motion::Translation { orientation, .. } => {
            Some(orientation)
        }
        Motion::Helical {
            orientation, rate, ..
        } if rate.signum() == 0 => Some(orientation),
        _ => None,
    }
}

/// `sr0 ≡ 0` by structure: the quadratic parts of `A(t)` and `B(t)` (the
/// upper-left 3×3 blocks, `R·diag(r⁻²)·Rᵀ` up to positive factors) are
/// proportional at every t — two spheres under rigid motions (Note 2), or
/// two ellipsoids with proportional radii and the same constant
/// orientation (as in Example 5.1). Then `λA + B` has a 3×3 block that
/// vanishes at one λ, so its rank drops by 2 there and `f` has a double
/// root for every t.
fn sr0_vanishes_by_structure(a: &Body, b: &Body) -> bool {
    let sphere = |x: &Body| {
        x.radii.iter().all(|r| *r == x.radii[0]) && !matches!(x.motion, Motion::Affine { .. })
    };
    if sphere(a) && sphere(b) {
        return true;
    }
    let proportional = |p: &[Rat], q: &[Rat]| {
        (0..p.len()).all(|i| (0..q.len()).all(|j| &p[i] * &q[j] == &p[j] * &q[i]))
    };
    match (fixed_orientation(&a.motion), fixed_orientation(&b.motion)) {
        (Some(qa), Some(qb)) => proportional(qa, qb) && proportional(&a.radii, &b.radii),
        _ => false,
    }
}

/// The body with its spin removed when the spin cannot move it: the helical
/// rotation `Rot(axis, θ)` leaves the quadric invariant for every θ exactly
/// when `Q = R₀·diag(r⁻²)·R₀ᵀ` (`R₀` the initial orientation) commutes with
/// the cross-product matrix `K = [axis]×` (then it commutes with
/// `Rot = I + sin θ·K/|a| + (1 − cos θ)·K²/|a|²`, and `R(t)·Q·R(t)ᵀ = Q`):
/// a sphere, or a spheroid spinning about its axis of symmetry. `A(t)`
/// depends on the rotation only through `R·diag(r⁻²)·Rᵀ`, so setting the
/// rate to 0 is an identity of the motion's symbolic form, checked in exact
/// rational arithmetic, not an approximation — and it takes the spin's
/// `sin`/`cos` out of every enclosure, whatever the rate.
pub fn without_invisible_spin(body: &Body) -> Body {
    let Motion::Helical {
        orientation,
        axis,
        rate,
        center,
    } = &body.motion
    else {
        return body.clone();
    };
    if rate.signum() == 0 {
        return body.clone();
    }
    let m = rotation_numerator(orientation);
    let inv2: [Rat; 3] = std::array::from_fn(|i| {
        let r2 = &body.radii[i] * &body.radii[i];
        r2.recip().unwrap_or_else(Rat::zero)
    });
    // Q = M·diag(r⁻²)·Mᵀ (a positive multiple of R₀·diag·R₀ᵀ).
    let q: [[Rat; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            (0..3).fold(Rat::zero(), |acc, k| {
                &acc + &(&(&m[i][k] * &inv2[k]) * &m[j][k])
            })
        })
    });
    let z = Rat::zero();
    let k: [[Rat; 3]; 3] = [
        [z.clone(), -&axis[2], axis[1].clone()],
        [axis[2].clone(), z.clone(), -&axis[0]],
        [-&axis[1], axis[0].clone(), z],
    ];
    let mul = |x: &[[Rat; 3]; 3], y: &[[Rat; 3]; 3]| -> [[Rat; 3]; 3] {
        std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..3).fold(Rat::zero(), |acc, l| &acc + &(&x[i][l] * &y[l][j]))
            })
        })
    };
    if mul(&q, &k) != mul(&k, &q) {
        return body.clone();
    }
    Body {
        radii: body.radii.clone(),
        motion: Motion::Helical {
            orientation: orientation.clone(),
            axis: axis.clone(),
            rate: Rat::zero(),
            center: center.clone(),
        },
    }
}

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

impl Query<'_> {
    fn problem(&self, target: Quantity) -> Problem<'_> {
        Problem {
            a: self.a,
            b: self.b,
            span: self.span,
            target,
        }
    }

    /// The readings of Theorem 3.10 over `t` (a point or a box), with the
    /// quantities in `zero` known to vanish there (and `sr0` when it is
    /// proven to vanish identically).
    fn readings<R: Real + Trig>(&self, t: &R, zero: &[Quantity]) -> Readings {
        let (f, inv) = invariants_at(self.a, self.b, self.span, t, t.precision());
        let mut r = Readings::of(&f, &inv);
        if self.sr0 == Sr0::Proven {
            r = r.with_zero(Quantity::Sr0);
        }
        for q in zero {
            r = r.with_zero(*q);
        }
        r
    }

    /// The possible configurations over `[lo, hi]`: `f64` first, then
    /// multi-precision (with the angle's bits on top) while undecided.
    fn possible(&self, lo: &Rat, hi: &Rat, zero: &[Quantity]) -> Possible {
        let box64 = Interval::from_rat(lo).hull(&Interval::from_rat(hi));
        let mut p = self.readings(&box64, zero).possible();
        for bits in DECISION_PRECISIONS {
            if p.single().is_some() {
                break;
            }
            let bits = bits + self.extra_bits;
            let bx = BigInterval::from_rat(lo, bits).hull(&BigInterval::from_rat(hi, bits));
            p = self.readings(&bx, zero).possible();
        }
        p
    }

    /// The configuration at the rational instant `t`: proven, or a best
    /// guess from the multi-precision midpoints marked uncertified.
    fn state_at(&self, t: &Rat) -> Decided {
        if let Some(c) = self.possible(t, t, &[]).single() {
            return Decided {
                state: State::from(c),
                certified: true,
            };
        }
        let bits = DECISION_PRECISIONS[DECISION_PRECISIONS.len() - 1] + self.extra_bits;
        let tt = BigInterval::from_rat(t, bits);
        let (f, inv) = invariants_at(self.a, self.b, self.span, &tt, bits);
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
        if self.sr0 == Sr0::Proven {
            s.sr0 = 0;
        }
        Decided {
            state: State::from(classify(&s)),
            certified: false,
        }
    }

    /// Bits for refining an enclosure to `target` on this span.
    fn refinement_bits(&self) -> u32 {
        let dt = (&self.span[1] - &self.span[0]).to_f64();
        let scale = self.span[0]
            .to_f64()
            .abs()
            .max(self.span[1].to_f64().abs())
            .max(dt);
        let ratio = (scale / dt).log2().max(0.0);
        (self.options.digits as f64 * std::f64::consts::LOG2_10 + ratio + 96.0).ceil() as u32
            + self.extra_bits
    }

    /// A certified simple root of `target` in the box `x`: decided (touch
    /// or not) and, when it may be a touch, refined to `width` (escalating
    /// to multi-precision when `x`'s arithmetic cannot get there).
    fn root_contact<R: Real + Trig>(&self, target: Quantity, x: R, width: &Rat) -> Option<Contact> {
        let zero = [target];
        let (lo, hi) = (x.lo_rat()?, x.hi_rat()?);
        if !self.possible(&lo, &hi, &zero).touch {
            return None;
        }
        let p = self.problem(target);
        let fine = refine(&p, x, width);
        let (mut lo, mut hi) = (fine.lo_rat()?, fine.hi_rat()?);
        let mut bits = self.refinement_bits().max(fine.precision());
        while &(&hi - &lo) > width && bits <= MAX_REFINEMENT_BITS + self.extra_bits {
            let start = BigInterval::from_rat(&lo, bits).hull(&BigInterval::from_rat(&hi, bits));
            let big = refine(&p, start, width);
            let w = width_rat(&big).unwrap_or_else(|| &hi - &lo);
            if w < &hi - &lo {
                (lo, hi) = (big.lo_rat(), big.hi_rat());
            }
            bits *= 2;
        }
        let decided = self.possible(&lo, &hi, &zero);
        decided.touch.then(|| Contact {
            certified: decided.single() == Some(Configuration::ExternalTouch),
            lo,
            hi,
        })
    }

    /// The breaks among what subdivision found: certified roots are decided
    /// and refined; a cluster that is consistent with a touch is subdivided
    /// again in multi-precision (when `escalate` and the budget allows), and
    /// what still cannot be proven is reported uncertified — as one contact
    /// candidate when narrow, as a gap when wider than `2^−16` of the span;
    /// unexamined boxes are gaps.
    fn examine<R: Real + Trig>(
        &self,
        target: Quantity,
        found: Found<R>,
        width: &Rat,
        escalate: bool,
        out: &mut Vec<Break>,
    ) {
        let ends = |x: &R| Some((x.lo_rat()?, x.hi_rat()?));
        let dt = &self.span[1] - &self.span[0];
        match found {
            Found::Root(x) => out.extend(self.root_contact(target, x, width).map(Break::Contact)),
            Found::Undecided(x) => {
                let (lo, hi) =
                    ends(&x).unwrap_or_else(|| (self.span[0].clone(), self.span[1].clone()));
                out.push(Break::Gap(
                    lo,
                    hi,
                    "effort budget reached before the roots were isolated",
                ));
            }
            Found::Cluster(x) => {
                let Some((lo, hi)) = ends(&x) else {
                    out.push(Break::Gap(
                        self.span[0].clone(),
                        self.span[1].clone(),
                        "enclosures unbounded",
                    ));
                    return;
                };
                if !self.possible(&lo, &hi, &[target]).touch {
                    // No touch is possible anywhere in it: no state change.
                    return;
                }
                let left = self.cluster_boxes.get();
                if !escalate || left == 0 {
                    if &hi - &lo > dt.mul_pow2(i64::from(CLUSTER_GAP_LOG2)) {
                        out.push(Break::Gap(lo, hi, "roots not separated (cluster)"));
                    } else {
                        out.push(Break::Contact(Contact {
                            lo,
                            hi,
                            certified: false,
                        }));
                    }
                    return;
                }
                let bits = CLUSTER_BITS + self.extra_bits;
                let cost = (bits.div_ceil(CLUSTER_BITS) as usize).pow(2);
                let bx = BigInterval::from_rat(&lo, bits).hull(&BigInterval::from_rat(&hi, bits));
                let limits = Limits {
                    min_width: dt.to_f64() * 2f64.powi(-(CLUSTER_BITS as i32) + 24),
                    max_boxes: MAX_CLUSTER_BOXES.min(left / cost).max(1),
                    pieces: 2,
                };
                let (found, used) = isolate(&self.problem(target), &bx, &limits);
                self.cluster_boxes.set(left.saturating_sub(used * cost));
                for f in found {
                    self.examine(target, f, width, false, out);
                }
            }
        }
    }

    /// Contacts and gaps from the roots of `target` in the span, in order
    /// (disjoint, clipped to the span; adjacent gaps merged).
    fn breaks(&self, target: Quantity, stats: &mut Stats) -> Vec<Break> {
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
        let width = &(t1 - t0) / &Rat::from_int(Int::pow10(self.options.digits));
        let mut out: Vec<Break> = Vec::new();
        let (all, _) = isolate(&self.problem(target), &domain, &limits);
        let mut roots = 0usize;
        let mut found = all.into_iter();
        while let Some(f) = found.next() {
            stats.candidates += 1;
            let mut here = Vec::new();
            if roots >= MAX_ROOTS && !matches!(f, Found::Undecided(_)) {
                // Budget of decided roots spent: the rest is one gap.
                let lo = ends_of(&f).map_or_else(|| t0.clone(), |(lo, _)| lo);
                let hi = found
                    .by_ref()
                    .last()
                    .and_then(|l| ends_of(&l).map(|(_, hi)| hi))
                    .or_else(|| ends_of(&f).map(|(_, hi)| hi))
                    .unwrap_or_else(|| t1.clone());
                here.push(Break::Gap(lo, hi, "effort budget of decided roots reached"));
            } else {
                if matches!(f, Found::Root(_)) {
                    roots += 1;
                }
                self.examine(target, f, &width, true, &mut here);
            }
            for mut c in here {
                // Clip to the span; an enclosure reaching past an end may
                // hold a root outside the span, so it is no longer certified.
                if c.hi() < t0 || c.lo() > t1 {
                    continue;
                }
                match &mut c {
                    Break::Contact(c) => {
                        if &c.lo < t0 {
                            c.lo = t0.clone();
                            c.certified = false;
                        }
                        if &c.hi > t1 {
                            c.hi = t1.clone();
                            c.certified = false;
                        }
                    }
                    Break::Gap(lo, hi, _) => {
                        if &*lo < t0 {
                            *lo = t0.clone();
                        }
                        if &*hi > t1 {
                            *hi = t1.clone();
                        }
                    }
                }
                match (out.last_mut(), c) {
                    (Some(Break::Gap(_, hi, _)), Break::Gap(lo2, hi2, _)) if lo2 <= *hi => {
                        if hi2 > *hi {
                            *hi = hi2;
                        }
                    }
                    (_, c) => out.push(c),
                }
            }
            if self.options.first_contact_only && !out.is_empty() {
                out.truncate(1);
                break;
            }
        }
        out
    }
}

/// The exact ends of a found box.
fn ends_of<R: Real>(f: &Found<R>) -> Option<(Rat, Rat)> {
    let x = match f {
        Found::Root(x) | Found::Cluster(x) | Found::Undecided(x) => x,
    };
    Some((x.lo_rat()?, x.hi_rat()?))
}

/// A rational strictly inside `(lo, hi)` with a small denominator.
fn sample_between(lo: &Rat, hi: &Rat) -> Rat {
    let quarter = (hi - lo).mul_pow2(-2);
    Rat::simplest_in(&(lo + &quarter), &(hi - &quarter))
}

fn instant(lo: Rat, hi: Rat, certified: bool) -> Instant {
    Instant { lo, hi, certified }
}

/// One entry of the timeline under construction, in time order.
#[derive(Clone, Debug)]
enum Item {
    Segment(Segment),
    Gap(Gap),
}

/// Separation or overlap proven from the centres alone, whatever the
/// orientations: each body lies in the ball of radius `max rᵢ` about its
/// centre and contains the ball of radius `min rᵢ`, so
/// `|c_a − c_b| > max r(a) + max r(b)` proves *separate* and
/// `|c_a − c_b| < max(min r(a), min r(b))` (one centre inside the other
/// body) proves *overlap*. The distance is enclosed over a box of times
/// (`f64` intervals, outward rounded); `None` when neither is proven (or a
/// body is affine).
fn sphere_state(a: &Body, b: &Body, span: &[Rat; 2], lo: &Rat, hi: &Rat) -> Option<State> {
    let t = Interval::from_rat(lo).hull(&Interval::from_rat(hi));
    let (ca, cb) = (center_at(a, span, &t)?, center_at(b, span, &t)?);
    let d2 = (0..3).fold(Interval::point(0.0), |acc, i| {
        acc.plus(&ca[i].minus(&cb[i]).square())
    });
    let max = |b: &Body| b.radii.iter().max().cloned().unwrap_or_else(Rat::zero);
    let min = |b: &Body| b.radii.iter().min().cloned().unwrap_or_else(Rat::zero);
    let outer = &max(a) + &max(b);
    let inner = min(a).max(min(b));
    if d2.lo > Interval::from_rat(&(&outer * &outer)).hi {
        Some(State::Separate)
    } else if d2.hi < Interval::from_rat(&(&inner * &inner)).lo {
        Some(State::Overlap)
    } else {
        None
    }
}

/// A gap cut into pieces proven by [`sphere_state`] (by bisection within
/// the budget) and the pieces left undecided, in order, adjacent pieces of
/// one kind merged.
fn sphere_pieces(
    q: &Query<'_>,
    lo: &Rat,
    hi: &Rat,
    budget: &mut usize,
) -> Vec<(Rat, Rat, Option<State>)> {
    let min_width = (hi - lo).mul_pow2(SPHERE_MIN_WIDTH_LOG2);
    let mut out: Vec<(Rat, Rat, Option<State>)> = Vec::new();
    let mut stack = vec![(lo.clone(), hi.clone())];
    let point = |t: &Rat| sphere_state(q.a, q.b, q.span, t, t).is_some();
    while let Some((l, h)) = stack.pop() {
        let state = if *budget > 0 {
            *budget -= 1;
            sphere_state(q.a, q.b, q.span, &l, &h)
        } else {
            None
        };
        // Bisect only where something is provable at a point of the box
        // (an end or the midpoint): the effort goes to the boundaries of
        // the provable pieces, not into stretches where nothing is.
        let m = Rat::midpoint(&l, &h);
        let promising = || point(&l) || point(&m) || point(&h);
        if state.is_none() && *budget > 0 && &h - &l > min_width && promising() {
            stack.push((m.clone(), h));
            stack.push((l, m));
            continue;
        }
        match out.last_mut() {
            Some((_, end, s)) if *s == state && *end == l => *end = h,
            _ => out.push((l, h, state)),
        }
    }
    out
}

/// The state of a piece `(lo, hi)` between breakpoints, read at a sample
/// inside (Theorem 5.1: no root of the isolated quantity lies in it).
fn piece(q: &Query<'_>, start: Instant, end: Instant) -> Segment {
    let d = q.state_at(&sample_between(&start.hi, &end.lo));
    Segment {
        state: d.state,
        start,
        end,
        certified: d.certified,
    }
}

/// Fills the gaps with what the sphere certificates prove, probes the
/// remaining gaps for a proven non-separate instant (a witness), and merges
/// neighbouring segments of one state.
fn settle_gaps(q: &Query<'_>, items: Vec<Item>) -> Vec<Item> {
    let mut sphere_budget = MAX_SPHERE_BOXES;
    let mut probes = MAX_WITNESS_PROBES;
    let mut out: Vec<Item> = Vec::new();
    let push = |out: &mut Vec<Item>, item: Item| {
        if let (Some(Item::Segment(prev)), Item::Segment(next)) = (out.last_mut(), &item) {
            let long = |s: &Segment| s.start != s.end;
            if long(prev) && long(next) && prev.state == next.state && prev.end == next.start {
                prev.end = next.end.clone();
                prev.certified &= next.certified;
                return;
            }
        }
        out.push(item);
    };
    for item in items {
        let Item::Gap(g) = item else {
            push(&mut out, item);
            continue;
        };
        for (lo, hi, state) in sphere_pieces(q, &g.lo, &g.hi, &mut sphere_budget) {
            match state {
                Some(state) => push(
                    &mut out,
                    Item::Segment(Segment {
                        state,
                        start: Instant::exact(lo),
                        end: Instant::exact(hi),
                        certified: true,
                    }),
                ),
                None => {
                    let mut witness = None;
                    if probes > 0 {
                        probes -= 1;
                        let t = sample_between(&lo, &hi);
                        let d = q.state_at(&t);
                        if d.certified && d.state != State::Separate {
                            witness = Some(Witness { t, state: d.state });
                        }
                    }
                    push(
                        &mut out,
                        Item::Gap(Gap {
                            lo,
                            hi,
                            reason: g.reason.clone(),
                            witness,
                        }),
                    );
                }
            }
        }
    }
    out
}

/// Runs continuous collision detection for two bodies over `span` on the
/// interval path (any motion kinds, in particular `helical`).
///
/// Contact instants come with exact rational enclosures, certified when
/// the root of `sr0` (or `sr11`) is proven simple and unique in its
/// enclosure by interval Newton and Theorem 3.10(2) is decided on the
/// enclosure; otherwise they are reported with `certified: false`. The
/// effort is bounded (the budgets of `docs/helical.md`): what is not decided
/// within it is an [`ccd_timeline::Gap`], filled where possible by sphere
/// certificates, and the outcome is then not `complete`; `collision_free`
/// is `true` only when separation over the whole span is proven, and
/// [`Outcome::undecided`] says why when neither separation nor a collision
/// is proven.
pub fn run(
    a: &Body,
    b: &Body,
    span: &[Rat; 2],
    options: &Options,
) -> Result<Outcome, EnclosureError> {
    validate(a, b, span, options)?;
    let (a, b) = (&without_invisible_spin(a), &without_invisible_spin(b));
    let (t0, t1) = (span[0].clone(), span[1].clone());
    let mut stats = Stats::default();
    let extra_bits = angle_bits([a, b], span);
    let sr0 = if sr0_vanishes_by_structure(a, b) {
        Sr0::Proven
    } else {
        let p = Problem {
            a,
            b,
            span,
            target: Quantity::Sr0,
        };
        match nonzero_somewhere(&p, span, extra_bits) {
            Some(_) => Sr0::NotZero,
            None => Sr0::Undecided,
        }
    };
    let q = Query {
        a,
        b,
        span,
        sr0,
        options,
        extra_bits,
        cluster_boxes: Cell::new(MAX_CLUSTER_BOXES_TOTAL),
    };
    let first_only = options.first_contact_only;
    let start0 = q.state_at(&t0);

    // The whole span in one state (Theorem 5.5), or the breaks.
    let mut throughout: Option<Decided> = None;
    let mut breaks: Vec<Break> = Vec::new();
    let stop_early = first_only && start0.state != State::Separate;
    let whole = |why: &'static str| vec![Break::Gap(t0.clone(), t1.clone(), why)];
    match sr0 {
        Sr0::NotZero => {
            stats.branch = "interval: sr0";
            if !stop_early {
                breaks = q.breaks(Quantity::Sr0, &mut stats);
            }
        }
        Sr0::Undecided => {
            stats.branch = "interval: sr0 undecided";
            if !stop_early {
                breaks = whole("sr0 neither proven nonzero at a sample nor identically zero");
            }
        }
        Sr0::Proven => {
            stats.branch = "interval: sr0 = 0 (structure), sr11";
            match nonzero_somewhere(&q.problem(Quantity::Sr11), span, extra_bits) {
                Some(delta) => {
                    // Theorem 5.5: touching at one non-root of sr11 means
                    // touching throughout.
                    let at = q.state_at(&delta);
                    if at.state == State::Touch {
                        throughout = Some(at);
                    } else if !stop_early {
                        breaks = q.breaks(Quantity::Sr11, &mut stats);
                    }
                }
                None => {
                    // Theorem 5.6 would need sr11 ≡ 0, which is only
                    // observed here: nothing is assumed.
                    stats.branch = "interval: sr0 = 0 (structure), sr11 undecided";
                    if !stop_early {
                        breaks =
                            whole("sr11 neither proven nonzero at a sample nor identically zero");
                    }
                }
            }
        }
    }

    let start = instant(t0.clone(), t0.clone(), start0.certified);
    let mut items: Vec<Item> = Vec::new();
    if let Some(d) = throughout {
        items.push(Item::Segment(Segment {
            state: d.state,
            start: Instant::exact(t0.clone()),
            end: Instant::exact(t1.clone()),
            certified: d.certified,
        }));
    } else if stop_early {
        items.push(Item::Segment(Segment {
            state: start0.state,
            start: start.clone(),
            end: start.clone(),
            certified: start0.certified,
        }));
    } else {
        // Breakpoints t0, the breaks, t1 (a break reaching an end replaces
        // it); a first-contact query stops at its first break.
        let mut prev: Option<Instant> =
            (breaks.first().is_none_or(|c| c.lo() > &t0)).then(|| Instant::exact(t0.clone()));
        for br in &breaks {
            let (entry, exit) = match br {
                Break::Contact(c) => {
                    let i = instant(c.lo.clone(), c.hi.clone(), c.certified);
                    (i.clone(), i)
                }
                Break::Gap(lo, hi, _) => (Instant::exact(lo.clone()), Instant::exact(hi.clone())),
            };
            if let Some(p) = prev.take() {
                if p.hi < entry.lo {
                    items.push(Item::Segment(piece(&q, p, entry.clone())));
                }
            }
            match br {
                Break::Contact(_) => items.push(Item::Segment(Segment {
                    state: State::Touch,
                    start: entry.clone(),
                    end: entry,
                    certified: exit.certified,
                })),
                Break::Gap(lo, hi, why) => items.push(Item::Gap(Gap {
                    lo: lo.clone(),
                    hi: hi.clone(),
                    reason: (*why).to_string(),
                    witness: None,
                })),
            }
            prev = Some(exit);
        }
        let reached_end = !first_only || breaks.is_empty();
        if let (Some(p), true) = (prev, reached_end) {
            if p.hi < t1 {
                items.push(Item::Segment(piece(&q, p, Instant::exact(t1.clone()))));
            }
        }
    }
    let items = settle_gaps(&q, items);

    let mut timeline: Vec<Segment> = Vec::new();
    let mut gaps: Vec<Gap> = Vec::new();
    let mut first_contact: Option<Instant> = None;
    let mut clean = true; // everything so far proven separate
    for item in items {
        match item {
            Item::Segment(s) => {
                if first_contact.is_none() && s.state != State::Separate {
                    first_contact = Some(Instant {
                        certified: clean && s.certified && s.start.certified,
                        ..s.start.clone()
                    });
                }
                clean &= s.certified;
                timeline.push(s);
            }
            Item::Gap(g) => {
                if let (None, Some(w)) = (&first_contact, &g.witness) {
                    first_contact = Some(instant(g.lo.clone(), w.t.clone(), false));
                }
                clean = false;
                gaps.push(g);
            }
        }
    }
    let contacts: Vec<Instant> = timeline
        .iter()
        .filter(|s| {
            s.start == s.end && s.state == State::Touch && !(stop_early && s.start.lo == t0)
        })
        .map(|s| s.start.clone())
        .collect();
    let covered_to_end = timeline.last().is_some_and(|s| s.end.hi == t1);
    // Complete exactly when the timeline tiles [t0, t1] (a first-contact
    // query stops at its first break, short of t1 unless its gap was filled).
    let complete = gaps.is_empty() && covered_to_end && !stop_early;
    let separation = complete
        && timeline
            .iter()
            .all(|s| s.certified && s.state == State::Separate);
    let collision = timeline
        .iter()
        .any(|s| s.certified && s.state != State::Separate)
        || gaps.iter().any(|g| g.witness.is_some());
    let undecided = (!separation && !collision).then(|| {
        let mut why: Vec<String> = Vec::new();
        if !gaps.is_empty() {
            why.push(format!(
                "{} piece(s) of the span undecided (see gaps)",
                gaps.len()
            ));
        }
        if timeline.iter().any(|s| !s.certified) {
            why.push("the state of a segment or a contact candidate is not proven".into());
        }
        if why.is_empty() {
            why.push("the timeline stops before t1".into());
        }
        why.join("; ")
    });
    Ok(Outcome {
        span: span.clone(),
        collision_free: separation,
        undecided,
        first_contact,
        contacts,
        timeline,
        gaps,
        complete,
        stats,
        geometry: Vec::new(),
    })
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
