//! Worlds and batches (issue 15), a bench binary: prints markdown tables.
//!
//! * `world`: N random moving ellipsoids (half translating, half rigid) on
//!   a jittered lattice (one density, set so that about 1 % of the pairs of
//!   the N = 1000 world are candidates): broad-phase time,
//!   candidates, total time of `run_world`, against brute force (the exact
//!   query on every pair; estimated from a random sample of pairs above
//!   `--brute-limit` pairs, and said so).
//! * `batch`: `run_batch` throughput, pairs per second on 1 and 2 worker
//!   threads, on JSON Lines of the paper's three motion classes (perturbed
//!   copies of benches/scenes/rigid-deg2, affine-deg2, affine-rational-deg2).
//!
//! `cargo bench --bench worlds` (both), `-- world 100 1000 10000`, `-- batch`.

use ccd_arith::Rat;
use ccd_exact::{run, run_batch, run_world, BatchOptions, Options, World};
use ccd_motion::{Bezier, Body, Motion};
use ccd_scene::NamedBody;
use rayon::prelude::*;
use serde_json::json;
use std::time::Instant;

/// The coordinate grid: 1/1024 (`CCD_BENCH_GRID` overrides it; the exact
/// query's cost grows with the numbers' bits).
fn grid() -> i64 {
    std::env::var("CCD_BENCH_GRID")
        .ok()
        .and_then(|g| g.parse().ok())
        .unwrap_or(1024)
}

/// splitmix64: a reproducible stream without a dependency.
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// An integer in `lo..=hi`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
    /// A multiple of 1/GRID in `[lo, hi]`.
    fn rat(&mut self, lo: f64, hi: f64) -> Rat {
        let g = grid();
        Rat::from_frac(self.int((lo * g as f64) as i64, (hi * g as f64) as i64), g)
    }
}

/// `n` bodies on a jittered cubic lattice of spacing `a` (a hard-particle
/// simulation's kind of configuration: neighbours near, few overlapping at
/// the start), half translating and half rigid (a linear quaternion curve:
/// a turn of a fraction of a radian), each moving up to 1 per coordinate
/// over the span. Radii in [1/2, 1]; coordinates on a 1/1024 grid.
fn random_world(n: usize, a: f64, seed: u64) -> World {
    let mut r = Rng(seed);
    let side = (n as f64).cbrt().ceil() as usize;
    let bodies = (0..n)
        .map(|i| {
            let cell = [i % side, (i / side) % side, i / (side * side)];
            let radii = [0; 3].map(|_| Rat::from_frac(r.int(4, 8), 8));
            let c0: [Rat; 3] = std::array::from_fn(|k| {
                r.rat(cell[k] as f64 * a - a / 8.0, cell[k] as f64 * a + a / 8.0)
            });
            let c1: [Rat; 3] = std::array::from_fn(|k| &c0[k] + &r.rat(-1.0, 1.0));
            let center = Bezier {
                points: vec![c0, c1],
                weights: None,
            };
            let q0: [Rat; 4] = [0; 4].map(|_| Rat::from(r.int(-3, 3)));
            let q0 = if q0.iter().all(Rat::is_zero) {
                Motion::identity()
            } else {
                q0
            };
            let motion = if i % 2 == 0 {
                Motion::Translation {
                    center,
                    orientation: q0,
                }
            } else {
                let q1: [Rat; 4] =
                    std::array::from_fn(|k| &q0[k] + &Rat::from_frac(r.int(-1, 1), 4));
                let q1 = if q1.iter().all(Rat::is_zero) {
                    q0.clone()
                } else {
                    q1
                };
                Motion::Rigid {
                    orientation: Bezier {
                        points: vec![q0, q1],
                        weights: None,
                    },
                    center,
                }
            };
            NamedBody {
                name: format!("e{i}"),
                body: Body { radii, motion },
            }
        })
        .collect();
    World {
        span: [Rat::zero(), Rat::one()],
        bodies,
    }
}

/// The share of pairs whose certified boxes overlap in some slice (the
/// candidates of a box broad phase; the separating planes then prune more).
fn candidate_share(w: &World) -> f64 {
    let swept: Vec<_> = w
        .bodies
        .par_iter()
        .map(|b| ccd_broad::sweep(&b.body, &w.span, ccd_broad::DEFAULT_DEPTH))
        .collect();
    let found = ccd_broad::broad_phase(&swept, usize::MAX).expect("same slices");
    let n = w.bodies.len() as f64;
    found.box_overlaps as f64 / (n * (n - 1.0) / 2.0)
}

/// The lattice spacing at which the boxes of about 1 % of the pairs of the
/// N = 1000 world overlap (bisection on the broad phase alone).
fn spacing() -> f64 {
    let (mut lo, mut hi) = (1.0f64, 6.0f64);
    for _ in 0..20 {
        let a = 0.5 * (lo + hi);
        if candidate_share(&random_world(1000, a, 1015)) > 0.01 {
            lo = a;
        } else {
            hi = a;
        }
    }
    0.5 * (lo + hi)
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn secs(s: f64) -> String {
    if s < 1e-3 {
        format!("{:.0} µs", s * 1e6)
    } else if s < 1.0 {
        format!("{:.1} ms", s * 1e3)
    } else {
        format!("{s:.2} s")
    }
}

fn world_bench(sizes: &[usize], brute_limit: u64) {
    let opts = Options {
        contact_geometry: false,
        ..Options::default()
    };
    let a = spacing();
    println!("lattice spacing {a:.3} (the boxes of about 1 % of the N = 1000 world's pairs overlap); {} worker threads\n", rayon::current_num_threads());
    println!(
        "| N | pairs | box candidates (share) | exact queries (share) | pruned (proven separate) | colliding | broad phase | world total | brute force | brute / world |"
    );
    println!("| ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
    for &n in sizes {
        let w = random_world(n, a, 15 + n as u64);
        let runs = if n >= 10_000 { 1 } else { 3 };
        let mut broad = Vec::new();
        let mut total = Vec::new();
        let mut last = None;
        for _ in 0..runs {
            let clock = Instant::now();
            let out = run_world(&w, &opts).expect("a valid world");
            total.push(clock.elapsed().as_secs_f64());
            broad.push(out.broad_phase.seconds);
            last = Some(out);
        }
        let out = last.expect("ran");
        let pairs = (n * (n - 1) / 2) as u64;
        // Brute force: every pair through the exact query, in parallel on
        // the same pool; above the limit a random sample of pairs, scaled.
        let mut r = Rng(7);
        let sample: Vec<(usize, usize)> = if pairs <= brute_limit {
            (0..n)
                .flat_map(|i| (i + 1..n).map(move |j| (i, j)))
                .collect()
        } else {
            (0..brute_limit)
                .map(|_| loop {
                    let (i, j) = (
                        r.int(0, n as i64 - 1) as usize,
                        r.int(0, n as i64 - 1) as usize,
                    );
                    if i != j {
                        break (i.min(j), i.max(j));
                    }
                })
                .collect()
        };
        let clock = Instant::now();
        sample.par_iter().for_each(|&(i, j)| {
            run(&w.pair(i, j), &opts).expect("a valid pair");
        });
        let brute = clock.elapsed().as_secs_f64() * pairs as f64 / sample.len() as f64;
        let estimated = if sample.len() as u64 == pairs {
            ""
        } else {
            " (est.)"
        };
        let c = out.broad_phase.candidates;
        let boxed = out.broad_phase.box_overlaps;
        println!(
            "| {n} | {pairs} | {boxed} ({:.2} %) | {c} ({:.2} %) | {} | {} | {} | {} | {}{estimated} | {:.0}× |",
            100.0 * boxed as f64 / pairs as f64,
            100.0 * c as f64 / pairs as f64,
            out.broad_phase.pruned,
            out.colliding().len(),
            secs(median(broad)),
            secs(median(total.clone())),
            secs(brute),
            brute / median(total)
        );
    }
}

/// JSON Lines of one motion class: `n` perturbed copies (b's translation
/// shifted by multiples of 1/64 within ±1/2 per coordinate).
fn batch_lines(class: &str, n: usize) -> String {
    let mut r = Rng(class.len() as u64);
    let mut text = String::new();
    for _ in 0..n {
        let d: Vec<String> = (0..3).map(|_| format!("{}/64", r.int(-32, 32))).collect();
        let add = |x: &str, k: usize| {
            let v: Rat =
                x.parse::<Rat>().expect("a number") + d[k].parse::<Rat>().expect("a fraction");
            v.to_string()
        };
        let scene = match class {
            "rigid-deg2" => json!({
                "a": {"radii": [3, 1, "1/2"], "motion": {"kind": "rigid", "orientation": [[1, 0, 0, 0], [1, 0, 1, 1]], "center": [[0, 0, 0]]}},
                "b": {"radii": [2, "3/2", 1], "motion": {"kind": "static", "center": [add("4", 0), add("1", 1), add("0", 2)], "orientation": [2, 1, 0, 0]}},
            }),
            "affine-deg2" => json!({
                "a": {"radii": [2, 1, 1], "motion": {"kind": "affine", "matrix": [
                    [[1, 0, 0, -3], [0, 1, 0, 0], [0, 0, 1, 0]],
                    [["1.2", "0.1", 0, 0], [0, "0.8", "0.2", 1], [0, 0, 1, "0.5"]],
                    [[1, 0, "0.3", 3], ["0.1", 1, 0, 0], [0, "0.2", "1.3", 0]]]}},
                "b": {"radii": [1, 2, 1], "motion": {"kind": "affine", "matrix": [
                    [[1, 0, 0, add("3", 0)], [0, 1, 0, add("0.5", 1)], [0, 0, 1, add("0", 2)]],
                    [["0.9", 0, "0.1", add("0", 0)], ["0.2", "1.1", 0, add("-1", 1)], [0, 0, 1, add("0.2", 2)]],
                    [["1.1", "0.2", 0, add("-3", 0)], [0, 1, 0, add("0.5", 1)], ["0.1", 0, "0.9", add("0", 2)]]]}},
            }),
            _ => json!({
                "a": {"radii": [2, 1, 1], "motion": {"kind": "affine", "weights": [1, 2, 1], "matrix": [
                    [[1, 0, 0, -4], [0, 1, 0, 0], [0, 0, 1, 0]],
                    [[2, "0.5", 0, 0], [0, "0.6", "0.3", 1], [0, 0, "1.5", "0.5"]],
                    [[1, 0, "0.5", 4], ["0.3", "1.5", 0, 0], [0, "0.4", 2, 0]]]}},
                "b": {"radii": [1, 2, 1], "motion": {"kind": "affine", "weights": [1, "0.5", 1], "matrix": [
                    [[1, 0, 0, add("4", 0)], [0, 1, 0, add("0.5", 1)], [0, 0, 1, add("0", 2)]],
                    [["0.5", 0, "0.2", add("0", 0)], ["0.4", "2.5", 0, add("-1", 1)], [0, 0, 1, add("0.2", 2)]],
                    [["1.5", "0.6", 0, add("-4", 0)], [0, 1, 0, add("0.5", 1)], ["0.2", 0, "0.7", add("0", 2)]]]}},
            }),
        };
        text.push_str(&scene.to_string());
        text.push('\n');
    }
    text
}

/// The speed-up the machine offers right now: the same CPU-bound loop
/// (no memory, no allocation) on 1 and on 2 threads at once. On a shared
/// machine it is below 2; the batch's own scaling is best read against it.
fn control() -> f64 {
    let spin = || {
        let mut x = 1u64;
        for i in 0..400_000_000u64 {
            x = x.wrapping_mul(6364136223846793005).wrapping_add(i);
        }
        std::hint::black_box(x)
    };
    let clock = Instant::now();
    spin();
    let one = clock.elapsed().as_secs_f64();
    let clock = Instant::now();
    std::thread::scope(|s| {
        s.spawn(spin);
        s.spawn(spin);
    });
    2.0 * one / clock.elapsed().as_secs_f64()
}

fn batch_bench(seconds: f64) {
    println!("| motion class | lines | 1 thread | 2 threads | speed-up (linear: 2.00) | control: the machine's speed-up meanwhile |");
    println!("| --- | ---: | ---: | ---: | ---: | ---: |");
    for class in ["rigid-deg2", "affine-deg2", "affine-rational-deg2"] {
        // Size the batch to about `seconds` on one thread.
        let probe = batch_lines(class, 32);
        let clock = Instant::now();
        let one = BatchOptions {
            threads: 1,
            ..BatchOptions::default()
        };
        run_batch(probe.as_bytes(), std::io::sink(), &one, &|| {}).expect("runs");
        let per = clock.elapsed().as_secs_f64() / 32.0;
        let n = ((seconds / per) as usize).clamp(16, 200_000);
        let lines = batch_lines(class, n);
        let machine = control();
        let mut rate = [0.0; 2];
        for (k, threads) in [1, 2].into_iter().enumerate() {
            let opts = BatchOptions {
                threads,
                ..BatchOptions::default()
            };
            let clock = Instant::now();
            let s = run_batch(lines.as_bytes(), std::io::sink(), &opts, &|| {}).expect("runs");
            assert_eq!((s.lines, s.errors), (n as u64, 0), "{class}");
            rate[k] = n as f64 / clock.elapsed().as_secs_f64();
        }
        println!(
            "| {class} | {n} | {:.0} pairs/s | {:.0} pairs/s | {:.2} | {:.2} (after: {:.2}) |",
            rate[0],
            rate[1],
            rate[1] / rate[0],
            machine,
            control()
        );
    }
}

fn main() {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    let sizes: Vec<usize> = args.iter().filter_map(|a| a.parse().ok()).collect();
    let want = |what: &str| args.is_empty() || args.iter().any(|a| a == what);
    if want("world") {
        let sizes = if sizes.is_empty() {
            vec![100, 1000, 10_000]
        } else {
            sizes
        };
        world_bench(&sizes, 5000);
        println!();
    }
    if want("batch") {
        batch_bench(10.0);
    }
}
