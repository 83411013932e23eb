//! Median wall-clock time of the library call `ccd_exact::run` per scene
//! and mode, with the path each query took: the quick, one-run table
//! behind docs/table4.md's per-class rows (criterion gives the benches).
//!
//! `cargo run --release --example speed -- [--reps N] [--no-geometry] SCENE.toml…`
//!
//! Prints one tab-separated line per scene: name, exact total, exact first
//! contact, float total (µs, medians), exact/float ratio, deg f, deg sr0,
//! whether `sr0` was formed, then `--raycast` total and first contact (µs)
//! and the path that answered it (`raycast`, or `exact` where it handed the
//! query to Algorithm 1). `--no-geometry` times every mode without the
//! contact points and normals (`Options::contact_geometry` off), which
//! separates their cost from the instants'.

use ccd_exact::{run, Arithmetic, Options};
use std::time::Instant;

mod timing;

fn median_us(reps: usize, mut f: impl FnMut()) -> f64 {
    timing::median(
        (0..reps)
            .map(|_| {
                let s = Instant::now();
                f();
                s.elapsed().as_secs_f64() * 1e6
            })
            .collect(),
    )
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let reps = timing::take_count(&mut args, "--reps", 31);
    let exact = Options {
        contact_geometry: !timing::take_switch(&mut args, "--no-geometry"),
        ..Options::default()
    };
    let first = Options {
        first_contact_only: true,
        ..exact.clone()
    };
    let float = Options {
        arithmetic: Arithmetic::Float,
        ..exact.clone()
    };
    let ray = Options {
        raycast: true,
        ..exact.clone()
    };
    let ray_first = Options {
        raycast: true,
        ..first.clone()
    };
    println!(
        "scene\texact_us\tfirst_us\tfloat_us\tratio\tdeg_f\tdeg_sr0\tsr0_formed\traycast_us\traycast_first_us\traycast_path"
    );
    for (path, scene) in timing::scenes(args) {
        let Ok(out) = run(&scene, &exact) else {
            eprintln!("{path}: error");
            continue;
        };
        let e = median_us(reps, || drop(run(&scene, &exact)));
        let fc = median_us(reps, || drop(run(&scene, &first)));
        let fl = if scene.a.motion.is_rational() && scene.b.motion.is_rational() {
            median_us(reps, || drop(run(&scene, &float)))
        } else {
            f64::NAN
        };
        let r = median_us(reps, || drop(run(&scene, &ray)));
        let rf = median_us(reps, || drop(run(&scene, &ray_first)));
        let answered_by = match run(&scene, &ray).map(|o| o.stats.path) {
            Ok(ccd_exact::Path::Raycast) => "raycast",
            Ok(_) => "exact",
            Err(_) => "error",
        };
        let name = path.rsplit('/').next().unwrap_or(&path);
        println!(
            "{name}\t{e:.1}\t{fc:.1}\t{fl:.1}\t{:.2}\t{}\t{}\t{}\t{r:.1}\t{rf:.1}\t{answered_by}",
            e / fl,
            out.stats.deg_f,
            out.stats.deg_sr0.map_or(-1, |d| d as i64),
            out.stats.sr0_formed
        );
    }
}
