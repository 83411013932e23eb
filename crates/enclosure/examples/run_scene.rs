//! Runs the interval path on a scene file and prints the timeline:
//! `cargo run -p ccd-enclosure --example run_scene -- tests/scenes/screw-step.toml [digits]`.

use ccd_enclosure::{run, Options};
use ccd_scene::Scene;
use ccd_timeline::Instant;

fn show(i: &Instant) -> String {
    format!(
        "{} (width {:.1e}, {})",
        i.approx(16),
        i.width().to_f64(),
        if i.certified {
            "certified"
        } else {
            "NOT certified"
        }
    )
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let path = args.next().ok_or("usage: run_scene SCENE.toml [digits]")?;
    let digits = args.next().map(|d| d.parse()).transpose()?.unwrap_or(15);
    let scene = Scene::from_toml(&std::fs::read_to_string(&path)?)?;
    let options = Options {
        digits,
        first_contact_only: false,
    };
    let clock = std::time::Instant::now();
    let out = run(&scene.a, &scene.b, &scene.span, &options)?;
    let elapsed = clock.elapsed();
    println!("collision_free: {}", out.collision_free);
    for c in &out.contacts {
        println!("contact: {}", show(c));
    }
    for s in &out.timeline {
        println!(
            "{:<8} {} .. {}",
            s.state.name(),
            show(&s.start),
            show(&s.end)
        );
    }
    println!(
        "branch: {}, candidates: {}, time: {elapsed:?}",
        out.stats.branch, out.stats.candidates
    );
    Ok(())
}
