//! The comparison harness: every method on every case, scored against the
//! ground truth, timed.

use crate::baseline::sample;
use crate::{Case, StabilityError};
use ccd_arith::Rat;
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
    /// Every true instant lies in its reported `[lo, hi]` (decided exactly).
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
        enclosed: count_ok && pairs().all(|(truth, (lo, hi))| truth.within(lo, hi)),
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

/// Runs and scores `method` on `case`: median of up to 5 runs within
/// about a quarter second.
pub fn evaluate(case: &Case, method: Method) -> Score {
    let (ans, secs) = timed(5, Duration::from_millis(250), || answer(case, method));
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
