//! The pictures of a query (`ccd-picture`, `--svg`, `--html`): what they
//! show is checked against the engine's answer and the bodies' equations.
//! (A real browser loads the HTML page in the Python package's tests.)

use ccd_exact::{run, Geometry, Options, Scene};
use ccd_picture::pose::{poses, Pose};
use std::process::Command;

fn scene(name: &str) -> String {
    let path = format!("{}/tests/scenes/{name}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(path).unwrap()
}

/// `(x − c)ᵀ (M Mᵀ)⁻¹ (x − c)`: 1 on the body's surface.
fn level(p: &Pose, x: [f64; 3]) -> f64 {
    // Solve M y = x − c by Cramer's rule; the level is |y|².
    let m = p.axes;
    let d: [f64; 3] = std::array::from_fn(|i| x[i] - p.center[i]);
    let det = |a: [[f64; 3]; 3]| {
        a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
            - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
            + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
    };
    let full = det(m);
    (0..3)
        .map(|j| {
            let mut a = m;
            (0..3).for_each(|i| a[i][j] = d[i]);
            (det(a) / full).powi(2)
        })
        .sum()
}

#[test]
fn each_contact_point_is_on_both_bodies_where_the_picture_puts_them() {
    for name in [
        "paper-example-5-1.toml",
        "paper-example-5-2.toml",
        "screw-step.toml",
    ] {
        let s = Scene::from_toml(&scene(name)).unwrap();
        let out = run(&s, &Options::default()).unwrap();
        assert!(!out.contacts.is_empty(), "{name}");
        for (c, g) in out.contacts.iter().zip(&out.geometry) {
            let Geometry::Point { point, .. } = g else {
                panic!("{name}: a contact without a point")
            };
            let x = point.midpoint().map(|v| v.to_f64());
            for (body, p) in poses(&s, c.midpoint().to_f64()).iter().enumerate() {
                let l = level(p, x);
                assert!((l - 1.0).abs() < 1e-6, "{name}: body {body} level {l}");
            }
        }
    }
}

#[test]
fn the_svg_shows_the_strip_and_one_panel_per_contact() {
    let s = Scene::from_toml(&scene("paper-example-5-1.toml")).unwrap();
    let out = run(&s, &Options::default()).unwrap();
    let svg = ccd_picture::svg(&s, &out, "Example 5.1 <&>");
    assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("Example 5.1 &lt;&amp;&gt;"));
    assert_eq!(svg.matches(r#"class="panel""#).count(), out.contacts.len());
    assert_eq!(
        svg.matches(r#"class="contact""#).count(),
        out.contacts.len()
    );
    assert_eq!(svg.matches(r#"class="point""#).count(), out.contacts.len());
    assert_eq!(svg.matches(r#"class="normal""#).count(), out.contacts.len());
    // Both bodies are cut by the plane through each contact point.
    assert_eq!(
        svg.matches(r#"class="section""#).count(),
        2 * out.contacts.len()
    );
    assert_eq!(svg.matches("first contact t ≈ 0.539504286780").count(), 2);
    let states =
        ["separate", "overlap"].map(|s| svg.matches(&format!(r#"class="seg {s}""#)).count());
    assert_eq!(states, [2, 1]);
    // The enclosures are written rounded outward: they hold the exact ones.
    let lo = out.contacts[0].lo.to_decimal(20);
    assert!(svg.contains(&lo[..14]), "{lo}");
}

#[test]
fn the_html_page_is_self_contained() {
    let s = Scene::from_toml(&scene("paper-example-5-2.toml")).unwrap();
    let out = run(&s, &Options::default()).unwrap();
    let page = ccd_picture::html(&s, &out, "Example 5.2");
    assert!(page.starts_with("<!doctype html>"));
    for outside in ["http://", "https://", "src=", "<link", "import "] {
        assert!(!page.contains(outside), "the page fetches with {outside}");
    }
    let data = page
        .split("const DATA = ")
        .nth(1)
        .and_then(|d| d.split(";</script>").next())
        .unwrap();
    let v: serde_json::Value = serde_json::from_str(data).unwrap();
    assert_eq!(v["contacts"].as_array().unwrap().len(), out.contacts.len());
    let n = v["samples"]["t"].as_array().unwrap().len();
    assert!(n > 400);
    for body in ["a", "b"] {
        assert_eq!(v["samples"][body].as_array().unwrap().len(), n);
    }
}

#[test]
fn the_cli_writes_both_pictures_and_names_a_missing_file_name() {
    let dir = std::env::temp_dir().join(format!("ccd-exact-picture-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (svg, html) = (dir.join("a.svg"), dir.join("a.html"));
    let scene = format!(
        "{}/tests/scenes/paper-example-5-1.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let bin = env!("CARGO_BIN_EXE_ccd-exact");
    let out = Command::new(bin)
        .args([&scene, "--json", "--svg"])
        .arg(&svg)
        .arg("--html")
        .arg(&html)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice::<serde_json::Value>(&out.stdout).expect("the JSON is unchanged");
    assert!(std::fs::read_to_string(&svg)
        .unwrap()
        .contains("class=\"panel\""));
    assert!(std::fs::read_to_string(&html)
        .unwrap()
        .contains("const DATA"));
    let out = Command::new(bin).args([&scene, "--svg"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
    let message = String::from_utf8_lossy(&out.stderr);
    assert!(
        message.contains("--svg <FILE>") && message.contains("value is required"),
        "{message}"
    );
    let bad = dir.join("no-such-dir").join("x.svg");
    let out = Command::new(bin)
        .args([&scene, "--svg"])
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write"));
    std::fs::remove_dir_all(&dir).ok();
}
