//! `ccd-exact SCENE.toml [--json] [--digits N] [--first-contact] …` (a pair
//! or a world) and `ccd-exact batch [FILE|-]` (JSON Lines of pair scenes).

mod cli {
    pub mod table;
}

use ccd_exact::{
    run, run_batch, run_world, to_json_pretty, world_to_json_pretty, Arithmetic, BatchOptions,
    Options, Outcome, Scene, SceneFile,
};
use ccd_scene::{Limit, SceneError, MAX_INPUT_BYTES};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand, ValueEnum};
use std::io::{IsTerminal, Read, Write};
use std::process::ExitCode;

const EXAMPLES: &str = "\
EXAMPLES:
    ccd-exact tests/scenes/paper-example-5-1.toml
    ccd-exact tests/scenes/rigid-tumbling.toml --json --digits 30
    ccd-exact tests/scenes/paper-example-5-1.toml --first-contact
    ccd-exact benches/scenes/affine-deg2.toml --arithmetic float
    ccd-exact tests/scenes/paper-example-5-1.toml --svg 5-1.svg --html 5-1.html
    ccd-exact tests/scenes/world-crossing.toml             (a world: [[body]] tables)
    ccd-exact tests/scenes/world-crossing.toml --first-contact --json
    ccd-exact batch < tests/scenes/pairs.jsonl              (see: ccd-exact help batch)

Exit status: 0 on success, 2 on bad input (the message names the field or option).";

const BATCH_EXAMPLES: &str = "\
Each input line is one pair scene as JSON with the TOML scene's structure,
numbers as JSON integers or strings (\"0.1\", \"1/3\", \"1e-20\"):
    {\"a\": {\"radii\": [2, 1, 1], \"motion\": {\"kind\": \"translation\", \"center\": [[11, 0, 0], [-1, 0, 0]]}}, \"b\": {\"radii\": [2, 1, 1]}}
Each output line is {\"line\": N, <the pair result object>} or
{\"line\": N, \"error\": \"line N: field `…`: …\", \"field\": \"…\"}, in input order.

EXAMPLES:
    ccd-exact batch < tests/scenes/pairs.jsonl
    ccd-exact batch tests/scenes/pairs.jsonl --threads 2 --no-geometry > results.jsonl

Exit status: 0 when every line was answered (error lines included; their
count goes to stderr), 2 when the input cannot be opened or an option is bad.";

/// ccd-exact: exact, certified continuous collision detection for moving
/// ellipsoids (a pair, a world of many, or a batch of pairs)
#[derive(Parser)]
#[command(
    name = "ccd-exact",
    after_help = EXAMPLES,
    args_conflicts_with_subcommands = true,
    arg_required_else_help = true
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    /// The scene file (a pair: [a] and [b]; a world: [[body]] tables), or
    /// `-` for standard input
    scene: Option<String>,
    #[command(flatten)]
    query: QueryArgs,
    #[command(flatten)]
    output: OutputArgs,
    /// Worker threads for a world's pairs (default: RAYON_NUM_THREADS, else
    /// one per core)
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
}

#[derive(Subcommand)]
enum Command {
    /// Answer JSON Lines of pair scenes, one result line per input line,
    /// in input order, in parallel
    #[command(after_help = BATCH_EXAMPLES)]
    Batch(BatchArgs),
}

#[derive(Args)]
struct BatchArgs {
    /// The JSON Lines file, or `-` for standard input
    #[arg(default_value = "-")]
    input: String,
    #[command(flatten)]
    query: QueryArgs,
    /// Worker threads (default: RAYON_NUM_THREADS, else one per core)
    #[arg(long, value_name = "N")]
    threads: Option<usize>,
    /// No progress bar (it is shown only when stderr is a terminal)
    #[arg(long, short)]
    quiet: bool,
}

/// The options of each pair query.
#[derive(Args)]
struct QueryArgs {
    /// Enclose each contact instant to 1e-N of the span
    #[arg(long, value_name = "N", default_value_t = 15, value_parser = digits)]
    digits: u32,
    /// Stop at the earliest instant the bodies are not separate (a world:
    /// the earliest contact in the world)
    #[arg(long)]
    first_contact: bool,
    /// exact (every answer certified) or float (the paper's f64 Bernstein
    /// solver: faster, NOT certified)
    #[arg(long, value_name = "M", value_enum, default_value_t = ArithmeticArg::Exact)]
    arithmetic: ArithmeticArg,
    /// Skip the contact point and normal of each contact
    #[arg(long)]
    no_geometry: bool,
    /// Pairs translating along straight lines: answer by a certified ray
    /// cast into the Minkowski difference (microseconds, f64 interval
    /// ends), falling back to the exact path where it proves less
    #[arg(long)]
    raycast: bool,
}

/// How a scene's result is written; each option is one more output.
#[derive(Args)]
struct OutputArgs {
    /// Print the result as JSON (docs/scene-format.md, format 1)
    #[arg(long)]
    json: bool,
    /// Also draw a pair's query as an SVG picture: the timeline strip and
    /// each contact's section through its point
    #[arg(long, value_name = "FILE")]
    svg: Option<String>,
    /// Also write a self-contained HTML page that animates a pair's bodies
    /// over the span (time slider, contacts marked)
    #[arg(long, value_name = "FILE")]
    html: Option<String>,
}

/// Draws a query: `ccd_picture::svg` or `ccd_picture::html`.
type Picture = fn(&Scene, &Outcome, &str) -> String;

impl OutputArgs {
    /// Writes the pictures asked for; the error names the file.
    fn pictures(&self, title: &str, scene: &Scene, out: &Outcome) -> Result<(), String> {
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

#[derive(Clone, Copy, ValueEnum)]
enum ArithmeticArg {
    Exact,
    Float,
}

fn digits(v: &str) -> Result<u32, String> {
    v.parse()
        .ok()
        .filter(|d| *d <= Options::MAX_DIGITS)
        .ok_or_else(|| {
            format!(
                "`{v}` is not a whole number from 0 to {}",
                Options::MAX_DIGITS
            )
        })
}

impl QueryArgs {
    fn options(&self) -> Options {
        Options {
            digits: self.digits,
            first_contact_only: self.first_contact,
            arithmetic: match self.arithmetic {
                ArithmeticArg::Exact => Arithmetic::Exact,
                ArithmeticArg::Float => Arithmetic::Float,
            },
            contact_geometry: !self.no_geometry,
            raycast: self.raycast,
        }
    }
}

/// The text of the scene at `path` (`-`: standard input), reading at most
/// [`MAX_INPUT_BYTES`] + 1 bytes: a longer file (or `/dev/zero`) is refused
/// with the scene format's size error, never read whole.
fn read_scene(path: &str) -> Result<String, String> {
    let cannot = |e: &dyn std::fmt::Display| format!("cannot read `{path}`: {e}");
    let reader: Box<dyn Read> = if path == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        Box::new(std::fs::File::open(path).map_err(|e| cannot(&e))?)
    };
    let mut bytes = Vec::new();
    reader
        .take(MAX_INPUT_BYTES as u64 + 1)
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

/// Writes `text` to standard output; a reader that stops early (`| head`)
/// is not an error of ours.
fn print(text: &str) -> ExitCode {
    match std::io::stdout().lock().write_all(text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => {
            eprintln!("ccd-exact: cannot write the result: {e}");
            ExitCode::from(1)
        }
        _ => ExitCode::SUCCESS,
    }
}

/// Bad input: the message, exit status 2.
fn bad(message: impl std::fmt::Display) -> ExitCode {
    eprintln!("ccd-exact: {message}");
    ExitCode::from(2)
}

/// One scene file (a pair or a world) → its result on standard output.
fn scene(path: &str, query: &QueryArgs, output: &OutputArgs) -> ExitCode {
    let text = match read_scene(path) {
        Ok(t) => t,
        Err(e) => return bad(e),
    };
    let options = query.options();
    let mut drawn = Ok(());
    let result = SceneFile::from_toml(&text)
        .map_err(ccd_exact::CcdError::from)
        .and_then(|file| match file {
            SceneFile::Pair(s) => run(&s, &options).map(|out| {
                drawn = output.pictures(path, &s, &out);
                if output.json {
                    to_json_pretty(&out) + "\n"
                } else {
                    cli::table::pair(&out, &options)
                }
            }),
            SceneFile::World(w) => run_world(&w, &options).map(|out| {
                if output.svg.is_some() || output.html.is_some() {
                    drawn = Err("--svg and --html draw pair scenes only".into());
                }
                if output.json {
                    world_to_json_pretty(&out) + "\n"
                } else {
                    cli::table::world(&out, &options)
                }
            }),
        });
    match (result, drawn) {
        (Ok(text), Ok(())) => print(&text),
        (Ok(text), Err(e)) => {
            print(&text);
            eprintln!("ccd-exact: {e}");
            ExitCode::from(1)
        }
        (Err(e), _) => bad(format_args!("{path}: {e}")),
    }
}

/// `ccd-exact batch`.
fn batch(args: &BatchArgs) -> ExitCode {
    let input: Box<dyn Read> = if args.input == "-" {
        Box::new(std::io::stdin().lock())
    } else {
        match std::fs::File::open(&args.input) {
            Ok(f) => Box::new(f),
            Err(e) => return bad(format_args!("cannot read `{}`: {e}", args.input)),
        }
    };
    let options = BatchOptions {
        options: args.query.options(),
        threads: args.threads.unwrap_or(0),
        ..BatchOptions::default()
    };
    let bar = if !args.quiet && std::io::stderr().is_terminal() {
        let bar = indicatif::ProgressBar::new_spinner();
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{spinner} {pos} lines answered ({per_sec}, {elapsed})",
        ) {
            bar.set_style(style);
        }
        bar
    } else {
        indicatif::ProgressBar::hidden()
    };
    let result = run_batch(
        std::io::BufReader::with_capacity(1 << 20, input),
        std::io::stdout().lock(),
        &options,
        &|| bar.inc(1),
    );
    bar.finish_and_clear();
    match result {
        Ok(summary) => {
            if summary.errors > 0 {
                eprintln!(
                    "ccd-exact batch: {} of {} lines are error lines",
                    summary.errors, summary.lines
                );
            }
            ExitCode::SUCCESS
        }
        Err(ccd_exact::BatchError::Io(e)) if e.kind() == std::io::ErrorKind::BrokenPipe => {
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("ccd-exact batch: {e}");
            ExitCode::from(1)
        }
    }
}

fn main() -> ExitCode {
    let version: &'static str = format!(
        "{} ({} integers)",
        env!("CARGO_PKG_VERSION"),
        ccd_arith::BACKEND
    )
    .leak();
    let matches = Cli::command().version(version).get_matches();
    let cli = match Cli::from_arg_matches(&matches) {
        Ok(c) => c,
        Err(e) => e.exit(),
    };
    match &cli.command {
        Some(Command::Batch(args)) => batch(args),
        None => {
            if let Some(n) = cli.threads {
                if let Err(e) = rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build_global()
                {
                    return bad(format_args!("option `--threads`: {e}"));
                }
            }
            match &cli.scene {
                Some(path) => scene(path, &cli.query, &cli.output),
                None => bad("no scene file given (see --help)"),
            }
        }
    }
}
