//! The `--json` result of the contract (`scene-format.md`, format 1).

use ccd_arith::Rat;
use ccd_timeline::{Box3, Gap, Geometry, Instant, Outcome, Segment};

use crate::WorldOutcome;
use serde_json::{json, Map, Value};

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

fn instant(i: &Instant, digits: u32) -> Value {
    json!({"lo": i.lo.to_string(), "hi": i.hi.to_string(), "approx": i.approx(digits), "certified": i.certified})
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

fn boxed(b: &Box3, certified: bool) -> Value {
    let d = box_digits(b);
    let strings = |v: &[Rat; 3]| v.iter().map(Rat::to_string).collect::<Vec<_>>();
    json!({"lo": strings(&b.lo), "hi": strings(&b.hi), "approx": b.approx(d), "certified": certified})
}

/// The keys of `g` in `obj`, each named with `prefix`: `point` and
/// `normal` (null, with a `point_note`, when there is no single point).
fn insert_geometry(obj: &mut Map<String, Value>, prefix: &str, g: &Geometry) {
    let key = |k: &str| format!("{prefix}{k}");
    match g {
        Geometry::Point {
            point,
            normal,
            certified,
        } => {
            obj.insert(key("point"), boxed(point, *certified));
            obj.insert(key("normal"), boxed(normal, *certified));
        }
        Geometry::NotASinglePoint => {
            obj.insert(key("point"), Value::Null);
            obj.insert(key("normal"), Value::Null);
            obj.insert(key("point_note"), "not a single point".into());
        }
        Geometry::Unknown { reason } => {
            obj.insert(key("point"), Value::Null);
            obj.insert(key("normal"), Value::Null);
            obj.insert(key("point_note"), format!("not computed: {reason}").into());
        }
    }
}

/// A contact's time object with its `point` and `normal` (null, with a
/// `point_note`, when there is no single point).
fn contact(i: &Instant, g: Option<&Geometry>, digits: u32) -> Value {
    let mut v = instant(i, digits);
    if let (Some(g), Some(obj)) = (g, v.as_object_mut()) {
        insert_geometry(obj, "", g);
    }
    v
}

/// A timeline entry; a touch segment that is not an isolated contact gains
/// `start_point`, `start_normal`, `end_point`, `end_normal` (or
/// `start_point_note` / `end_point_note`).
fn segment(seg: &Segment, ends: Option<&[Geometry; 2]>, digits: u32) -> Value {
    let mut v = json!({
        "state": seg.state.name(),
        "start": instant(&seg.start, digits),
        "end": instant(&seg.end, digits),
        "certified": seg.certified,
    });
    if let (Some([start, end]), Some(obj)) = (ends, v.as_object_mut()) {
        insert_geometry(obj, "start_", start);
        insert_geometry(obj, "end_", end);
    }
    v
}

fn gap(g: &Gap) -> Value {
    json!({
        "lo": g.lo.to_string(),
        "hi": g.hi.to_string(),
        "reason": g.reason,
        "witness": g.witness.as_ref().map(|w| json!({"t": w.t.to_string(), "state": w.state.name()})),
    })
}

/// The result as the contract's JSON object (plus `complete`, `certified`,
/// `gaps`, `collision_free_reason`, a `certified` flag per segment, and
/// `stats`, which consumers may ignore; semantics in `docs/scene-format.md`).
pub fn to_json(outcome: &Outcome) -> Value {
    let d = approx_digits(&outcome.span);
    let s = &outcome.stats;
    json!({
        "format": 1,
        "span": [outcome.span[0].to_string(), outcome.span[1].to_string()],
        "collision_free": if outcome.undecided.is_some() { Value::Null } else { Value::Bool(outcome.collision_free) },
        "collision_free_reason": outcome.undecided,
        "first_contact": outcome.first_contact.as_ref()
            .map(|i| contact(i, outcome.first_contact_geometry(), d)),
        "contacts": outcome.contacts.iter().enumerate()
            .map(|(k, i)| contact(i, outcome.geometry.get(k), d)).collect::<Vec<_>>(),
        "timeline": outcome.timeline.iter().enumerate()
            .map(|(k, seg)| segment(seg, outcome.segment_geometry.get(k).and_then(Option::as_ref), d))
            .collect::<Vec<_>>(),
        "gaps": outcome.gaps.iter().map(gap).collect::<Vec<_>>(),
        "complete": outcome.complete,
        "certified": outcome.certified(),
        "stats": {
            "deg_f": s.deg_f,
            "deg_sr0": s.deg_sr0,
            "deg_candidates": s.deg_candidates,
            "branch": s.branch_name(),
            "candidates": s.candidates,
            "sr0_formed": s.sr0_formed,
        },
    })
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
    let d = approx_digits(&world.span);
    let name = |i: usize| Value::from(world.bodies[i].as_str());
    let pair_names = |list: Vec<(usize, usize)>| {
        list.into_iter()
            .map(|(a, b)| json!([name(a), name(b)]))
            .collect::<Vec<_>>()
    };
    let pairs: Vec<Value> = world
        .pairs
        .iter()
        .map(|p| {
            let mut obj = serde_json::Map::new();
            obj.insert("a".into(), name(p.a));
            obj.insert("b".into(), name(p.b));
            match &p.result {
                Ok(o) => {
                    if let Value::Object(m) = to_json(o) {
                        obj.extend(m);
                    }
                }
                Err(e) => {
                    obj.insert("error".into(), e.to_string().into());
                }
            }
            Value::Object(obj)
        })
        .collect();
    json!({
        "format": 1,
        "span": [world.span[0].to_string(), world.span[1].to_string()],
        "bodies": world.bodies,
        "colliding": pair_names(world.colliding()),
        "undecided": pair_names(world.undecided()),
        "first_contact": world.first_contact.as_ref().map(|c| {
            let mut v = instant(&c.instant, d);
            if let Some(obj) = v.as_object_mut() {
                obj.insert("pair".into(), json!([name(c.pair.0), name(c.pair.1)]));
            }
            v
        }),
        "pairs": pairs,
        "broad_phase": {
            "candidates": world.broad_phase.candidates,
            "pruned": world.broad_phase.pruned,
            "box_overlaps": world.broad_phase.box_overlaps,
            "pruned_proven_separate": true,
            "slices": world.broad_phase.slices,
        },
        "complete": world.complete,
        "certified": world.certified(),
    })
}
