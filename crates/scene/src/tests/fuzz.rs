//! No input makes the parser panic: mutated shipped scenes and random
//! TOML-like text. Whatever parses also validates.

use super::SHIPPED;
use crate::Scene;
use proptest::prelude::*;

/// One byte edit: replace, insert or delete at a position (taken modulo the
/// current length).
#[derive(Clone, Debug)]
enum Edit {
    Replace(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    /// Duplicate a range, e.g. a whole line or array.
    Repeat(usize, usize),
}

/// Bytes that matter to TOML and to numbers, plus anything at all.
fn byte() -> impl Strategy<Value = u8> {
    prop_oneof![
        3 => prop::sample::select(b"[]{}=,.\"'#\n 0123456789-+_/eEinfa".to_vec()),
        1 => any::<u8>(),
    ]
}

fn edit() -> impl Strategy<Value = Edit> {
    prop_oneof![
        (any::<usize>(), byte()).prop_map(|(i, b)| Edit::Replace(i, b)),
        (any::<usize>(), byte()).prop_map(|(i, b)| Edit::Insert(i, b)),
        any::<usize>().prop_map(Edit::Delete),
        (any::<usize>(), 1usize..64).prop_map(|(i, n)| Edit::Repeat(i, n)),
    ]
}

fn apply(mut bytes: Vec<u8>, edits: &[Edit]) -> Vec<u8> {
    for e in edits {
        let len = bytes.len();
        match *e {
            Edit::Replace(i, b) if len > 0 => bytes[i % len] = b,
            Edit::Insert(i, b) => bytes.insert(i % (len + 1), b),
            Edit::Delete(i) if len > 0 => {
                bytes.remove(i % len);
            }
            Edit::Repeat(i, n) if len > 0 => {
                let start = i % len;
                let end = (start + n).min(len);
                let copy = bytes[start..end].to_vec();
                bytes.splice(start..start, copy);
            }
            _ => {}
        }
    }
    bytes
}

/// Parsing never panics; a parsed scene passes `validate`, and an error
/// message starts with its field.
fn check(text: &str) {
    match Scene::from_toml(text) {
        Ok(s) => assert_eq!(s.validate(), Ok(())),
        Err(e) => {
            let shown = e.to_string();
            match e.field() {
                Some(f) => assert!(shown.starts_with(&format!("field `{f}`: ")), "{shown}"),
                None => assert!(shown.starts_with("not TOML"), "{shown}"),
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn mutated_shipped_scenes_never_panic(which in 0..SHIPPED.len(), edits in prop::collection::vec(edit(), 1..8)) {
        let bytes = apply(SHIPPED[which].1.as_bytes().to_vec(), &edits);
        check(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn random_toml_like_text_never_panics(text in "[\\[\\]{}=,.\"'#\n 0-9a-z_+/-]{0,200}") {
        check(&text);
    }

    #[test]
    fn random_values_in_a_scene_never_panic(
        key in prop::sample::select(vec!["radii", "center", "orientation", "axis", "rate", "weights", "matrix", "kind", "frequency"]),
        kind in prop::sample::select(vec!["static", "translation", "rigid", "affine", "helical", "x"]),
        value in "[\\[\\]{}, 0-9a-z_+./\"-]{0,60}",
    ) {
        check(&format!("[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"{kind}\"\n{key} = {value}\n[b]\nradii = [1, 1, 1]\n"));
        check(&format!("[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\ncenter = {{ {key} = {value} }}\n[b]\nradii = [1, 1, 1]\n"));
    }
}
