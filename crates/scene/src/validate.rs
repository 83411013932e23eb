//! The local value checks shared by the parser and [`Scene::validate`]:
//! everything that can be decided without solving for roots on the span.

use ccd_arith::Rat;
use ccd_motion::{Bezier, Body, Motion};

use crate::error::{FieldPath, Limit, SceneError};
use crate::{Scene, World, MAX_BODIES, MAX_CONTROL_POINTS};

type Result<T> = std::result::Result<T, SceneError>;

/// The path of a field, spelt out ([`FieldPath`]) only when an error names
/// it: the checks pass far more often than they fail, and a path's text
/// costs allocations and formatting.
#[derive(Clone, Copy)]
enum Field<'a> {
    /// A top-level key.
    Root(&'a str),
    /// Body `i` of a world, named `name` ([`FieldPath::body`]).
    Body(usize, &'a str),
    /// `parent.key`.
    Key(&'a Field<'a>, &'a str),
    /// `parent[i]`.
    Index(&'a Field<'a>, usize),
}

impl<'a> Field<'a> {
    fn key(&'a self, key: &'a str) -> Field<'a> {
        Field::Key(self, key)
    }
    fn index(&'a self, i: usize) -> Field<'a> {
        Field::Index(self, i)
    }
    /// The path, as [`FieldPath`] builds it.
    fn path(&self) -> FieldPath {
        match self {
            Field::Root(key) => FieldPath::root(key),
            Field::Body(i, name) => FieldPath::body(*i, name),
            Field::Key(parent, key) => parent.path().key(key),
            Field::Index(parent, i) => parent.path().index(*i),
        }
    }
    /// The path as text, for an error.
    fn to_field(self) -> String {
        self.path().to_field()
    }
}

/// See [`Scene::validate`].
pub(crate) fn validate(scene: &Scene) -> Result<()> {
    span(&scene.span)?;
    body(&scene.a, &Field::Root("a"))?;
    body(&scene.b, &Field::Root("b"))
}

/// See [`World::validate`].
pub(crate) fn world(world: &World) -> Result<()> {
    span(&world.span)?;
    if world.bodies.len() > MAX_BODIES {
        return Err(SceneError::TooLarge {
            field: "body".into(),
            limit: Limit::Bodies,
        });
    }
    let mut seen = std::collections::HashMap::new();
    for (i, b) in world.bodies.iter().enumerate() {
        let path = Field::Body(i, &b.name);
        let name_error = |first| SceneError::Name {
            field: path.key("name").to_field(),
            first,
        };
        if b.name.is_empty() {
            return Err(name_error(None));
        }
        if let Some(first) = seen.insert(b.name.as_str(), i) {
            return Err(name_error(Some(first)));
        }
        body(&b.body, &path)?;
    }
    Ok(())
}

/// `t0 < t1`.
fn span([t0, t1]: &[Rat; 2]) -> Result<()> {
    if t0 >= t1 {
        return Err(SceneError::Span {
            t0: Box::new(t0.clone()),
            t1: Box::new(t1.clone()),
        });
    }
    Ok(())
}

/// A curve at `path` has `n` control points: between 1 and
/// [`MAX_CONTROL_POINTS`].
pub(crate) fn control_count(n: usize, path: &FieldPath) -> Result<()> {
    curve_points(n, || path.to_field())
}

/// [`control_count`] with the path's text built only for the error.
fn curve_points(n: usize, field: impl FnOnce() -> String) -> Result<()> {
    if n == 0 {
        Err(SceneError::Empty { field: field() })
    } else if n > MAX_CONTROL_POINTS {
        Err(SceneError::TooLarge {
            field: field(),
            limit: Limit::ControlPoints,
        })
    } else {
        Ok(())
    }
}

/// `x > 0`.
fn positive(x: &Rat, path: Field) -> Result<()> {
    if x.signum() > 0 {
        Ok(())
    } else {
        Err(SceneError::NonPositive {
            field: path.to_field(),
            value: x.clone(),
        })
    }
}

/// Not all of `v` is zero; `err` builds the error otherwise.
fn nonzero(v: &[Rat], path: Field, err: fn(String) -> SceneError) -> Result<()> {
    if v.iter().all(Rat::is_zero) {
        Err(err(path.to_field()))
    } else {
        Ok(())
    }
}

/// An orientation quaternion is not zero.
fn rotation(q: &[Rat], path: &Field) -> Result<()> {
    nonzero(q, path.key("orientation"), |field| {
        SceneError::ZeroQuaternion { field }
    })
}

fn body(b: &Body, path: &Field) -> Result<()> {
    let radii = path.key("radii");
    for (i, r) in b.radii.iter().enumerate() {
        positive(r, radii.index(i))?;
    }
    motion(&b.motion, &path.key("motion"))
}

/// The curve at `motion.key` and its weights at `motion.weights`: 1 to
/// [`MAX_CONTROL_POINTS`] points, one positive weight per point.
fn curve<P>(c: &Bezier<P>, motion: &Field, key: &str) -> Result<()> {
    curve_points(c.points.len(), || motion.key(key).to_field())?;
    let Some(w) = &c.weights else { return Ok(()) };
    let path = motion.key("weights");
    if w.len() != c.points.len() {
        return Err(SceneError::Length {
            field: path.to_field(),
            expected: c.points.len(),
            found: w.len(),
        });
    }
    w.iter()
        .enumerate()
        .try_for_each(|(i, x)| positive(x, path.index(i)))
}

fn motion(m: &Motion, path: &Field) -> Result<()> {
    match m {
        Motion::Static { orientation, .. } => rotation(orientation, path),
        Motion::Translation {
            center,
            orientation,
        } => {
            curve(center, path, "center")?;
            rotation(orientation, path)
        }
        Motion::Rigid {
            orientation,
            center,
        } => {
            // The format has no weights for the quaternion curve.
            if orientation.weights.is_some() {
                return Err(SceneError::Unknown {
                    field: path.key("orientation").key("weights").to_field(),
                });
            }
            curve(orientation, path, "orientation")?;
            curve(center, path, "center")
        }
        Motion::Affine { matrix } => curve(matrix, path, "matrix"),
        Motion::Helical {
            orientation, axis, ..
        } => {
            rotation(orientation, path)?;
            nonzero(axis, path.key("axis"), |field| SceneError::ZeroAxis {
                field,
            })
        }
    }
}
