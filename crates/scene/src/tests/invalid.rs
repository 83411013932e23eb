//! The invalid-scene suite: each snippet with its expected error variant and
//! field path.

use crate::{Limit, Scene, SceneError, TomlType, MAX_INPUT_BYTES};

/// The variant's name, to compare variants without their payloads.
pub(crate) fn variant(e: &SceneError) -> &'static str {
    match e {
        SceneError::NotToml { .. } => "NotToml",
        SceneError::Missing { .. } => "Missing",
        SceneError::Unknown { .. } => "Unknown",
        SceneError::WrongType { .. } => "WrongType",
        SceneError::Number { .. } => "Number",
        SceneError::Length { .. } => "Length",
        SceneError::Empty { .. } => "Empty",
        SceneError::NonPositive { .. } => "NonPositive",
        SceneError::Span { .. } => "Span",
        SceneError::UnknownKind { .. } => "UnknownKind",
        SceneError::ZeroQuaternion { .. } => "ZeroQuaternion",
        SceneError::ZeroAxis { .. } => "ZeroAxis",
        SceneError::TooLarge { .. } => "TooLarge",
        SceneError::UnsupportedFormat { .. } => "UnsupportedFormat",
        SceneError::NotJson { .. } => "NotJson",
        SceneError::JsonFloat { .. } => "JsonFloat",
        SceneError::JsonNull { .. } => "JsonNull",
        SceneError::Name { .. } => "Name",
    }
}

const B: &str = "[b]\nradii = [1, 1, 1]\n";

/// `[a]` with unit radii and the given `[a.motion]` body, then a plain `[b]`.
fn a_motion(body: &str) -> String {
    format!("[a]\nradii = [1, 1, 1]\n[a.motion]\n{body}\n{B}")
}

/// `[a]` with the given body, then a plain `[b]`.
fn a_body(body: &str) -> String {
    format!("[a]\n{body}\n{B}")
}

/// Parses `text`, which must fail with `want` on `field`; returns the error.
fn reject(text: &str, want: &str, field: Option<&str>) -> SceneError {
    let e = match Scene::from_toml(text) {
        Ok(s) => panic!("expected {want} at {field:?}, parsed {s:?} from\n{text}"),
        Err(e) => e,
    };
    assert_eq!(
        (variant(&e), e.field()),
        (want, field),
        "error `{e}` for\n{text}"
    );
    let shown = e.to_string();
    match field {
        Some(f) => assert!(shown.starts_with(&format!("field `{f}`: ")), "{shown}"),
        None => assert!(shown.starts_with("not TOML"), "{shown}"),
    }
    e
}

#[test]
fn invalid_scene_suite() {
    let many = vec!["[0, 0, 0]"; crate::MAX_CONTROL_POINTS + 1].join(", ");
    let cases: Vec<(String, &str, Option<&str>)> = vec![
        // Not TOML at all, or broken TOML.
        ("this is not toml [".into(), "NotToml", None),
        ("[a]\nradii = [1, 1, 1]\nradii = [2, 2, 2]\n".into(), "NotToml", None),
        (a_body("radii = [99999999999999999999, 1, 1]"), "NotToml", None),
        // Missing required parts.
        (B.into(), "Missing", Some("a")),
        ("[a]\nradii = [1, 1, 1]\n".into(), "Missing", Some("b")),
        (format!("[a]\n{B}"), "Missing", Some("a.radii")),
        (a_motion("center = [0, 0, 0]"), "Missing", Some("a.motion.kind")),
        (a_motion("kind = \"translation\""), "Missing", Some("a.motion.center")),
        (a_motion("kind = \"rigid\"\ncenter = [[0, 0, 0]]"), "Missing", Some("a.motion.orientation")),
        (a_motion("kind = \"rigid\"\norientation = [[1, 0, 0, 0]]"), "Missing", Some("a.motion.center")),
        (a_motion("kind = \"affine\""), "Missing", Some("a.motion.matrix")),
        (a_motion("kind = \"helical\"\nrate = 1"), "Missing", Some("a.motion.axis")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]"), "Missing", Some("a.motion.rate")),
        // Radii.
        (a_body("radii = [1, 0, 1]"), "NonPositive", Some("a.radii[1]")),
        ("[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, -2]\n".into(), "NonPositive", Some("b.radii[2]")),
        (a_body("radii = [\"-1/3\", 1, 1]"), "NonPositive", Some("a.radii[0]")),
        (a_body("radii = [1, 1]"), "Length", Some("a.radii")),
        (a_body("radii = [1, 1, 1, 1]"), "Length", Some("a.radii")),
        (a_body("radii = [true, 1, 1]"), "WrongType", Some("a.radii[0]")),
        (a_body("radii = [1979-05-27, 1, 1]"), "WrongType", Some("a.radii[0]")),
        (a_body("radii = 1"), "WrongType", Some("a.radii")),
        (a_body("[a.radii]\nx = 1"), "WrongType", Some("a.radii")),
        // Span and format.
        (format!("span = [1, 1]\n[a]\nradii = [1, 1, 1]\n{B}"), "Span", Some("span")),
        (format!("span = [2, \"1/2\"]\n[a]\nradii = [1, 1, 1]\n{B}"), "Span", Some("span")),
        (format!("span = [0, 1, 2]\n[a]\nradii = [1, 1, 1]\n{B}"), "Length", Some("span")),
        (format!("span = [0]\n[a]\nradii = [1, 1, 1]\n{B}"), "Length", Some("span")),
        (format!("span = [0, +inf]\n[a]\nradii = [1, 1, 1]\n{B}"), "Number", Some("span[1]")),
        (format!("format = 2\n[a]\nradii = [1, 1, 1]\n{B}"), "UnsupportedFormat", Some("format")),
        (format!("format = \"one\"\n[a]\nradii = [1, 1, 1]\n{B}"), "Number", Some("format")),
        // Unknown keys and kinds.
        (format!("speed = 1\n[a]\nradii = [1, 1, 1]\n{B}"), "Unknown", Some("speed")),
        (format!("\"x.y\" = 1\n[a]\nradii = [1, 1, 1]\n{B}"), "Unknown", Some("\"x.y\"")),
        (a_body("radii = [1, 1, 1]\ncolor = \"red\""), "Unknown", Some("a.color")),
        (a_motion("kind = \"translation\"\ncenter = [[0, 0, 0]]\nspeed = 2"), "Unknown", Some("a.motion.speed")),
        (a_motion("kind = \"static\"\nweights = [1]"), "Unknown", Some("a.motion.weights")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\nweights = [1]"), "Unknown", Some("a.motion.weights")),
        (
            a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\ncenter = { base = [0, 0, 0], phase = 1 }"),
            "Unknown",
            Some("a.motion.center.phase"),
        ),
        (a_motion("kind = \"spin\""), "UnknownKind", Some("a.motion.kind")),
        (a_motion("kind = \"Static\""), "UnknownKind", Some("a.motion.kind")),
        (a_motion("kind = 3"), "WrongType", Some("a.motion.kind")),
        (a_body("radii = [1, 1, 1]\nmotion = \"static\""), "WrongType", Some("a.motion")),
        (format!("a = 5\n{B}"), "WrongType", Some("a")),
        (format!("[[a]]\nradii = [1, 1, 1]\n{B}"), "WrongType", Some("a")),
        // Weights.
        (a_motion("kind = \"translation\"\ncenter = [[0, 0, 0], [1, 0, 0]]\nweights = [0, 1]"), "NonPositive", Some("a.motion.weights[0]")),
        (a_motion("kind = \"translation\"\ncenter = [[0, 0, 0], [1, 0, 0]]\nweights = [1, -0.5]"), "NonPositive", Some("a.motion.weights[1]")),
        (a_motion("kind = \"translation\"\ncenter = [[0, 0, 0], [1, 0, 0]]\nweights = [1, 1, 1]"), "Length", Some("a.motion.weights")),
        (a_motion("kind = \"rigid\"\norientation = [[1, 0, 0, 0]]\ncenter = [[0, 0, 0]]\nweights = []"), "Length", Some("a.motion.weights")),
        (a_motion("kind = \"affine\"\nmatrix = [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]]\nweights = [\"0/5\"]"), "NonPositive", Some("a.motion.weights[0]")),
        // Control points.
        (
            "[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"translation\"\ncenter = [[0, 0, 0], [1, 2]]\n".into(),
            "Length",
            Some("b.motion.center[1]"),
        ),
        (
            "[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"translation\"\ncenter = [[0, 0, 0], [1, 2, \"abc\"]]\n".into(),
            "Number",
            Some("b.motion.center[1][2]"),
        ),
        (a_motion("kind = \"translation\"\ncenter = [1, 2, 3]"), "WrongType", Some("a.motion.center[0]")),
        (a_motion("kind = \"translation\"\ncenter = []"), "Empty", Some("a.motion.center")),
        (a_motion("kind = \"rigid\"\norientation = []\ncenter = [[0, 0, 0]]"), "Empty", Some("a.motion.orientation")),
        (a_motion(&format!("kind = \"translation\"\ncenter = [{many}]")), "TooLarge", Some("a.motion.center")),
        (a_motion("kind = \"rigid\"\norientation = [[1, 0, 0]]\ncenter = [[0, 0, 0]]"), "Length", Some("a.motion.orientation[0]")),
        (a_motion("kind = \"affine\"\nmatrix = [[[1, 0, 0, 0], [0, 1, 0], [0, 0, 1, 0]]]"), "Length", Some("a.motion.matrix[0][1]")),
        (a_motion("kind = \"affine\"\nmatrix = [[[1, 0, 0, 0], [0, 1, 0, 0]]]"), "Length", Some("a.motion.matrix[0]")),
        (a_motion("kind = \"affine\"\nmatrix = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]]"), "Length", Some("a.motion.matrix[0]")),
        // Quaternions and axes.
        (a_motion("kind = \"static\"\norientation = [0, 0, 0, 0]"), "ZeroQuaternion", Some("a.motion.orientation")),
        (a_motion("kind = \"translation\"\ncenter = [[0, 0, 0]]\norientation = [0, 0.0, \"0/3\", 0]"), "ZeroQuaternion", Some("a.motion.orientation")),
        (a_motion("kind = \"helical\"\norientation = [0, 0, 0, 0]\naxis = [1, 0, 0]\nrate = 1"), "ZeroQuaternion", Some("a.motion.orientation")),
        (a_motion("kind = \"helical\"\naxis = [0, 0, 0]\nrate = 1"), "ZeroAxis", Some("a.motion.axis")),
        (a_motion("kind = \"helical\"\naxis = [0, 0]\nrate = 1"), "Length", Some("a.motion.axis")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = [1]"), "WrongType", Some("a.motion.rate")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\ncenter = [0, 0, 0]"), "WrongType", Some("a.motion.center")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\ncenter = { sin = [0, 1] }"), "Length", Some("a.motion.center.sin")),
        (a_motion("kind = \"helical\"\naxis = [1, 0, 0]\nrate = 1\ncenter = { frequency = nan }"), "Number", Some("a.motion.center.frequency")),
        // Numbers that are not finite exact rationals.
        (a_body("radii = [inf, 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [1, -inf, 1]"), "Number", Some("a.radii[1]")),
        (a_body("radii = [1, 1, nan]"), "Number", Some("a.radii[2]")),
        (a_body("radii = [1, 1, -nan]"), "Number", Some("a.radii[2]")),
        (a_body("radii = [\"1/0\", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [\"\", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [\"abc\", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [\"inf\", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [\"1_000\", 1, 1]"), "Number", Some("a.radii[0]")),
        // Hostile sizes.
        (a_body("radii = [\"1e999999\", 1, 1]"), "TooLarge", Some("a.radii[0]")),
        // A TOML float must fit a binary64 (TOML's rule, enforced by the TOML
        // parser); beyond it, write the number as a string.
        (a_body("radii = [1e9999, 1, 1]"), "NotToml", None),
        (a_body("radii = [\"1e9999\", 1, 1]"), "TooLarge", Some("a.radii[0]")),
        (a_body(&format!("radii = [\"{}\", 1, 1]", "1".repeat(5000))), "TooLarge", Some("a.radii[0]")),
        // Over-long text whose 32nd byte is inside a multi-byte character.
        (a_body(&format!("radii = [\"1{}\", 1, 1]", "é".repeat(3000))), "TooLarge", Some("a.radii[0]")),
        (a_body(&format!("radii = [\"{}\", 1, 1]", "é".repeat(100))), "Number", Some("a.radii[0]")),
        // The exponent limit is the written exponent, |e| <= 4096.
        (a_body("radii = [\"1e4097\", 1, 1]"), "TooLarge", Some("a.radii[0]")),
        (a_body("radii = [1, \"1e8192\", 1]"), "TooLarge", Some("a.radii[1]")),
        (a_body("radii = [1, 1, \"2.5e-8192\"]"), "TooLarge", Some("a.radii[2]")),
        (a_body("radii = [1, 1, 1e-8192]"), "TooLarge", Some("a.radii[2]")),
        // No whitespace in a number string; a sign leads, nowhere else.
        (a_body("radii = [\" 2 \", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [\"2 \", 1, 1]"), "Number", Some("a.radii[0]")),
        (a_body("radii = [1, \"1 / 2\", 1]"), "Number", Some("a.radii[1]")),
        (a_body("radii = [1, \"1/+2\", 1]"), "Number", Some("a.radii[1]")),
        (a_body("radii = [1, \"+-2\", 1]"), "Number", Some("a.radii[1]")),
        (a_body("radii = [1, \"\\t2\", 1]"), "Number", Some("a.radii[1]")),
    ];
    assert!(cases.len() >= 25);
    for (text, want, field) in &cases {
        reject(text, want, *field);
    }
}

#[test]
fn oversized_input_is_refused_unread() {
    let mut text = a_body("radii = [1, 1, 1]");
    text.push_str(&"#".repeat(MAX_INPUT_BYTES));
    let e = reject(&text, "TooLarge", Some("<file>"));
    assert_eq!(
        e,
        SceneError::TooLarge {
            field: "<file>".into(),
            limit: Limit::InputBytes
        }
    );
}

#[test]
fn error_payloads_and_messages() {
    let e = reject(
        "[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"translation\"\ncenter = [[0, 0, 0], [1, 2, \"abc\"]]\n",
        "Number",
        Some("b.motion.center[1][2]"),
    );
    assert_eq!(
        e.to_string(),
        "field `b.motion.center[1][2]`: `abc` is not a number (expected an integer, a decimal such as 0.125 or 1e-20, or a fraction p/q)"
    );
    let e = reject(
        &a_body("radii = [false, 1, 1]"),
        "WrongType",
        Some("a.radii[0]"),
    );
    assert_eq!(
        e,
        SceneError::WrongType {
            field: "a.radii[0]".into(),
            expected: TomlType::Number,
            found: TomlType::Boolean
        }
    );
    assert_eq!(
        e.to_string(),
        "field `a.radii[0]`: expected a number, found a boolean"
    );
    let e = reject(&a_body("radii = [1, 1]"), "Length", Some("a.radii"));
    assert_eq!(
        e.to_string(),
        "field `a.radii`: expected 3 entries, found 2"
    );
    let e = reject(
        &a_body("radii = [1, \"-0.5\", 1]"),
        "NonPositive",
        Some("a.radii[1]"),
    );
    assert_eq!(e.to_string(), "field `a.radii[1]`: must be > 0, found -1/2");
    let e = reject(
        &format!("span = [\"3/2\", 1.5]\n[a]\nradii = [1, 1, 1]\n{B}"),
        "Span",
        Some("span"),
    );
    assert_eq!(
        e.to_string(),
        "field `span`: t0 = 3/2 must be less than t1 = 3/2"
    );
    let e = reject(
        &format!("format = 2.5\n[a]\nradii = [1, 1, 1]\n{B}"),
        "UnsupportedFormat",
        Some("format"),
    );
    assert_eq!(
        e.to_string(),
        "field `format`: unsupported format 5/2 (only format 1 exists)"
    );
    let e = reject(
        &a_motion("kind = \"spin\""),
        "UnknownKind",
        Some("a.motion.kind"),
    );
    assert_eq!(
        e.to_string(),
        "field `a.motion.kind`: unknown motion kind `spin` (expected static, translation, rigid, affine or helical)"
    );
    let e = reject(
        &a_motion("center = [0, 0, 0]"),
        "Missing",
        Some("a.motion.kind"),
    );
    assert_eq!(e.to_string(), "field `a.motion.kind`: required but missing");
    let e = reject(&a_body("radii = [inf, 1, 1]"), "Number", Some("a.radii[0]"));
    assert_eq!(
        e.to_string(),
        "field `a.radii[0]`: `inf` is not a finite number"
    );
    let e = reject(
        &a_body("radii = [\"1/0\", 1, 1]"),
        "Number",
        Some("a.radii[0]"),
    );
    assert_eq!(
        e.to_string(),
        "field `a.radii[0]`: zero denominator in `1/0`"
    );
    let e = reject("[a]\nradii = [1, 1, 1]\n[b\n", "NotToml", None);
    let SceneError::NotToml { line, .. } = e else {
        unreachable!()
    };
    assert_eq!(line, 3);
    let e = reject(
        &a_motion("kind = \"x\"\n").replace('x', &"k".repeat(1000)),
        "UnknownKind",
        Some("a.motion.kind"),
    );
    let SceneError::UnknownKind { kind, .. } = e else {
        unreachable!()
    };
    assert_eq!(kind, format!("{}…", "k".repeat(64)));
}

/// The first error wins, in document order within a table.
#[test]
fn errors_come_in_a_stable_order() {
    // Structure before values: the unknown key in b is reported although a
    // radius of a is zero.
    reject(
        "[a]\nradii = [0, 1, 1]\n[b]\nradii = [1, 1, 1]\nextra = 1\n",
        "Unknown",
        Some("b.extra"),
    );
    // The format is checked before anything else.
    reject(
        "format = 2\nwhatever = 1\n",
        "UnsupportedFormat",
        Some("format"),
    );
    // An unknown kind is reported before the keys that kind would not allow.
    reject(
        &a_motion("kind = \"spin\"\nweights = [1]"),
        "UnknownKind",
        Some("a.motion.kind"),
    );
}

#[test]
fn deep_nesting_is_refused_not_overflowed() {
    let n = 10_000;
    let arrays = format!("[a]\nradii = {}{}\n{B}", "[".repeat(n), "]".repeat(n));
    reject(&arrays, "NotToml", None);
    let tables = format!("a = {}1{}\n{B}", "{ b = ".repeat(n), " }".repeat(n));
    reject(&tables, "NotToml", None);
    let dotted = format!("{} = 1\n{B}", vec!["a"; n].join("."));
    reject(&dotted, "NotToml", None);
    // Shallow but wrongly nested: a type error, not a crash.
    reject(
        &a_body("radii = [[[1]], 1, 1]"),
        "WrongType",
        Some("a.radii[0]"),
    );
}

/// An unknown key from the file is cut in the message, as an unknown kind is.
#[test]
fn a_huge_unknown_key_is_cut() {
    for (key, written) in [
        ("k".repeat(500_000), "k".repeat(500_000)),
        ("é".repeat(100_000), format!("\"{}\"", "é".repeat(100_000))),
    ] {
        let e = reject(
            &format!("[a]\nradii = [1, 1, 1]\n{written} = 1\n{B}"),
            "Unknown",
            Some(&format!(
                "a.\"{}…\"",
                &key.chars().take(64).collect::<String>()
            )),
        );
        assert!(e.to_string().len() < 400, "{e}");
    }
    // Short keys are shown whole (quoted only when not bare).
    reject(
        &a_body("radii = [1, 1, 1]\nwobble = 1"),
        "Unknown",
        Some("a.wobble"),
    );
    reject(
        &a_body("radii = [1, 1, 1]\n\"two words\" = 1"),
        "Unknown",
        Some("a.\"two words\""),
    );
}

/// A rejected number is quoted cut, however long its text.
#[test]
fn a_long_bad_number_is_quoted_cut() {
    let e = reject(
        &a_body(&format!("radii = [\"{}x\", 1, 1]", "1".repeat(4000))),
        "Number",
        Some("a.radii[0]"),
    );
    assert!(e.to_string().len() < 300, "{e}");
}

/// Values from the file in messages are cut too: a radius, a span end or a
/// format can have thousands of digits.
#[test]
fn huge_values_in_messages_are_cut() {
    let huge = "\"-1e4000\"";
    for (text, field) in [
        (a_body(&format!("radii = [1, {huge}, 1]")), "a.radii[1]"),
        (
            format!("span = [\"1e4000\", 1]\n[a]\nradii = [1, 1, 1]\n{B}"),
            "span",
        ),
        (
            format!("format = \"1e4000\"\n[a]\nradii = [1, 1, 1]\n{B}"),
            "format",
        ),
    ] {
        let e = Scene::from_toml(&text).unwrap_err();
        assert_eq!(e.field(), Some(field));
        let shown = e.to_string();
        assert!(shown.len() < 300 && shown.contains('…'), "{shown}");
    }
}
