//! Timings of the float mode (`ccd-float`, the paper's Table 3 setting) on
//! the shipped scenes and on the benchmark scenes of Table 3's three motion
//! classes (`benches/scenes/`: degree-2 rigid, degree-2 affine, rational
//! degree-2 affine "degree 4 affine"), plus a pair of tumbling bodies whose
//! normalised `f` keeps the paper's third-row degrees (deg_t f = 48,
//! deg sr0 = 288).
//!
//! For each scene: the exact set-up shared with the exact path (placed
//! quadrics → normalised `f(λ; u)` over ℤ[u], as in `ccd_exact::symbolic`),
//! the float set-up (`prepare`: `f` → f64 Bernstein `sr` polynomials), the
//! float solve (`solve_prepared`), and the totals (scene → outcome), for
//! full timelines and first-contact queries. Criterion prints means; the
//! medians are in `target/criterion/<group>/<bench>/new/estimates.json`.
//!
//! `cargo bench -p ccd-benches --bench float` (about a minute).

use ccd_exact::Options;
use ccd_float::{prepare, solve, solve_prepared};
use ccd_scene::Scene;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::time::Duration;

fn file(name: &str) -> String {
    let path = format!("{}/../{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

fn scenes() -> Vec<(&'static str, Scene)> {
    let parse = |t: &str| Scene::from_toml(t).expect("a valid scene");
    vec![
        (
            "example-5-1",
            parse(&file("tests/scenes/paper-example-5-1.toml")),
        ),
        (
            "rigid-tumbling",
            parse(&file("tests/scenes/rigid-tumbling.toml")),
        ),
        ("rigid-deg2", parse(&file("benches/scenes/rigid-deg2.toml"))),
        (
            "affine-deg2",
            parse(&file("benches/scenes/affine-deg2.toml")),
        ),
        (
            "affine-rational-deg2",
            parse(&file("benches/scenes/affine-rational-deg2.toml")),
        ),
        ("rigid-288", parse(&file("benches/scenes/rigid-288.toml"))),
    ]
}

/// The exact, normalised `f(λ; u)`, as the exact path computes it.
fn char_poly(s: &Scene) -> ccd_motion::CharPoly {
    ccd_motion::char_poly(&s.a, &s.b, &s.span).expect("a valid rational scene")
}

fn float(c: &mut Criterion) {
    let full = Options::default();
    let first = Options {
        first_contact_only: true,
        ..Options::default()
    };
    for (name, s) in scenes() {
        let f = char_poly(&s);
        let p = prepare(&f);
        let out = solve(&f, &s.span, &full);
        eprintln!(
            "{name}: deg f = {}, deg sr0 = {:?}, branch {}, {} candidates, {} contacts",
            out.stats.deg_f,
            out.stats.deg_sr0,
            out.stats.branch_name(),
            out.stats.candidates,
            out.contacts.len()
        );
        let mut g = c.benchmark_group(format!("float {name}"));
        g.sample_size(15)
            .warm_up_time(Duration::from_millis(150))
            .measurement_time(Duration::from_millis(700));
        g.bench_function("set-up exact f (shared)", |b| {
            b.iter(|| char_poly(black_box(&s)))
        });
        g.bench_function("set-up float sr", |b| b.iter(|| prepare(black_box(&f))));
        g.bench_function("solve", |b| {
            b.iter(|| solve_prepared(black_box(&p), &s.span, &full))
        });
        g.bench_function("solve first contact", |b| {
            b.iter(|| solve_prepared(black_box(&p), &s.span, &first))
        });
        g.bench_function("total", |b| {
            b.iter(|| solve(&char_poly(black_box(&s)), &s.span, &full))
        });
        g.bench_function("total first contact", |b| {
            b.iter(|| solve(&char_poly(black_box(&s)), &s.span, &first))
        });
        g.finish();
    }
}

criterion_group!(benches, float);
criterion_main!(benches);
