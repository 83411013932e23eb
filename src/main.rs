//! `ccd-exact SCENE.toml [--json] [--digits N] [--first-contact] [--no-geometry]
//! [--svg FILE] [--html FILE]`

use ccd_exact::{run, to_json, Arithmetic, Geometry, Options, Outcome, Scene};
use ccd_scene::{Limit, SceneError, MAX_INPUT_BYTES};
use std::io::Write;
use std::process::ExitCode;

const HELP: &str = "\
ccd-exact: exact, certified continuous collision detection for two moving ellipsoids

USAGE:
    ccd-exact SCENE.toml [--json] [--digits N] [--first-contact] [--arithmetic exact|float]
              [--no-geometry] [--svg FILE] [--html FILE]

OPTIONS:
    --json            print the result as JSON (scene-format.md, format 1)
    --digits N        enclose each contact instant to 1e-N of the span (default 15)
    --first-contact   stop at the earliest instant the bodies are not separate
    --arithmetic M    exact (default: every answer certified) or float (the
                      paper's f64 Bernstein solver: faster, NOT certified)
    --no-geometry     skip the contact point and normal of each contact
    --svg FILE        also draw the query as an SVG picture: the timeline strip
                      and each contact's section through its point
    --html FILE       also write a self-contained HTML page that animates the
                      two bodies over the span (time slider, contacts marked)
    -h, --help        this help
    -V, --version     the version

EXAMPLES:
    ccd-exact tests/scenes/paper-example-5-1.toml
    ccd-exact tests/scenes/rigid-tumbling.toml --json --digits 30
    ccd-exact tests/scenes/paper-example-5-1.toml --first-contact
    ccd-exact tests/scenes/paper-example-5-1.toml --svg 5-1.svg --html 5-1.html
    ccd-exact benches/scenes/affine-deg2.toml --arithmetic float

Exit status: 0 on success, 2 on bad input (the message names the field).";

struct Args {
    path: String,
    json: bool,
    options: Options,
    /// Where to write the pictures (`--svg`, `--html`), if asked.
    pictures: Pictures,
}

/// Draws a query: `ccd_picture::svg` or `ccd_picture::html`.
type Picture = fn(&Scene, &Outcome, &str) -> String;

/// The files `--svg` and `--html` name.
#[derive(Default)]
struct Pictures {
    svg: Option<String>,
    html: Option<String>,
}

impl Pictures {
    /// Writes the pictures asked for; the error names the file.
    fn write(&self, title: &str, scene: &Scene, out: &Outcome) -> Result<(), String> {
        let draw: [(&Option<String>, Picture); 2] = [
            (&self.svg, ccd_picture::svg),
            (&self.html, ccd_picture::html),
        ];
        for (file, picture) in draw {
            if let Some(file) = file {
                std::fs::write(file, picture(scene, out, title))
                    .map_err(|e| format!("cannot write `{file}`: {e}"))?;
            }
        }
        Ok(())
    }
}

fn parse_args(mut args: impl Iterator<Item = String>) -> Result<Option<Args>, String> {
    let mut path = None;
    let mut json = false;
    let mut options = Options::default();
    let mut pictures = Pictures::default();
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
            "--svg" | "--html" => {
                let file = args
                    .next()
                    .ok_or(format!("option `{a}` needs a file name"))?;
                let slot = if a == "--svg" {
                    &mut pictures.svg
                } else {
                    &mut pictures.html
                };
                *slot = Some(file);
            }
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
        pictures,
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
    for seg in &out.timeline {
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
        match out.geometry.get(k) {
            Some(Geometry::Point {
                point,
                normal,
                certified,
            }) => {
                let mark = if *certified { "" } else { "  (NOT certified)" };
                let show = |b: &ccd_exact::Box3| b.approx(12).join(", ");
                let _ = writeln!(
                    t,
                    "    point  ≈ ({}){mark}  (box width {:.1e})\n    normal ≈ ({})  (A's outward normal, largest component ±1)",
                    show(point),
                    point.width().to_f64(),
                    show(normal)
                );
            }
            Some(Geometry::NotASinglePoint) => {
                t.push_str("    point: not a single point\n");
            }
            Some(Geometry::Unknown { reason }) => {
                let _ = writeln!(t, "    point: not computed ({reason})");
            }
            None => {}
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
    let result = Scene::from_toml(&text)
        .map_err(ccd_exact::CcdError::from)
        .and_then(|scene| Ok((run(&scene, &args.options)?, scene)));
    match result {
        Ok((out, scene)) => {
            if let Err(e) = args.pictures.write(&args.path, &scene, &out) {
                eprintln!("ccd-exact: {e}");
                return ExitCode::from(1);
            }
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
