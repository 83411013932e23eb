//! Time against size: the exact mode's time per scene against the input's
//! bit size and against the family parameter `k` (issue 12: "every exact
//! query terminates, in time polynomial in the input's bit size"), as a
//! Markdown section and the chart `docs/stability-scaling.svg` (plain SVG,
//! log–log axes, written directly).

use crate::report::{secs, Row};
use crate::Case;
use ccd_arith::Rat;
use ccd_motion::{Body, Motion};
use std::fmt::Write;

/// The bits of one number: `bits(p) + bits(q)` for `p/q`.
fn bits_of(x: &Rat) -> u64 {
    x.numer().bits() + x.denom().bits()
}

fn body_bits(b: &Body) -> u64 {
    let sum = |xs: &[Rat]| xs.iter().map(bits_of).sum::<u64>();
    let weights = |w: &Option<Vec<Rat>>| w.as_deref().map_or(0, sum);
    sum(&b.radii)
        + match &b.motion {
            Motion::Static {
                center,
                orientation,
            } => sum(center) + sum(orientation),
            Motion::Translation {
                center,
                orientation,
            } => {
                center.points.iter().map(|p| sum(p)).sum::<u64>()
                    + weights(&center.weights)
                    + sum(orientation)
            }
            Motion::Rigid {
                orientation,
                center,
            } => {
                orientation.points.iter().map(|q| sum(q)).sum::<u64>()
                    + center.points.iter().map(|p| sum(p)).sum::<u64>()
                    + weights(&center.weights)
            }
            Motion::Affine { matrix } => {
                matrix
                    .points
                    .iter()
                    .flat_map(|m| m.iter())
                    .map(|row| sum(row))
                    .sum::<u64>()
                    + weights(&matrix.weights)
            }
            Motion::Helical { .. } => 0,
        }
}

/// The input's size: the bits of every number of the scene (span, radii,
/// control points, weights), `bits(p) + bits(q)` each.
pub fn scene_bits(case: &Case) -> u64 {
    let s = &case.scene;
    s.span.iter().map(bits_of).sum::<u64>() + body_bits(&s.a) + body_bits(&s.b)
}

/// The families charted against `k` (a gap `10⁻ᵏ`, a radius `10⁻ᵏ`, `d`
/// digits), with their colours.
const K_FAMILIES: &[(&str, &str)] = &[
    ("graze-spheres", "#999999"),
    ("graze-ellipsoids", "#555555"),
    ("graze-shapes", "#0072b2"),
    ("graze-turned", "#56b4e9"),
    ("graze-scene-turned", "#009e73"),
    ("graze-spin", "#e69f00"),
    ("ratio-needle", "#d55e00"),
    ("ratio-disc", "#cc79a7"),
    ("bench-perturbed", "#000000"),
];

fn colour(family: &str) -> &'static str {
    K_FAMILIES
        .iter()
        .find(|(f, _)| *f == family)
        .map_or("#bbbbbb", |(_, c)| c)
}

/// The Markdown section: the slowest exact query and its ratio to the
/// median, per family the exact time range against the input's size, and
/// every query that gave no answer.
pub fn markdown(rows: &[Row]) -> String {
    let mut md = String::new();
    let exact: Vec<(&Row, f64, u64)> = rows
        .iter()
        .map(|r| (r, r.scores[0].seconds, scene_bits(&r.case)))
        .collect();
    let mut times: Vec<f64> = exact.iter().map(|e| e.1).collect();
    times.sort_by(f64::total_cmp);
    let median = times.get(times.len() / 2).copied().unwrap_or(0.0);
    let _ = writeln!(md, "\n### Exact time against input size\n");
    if let Some((r, t, b)) = exact.iter().max_by(|a, b| a.1.total_cmp(&b.1)) {
        let _ = writeln!(
            md,
            "Slowest exact query: `{}` ({} input bits) in {}, **{:.0}×** the median exact query ({}).\n",
            r.case.name,
            b,
            secs(*t),
            t / median.max(1e-12),
            secs(median)
        );
    }
    let _ = writeln!(
        md,
        "| family | scenes | input bits (min – max) | exact time (median) | exact time (max) | slowest scene |"
    );
    let _ = writeln!(md, "| --- | ---: | ---: | ---: | ---: | --- |");
    let mut families: Vec<&str> = Vec::new();
    for r in rows {
        if !families.contains(&r.case.truth.family.as_str()) {
            families.push(&r.case.truth.family);
        }
    }
    for family in families {
        let fam: Vec<&(&Row, f64, u64)> = exact
            .iter()
            .filter(|e| e.0.case.truth.family == family)
            .collect();
        let mut t: Vec<f64> = fam.iter().map(|e| e.1).collect();
        t.sort_by(f64::total_cmp);
        let slow = fam.iter().max_by(|a, b| a.1.total_cmp(&b.1));
        let bits = |f: fn(u64, u64) -> u64| fam.iter().map(|e| e.2).reduce(f).unwrap_or(0);
        let _ = writeln!(
            md,
            "| {family} | {} | {} – {} | {} | {} | {} |",
            fam.len(),
            bits(u64::min),
            bits(u64::max),
            secs(t[t.len() / 2]),
            secs(t[t.len() - 1]),
            slow.map_or(String::new(), |s| format!("`{}`", s.0.case.name)),
        );
    }
    let refused: Vec<String> = rows
        .iter()
        .flat_map(|r| r.scores.iter().map(move |s| (r, s)))
        .filter_map(|(r, s)| {
            s.refused
                .as_ref()
                .map(|why| format!("- `{}`, {}: {why}", r.case.name, s.method.label()))
        })
        .collect();
    let _ = writeln!(
        md,
        "\nQueries that gave no answer (or were refused): {}\n{}",
        if refused.is_empty() { "none." } else { "" },
        refused.join("\n")
    );
    md
}

/// A log-scale axis mapping `[lo, hi]` onto pixels `[p0, p1]`.
struct Axis {
    lo: f64,
    hi: f64,
    p0: f64,
    p1: f64,
}

impl Axis {
    fn at(&self, v: f64) -> f64 {
        let f = (v.max(self.lo).log10() - self.lo.log10()) / (self.hi.log10() - self.lo.log10());
        self.p0 + f.clamp(0.0, 1.0) * (self.p1 - self.p0)
    }

    fn decades(&self) -> Vec<f64> {
        let (a, b) = (
            self.lo.log10().ceil() as i32,
            self.hi.log10().floor() as i32,
        );
        (a..=b).map(|e| 10f64.powi(e)).collect()
    }
}

fn text(out: &mut String, x: f64, y: f64, s: &str, size: u32, anchor: &str, extra: &str) {
    let esc = s
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    let _ = writeln!(
        out,
        "<text x=\"{x:.1}\" y=\"{y:.1}\" font-family=\"sans-serif\" font-size=\"{size}\" text-anchor=\"{anchor}\" {extra}>{esc}</text>"
    );
}

fn tick(v: f64, unit_s: bool) -> String {
    let e = v.log10().round() as i32;
    match (unit_s, e) {
        (true, 0) => "1 s".into(),
        (true, -3) => "1 ms".into(),
        (true, -6) => "1 µs".into(),
        (false, 0..=3) => format!("{}", 10i64.pow(e as u32)),
        _ => format!("1e{e}"),
    }
}

/// One panel: dots `(x, seconds, family, answered)`.
fn panel(
    out: &mut String,
    left: f64,
    title: &str,
    x_label: &str,
    x: Axis,
    pts: &[(f64, f64, &str, bool)],
) {
    let y = Axis {
        lo: 1e-5,
        hi: 100.0,
        p0: 470.0,
        p1: 50.0,
    };
    let grid = "stroke=\"#dddddd\" stroke-width=\"1\"";
    for v in x.decades() {
        let px = x.at(v);
        let _ = writeln!(
            out,
            "<line x1=\"{px:.1}\" y1=\"{:.1}\" x2=\"{px:.1}\" y2=\"{:.1}\" {grid}/>",
            y.p0, y.p1
        );
        text(out, px, y.p0 + 16.0, &tick(v, false), 11, "middle", "");
    }
    for v in y.decades() {
        let py = y.at(v);
        let _ = writeln!(
            out,
            "<line x1=\"{:.1}\" y1=\"{py:.1}\" x2=\"{:.1}\" y2=\"{py:.1}\" {grid}/>",
            x.p0, x.p1
        );
        text(out, x.p0 - 6.0, py + 4.0, &tick(v, true), 11, "end", "");
    }
    let _ = writeln!(
        out,
        "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{:.1}\" height=\"{:.1}\" fill=\"none\" stroke=\"black\"/>",
        x.p0,
        y.p1,
        x.p1 - x.p0,
        y.p0 - y.p1
    );
    for (vx, vy, family, answered) in pts {
        let (px, py) = (x.at(*vx), y.at(*vy));
        let c = colour(family);
        if *answered {
            let _ = writeln!(
                out,
                "<circle cx=\"{px:.1}\" cy=\"{py:.1}\" r=\"3\" fill=\"{c}\" fill-opacity=\"0.7\"/>"
            );
        } else {
            let _ = writeln!(
                out,
                "<circle cx=\"{px:.1}\" cy=\"{py:.1}\" r=\"6\" fill=\"none\" stroke=\"#d00000\" stroke-width=\"2\"/>"
            );
        }
    }
    let mid = (x.p0 + x.p1) / 2.0;
    text(out, mid, 36.0, title, 14, "middle", "font-weight=\"bold\"");
    text(out, mid, y.p0 + 36.0, x_label, 12, "middle", "");
    let cy = (y.p0 + y.p1) / 2.0;
    text(
        out,
        left + 14.0,
        cy,
        "exact time per query (median of up to 5)",
        12,
        "middle",
        &format!("transform=\"rotate(-90 {:.1} {cy:.1})\"", left + 14.0),
    );
}

/// The chart: left, exact time per scene against the input's bit size
/// (every scene); right, against `k` for the families that have one.
/// Red rings: no answer within the report's budget (drawn at the time
/// waited).
pub fn chart(rows: &[Row]) -> String {
    let (w, h) = (1200.0, 600.0);
    let mut out = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">\n<rect width=\"{w}\" height=\"{h}\" fill=\"white\"/>\n"
    );
    let by_bits: Vec<(f64, f64, &str, bool)> = rows
        .iter()
        .map(|r| {
            let s = &r.scores[0];
            (
                scene_bits(&r.case) as f64,
                s.seconds,
                r.case.truth.family.as_str(),
                s.refused.is_none(),
            )
        })
        .collect();
    let max_bits = by_bits.iter().map(|p| p.0).fold(1e3, f64::max);
    panel(
        &mut out,
        20.0,
        "exact time vs input size (every scene)",
        "input size: bits of all the scene's numbers (log scale)",
        Axis {
            lo: 100.0,
            hi: 10f64.powf(max_bits.log10().ceil()),
            p0: 90.0,
            p1: 580.0,
        },
        &by_bits,
    );
    let by_k: Vec<(f64, f64, &str, bool)> = rows
        .iter()
        .filter(|r| K_FAMILIES.iter().any(|(f, _)| *f == r.case.truth.family))
        .filter_map(|r| {
            let s = &r.scores[0];
            r.case.truth.k.map(|k| {
                (
                    f64::from(k),
                    s.seconds,
                    r.case.truth.family.as_str(),
                    s.refused.is_none(),
                )
            })
        })
        .collect();
    panel(
        &mut out,
        610.0,
        "exact time vs k (gap 1e-k, radius 1e-k, d digits)",
        "k (log scale)",
        Axis {
            lo: 1.0,
            hi: 1e4,
            p0: 680.0,
            p1: 1170.0,
        },
        &by_k,
    );
    for (i, (family, c)) in K_FAMILIES.iter().enumerate() {
        let x = 40.0 + 128.0 * i as f64;
        let _ = writeln!(
            out,
            "<circle cx=\"{x:.1}\" cy=\"{:.1}\" r=\"5\" fill=\"{c}\"/>",
            h - 40.0
        );
        text(&mut out, x + 8.0, h - 36.0, family, 11, "start", "");
    }
    let _ = writeln!(
        out,
        "<circle cx=\"46\" cy=\"{:.1}\" r=\"6\" fill=\"none\" stroke=\"#d00000\" stroke-width=\"2\"/>",
        h - 16.0
    );
    text(
        &mut out,
        58.0,
        h - 12.0,
        "no answer within the budget (drawn at the time waited); other families grey",
        11,
        "start",
        "",
    );
    out.push_str("</svg>\n");
    out
}
