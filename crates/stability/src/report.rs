//! The report: run every method on every case, tabulate (Markdown) and
//! chart (SVG, drawn with `plotters`; its text is written as plain SVG
//! `<text>` so no system font is needed).

use crate::families::FAMILIES;
use crate::harness::{evaluate_with, Guard, Method, Score};
use crate::{Case, StabilityError};
use plotters::prelude::*;
use std::collections::BTreeMap;
use std::fmt::Write;

/// All methods' scores on one case.
#[derive(Clone, Debug)]
pub struct Row {
    /// The case.
    pub case: Case,
    /// One score per method of [`Method::ALL`], in order.
    pub scores: Vec<Score>,
}

/// Runs every method of [`Method::ALL`] on every case (each method's
/// first query under `guard`, if any); `progress` hears about each case as
/// it finishes.
pub fn run_all(
    cases: Vec<Case>,
    guard: Option<&Guard>,
    mut progress: impl FnMut(&Row),
) -> Vec<Row> {
    cases
        .into_iter()
        .map(|case| {
            let scores = Method::ALL
                .iter()
                .map(|&m| evaluate_with(&case, m, guard))
                .collect();
            let row = Row { case, scores };
            progress(&row);
            row
        })
        .collect()
}

/// Median of a list (0 when empty).
fn median(mut xs: Vec<f64>) -> f64 {
    if xs.is_empty() {
        return 0.0;
    }
    xs.sort_by(f64::total_cmp);
    xs[xs.len() / 2]
}

/// Seconds in a readable unit.
pub(crate) fn secs(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn err(e: Option<f64>) -> String {
    match e {
        None => "—".into(),
        Some(0.0) => "0".into(),
        Some(x) => format!("{x:.0e}"),
    }
}

/// The case name without its family prefix.
fn short(case: &Case) -> &str {
    case.name
        .strip_prefix(&case.truth.family)
        .map_or(case.name.as_str(), |s| s.trim_start_matches('-'))
}

/// The wrong cases of one family, compressed: cases `kNN-tag` (or
/// `jN-tag`) are grouped by tag into runs of the parameter, e.g.
/// `overlap k=9–30`.
fn which(rows: &[(&Case, &Score)]) -> String {
    let mut by_tag: BTreeMap<String, Vec<u32>> = BTreeMap::new();
    let mut plain = Vec::new();
    for (case, _) in rows {
        let name = short(case);
        // `k07-overlap`, `j3-touch`, `n12`: a parameter, then maybe a tag.
        let (param, tag) = name.split_once('-').unwrap_or((name, ""));
        let var = param.chars().next().filter(|c| "kjn".contains(*c));
        match (var, param.get(1..).and_then(|d| d.parse::<u32>().ok())) {
            (Some(var), Some(k)) => by_tag.entry(format!("{tag} {var}")).or_default().push(k),
            _ => plain.push(name.to_string()),
        }
    }
    let mut parts = plain;
    for (tag, mut ks) in by_tag {
        ks.sort_unstable();
        let mut runs: Vec<(u32, u32)> = Vec::new();
        for k in ks {
            match runs.last_mut() {
                Some(r) if r.1 + 1 == k => r.1 = k,
                _ => runs.push((k, k)),
            }
        }
        let (name, var) = tag.split_at(tag.len() - 1);
        let list: Vec<String> = runs
            .iter()
            .map(|&(a, b)| {
                if a == b {
                    format!("{a}")
                } else {
                    format!("{a}–{b}")
                }
            })
            .collect();
        parts.push(format!("{}{var}={}", name.trim_start(), list.join(",")));
    }
    if parts.is_empty() {
        "none".into()
    } else {
        parts.join("; ")
    }
}

/// The Markdown tables: overall per method, per family and method, and
/// per `k` for the families that have one.
pub fn markdown(rows: &[Row]) -> String {
    let mut md = String::new();
    let n_methods = Method::ALL.len();
    let _ = writeln!(md, "### Overall ({} scenes)\n", rows.len());
    let _ = writeln!(md, "| method | wrong verdict | wrong contact count | wrong (either) | median time / query | max time / query | median contact-time error | worst contact-time error (right count) |");
    let _ = writeln!(
        md,
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"
    );
    for (mi, m) in Method::ALL.iter().enumerate() {
        let s: Vec<&Score> = rows.iter().map(|r| &r.scores[mi]).collect();
        let n = s.len().max(1) as f64;
        let verdict = s.iter().filter(|x| !x.verdict_ok).count();
        let count = s.iter().filter(|x| !x.count_ok).count();
        let wrong = s.iter().filter(|x| x.wrong()).count();
        let errs: Vec<f64> = s.iter().filter_map(|x| x.time_error).collect();
        let worst = errs
            .iter()
            .copied()
            .fold(None, |a: Option<f64>, e| Some(a.map_or(e, |a| a.max(e))));
        let _ = writeln!(
            md,
            "| {} | {verdict} | {count} | {wrong} ({:.0}%) | {} | {} | {} | {} |",
            m.label(),
            100.0 * wrong as f64 / n,
            secs(median(s.iter().map(|x| x.seconds).collect())),
            secs(s.iter().map(|x| x.seconds).fold(0.0, f64::max)),
            err((!errs.is_empty()).then(|| median(errs.clone()))),
            err(worst),
        );
    }
    let _ = writeln!(md, "\n### Per family\n");
    let _ = writeln!(md, "\"wrong\" = wrong collision-free verdict or wrong number of contacts; the cases listed are the wrong ones. Contact-time error: worst `|estimate − true instant|` over the cases with the right count (estimate = midpoint of the reported enclosure, or the reporting sample).\n");
    let _ = writeln!(md, "| family | scenes | method | wrong | which | worst contact-time error | median time / query |");
    let _ = writeln!(md, "| --- | ---: | --- | ---: | --- | ---: | ---: |");
    for (family, _) in FAMILIES {
        let fam: Vec<&Row> = rows
            .iter()
            .filter(|r| r.case.truth.family == *family)
            .collect();
        if fam.is_empty() {
            continue;
        }
        for mi in 0..n_methods {
            let pairs: Vec<(&Case, &Score)> =
                fam.iter().map(|r| (&r.case, &r.scores[mi])).collect();
            let wrong: Vec<(&Case, &Score)> =
                pairs.iter().copied().filter(|(_, s)| s.wrong()).collect();
            let worst = pairs
                .iter()
                .filter_map(|(_, s)| s.time_error)
                .fold(None, |a: Option<f64>, e| Some(a.map_or(e, |a| a.max(e))));
            let _ = writeln!(
                md,
                "| {} | {} | {} | {} | {} | {} | {} |",
                if mi == 0 { *family } else { "" },
                if mi == 0 {
                    fam.len().to_string()
                } else {
                    String::new()
                },
                Method::ALL[mi].label(),
                wrong.len(),
                which(&wrong),
                err(worst),
                secs(median(pairs.iter().map(|(_, s)| s.seconds).collect())),
            );
        }
    }
    let by_k = ["graze-spheres", "graze-ellipsoids", "affine-cluster"];
    for &family in by_k.iter().chain(crate::families::GENERIC) {
        let fam: Vec<&Row> = rows
            .iter()
            .filter(|r| r.case.truth.family == family && r.case.truth.k.is_some())
            .collect();
        if fam.is_empty() {
            continue;
        }
        let _ = writeln!(md, "\n### {family}, by k\n");
        let _ = writeln!(
            md,
            "Each cell: ✓ right or ✗ wrong (contacts found/true), then the contact-time error.\n"
        );
        let mut head = "| k | case |".to_string();
        let mut rule = "| ---: | --- |".to_string();
        for m in Method::ALL {
            let _ = write!(head, " {} |", m.label());
            rule.push_str(" --- |");
        }
        let _ = writeln!(md, "{head}\n{rule}");
        for r in fam {
            let mut line = format!("| {} | {} |", r.case.truth.k.unwrap_or(0), short(&r.case));
            for s in &r.scores {
                let mark = if s.wrong() {
                    format!("✗ {}/{}", s.found, r.case.truth.contacts.len())
                } else {
                    "✓".into()
                };
                let e = s
                    .time_error
                    .map(|e| format!(" {}", err(Some(e))))
                    .unwrap_or_default();
                let _ = write!(line, " {mark}{e} |");
            }
            let _ = writeln!(md, "{line}");
        }
    }
    md
}

/// Replaces the text between `<!-- BEGIN GENERATED -->` and
/// `<!-- END GENERATED -->` in `doc` (appending the markers if missing).
pub fn splice(doc: &str, generated: &str) -> String {
    const BEGIN: &str = "<!-- BEGIN GENERATED -->";
    const END: &str = "<!-- END GENERATED -->";
    let body = format!("{BEGIN}\n{generated}\n{END}");
    match (doc.find(BEGIN), doc.find(END)) {
        (Some(a), Some(b)) if a < b => format!("{}{body}{}", &doc[..a], &doc[b + END.len()..]),
        _ => format!("{doc}\n{body}\n"),
    }
}

/// Method colours (colour-blind safe).
fn colour(m: Method) -> RGBColor {
    match m {
        Method::Exact => RGBColor(0, 114, 178),
        Method::Float => RGBColor(213, 94, 0),
        Method::Sampled(100) => RGBColor(0, 158, 115),
        Method::Sampled(_) => RGBColor(204, 121, 167),
    }
}

fn hex(c: RGBColor) -> String {
    format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2)
}

/// Floor for plotting errors of exactly zero on a log axis.
const ERROR_FLOOR: f64 = 1e-20;

/// One panel's frame: ranges and labels.
struct Panel {
    title: &'static str,
    y_label: &'static str,
    y_log: bool,
    y: (f64, f64),
}

/// An SVG text element.
fn text(x: i32, y: i32, s: &str, size: u32, anchor: &str, extra: &str) -> String {
    let esc = s
        .replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;");
    format!(
        "<text x=\"{x}\" y=\"{y}\" font-family=\"sans-serif\" font-size=\"{size}\" text-anchor=\"{anchor}\" {extra}>{esc}</text>\n"
    )
}

/// The chart: left, contact-time error against time per query (one dot
/// per scene and method, errors of 0 drawn at 10⁻²⁰); right, the share of
/// wrong answers against time per query (one dot per family and method,
/// a large dot per method overall). Both x axes are logarithmic.
pub fn chart(rows: &[Row]) -> Result<String, StabilityError> {
    let (w, h) = (1200u32, 560u32);
    let mut svg = String::new();
    let mut labels = String::new();
    let x_range = (1e-5f64, 10.0f64);
    let panels = [
        Panel {
            title: "contact-time error vs time (per scene with the right contact count)",
            y_label: "|t_reported − t_true|   (error 0 drawn at 1e-20)",
            y_log: true,
            y: (ERROR_FLOOR / 10.0, 1.0),
        },
        Panel {
            title: "wrong answers vs time (small: per family; large: all scenes)",
            y_label: "wrong verdict or contact count (%)",
            y_log: false,
            y: (-2.0, 102.0),
        },
    ];
    {
        let root = SVGBackend::with_string(&mut svg, (w, h)).into_drawing_area();
        let ce = |e: DrawingAreaErrorKind<_>| StabilityError::Chart(e.to_string());
        root.fill(&WHITE).map_err(ce)?;
        let areas = root.margin(40, 90, 20, 20).split_evenly((1, 2));
        for (pi, (area, panel)) in areas.iter().zip(&panels).enumerate() {
            let area = area.margin(0, 20, 70, 10);
            let x_spec = (x_range.0..x_range.1).log_scale();
            let decades = |lo: f64, hi: f64| {
                let (a, b) = (lo.log10().ceil() as i32, hi.log10().floor() as i32);
                (a..=b).map(|e| 10f64.powi(e)).collect::<Vec<f64>>()
            };
            let grey = RGBColor(220, 220, 220);
            // Draw on a log-x chart; the y axis is log or linear per panel.
            macro_rules! draw_panel {
                ($chart:expr) => {{
                    let mut chart = $chart;
                    let y_ticks: Vec<f64> = if panel.y_log {
                        decades(panel.y.0, panel.y.1)
                            .into_iter()
                            .filter(|v| v.log10() as i32 % 2 == 0)
                            .collect()
                    } else {
                        vec![0.0, 20.0, 40.0, 60.0, 80.0, 100.0]
                    };
                    for &x in &decades(x_range.0, x_range.1) {
                        chart
                            .draw_series(LineSeries::new(
                                vec![(x, (panel.y.0)), (x, (panel.y.1))],
                                &grey,
                            ))
                            .map_err(ce)?;
                        let (px, py) = chart.backend_coord(&(x, (panel.y.0)));
                        let label = match x.log10().round() as i32 {
                            0 => "1 s".to_string(),
                            -3 => "1 ms".to_string(),
                            -6 => "1 µs".to_string(),
                            e => format!("1e{e}"),
                        };
                        labels.push_str(&text(px, py + 16, &label, 11, "middle", ""));
                    }
                    for &y in &y_ticks {
                        chart
                            .draw_series(LineSeries::new(
                                vec![(x_range.0, (y)), (x_range.1, (y))],
                                &grey,
                            ))
                            .map_err(ce)?;
                        let (px, py) = chart.backend_coord(&(x_range.0, (y)));
                        let label = if panel.y_log {
                            format!("1e{}", y.log10().round() as i32)
                        } else {
                            format!("{y:.0}")
                        };
                        labels.push_str(&text(px - 6, py + 4, &label, 11, "end", ""));
                    }
                    // Frame.
                    let (y0, y1) = ((panel.y.0), (panel.y.1));
                    chart
                        .draw_series(LineSeries::new(
                            vec![
                                (x_range.0, y0),
                                (x_range.1, y0),
                                (x_range.1, y1),
                                (x_range.0, y1),
                                (x_range.0, y0),
                            ],
                            &BLACK,
                        ))
                        .map_err(ce)?;
                    for (mi, &m) in Method::ALL.iter().enumerate() {
                        let c = colour(m);
                        if pi == 0 {
                            let pts: Vec<(f64, f64)> = rows
                                .iter()
                                .filter_map(|r| {
                                    let s = &r.scores[mi];
                                    s.time_error
                                        .map(|e| (s.seconds.max(x_range.0), (e.max(ERROR_FLOOR))))
                                })
                                .collect();
                            chart
                                .draw_series(
                                    pts.into_iter()
                                        .map(|p| Circle::new(p, 3, c.mix(0.55).filled())),
                                )
                                .map_err(ce)?;
                        } else {
                            let mut fam_pts = Vec::new();
                            for (family, _) in FAMILIES {
                                let s: Vec<&Score> = rows
                                    .iter()
                                    .filter(|r| r.case.truth.family == *family)
                                    .map(|r| &r.scores[mi])
                                    .collect();
                                if s.is_empty() {
                                    continue;
                                }
                                let wrong =
                                    s.iter().filter(|x| x.wrong()).count() as f64 / s.len() as f64;
                                fam_pts.push((
                                    median(s.iter().map(|x| x.seconds).collect()),
                                    100.0 * wrong,
                                ));
                            }
                            let all: Vec<&Score> = rows.iter().map(|r| &r.scores[mi]).collect();
                            let rate = 100.0 * all.iter().filter(|x| x.wrong()).count() as f64
                                / all.len().max(1) as f64;
                            let t = median(all.iter().map(|x| x.seconds).collect());
                            chart
                                .draw_series(fam_pts.into_iter().map(|(x, y)| {
                                    Circle::new((x.max(x_range.0), (y)), 4, c.mix(0.6).filled())
                                }))
                                .map_err(ce)?;
                            chart
                                .draw_series(std::iter::once(Circle::new(
                                    (t.max(x_range.0), (rate)),
                                    10,
                                    c.filled(),
                                )))
                                .map_err(ce)?;
                            let (px, py) = chart.backend_coord(&(t.max(x_range.0), (rate)));
                            labels.push_str(&text(
                                px + 14,
                                py + 4,
                                &format!("{} {rate:.0}%", m.label()),
                                12,
                                "start",
                                &format!("fill=\"{}\" font-weight=\"bold\"", hex(c)),
                            ));
                        }
                    }
                    let (l, t) = chart.backend_coord(&(x_range.0, y1));
                    let (r, b) = chart.backend_coord(&(x_range.1, y0));
                    labels.push_str(&text(
                        (l + r) / 2,
                        t - 10,
                        panel.title,
                        14,
                        "middle",
                        "font-weight=\"bold\"",
                    ));
                    labels.push_str(&text(
                        (l + r) / 2,
                        b + 36,
                        "time per query (log scale, median of up to 5 runs)",
                        12,
                        "middle",
                        "",
                    ));
                    let cy = (t + b) / 2;
                    labels.push_str(&text(
                        l - 48,
                        cy,
                        panel.y_label,
                        12,
                        "middle",
                        &format!("transform=\"rotate(-90 {} {cy})\"", l - 48),
                    ));
                }};
            }
            if panel.y_log {
                let chart = ChartBuilder::on(&area)
                    .build_cartesian_2d(x_spec, (panel.y.0..panel.y.1).log_scale())
                    .map_err(ce)?;
                draw_panel!(chart);
            } else {
                let chart = ChartBuilder::on(&area)
                    .build_cartesian_2d(x_spec, panel.y.0..panel.y.1)
                    .map_err(ce)?;
                draw_panel!(chart);
            }
        }
        // Legend.
        for (mi, &m) in Method::ALL.iter().enumerate() {
            let x = 80 + 260 * mi as i32;
            let y = h as i32 - 24;
            root.draw(&Circle::new((x, y - 4), 6, colour(m).filled()))
                .map_err(ce)?;
            labels.push_str(&text(x + 12, y, &m.label(), 13, "start", ""));
        }
        root.present().map_err(ce)?;
    }
    let end = svg
        .rfind("</svg>")
        .ok_or_else(|| StabilityError::Chart("no </svg> in the output".into()))?;
    svg.insert_str(end, &labels);
    Ok(svg)
}
