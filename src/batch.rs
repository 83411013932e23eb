//! The streaming batch: JSON Lines in (one pair scene per line), one result
//! line per input line out, in input order, solved in parallel in bounded
//! memory. The unit that shards across machines (docs/scaling.md).

use ccd_scene::{Limit, Scene, SceneError, MAX_INPUT_BYTES};
use serde_json::{Map, Value};
use std::collections::BTreeMap;
use std::io::{self, BufRead, Write};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::mpsc;

use crate::{run, to_json, Options};

/// How a batch runs.
#[derive(Clone, Debug)]
pub struct BatchOptions {
    /// The options of every pair query.
    pub options: Options,
    /// Worker threads; `0` for rayon's default (`RAYON_NUM_THREADS`, else
    /// one per core).
    pub threads: usize,
    /// Most lines read but not yet written (bounds memory together with
    /// [`BatchOptions::max_bytes_in_flight`]); at least 1.
    pub max_lines_in_flight: usize,
    /// Most bytes of input lines read but not yet answered; one line is
    /// always admitted (a line is at most [`MAX_INPUT_BYTES`]).
    pub max_bytes_in_flight: usize,
}

impl Default for BatchOptions {
    fn default() -> BatchOptions {
        BatchOptions {
            options: Options::default(),
            threads: 0,
            max_lines_in_flight: 1024,
            max_bytes_in_flight: 64 << 20,
        }
    }
}

/// What a batch did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BatchSummary {
    /// Lines read (and result lines written).
    pub lines: u64,
    /// Of them, error lines.
    pub errors: u64,
}

/// Why a batch stopped before the end of its input.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum BatchError {
    /// Reading the input or writing the output failed.
    #[error("{0}")]
    Io(#[from] io::Error),
    /// The worker threads could not be started.
    #[error("cannot start the worker threads: {0}")]
    Threads(#[from] rayon::ThreadPoolBuildError),
}

/// One input line: its bytes, or the mark of a line over the limit (whose
/// bytes are skipped, not kept).
enum Line {
    Text(Vec<u8>),
    TooLong,
}

/// Reads one line (without its `\n` or `\r\n`), keeping at most `max`
/// bytes of it; `None` at the end of the input.
fn read_line(r: &mut impl BufRead, max: usize) -> io::Result<Option<Line>> {
    let mut buf = Vec::new();
    let mut too_long = false;
    let mut any = false;
    loop {
        let chunk = match r.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            break;
        }
        any = true;
        let (take, newline) = match chunk.iter().position(|&b| b == b'\n') {
            Some(i) => (i, true),
            None => (chunk.len(), false),
        };
        if !too_long {
            if buf.len() + take > max {
                too_long = true;
                buf = Vec::new();
            } else {
                buf.extend_from_slice(&chunk[..take]);
            }
        }
        r.consume(take + usize::from(newline));
        if newline {
            break;
        }
    }
    if !any {
        return Ok(None);
    }
    if buf.last() == Some(&b'\r') {
        buf.pop();
    }
    Ok(Some(if too_long {
        Line::TooLong
    } else {
        Line::Text(buf)
    }))
}

/// The result line (compact JSON, no newline) for input line `n` (1-based):
/// `{"line": n, <the pair result object>}`, or `{"line": n, "error": "line
/// n: …", "field": …}` naming the field (`null` when the error is not about
/// one, e.g. JSON syntax).
pub fn batch_line(n: u64, text: &str, options: &Options) -> String {
    answer(n, Line::Text(text.as_bytes().to_vec()), options).0
}

/// [`batch_line`] on a read line; also says whether it is an error line.
fn answer(n: u64, line: Line, options: &Options) -> (String, bool) {
    let mut obj = Map::new();
    obj.insert("line".into(), n.into());
    let error = |obj: &mut Map<String, Value>, field: Option<&str>, message: String| {
        obj.insert("error".into(), format!("line {n}: {message}").into());
        obj.insert("field".into(), field.map_or(Value::Null, Value::from));
    };
    let text = match line {
        Line::TooLong => {
            let e = SceneError::TooLarge {
                field: "<file>".into(),
                limit: Limit::InputBytes,
            };
            error(&mut obj, e.field(), e.to_string());
            None
        }
        Line::Text(bytes) => match String::from_utf8(bytes) {
            Ok(t) => Some(t),
            Err(_) => {
                error(&mut obj, None, "not UTF-8".into());
                None
            }
        },
    };
    if let Some(text) = text {
        let solved = catch_unwind(AssertUnwindSafe(|| {
            Scene::from_json(&text)
                .map_err(crate::CcdError::from)
                .and_then(|s| run(&s, options))
        }));
        match solved {
            Ok(Ok(out)) => {
                if let Value::Object(m) = to_json(&out) {
                    obj.extend(m);
                }
            }
            Ok(Err(e)) => {
                let field = match &e {
                    crate::CcdError::Scene(s) => s.field().map(str::to_string),
                    crate::CcdError::Motion { field, .. } => Some(field.clone()),
                    _ => None,
                };
                error(&mut obj, field.as_deref(), e.to_string());
            }
            Err(_) => error(
                &mut obj,
                None,
                "internal error: the query panicked (a bug: please report the line)".into(),
            ),
        }
    }
    let is_error = obj.contains_key("error");
    (Value::Object(obj).to_string(), is_error)
}

/// The ordered writer: results arrive in any order and leave in input
/// order.
struct Ordered<'a, W: Write> {
    out: io::BufWriter<W>,
    pending: BTreeMap<u64, (String, bool)>,
    written: u64,
    summary: BatchSummary,
    progress: &'a dyn Fn(),
}

impl<W: Write> Ordered<'_, W> {
    /// Takes result `n` and writes every result now in order.
    fn push(&mut self, n: u64, line: String, is_error: bool) -> io::Result<()> {
        self.pending.insert(n, (line, is_error));
        while let Some((line, is_error)) = self.pending.remove(&(self.written + 1)) {
            self.out.write_all(line.as_bytes())?;
            self.out.write_all(b"\n")?;
            self.written += 1;
            self.summary.lines += 1;
            self.summary.errors += u64::from(is_error);
            (self.progress)();
        }
        Ok(())
    }
}

/// Runs a batch: reads `input` line by line, answers each line on a pool of
/// `options.threads` workers and writes its result line to `output` in
/// input order (see [`batch_line`]), calling `progress` after each written
/// line. A bad line gives an error line and the batch goes on; at most
/// `max_lines_in_flight` lines (and about `max_bytes_in_flight` bytes) are
/// held at once, so memory stays bounded on any input. A line over
/// [`MAX_INPUT_BYTES`] is an error line (its bytes are skipped unread).
/// Output is flushed whenever the batch waits for a worker.
///
/// Call it from outside a rayon pool (it blocks its thread while the
/// workers run).
pub fn run_batch(
    mut input: impl BufRead,
    output: impl Write,
    options: &BatchOptions,
    progress: &dyn Fn(),
) -> Result<BatchSummary, BatchError> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.threads)
        .build()?;
    let mut out = Ordered {
        out: io::BufWriter::new(output),
        pending: BTreeMap::new(),
        written: 0,
        summary: BatchSummary::default(),
        progress,
    };
    let (tx, rx) = mpsc::channel::<(u64, usize, String, bool)>();
    let (mut read, mut bytes, mut eof) = (0u64, 0usize, false);
    let max_lines = options.max_lines_in_flight.max(1) as u64;
    loop {
        let in_flight = read - out.written;
        if eof && in_flight == 0 {
            break;
        }
        let full =
            in_flight >= max_lines || (in_flight > 0 && bytes >= options.max_bytes_in_flight);
        let received = if eof || full {
            // Waiting for a worker: let the reader of our output see what
            // is done.
            out.out.flush()?;
            Some(
                rx.recv()
                    .map_err(|_| io::Error::other("a worker stopped"))?,
            )
        } else {
            rx.try_recv().ok()
        };
        if let Some((n, size, line, is_error)) = received {
            bytes -= size;
            out.push(n, line, is_error)?;
            continue;
        }
        match read_line(&mut input, MAX_INPUT_BYTES)? {
            None => eof = true,
            Some(line) => {
                read += 1;
                let n = read;
                let size = match &line {
                    Line::Text(b) => b.len(),
                    Line::TooLong => 0,
                };
                bytes += size;
                let tx = tx.clone();
                let opts = options.options.clone();
                pool.spawn(move || {
                    let (text, is_error) = answer(n, line, &opts);
                    // The receiver outlives every worker unless writing
                    // failed; then the answer has nowhere to go.
                    let _ = tx.send((n, size, text, is_error));
                });
            }
        }
    }
    out.out.flush()?;
    Ok(out.summary)
}
