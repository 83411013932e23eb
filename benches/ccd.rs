//! Timings of the exact path: one static classification, and full CCD and
//! first-contact queries on the shipped rational scenes.
//!
//! `cargo bench -p ccd-benches --bench ccd` (default build) and
//! `cargo bench -p ccd-benches --bench ccd --features gmp`.

use ccd_arith::Rat;
use ccd_exact::{run, Options, Scene};
use ccd_quadric::{classify_pair, Ellipsoid};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;

fn scene(name: &str) -> Scene {
    let path = format!("{}/../{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn r(s: &str) -> Rat {
    s.parse().expect("a rational")
}

fn static_classification(c: &mut Criterion) {
    let a = Ellipsoid {
        radii: [r("3"), r("1/2"), r("0.5")],
        center: [r("0"), r("0"), r("0")],
        orientation: [r("1"), r("0"), r("0"), r("0")],
    };
    let b = Ellipsoid {
        radii: [r("2"), r("1.5"), r("0.25")],
        center: [r("0.1"), r("1.05"), r("0.05")],
        orientation: [r("1"), r("1/2"), r("0"), r("1/2")],
    };
    c.bench_function("static classification (exact)", |bench| {
        bench.iter(|| classify_pair(black_box(&a), black_box(&b)))
    });
}

fn ccd(c: &mut Criterion) {
    let mut g = c.benchmark_group("ccd exact");
    g.sample_size(30).measurement_time(Duration::from_secs(3));
    for name in [
        "tests/scenes/paper-example-5-1.toml",
        "tests/scenes/rigid-tumbling.toml",
        "benches/scenes/rigid-deg2.toml",
        "benches/scenes/affine-deg2.toml",
        "benches/scenes/affine-rational-deg2.toml",
        "benches/scenes/rigid-288.toml",
    ] {
        let s = scene(name);
        let full = Options::default();
        let first = Options {
            first_contact_only: true,
            ..Options::default()
        };
        let name = name.rsplit('/').next().unwrap_or(name);
        g.bench_function(format!("{name} total"), |bench| {
            bench.iter(|| run(black_box(&s), &full).expect("runs"))
        });
        g.bench_function(format!("{name} first contact"), |bench| {
            bench.iter(|| run(black_box(&s), &first).expect("runs"))
        });
    }
    g.finish();
}

/// What the contact point and normal add to a query (issue 14): the same
/// queries with and without `contact_geometry`.
fn geometry(c: &mut Criterion) {
    let mut g = c.benchmark_group("contact geometry");
    g.sample_size(30).measurement_time(Duration::from_secs(3));
    for name in [
        "tests/scenes/paper-example-5-1.toml",
        "benches/scenes/affine-rational-deg2.toml",
        "tests/stability/graze-ellipsoids-k08-overlap.toml",
    ] {
        let s = scene(name);
        let name = name.rsplit('/').next().unwrap_or(name);
        for geometry in [false, true] {
            let o = Options {
                contact_geometry: geometry,
                ..Options::default()
            };
            let label = if geometry { "with" } else { "without" };
            g.bench_function(format!("{name} total {label} geometry"), |bench| {
                bench.iter(|| run(black_box(&s), &o).expect("runs"))
            });
        }
    }
    g.finish();
}

/// Straight-line pairs (issue 17's workload: particle moves, planners):
/// Algorithm 1's exact query against the certified ray cast (`--raycast`),
/// total and first contact, on a crossing whose `sr0` is formed, a plain
/// crossing and a miss.
fn straight_lines(c: &mut Criterion) {
    let mut g = c.benchmark_group("straight lines");
    g.sample_size(30).measurement_time(Duration::from_secs(3));
    for name in ["line01", "line04", "line05"] {
        let s = scene(&format!("benches/scenes/lines/{name}.toml"));
        for raycast in [false, true] {
            for first_contact_only in [false, true] {
                let o = Options {
                    raycast,
                    first_contact_only,
                    ..Options::default()
                };
                let path = run(&s, &o).expect("runs").stats.path;
                assert_eq!(path == ccd_exact::Path::Raycast, raycast, "{name}");
                let mode = if raycast { "raycast" } else { "exact" };
                let what = if first_contact_only {
                    "first contact"
                } else {
                    "total"
                };
                g.bench_function(format!("{name} {mode} {what}"), |bench| {
                    bench.iter(|| run(black_box(&s), &o).expect("runs"))
                });
            }
        }
    }
    g.finish();
}

criterion_group!(
    benches,
    static_classification,
    ccd,
    geometry,
    straight_lines
);
criterion_main!(benches);
