//! The SVG picture: the timeline strip and one panel per contact.

use std::fmt::Write as _;

use ccd_arith::{Int, Rat};
use ccd_scene::Scene;
use ccd_timeline::{Geometry, Instant, Outcome, State};

use crate::pose::{poses, Pose};
use crate::{escape, hex, state_color, COLOR_A, COLOR_B, GAP_COLOR};

const WIDTH: f64 = 960.0;
const STRIP_X0: f64 = 70.0;
const STRIP_X1: f64 = WIDTH - 40.0;
const STRIP_Y: f64 = 80.0;
const STRIP_H: f64 = 28.0;
const PANEL: f64 = 300.0;
const PANEL_GAP: f64 = 12.0;
const PANELS_PER_ROW: usize = 3;

/// A 2×2 symmetric matrix `[[a, b], [b, c]]`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Sym2 {
    a: f64,
    b: f64,
    c: f64,
}

/// An ellipse `{ center + z : zᵀ·shape⁻¹·z <= 1 }` in the picture's plane.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Ellipse {
    center: [f64; 2],
    shape: Sym2,
}

impl Ellipse {
    /// Semi-axes (major first) and the angle of the major one (radians).
    fn axes(&self) -> (f64, f64, f64) {
        let Sym2 { a, b, c } = self.shape;
        let mean = (a + c) / 2.0;
        let root = (((a - c) / 2.0).powi(2) + b * b).sqrt();
        let angle = 0.5 * (2.0 * b).atan2(a - c);
        (
            (mean + root).max(0.0).sqrt(),
            (mean - root).max(0.0).sqrt(),
            angle,
        )
    }
    /// Half the width and height of the bounding box.
    fn half_extent(&self) -> [f64; 2] {
        [self.shape.a.max(0.0).sqrt(), self.shape.c.max(0.0).sqrt()]
    }
}

/// The plane of a panel: coordinates `(i, j)` of the world, the axis `k`
/// dropped, through `x_k = level`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Plane {
    i: usize,
    j: usize,
    k: usize,
    level: f64,
}

impl Plane {
    /// The plane perpendicular to axis `k` through `point`.
    fn through(point: [f64; 3], k: usize) -> Plane {
        let (i, j) = match k {
            0 => (1, 2),
            1 => (0, 2),
            _ => (0, 1),
        };
        Plane {
            i,
            j,
            k,
            level: point[k],
        }
    }
    fn project(&self, x: [f64; 3]) -> [f64; 2] {
        [x[self.i], x[self.j]]
    }
    /// The outline of the body projected along axis `k` onto the plane.
    fn silhouette(&self, p: &Pose) -> Ellipse {
        let g = gram(p);
        Ellipse {
            center: self.project(p.center),
            shape: Sym2 {
                a: g[self.i][self.i],
                b: g[self.i][self.j],
                c: g[self.j][self.j],
            },
        }
    }
    /// The body cut by the plane, if the plane meets its interior: for the
    /// ellipsoid `{ c + z : zᵀ·G⁻¹·z <= 1 }` and `h = level − c_k`, the cut is
    /// centred at `c + G·e_k·h/G_kk` with shape `(1 − h²/G_kk)` times the
    /// Schur complement of `G_kk` in `G`.
    fn section(&self, p: &Pose) -> Option<Ellipse> {
        let g = gram(p);
        let (i, j, k) = (self.i, self.j, self.k);
        let h = self.level - p.center[k];
        let gkk = g[k][k];
        let rho = 1.0 - h * h / gkk;
        if rho.is_nan() || rho <= 1e-12 {
            return None;
        }
        Some(Ellipse {
            center: [
                p.center[i] + g[i][k] * h / gkk,
                p.center[j] + g[j][k] * h / gkk,
            ],
            shape: Sym2 {
                a: rho * (g[i][i] - g[i][k] * g[i][k] / gkk),
                b: rho * (g[i][j] - g[i][k] * g[j][k] / gkk),
                c: rho * (g[j][j] - g[j][k] * g[j][k] / gkk),
            },
        })
    }
}

/// `M·Mᵀ` of a pose: the ellipsoid is `{ c + z : zᵀ·(M·Mᵀ)⁻¹·z <= 1 }`.
fn gram(p: &Pose) -> [[f64; 3]; 3] {
    let m = &p.axes;
    std::array::from_fn(|r| std::array::from_fn(|s| (0..3).map(|k| m[r][k] * m[s][k]).sum()))
}

/// `x` rounded outward (`up`: towards +∞) to `digits` decimals, as text: a
/// printed lower end is never above the exact one, an upper end never below.
fn outward(x: &Rat, digits: u32, up: bool) -> String {
    let scale = Rat::from_int(Int::pow10(digits));
    let scaled = x * &scale;
    let floor = if up {
        -(-&scaled).floor()
    } else {
        scaled.floor()
    };
    (&Rat::from_int(floor) / &scale).to_decimal(digits)
}

/// Decimals enough to tell `lo` from `hi` (two more than the width asks),
/// 12 at the least and 40 at the most.
fn digits_for(width: &Rat) -> u32 {
    let w = width.to_f64();
    if w > 0.0 {
        ((-w.log10()).ceil() as i64 + 2).clamp(12, 40) as u32
    } else {
        12
    }
}

/// The ends of an instant's enclosure as outward-rounded decimals (the
/// exact rational when it is short).
fn enclosure_ends(i: &Instant) -> (String, String) {
    let short = |x: &Rat| {
        let exact = x.to_string();
        (exact.len() <= 24).then_some(exact)
    };
    if let (Some(lo), Some(hi)) = (short(&i.lo), short(&i.hi)) {
        return (lo, hi);
    }
    let d = digits_for(&i.width());
    (outward(&i.lo, d, false), outward(&i.hi, d, true))
}

/// `[lo, hi]` of an instant as outward-rounded decimals.
pub(crate) fn enclosure_text(i: &Instant) -> String {
    let (lo, hi) = enclosure_ends(i);
    if lo == hi {
        format!("exactly {lo}")
    } else {
        format!("[{lo}, {hi}]")
    }
}

/// Maps times of the span to x on the strip, exactly up to the final `f64`.
struct Strip {
    t0: Rat,
    width: Rat,
}

impl Strip {
    fn x(&self, t: &Rat) -> f64 {
        let u = ((t - &self.t0) / &self.width).to_f64();
        STRIP_X0 + u.clamp(0.0, 1.0) * (STRIP_X1 - STRIP_X0)
    }
}

/// One line of the verdict, in words.
pub(crate) fn verdict(outcome: &Outcome) -> String {
    let proven = if outcome.certified() {
        "certified"
    } else {
        "NOT everything certified"
    };
    let what = match (&outcome.first_contact, &outcome.undecided) {
        (_, Some(why)) => format!("collision-free: not decided ({why})"),
        (Some(fc), None) => format!("first contact t ≈ {}", fc.approx(12)),
        (None, None) if outcome.collision_free => "collision-free over the span".to_string(),
        (None, None) => "not collision-free".to_string(),
    };
    format!("{what}; {} contact(s); {proven}", outcome.contacts.len())
}

fn strip(out: &mut String, outcome: &Outcome) {
    let s = Strip {
        t0: outcome.span[0].clone(),
        width: &outcome.span[1] - &outcome.span[0],
    };
    let (y, h) = (STRIP_Y, STRIP_H);
    let _ = writeln!(
        out,
        r##"<rect x="{STRIP_X0}" y="{y}" width="{}" height="{h}" fill="white" stroke="#444"/>"##,
        STRIP_X1 - STRIP_X0
    );
    for seg in &outcome.timeline {
        let (x0, x1) = (s.x(&seg.start.midpoint()), s.x(&seg.end.midpoint()));
        if seg.start == seg.end {
            continue; // an isolated contact: drawn as a marker below
        }
        let hatch = if seg.certified {
            ""
        } else {
            r#" stroke-dasharray="4 3" stroke="black""#
        };
        let _ = writeln!(
            out,
            r#"<rect class="seg {}" x="{x0:.2}" y="{y}" width="{:.2}" height="{h}" fill="{}"{hatch}><title>{} from t ≈ {} to t ≈ {}{}</title></rect>"#,
            seg.state.name(),
            (x1 - x0).max(0.5),
            state_color(seg.state),
            seg.state.name(),
            seg.start.approx(12),
            seg.end.approx(12),
            if seg.certified { "" } else { " (not proven)" }
        );
    }
    for g in &outcome.gaps {
        let (x0, x1) = (s.x(&g.lo), s.x(&g.hi));
        let _ = writeln!(
            out,
            r#"<rect class="gap" x="{x0:.2}" y="{y}" width="{:.2}" height="{h}" fill="{GAP_COLOR}"><title>undecided: {}</title></rect>"#,
            (x1 - x0).max(0.5),
            escape(&g.reason)
        );
    }
    // Ends of the span.
    for (t, anchor) in [(&outcome.span[0], "start"), (&outcome.span[1], "end")] {
        let _ = writeln!(
            out,
            r#"<text x="{:.2}" y="{}" font-size="12" text-anchor="{anchor}">t = {}</text>"#,
            s.x(t),
            y + h + 16.0,
            escape(&short(t))
        );
    }
    // Contacts: a bracket over the enclosure (3 px at the least), a label.
    for (k, c) in outcome.contacts.iter().enumerate() {
        let (x0, x1) = (s.x(&c.lo), s.x(&c.hi));
        let mid = (x0 + x1) / 2.0;
        let w = (x1 - x0).max(3.0);
        let dash = if c.certified {
            ""
        } else {
            r#" stroke-dasharray="2 2""#
        };
        let _ = writeln!(
            out,
            r##"<rect class="contact" x="{:.2}" y="{}" width="{w:.2}" height="{}" fill="none" stroke="#000" stroke-width="1.5"{dash}><title>contact t{} ∈ {}</title></rect>"##,
            mid - w / 2.0,
            y - 6.0,
            h + 12.0,
            k + 1,
            enclosure_text(c)
        );
        let _ = writeln!(
            out,
            r#"<text x="{mid:.2}" y="{}" font-size="12" text-anchor="middle">t{}</text>"#,
            y - 10.0,
            k + 1
        );
    }
    if let Some(fc) = &outcome.first_contact {
        let x = s.x(&fc.midpoint());
        let anchor = if x > (STRIP_X0 + STRIP_X1) / 2.0 {
            "end"
        } else {
            "start"
        };
        // Below the strip, in a row of its own.
        let _ = writeln!(
            out,
            r##"<path d="M {x:.2} {} L {x:.2} {}" stroke="#000" stroke-width="1"/><text class="first-contact" x="{x:.2}" y="{}" font-size="13" font-weight="bold" text-anchor="{anchor}">first contact t ≈ {}</text>"##,
            y + h + 6.0,
            y + h + 22.0,
            y + h + 34.0,
            fc.approx(12)
        );
    }
}

/// A rational as short text: itself when short, else a decimal.
fn short(t: &Rat) -> String {
    let s = t.to_string();
    if s.len() <= 16 {
        s
    } else {
        t.to_decimal(12)
    }
}

fn legend(out: &mut String, y: f64) {
    let items = [
        (state_color(State::Separate), "separate"),
        (state_color(State::Touch), "touch"),
        (state_color(State::Overlap), "overlap"),
        (GAP_COLOR, "undecided"),
    ];
    let mut x = STRIP_X0;
    for (color, name) in items {
        let _ = writeln!(
            out,
            r##"<rect x="{x}" y="{}" width="14" height="14" fill="{color}" stroke="#444"/><text x="{}" y="{y}" font-size="12">{name}</text>"##,
            y - 11.0,
            x + 19.0
        );
        x += 100.0;
    }
    let _ = writeln!(
        out,
        r##"<rect x="{x}" y="{}" width="10" height="14" fill="none" stroke="#000" stroke-width="1.5"/><text x="{}" y="{y}" font-size="12">contact enclosure [lo, hi] (at least 3 px wide)</text>"##,
        y - 11.0,
        x + 16.0
    );
    for (k, (rgb, name)) in [(COLOR_A, "A"), (COLOR_B, "B")].into_iter().enumerate() {
        let x = STRIP_X1 - 150.0 + 75.0 * k as f64;
        let _ = writeln!(
            out,
            r##"<rect x="{x}" y="{}" width="14" height="14" fill="{}" stroke="#444"/><text x="{}" y="{y}" font-size="12">body {name}</text>"##,
            y - 11.0,
            hex(rgb),
            x + 19.0
        );
    }
}

/// The index of the smallest component of `n` in magnitude (the axis the
/// panel's plane is perpendicular to: the normal then lies nearly in it).
fn flattest_axis(n: &[f64; 3]) -> usize {
    (0..3)
        .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(2)
}

/// One contact's panel at `(x, y)`.
fn panel(
    out: &mut String,
    scene: &Scene,
    k: usize,
    c: &Instant,
    g: Option<&Geometry>,
    at: [f64; 2],
) {
    let t = c.midpoint().to_f64();
    let bodies = poses(scene, t);
    let (point, normal, note) = match g {
        Some(Geometry::Point {
            point,
            normal,
            certified,
        }) => (
            Some(point.midpoint().map(|x| x.to_f64())),
            Some(normal.midpoint().map(|x| x.to_f64())),
            if *certified {
                format!(
                    "point & normal certified (box width {:.1e})",
                    point.width().to_f64()
                )
            } else {
                "point & normal NOT certified".to_string()
            },
        ),
        Some(Geometry::NotASinglePoint) => (None, None, "not a single contact point".into()),
        Some(Geometry::Unknown { reason }) => (None, None, format!("no point: {reason}")),
        None => (None, None, "contact point not computed".into()),
    };
    // Without a point, cut through the midpoint of the centres, ⟂ z.
    let through = point.unwrap_or_else(|| {
        std::array::from_fn(|i| (bodies[0].center[i] + bodies[1].center[i]) / 2.0)
    });
    let plane = Plane::through(through, normal.map_or(2, |n| flattest_axis(&n)));
    let outlines = bodies.map(|b| plane.silhouette(&b));
    let cuts = bodies.map(|b| plane.section(&b));
    // Fit both outlines into the panel.
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for e in &outlines {
        let h = e.half_extent();
        for d in 0..2 {
            lo[d] = lo[d].min(e.center[d] - h[d]);
            hi[d] = hi[d].max(e.center[d] + h[d]);
        }
    }
    let inner = 230.0;
    let scale = inner / (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-300);
    let mid = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
    let (px, py) = (at[0] + PANEL / 2.0, at[1] + 196.0);
    let screen = |p: [f64; 2]| [px + scale * (p[0] - mid[0]), py - scale * (p[1] - mid[1])];
    let names = ["x", "y", "z"];
    let _ = writeln!(
        out,
        r##"<g class="panel" id="contact-{}"><rect x="{}" y="{}" width="{PANEL}" height="{}" fill="#fafafa" stroke="#999"/>"##,
        k + 1,
        at[0],
        at[1],
        PANEL + 40.0
    );
    let (lo, hi) = enclosure_ends(c);
    let lines = [
        format!("lo = {lo}"),
        format!("hi = {hi}"),
        format!(
            "plane {} = {:.6} through the point",
            names[plane.k], plane.level
        ),
        note,
    ];
    let _ = writeln!(
        out,
        r#"<text x="{}" y="{}" font-size="12" font-weight="bold">contact t{} ≈ {}{}</text>"#,
        at[0] + 6.0,
        at[1] + 14.0,
        k + 1,
        c.approx(12),
        if c.certified { "" } else { " (NOT certified)" },
    );
    for (n, line) in lines.iter().enumerate() {
        let _ = writeln!(
            out,
            r#"<text x="{}" y="{}" font-size="10">{}</text>"#,
            at[0] + 6.0,
            at[1] + 27.0 + 12.0 * n as f64,
            escape(line)
        );
    }
    let draw = |out: &mut String, e: &Ellipse, style: &str| {
        let (ra, rb, angle) = e.axes();
        let [cx, cy] = screen(e.center);
        let _ = writeln!(
            out,
            r#"<ellipse cx="{cx:.2}" cy="{cy:.2}" rx="{:.2}" ry="{:.2}" transform="rotate({:.3} {cx:.2} {cy:.2})" {style}/>"#,
            ra * scale,
            rb * scale,
            -angle.to_degrees()
        );
    };
    for (b, rgb) in [COLOR_A, COLOR_B].into_iter().enumerate() {
        let color = hex(rgb);
        draw(
            out,
            &outlines[b],
            &format!(r#"fill="none" stroke="{color}" stroke-dasharray="5 4""#),
        );
        if let Some(cut) = &cuts[b] {
            draw(
                out,
                cut,
                &format!(
                    r#"class="section" fill="{color}" fill-opacity="0.45" stroke="{color}" stroke-width="1.5""#
                ),
            );
        }
        let [cx, cy] = screen(outlines[b].center);
        let _ = writeln!(
            out,
            r##"<text x="{cx:.2}" y="{cy:.2}" font-size="13" font-weight="bold" fill="#222" text-anchor="middle">{}</text>"##,
            ["A", "B"][b]
        );
    }
    if let (Some(p), Some(n)) = (point, normal) {
        let [x, y] = screen(plane.project(p));
        let d = plane.project(n);
        let len = (d[0] * d[0] + d[1] * d[1]).sqrt();
        if len > 1e-12 {
            let (ux, uy) = (d[0] / len * 50.0, -d[1] / len * 50.0);
            let _ = writeln!(
                out,
                r##"<path class="normal" d="M {x:.2} {y:.2} L {:.2} {:.2}" stroke="#000" stroke-width="2" marker-end="url(#arrow)"/>"##,
                x + ux,
                y + uy
            );
        }
        let _ = writeln!(
            out,
            r##"<circle class="point" cx="{x:.2}" cy="{y:.2}" r="4" fill="#000" stroke="#fff" stroke-width="1.5"><title>contact point ≈ ({:.12}, {:.12}, {:.12}); A's outward normal ≈ ({:.6}, {:.6}, {:.6})</title></circle>"##,
            p[0], p[1], p[2], n[0], n[1], n[2]
        );
    }
    let _ = writeln!(
        out,
        r##"<text x="{}" y="{}" font-size="11" fill="#555">{} →</text><text x="{}" y="{}" font-size="11" fill="#555">{} ↑</text></g>"##,
        at[0] + PANEL - 30.0,
        at[1] + PANEL + 34.0,
        names[plane.i],
        at[0] + 6.0,
        at[1] + PANEL + 34.0,
        names[plane.j]
    );
}

/// The SVG picture of a query (see the crate docs): `title` heads it.
pub fn svg(scene: &Scene, outcome: &Outcome, title: &str) -> String {
    let rows = outcome.contacts.len().div_ceil(PANELS_PER_ROW);
    let panels_y = 200.0;
    let height = panels_y + rows as f64 * (PANEL + 40.0 + PANEL_GAP) + 10.0;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" font-family="sans-serif">
<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M 0 0 L 10 5 L 0 10 z" fill="#000"/></marker></defs>
<rect width="100%" height="100%" fill="white"/>
<text x="{STRIP_X0}" y="24" font-size="16" font-weight="bold">{}</text>
<text x="{STRIP_X0}" y="44" font-size="13">{}</text>"##,
        escape(if title.is_empty() { "ccd-exact" } else { title }),
        escape(&verdict(outcome))
    );
    strip(&mut out, outcome);
    legend(&mut out, STRIP_Y + STRIP_H + 62.0);
    for (k, c) in outcome.contacts.iter().enumerate() {
        let (row, col) = (k / PANELS_PER_ROW, k % PANELS_PER_ROW);
        let at = [
            STRIP_X0 - 50.0 + col as f64 * (PANEL + PANEL_GAP),
            panels_y + row as f64 * (PANEL + 40.0 + PANEL_GAP),
        ];
        panel(&mut out, scene, k, c, outcome.geometry.get(k), at);
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn outward_rounding_contains_the_number() {
        let x = Rat::from_frac(2, 3);
        assert_eq!(outward(&x, 3, false), "0.666");
        assert_eq!(outward(&x, 3, true), "0.667");
        assert_eq!(outward(&-x.clone(), 3, false), "-0.667");
        assert_eq!(outward(&Rat::from_frac(1, 4), 2, true), "0.25");
    }

    #[test]
    fn a_section_through_the_centre_is_the_middle_ellipse() {
        let pose = Pose {
            center: [1.0, 2.0, 3.0],
            axes: [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 3.0]],
        };
        let plane = Plane::through([0.0, 0.0, 3.0], 2);
        let cut = plane.section(&pose).unwrap();
        assert_eq!(cut.center, [1.0, 2.0]);
        let (ra, rb, _) = cut.axes();
        assert!((ra - 2.0).abs() < 1e-12 && (rb - 1.0).abs() < 1e-12);
        // Halfway up the z semi-axis the cut shrinks by sqrt(3)/2.
        let cut = Plane::through([0.0, 0.0, 4.5], 2).section(&pose).unwrap();
        assert!((cut.axes().0 - 3f64.sqrt()).abs() < 1e-12);
        assert!(Plane::through([0.0, 0.0, 6.5], 2).section(&pose).is_none());
    }
}
