//! Certified contact of two ellipsoids that translate along straight lines,
//! without forming `f(λ; t)`: a ray cast into their Minkowski difference.
//!
//! When neither body turns and each centre moves along a straight line at
//! constant speed (`static`, or a `translation` of degree ≤ 1 without
//! weights), the bodies meet exactly when the ray
//! `c(u) = b(u) − a(u) = c₀ + u·v` lies in the convex body
//! `K = A₀ ⊕ (−B₀)` ([`mod@line`]). Then:
//!
//! * the bodies are **apart over the whole span** when one plane
//!   `n·x = h_K(n)` has the ray's two ends strictly beyond it
//!   ([`verify::apart`]);
//! * the ray **enters** `K` at `u_in = φ(n*)`, the value of
//!   `φ(n) = (h_K(n) − n·c₀)/(n·v)` at its stationary normal with `n·v < 0`,
//!   and **leaves** it at `u_out = φ(n*)` for the one with `n·v > 0`
//!   ([`support`]): for `u < u_in` (and `u > u_out`) the plane of `n*` keeps
//!   the ray outside `K`, at `u_in` it touches `∂K`, and between the two the
//!   chord of the strictly convex `K` is in its interior. So the bodies are
//!   separate before `u_in`, touch externally at `u_in` (a point of both
//!   surfaces, interiors disjoint, since `int K = int A₀ ⊕ (−int B₀)`),
//!   overlap on `(u_in, u_out)`, touch at `u_out`, and are separate after.
//!
//! The normals are found in `f64` ([`search`]: an outer ellipsoid of `K`,
//! then Newton's method) and proven in outward-rounded intervals
//! ([`verify`]: the plane test, and a Krawczyk test that encloses `n*`,
//! hence the instant and the contact point `a(u*) + ∇h_A(n*)` whose
//! outward normal is `n*`). Every state and instant of the result is
//! proven; the instants are intervals with `f64` (dyadic) ends.
//!
//! [`run`] answers only what it proves to the query's widths (instants
//! within `10^(−digits)` of the span, the contact geometry within
//! [`ccd_contact::Goal`]) and returns `None` otherwise — another motion
//! kind, a ray that grazes `K` (entry and exit not separated, for the
//! whole timeline; a first contact needs only its entry), a crossing
//! at `t0` or `t1` or before it (except a first contact whose ray entered
//! `K` before the span and is proven still inside at `t0`: an overlap at
//! `t0`, the first contact `t0` itself), bodies at rest relative to each
//! other, a width its enclosures do not reach (`--digits` beyond about 15
//! unless the instants happen to be that narrow): the caller then runs
//! Algorithm 1.
//!
//! ```
//! use ccd_scene::Scene;
//! let scene = Scene::from_toml(r#"
//!     format = 1
//!     span = ["0", "1"]
//!     [a]
//!     radii = ["1", "1", "1"]
//!     [b]
//!     radii = ["2", "2", "2"]
//!     [b.motion]
//!     kind = "translation"
//!     center = [["-10", "1", "0"], ["10", "1", "0"]]
//! "#).unwrap();
//! let options = ccd_algorithm::Options::default();
//! let out = ccd_raycast::run(&scene, &options).expect("a clean crossing");
//! // K is the ball of radius 3: the ray (−10 + 20u, 1, 0) enters at u = (10 − √8)/20.
//! let first = out.first_contact.expect("they collide");
//! let t = (10.0 - 8f64.sqrt()) / 20.0;
//! assert!(first.lo.to_f64() <= t && t <= first.hi.to_f64());
//! assert_eq!(out.contacts.len(), 2);
//! ```

pub mod line;
pub mod scalar;
pub mod search;
pub mod support;
pub mod verify;

use ccd_algorithm::{time_on, Options};
use ccd_arith::{DwBall, Interval, Rat};
use ccd_contact::Goal;
use ccd_scene::Scene;
use ccd_timeline::{Box3, Geometry, Instant, Outcome, Path, Segment, State, Stats};
use line::{Line, Pair};
use search::Guess;
use std::cell::OnceCell;
use verify::Crossing;

/// The proven timeline of a pair that translates along straight lines,
/// or `None` where the ray cast does not prove everything the query asks
/// for (module docs), or when the scene is not valid
/// ([`Scene::validate`]).
pub fn run(scene: &Scene, options: &Options) -> Option<Outcome> {
    // `ccd_exact::run` has validated it; a direct caller may not have.
    scene.validate().ok()?;
    // The search runs on f64 values of the scene's numbers; the proofs on
    // f64 intervals (for most planes) and double words (for crossings and
    // near misses), each set up only when first needed, the intervals from
    // the double words when those exist (about 2K instructions instead of
    // 20K).
    let (a, b) = (&scene.a, &scene.b);
    let pair = Pair::of(a, b)?;
    let f = Line::<f64>::of(&pair)?.unit_sized();
    let fine_cell = OnceCell::new();
    let fine = || fine_cell.get_or_init(|| Line::<DwBall>::of(&pair)).as_ref();
    let line_cell = OnceCell::new();
    let line = || {
        line_cell
            .get_or_init(|| match fine_cell.get() {
                Some(Some(fine)) => Some(fine.enclosed()),
                _ => Line::<Interval>::of(&pair),
            })
            .as_ref()
    };
    let apart = || Some(Answer::Apart.outcome(scene, options));
    // A plane in f64 intervals, else (a near miss) in double words, as
    // found or made exactly parallel to the ray.
    let separates = |planes: &[Option<[f64; 3]>]| {
        let planes = || planes.iter().flatten();
        line().is_some_and(|line| planes().any(|n| verify::apart(line, n)))
            || fine().is_some_and(|fine| {
                planes().any(|n| verify::apart(fine, n) || verify::apart_parallel(fine, n))
            })
    };
    let (entry, exit) = match search::guess(&f)? {
        Guess::Misses(n) => {
            return if separates(&[Some(n), search::parallel(&f, &n)]) {
                apart()
            } else {
                None
            };
        }
        Guess::Crosses { entry, exit } => (entry, exit),
    };
    // The search leaving the side it started on signals a near miss, where
    // the two normals turn towards the plane parallel to the ray.
    let near_miss = |a: [f64; 3], b: [f64; 3]| {
        let plane = search::parallel(&f, &std::array::from_fn(|i| a[i] + b[i]));
        if separates(&[plane]) {
            apart()
        } else {
            None
        }
    };
    // The exit normal (or, when its search left its side, its guess) is
    // polished only when needed: a first contact proven inside the span
    // does not need it.
    let exit_guess = exit;
    let exit_cell = OnceCell::new();
    let exit = || *exit_cell.get_or_init(|| search::polish(&f, &exit, 1.0).ok_or(exit));
    // An entry that does not polish signals a near miss; its plane starts
    // from the two unpolished guesses. Polishing the exit there (40 `f64`
    // Newton steps) fails as a rule and gives back the same guess; either
    // start only seeds `search::parallel`, whose plane `verify` proves.
    let entry = match search::polished(&f, &entry, -1.0) {
        Some(p) => p,
        None => return near_miss(entry, exit_guess),
    };
    // The whole timeline needs the exit; a first contact only when the
    // entry stopped at the noise floor (a graze or a near miss), where an
    // exit that does not polish shows a near miss before the entry's
    // proof, which there fails only after all its double-word steps.
    if !options.first_contact_only || !entry.converged {
        if let Err(b) = exit() {
            return near_miss(entry.normal, b);
        }
    }
    let entry = entry.normal;
    // A crossing of the line: the double words first (the crossing's
    // proof needs them), then the intervals from them.
    // The proof of the entry comes first: for a crossing inside the span
    // (the usual case) the planes of the two normals cannot separate, and
    // testing them first cost 7.6K instructions. For an entry after the
    // span the ray is outside K for every u < u_in; otherwise (the proof
    // failed, or the line crosses K before the span) a near miss or the
    // planes decide.
    let fine = fine()?;
    let line = line()?;
    let system = verify::System::new(line, fine);
    let crossing = |n: &[f64; 3], side| system.as_ref()?.crossing(n, side);
    // A first contact whose ray entered `K` before the span and leaves it
    // after `u = 0` (both crossings proven) overlaps at `t0`: its first
    // contact is `t0` itself.
    let overlaps_at_start = || {
        let exit = exit().ok()?;
        crossing(&exit, 1.0).filter(|out| out.u.lo > 0.0)
    };
    let inn = match crossing(&entry, -1.0) {
        Some(inn) if inn.u.lo > 0.0 && inn.u.hi < 1.0 => inn,
        Some(inn) if inn.u.lo > 1.0 => return apart(),
        Some(inn)
            if options.first_contact_only && inn.u.hi < 0.0 && overlaps_at_start().is_some() =>
        {
            return Some(Answer::OverlapsAtStart.outcome(scene, options));
        }
        _ => {
            return match exit() {
                Err(b) => near_miss(entry, b),
                Ok(exit) if [entry, exit].iter().any(|n| verify::apart(line, n)) => apart(),
                Ok(_) => None,
            }
        }
    };
    let out = if options.first_contact_only {
        None
    } else {
        let out = crossing(&exit().ok()?, 1.0)?;
        if !(out.u.lo > inn.u.hi && (out.u.hi < 1.0 || out.u.lo > 1.0)) {
            return None;
        }
        (out.u.hi < 1.0).then_some(out)
    };
    let inn = contact(&inn, &scene.span, line, options)?;
    let out = match out {
        Some(out) => Some(contact(&out, &scene.span, line, options)?),
        None => None,
    };
    Some(Answer::Crosses(inn, out).outcome(scene, options))
}

/// What the proofs found on the span `u ∈ [0, 1]` (one per query, on
/// the stack: the size of its large variant costs nothing).
#[allow(clippy::large_enum_variant)]
enum Answer {
    /// Separate throughout.
    Apart,
    /// Entering at the first contact, inside `(0, 1)`; leaving at the
    /// second when it is inside `(0, 1)` and asked for, otherwise still
    /// overlapping at `u = 1` (or not asked: a first-contact query).
    Crosses(Contact, Option<Contact>),
    /// Overlapping at `u = 0`: the first contact is `t0` (a first-contact
    /// query, which stops there).
    OverlapsAtStart,
}

/// A proven crossing in the contract's terms: its instant in time and,
/// when asked for, its point and normal.
struct Contact {
    instant: Instant,
    geometry: Option<Geometry>,
}

/// `x` as the exact dyadic rational it is.
fn exact(x: f64) -> Option<Rat> {
    Rat::from_f64_exact(x)
}

fn box3(x: &[Interval; 3]) -> Option<Box3> {
    Some(Box3 {
        lo: [exact(x[0].lo)?, exact(x[1].lo)?, exact(x[2].lo)?],
        hi: [exact(x[0].hi)?, exact(x[1].hi)?, exact(x[2].hi)?],
    })
}

/// The contact point and `A`'s outward normal scaled so that its largest
/// component is exactly `±1` (`None` unless that component is proven the
/// largest), as intervals.
fn geometry(c: &Crossing) -> Option<[[Interval; 3]; 2]> {
    let mag = |x: &Interval| x.lo.abs().max(x.hi.abs());
    let mig = |x: &Interval| {
        if x.contains_zero() {
            0.0
        } else {
            x.lo.abs().min(x.hi.abs())
        }
    };
    let k = (0..3).find(|&k| (0..3).all(|j| j == k || mig(&c.normal[k]) > mag(&c.normal[j])))?;
    let sign = c.normal[k].sign()?;
    let size = if sign > 0 { c.normal[k] } else { -c.normal[k] };
    let normal = std::array::from_fn(|j| {
        if j == k {
            Interval::point(f64::from(sign))
        } else {
            let q = c.normal[j] / size;
            Interval::new(q.lo.max(-1.0), q.hi.min(1.0))
        }
    });
    Some([c.point, normal])
}

/// The widest of three intervals (rounded up).
fn widest(x: &[Interval; 3]) -> f64 {
    x.iter().map(Interval::width).fold(0.0, f64::max)
}

/// The crossing `c` as a [`Contact`] in time, or `None` unless its instant
/// is within `10^(−digits)` of the span and (when asked for) its geometry
/// within [`Goal::floors`].
fn contact(
    c: &Crossing,
    span: &[Rat; 2],
    line: &Line<Interval>,
    options: &Options,
) -> Option<Contact> {
    let tol = 10f64.powi(-(options.digits.min(400) as i32)) * (1.0 - 1e-9);
    if !c.u.is_finite() || c.u.width() > tol {
        return None;
    }
    let instant = Instant {
        lo: time_on(span, &exact(c.u.lo)?),
        hi: time_on(span, &exact(c.u.hi)?),
        certified: true,
    };
    let geometry = if options.contact_geometry {
        let [largest, smallest] = line.radii;
        let [point_floor, normal_floor] = Goal::floors(largest, smallest, options.digits);
        let [point, normal] = geometry(c)?;
        if !(widest(&point) <= point_floor && widest(&normal) <= normal_floor) {
            return None;
        }
        Some(Geometry::Point {
            point: box3(&point)?,
            normal: box3(&normal)?,
            certified: true,
        })
    } else {
        None
    };
    Some(Contact { instant, geometry })
}

impl Answer {
    /// The result in the contract's shape, as Algorithm 1 reports it.
    fn outcome(self, scene: &Scene, options: &Options) -> Outcome {
        let span = &scene.span;
        let [t0, t1] = span.clone().map(Instant::exact);
        let segment = |state, start: &Instant, end: &Instant| Segment {
            state,
            start: start.clone(),
            end: end.clone(),
            certified: true,
        };
        let crossed = matches!(self, Answer::Crosses(..));
        // Each list allocated once, at its final size.
        let mut contacts = Vec::new();
        let mut geometry = Vec::new();
        let mut first = None;
        let timeline = match self {
            Answer::Apart => vec![segment(State::Separate, &t0, &t1)],
            Answer::OverlapsAtStart => {
                first = Some(t0.clone());
                vec![segment(State::Overlap, &t0, &t0)]
            }
            Answer::Crosses(inn, out) => {
                let i = &inn.instant;
                let mut timeline = Vec::with_capacity(5);
                timeline.push(segment(State::Separate, &t0, i));
                timeline.push(segment(State::Touch, i, i));
                if !options.first_contact_only {
                    match &out {
                        Some(out) => {
                            let o = &out.instant;
                            timeline.push(segment(State::Overlap, i, o));
                            timeline.push(segment(State::Touch, o, o));
                            timeline.push(segment(State::Separate, o, &t1));
                        }
                        None => timeline.push(segment(State::Overlap, i, &t1)),
                    }
                }
                contacts.reserve_exact(1 + usize::from(out.is_some()));
                for c in std::iter::once(inn).chain(out) {
                    contacts.push(c.instant);
                    geometry.extend(c.geometry);
                }
                timeline
            }
        };
        let segment_geometry = if options.contact_geometry {
            vec![None; timeline.len()]
        } else {
            Vec::new()
        };
        let first = first.or_else(|| contacts.first().cloned());
        Outcome {
            span: span.clone(),
            collision_free: first.is_none(),
            undecided: None,
            complete: !options.first_contact_only || first.is_none(),
            first_contact: first,
            contacts,
            timeline,
            gaps: Vec::new(),
            stats: Stats {
                path: Path::Raycast,
                candidates: usize::from(crossed),
                ..Stats::default()
            },
            geometry,
            segment_geometry,
        }
    }
}
