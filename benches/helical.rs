//! Timings of the interval path (`ccd-enclosure`) on non-rational motions:
//! the paper's Example 5.2 and a constant-velocity screw step, and the same
//! screw step approximated by a rational motion (quadratic quaternion
//! Bézier matching the end orientations, linear centre) through the exact
//! path (`ccd_exact::run`).
//!
//! `cargo bench -p ccd-benches --bench helical` (default build) and
//! `cargo bench -p ccd-benches --bench helical --features gmp`.

use ccd_exact::{Options, Scene};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;

fn scene(name: &str) -> Scene {
    let path = format!("{}/../tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    Scene::from_toml(&text).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// `screw-step.toml` with the rotation by 1.5 rad about z replaced by the
/// quadratic quaternion Bézier `(1, 0, 0, 0)`, `(1, 0, 0, tan 0.375)`,
/// `(cos 0.75, 0, 0, sin 0.75)` (same end orientations, rotation angle
/// monotone from 0 to 1.5 but not linear in t) and the centre line as a
/// linear Bézier: a rational motion for the exact path.
const SCREW_RATIONAL: &str = r#"
span = [0, 1]
[a]
radii = [2, 0.5, 0.5]
[a.motion]
kind = "rigid"
orientation = [[1, 0, 0, 0], [1, 0, 0, 0.39362657592563277], [0.7316888688738209, 0, 0, 0.6816387600233341]]
center = [[-4, 0.5, 0], [4, 0.5, 0]]
[b]
radii = [0.5, 0.5, 1.5]
"#;

fn helical(c: &mut Criterion) {
    let mut g = c.benchmark_group("helical");
    g.sample_size(10).measurement_time(Duration::from_secs(5));
    let full = ccd_exact::Options::default();
    let first = ccd_exact::Options {
        first_contact_only: true,
        ..full.clone()
    };
    for name in ["paper-example-5-2.toml", "screw-step.toml"] {
        let s = scene(name);
        g.bench_function(format!("{name} interval total"), |b| {
            b.iter(|| ccd_interval::run(&s.a, &s.b, &s.span, &full).expect("runs"))
        });
        g.bench_function(format!("{name} interval first contact"), |b| {
            b.iter(|| ccd_interval::run(&s.a, &s.b, &s.span, &first).expect("runs"))
        });
    }
    let rational = Scene::from_toml(SCREW_RATIONAL).expect("valid scene");
    g.bench_function("screw-step rational approximation exact total", |b| {
        b.iter(|| ccd_exact::run(black_box(&rational), &Options::default()).expect("runs"))
    });
    g.bench_function(
        "screw-step rational approximation exact first contact",
        |b| {
            let o = Options {
                first_contact_only: true,
                ..Options::default()
            };
            b.iter(|| ccd_exact::run(black_box(&rational), &o).expect("runs"))
        },
    );
    g.finish();
}

criterion_group!(benches, helical);
criterion_main!(benches);
