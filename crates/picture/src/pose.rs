//! Where a body is at a time `t`, in `f64` — for drawing only: the engine's
//! answers never pass through here.
//!
//! A placed ellipsoid is `{ c + M·y : |y| <= 1 }`: `c` its centre and `M`
//! the placement's linear part times `diag(radii)`.

use ccd_arith::Rat;
use ccd_scene::{Bezier, Body, Motion, Scene};

/// A 3-vector of floats.
pub type V3 = [f64; 3];
/// A 3×3 matrix of floats, rows first.
pub type M3 = [[f64; 3]; 3];

/// An ellipsoid placed in the world: `{ center + axes·y : |y| <= 1 }`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    /// The centre.
    pub center: V3,
    /// The placement's linear part times `diag(radii)`; its columns are the
    /// semi-axes in the world.
    pub axes: M3,
}

fn f(x: &Rat) -> f64 {
    x.to_f64()
}

fn v3(v: &[Rat; 3]) -> V3 {
    v.each_ref().map(f)
}

/// `R(q) = M(q)/|q|²` of the scene format, for a float quaternion `[w, x, y, z]`.
fn rotation(q: [f64; 4]) -> M3 {
    let [w, x, y, z] = q;
    let n = w * w + x * x + y * y + z * z;
    [
        [
            (w * w + x * x - y * y - z * z) / n,
            2.0 * (x * y - w * z) / n,
            2.0 * (x * z + w * y) / n,
        ],
        [
            2.0 * (x * y + w * z) / n,
            (w * w - x * x + y * y - z * z) / n,
            2.0 * (y * z - w * x) / n,
        ],
        [
            2.0 * (x * z - w * y) / n,
            2.0 * (y * z + w * x) / n,
            (w * w - x * x - y * y + z * z) / n,
        ],
    ]
}

fn mul(a: &M3, b: &M3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
}

/// `m · diag(r)`.
fn scale_columns(m: &M3, r: &V3) -> M3 {
    std::array::from_fn(|i| std::array::from_fn(|j| m[i][j] * r[j]))
}

/// The Bézier curve at `u` (de Casteljau on the weighted points), each
/// control point flattened to `N` floats.
fn bezier<P, const N: usize>(c: &Bezier<P>, u: f64, flat: impl Fn(&P) -> [f64; N]) -> [f64; N] {
    let weight = |i: usize| c.weights.as_ref().map_or(1.0, |w| f(&w[i]));
    // Homogeneous points (w·P, w), combined in one de Casteljau pass.
    let mut pts: Vec<(Vec<f64>, f64)> = c
        .points
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let w = weight(i);
            (flat(p).iter().map(|x| x * w).collect(), w)
        })
        .collect();
    while pts.len() > 1 {
        pts = pts
            .windows(2)
            .map(|ab| {
                let (p, wp) = &ab[0];
                let (q, wq) = &ab[1];
                let mixed = p
                    .iter()
                    .zip(q)
                    .map(|(x, y)| (1.0 - u) * x + u * y)
                    .collect();
                (mixed, (1.0 - u) * wp + u * wq)
            })
            .collect();
    }
    let (p, w) = &pts[0];
    std::array::from_fn(|k| p[k] / w)
}

/// `Rot(axis, angle)` (right-hand rule) as a quaternion.
fn axis_angle(axis: V3, angle: f64) -> [f64; 4] {
    let n = (axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]).sqrt();
    let (s, c) = (angle / 2.0).sin_cos();
    [c, s * axis[0] / n, s * axis[1] / n, s * axis[2] / n]
}

/// Where `body` is at time `t` of `span`.
pub fn pose(body: &Body, span: &[Rat; 2], t: f64) -> Pose {
    let (t0, t1) = (f(&span[0]), f(&span[1]));
    let u = (t - t0) / (t1 - t0);
    let radii = v3(&body.radii);
    let quat = |q: &[Rat; 4]| q.each_ref().map(f);
    let (linear, center) = match &body.motion {
        Motion::Static {
            center,
            orientation,
        } => (rotation(quat(orientation)), v3(center)),
        Motion::Translation {
            center,
            orientation,
        } => (rotation(quat(orientation)), bezier(center, u, v3)),
        Motion::Rigid {
            orientation,
            center,
        } => (
            rotation(bezier(orientation, u, quat)),
            bezier(center, u, v3),
        ),
        Motion::Affine { matrix } => {
            let m: [f64; 12] = bezier(matrix, u, |m| std::array::from_fn(|k| f(&m[k / 4][k % 4])));
            let l = std::array::from_fn(|i| std::array::from_fn(|j| m[4 * i + j]));
            (l, [m[3], m[7], m[11]])
        }
        Motion::Helical {
            orientation,
            axis,
            rate,
            center: hc,
        } => {
            let spin = rotation(axis_angle(v3(axis), f(rate) * t));
            let (s, c) = (f(&hc.frequency) * t).sin_cos();
            let center = std::array::from_fn(|k| {
                f(&hc.base[k]) + f(&hc.velocity[k]) * t + f(&hc.cos[k]) * c + f(&hc.sin[k]) * s
            });
            (mul(&spin, &rotation(quat(orientation))), center)
        }
    };
    Pose {
        center,
        axes: scale_columns(&linear, &radii),
    }
}

/// Both bodies of `scene` at time `t`.
pub fn poses(scene: &Scene, t: f64) -> [Pose; 2] {
    [
        pose(&scene.a, &scene.span, t),
        pose(&scene.b, &scene.span, t),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(text: &str) -> Scene {
        Scene::from_toml(text).unwrap()
    }

    #[test]
    fn translation_is_the_line_between_its_control_points() {
        let s = scene(
            "span = [2, 4]\n[a]\nradii = [2, 1, 1]\n[a.motion]\nkind = \"translation\"\ncenter = [[11, 0, 0], [-1, 0, 0]]\n[b]\nradii = [1, 1, 1]",
        );
        let [a, b] = poses(&s, 3.0);
        assert_eq!(a.center, [5.0, 0.0, 0.0]);
        assert_eq!(a.axes, [[2.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
        assert_eq!(b.center, [0.0; 3]);
    }

    #[test]
    fn rigid_turns_by_its_quaternion_curve() {
        // q(u) = (1-u)·[1,0,0,0] + u·[1,0,0,1]: at u = 1 a quarter turn about z.
        let s = scene(
            "[a]\nradii = [3, 1, 1]\n[a.motion]\nkind = \"rigid\"\norientation = [[1, 0, 0, 0], [1, 0, 0, 1]]\ncenter = [[0, 0, 0], [0, 0, 2]]\n[b]\nradii = [1, 1, 1]",
        );
        let a = pose(&s.a, &s.span, 1.0);
        // Body x (length 3) now points along world y.
        assert!((a.axes[1][0] - 3.0).abs() < 1e-12 && a.axes[0][0].abs() < 1e-12);
        assert_eq!(a.center, [0.0, 0.0, 2.0]);
    }

    #[test]
    fn weighted_curves_are_rational() {
        // Weights [1, 3]: at u = 1/2 the point is (1·0 + 3·4)/(1 + 3) = 3.
        let s = scene(
            "[a]\nradii = [1, 1, 1]\n[a.motion]\nkind = \"translation\"\ncenter = [[0, 0, 0], [4, 0, 0]]\nweights = [1, 3]\n[b]\nradii = [1, 1, 1]",
        );
        assert_eq!(pose(&s.a, &s.span, 0.5).center, [3.0, 0.0, 0.0]);
    }

    #[test]
    fn helical_spins_and_follows_its_centre() {
        let s = scene(
            "[a]\nradii = [2, 1, 1]\n[a.motion]\nkind = \"helical\"\naxis = [0, 0, 1]\nrate = 1\ncenter = { cos = [1, 0, 0], sin = [0, 1, 0], velocity = [0, 0, 10], frequency = 1 }\n[b]\nradii = [1, 1, 1]",
        );
        let t = std::f64::consts::FRAC_PI_2;
        let a = pose(&s.a, &s.span, t);
        let want = [0.0, 1.0, 10.0 * t];
        assert!((0..3).all(|k| (a.center[k] - want[k]).abs() < 1e-12));
        assert!((a.axes[1][0] - 2.0).abs() < 1e-12);
    }

    #[test]
    fn affine_is_the_rational_curve_of_its_matrices() {
        // One control matrix: its weight cancels, X = L·Xbody + d.
        let s = scene(
            "[a]\nradii = [1, 2, 1]\n[a.motion]\nkind = \"affine\"\nmatrix = [[[2, 0, 0, 4], [0, 1, 0, 0], [0, 0, 1, 2]]]\nweights = [2]\n[b]\nradii = [1, 1, 1]",
        );
        let a = pose(&s.a, &s.span, 0.3);
        assert_eq!(a.center, [4.0, 0.0, 2.0]);
        assert_eq!(a.axes[0][0], 2.0);
        assert_eq!(a.axes[1][1], 2.0);
    }
}
