//! World files (`[[body]]`), the pair/world decision, and scenes written as
//! JSON (one line of `ccd-exact batch`).

use super::invalid::variant;
use super::{rat, SHIPPED};
use crate::{Motion, Scene, SceneError, SceneFile, World, MAX_BODIES};
use toml_edit::{DocumentMut, Item, Value};

const WORLD: &str = r#"
span = [0, 2]
[[body]]
name = "ball"
radii = [1, 1, 1]
[[body]]
name = "arm-2"
radii = [2, "1/2", 0.25]
motion = { kind = "translation", center = [[5, 0, 0], [0, 0, 0]] }
[[body]]
name = "wall"
radii = [1, 10, 10]
[body.motion]
kind = "static"
center = [-3, 0, 0]
"#;

fn world(text: &str) -> World {
    match SceneFile::from_toml(text) {
        Ok(SceneFile::World(w)) => w,
        other => panic!("expected a world, got {other:?}"),
    }
}

fn reject(text: &str, want: &str, field: &str) {
    match SceneFile::from_toml(text) {
        Err(e) => {
            assert_eq!(variant(&e), want, "{e}");
            assert_eq!(e.field(), Some(field), "{e}");
            assert!(
                e.to_string().starts_with(&format!("field `{field}`")),
                "{e}"
            );
        }
        Ok(f) => panic!("expected {want} on {field}, parsed {f:?}"),
    }
}

#[test]
fn a_world_file_has_named_bodies_in_file_order() {
    let w = world(WORLD);
    assert_eq!(w.span, [rat("0"), rat("2")]);
    let names: Vec<&str> = w.bodies.iter().map(|b| b.name.as_str()).collect();
    assert_eq!(names, ["ball", "arm-2", "wall"]);
    assert_eq!(w.bodies[1].body.radii[2], rat("1/4"));
    assert_eq!(w.bodies[0].body.motion, Motion::at_origin());
    let p = w.pair(1, 2);
    assert_eq!(
        (p.span, p.a, p.b),
        (
            w.span.clone(),
            w.bodies[1].body.clone(),
            w.bodies[2].body.clone()
        )
    );
    assert_eq!(w.body_field(1), "body[1] \"arm-2\"");
    // Inline spelling: the same world.
    let inline = r#"span = [0, 2]
        body = [{ name = "ball", radii = [1, 1, 1] },
                { name = "arm-2", radii = [2, "1/2", 0.25], motion = { kind = "translation", center = [[5, 0, 0], [0, 0, 0]] } },
                { name = "wall", radii = [1, 10, 10], motion = { kind = "static", center = [-3, 0, 0] } }]"#;
    assert_eq!(world(inline), w);
}

#[test]
fn every_pair_file_stays_a_pair_file() {
    for (name, text) in SHIPPED {
        match SceneFile::from_toml(text) {
            Ok(SceneFile::Pair(s)) => assert_eq!(*s, Scene::from_toml(text).unwrap(), "{name}"),
            other => panic!("{name}: {other:?}"),
        }
    }
    // A world file is not a pair scene: `Scene::from_toml` keeps format 1's
    // keys.
    let e = Scene::from_toml(WORLD).unwrap_err();
    assert_eq!(e.field(), Some("body"));
}

#[test]
fn world_errors_name_the_body() {
    let arm = WORLD.replace("[[5, 0, 0], [0, 0, 0]]", "[[5, 0, 0], [0, 0]]");
    reject(&arm, "Length", "body[1] \"arm-2\".motion.center[1]");
    reject(
        &WORLD.replace("[1, 10, 10]", "[1, -10, 10]"),
        "NonPositive",
        "body[2] \"wall\".radii[1]",
    );
    reject(
        &WORLD.replace("name = \"wall\"", "name = \"ball\""),
        "Name",
        "body[2] \"ball\".name",
    );
    reject(
        &WORLD.replace("name = \"wall\"", "name = \"\""),
        "Name",
        "body[2] \"\".name",
    );
    reject(
        &WORLD.replace("name = \"wall\"\n", ""),
        "Missing",
        "body[2].name",
    );
    reject(
        &WORLD.replace("name = \"wall\"", "name = 7"),
        "WrongType",
        "body[2].name",
    );
    reject(
        &WORLD.replace("name = \"wall\"", "name = \"wall\"\ncolour = 1"),
        "Unknown",
        "body[2] \"wall\".colour",
    );
    reject(&format!("{WORLD}\n[a]\nradii = [1, 1, 1]"), "Unknown", "a");
    reject("body = 3", "WrongType", "body");
    reject("body = [1]", "WrongType", "body[0]");
    reject(
        &WORLD.replace("span = [0, 2]", "span = [2, 2]"),
        "Span",
        "span",
    );
    let e = SceneFile::from_toml(&WORLD.replace("[1, 10, 10]", "[1, -10, 10]")).unwrap_err();
    assert_eq!(
        e.to_string(),
        "field `body[2] \"wall\".radii[1]`: must be > 0, found -10"
    );
}

#[test]
fn too_many_bodies_are_refused() {
    // The short inline spelling fits MAX_BODIES + 1 bodies in 4 MiB.
    let bodies = |n: usize| {
        let list: Vec<String> = (0..n)
            .map(|i| format!("{{name=\"{i}\",radii=[1,1,1]}}"))
            .collect();
        format!("body=[{}]", list.join(","))
    };
    let text = bodies(MAX_BODIES + 1);
    assert!(text.len() < crate::MAX_INPUT_BYTES);
    reject(&text, "TooLarge", "body");
    assert_eq!(world(&bodies(50)).bodies.len(), 50);
    let body = "[[body]]\nname = \"b{}\"\nradii = [1, 1, 1]\n";
    let ok: String = (0..50)
        .map(|i| body.replace("{}", &i.to_string()))
        .collect();
    assert_eq!(world(&ok).bodies.len(), 50);
}

/// TOML → JSON with numbers as the issue's JSON lines write them:
/// integers as integers, every other number as its decimal text.
fn to_json(item: &Item) -> serde_json::Value {
    use serde_json::Value as J;
    fn value(v: &Value) -> J {
        match v {
            Value::Integer(i) => J::from(*i.value()),
            Value::Float(f) => J::from(
                f.as_repr()
                    .unwrap()
                    .as_raw()
                    .as_str()
                    .unwrap()
                    .replace('_', ""),
            ),
            Value::String(s) => J::from(s.value().as_str()),
            Value::Boolean(b) => J::from(*b.value()),
            Value::Array(a) => J::Array(a.iter().map(value).collect()),
            Value::InlineTable(t) => {
                J::Object(t.iter().map(|(k, v)| (k.to_string(), value(v))).collect())
            }
            Value::Datetime(_) => unreachable!("no dates in scenes"),
        }
    }
    match item {
        Item::Value(v) => value(v),
        Item::Table(t) => J::Object(t.iter().map(|(k, v)| (k.to_string(), to_json(v))).collect()),
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn json_scenes_read_as_their_toml() {
    for (name, text) in SHIPPED {
        let doc: DocumentMut = text.parse().unwrap();
        let json = to_json(doc.as_item()).to_string();
        assert_eq!(
            Scene::from_json(&json).unwrap(),
            Scene::from_toml(text).unwrap(),
            "{name}: {json}"
        );
    }
}

#[test]
fn json_errors_name_the_field() {
    let ok = r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1]}}"#;
    assert!(Scene::from_json(ok).is_ok());
    let cases = [
        (
            r#"{"a": {"radii": [1, 0.5, 1]}, "b": {"radii": [1, 1, 1]}}"#,
            "JsonFloat",
            Some("a.radii[1]"),
        ),
        (
            r#"{"a": {"radii": [1, null, 1]}, "b": {"radii": [1, 1, 1]}}"#,
            "JsonNull",
            Some("a.radii[1]"),
        ),
        (
            r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 0]}}"#,
            "NonPositive",
            Some("b.radii[2]"),
        ),
        (
            r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1], "motion": {"kind": "wobble"}}}"#,
            "UnknownKind",
            Some("b.motion.kind"),
        ),
        (
            r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1]}"#,
            "NotJson",
            None,
        ),
        (r#"[1, 2]"#, "WrongType", Some("<file>")),
        (r#"{"a": {"radii": [1, 1, 1]}}"#, "Missing", Some("b")),
        (
            r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1]}, "body": []}"#,
            "Unknown",
            Some("body"),
        ),
    ];
    for (text, want, field) in cases {
        let e = Scene::from_json(text).unwrap_err();
        assert_eq!((variant(&e), e.field()), (want, field), "{text}: {e}");
    }
    // A `null` member is absent; integers beyond i64 are exact.
    let s = Scene::from_json(r#"{"span": null, "a": {"radii": [18446744073709551615, 1, 1], "motion": null}, "b": {"radii": [1, 1, 1]}}"#).unwrap();
    assert_eq!(s.span, Scene::default_span());
    assert_eq!(s.a.radii[0], rat("18446744073709551615"));
    // Deep nesting is the JSON parser's recursion limit, not a stack overflow.
    let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
    assert!(matches!(
        Scene::from_json(&deep),
        Err(SceneError::NotJson { .. })
    ));
}
