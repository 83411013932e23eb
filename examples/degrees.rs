//! Degrees of f(λ; t) and sr0(t) for a scene: in the plain adjugate form
//! (`A ∝ adj(P)ᵀ·D·adj(P)`, `det(λA + B)` with only its common content
//! removed — what the paper's Table 3 reports for its affine rows) and in
//! ours (content removal and λ-rescaling, `ccd_motion::characteristic`).
//!
//! `cargo run --release --example degrees -- SCENE.toml…`

use ccd_motion::{moving_quadric, CharPoly};
use ccd_poly::ZPoly;
use ccd_quadric::characteristic;
use ccd_subres::{closed_form, Quantity};

fn degrees(f: &[ZPoly; 5]) -> (usize, usize) {
    let deg_f = f.iter().filter_map(ZPoly::degree).max().unwrap_or(0);
    (
        deg_f,
        closed_form(f, Quantity::Sr0).map_or(0, |s| s.degree().unwrap_or(0)),
    )
}

fn main() {
    for path in std::env::args().skip(1) {
        let text = match std::fs::read_to_string(&path) {
            Ok(t) => t,
            Err(e) => {
                eprintln!("{path}: {e}");
                std::process::exit(2);
            }
        };
        let scene = match ccd_exact::Scene::from_toml(&text) {
            Ok(s) => s,
            Err(e) => {
                eprintln!("{path}: {e}");
                std::process::exit(2);
            }
        };
        let (Ok(a), Ok(b)) = (
            moving_quadric(&scene.a, &scene.span),
            moving_quadric(&scene.b, &scene.span),
        ) else {
            eprintln!("{path}: not a valid rational scene");
            std::process::exit(2);
        };
        let raw = characteristic(&a, &b);
        let g = raw.iter().fold(ZPoly::zero(), |g, c| g.gcd(c));
        let adjugate: [ZPoly; 5] =
            std::array::from_fn(|k| raw[k].div_exact(&g).expect("gcd divides"));
        let ours = CharPoly::new(&a, &b).coeffs;
        let (pf, ps) = degrees(&adjugate);
        let (of, os) = degrees(&ours);
        println!("{path}: adjugate form {pf} / {ps}, ours {of} / {os}");
    }
}
