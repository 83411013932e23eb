//! The `--json` result of the contract (`scene-format.md`, format 1).

use ccd_timeline::{Gap, Instant, Outcome};
use serde_json::{json, Value};

/// Decimals of `approx`: 12, plus one per leading zero of the span's width.
fn approx_digits(outcome: &Outcome) -> u32 {
    let width = (&outcome.span[1] - &outcome.span[0]).to_f64();
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
    let d = approx_digits(outcome);
    let s = &outcome.stats;
    json!({
        "format": 1,
        "span": [outcome.span[0].to_string(), outcome.span[1].to_string()],
        "collision_free": if outcome.undecided.is_some() { Value::Null } else { Value::Bool(outcome.collision_free) },
        "collision_free_reason": outcome.undecided,
        "first_contact": outcome.first_contact.as_ref().map(|i| instant(i, d)),
        "contacts": outcome.contacts.iter().map(|i| instant(i, d)).collect::<Vec<_>>(),
        "timeline": outcome.timeline.iter().map(|seg| json!({
            "state": seg.state.name(),
            "start": instant(&seg.start, d),
            "end": instant(&seg.end, d),
            "certified": seg.certified,
        })).collect::<Vec<_>>(),
        "gaps": outcome.gaps.iter().map(gap).collect::<Vec<_>>(),
        "complete": outcome.complete,
        "certified": outcome.certified(),
        "stats": {
            "deg_f": s.deg_f,
            "deg_sr0": s.deg_sr0,
            "deg_candidates": s.deg_candidates,
            "branch": s.branch,
            "candidates": s.candidates,
            "sr0_formed": s.sr0_formed,
        },
    })
}
