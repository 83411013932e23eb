//! The comparison harness: every method on every case, scored against the
//! ground truth, timed.

use crate::baseline::sample;
use crate::{Case, StabilityError};
use ccd_arith::{Int, Rat};
use ccd_exact::{run, Arithmetic, Options, Outcome, State};
use std::time::{Duration, Instant};

/// A method under test.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Method {
    /// `ccd-exact`, exact certified arithmetic (the default).
    Exact,
    /// `ccd-exact --arithmetic float`: the paper's `f64` Bernstein
    /// subdivision on the exact `f(λ; t)`.
    Float,
    /// The exact static test at `N` evenly spaced instants.
    Sampled(usize),
}

impl Method {
    /// The methods of the report, in order.
    pub const ALL: [Method; 4] = [
        Method::Exact,
        Method::Float,
        Method::Sampled(100),
        Method::Sampled(1000),
    ];

    /// A short label.
    pub fn label(self) -> String {
        match self {
            Method::Exact => "exact".into(),
            Method::Float => "float".into(),
            Method::Sampled(n) => format!("sampled N={n}"),
        }
    }
}

/// A method's answer, in common terms.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Answer {
    /// Separate throughout?
    pub collision_free: bool,
    /// Reported isolated contacts as `[lo, hi]` (a single point `lo = hi` for
    /// an estimate).
    pub contacts: Vec<(Rat, Rat)>,
    /// The timeline's (or the samples') states, repeats collapsed.
    pub states: Vec<State>,
}

impl From<&Outcome> for Answer {
    fn from(out: &Outcome) -> Answer {
        let mut states: Vec<State> = out.timeline.iter().map(|s| s.state).collect();
        states.dedup();
        Answer {
            collision_free: out.collision_free,
            contacts: out
                .contacts
                .iter()
                .map(|c| (c.lo.clone(), c.hi.clone()))
                .collect(),
            states,
        }
    }
}

/// One query of `method` on `case`.
pub fn answer(case: &Case, method: Method) -> Result<Answer, StabilityError> {
    let engine = |arithmetic| {
        let opts = Options {
            arithmetic,
            ..Options::default()
        };
        run(&case.scene, &opts)
            .map(|o| Answer::from(&o))
            .map_err(|source| StabilityError::Engine {
                name: case.name.clone(),
                method: if arithmetic == Arithmetic::Exact {
                    "exact"
                } else {
                    "float"
                },
                source: Box::new(source),
            })
    };
    match method {
        Method::Exact => engine(Arithmetic::Exact),
        Method::Float => engine(Arithmetic::Float),
        Method::Sampled(n) => {
            let s = sample(&case.scene, n)?;
            Ok(Answer {
                collision_free: s.collision_free,
                contacts: s.contacts.into_iter().map(|t| (t.clone(), t)).collect(),
                states: s.states,
            })
        }
    }
}

/// How one method did on one case.
#[derive(Clone, Debug)]
pub struct Score {
    /// The case's name.
    pub case: String,
    /// The method.
    pub method: Method,
    /// The collision-free verdict is right.
    pub verdict_ok: bool,
    /// The number of isolated contacts is right.
    pub count_ok: bool,
    /// The state sequence is right.
    pub states_ok: bool,
    /// Contacts reported.
    pub found: usize,
    /// `max |estimate − true instant|` over the contacts (the midpoint of an
    /// enclosure is the estimate), when the count is right and nonzero.
    pub time_error: Option<f64>,
    /// Every true instant lies in its reported `[lo, hi]`, or (for a
    /// bracketed truth) the bracket meets it — decided exactly.
    pub enclosed: bool,
    /// Median wall time of one query.
    pub seconds: f64,
    /// The engine refused the scene (counts as wrong).
    pub refused: Option<String>,
}

impl Score {
    /// Wrong verdict, wrong contact count, or refused.
    pub fn wrong(&self) -> bool {
        !self.verdict_ok || !self.count_ok || self.refused.is_some()
    }
}

/// Scores an answer against the case's truth.
pub fn score(case: &Case, method: Method, ans: &Answer, seconds: f64) -> Score {
    let t = &case.truth;
    let count_ok = ans.contacts.len() == t.contacts.len();
    let pairs = || t.contacts.iter().zip(&ans.contacts);
    let time_error = (count_ok && !t.contacts.is_empty()).then(|| {
        pairs()
            .map(|(truth, (lo, hi))| truth.distance(&Rat::midpoint(lo, hi)))
            .fold(0.0, f64::max)
    });
    Score {
        case: case.name.clone(),
        method,
        verdict_ok: ans.collision_free == t.collision_free,
        count_ok,
        states_ok: ans.states == t.states,
        found: ans.contacts.len(),
        time_error,
        enclosed: count_ok && pairs().all(|(truth, (lo, hi))| truth.agrees(lo, hi)),
        seconds,
        refused: None,
    }
}

/// Runs `f` once, then again while the total stays under `budget`, up to
/// `max_reps` runs; returns the first result and the median time.
pub fn timed<T>(max_reps: usize, budget: Duration, mut f: impl FnMut() -> T) -> (T, f64) {
    let start = Instant::now();
    let first = f();
    let mut times = vec![start.elapsed().as_secs_f64()];
    while times.len() < max_reps && start.elapsed() < budget {
        let s = Instant::now();
        std::hint::black_box(f());
        times.push(s.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    (first, times[times.len() / 2])
}

impl Method {
    /// The method as a command-line word: `exact`, `float`, `sampled:N`.
    pub fn word(self) -> String {
        match self {
            Method::Exact => "exact".into(),
            Method::Float => "float".into(),
            Method::Sampled(n) => format!("sampled:{n}"),
        }
    }

    /// The method named by [`Method::word`].
    pub fn from_word(word: &str) -> Option<Method> {
        match word {
            "exact" => Some(Method::Exact),
            "float" => Some(Method::Float),
            _ => word
                .strip_prefix("sampled:")
                .and_then(|n| n.parse().ok())
                .map(Method::Sampled),
        }
    }
}

impl Answer {
    /// The answer as JSON (rationals as exact strings).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "collision_free": self.collision_free,
            "contacts": self.contacts.iter()
                .map(|(lo, hi)| [lo.to_string(), hi.to_string()]).collect::<Vec<_>>(),
            "states": self.states.iter().map(|s| s.name()).collect::<Vec<_>>(),
        })
    }

    /// Reads [`Answer::to_json`]'s text.
    pub fn from_json(text: &str) -> Option<Answer> {
        let v: serde_json::Value = serde_json::from_str(text).ok()?;
        // `p/q` of any length (enclosure ends can exceed the scene
        // format's 4096 characters a number, which `Rat::parse_exact`
        // enforces).
        let rat = |x: &serde_json::Value| {
            let text = x.as_str()?;
            let (p, q) = text.split_once('/').unwrap_or((text, "1"));
            Rat::new(Int::parse_decimal(p)?, Int::parse_decimal(q)?)
        };
        let contacts = v
            .get("contacts")?
            .as_array()?
            .iter()
            .map(|c| Some((rat(c.get(0)?)?, rat(c.get(1)?)?)))
            .collect::<Option<Vec<_>>>()?;
        let states = v
            .get("states")?
            .as_array()?
            .iter()
            .map(|s| crate::truth::parse_state(s.as_str()?))
            .collect::<Option<Vec<_>>>()?;
        Some(Answer {
            collision_free: v.get("collision_free")?.as_bool()?,
            contacts,
            states,
        })
    }
}

/// Runs each method's first query in a child process (`EXE answer FILE
/// METHOD`, the `stability` binary) that is killed after `budget`, so a
/// query that stalls costs the report `budget`, not the rest of its run,
/// and leaves nothing running.
#[derive(Clone, Debug)]
pub struct Guard {
    /// The `stability` executable.
    pub exe: std::path::PathBuf,
    /// The longest one query may take.
    pub budget: Duration,
}

impl Guard {
    /// [`answer`] in a child process, waited for at most `self.budget`.
    pub fn answer(&self, case: &Case, method: Method) -> Result<Answer, StabilityError> {
        let dir = std::env::temp_dir();
        let path = dir.join(format!(
            "ccd-stability-{}-{}.toml",
            std::process::id(),
            case.name
        ));
        let text = crate::scene_io::to_toml(&case.scene, &[])?;
        std::fs::write(&path, text).map_err(|e| StabilityError::io(&path, e))?;
        let result = self.run_child(case, method, &path);
        let _ = std::fs::remove_file(&path);
        result
    }

    fn run_child(
        &self,
        case: &Case,
        method: Method,
        path: &std::path::Path,
    ) -> Result<Answer, StabilityError> {
        use std::io::Read;
        use std::process::{Command, Stdio};
        let io = |e| StabilityError::io(&self.exe, e);
        let mut child = Command::new(&self.exe)
            .arg("answer")
            .arg(path)
            .arg(method.word())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .map_err(io)?;
        // Both pipes are drained while the child runs: an answer longer
        // than a pipe's buffer would otherwise block it until the budget.
        let drain = |pipe: Option<Box<dyn std::io::Read + Send>>| {
            std::thread::spawn(move || {
                let mut bytes = Vec::new();
                if let Some(mut pipe) = pipe {
                    let _ = pipe.read_to_end(&mut bytes);
                }
                bytes
            })
        };
        let out_reader = drain(child.stdout.take().map(|p| Box::new(p) as _));
        let err_reader = drain(child.stderr.take().map(|p| Box::new(p) as _));
        let start = Instant::now();
        let status = loop {
            if let Some(status) = child.try_wait().map_err(io)? {
                break status;
            }
            if start.elapsed() > self.budget {
                let _ = child.kill();
                let _ = child.wait();
                return Err(StabilityError::NoAnswer {
                    name: case.name.clone(),
                    method: method.label(),
                    seconds: self.budget.as_secs(),
                });
            }
            std::thread::sleep(Duration::from_millis(2));
        };
        let out = out_reader.join().unwrap_or_default();
        let err = err_reader.join().unwrap_or_default();
        let stdout = String::from_utf8_lossy(&out);
        match Answer::from_json(&stdout) {
            Some(a) if status.success() => Ok(a),
            _ => Err(StabilityError::Child {
                name: case.name.clone(),
                method: method.label(),
                message: String::from_utf8_lossy(&err).trim().to_string(),
            }),
        }
    }
}

/// Runs and scores `method` on `case`: median of up to 5 runs within
/// about a quarter second.
pub fn evaluate(case: &Case, method: Method) -> Score {
    evaluate_with(case, method, None)
}

/// [`evaluate`], the first run under `guard` when given (a query that
/// does not answer within the budget is refused: wrong).
pub fn evaluate_with(case: &Case, method: Method, guard: Option<&Guard>) -> Score {
    let mut first = guard;
    let (ans, secs) = timed(5, Duration::from_millis(250), || match first.take() {
        Some(g) => g.answer(case, method),
        None => answer(case, method),
    });
    match ans {
        Ok(a) => score(case, method, &a, secs),
        Err(e) => Score {
            case: case.name.clone(),
            method,
            verdict_ok: false,
            count_ok: false,
            states_ok: false,
            found: 0,
            time_error: None,
            enclosed: false,
            seconds: secs,
            refused: Some(e.to_string()),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn answers_round_trip_through_json_with_long_numbers() {
        let long = Rat::new(Int::one(), Int::pow10(5000)).unwrap_or_else(Rat::zero);
        let a = Answer {
            collision_free: false,
            contacts: vec![(long.clone(), &long + &Rat::from_frac(-3, 7))],
            states: vec![State::Separate, State::Touch, State::Separate],
        };
        assert_eq!(Answer::from_json(&a.to_json().to_string()), Some(a));
        for m in Method::ALL {
            assert_eq!(Method::from_word(&m.word()), Some(m));
        }
    }
}
