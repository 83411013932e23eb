//! Writing a [`Scene`] as scene TOML (format 1, `docs/scene-format.md`),
//! every number as an exact rational string, so that
//! `Scene::from_toml(&to_toml(s)) == s`.

use crate::StabilityError;
use ccd_arith::{Int, Rat};
use ccd_motion::{Bezier, Body, Motion};
use ccd_scene::Scene;
use std::fmt::Write;

/// `p/q` forms longer than this are written as a decimal when shorter.
const LONG: usize = 100;

/// `x` as `"p/q"`, or — when that is long and the denominator divides
/// `10^e` — as the shorter decimal `"me-e"`, so that `10⁻⁴⁰⁹⁶` is
/// `"1e-4096"`, within the format's 4096 characters a number.
fn num(x: &Rat) -> String {
    let plain = x.to_string();
    match decimal(x) {
        Some(d) if plain.len() > LONG && d.len() < plain.len() => format!("\"{d}\""),
        _ => format!("\"{plain}\""),
    }
}

/// `x = m/10^e` written `me-e`, when the denominator is `2^a·5^b`.
fn decimal(x: &Rat) -> Option<String> {
    let q = x.denom();
    let a = q.trailing_zeros()?;
    let odd = q.shr_floor(a);
    // odd = 5^b: b is within one of bits(odd)/log2(5).
    let guess = (odd.bits() as f64 / 5f64.log2()).round() as u32;
    let five = Int::from_i64(5);
    let b = (guess.saturating_sub(1)..=guess + 1).find(|&b| five.pow(b) == odd)?;
    let e = (a as u32).max(b);
    let m = &(x.numer() * &Int::one().shl(u64::from(e) - a)) * &five.pow(e - b);
    Some(if e == 0 {
        m.to_string()
    } else {
        format!("{m}e-{e}")
    })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn powers_of_ten_are_written_short_and_read_back() {
        let tiny = Rat::new(Int::one(), Int::pow10(4096)).unwrap_or_else(Rat::zero);
        for x in [
            tiny.clone(),
            -&tiny,
            &Rat::from_frac(5, 8)
                + &Rat::new(Int::one(), Int::pow10(200)).unwrap_or_else(Rat::zero),
            Rat::from_frac(-3, 40),
            Rat::from_frac(1, 3),
            Rat::from(7),
        ] {
            let text = num(&x);
            let inner = text.trim_matches('"');
            assert!(inner.len() <= x.to_string().len(), "{text}");
            assert_eq!(Rat::parse_exact(inner).ok(), Some(x), "{text}");
        }
        assert_eq!(num(&tiny), "\"1e-4096\"");
    }
}
