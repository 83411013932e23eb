//! A seeded mutation fuzzer over the shipped scenes (issue 12, "never
//! hang"), and the replay of every input it ever found.
//!
//! Seeds: `tests/scenes/*.toml`, `benches/scenes/*.toml` (not `rigid-288`,
//! a benchmark of minutes) and `tests/stability/*.toml`. Each mutant (see
//! [`mutate`]) goes through the `ccd-exact` binary and must
//!
//! * answer within the bound (CPU seconds of the child, with a wall-clock
//!   backstop of 5×; the child is killed after it, with a gdb stack sample
//!   when gdb is installed): a hang detector, not a speed target;
//! * exit with status 0 or 2, never panic, and name the field on exit 2;
//! * when it answers, give a timeline that follows the JSON contract and
//!   agrees with the static classifier (Theorem 3.10, computed here from
//!   placements by de Casteljau over ℚ) at rational instants inside its
//!   segments; one mutant in four is also run with `--arithmetic float`
//!   (status and bound only) and one in four with `--first-contact` (its
//!   first contact must meet the full run's); every other one also with
//!   `--raycast` (its answer must agree with the exact one, or be it byte
//!   for byte where the ray cast hands the query on).
//!
//! Environment (see docs/fuzzing.md):
//!
//! * `CCD_FUZZ_SEED` (default 12): the seed; case `i` of seed `s` is the
//!   same mutant on every machine.
//! * `CCD_FUZZ_CASES` (default 40, or unbounded when `CCD_FUZZ_SECONDS` is
//!   set): how many mutants (the case numbers below it).
//! * `CCD_FUZZ_FROM` (default 0): the first case; with `CCD_FUZZ_CASES`
//!   one past the last, `CCD_FUZZ_FROM=3270 CCD_FUZZ_CASES=3271` replays
//!   case 3270 alone.
//! * `CCD_FUZZ_SECONDS`: keep making mutants until this many seconds have
//!   passed (the last one started is finished); also replays the slow
//!   regressions.
//! * `CCD_FUZZ_BOUND` (default 20): CPU seconds per run of the binary
//!   before it counts as a hang (and 5× that in wall-clock time).
//! * `CCD_FUZZ_SLOW=1`: replay `tests/fuzz-regressions/slow/` too (bound ×
//!   6).
//! * `CCD_FUZZ_GDB=0`: no stack sample on a hang.
//!
//! A failing mutant is written to `target/tmp/fuzz-failures/` and shown in
//! full in the report; keep it as a regression scene in
//! `tests/fuzz-regressions/` once fixed (or `tests/fuzz-regressions-open/`
//! until then).

#[path = "../common/mod.rs"]
mod common;

mod check;
mod mutate;
mod rng;

use check::{check, cut, scratch, Bound, Failure, Runs, Verdict};
use rng::Rng;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The run's settings, from the environment.
struct Config {
    seed: u64,
    from: u64,
    cases: Option<u64>,
    seconds: Option<f64>,
    bound: Bound,
    slow: bool,
}

/// `name` from the environment parsed as `T`; a value that does not parse
/// is an error of the caller, not a silent default.
fn env<T: std::str::FromStr>(name: &str) -> Option<T> {
    let v = std::env::var(name).ok()?;
    Some(
        v.parse()
            .unwrap_or_else(|_| panic!("{name}={v:?} is not a valid value")),
    )
}

fn config() -> Config {
    let seconds = env::<f64>("CCD_FUZZ_SECONDS");
    let cases = env::<u64>("CCD_FUZZ_CASES").or(if seconds.is_some() { None } else { Some(40) });
    Config {
        seed: env("CCD_FUZZ_SEED").unwrap_or(12),
        from: env("CCD_FUZZ_FROM").unwrap_or(0),
        cases,
        seconds,
        bound: Bound {
            cpu: env("CCD_FUZZ_BOUND").unwrap_or(20.0),
        },
        slow: env::<u8>("CCD_FUZZ_SLOW") == Some(1) || seconds.is_some(),
    }
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The `*.toml` files of `dir`, sorted by name.
fn scenes_in(dir: &Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|d| {
            d.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "toml"))
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// The seed scenes, by name, in a fixed order.
fn seeds() -> Vec<(String, String)> {
    ["tests/scenes", "benches/scenes", "tests/stability"]
        .iter()
        .flat_map(|d| scenes_in(&root().join(d)))
        .filter(|p| !p.ends_with("rigid-288.toml"))
        // World files (many bodies) answer with the world result, not the
        // pair contract these checks read (tests/world.rs covers them).
        .filter(|p| {
            !p.file_name()
                .is_some_and(|n| n.to_string_lossy().starts_with("world-"))
        })
        .map(|p| {
            let name = p.strip_prefix(root()).unwrap_or(&p).display().to_string();
            (name, std::fs::read_to_string(&p).expect("a shipped scene"))
        })
        .collect()
}

/// A failure, reported with everything needed to reproduce it.
fn report(label: &str, text: &str, why: &Failure) -> String {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("fuzz-failures");
    let _ = std::fs::create_dir_all(&dir);
    let file = dir.join(format!("{}.toml", label.replace(['/', ' '], "_")));
    let _ = std::fs::write(&file, text);
    format!(
        "=== {label}: {}\n--- scene (also in {}):\n{}\n",
        cut(why, 6000),
        file.display(),
        cut(text, 4000)
    )
}

/// Tallies of a run, printed at the end (`cargo test -- --nocapture`).
#[derive(Default)]
struct Tally {
    answered: usize,
    refused: usize,
    compared: usize,
    slowest: (Duration, String),
}

impl Tally {
    fn add(&mut self, v: Verdict, took: Duration, label: &str) {
        match v {
            Verdict::Answered { compared } => {
                self.answered += 1;
                self.compared += compared;
            }
            Verdict::Refused => self.refused += 1,
        }
        if took > self.slowest.0 {
            self.slowest = (took, label.to_string());
        }
    }
}

#[test]
fn mutants_of_the_shipped_scenes() {
    let cfg = config();
    let seeds = seeds();
    assert!(seeds.len() >= 60, "only {} seed scenes found", seeds.len());
    let start = Instant::now();
    let mut tally = Tally::default();
    let mut failures = Vec::new();
    let mut case = cfg.from;
    while cfg.cases.is_none_or(|n| case < n)
        && cfg
            .seconds
            .is_none_or(|s| start.elapsed().as_secs_f64() < s)
    {
        let mut rng = Rng::for_case(cfg.seed, case);
        let (name, seed) = rng.pick(&seeds);
        let m = mutate::mutate(seed, &mut rng);
        let runs = Runs {
            float: rng.chance(1, 4),
            first_contact: rng.chance(1, 4),
            // Not drawn from `rng`: each case keeps its mutant and samples.
            raycast: case.is_multiple_of(2),
        };
        let label = format!("seed-{}-case-{case}", cfg.seed);
        let t = Instant::now();
        match check(&m.text, &scratch("mutant"), runs, cfg.bound, &mut |n| {
            rng.below(n)
        }) {
            Ok(v) => tally.add(v, t.elapsed(), &label),
            Err(why) => failures.push(report(
                &label,
                &m.text,
                &format!("mutant of {name} by {:?}: {why}", m.ops),
            )),
        }
        case += 1;
    }
    println!(
        "fuzz: seed {}, {} mutants in {:.1?}: {} answered ({} instants compared), {} refused, {} failed; slowest {:.2?} ({})",
        cfg.seed,
        case - cfg.from,
        start.elapsed(),
        tally.answered,
        tally.compared,
        tally.refused,
        failures.len(),
        tally.slowest.0,
        tally.slowest.1
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    // Guards against a mutator that only makes refusals: the timeline
    // check must have run.
    let made = case - cfg.from;
    if made >= 20 {
        assert!(
            tally.answered * 5 >= made as usize && tally.compared > 0,
            "only {} of {made} mutants answered, {} instants compared",
            tally.answered,
            tally.compared
        );
    }
}

/// Replays the scenes of `dir` with every run, bounded by `bound`.
fn replay(dir: &str, bound: Bound) {
    let scenes = scenes_in(&root().join(dir));
    assert!(!scenes.is_empty(), "no regression scenes in {dir}");
    let mut failures = Vec::new();
    let mut tally = Tally::default();
    for (k, path) in scenes.iter().enumerate() {
        let text = std::fs::read_to_string(path).expect("a regression scene");
        let name = path.file_stem().unwrap_or_default().to_string_lossy();
        let runs = Runs {
            float: true,
            first_contact: true,
            raycast: true,
        };
        // The instants compared vary with the file, deterministically.
        let mut rng = Rng::for_case(k as u64, 0);
        let t = Instant::now();
        match check(
            &text,
            &scratch(&format!("replay-{}", dir.replace('/', "-"))),
            runs,
            bound,
            &mut |n| rng.below(n),
        ) {
            Ok(v) => tally.add(v, t.elapsed(), &name),
            Err(why) => failures.push(report(&format!("{dir}/{name}"), &text, &why)),
        }
    }
    println!(
        "fuzz: {} regression scenes of {dir}: {} answered ({} instants compared), {} refused; slowest {:.2?} ({})",
        scenes.len(),
        tally.answered,
        tally.compared,
        tally.refused,
        tally.slowest.0,
        tally.slowest.1
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Every input the fuzzer (or a session hunting issue 12) ever found, still
/// answered within the bound and right; the slow ones (bound × 6) only in
/// the long run or with `CCD_FUZZ_SLOW=1`.
#[test]
fn regressions_stay_fixed() {
    let cfg = config();
    replay("tests/fuzz-regressions", cfg.bound);
    if cfg.slow {
        replay("tests/fuzz-regressions/slow", cfg.bound.times(6.0));
    }
}
