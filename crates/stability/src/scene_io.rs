//! Writing a [`Scene`] as scene TOML (format 1, `docs/scene-format.md`),
//! every number as an exact rational string, so that
//! `Scene::from_toml(&to_toml(s)) == s`.

use crate::StabilityError;
use ccd_arith::Rat;
use ccd_motion::{Bezier, Body, Motion};
use ccd_scene::Scene;
use std::fmt::Write;

fn num(x: &Rat) -> String {
    format!("\"{x}\"")
}

fn list<T>(xs: &[T], f: impl Fn(&T) -> String) -> String {
    format!("[{}]", xs.iter().map(f).collect::<Vec<_>>().join(", "))
}

fn curve<const N: usize>(key: &str, c: &Bezier<[Rat; N]>, out: &mut String) {
    let _ = writeln!(out, "{key} = {}", list(&c.points, |p| list(p, num)));
    if let Some(w) = &c.weights {
        let _ = writeln!(out, "weights = {}", list(w, num));
    }
}

fn body(name: &str, b: &Body, out: &mut String) -> Result<(), StabilityError> {
    let _ = writeln!(out, "\n[{name}]\nradii = {}", list(&b.radii, num));
    let _ = writeln!(out, "[{name}.motion]");
    match &b.motion {
        Motion::Static {
            center,
            orientation,
        } => {
            let _ = writeln!(out, "kind = \"static\"\ncenter = {}", list(center, num));
            let _ = writeln!(out, "orientation = {}", list(orientation, num));
        }
        Motion::Translation {
            center,
            orientation,
        } => {
            let _ = writeln!(out, "kind = \"translation\"");
            curve("center", center, out);
            let _ = writeln!(out, "orientation = {}", list(orientation, num));
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            let _ = writeln!(out, "kind = \"rigid\"");
            let _ = writeln!(
                out,
                "orientation = {}",
                list(&orientation.points, |q| list(q, num))
            );
            curve("center", center, out);
        }
        Motion::Affine { matrix } => {
            let _ = writeln!(out, "kind = \"affine\"");
            let rows = |m: &[[Rat; 4]; 3]| list(m, |r| list(r, num));
            let _ = writeln!(out, "matrix = {}", list(&matrix.points, rows));
            if let Some(w) = &matrix.weights {
                let _ = writeln!(out, "weights = {}", list(w, num));
            }
        }
        Motion::Helical { .. } => return Err(StabilityError::Unsupported("helical")),
    }
    Ok(())
}

/// The scene as TOML text, preceded by `comment` lines (`# …`).
pub fn to_toml(scene: &Scene, comment: &[String]) -> Result<String, StabilityError> {
    let mut out = String::new();
    for line in comment {
        let _ = writeln!(out, "# {line}");
    }
    let _ = writeln!(out, "format = 1\nspan = {}", list(&scene.span, num));
    body("a", &scene.a, &mut out)?;
    body("b", &scene.b, &mut out)?;
    Ok(out)
}
