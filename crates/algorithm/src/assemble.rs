//! The timeline (Theorem 5.1): the span cut at `t0`, the contacts and gaps
//! the walk found, and `t1`; each piece's state read at a rational sample
//! inside it; then the verdicts (first contact, collision-free, complete).

use crate::oracle::{Decided, Item, Oracle};
use crate::run::state_at;
use crate::{CcdError, Options};
use ccd_arith::Rat;
use ccd_subres::Quantity;
use ccd_timeline::{Gap, Geometry, Instant, Outcome, Path, Segment, State, Stats, Witness};

/// What the walk over the candidates leaves between pieces of constant
/// state.
pub(crate) enum Break<R> {
    /// A contact (an external touch) with its root, when there is one to
    /// compute the geometry at.
    Contact(Instant, Option<R>),
    /// An undecided piece `[lo, hi]` and why.
    Gap(Rat, Rat, &'static str),
}

/// The breaks of one walk, in order, the quantities that vanish at its
/// contacts, and whether it stopped at its last break (a first-contact
/// query's first contact, or a gap not proven separate).
pub(crate) struct Walk<R> {
    pub(crate) breaks: Vec<Break<R>>,
    pub(crate) zeros: &'static [Quantity],
    pub(crate) stopped: bool,
}

impl<R> Default for Walk<R> {
    fn default() -> Self {
        Walk {
            breaks: Vec::new(),
            zeros: &[],
            stopped: false,
        }
    }
}

impl<R> Walk<R> {
    /// Appends a break clipped to `[d0, d1]` (an enclosure reaching past an
    /// end may hold a root outside the span, so it is no longer certified),
    /// merged into the previous gap when it is an overlapping gap.
    pub(crate) fn push(&mut self, mut b: Break<R>, d0: &Rat, d1: &Rat) {
        let (lo, hi) = match &mut b {
            Break::Contact(c, _) => (&mut c.lo, &mut c.hi),
            Break::Gap(lo, hi, _) => (lo, hi),
        };
        if &*hi < d0 || &*lo > d1 {
            return;
        }
        let clipped = &*lo < d0 || &*hi > d1;
        if &*lo < d0 {
            *lo = d0.clone();
        }
        if &*hi > d1 {
            *hi = d1.clone();
        }
        if let (Break::Contact(c, _), true) = (&mut b, clipped) {
            c.certified = false;
        }
        match (self.breaks.last_mut(), b) {
            (Some(Break::Gap(_, hi, _)), Break::Gap(lo2, hi2, _)) if lo2 <= *hi => {
                if hi2 > *hi {
                    *hi = hi2;
                }
            }
            (_, b) => self.breaks.push(b),
        }
    }
}

/// A rational strictly inside `(lo, hi)` with a small denominator (the
/// simplest one in the middle half): the sample of a piece.
pub fn sample_between(lo: &Rat, hi: &Rat) -> Rat {
    let quarter = (hi - lo).mul_pow2(-2);
    Rat::simplest_in(&(lo + &quarter), &(hi - &quarter))
}

/// What a breakpoint of the timeline is.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Point {
    /// `t0` or `t1`.
    End,
    /// A contact's enclosure (a root of the candidate polynomial in it).
    Contact,
    /// An end of a gap (not proven a non-root).
    Gap,
}

/// The sample of the piece from `start` to `end`: with
/// [`Oracle::SAMPLE_AT_ENDS`], the simplest rational of the closed piece
/// `[start.hi, end.lo]` unless it is a contact's exact instant (the cheapest
/// to evaluate exactly, often `t0` itself); otherwise, and for an arithmetic
/// of enclosures, which need room around a root, [`sample_between`].
fn sample<O: Oracle>(start: (&Instant, Point), end: (&Instant, Point)) -> Rat {
    let (lo, hi) = (&start.0.hi, &end.0.lo);
    if O::SAMPLE_AT_ENDS && lo != hi {
        let s = Rat::simplest_in(lo, hi);
        let root = |(i, p): (&Instant, Point)| p == Point::Contact && i.lo == i.hi && i.lo == s;
        if !root(start) && !root(end) {
            return s;
        }
    }
    sample_between(lo, hi)
}

/// The state of the piece from `start` to `end` between breaks, read at a
/// sample (Theorem 5.1: no candidate root lies in it).
fn piece<O: Oracle>(
    o: &O,
    start: (Instant, Point),
    end: (Instant, Point),
) -> Result<Segment, CcdError> {
    let x = sample::<O>((&start.0, start.1), (&end.0, end.1));
    let mut d = state_at(o, &x);
    if d.state == State::Touch {
        d = o.touch_between_contacts(&x, d)?;
    }
    Ok(Segment {
        state: d.state,
        start: start.0,
        end: end.0,
        certified: d.certified,
    })
}

/// Appends `item`, merging two long segments of one state that meet.
fn push(out: &mut Vec<Item>, item: Item) {
    if let (Some(Item::Segment(prev)), Item::Segment(next)) = (out.last_mut(), &item) {
        let long = |s: &Segment| s.start != s.end;
        if long(prev) && long(next) && prev.state == next.state && prev.end == next.start {
            prev.end = next.end.clone();
            prev.certified &= next.certified;
            return;
        }
    }
    out.push(item);
}

/// The outcome of a run: the items in the oracle's parameter, settled by
/// the oracle, then the verdicts, mapped to time.
pub(crate) fn assemble<O: Oracle>(
    o: &O,
    opts: &Options,
    state0: Decided,
    throughout: Option<(Decided, &'static [Quantity])>,
    stop_early: bool,
    walk: Walk<O::Root>,
) -> Result<Outcome, CcdError> {
    let [d0, d1] = o.domain();
    let mut items: Vec<Item> = Vec::new();
    let mut roots: Vec<(Instant, Option<O::Root>)> = Vec::new();
    let breaks = walk.breaks;
    // A first-contact query that found a contact stops there (a gap it
    // stopped at may still be filled to t1 by the oracle's certificates).
    let at_contact = walk.stopped && matches!(breaks.last(), Some(Break::Contact(..)));
    if let Some((d, _)) = throughout {
        items.push(Item::Segment(Segment {
            state: d.state,
            start: Instant::exact(d0.clone()),
            end: Instant::exact(d1.clone()),
            certified: d.certified,
        }));
    } else if stop_early {
        let start = Instant {
            lo: d0.clone(),
            hi: d0.clone(),
            certified: state0.certified,
        };
        items.push(Item::Segment(Segment {
            state: state0.state,
            start: start.clone(),
            end: start,
            certified: state0.certified,
        }));
    } else {
        // Breakpoints t0, the breaks, t1: a gap starting at t0 or a contact
        // exactly at t0 replaces t0; a first-contact query stops at its
        // first break. Between two breakpoints a piece is read at a sample
        // (at their common end when they meet, as two contact enclosures
        // may: an end of a contact's enclosure that is not a single point
        // is not its root), except next to a gap, whose ends are not
        // proven non-roots.
        let replaces_t0 = |b: &Break<O::Root>| match b {
            Break::Gap(lo, _, _) => lo == d0,
            Break::Contact(c, _) => c.lo == *d0 && c.hi == *d0,
        };
        let mut prev = (!breaks.first().is_some_and(replaces_t0))
            .then(|| (Instant::exact(d0.clone()), Point::End));
        let between = |(p, pk): &(Instant, Point), (next, nk): &(Instant, Point)| {
            p.hi < next.lo
                || (p.hi == next.lo
                    && *pk != Point::Gap
                    && *nk != Point::Gap
                    && (p.lo != p.hi || next.lo != next.hi))
        };
        for br in breaks {
            let entry = match &br {
                Break::Contact(c, _) => (c.clone(), Point::Contact),
                Break::Gap(lo, _, _) => (Instant::exact(lo.clone()), Point::Gap),
            };
            if let Some(p) = prev.take() {
                if between(&p, &entry) {
                    items.push(Item::Segment(piece(o, p, entry.clone())?));
                }
            }
            match br {
                Break::Contact(c, root) => {
                    items.push(Item::Segment(Segment {
                        state: State::Touch,
                        start: c.clone(),
                        end: c.clone(),
                        certified: c.certified,
                    }));
                    roots.push((c.clone(), root));
                    prev = Some((c, Point::Contact));
                }
                Break::Gap(lo, hi, why) => {
                    items.push(Item::Gap(Gap {
                        lo,
                        hi: hi.clone(),
                        reason: why.to_string(),
                        witness: None,
                    }));
                    prev = Some((Instant::exact(hi), Point::Gap));
                }
            }
        }
        let reached_end = !walk.stopped;
        if let (Some(p), true) = (prev, reached_end) {
            let end = (Instant::exact(d1.clone()), Point::End);
            if between(&p, &end) {
                items.push(Item::Segment(piece(o, p, end)?));
            }
        }
    }
    let mut merged = Vec::new();
    for item in o.settle(items) {
        push(&mut merged, item);
    }
    // A gap from t0 on, where the state at t0 is proven not separate: t0
    // itself is its witness (a first-contact query stops there with that
    // state; the full query must not know less).
    if let (Some(Item::Gap(g)), true) = (
        merged.first_mut(),
        state0.certified && state0.state != State::Separate,
    ) {
        if g.lo == *d0 && g.witness.is_none() {
            g.witness = Some(Witness {
                t: d0.clone(),
                state: state0.state,
            });
        }
    }
    let geometry: Vec<Geometry> = if opts.contact_geometry {
        roots
            .into_iter()
            .map(|(c, root)| match root {
                Some(mut r) => o.geometry(&mut r, walk.zeros, &c),
                None => Geometry::Unknown {
                    reason: "the contact's roots were not separated".into(),
                },
            })
            .collect()
    } else {
        Vec::new()
    };
    let segment_geometry = if opts.contact_geometry {
        let zeros = throughout.map_or(walk.zeros, |(_, z)| z);
        touch_segments(o, &merged, zeros, stop_early)
    } else {
        Vec::new()
    };
    let mut outcome = verdicts(o, merged, stop_early, opts.first_contact_only && at_contact);
    outcome.geometry = geometry;
    outcome.segment_geometry = segment_geometry;
    Ok(outcome)
}

/// The geometry at the ends of each segment of `items` that is a touch but
/// not an isolated contact (`Outcome::segment_geometry`): a long touch
/// segment, or the touch at `t0` where a first-contact query stopped
/// (`stop_early`). Each end that is an exact instant is evaluated there
/// ([`Oracle::geometry_at`]); the result is certified only where the
/// segment's state is.
fn touch_segments<O: Oracle>(
    o: &O,
    items: &[Item],
    zeros: &[Quantity],
    stop_early: bool,
) -> Vec<Option<[Geometry; 2]>> {
    let at = |i: &Instant, certified: bool| {
        if i.lo != i.hi {
            return Geometry::Unknown {
                reason: "the end of the touch segment is not an exact instant".into(),
            };
        }
        match o.geometry_at(&i.lo, zeros) {
            Geometry::Point {
                point,
                normal,
                certified: c,
            } => Geometry::Point {
                point,
                normal,
                certified: c && certified && i.certified,
            },
            other => other,
        }
    };
    items
        .iter()
        .filter_map(|item| match item {
            Item::Segment(s) => Some(s),
            Item::Gap(_) => None,
        })
        .map(|s| {
            let isolated = s.start == s.end && !stop_early;
            (s.state == State::Touch && !isolated).then(|| {
                let start = at(&s.start, s.certified);
                let end = if s.end == s.start {
                    start.clone()
                } else {
                    at(&s.end, s.certified)
                };
                [start, end]
            })
        })
        .collect()
}

/// The first contact, the contacts, completeness and the collision verdict
/// of a settled timeline, mapped to time; on the float path every instant
/// and segment is marked uncertified, and `collision_free` is the float
/// answer.
fn verdicts<O: Oracle>(o: &O, items: Vec<Item>, stop_early: bool, stopped: bool) -> Outcome {
    let [d0, d1] = o.domain();
    let certifies = O::PATH != Path::Float;
    let map = |i: &Instant| Instant {
        lo: o.time(&i.lo),
        hi: o.time(&i.hi),
        certified: i.certified && certifies,
    };
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
                    // Proven exactly when nothing undecided precedes it: a
                    // witness at the gap's start after proven separation.
                    first_contact = Some(Instant {
                        lo: g.lo.clone(),
                        hi: w.t.clone(),
                        certified: clean && w.t == g.lo,
                    });
                }
                clean = false;
                gaps.push(g);
            }
        }
    }
    let contacts: Vec<Instant> = timeline
        .iter()
        .filter(|s| {
            s.start == s.end && s.state == State::Touch && !(stop_early && s.start.lo == *d0)
        })
        .map(|s| s.start.clone())
        .collect();
    let covered_to_end = timeline.last().is_some_and(|s| s.end.hi == *d1);
    // Complete exactly when the timeline tiles the span (a first-contact
    // query that found a contact or gap stops there).
    let complete = gaps.is_empty() && covered_to_end && !stop_early && !stopped;
    let all_separate = timeline.iter().all(|s| s.state == State::Separate);
    let separation =
        complete && all_separate && (!certifies || timeline.iter().all(|s| s.certified));
    let collision = !certifies
        || timeline
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
    let span = [o.time(d0), o.time(d1)];
    Outcome {
        span,
        collision_free: separation,
        undecided,
        first_contact: first_contact.as_ref().map(map),
        contacts: contacts.iter().map(map).collect(),
        timeline: timeline
            .iter()
            .map(|s| Segment {
                state: s.state,
                start: map(&s.start),
                end: map(&s.end),
                certified: s.certified && certifies,
            })
            .collect(),
        gaps: gaps
            .into_iter()
            .map(|g| Gap {
                lo: o.time(&g.lo),
                hi: o.time(&g.hi),
                witness: g.witness.map(|w| Witness {
                    t: o.time(&w.t),
                    state: w.state,
                }),
                ..g
            })
            .collect(),
        complete,
        stats: Stats::default(),
        geometry: Vec::new(),
        segment_geometry: Vec::new(),
    }
}
