//! The checks on one scene text: the binary answers within the bound with
//! exit status 0 or 2 and no panic; a refusal names the field; an answer is
//! a well-formed timeline that agrees with the static classifier at
//! rational instants inside its segments.

use crate::common::static_state;
use ccd_arith::{Int, Rat};
use ccd_exact::{Scene, State};
use ccd_motion::Motion;
use serde_json::Value;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// Which runs of the binary a scene gets besides the exact `--json` one.
#[derive(Clone, Copy, Debug)]
pub struct Runs {
    /// `--arithmetic float` (exit status and the bound only: not certified).
    pub float: bool,
    /// `--first-contact`, whose first contact must meet the full run's.
    pub first_contact: bool,
    /// `--raycast` (and `--raycast --first-contact` with `first_contact`):
    /// the ray cast's answer must agree with the exact one, and a query
    /// it hands on must come back byte-identical.
    pub raycast: bool,
}

/// How a scene fared.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// Answered; `compared` instants matched the static classifier.
    Answered { compared: usize },
    /// Refused with exit status 2 and a message naming the field.
    Refused,
}

/// One broken promise, described for the report.
pub type Failure = String;

/// The output of one run of the binary.
struct Run {
    code: Option<i32>,
    stdout: String,
    stderr: String,
}

/// Seconds of CPU time the process `pid` has used (user + system, from
/// `/proc/PID/stat`, in the kernel's fixed USER_HZ = 100 ticks per second);
/// `None` where there is no `/proc`.
fn cpu_seconds(pid: u32) -> Option<f64> {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).ok()?;
    // The command name, in parentheses, may hold spaces: fields after it.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks = |i: usize| fields.get(i)?.parse::<u64>().ok();
    Some((ticks(11)? + ticks(12)?) as f64 / 100.0)
}

/// How long a run of the binary may take before it counts as a hang: `cpu`
/// seconds of its own CPU time (so a machine loaded by other builds does
/// not turn a slow answer into a false hang), and `WALL_FACTOR` times that
/// in wall-clock time in any case (a child that blocks, or no `/proc`).
#[derive(Clone, Copy, Debug)]
pub struct Bound {
    /// CPU seconds of the child.
    pub cpu: f64,
}

/// The wall-clock backstop, as a multiple of the CPU bound.
const WALL_FACTOR: u32 = 5;

impl Bound {
    /// `self` scaled by `k` (slow regressions).
    pub fn times(self, k: f64) -> Bound {
        Bound { cpu: self.cpu * k }
    }
    fn wall(self) -> Duration {
        Duration::from_secs_f64(self.cpu) * WALL_FACTOR
    }
}

/// Runs the binary on `path` with `args`, killing it once it passes
/// `bound` (with a stack sample first when gdb is at hand).
fn run(path: &Path, args: &[&str], bound: Bound) -> Result<Run, Failure> {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ccd-exact"))
        .arg(path)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start the binary: {e}"))?;
    // Drained on threads so a large output cannot block the child.
    let drain = |mut r: Box<dyn Read + Send>| {
        std::thread::spawn(move || {
            let mut s = Vec::new();
            let _ = r.read_to_end(&mut s);
            String::from_utf8_lossy(&s).into_owned()
        })
    };
    let out = drain(Box::new(child.stdout.take().expect("piped")));
    let err = drain(Box::new(child.stderr.take().expect("piped")));
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) => {
                let cpu = cpu_seconds(child.id()).unwrap_or(0.0);
                if cpu <= bound.cpu && start.elapsed() <= bound.wall() {
                    std::thread::sleep(Duration::from_millis(5));
                    continue;
                }
                let stack = stack_sample(child.id());
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "no answer within the bound of {} s CPU / {:?} wall (`ccd-exact {} {}` killed after {cpu:.1} s CPU, {:.1?} wall; the bound is a hang detector, not a speed target){stack}",
                    bound.cpu,
                    bound.wall(),
                    path.display(),
                    args.join(" "),
                    start.elapsed()
                ));
            }
            Err(e) => return Err(format!("cannot wait for the binary: {e}")),
        }
    };
    Ok(Run {
        code: status.code(),
        stdout: out.join().unwrap_or_default(),
        stderr: err.join().unwrap_or_default(),
    })
}

/// `gdb -p PID -batch -ex bt` of a stalled child, when gdb is installed and
/// `CCD_FUZZ_GDB` is not `0`; empty otherwise.
fn stack_sample(pid: u32) -> String {
    if std::env::var("CCD_FUZZ_GDB").as_deref() == Ok("0") {
        return String::new();
    }
    let Ok(out) = Command::new("gdb")
        .args(["-p", &pid.to_string(), "-batch", "-ex", "bt 40"])
        .stdin(Stdio::null())
        .output()
    else {
        return String::new();
    };
    let frames: Vec<&str> = std::str::from_utf8(&out.stdout)
        .unwrap_or("")
        .lines()
        .filter(|l| l.starts_with('#'))
        .collect();
    if frames.is_empty() {
        String::new()
    } else {
        format!("\nstack sample (gdb):\n{}", frames.join("\n"))
    }
}

/// How a refusal starts, after `ccd-exact: FILE: `: with the field (scene
/// and motion errors), the option (`--arithmetic float` on a helical
/// scene), `not TOML`, or the path of the interval path's
/// errors (`a.motion: …`, `span: …`).
const NAMES_THE_FIELD: [&str; 7] = [
    "field `", "option `", "limit `", "not TOML", "a.", "b.", "span",
];

/// The checks common to every run: exit 0 or 2, no panic, and a refusal
/// that names what was wrong in a message of bounded length.
fn status_ok(r: &Run, path: &Path, what: &str) -> Result<(), Failure> {
    let fail = |why: &str| {
        Err(format!(
            "{what}: {why} (exit {:?})\nstderr: {}",
            r.code,
            cut(&r.stderr, 2000)
        ))
    };
    if r.stderr.contains("panicked") {
        return fail("panicked");
    }
    match r.code {
        Some(0) => Ok(()),
        Some(2) => {
            let msg = r.stderr.trim_end();
            let names = msg
                .strip_prefix(&format!("ccd-exact: {}: ", path.display()))
                .is_some_and(|m| NAMES_THE_FIELD.iter().any(|n| m.starts_with(n)));
            if !names {
                fail("exit 2 without a message naming the field")
            } else if msg.contains("internal error") {
                fail("internal error")
            } else if msg.len() > 1500 {
                fail("error message longer than 1500 bytes")
            } else {
                Ok(())
            }
        }
        _ => fail("exit status neither 0 nor 2"),
    }
}

/// `s` cut to at most `n` bytes at a character boundary.
pub fn cut(s: &str, n: usize) -> String {
    if s.len() <= n {
        return s.to_string();
    }
    let mut end = n;
    while !s.is_char_boundary(end) {
        end -= 1;
    }
    format!("{}… ({} bytes in all)", &s[..end], s.len())
}

/// A time of the JSON result: its certified enclosure.
#[derive(Clone, Debug, PartialEq)]
struct Time {
    lo: Rat,
    hi: Rat,
}

/// A timeline segment of the JSON result.
#[derive(Debug)]
struct Segment {
    state: State,
    start: Time,
    end: Time,
}

/// An exact rational `p/q` or `p` of the result. Not through the scene
/// parser: an output number may be longer than the input limit (a span
/// `[0, 1e-4096]` has an end of 4098 characters).
fn rat(v: &Value, what: &str) -> Result<Rat, Failure> {
    let read = |s: &str| {
        let (p, q) = s.split_once('/').unwrap_or((s, "1"));
        Rat::new(Int::parse_decimal(p)?, Int::parse_decimal(q)?)
    };
    v.as_str().and_then(read).ok_or_else(|| {
        format!(
            "JSON: {what} is not an exact rational: {}",
            cut(&v.to_string(), 200)
        )
    })
}

fn time(v: &Value) -> Result<Time, Failure> {
    let t = Time {
        lo: rat(&v["lo"], "lo")?,
        hi: rat(&v["hi"], "hi")?,
    };
    if t.lo > t.hi {
        return Err(format!("JSON: enclosure with lo > hi: {v}"));
    }
    Ok(t)
}

fn state(v: &Value) -> Result<State, Failure> {
    match v.as_str() {
        Some("separate") => Ok(State::Separate),
        Some("touch") => Ok(State::Touch),
        Some("overlap") => Ok(State::Overlap),
        _ => Err(format!("JSON: unknown state {v}")),
    }
}

/// The result's span and timeline, checked against the contract: it starts
/// at t0, each segment starts where the last ended, it ends at t1 (when
/// complete); `contacts` are its isolated touches; `collision_free` and
/// `first_contact` agree with it.
fn timeline(v: &Value) -> Result<([Rat; 2], Vec<Segment>), Failure> {
    let span = [
        rat(&v["span"][0], "span[0]")?,
        rat(&v["span"][1], "span[1]")?,
    ];
    let segs: Vec<Segment> = v["timeline"]
        .as_array()
        .ok_or("JSON: no timeline")?
        .iter()
        .map(|s| {
            Ok(Segment {
                state: state(&s["state"])?,
                start: time(&s["start"])?,
                end: time(&s["end"])?,
            })
        })
        .collect::<Result<_, Failure>>()?;
    // A certified end of the timeline is the span's end exactly; an
    // uncertified one (the interval path clips a candidate reaching past
    // the span and flags it, docs/helical.md) must contain it.
    let at = |t: &Time, v: &Value, end: &Rat| {
        if v["certified"].as_bool() != Some(false) {
            t.lo == *end && t.hi == *end
        } else {
            t.lo <= *end && *end <= t.hi
        }
    };
    let raw = v["timeline"].as_array().expect("checked above");
    // The gaps (issue 18): pieces of the span the timeline does not cover,
    // each with exact ends, a reason and its witness, when present: a
    // proven non-separate exact instant inside it.
    let gaps: Vec<(Rat, Rat, Option<Rat>)> = match v["gaps"].as_array() {
        None => vec![],
        Some(gaps) => gaps
            .iter()
            .map(|g| {
                if g["reason"].as_str().is_none_or(str::is_empty) {
                    return Err(Failure::from("JSON: a gap without a reason"));
                }
                let (lo, hi) = (rat(&g["lo"], "gap lo")?, rat(&g["hi"], "gap hi")?);
                let w = &g["witness"];
                let t = if w.is_null() {
                    None
                } else {
                    let t = rat(&w["t"], "gap witness t")?;
                    if !(lo <= t && t <= hi) || state(&w["state"])? == State::Separate {
                        return Err(format!(
                            "JSON: a gap's witness {w} is not a collision in it"
                        ));
                    }
                    Some(t)
                };
                Ok((lo, hi, t))
            })
            .collect::<Result<_, Failure>>()?,
    };
    // Segments and gaps tile the span in order from t0, without holes.
    enum Piece<'a> {
        Seg(usize, &'a Segment),
        Gap(&'a (Rat, Rat, Option<Rat>)),
    }
    let mut pieces: Vec<(&Rat, Piece<'_>)> = segs
        .iter()
        .enumerate()
        .map(|(i, s)| (&s.start.lo, Piece::Seg(i, s)))
        .chain(gaps.iter().map(|g| (&g.0, Piece::Gap(g))))
        .collect();
    pieces.sort_by(|x, y| x.0.cmp(y.0));
    let first = pieces.first().ok_or("JSON: empty timeline and no gaps")?;
    let starts_at_t0 = match &first.1 {
        Piece::Seg(i, s) => at(&s.start, &raw[*i]["start"], &span[0]),
        Piece::Gap(g) => g.0 == span[0],
    };
    if !starts_at_t0 {
        return Err("the timeline does not start at t0".into());
    }
    for w in pieces.windows(2) {
        let joined = match (&w[0].1, &w[1].1) {
            (Piece::Seg(_, p), Piece::Seg(_, n)) => p.end == n.start,
            (Piece::Seg(_, p), Piece::Gap(g)) => p.end.hi == g.0,
            (Piece::Gap(g), Piece::Seg(_, n)) => n.start.lo == g.1 && n.start.hi == g.1,
            (Piece::Gap(_), Piece::Gap(_)) => false,
        };
        if !joined {
            return Err(
                "a hole, an overlap or unmerged gaps between pieces of the timeline".into(),
            );
        }
    }
    for s in &segs {
        if s.start != s.end && s.start.hi > s.end.lo {
            return Err(format!("segment {s:?} has crossed enclosures"));
        }
    }
    let complete = v["complete"].as_bool() != Some(false);
    if complete && !gaps.is_empty() {
        return Err("complete with gaps".into());
    }
    let Some(last) = segs.last() else {
        // Only gaps: nothing is decided, so nothing may be claimed.
        if complete || v["collision_free"] == Value::Bool(true) {
            return Err("only gaps, yet complete or collision-free".into());
        }
        return Ok((span, segs));
    };
    if complete && !at(&last.end, &raw[raw.len() - 1]["end"], &span[1]) {
        return Err(format!("timeline ends at {:?}, not t1", last.end));
    }
    let mut touches: Vec<&Time> = segs
        .iter()
        .filter(|s| s.state == State::Touch && s.start == s.end)
        .map(|s| &s.start)
        .collect();
    let contacts: Vec<Time> = v["contacts"]
        .as_array()
        .ok_or("JSON: no contacts")?
        .iter()
        .map(time)
        .collect::<Result<_, _>>()?;
    // A first-contact run that stops at a touch cannot tell yet whether it
    // is an isolated contact.
    let stops_at_touch = last.state == State::Touch && last.start == last.end;
    if !complete && stops_at_touch && contacts.len() + 1 == touches.len() {
        touches.pop();
    }
    if contacts.iter().collect::<Vec<_>>() != touches {
        return Err(format!(
            "contacts {contacts:?} are not the isolated touches {touches:?}"
        ));
    }
    let separate = segs.iter().all(|s| s.state == State::Separate);
    // `collision_free` is true only when separation is proven (issue 18):
    // a complete timeline of separate segments; when complete, it says
    // exactly that.
    if v["collision_free"] == Value::Bool(true) && !(complete && separate) {
        return Err("collision_free without a complete separate timeline".into());
    }
    match v["collision_free"].as_bool() {
        Some(free) if complete && free != separate => {
            return Err("collision_free disagrees with the timeline".into());
        }
        None if v["collision_free_reason"]
            .as_str()
            .is_none_or(str::is_empty) =>
        {
            return Err("collision_free is null without a reason".into());
        }
        _ => {}
    }
    // `first_contact` is the earliest non-separate instant *known*
    // (scene-format.md): the start of the first non-separate segment, or a
    // gap's start up to its witness, whichever comes first; `null` when
    // neither exists (separate throughout, or gaps without witnesses).
    let known = pieces.iter().find_map(|(_, p)| match p {
        Piece::Seg(_, s) if s.state != State::Separate => Some(s.start.clone()),
        Piece::Seg(..) => None,
        Piece::Gap((lo, _, witness)) => witness.clone().map(|t| Time {
            lo: lo.clone(),
            hi: t,
        }),
    });
    let reported = match &v["first_contact"] {
        Value::Null => None,
        t => Some(time(t)?),
    };
    if reported != known {
        return Err(format!(
            "first_contact {reported:?} is not the earliest non-separate instant known, {known:?}"
        ));
    }
    if reported.is_none() && v["collision_free"] == Value::Bool(false) {
        return Err("collision_free is false without a first contact".into());
    }
    Ok((span, segs))
}

/// Rational instants strictly inside the segments (at most `max`), chosen
/// by `pick` among fractions of each segment's open interior.
fn instants(
    segs: &[Segment],
    max: usize,
    pick: &mut dyn FnMut(usize) -> usize,
) -> Vec<(Rat, State)> {
    let mut out = Vec::new();
    let open: Vec<&Segment> = segs.iter().filter(|s| s.start.hi < s.end.lo).collect();
    for k in 0..max.min(2 * open.len()) {
        let s = open[if k < open.len() { k } else { pick(open.len()) }];
        let den = 2 + pick(8) as i64;
        let num = 1 + pick(den as usize - 1) as i64;
        let f = Rat::from_frac(num, den);
        let t = &s.start.hi + &(&(&s.end.lo - &s.start.hi) * &f);
        out.push((t, s.state));
    }
    out
}

/// A scratch file named `k` of this process, rewritten for each scene (a
/// failing scene is kept apart by the caller).
pub fn scratch(k: &str) -> PathBuf {
    let dir =
        PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join(format!("fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("scratch directory");
    dir.join(format!("{k}.toml"))
}

/// The `--raycast` run `ray` against the same query without it
/// (`plain`, answered): where the ray cast answered (`stats.branch`
/// `"raycast"`), the same states, verdict and number of contacts, and
/// every instant meeting the plain one; elsewhere the same bytes.
fn raycast_agrees(ray: &Run, plain: &Run, path: &Path) -> Result<(), Failure> {
    status_ok(ray, path, "raycast")?;
    if ray.code != Some(0) {
        return Err("raycast: refused a query the exact path answered".into());
    }
    let (r, p): (Value, Value) = match (
        serde_json::from_str(&ray.stdout),
        serde_json::from_str(&plain.stdout),
    ) {
        (Ok(r), Ok(p)) => (r, p),
        _ => return Err("raycast: output is not JSON".into()),
    };
    if r["stats"]["branch"] != "raycast" {
        return if ray.stdout == plain.stdout {
            Ok(())
        } else {
            Err("raycast: a query handed on came back changed".into())
        };
    }
    let (_, rs) = timeline(&r).map_err(|e| format!("raycast: {e}"))?;
    let (_, ps) = timeline(&p)?;
    let meet = |a: &Time, b: &Time| a.lo <= b.hi && b.lo <= a.hi;
    let same = rs.len() == ps.len()
        && rs
            .iter()
            .zip(&ps)
            .all(|(a, b)| a.state == b.state && meet(&a.start, &b.start) && meet(&a.end, &b.end))
        && r["collision_free"] == p["collision_free"]
        && r["complete"] == p["complete"]
        && r["certified"] == Value::Bool(true)
        && r["contacts"].as_array().map(Vec::len) == p["contacts"].as_array().map(Vec::len);
    if same {
        Ok(())
    } else {
        Err(format!(
            "raycast: {} disagrees with the exact run {}",
            cut(&ray.stdout, 1500),
            cut(&plain.stdout, 1500)
        ))
    }
}

/// Every check on scene `text` (written to `path`), each run of the binary
/// bounded by `bound`; `pick` chooses the instants compared.
pub fn check(
    text: &str,
    path: &Path,
    runs: Runs,
    bound: Bound,
    pick: &mut dyn FnMut(usize) -> usize,
) -> Result<Verdict, Failure> {
    std::fs::write(path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    let exact = run(path, &["--json"], bound)?;
    status_ok(&exact, path, "exact")?;
    if runs.float {
        status_ok(
            &run(path, &["--json", "--arithmetic", "float"], bound)?,
            path,
            "float",
        )?;
    }
    if exact.code != Some(0) {
        return Ok(Verdict::Refused);
    }
    let json: Value = serde_json::from_str(&exact.stdout).map_err(|e| {
        format!(
            "exact: output is not JSON ({e}): {}",
            cut(&exact.stdout, 500)
        )
    })?;
    let (span, segs) = timeline(&json)?;
    let scene = Scene::from_toml(text)
        .map_err(|e| format!("the binary answered, the library refuses: {e}"))?;
    let helical = |m: &Motion| matches!(m, Motion::Helical { .. });
    let rational = !helical(&scene.a.motion) && !helical(&scene.b.motion);
    if rational && json["certified"] != Value::Bool(true) {
        return Err("the exact path answered a rational scene uncertified".into());
    }
    let fc = if runs.first_contact {
        Some(run(path, &["--json", "--first-contact"], bound)?)
    } else {
        None
    };
    if let Some(fc) = &fc {
        status_ok(fc, path, "first contact")?;
        let v: Value = serde_json::from_str(&fc.stdout)
            .map_err(|e| format!("first contact: output is not JSON ({e})"))?;
        timeline(&v).map_err(|e| format!("first contact: {e}"))?;
        let (a, b) = (&json["first_contact"], &v["first_contact"]);
        // One run may know a first contact the other does not only where
        // the other stopped at a gap (the helical path's effort budget:
        // a first-contact query stops at its first gap that the sphere
        // certificates do not prove separate) and the known one
        // is not proven the earliest.
        let unknown_to = |run: &Value, known: &Value| {
            run["gaps"].as_array().is_some_and(|g| !g.is_empty())
                && known["certified"] == Value::Bool(false)
        };
        let meet = match (a.is_null(), b.is_null()) {
            (true, true) => true,
            (false, false) => time(a)?.lo <= time(b)?.hi && time(b)?.lo <= time(a)?.hi,
            (false, true) => unknown_to(&v, a),
            (true, false) => unknown_to(&json, b),
        };
        if !meet {
            return Err(format!("--first-contact gives {b}, the full run {a}"));
        }
    }
    if runs.raycast {
        let mut modes = vec![(vec!["--json", "--raycast"], &exact)];
        if let Some(fc) = &fc {
            modes.push((vec!["--json", "--raycast", "--first-contact"], fc));
        }
        for (args, plain) in modes {
            raycast_agrees(&run(path, &args, bound)?, plain, path)?;
        }
    }
    if !rational {
        // Placements at a rational instant are not rational.
        return Ok(Verdict::Answered { compared: 0 });
    }
    let samples = instants(&segs, 8, pick);
    let compared = samples.len();
    // The classifier runs on a thread so that a stall there is reported
    // within the bound too (the thread is abandoned).
    let (tx, rx) = mpsc::channel();
    std::thread::spawn(move || {
        let width = &span[1] - &span[0];
        for (t, want) in samples {
            let u = &(&t - &span[0]) / &width;
            let got = static_state(&scene, &u);
            if got != want {
                let _ = tx.send(Err(format!(
                    "the timeline says {want:?} at t = {t}, the static classifier {got:?}"
                )));
                return;
            }
        }
        let _ = tx.send(Ok(()));
    });
    match rx.recv_timeout(bound.wall()) {
        Ok(r) => r.map(|()| Verdict::Answered { compared }),
        Err(mpsc::RecvTimeoutError::Timeout) => Err(format!(
            "the static classifier took over {:?}",
            bound.wall()
        )),
        Err(mpsc::RecvTimeoutError::Disconnected) => Err("the static classifier panicked".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn t(lo: &str, hi: &str) -> Value {
        json!({"lo": lo, "hi": hi, "approx": "", "certified": true})
    }

    /// A well-formed result: separate, touch at 1/2, separate.
    fn good() -> Value {
        json!({
            "span": ["0", "1"],
            "collision_free": false,
            "complete": true,
            "first_contact": t("1/3", "2/3"),
            "contacts": [t("1/3", "2/3")],
            "timeline": [
                {"state": "separate", "start": t("0", "0"), "end": t("1/3", "2/3")},
                {"state": "touch", "start": t("1/3", "2/3"), "end": t("1/3", "2/3")},
                {"state": "separate", "start": t("1/3", "2/3"), "end": t("1", "1")},
            ],
        })
    }

    #[test]
    fn the_contract_checks_can_fail() {
        assert!(timeline(&good()).is_ok());
        type Breaks = fn(&mut Value);
        let broken: [(&str, Breaks); 8] = [
            ("no first contact", |v| v["first_contact"] = Value::Null),
            ("late first contact", |v| {
                v["first_contact"] = t("1/2", "2/3")
            }),
            ("gap", |v| v["timeline"][2]["start"] = t("1/2", "2/3")),
            ("short", |v| v["timeline"][2]["end"] = t("0", "1")),
            ("late start", |v| {
                v["timeline"][0]["start"] = t("1/9", "1/9")
            }),
            ("contacts", |v| v["contacts"] = json!([])),
            ("free", |v| v["collision_free"] = json!(true)),
            ("state", |v| v["timeline"][0]["state"] = json!("apart")),
        ];
        for (name, breaks) in broken {
            let mut v = good();
            breaks(&mut v);
            assert!(timeline(&v).is_err(), "{name} not caught");
        }
        // An uncertified end need only contain t1.
        let mut v = good();
        v["timeline"][2]["end"] = json!({"lo": "3/4", "hi": "1", "certified": false});
        assert!(timeline(&v).is_ok());
        // A gap without a witness (the helical path): nothing non-separate
        // is known, so no first contact, and none may be claimed.
        let gapped = |witness: Value, first: Value| {
            json!({
                "span": ["0", "1"],
                "collision_free": null,
                "collision_free_reason": "1 piece(s) of the span undecided (see gaps)",
                "complete": false,
                "first_contact": first,
                "contacts": [],
                "timeline": [
                    {"state": "separate", "start": t("0", "0"), "end": t("1/4", "1/4")},
                    {"state": "separate", "start": t("3/4", "3/4"), "end": t("1", "1")},
                ],
                "gaps": [{"lo": "1/4", "hi": "3/4", "reason": "undecided", "witness": witness}],
            })
        };
        assert!(timeline(&gapped(Value::Null, Value::Null)).is_ok());
        assert!(timeline(&gapped(Value::Null, t("1/4", "3/4"))).is_err());
        // With a witness, the first contact runs from the gap's start to it.
        let w = json!({"t": "1/2", "state": "overlap"});
        assert!(timeline(&gapped(w.clone(), t("1/4", "1/2"))).is_ok());
        assert!(timeline(&gapped(w.clone(), Value::Null)).is_err());
        assert!(timeline(&gapped(
            json!({"t": "7/8", "state": "overlap"}),
            t("1/4", "7/8")
        ))
        .is_err());
    }

    #[test]
    fn instants_lie_strictly_inside_segments() {
        let (_, segs) = timeline(&good()).unwrap();
        let mut k = 0;
        let got = instants(&segs, 8, &mut |n| {
            k += 1;
            k % n
        });
        assert_eq!(got.len(), 4, "two open segments, two instants each");
        for (at, state) in got {
            assert_eq!(state, State::Separate);
            assert!(
                (Rat::zero() < at && at < Rat::from_frac(1, 3))
                    || (Rat::from_frac(2, 3) < at && at < Rat::one()),
                "{at}"
            );
        }
    }

    #[test]
    fn long_output_rationals_are_read() {
        let long = format!("1/{}", "1".repeat(5000));
        assert!(rat(&json!(long), "x").is_ok());
        assert!(rat(&json!("1/0"), "x").is_err());
        assert!(rat(&json!("x"), "x").is_err());
    }
}
