//! `ccd-exact SCENE.toml [--json] [--digits N] [--first-contact] [--no-geometry]`

use ccd_exact::{run_toml, to_json, Arithmetic, Geometry, Options, Outcome};
use ccd_scene::{Limit, SceneError, MAX_INPUT_BYTES};
use std::io::Write;
use std::process::ExitCode;

const HELP: &str = "\
ccd-exact: exact, certified continuous collision detection for two moving ellipsoids

USAGE:
    ccd-exact SCENE.toml [--json] [--digits N] [--first-contact] [--arithmetic exact|float]
              [--no-geometry]

OPTIONS:
    --json            print the result as JSON (scene-format.md, format 1)
    --digits N        enclose each contact instant to 1e-N of the span (default 15)
    --first-contact   stop at the earliest instant the bodies are not separate
    --arithmetic M    exact (default: every answer certified) or float (the
                      paper's f64 Bernstein solver: faster, NOT certified)
    --no-geometry     skip the contact point and normal of each contact
    -h, --help        this help
    -V, --version     the version

EXAMPLES:
    ccd-exact tests/scenes/paper-example-5-1.toml
    ccd-exact tests/scenes/rigid-tumbling.toml --json --digits 30
    ccd-exact tests/scenes/paper-example-5-1.toml --first-contact
    ccd-exact benches/scenes/affine-deg2.toml --arithmetic float

Exit status: 0 on success, 2 on bad input (the message names the field).";

struct Args {
    path: String,
    json: bool,
    options: Options,
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Option<Args>, String> {
    let mut path = None;
    let mut json = false;
    let mut options = Options::default();
    while let Some(a) = args.next() {
        match a.as_str() {
            "-h" | "--help" => return Ok(None),
            "-V" | "--version" => {
                println!(
                    "ccd-exact {} ({} integers)",
                    env!("CARGO_PKG_VERSION"),
                    ccd_arith::BACKEND
                );
                std::process::exit(0);
            }
            "--json" => json = true,
            "--first-contact" => options.first_contact_only = true,
            "--no-geometry" => options.contact_geometry = false,
            "--arithmetic" => {
                options.arithmetic = match args.next().as_deref() {
                    Some("exact") => Arithmetic::Exact,
                    Some("float") => Arithmetic::Float,
                    other => {
                        return Err(format!(
                            "option `--arithmetic`: expected `exact` or `float`, found `{}`",
                            other.unwrap_or("")
                        ))
                    }
                }
            }
            "--digits" => {
                let v = args.next().ok_or("option `--digits` needs a value")?;
                options.digits = v
                    .parse()
                    .ok()
                    .filter(|d| *d <= Options::MAX_DIGITS)
                    .ok_or_else(|| {
                        format!(
                            "option `--digits`: `{v}` is not a whole number from 0 to {}",
                            Options::MAX_DIGITS
                        )
                    })?;
            }
            s if s.starts_with('-') => return Err(format!("unknown option `{s}` (see --help)")),
            s => {
                if path.replace(s.to_string()).is_some() {
                    return Err("more than one scene file given".into());
                }
            }
        }
    }
    let path = path.ok_or("no scene file given (see --help)")?;
    Ok(Some(Args {
        path,
        json,
        options,
    }))
}

/// The human-readable result: the timeline, the contacts, and in words
/// what is proven and what is not (`float`: the float mode ran, so nothing
/// is).
fn table(out: &Outcome, options: &Options) -> String {
    use std::fmt::Write as _;
    let float = options.arithmetic == Arithmetic::Float;
    let s = &out.stats;
    let mut t = String::new();
    if s.path == ccd_exact::Path::Interval {
        let _ = writeln!(
            t,
            "span [{}, {}]; non-rational motion: certified interval enclosures ({})\n",
            out.span[0],
            out.span[1],
            s.branch_name()
        );
    } else {
        let sr0 = s.deg_sr0.map_or("≡ 0".into(), |d| d.to_string());
        let _ = writeln!(
            t,
            "span [{}, {}]; deg_t f = {}, deg sr0 = {sr0}, branch: {}\n",
            out.span[0],
            out.span[1],
            s.deg_f,
            s.branch_name()
        );
    }
    let _ = writeln!(t, "  {:<9} {:>20}  {:>20}", "state", "from", "to");
    let unproven = |ok: bool| if ok || float { "" } else { "  (not proven)" };
    let mut gaps = out.gaps.iter().peekable();
    let gap_line = |t: &mut String, g: &ccd_exact::Gap| {
        let _ = writeln!(
            t,
            "  {:<9} {:>20}  {:>20}  (not covered: {})",
            "undecided",
            g.lo.to_decimal(12),
            g.hi.to_decimal(12),
            g.reason
        );
        if let Some(w) = &g.witness {
            let _ = writeln!(t, "  {:<9} proven {} at t = {}", "", w.state.name(), w.t);
        }
    };
    let show = |b: &ccd_exact::Box3| b.approx(12).join(", ");
    // The point and normal at one end of a touch segment, or one contact.
    let geometry_lines = |t: &mut String, indent: &str, g: &Geometry| match g {
        Geometry::Point {
            point,
            normal,
            certified,
        } => {
            let mark = if *certified { "" } else { "  (NOT certified)" };
            let _ = writeln!(
                t,
                "{indent}point  ≈ ({}){mark}  (box width {:.1e})\n{indent}normal ≈ ({})  (A's outward normal, largest component ±1)",
                show(point),
                point.width().to_f64(),
                show(normal)
            );
        }
        Geometry::NotASinglePoint => {
            let _ = writeln!(t, "{indent}point: not a single point");
        }
        Geometry::Unknown { reason } => {
            let _ = writeln!(t, "{indent}point: not computed ({reason})");
        }
    };
    for (k, seg) in out.timeline.iter().enumerate() {
        while let Some(g) = gaps.next_if(|g| g.hi <= seg.start.lo) {
            gap_line(&mut t, g);
        }
        let _ = writeln!(
            t,
            "  {:<9} {:>20}  {:>20}{}",
            seg.state.name(),
            seg.start.approx(12),
            seg.end.approx(12),
            unproven(seg.certified)
        );
        if let Some(Some([start, end])) = out.segment_geometry.get(k) {
            t.push_str("            at the start:\n");
            geometry_lines(&mut t, "              ", start);
            if seg.start != seg.end {
                t.push_str("            at the end:\n");
                geometry_lines(&mut t, "              ", end);
            }
        }
    }
    for g in gaps {
        gap_line(&mut t, g);
    }
    t.push('\n');
    if out.contacts.is_empty() {
        t.push_str("contacts: none\n");
    }
    for (k, c) in out.contacts.iter().enumerate() {
        let mark = if c.certified { "" } else { "  (NOT certified)" };
        let _ = writeln!(
            t,
            "contact {} ≈ {}{mark}\n    lo = {}\n    hi = {}",
            k + 1,
            c.approx(15),
            c.lo,
            c.hi
        );
        if let Some(g) = out.geometry.get(k) {
            geometry_lines(&mut t, "    ", g);
        }
    }
    match (&out.first_contact, &out.undecided) {
        (Some(fc), _) => {
            let mark = unproven(fc.certified);
            let _ = writeln!(t, "first contact ≈ {}{mark}", fc.approx(15));
        }
        (None, _) if out.collision_free => t.push_str("collision-free over the span\n"),
        _ => {}
    }
    if let Some(why) = &out.undecided {
        let _ = writeln!(
            t,
            "collision-free: NOT decided (neither separation over the span nor a collision is proven: {why})"
        );
    } else if !float && !out.collision_free && !out.certified() {
        t.push_str("a collision is proven (a certified touch or overlap)\n");
    }
    if !out.gaps.is_empty() {
        let _ = writeln!(
            t,
            "timeline NOT complete: {} piece(s) of the span undecided within the effort budget",
            out.gaps.len()
        );
    } else if options.first_contact_only && !out.complete {
        t.push_str("(first contact only: the timeline stops there)\n");
    }
    if float {
        if !out.certified() {
            t.push_str(
                "NOT certified: float arithmetic (run with --arithmetic exact for proven answers)\n",
            );
        }
    } else if !out.certified() {
        let counts = [
            (
                out.timeline.iter().filter(|s| !s.certified).count(),
                "segment state(s) not proven",
            ),
            (
                out.contacts.iter().filter(|c| !c.certified).count(),
                "contact(s) not certified",
            ),
            (out.gaps.len(), "piece(s) of the span undecided"),
        ];
        let what: Vec<String> = counts
            .iter()
            .filter(|(n, _)| *n > 0)
            .map(|(n, what)| format!("{n} {what}"))
            .collect();
        let _ = writeln!(t, "NOT everything is proven: {}", what.join(", "));
    }
    t
}

/// The text of the scene file at `path`, reading at most
/// [`MAX_INPUT_BYTES`] + 1 bytes: a longer file (or `/dev/zero`) is refused
/// with the scene format's size error, never read whole.
fn read_scene(path: &str) -> Result<String, String> {
    use std::io::Read;
    let cannot = |e: &dyn std::fmt::Display| format!("cannot read `{path}`: {e}");
    let file = std::fs::File::open(path).map_err(|e| cannot(&e))?;
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES as u64 + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| cannot(&e))?;
    if bytes.len() > MAX_INPUT_BYTES {
        let e = SceneError::TooLarge {
            field: "<file>".into(),
            limit: Limit::InputBytes,
        };
        return Err(format!("{path}: {e}"));
    }
    String::from_utf8(bytes).map_err(|e| cannot(&e))
}

fn main() -> ExitCode {
    let args = match parse_args(std::env::args().skip(1)) {
        Ok(Some(a)) => a,
        Ok(None) => {
            println!("{HELP}");
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            eprintln!("ccd-exact: {e}");
            return ExitCode::from(2);
        }
    };
    let text = match read_scene(&args.path) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("ccd-exact: {e}");
            return ExitCode::from(2);
        }
    };
    match run_toml(&text, &args.options) {
        Ok(out) => {
            let text = if args.json {
                serde_json::to_string_pretty(&to_json(&out)).unwrap_or_default() + "\n"
            } else {
                table(&out, &args.options)
            };
            // A reader that stops early (`| head`) is not an error of ours.
            match std::io::stdout().lock().write_all(text.as_bytes()) {
                Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
                    eprintln!("ccd-exact: cannot write the result: {e}");
                    ExitCode::from(1)
                }
                _ => ExitCode::SUCCESS,
            }
        }
        Err(e) => {
            eprintln!("ccd-exact: {}: {e}", args.path);
            ExitCode::from(2)
        }
    }
}
