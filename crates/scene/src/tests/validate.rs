//! [`Scene::validate`] on scenes built in code: the same local errors, with
//! the same field paths, as the parser.

use super::{parse_ok, rats, SHIPPED};
use crate::{Bezier, Limit, Motion, Rat, Scene, SceneError, MAX_CONTROL_POINTS};

/// A valid scene: `a` translates along a weighted curve, `b` is static.
fn base() -> Scene {
    parse_ok(
        "[a]\nradii = [1, 2, 3]\n[a.motion]\nkind = \"translation\"\n\
         center = [[0, 0, 0], [1, 0, 0]]\nweights = [1, 2]\n[b]\nradii = [1, 1, 1]\n",
    )
}

/// `base()` changed by `edit`, which must make `validate` fail exactly as
/// `from_toml(text)` does.
fn same_error(edit: impl FnOnce(&mut Scene), text: &str) {
    let mut s = base();
    edit(&mut s);
    let by_code = s.validate().expect_err("edited scene must be invalid");
    let by_text = Scene::from_toml(text).expect_err("text must be invalid");
    assert_eq!(by_code, by_text, "{text}");
}

/// `a`'s motion mutably, for editing.
fn a_curve(s: &mut Scene) -> &mut Bezier<[Rat; 3]> {
    match &mut s.a.motion {
        Motion::Translation { center, .. } => center,
        _ => unreachable!("base() translates a"),
    }
}

const A: &str = "[a]\nradii = [1, 2, 3]\n[a.motion]\nkind = \"translation\"\n";
const B: &str = "[b]\nradii = [1, 1, 1]\n";

#[test]
fn validate_matches_the_parser() {
    same_error(
        |s| s.a.radii[1] = Rat::zero(),
        &format!("[a]\nradii = [1, 0, 3]\n{B}"),
    );
    same_error(
        |s| s.b.radii[2] = Rat::from(-2),
        "[a]\nradii = [1, 2, 3]\n[b]\nradii = [1, 1, -2]\n",
    );
    same_error(
        |s| s.span = rats(["1", "1/2"]),
        &format!("span = [1, 0.5]\n[a]\nradii = [1, 2, 3]\n{B}"),
    );
    same_error(
        |s| a_curve(s).weights = Some(rats(["1", "0"]).to_vec()),
        &format!("{A}center = [[0, 0, 0], [1, 0, 0]]\nweights = [1, 0]\n{B}"),
    );
    same_error(
        |s| a_curve(s).weights = Some(rats(["1", "1", "1"]).to_vec()),
        &format!("{A}center = [[0, 0, 0], [1, 0, 0]]\nweights = [1, 1, 1]\n{B}"),
    );
    same_error(
        |s| a_curve(s).points.clear(),
        &format!("{A}center = []\n{B}"),
    );
    let many = vec!["[0, 0, 0]"; MAX_CONTROL_POINTS + 1].join(", ");
    same_error(
        |s| {
            let c = a_curve(s);
            c.points = vec![rats(["0", "0", "0"]); MAX_CONTROL_POINTS + 1];
            c.weights = None;
        },
        &format!("{A}center = [{many}]\n{B}"),
    );
    same_error(
        |s| s.b.motion = Motion::Static { center: rats(["0", "0", "0"]), orientation: rats(["0", "0", "0", "0"]) },
        &format!("[a]\nradii = [1, 2, 3]\n{B}[b.motion]\nkind = \"static\"\norientation = [0, 0, 0, 0]\n"),
    );
    same_error(
        |s| {
            let Motion::Translation { orientation, .. } = &mut s.a.motion else {
                unreachable!()
            };
            *orientation = rats(["0", "0", "0", "0"]);
        },
        &format!("{A}center = [[0, 0, 0]]\norientation = [0, 0, 0, 0]\n{B}"),
    );
}

#[test]
fn validate_helical_and_rigid() {
    let (_, text) = SHIPPED[1];
    let mut s = parse_ok(text);
    let Motion::Helical { axis, .. } = &mut s.a.motion else {
        unreachable!("example 5.2 is helical")
    };
    *axis = rats(["0", "0", "0"]);
    assert_eq!(
        s.validate(),
        Err(SceneError::ZeroAxis {
            field: "a.motion.axis".into()
        })
    );
    let Motion::Helical { axis, .. } = &mut s.a.motion else {
        unreachable!()
    };
    *axis = rats(["0", "0", "-1"]);
    assert_eq!(s.validate(), Ok(()));
    let Motion::Helical { orientation, .. } = &mut s.a.motion else {
        unreachable!()
    };
    *orientation = rats(["0", "0", "0", "0"]);
    assert_eq!(
        s.validate(),
        Err(SceneError::ZeroQuaternion {
            field: "a.motion.orientation".into()
        })
    );

    let (_, text) = SHIPPED[2];
    let mut s = parse_ok(text);
    let Motion::Rigid {
        orientation,
        center,
    } = &mut s.b.motion
    else {
        unreachable!("rigid-tumbling's b is rigid")
    };
    // A zero control quaternion is a matter for the motion crate.
    orientation.points[0] = rats(["0", "0", "0", "0"]);
    center.weights = Some(rats(["2", "1/2"]).to_vec());
    assert_eq!(s.validate(), Ok(()));
    let Motion::Rigid { orientation, .. } = &mut s.b.motion else {
        unreachable!()
    };
    orientation.weights = Some(rats(["1", "1"]).to_vec());
    assert_eq!(
        s.validate(),
        Err(SceneError::Unknown {
            field: "b.motion.orientation.weights".into()
        })
    );
    let Motion::Rigid { orientation, .. } = &mut s.b.motion else {
        unreachable!()
    };
    orientation.weights = None;
    orientation.points = vec![rats(["1", "0", "0", "0"]); MAX_CONTROL_POINTS + 1];
    assert_eq!(
        s.validate(),
        Err(SceneError::TooLarge {
            field: "b.motion.orientation".into(),
            limit: Limit::ControlPoints
        })
    );
}

#[test]
fn validate_affine_weights() {
    let mut s = base();
    let identity = [
        rats(["1", "0", "0", "0"]),
        rats(["0", "1", "0", "0"]),
        rats(["0", "0", "1", "0"]),
    ];
    s.a.motion = Motion::Affine {
        matrix: Bezier {
            points: vec![identity.clone(), identity],
            weights: None,
        },
    };
    assert_eq!(s.validate(), Ok(()));
    let Motion::Affine { matrix } = &mut s.a.motion else {
        unreachable!()
    };
    matrix.weights = Some(rats(["1", "-1"]).to_vec());
    assert_eq!(
        s.validate(),
        Err(SceneError::NonPositive {
            field: "a.motion.weights[1]".into(),
            value: Rat::from(-1)
        })
    );
}
