//! The `--json` result of the contract (`scene-format.md`, format 1).
//!
//! One definition, as `serde::Serialize` views over the outcome: the CLI
//! streams it as pretty text ([`to_json_pretty`]) without building a
//! `serde_json::Value`, and [`to_json`] collects the same entries into one.

use ccd_arith::Rat;
use ccd_timeline::{Box3, Gap, Geometry, Instant, Outcome, Segment};
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};
use serde_json::Value;
use std::fmt::Display;

use crate::WorldOutcome;

/// Decimals of `approx`: 12, plus one per leading zero of the span's width.
fn approx_digits(span: &[Rat; 2]) -> u32 {
    let width = (&span[1] - &span[0]).to_f64();
    let extra = if width < 1.0 {
        (-width.log10()).ceil().clamp(0.0, 300.0) as u32
    } else {
        0
    };
    12 + extra
}

/// Decimals for a box's `approx`: enough for its width (12 to 16), 16
/// for a box of zero width (an exact point, or a float estimate).
pub(crate) fn box_digits(b: &Box3) -> u32 {
    let w = b.width().to_f64();
    if w > 0.0 {
        (-w.log10()).ceil().clamp(12.0, 16.0) as u32
    } else {
        16
    }
}

/// A value written as the JSON string of its `Display` text (an exact
/// rational `p/q`), without an intermediate `String`.
struct Text<'a, T: Display>(&'a T);

impl<T: Display> Serialize for Text<'_, T> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self.0)
    }
}

/// A list of exact rationals as strings.
struct Rats<'a>(&'a [Rat]);

impl Serialize for Rats<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut seq = s.serialize_seq(Some(self.0.len()))?;
        for r in self.0 {
            seq.serialize_element(&Text(r))?;
        }
        seq.end()
    }
}

/// A list written element by element from an iterator (cloned per write).
struct List<I>(I);

impl<I: Iterator + Clone> Serialize for List<I>
where
    I::Item: Serialize,
{
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.0.clone())
    }
}

/// The map keys of a geometry: `point`, `normal`, `point_note` with a
/// prefix (none, `start_` or `end_`).
type GeometryKeys = [&'static str; 3];
const CONTACT_KEYS: GeometryKeys = ["point", "normal", "point_note"];
const START_KEYS: GeometryKeys = ["start_point", "start_normal", "start_point_note"];
const END_KEYS: GeometryKeys = ["end_point", "end_normal", "end_point_note"];

/// A time object: `lo`, `hi`, `approx`, `certified`, then (a contact) its
/// `point` and `normal` (null, with a `point_note`, when there is no single
/// point), or (a world's first contact) its `pair`.
struct Time<'a> {
    i: &'a Instant,
    digits: u32,
    geometry: Option<&'a Geometry>,
    pair: Option<[&'a str; 2]>,
}

impl<'a> Time<'a> {
    fn new(i: &'a Instant, digits: u32) -> Time<'a> {
        Time {
            i,
            digits,
            geometry: None,
            pair: None,
        }
    }
    fn contact(i: &'a Instant, g: Option<&'a Geometry>, digits: u32) -> Time<'a> {
        Time {
            geometry: g,
            ..Time::new(i, digits)
        }
    }
}

impl Serialize for Time<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("lo", &Text(&self.i.lo))?;
        m.serialize_entry("hi", &Text(&self.i.hi))?;
        m.serialize_entry("approx", &self.i.approx(self.digits))?;
        m.serialize_entry("certified", &self.i.certified)?;
        if let Some(g) = self.geometry {
            geometry(&mut m, &CONTACT_KEYS, g)?;
        }
        if let Some(pair) = &self.pair {
            m.serialize_entry("pair", pair)?;
        }
        m.end()
    }
}

/// A certified box (or a float estimate): `lo`, `hi`, `approx`,
/// `certified`.
struct Boxed<'a>(&'a Box3, bool);

impl Serialize for Boxed<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let Boxed(b, certified) = *self;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("lo", &Rats(&b.lo))?;
        m.serialize_entry("hi", &Rats(&b.hi))?;
        m.serialize_entry("approx", &b.approx(box_digits(b)))?;
        m.serialize_entry("certified", &certified)?;
        m.end()
    }
}

/// The entries of `g` in an open map, named by `keys`.
fn geometry<M: SerializeMap>(m: &mut M, keys: &GeometryKeys, g: &Geometry) -> Result<(), M::Error> {
    let [point, normal, note] = *keys;
    match g {
        Geometry::Point {
            point: p,
            normal: n,
            certified,
        } => {
            m.serialize_entry(point, &Boxed(p, *certified))?;
            m.serialize_entry(normal, &Boxed(n, *certified))
        }
        Geometry::NotASinglePoint => {
            m.serialize_entry(point, &())?;
            m.serialize_entry(normal, &())?;
            m.serialize_entry(note, "not a single point")
        }
        Geometry::Unknown { reason } => {
            m.serialize_entry(point, &())?;
            m.serialize_entry(normal, &())?;
            m.serialize_entry(note, &format_args!("not computed: {reason}"))
        }
    }
}

/// A timeline entry; a touch segment that is not an isolated contact gains
/// `start_point`, `start_normal`, `end_point`, `end_normal` (or
/// `start_point_note` / `end_point_note`).
struct Entry<'a>(&'a Segment, Option<&'a [Geometry; 2]>, u32);

impl Serialize for Entry<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let Entry(seg, ends, digits) = *self;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("state", seg.state.name())?;
        m.serialize_entry("start", &Time::new(&seg.start, digits))?;
        m.serialize_entry("end", &Time::new(&seg.end, digits))?;
        m.serialize_entry("certified", &seg.certified)?;
        if let Some([start, end]) = ends {
            geometry(&mut m, &START_KEYS, start)?;
            geometry(&mut m, &END_KEYS, end)?;
        }
        m.end()
    }
}

/// An undecided piece of the span.
struct GapView<'a>(&'a Gap);

impl Serialize for GapView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let g = self.0;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("lo", &Text(&g.lo))?;
        m.serialize_entry("hi", &Text(&g.hi))?;
        m.serialize_entry("reason", &g.reason)?;
        m.serialize_entry("witness", &g.witness.as_ref().map(WitnessView))?;
        m.end()
    }
}

struct WitnessView<'a>(&'a ccd_timeline::Witness);

impl Serialize for WitnessView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("t", &Text(&self.0.t))?;
        m.serialize_entry("state", self.0.state.name())?;
        m.end()
    }
}

/// The entries of a pair result in an open map (a pair file's whole
/// object; a world's pair after its `a` and `b`).
fn outcome_entries<M: SerializeMap>(m: &mut M, outcome: &Outcome) -> Result<(), M::Error> {
    let d = approx_digits(&outcome.span);
    m.serialize_entry("format", &1)?;
    m.serialize_entry("span", &Rats(&outcome.span))?;
    let free = outcome
        .undecided
        .is_none()
        .then_some(outcome.collision_free);
    m.serialize_entry("collision_free", &free)?;
    m.serialize_entry("collision_free_reason", &outcome.undecided)?;
    let first = outcome
        .first_contact
        .as_ref()
        .map(|i| Time::contact(i, outcome.first_contact_geometry(), d));
    m.serialize_entry("first_contact", &first)?;
    let contacts = outcome.contacts.iter().enumerate();
    let contacts = contacts.map(|(k, i)| Time::contact(i, outcome.geometry.get(k), d));
    m.serialize_entry("contacts", &List(contacts))?;
    let timeline = outcome.timeline.iter().enumerate().map(|(k, seg)| {
        let ends = outcome.segment_geometry.get(k).and_then(Option::as_ref);
        Entry(seg, ends, d)
    });
    m.serialize_entry("timeline", &List(timeline))?;
    m.serialize_entry("gaps", &List(outcome.gaps.iter().map(GapView)))?;
    m.serialize_entry("complete", &outcome.complete)?;
    m.serialize_entry("certified", &outcome.certified())?;
    m.serialize_entry("stats", &StatsView(outcome))
}

struct StatsView<'a>(&'a Outcome);

impl Serialize for StatsView<'_> {
    fn serialize<S: Serializer>(&self, ser: S) -> Result<S::Ok, S::Error> {
        let s = &self.0.stats;
        let mut m = ser.serialize_map(None)?;
        m.serialize_entry("deg_f", &s.deg_f)?;
        m.serialize_entry("deg_sr0", &s.deg_sr0)?;
        m.serialize_entry("deg_candidates", &s.deg_candidates)?;
        m.serialize_entry("branch", s.branch_name())?;
        m.serialize_entry("candidates", &s.candidates)?;
        m.serialize_entry("sr0_formed", &s.sr0_formed)?;
        m.end()
    }
}

/// A pair result as the contract's object.
struct PairView<'a>(&'a Outcome);

impl Serialize for PairView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(None)?;
        outcome_entries(&mut m, self.0)?;
        m.end()
    }
}

/// A world result as the contract's object.
struct WorldView<'a>(&'a WorldOutcome);

impl Serialize for WorldView<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let world = self.0;
        let d = approx_digits(&world.span);
        let name = |i: usize| world.bodies[i].as_str();
        let pair_names = |list: Vec<(usize, usize)>| {
            list.into_iter()
                .map(|(a, b)| [name(a), name(b)])
                .collect::<Vec<_>>()
        };
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("format", &1)?;
        m.serialize_entry("span", &Rats(&world.span))?;
        m.serialize_entry("bodies", &world.bodies)?;
        m.serialize_entry("colliding", &pair_names(world.colliding()))?;
        m.serialize_entry("undecided", &pair_names(world.undecided()))?;
        let first = world.first_contact.as_ref().map(|c| Time {
            pair: Some([name(c.pair.0), name(c.pair.1)]),
            ..Time::new(&c.instant, d)
        });
        m.serialize_entry("first_contact", &first)?;
        let pairs = world.pairs.iter().map(|p| WorldPair(world, p));
        m.serialize_entry("pairs", &List(pairs))?;
        m.serialize_entry("broad_phase", &Broad(world))?;
        m.serialize_entry("complete", &world.complete)?;
        m.serialize_entry("certified", &world.certified())?;
        m.end()
    }
}

/// One queried pair of a world: `a`, `b` and the pair result object, or
/// `error`.
struct WorldPair<'a>(&'a WorldOutcome, &'a crate::PairResult);

impl Serialize for WorldPair<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let WorldPair(world, p) = *self;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("a", &world.bodies[p.a])?;
        m.serialize_entry("b", &world.bodies[p.b])?;
        match &p.result {
            Ok(o) => outcome_entries(&mut m, o)?,
            Err(e) => m.serialize_entry("error", &Text(e))?,
        }
        m.end()
    }
}

/// A world's broad-phase counts (`pruned_proven_separate: true`: a pruned
/// pair is proven separate throughout).
struct Broad<'a>(&'a WorldOutcome);

impl Serialize for Broad<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let b = &self.0.broad_phase;
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("candidates", &b.candidates)?;
        m.serialize_entry("pruned", &b.pruned)?;
        m.serialize_entry("box_overlaps", &b.box_overlaps)?;
        m.serialize_entry("pruned_proven_separate", &true)?;
        m.serialize_entry("slices", &b.slices)?;
        m.end()
    }
}

/// `view` collected into a `serde_json::Value` (whose serializer cannot
/// fail on these views: every key is a string).
fn value(view: impl Serialize) -> Value {
    serde_json::to_value(view).unwrap_or_else(|e| Value::String(e.to_string()))
}

/// `view` as pretty JSON text (two-space indent), written straight from
/// the outcome: the text of `serde_json::to_string_pretty` of its `Value`.
fn pretty(view: impl Serialize) -> String {
    let mut out = Vec::with_capacity(4096);
    let mut ser = serde_json::Serializer::pretty(&mut out);
    if let Err(e) = view.serialize(&mut ser) {
        return e.to_string();
    }
    // serde_json writes only valid UTF-8 (keys and values are `str`s).
    String::from_utf8(out).unwrap_or_else(|e| e.to_string())
}

/// The result as the contract's JSON object (plus `complete`, `certified`,
/// `gaps`, `collision_free_reason`, a `certified` flag per segment, and
/// `stats`, which consumers may ignore; semantics in `docs/scene-format.md`).
pub fn to_json(outcome: &Outcome) -> Value {
    value(PairView(outcome))
}

/// [`to_json`] as pretty JSON text (two-space indent, no final newline),
/// written without building the `Value`: the CLI's `--json`.
pub fn to_json_pretty(outcome: &Outcome) -> String {
    pretty(PairView(outcome))
}

/// A world's result as the contract's JSON object (`docs/scene-format.md`,
/// "World result"): `bodies`, `colliding` (pairs proven to touch or overlap,
/// names in file order), `undecided`, `first_contact` (a time with
/// `"pair": [a, b]`, or `null`), `pairs` (each queried candidate pair: `a`,
/// `b` and the pair result object, or `error`), `broad_phase`
/// (`candidates`, `pruned`, `box_overlaps`, `slices`, and
/// `pruned_proven_separate: true`: a pruned pair is proven separate
/// throughout), `complete` and `certified`.
pub fn world_to_json(world: &WorldOutcome) -> Value {
    value(WorldView(world))
}

/// [`world_to_json`] as pretty JSON text (two-space indent, no final
/// newline), written without building the `Value`.
pub fn world_to_json_pretty(world: &WorldOutcome) -> String {
    pretty(WorldView(world))
}
