//! Whether the exact and float queries slow each other down when they run
//! in turn: the median wall-clock time of the library call
//! `ccd_exact::run` per scene in the exact mode alone, in the float mode
//! alone, and of one exact plus one float query alternated (blocks of 200
//! queries, medians of the per-block means).
//!
//! `cargo run --release --example interference -- [--blocks N] [--no-geometry] SCENE.toml…`
//!
//! Prints one tab-separated line per scene: name, exact alone, float
//! alone, their sum, the alternated pair (µs) and the pair's excess over
//! the sum (%). Both modes run the same code for the quadric matrices and
//! `f(λ; t)`; an excess is time the two queries cost each other when run
//! in turn, not work (through the caches or the branch predictors, we
//! presume; docs/table4.md, issue 17, session 41, could not see which).
//! `--no-geometry` leaves out the contact points and normals in both
//! modes, as in `speed`.

use ccd_exact::{run, Arithmetic, Options};
use std::time::Instant;
use timing::median;

mod timing;

/// Queries per timed block.
const BLOCK: usize = 200;

/// The mean time (µs) of one call of `f` over a block of calls.
fn block_mean_us(mut f: impl FnMut()) -> f64 {
    let s = Instant::now();
    for _ in 0..BLOCK {
        f();
    }
    s.elapsed().as_secs_f64() * 1e6 / BLOCK as f64
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let blocks = timing::take_count(&mut args, "--blocks", 15);
    println!("scene\texact_us\tfloat_us\tsum_us\talternated_us\texcess_pct");
    let exact = Options {
        contact_geometry: !timing::take_switch(&mut args, "--no-geometry"),
        ..Options::default()
    };
    let float = Options {
        arithmetic: Arithmetic::Float,
        ..exact.clone()
    };
    for (path, scene) in timing::scenes(args) {
        if run(&scene, &exact).is_err() || run(&scene, &float).is_err() {
            eprintln!("{path}: not answered in both modes");
            continue;
        }
        // Interleaved, so that drifts of the machine reach all three alike.
        let (mut e, mut f, mut p) = (Vec::new(), Vec::new(), Vec::new());
        for _ in 0..blocks {
            e.push(block_mean_us(|| drop(run(&scene, &exact))));
            f.push(block_mean_us(|| drop(run(&scene, &float))));
            p.push(block_mean_us(|| {
                drop(run(&scene, &exact));
                drop(run(&scene, &float));
            }));
        }
        let (e, f, p) = (median(e), median(f), median(p));
        let name = path.rsplit('/').next().unwrap_or(&path);
        println!(
            "{name}\t{e:.1}\t{f:.1}\t{:.1}\t{p:.1}\t{:+.1}",
            e + f,
            100.0 * (p / (e + f) - 1.0)
        );
    }
}
