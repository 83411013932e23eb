//! `ccd_exact._native`: the Rust half of the Python package `ccd_exact`.
//!
//! The Python half (`ccd_exact/__init__.py`) turns Python objects into a
//! scene's TOML text (every number as exact text), so scenes reach the
//! engine through the same parser and the same field-naming errors as the
//! CLI. Here: run queries with the GIL released (one, or many on rayon's
//! threads in the order given, or a world of many bodies), and hand back
//! each answer as an opaque [`Query`] or [`WorldQuery`] whose JSON is the
//! CLI's `--json` text. A panic never crosses into Python: it becomes a
//! `RuntimeError`.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::Instant;

use ccd_broad::BroadError;
use ccd_exact::{
    run, run_world, to_json_pretty, world_to_json_pretty, Arithmetic, CcdError, Options, Outcome,
    Scene, SceneFile, World, WorldOutcome,
};
use ccd_scene::SceneError;
use pyo3::exceptions::{PyIndexError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use rayon::prelude::*;

/// One answered query: the scene and its outcome.
#[pyclass(frozen, module = "ccd_exact._native")]
struct Query {
    scene: Scene,
    outcome: Outcome,
}

#[pymethods]
impl Query {
    /// The result as the CLI's `--json` prints it (pretty, no final newline).
    fn json(&self) -> String {
        to_json_pretty(&self.outcome)
    }
    /// The SVG picture (timeline strip and contact sections).
    #[pyo3(signature = (title = ""))]
    fn svg(&self, title: &str) -> String {
        ccd_picture::svg(&self.scene, &self.outcome, title)
    }
    /// The self-contained HTML page animating the query.
    #[pyo3(signature = (title = ""))]
    fn html(&self, title: &str) -> String {
        ccd_picture::html(&self.scene, &self.outcome, title)
    }
}

/// One answered world: the world and its outcome.
#[pyclass(frozen, module = "ccd_exact._native")]
struct WorldQuery {
    world: World,
    outcome: WorldOutcome,
}

impl WorldQuery {
    /// The outcome of queried pair `k` (`pairs[k]` of the JSON), or why
    /// there is none.
    fn outcome(&self, k: usize) -> PyResult<(Scene, &Outcome)> {
        let p = self.outcome.pairs.get(k).ok_or_else(|| {
            PyIndexError::new_err(format!(
                "pair {k}: the world has {} queried pairs",
                self.outcome.pairs.len()
            ))
        })?;
        match &p.result {
            Ok(o) => Ok((self.world.pair(p.a, p.b), o)),
            Err(e) => Err(PyValueError::new_err(format!(
                "pair {k} ({:?}, {:?}) has no answer: {e}",
                self.outcome.bodies[p.a], self.outcome.bodies[p.b]
            ))),
        }
    }
}

#[pymethods]
impl WorldQuery {
    /// The result as the CLI's `--json` prints it for the world (pretty, no
    /// final newline); written with the GIL released.
    fn json(&self, py: Python<'_>) -> String {
        py.detach(|| world_to_json_pretty(&self.outcome))
    }
    /// Queried pair `k`'s result as `ccd-exact --json` prints it for that
    /// pair's scene (the world's span, bodies `a` and `b`); `None` when the
    /// pair's query has no answer (its `error` in the world's JSON).
    fn pair_json(&self, k: usize) -> PyResult<Option<String>> {
        match self.outcome.pairs.get(k).map(|p| &p.result) {
            Some(Ok(o)) => Ok(Some(to_json_pretty(o))),
            Some(Err(_)) => Ok(None),
            None => Err(PyIndexError::new_err(format!(
                "pair {k}: the world has {} queried pairs",
                self.outcome.pairs.len()
            ))),
        }
    }
    /// Queried pair `k`'s SVG picture.
    #[pyo3(signature = (k, title = ""))]
    fn pair_svg(&self, k: usize, title: &str) -> PyResult<String> {
        let (scene, o) = self.outcome(k)?;
        Ok(ccd_picture::svg(&scene, o, title))
    }
    /// Queried pair `k`'s HTML page.
    #[pyo3(signature = (k, title = ""))]
    fn pair_html(&self, k: usize, title: &str) -> PyResult<String> {
        let (scene, o) = self.outcome(k)?;
        Ok(ccd_picture::html(&scene, o, title))
    }
}

/// Why a query failed, before it becomes a Python exception (which needs
/// the GIL, so is made after the work).
enum Failure {
    /// The scene is invalid: the message and the field it names.
    Scene(String, Option<String>),
    /// An option is out of range.
    Option(String),
    /// The exact path reached a documented effort bound.
    Effort(String),
    /// A bug: an internal error or a panic.
    Internal(String),
}

impl From<SceneError> for Failure {
    fn from(e: SceneError) -> Failure {
        Failure::Scene(e.to_string(), e.field().map(str::to_string))
    }
}

impl From<CcdError> for Failure {
    fn from(e: CcdError) -> Failure {
        let message = e.to_string();
        match e {
            CcdError::Scene(s) => s.into(),
            CcdError::Motion { field, .. } => Failure::Scene(message, Some(field)),
            CcdError::Option { .. } => Failure::Option(message),
            CcdError::Effort { .. } => Failure::Effort(message),
            // A world's documented cap on candidate pairs: a limit, as an effort bound is.
            CcdError::Broad(BroadError::TooManyCandidates { .. }) => Failure::Effort(message),
            CcdError::Internal(_) => Failure::Internal(message),
            // `CcdError` is non-exhaustive: a new kind is a bug until it is mapped.
            _ => Failure::Internal(message),
        }
    }
}

impl Failure {
    /// The Python exception: `ccd_exact.SceneError(message, field)`,
    /// `ValueError`, `ccd_exact.EffortError` or `RuntimeError`.
    fn into_py(self, py: Python<'_>, prefix: &str) -> PyErr {
        let errors = py.import("ccd_exact._errors");
        let raise = |class: &str, args: (String, Option<String>)| -> PyErr {
            match errors
                .as_ref()
                .map_err(|e| e.clone_ref(py))
                .and_then(|m| m.getattr(class))
                .and_then(|c| c.call1(args))
            {
                Ok(value) => PyErr::from_value(value),
                Err(e) => e,
            }
        };
        match self {
            Failure::Scene(m, field) => raise("SceneError", (format!("{prefix}{m}"), field)),
            Failure::Effort(m) => raise("EffortError", (format!("{prefix}{m}"), None)),
            Failure::Option(m) => PyValueError::new_err(format!("{prefix}{m}")),
            Failure::Internal(m) => PyRuntimeError::new_err(format!(
                "{prefix}ccd-exact {m} (a bug: please report it with the scene)"
            )),
        }
    }
}

/// The engine's options from the Python ones (checked in Python too).
fn options(
    first_contact: bool,
    digits: u32,
    arithmetic: &str,
    geometry: bool,
    raycast: bool,
) -> PyResult<Options> {
    let arithmetic = match arithmetic {
        "exact" => Arithmetic::Exact,
        "float" => Arithmetic::Float,
        other => {
            return Err(PyValueError::new_err(format!(
                "option `arithmetic`: expected \"exact\" or \"float\", found {other:?}"
            )))
        }
    };
    Ok(Options {
        first_contact_only: first_contact,
        digits,
        arithmetic,
        contact_geometry: geometry,
        raycast,
    })
}

/// Runs `work`; a panic is caught and reported as an internal error.
fn guarded<T>(work: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    catch_unwind(AssertUnwindSafe(work)).unwrap_or_else(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "panic".into());
        Err(Failure::Internal(format!("internal error (panic): {what}")))
    })
}

/// Parses and runs one pair scene; a world file is refused, naming the
/// entry that answers it.
fn answer(text: &str, options: &Options) -> Result<Query, Failure> {
    guarded(|| match SceneFile::from_toml(text)? {
        SceneFile::Pair(scene) => {
            let outcome = run(&scene, options)?;
            Ok(Query {
                scene: *scene,
                outcome,
            })
        }
        SceneFile::World(_) => Err(Failure::Scene(
            "field `body`: this is a world file (`[[body]]` tables), not a pair scene: \
             answer it with `collide_world_toml` (or `collide_world`)"
                .into(),
            Some("body".into()),
        )),
    })
}

/// Parses and runs one world; a pair file is refused, naming the entry
/// that answers it.
fn answer_world(text: &str, options: &Options) -> Result<WorldQuery, Failure> {
    guarded(|| match SceneFile::from_toml(text)? {
        SceneFile::World(world) => {
            let outcome = run_world(&world, options)?;
            Ok(WorldQuery { world, outcome })
        }
        SceneFile::Pair(_) => Err(Failure::Scene(
            "field `body`: missing: a world file has `[[body]]` tables; this is a pair \
             scene (`[a]`, `[b]`): answer it with `collide_toml`"
                .into(),
            Some("body".into()),
        )),
    })
}

/// Runs `work` on `threads` threads (`None`: rayon's global pool).
fn on_threads<T: Send>(
    threads: Option<usize>,
    work: impl FnOnce() -> T + Send,
) -> Result<T, String> {
    match threads {
        None => Ok(work()),
        Some(0) => Err("option `threads`: at least 1".to_string()),
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n)
            .build()
            .map(|pool| pool.install(work))
            .map_err(|e| format!("option `threads`: cannot start {n} threads: {e}")),
    }
}

/// Runs the scene `text` (TOML) with the GIL released.
#[pyfunction]
#[pyo3(signature = (text, first_contact = false, digits = 15, arithmetic = "exact", geometry = true, raycast = false))]
fn run_toml(
    py: Python<'_>,
    text: &str,
    first_contact: bool,
    digits: u32,
    arithmetic: &str,
    geometry: bool,
    raycast: bool,
) -> PyResult<Query> {
    let options = options(first_contact, digits, arithmetic, geometry, raycast)?;
    py.detach(|| answer(text, &options))
        .map_err(|f| f.into_py(py, ""))
}

/// Runs many scenes on `threads` threads (`None`: rayon's pool, one per
/// core) with the GIL released; the answers come in the order given. The
/// first failing scene (in that order) raises, its index in the message.
#[pyfunction]
#[pyo3(signature = (texts, threads = None, first_contact = false, digits = 15, arithmetic = "exact", geometry = true, raycast = false))]
fn run_many(
    py: Python<'_>,
    texts: Vec<String>,
    threads: Option<usize>,
    first_contact: bool,
    digits: u32,
    arithmetic: &str,
    geometry: bool,
    raycast: bool,
) -> PyResult<Vec<Query>> {
    let options = options(first_contact, digits, arithmetic, geometry, raycast)?;
    let all = || -> Vec<Result<Query, Failure>> {
        texts.par_iter().map(|t| answer(t, &options)).collect()
    };
    let answers = py.detach(|| on_threads(threads, all));
    let answers = answers.map_err(PyValueError::new_err)?;
    answers
        .into_iter()
        .enumerate()
        .map(|(i, a)| a.map_err(|f| f.into_py(py, &format!("pairs[{i}]: "))))
        .collect()
}

/// Runs the world file `text` (TOML, `[[body]]` tables) on `threads`
/// threads (`None`: rayon's pool, one per core) with the GIL released.
#[pyfunction]
#[pyo3(signature = (text, threads = None, first_contact = false, digits = 15, arithmetic = "exact", geometry = true, raycast = false))]
fn run_world_toml(
    py: Python<'_>,
    text: &str,
    threads: Option<usize>,
    first_contact: bool,
    digits: u32,
    arithmetic: &str,
    geometry: bool,
    raycast: bool,
) -> PyResult<WorldQuery> {
    let options = options(first_contact, digits, arithmetic, geometry, raycast)?;
    py.detach(|| on_threads(threads, || answer_world(text, &options)))
        .map_err(PyValueError::new_err)?
        .map_err(|f| f.into_py(py, ""))
}

/// Median seconds of `reps` runs of the scene `text` inside Rust (parsing
/// once, then `ccd_exact::run` only): the baseline for the Python overhead.
#[pyfunction]
#[pyo3(signature = (text, reps = 100))]
fn median_run_seconds(py: Python<'_>, text: &str, reps: usize) -> PyResult<f64> {
    /// Most runs one call times (the sample is held in memory).
    const MAX_REPS: usize = 1_000_000;
    if reps > MAX_REPS {
        return Err(PyValueError::new_err(format!(
            "option `reps`: at most {MAX_REPS}"
        )));
    }
    let options = Options::default();
    let scene = Scene::from_toml(text).map_err(|e| Failure::from(e).into_py(py, ""))?;
    py.detach(|| {
        guarded(|| {
            let mut times: Vec<f64> = (0..reps.max(1))
                .map(|_| {
                    let start = Instant::now();
                    let out = run(&scene, &options);
                    let secs = start.elapsed().as_secs_f64();
                    drop(out);
                    secs
                })
                .collect();
            times.sort_by(f64::total_cmp);
            Ok(times[times.len() / 2])
        })
    })
    .map_err(|e| e.into_py(py, ""))
}

/// The module `ccd_exact._native`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Query>()?;
    m.add_class::<WorldQuery>()?;
    m.add_function(wrap_pyfunction!(run_toml, m)?)?;
    m.add_function(wrap_pyfunction!(run_many, m)?)?;
    m.add_function(wrap_pyfunction!(run_world_toml, m)?)?;
    m.add_function(wrap_pyfunction!(median_run_seconds, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
