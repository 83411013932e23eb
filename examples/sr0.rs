//! The integer coefficients of a scene's λ-discriminant `sr0(u)`, as the
//! exact path's closed form gives it (`u = (t − t0)/(t1 − t0)`, the
//! normalised `f(λ; u)` of `ccd_exact::symbolic`), one JSON line per scene:
//! the input of benches/compare/compare.py's FLINT column.
//!
//! `cargo run --release --example sr0 -- SCENE.toml…`
//!
//! Each line is `{"scene": NAME, "quantity": "sr0", "coeffs": [c0, c1, …]}`
//! with the coefficients as decimal strings, constant term first. When
//! `sr0 ≡ 0` (e.g. Example 5.1) the line carries `sr11` instead, with
//! `"quantity": "sr11"` and `"sr0_zero": true` (and `"sr11_zero": true`,
//! `"coeffs": []` when `sr11 ≡ 0` too). A scene that is not a
//! rational pair (a world file, a helical motion) prints `"error"`.

use ccd_poly::ZPoly;
use ccd_subres::{closed_form, Quantity};
use serde_json::json;

/// The JSON line of one scene file.
fn line(path: &str) -> serde_json::Value {
    let name = path.rsplit('/').next().unwrap_or(path);
    let fail = |e: String| json!({ "scene": name, "error": e });
    let text = match std::fs::read_to_string(path) {
        Ok(t) => t,
        Err(e) => return fail(e.to_string()),
    };
    let scene = match ccd_exact::Scene::from_toml(&text) {
        Ok(s) => s,
        Err(e) => return fail(e.to_string()),
    };
    let (f, _) = match ccd_exact::symbolic(&scene) {
        Ok(x) => x,
        Err(e) => return fail(e.to_string()),
    };
    let digits = |p: &ZPoly| -> Vec<String> { p.coeffs().iter().map(|c| c.to_string()).collect() };
    let sr0 = closed_form(&f.coeffs, Quantity::Sr0).expect("sr0 has a closed form");
    if !sr0.is_zero() {
        return json!({ "scene": name, "quantity": "sr0", "sr0_zero": false, "coeffs": digits(&sr0) });
    }
    let sr11 = closed_form(&f.coeffs, Quantity::Sr11).expect("sr11 has a closed form");
    json!({
        "scene": name, "quantity": "sr11", "sr0_zero": true,
        "sr11_zero": sr11.is_zero(), "coeffs": digits(&sr11)
    })
}

fn main() {
    for path in std::env::args().skip(1) {
        println!("{}", line(&path));
    }
}
