//! Unit tests: the shipped scenes, exactness, the invalid-scene suite,
//! [`Scene::validate`] on code-built scenes, and no-panic fuzzing.

mod fuzz;
mod invalid;
mod valid;
mod validate;
mod world;

use crate::{Rat, Scene};

/// The shipped example scenes (repository `tests/scenes/`), by file name.
pub(crate) const SHIPPED: [(&str, &str); 4] = [
    (
        "paper-example-5-1.toml",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/scenes/paper-example-5-1.toml"
        )),
    ),
    (
        "paper-example-5-2.toml",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/scenes/paper-example-5-2.toml"
        )),
    ),
    (
        "rigid-tumbling.toml",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/scenes/rigid-tumbling.toml"
        )),
    ),
    (
        "static-touching-spheres.toml",
        include_str!(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../tests/scenes/static-touching-spheres.toml"
        )),
    ),
];

/// Exact rationals from text, for expected values.
pub(crate) fn rats<const N: usize>(xs: [&str; N]) -> [Rat; N] {
    xs.map(|x| Rat::parse_exact(x).expect("test literal"))
}

/// One exact rational from text.
pub(crate) fn rat(x: &str) -> Rat {
    Rat::parse_exact(x).expect("test literal")
}

/// Parses a scene that must be valid.
pub(crate) fn parse_ok(text: &str) -> Scene {
    match Scene::from_toml(text) {
        Ok(s) => s,
        Err(e) => panic!("expected a valid scene, got `{e}` for\n{text}"),
    }
}
