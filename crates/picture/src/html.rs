//! The HTML page: the bodies sampled over the span, the timeline and the
//! contacts as inline JSON, drawn by an inline script on a 2D canvas.

use ccd_scene::Scene;
use ccd_timeline::{Geometry, Outcome, State};
use serde_json::{json, Value};

use crate::pose::{poses, Pose};
use crate::svg::{enclosure_text, verdict};
use crate::{escape, hex, state_color, COLOR_A, COLOR_B, GAP_COLOR};

/// Uniform samples of the span (contact instants are added to them).
const SAMPLES: usize = 480;

/// The page's script: reads `DATA`, draws, animates.
const SCRIPT: &str = include_str!("page.js");

/// `x` to 7 significant digits (the page draws; it need not carry more).
fn round7(x: f64) -> f64 {
    format!("{x:.6e}").parse().unwrap_or(x)
}

/// A pose as 12 numbers: the centre, then the axes matrix row by row.
fn flat(p: &Pose) -> Vec<f64> {
    p.center
        .iter()
        .chain(p.axes.iter().flatten())
        .map(|&x| round7(x))
        .collect()
}

fn data(scene: &Scene, outcome: &Outcome, title: &str) -> Value {
    let (t0, t1) = (outcome.span[0].to_f64(), outcome.span[1].to_f64());
    let mut times: Vec<f64> = (0..=SAMPLES)
        .map(|k| t0 + (t1 - t0) * k as f64 / SAMPLES as f64)
        .chain(outcome.contacts.iter().map(|c| c.midpoint().to_f64()))
        .collect();
    times.sort_by(f64::total_cmp);
    times.dedup();
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for &t in &times {
        let [pa, pb] = poses(scene, t);
        a.push(flat(&pa));
        b.push(flat(&pb));
    }
    let f = |r: &ccd_arith::Rat| r.to_f64();
    let contacts: Vec<Value> = outcome
        .contacts
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let (point, normal) = match outcome.geometry.get(k) {
                Some(Geometry::Point { point, normal, .. }) => (
                    json!(point.midpoint().map(|x| x.to_f64())),
                    json!(normal.midpoint().map(|x| x.to_f64())),
                ),
                _ => (Value::Null, Value::Null),
            };
            json!({
                "t": c.midpoint().to_f64(),
                "approx": c.approx(12),
                "enclosure": enclosure_text(c),
                "certified": c.certified,
                "point": point,
                "normal": normal,
            })
        })
        .collect();
    json!({
        "title": title,
        "verdict": verdict(outcome),
        "span": [t0, t1],
        "first_contact": outcome.first_contact.as_ref().map(|i| i.midpoint().to_f64()),
        "timeline": outcome.timeline.iter().map(|s| json!({
            "state": s.state.name(),
            "start": f(&s.start.midpoint()),
            "end": f(&s.end.midpoint()),
            "certified": s.certified,
        })).collect::<Vec<_>>(),
        "gaps": outcome.gaps.iter().map(|g| json!({"lo": f(&g.lo), "hi": f(&g.hi)})).collect::<Vec<_>>(),
        "contacts": contacts,
        "colors": {
            "a": hex(COLOR_A),
            "b": hex(COLOR_B),
            "separate": state_color(State::Separate),
            "touch": state_color(State::Touch),
            "overlap": state_color(State::Overlap),
            "undecided": GAP_COLOR,
        },
        "samples": {"t": times, "a": a, "b": b},
    })
}

/// The self-contained HTML page of a query (see the crate docs): `title`
/// heads it. Open `FILE#t=0.25` to start at `t = 0.25`; by default it
/// starts at the first contact (or `t0`).
pub fn html(scene: &Scene, outcome: &Outcome, title: &str) -> String {
    let title = if title.is_empty() { "ccd-exact" } else { title };
    // `</` inside a script would end it: JSON allows `<\/` for `</`.
    let json = data(scene, outcome, title)
        .to_string()
        .replace("</", "<\\/");
    format!(
        r#"<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>{t}</title>
<style>
body {{ font-family: sans-serif; margin: 12px; background: #fff; color: #222; }}
h1 {{ font-size: 18px; margin: 0 0 4px 0; }}
#verdict {{ margin: 0 0 8px 0; font-size: 14px; }}
canvas {{ display: block; border: 1px solid #ccc; }}
#controls {{ margin: 6px 0; font-size: 14px; }}
#slider {{ width: 600px; vertical-align: middle; }}
#contacts button {{ margin: 2px; }}
</style></head>
<body>
<h1>{t}</h1>
<p id="verdict"></p>
<canvas id="view" width="900" height="480"></canvas>
<canvas id="strip" width="900" height="64"></canvas>
<div id="controls"><button id="play">play</button> <input type="range" id="slider" min="0" max="1000" step="1" value="0"> <span id="readout"></span></div>
<div id="contacts"></div>
<p style="font-size:12px;color:#666">Drag the picture to turn the view. Outline colour = state at t (separate / touch / overlap); body A and body B filled. Positions are drawn from floating-point samples; the enclosures are the exact ones.</p>
<script>const DATA = {json};</script>
<script>
{SCRIPT}
</script>
</body></html>
"#,
        t = escape(title)
    )
}
