//! Valid scenes: the shipped examples with their exact values, and exact
//! number reading.

use super::{parse_ok, rat, rats, SHIPPED};
use crate::{Bezier, HelicalCenter, Motion, Rat, Scene};

fn shipped(name: &str) -> Scene {
    let (_, text) = SHIPPED
        .iter()
        .find(|(n, _)| *n == name)
        .expect("shipped scene");
    parse_ok(text)
}

#[test]
fn paper_example_5_1() {
    let s = shipped("paper-example-5-1.toml");
    assert_eq!(s.span, rats(["0", "1"]));
    assert_eq!(s.a.radii, rats(["2", "1", "1"]));
    assert_eq!(s.b.radii, rats(["2", "1", "1"]));
    assert_eq!(
        s.a.motion,
        Motion::Translation {
            center: Bezier {
                points: vec![rats(["11", "0", "0"]), rats(["-1", "0", "0"])],
                weights: None
            },
            orientation: Motion::identity(),
        }
    );
    assert_eq!(
        s.b.motion,
        Motion::Translation {
            center: Bezier {
                points: vec![rats(["3", "-2", "-4"]), rats(["3", "2", "0"])],
                weights: None
            },
            orientation: Motion::identity(),
        }
    );
}

#[test]
fn paper_example_5_2_helical() {
    let s = shipped("paper-example-5-2.toml");
    assert_eq!(s.span, rats(["0", "1"]));
    assert_eq!(s.a.radii, rats(["1", "2", "1"]));
    assert_eq!(
        s.a.motion,
        Motion::Helical {
            orientation: Motion::identity(),
            axis: rats(["1", "0", "0"]),
            rate: rat("-10"),
            center: HelicalCenter {
                base: rats(["0", "0", "0"]),
                velocity: rats(["0", "0", "10"]),
                cos: rats(["1", "0", "0"]),
                sin: rats(["0", "1", "0"]),
                frequency: rat("10"),
            },
        }
    );
    assert_eq!(s.b.radii, rats(["1", "1", "3"]));
    assert_eq!(
        s.b.motion,
        Motion::Static {
            center: rats(["0", "0", "5"]),
            orientation: Motion::identity()
        }
    );
}

#[test]
fn rigid_tumbling() {
    let s = shipped("rigid-tumbling.toml");
    assert_eq!(s.span, [Rat::zero(), Rat::one()]);
    assert_eq!(
        s.a.radii,
        [Rat::from(3), Rat::from_frac(1, 2), Rat::from_frac(1, 2)]
    );
    assert_eq!(s.a.motion, Motion::at_origin());
    assert_eq!(
        s.b.radii,
        [Rat::from(2), Rat::from_frac(3, 2), Rat::from_frac(1, 4)]
    );
    assert_eq!(
        s.b.motion,
        Motion::Rigid {
            orientation: Bezier {
                points: vec![rats(["1", "0", "0", "0"]), rats(["1", "1", "0", "1"])],
                weights: None
            },
            center: Bezier {
                points: vec![
                    [Rat::from(-4), Rat::from_frac(6, 5), Rat::zero()],
                    [Rat::from(4), Rat::from_frac(9, 10), Rat::from_frac(1, 10)],
                ],
                weights: None,
            },
        }
    );
}

#[test]
fn static_touching_spheres_defaults() {
    let s = shipped("static-touching-spheres.toml");
    assert_eq!(s.span, Scene::default_span());
    assert_eq!(s.a.radii, rats(["1", "1", "1"]));
    // Omitted motion: static at the origin, unrotated.
    assert_eq!(
        s.a.motion,
        Motion::Static {
            center: rats(["0", "0", "0"]),
            orientation: rats(["1", "0", "0", "0"])
        }
    );
    assert_eq!(
        s.b.motion,
        Motion::Static {
            center: rats(["2", "0", "0"]),
            orientation: Motion::identity()
        }
    );
}

#[test]
fn shipped_scenes_validate_and_parse_via_from_str() {
    for (name, text) in SHIPPED {
        let s: Scene = text.parse().unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(s.validate(), Ok(()), "{name}");
    }
}

/// The first radius of `[a]` written as `x`.
fn radius(x: &str) -> Rat {
    parse_ok(&format!(
        "[a]\nradii = [{x}, 1, 1]\n[b]\nradii = [1, 1, 1]\n"
    ))
    .a
    .radii[0]
        .clone()
}

#[test]
fn numbers_are_exact() {
    let pow10 = |k: u32| Rat::from(ccd_arith::Int::pow10(k));
    let cases: [(&str, Rat); 19] = [
        ("0.1", Rat::from_frac(1, 10)),
        ("1e-20", Rat::one() / pow10(20)),
        ("1E-20", Rat::one() / pow10(20)),
        ("\"1e-20\"", Rat::one() / pow10(20)),
        ("\"1/3\"", Rat::from_frac(1, 3)),
        ("'22/7'", Rat::from_frac(22, 7)),
        ("1_000.5", Rat::from_frac(2001, 2)),
        ("1_000", Rat::from(1000)),
        ("+1.5", Rat::from_frac(3, 2)),
        ("2.5e-3", Rat::from_frac(1, 400)),
        ("6.02e+23", Rat::from(602) * pow10(21)),
        ("1E5", Rat::from(100_000)),
        ("\"0.125\"", Rat::from_frac(1, 8)),
        ("0x10", Rat::from(16)),
        ("0o17", Rat::from(15)),
        // Not representable in binary: distinct from 0.3 only if read exactly.
        (
            "0.30000000000000000001",
            Rat::from_frac(3, 10) + Rat::one() / pow10(20),
        ),
        ("9_007_199_254_740_993", Rat::from(9_007_199_254_740_993)),
        // Below the binary64 range, still exact.
        ("1e-400", Rat::one() / pow10(400)),
        ("\"1e400\"", pow10(400)),
    ];
    for (text, want) in cases {
        assert_eq!(radius(text), want, "{text}");
    }
}

#[test]
fn negative_and_nested_numbers_are_exact() {
    let s = parse_ok(
        "span = [\"-7/2\", -2.5e-3]\n\
         [a]\nradii = [1, 1, 1]\n\
         [a.motion]\nkind = \"affine\"\n\
         matrix = [[[1, 0, 0, -0.1], [0, 1, 0, \"1/3\"], [0, 0, 1, 1e-3]]]\n\
         weights = [0.5]\n\
         [b]\nradii = [1, 1, 1]\n",
    );
    assert_eq!(s.span, [Rat::from_frac(-7, 2), Rat::from_frac(-1, 400)]);
    let Motion::Affine { matrix } = &s.a.motion else {
        panic!("affine expected")
    };
    assert_eq!(matrix.weights, Some(vec![Rat::from_frac(1, 2)]));
    assert_eq!(matrix.points[0][0][3], Rat::from_frac(-1, 10));
    assert_eq!(matrix.points[0][1][3], Rat::from_frac(1, 3));
    assert_eq!(matrix.points[0][2][3], Rat::from_frac(1, 1000));
}

#[test]
fn every_kind_in_every_table_style() {
    // Inline tables, dotted keys and header tables all read alike.
    let s = parse_ok(
        "format = 1\n\
         a = { radii = [1, 2, 3], motion = { kind = \"translation\", center = [[0, 0, 0], [1, 1, 1], [2, 0, 0]], weights = [1, 2, \"1/2\"], orientation = [0, 0, 0, 1] } }\n\
         [b]\nradii = [1, 1, 1]\nmotion.kind = \"helical\"\nmotion.axis = [0, 0, 2]\nmotion.rate = 0.5\n\
         [b.motion.center]\nbase = [1, 2, 3]\nfrequency = \"1/4\"\n",
    );
    assert_eq!(s.a.radii, rats(["1", "2", "3"]));
    assert_eq!(
        s.a.motion,
        Motion::Translation {
            center: Bezier {
                points: vec![
                    rats(["0", "0", "0"]),
                    rats(["1", "1", "1"]),
                    rats(["2", "0", "0"])
                ],
                weights: Some(rats(["1", "2", "1/2"]).to_vec()),
            },
            orientation: rats(["0", "0", "0", "1"]),
        }
    );
    let zero = rats(["0", "0", "0"]);
    assert_eq!(
        s.b.motion,
        Motion::Helical {
            orientation: Motion::identity(),
            axis: rats(["0", "0", "2"]),
            rate: rat("1/2"),
            center: HelicalCenter {
                base: rats(["1", "2", "3"]),
                velocity: zero.clone(),
                cos: zero.clone(),
                sin: zero,
                frequency: rat("1/4"),
            },
        }
    );
}

#[test]
fn optional_fields_default() {
    let s = parse_ok(
        "[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"static\"\n\
         [b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"helical\"\naxis = [1, 0, 0]\nrate = 0\n",
    );
    assert_eq!(s.a.motion, Motion::at_origin());
    let zero = rats(["0", "0", "0"]);
    let Motion::Helical {
        orientation,
        center,
        ..
    } = &s.b.motion
    else {
        panic!("helical expected")
    };
    assert_eq!(orientation, &Motion::identity());
    assert_eq!(
        center,
        &HelicalCenter {
            base: zero.clone(),
            velocity: zero.clone(),
            cos: zero.clone(),
            sin: zero,
            frequency: Rat::zero()
        }
    );
}

#[test]
fn rigid_and_affine_curves_with_weights() {
    // A zero control quaternion alone does not make the curve vanish: the
    // curve check is the motion crate's.
    let s = parse_ok(
        "[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"rigid\"\n\
         orientation = [[1, 0, 0, 0], [0, 0, 0, 0], [0, 1, 0, 0]]\ncenter = [[0, 0, 0], [1, 0, 0]]\nweights = [1, 3]\n\
         [b]\nradii = [1, 1, 1]\n[b.motion]\nkind = \"affine\"\n\
         matrix = [[[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0]], [[2, 0, 0, 1], [0, 2, 0, 0], [0, 0, 2, 0]]]\n",
    );
    let Motion::Rigid {
        orientation,
        center,
    } = &s.a.motion
    else {
        panic!("rigid expected")
    };
    assert_eq!(orientation.points.len(), 3);
    assert_eq!(orientation.weights, None);
    assert_eq!(center.weights, Some(rats(["1", "3"]).to_vec()));
    let Motion::Affine { matrix } = &s.b.motion else {
        panic!("affine expected")
    };
    assert_eq!(matrix.degree(), 1);
    assert_eq!(matrix.points[1][0], rats(["2", "0", "0", "1"]));
    assert_eq!(matrix.weights, None);
}

#[test]
fn sixteen_control_points_are_accepted() {
    let points = vec!["[0, 0, 0]"; crate::MAX_CONTROL_POINTS].join(", ");
    let s = parse_ok(&format!(
        "[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"translation\"\ncenter = [{points}]\n[b]\nradii = [1, 1, 1]\n"
    ));
    let Motion::Translation { center, .. } = &s.a.motion else {
        panic!("translation expected")
    };
    assert_eq!(center.degree(), 15);
}

/// A leading `+` is a sign, in strings as in TOML's own number syntax, and
/// the exponent limit is inclusive.
#[test]
fn signs_and_the_largest_exponents_are_accepted() {
    let s = parse_ok(
        "[a]\nradii = [\"+2\", +3, +0.5]\n[b]\nradii = [\"+1/3\", \"1e4096\", \"1e-4096\"]\n",
    );
    assert_eq!(s.a.radii, rats(["2", "3", "1/2"]));
    assert_eq!(s.b.radii[0], rat("1/3"));
    assert_eq!(s.b.radii[1], Rat::from_int(ccd_arith::Int::pow10(4096)));
    assert_eq!(
        &s.b.radii[2] * &s.b.radii[1],
        Rat::one(),
        "1e-4096 is the inverse of 1e4096"
    );
}

/// A whole scene at the number limit parses: the input limit is above what
/// the other limits allow.
#[test]
fn a_scene_at_every_limit_fits_the_input_limit() {
    let n = format!("\"1.{}\"", "0".repeat(Rat::MAX_TEXT - 2));
    let row = [n.as_str(); 4].join(", ");
    let matrix = format!("[[{row}], [{row}], [{row}]]");
    let points = vec![matrix.as_str(); crate::MAX_CONTROL_POINTS].join(",\n");
    let weights = vec![n.as_str(); crate::MAX_CONTROL_POINTS].join(", ");
    let body = format!("radii = [{n}, {n}, {n}]\n[a.motion]\nkind = \"affine\"\nmatrix = [{points}]\nweights = [{weights}]\n");
    let text = format!("[a]\n{body}[b]\n{}", body.replace("[a.", "[b."));
    assert!(text.len() <= crate::MAX_INPUT_BYTES, "{}", text.len());
    let s = parse_ok(&text);
    assert_eq!(s.a.radii[0], Rat::one());
}
