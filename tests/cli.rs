//! The `ccd-exact` binary: output formats, exit statuses, error messages.

use serde_json::Value;
use std::process::{Command, Output};

fn cli(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ccd-exact"))
        .args(args)
        .output()
        .expect("the binary runs")
}

fn scene(name: &str) -> String {
    format!("{}/tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"))
}

fn temp_scene(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("ccd-exact-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_string_lossy().into_owned()
}

#[test]
fn json_follows_the_contract() {
    let out = cli(&[&scene("paper-example-5-1.toml"), "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["format"], 1);
    assert_eq!(v["span"], serde_json::json!(["0", "1"]));
    assert_eq!(v["collision_free"], false);
    let contacts = v["contacts"].as_array().unwrap();
    assert_eq!(contacts.len(), 2);
    for (c, paper) in contacts.iter().zip([0.5395042868, 0.8722604191]) {
        let approx: f64 = c["approx"].as_str().unwrap().parse().unwrap();
        assert!((approx - paper).abs() < 6e-11, "{c}");
        // lo/hi are exact rationals p/q in lowest terms.
        for k in ["lo", "hi"] {
            let s = c[k].as_str().unwrap();
            let r: ccd_arith::Rat = s.parse().unwrap();
            assert_eq!(r.to_string(), s);
        }
    }
    assert_eq!(v["first_contact"], contacts[0]);
    let states: Vec<&str> = v["timeline"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["state"].as_str().unwrap())
        .collect();
    assert_eq!(
        states,
        ["separate", "touch", "overlap", "touch", "separate"]
    );
    assert_eq!(v["timeline"][0]["start"]["lo"], "0");
}

#[test]
fn digits_controls_the_enclosure_width() {
    let out = cli(&[&scene("paper-example-5-1.toml"), "--json", "--digits", "40"]);
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    let c = &v["contacts"][0];
    let lo: ccd_arith::Rat = c["lo"].as_str().unwrap().parse().unwrap();
    let hi: ccd_arith::Rat = c["hi"].as_str().unwrap().parse().unwrap();
    assert!(
        &hi - &lo <= ccd_arith::Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(40)).unwrap()
    );
}

#[test]
fn the_table_is_readable() {
    let out = cli(&[&scene("paper-example-5-1.toml")]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(out.status.success());
    assert!(
        text.contains("overlap") && text.contains("0.539504286"),
        "{text}"
    );
}

#[test]
fn bad_input_exits_2_naming_the_field() {
    let cases = [
        (
            "radius.toml",
            "[a]\nradii = [1, 0, 1]\n[b]\nradii = [1, 1, 1]\n",
            "a.radii[1]",
        ),
        (
            "kind.toml",
            "[a]\nradii = [1, 1, 1]\nmotion = { kind = \"wobble\" }\n[b]\nradii = [1, 1, 1]\n",
            "a.motion.kind",
        ),
        ("toml.toml", "this is not = = toml", "TOML"),
        ("missing.toml", "[a]\nradii = [1, 1, 1]\n", "b"),
    ];
    for (name, text, needle) in cases {
        let out = cli(&[&temp_scene(name, text)]);
        assert_eq!(out.status.code(), Some(2), "{name}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.contains(needle), "{name}: {err}");
        assert!(!err.contains("panicked"), "{name}: {err}");
    }
    for args in [
        &["--digits", "x", "s.toml"][..],
        &["--frobnicate"],
        &[],
        &["/nonexistent/scene.toml"],
    ] {
        let out = cli(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
    }
}

#[test]
fn help_lists_examples() {
    let out = cli(&["--help"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("EXAMPLES"));
}

#[test]
fn a_closed_pipe_is_not_a_panic() {
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_ccd-exact"))
        .arg(scene("paper-example-5-1.toml"))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn float_mode_says_it_is_not_certified() {
    let out = cli(&[
        &scene("paper-example-5-1.toml"),
        "--json",
        "--arithmetic",
        "float",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["certified"], false);
    assert!(v["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .all(|c| c["certified"] == false));
    let table =
        String::from_utf8(cli(&[&scene("paper-example-5-1.toml"), "--arithmetic", "float"]).stdout)
            .unwrap();
    assert!(table.contains("NOT certified"), "{table}");
    let exact: Value =
        serde_json::from_slice(&cli(&[&scene("paper-example-5-1.toml"), "--json"]).stdout).unwrap();
    assert_eq!(exact["certified"], true);
    assert_eq!(
        cli(&[&scene("paper-example-5-1.toml"), "--arithmetic", "fast"])
            .status
            .code(),
        Some(2)
    );
}

/// Runs the binary on `text` written to a scratch file; returns the exit
/// code and stderr.
fn cli_on(name: &str, text: &str) -> (Option<i32>, String) {
    let out = cli(&[&temp_scene(name, text)]);
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn an_endless_file_is_refused_at_the_input_limit() {
    let limit = ccd_scene::MAX_INPUT_BYTES;
    // /dev/zero never ends: only the bounded read stops it.
    if std::path::Path::new("/dev/zero").exists() {
        let out = cli(&["/dev/zero"]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("field `<file>`") && err.contains(&limit.to_string()),
            "{err}"
        );
    }
    // One byte over the limit is refused, at the limit is read (and parsed).
    let scene = "[a]\nradii = [1, 1, 1]\n[b]\nradii = [1, 1, 1]\n#";
    let at = format!("{scene}{}", "#".repeat(limit - scene.len()));
    let (code, err) = cli_on("at-limit.toml", &at);
    assert_eq!(code, Some(0), "{err}");
    let (code, err) = cli_on("over-limit.toml", &format!("{at}#"));
    assert_eq!(code, Some(2));
    assert!(err.contains("field `<file>`: too large"), "{err}");
    assert!(err.contains(&format!("at most {limit} bytes")), "{err}");
}

#[test]
fn input_edges_exit_2_naming_the_field() {
    let b = "[b]\nradii = [1, 1, 1]\n";
    let key = "k".repeat(500_000);
    let cases = [
        (
            "exp.toml",
            format!("[a]\nradii = [1, \"1e8192\", 1]\n{b}"),
            "a.radii[1]",
        ),
        (
            "ws.toml",
            format!("[a]\nradii = [\" 2 \", 1, 1]\n{b}"),
            "a.radii[0]",
        ),
        (
            "slash.toml",
            format!("[a]\nradii = [1, 1, \"1 / 2\"]\n{b}"),
            "a.radii[2]",
        ),
        (
            "key.toml",
            format!("[a]\nradii = [1, 1, 1]\n{key} = 1\n{b}"),
            "a.\"kkkk",
        ),
        (
            "utf8.toml",
            format!("[a]\nradii = [1, 1, 1]\n{b}\u{0}\u{ff}"),
            "TOML",
        ),
    ];
    for (name, text, needle) in &cases {
        let (code, err) = cli_on(name, text);
        assert_eq!(code, Some(2), "{name}: {err}");
        assert!(err.contains(needle), "{name}: {err}");
        assert!(err.len() < 1000, "{name}: message of {} bytes", err.len());
    }
    // Not UTF-8 at all.
    let path = temp_scene("latin1.toml", "");
    std::fs::write(&path, b"[a]\nradii = [1, 1, 1]\n# \xff\n").unwrap();
    let out = cli(&[&path]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read"));
    // A leading `+` is a sign, and 1e4096 is within the limit.
    let (code, err) = cli_on(
        "plus.toml",
        &format!("[a]\nradii = [\"+2\", +1, \"1e4096\"]\n{b}"),
    );
    assert_eq!(code, Some(0), "{err}");
}

#[test]
fn helical_output_says_what_is_not_proven() {
    // Issue 18: a spin of 1e300 rad per unit of time. Overlap at t = 1/2 is
    // proven (B's centre inside A); the pieces where the spin makes about
    // 1e299 contacts are undecided gaps, so the timeline is not complete.
    let out = cli(&[&scene("issue-18-spin-1e300.toml"), "--json"]);
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["collision_free"], false);
    assert_eq!(v["collision_free_reason"], Value::Null);
    assert_eq!(v["complete"], false);
    assert_eq!(v["certified"], false);
    let gaps = v["gaps"].as_array().unwrap();
    assert!(!gaps.is_empty());
    assert!(gaps
        .iter()
        .all(|g| g["reason"].as_str().is_some_and(|r| !r.is_empty())));
    let timeline = v["timeline"].as_array().unwrap();
    assert!(timeline.iter().all(|s| s["certified"].is_boolean()));
    assert!(timeline
        .iter()
        .any(|s| s["state"] == "overlap" && s["certified"] == true));
    assert!(!v["stats"]["branch"].as_str().unwrap().contains("assumed"));
    let table = cli(&[&scene("issue-18-spin-1e300.toml")]);
    let text = String::from_utf8_lossy(&table.stdout);
    assert!(!text.contains("float"), "{text}");
    assert!(!text.contains("collision-free over the span"), "{text}");
    assert!(
        text.contains("undecided") && text.contains("NOT complete"),
        "{text}"
    );

    // Undecided both ways: collision_free is null, with a reason.
    let out = cli(&[&scene("issue-18-frequency-1e10.toml"), "--json"]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["collision_free"], Value::Null, "{v}");
    assert!(v["collision_free_reason"]
        .as_str()
        .is_some_and(|r| !r.is_empty()));
    assert_eq!(v["complete"], false);

    // A certified rational scene: every segment certified, no gap.
    let out = cli(&[&scene("paper-example-5-1.toml"), "--json"]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["gaps"], serde_json::json!([]));
    assert_eq!(v["collision_free_reason"], Value::Null);
    assert!(v["timeline"]
        .as_array()
        .unwrap()
        .iter()
        .all(|s| s["certified"] == true));
}

fn cli_stdin(args: &[&str], input: &[u8]) -> Output {
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_ccd-exact"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdin = child.stdin.take().unwrap();
    let input = input.to_vec();
    // Written from a thread: the child streams output while it reads.
    let writer = std::thread::spawn(move || {
        use std::io::Write;
        let _ = stdin.write_all(&input);
    });
    let out = child.wait_with_output().unwrap();
    writer.join().unwrap();
    out
}

#[test]
fn a_world_prints_its_contacts() {
    let out = cli(&[&scene("world-crossing.toml"), "--no-geometry"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        text.contains("left × right: first contact ≈ 0.5395042867"),
        "{text}"
    );
    assert!(
        text.contains("first contact in the world ≈ 0.0749830692"),
        "{text}"
    );
    assert!(
        text.contains("proven separate by certified boxes"),
        "{text}"
    );

    let out = cli(&[&scene("world-crossing.toml"), "--json", "--digits=20"]);
    assert!(out.status.success());
    let v: Value = serde_json::from_slice(&out.stdout).expect("valid JSON");
    assert_eq!(v["bodies"].as_array().unwrap().len(), 8);
    assert_eq!(
        v["colliding"],
        serde_json::json!([["left", "right"], ["rod", "tumbler"], ["coil", "post"]])
    );
    assert_eq!(
        v["first_contact"]["pair"],
        serde_json::json!(["coil", "post"])
    );
    let pairs = v["pairs"].as_array().unwrap();
    assert_eq!(
        pairs.len(),
        v["broad_phase"]["candidates"].as_u64().unwrap() as usize
    );
    assert_eq!(
        pairs.len() as u64 + v["broad_phase"]["pruned"].as_u64().unwrap(),
        28
    );
    assert_eq!(v["broad_phase"]["pruned_proven_separate"], true);
    let lr = pairs
        .iter()
        .find(|p| p["a"] == "left" && p["b"] == "right")
        .unwrap();
    assert_eq!(lr["contacts"].as_array().unwrap().len(), 2);
    // --digits=20 reached the pairs.
    let c = &lr["contacts"][0];
    let lo: ccd_arith::Rat = c["lo"].as_str().unwrap().parse().unwrap();
    let hi: ccd_arith::Rat = c["hi"].as_str().unwrap().parse().unwrap();
    assert!(
        &hi - &lo <= ccd_arith::Rat::new(ccd_arith::Int::one(), ccd_arith::Int::pow10(20)).unwrap()
    );

    // First-contact mode: the same earliest pair, no later contact isolated.
    let out = cli(&[&scene("world-crossing.toml"), "--json", "--first-contact"]);
    let f: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(f["first_contact"]["pair"], v["first_contact"]["pair"]);
    assert_eq!(f["complete"], false);
    assert!(f["pairs"]
        .as_array()
        .unwrap()
        .iter()
        .all(|p| p["contacts"].as_array().unwrap().len() <= 1));

    // The world from standard input.
    let text = std::fs::read(scene("world-crossing.toml")).unwrap();
    let out = cli_stdin(&["-", "--json", "--no-geometry"], &text);
    assert!(out.status.success());
    let s: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(s["colliding"], v["colliding"]);
}

#[test]
fn a_bad_world_exits_2_naming_the_body() {
    let text = "[[body]]\nname = \"ball\"\nradii = [1, 1, 1]\n[[body]]\nname = \"arm-2\"\nradii = [1, 1, 1]\nmotion = { kind = \"translation\", center = [[0, 0, 0], [1, 0]] }\n";
    let (code, err) = cli_on("bad-world.toml", text);
    assert_eq!(code, Some(2));
    assert!(err.contains("body[1] \"arm-2\".motion.center[1]"), "{err}");
}

#[test]
fn batch_streams_one_line_per_input_line() {
    let pairs = std::fs::read(scene("pairs.jsonl")).unwrap();
    let n = pairs.iter().filter(|&&b| b == b'\n').count();
    let out = cli_stdin(&["batch", "--no-geometry", "--threads", "2"], &pairs);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).expect("each line is JSON"))
        .collect();
    assert_eq!(lines.len(), n);
    for (i, l) in lines.iter().enumerate() {
        assert_eq!(l["line"], i as u64 + 1);
        assert!(
            l.get("error").is_some() != l.get("timeline").is_some(),
            "{l}"
        );
    }
    // The first line is Example 5.1; the error lines name their field.
    assert_eq!(lines[0]["contacts"].as_array().unwrap().len(), 2);
    let errors: Vec<&Value> = lines.iter().filter(|l| l.get("error").is_some()).collect();
    assert!(errors.iter().any(|l| l["field"] == "a.radii[1]"));
    assert!(errors.iter().all(|l| l["error"]
        .as_str()
        .unwrap()
        .starts_with(&format!("line {}: ", l["line"]))));
    assert!(String::from_utf8_lossy(&out.stderr).contains("error lines"));

    // The same from a file, on one thread, is the same output.
    let one = cli(&[
        "batch",
        &scene("pairs.jsonl"),
        "--no-geometry",
        "--threads=1",
    ]);
    let one: Vec<Value> = String::from_utf8(one.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(one, lines);
}

#[test]
fn a_batch_line_over_the_limit_is_an_error_line() {
    let good = r#"{"a": {"radii": [1, 1, 1]}, "b": {"radii": [1, 1, 1], "motion": {"kind": "static", "center": [5, 0, 0]}}}"#;
    let huge = format!("{{\"a\": \"{}\"}}", "x".repeat(ccd_scene::MAX_INPUT_BYTES));
    let input = format!("{good}\n{huge}\n\n{good}");
    let out = cli_stdin(&["batch"], input.as_bytes());
    assert!(out.status.success());
    let lines: Vec<Value> = String::from_utf8(out.stdout)
        .unwrap()
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 4);
    assert_eq!(lines[0]["collision_free"], true);
    assert!(
        lines[1]["error"].as_str().unwrap().contains("too large"),
        "{}",
        lines[1]
    );
    assert_eq!(lines[1]["field"], "<file>");
    assert!(lines[2]["error"]
        .as_str()
        .unwrap()
        .starts_with("line 3: not JSON"));
    assert_eq!(lines[3]["collision_free"], true);
}

#[test]
fn help_and_options_work_as_users_expect() {
    let out = cli(&["help", "batch"]);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("JSON Lines") && text.contains("EXAMPLES"),
        "{text}"
    );
    let out = cli(&["-V"]);
    assert!(String::from_utf8_lossy(&out.stdout).contains("integers"));
    let out = cli(&[&scene("paper-example-5-1.toml"), "--digits=1001"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--digits"));
    let out = cli(&["batch", "/nonexistent/pairs.jsonl"]);
    assert_eq!(out.status.code(), Some(2));
}
