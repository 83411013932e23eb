//! TOML text → a typed [`Scene`]: structure, types, lengths and numbers here;
//! the value checks (radii and weights `> 0`, `t0 < t1`, nonzero quaternions
//! and axes) are [`Scene::validate`]'s, run on the result.

use ccd_arith::{excerpt, Rat};
use ccd_motion::{Bezier, Body, HelicalCenter, Mat34, Motion, Quat, Vec3};
use toml_edit::{Array, DocumentMut, Item, TableLike, TomlError, Value};

use crate::error::{FieldPath, Limit, SceneError, TomlType};
use crate::number::{item_type, number, value_type};
use crate::validate::control_count;
use crate::{NamedBody, Scene, SceneFile, World, MAX_BODIES, MAX_INPUT_BYTES};

type Result<T> = std::result::Result<T, SceneError>;

/// Reads one value found at a path.
trait Read<T>: Fn(&Value, &FieldPath) -> Result<T> {}
impl<T, F: Fn(&Value, &FieldPath) -> Result<T>> Read<T> for F {}

/// The root table of TOML text, after the size check.
fn toml_root(text: &str) -> Result<DocumentMut> {
    if text.len() > MAX_INPUT_BYTES {
        return Err(SceneError::TooLarge {
            field: "<file>".to_string(),
            limit: Limit::InputBytes,
        });
    }
    text.parse().map_err(|e| not_toml(text, &e))
}

/// Parses and validates scene text (see [`Scene::from_toml`]).
pub(crate) fn parse_scene(text: &str) -> Result<Scene> {
    let doc = toml_root(text)?;
    pair(&Table::root(doc.as_table()))
}

/// Parses and validates a pair or world file (see [`SceneFile::from_toml`]).
pub(crate) fn parse_file(text: &str) -> Result<SceneFile> {
    let doc = toml_root(text)?;
    file(&Table::root(doc.as_table()))
}

/// Parses and validates a pair scene written as JSON (see
/// [`Scene::from_json`]).
pub(crate) fn parse_json_scene(text: &str) -> Result<Scene> {
    if text.len() > MAX_INPUT_BYTES {
        return Err(SceneError::TooLarge {
            field: "<file>".to_string(),
            limit: Limit::InputBytes,
        });
    }
    let table = crate::json::to_table(text)?;
    pair(&Table::root(&table))
}

/// A pair file when the root has no `body` key, a world file otherwise.
fn file(root: &Table<'_>) -> Result<SceneFile> {
    if root.get("body").is_some() {
        world(root).map(SceneFile::World)
    } else {
        pair(root).map(|s| SceneFile::Pair(Box::new(s)))
    }
}

/// `format` (which must be 1 when present) and `span`, after checking that
/// the root has no key but `format`, `span` and `bodies`.
fn header(root: &Table<'_>, bodies: &[&str]) -> Result<[Rat; 2]> {
    // The format first: a later format may have other keys.
    if let Some(found) = root.optional("format", TomlType::Number, number)? {
        if found != Rat::one() {
            return Err(SceneError::UnsupportedFormat { found });
        }
    }
    let allowed: Vec<&str> = ["format", "span"].iter().chain(bodies).copied().collect();
    root.only(&allowed)?;
    Ok(root
        .optional("span", TomlType::Array, fixed::<_, 2>(number))?
        .unwrap_or_else(Scene::default_span))
}

/// A pair scene: `[a]` and `[b]`.
fn pair(root: &Table<'_>) -> Result<Scene> {
    let span = header(root, &["a", "b"])?;
    const KEYS: [&str; 2] = ["radii", "motion"];
    let a = body(&root.child("a")?, &KEYS)?;
    let b = body(&root.child("b")?, &KEYS)?;
    let scene = Scene { span, a, b };
    scene.validate()?;
    Ok(scene)
}

/// A world scene: `[[body]]` tables (or `body = [{…}, …]`), each with a
/// `name`.
fn world(root: &Table<'_>) -> Result<World> {
    let span = header(root, &["body"])?;
    let (item, path) = root.require("body")?;
    let tables: Vec<&dyn TableLike> = match item {
        Item::ArrayOfTables(a) => a.iter().map(|t| t as &dyn TableLike).collect(),
        Item::Value(Value::Array(a)) => a
            .iter()
            .enumerate()
            .map(|(i, v)| match v {
                Value::InlineTable(t) => Ok(t as &dyn TableLike),
                other => Err(SceneError::WrongType {
                    field: path.index(i).to_field(),
                    expected: TomlType::Table,
                    found: value_type(other),
                }),
            })
            .collect::<Result<_>>()?,
        other => {
            return Err(SceneError::WrongType {
                field: path.to_field(),
                expected: TomlType::ArrayOfTables,
                found: item_type(other),
            })
        }
    };
    if tables.len() > MAX_BODIES {
        return Err(SceneError::TooLarge {
            field: path.to_field(),
            limit: Limit::Bodies,
        });
    }
    let bodies = tables
        .into_iter()
        .enumerate()
        .map(|(i, t)| {
            let t = Table {
                t,
                path: path.index(i),
            };
            let name = t.required("name", TomlType::String, |v: &Value, p: &FieldPath| {
                string(v, p).map(str::to_string)
            })?;
            let named = Table {
                t: t.t,
                path: FieldPath::body(i, &name),
            };
            Ok(NamedBody {
                name,
                body: body(&named, &["name", "radii", "motion"])?,
            })
        })
        .collect::<Result<_>>()?;
    let world = World { span, bodies };
    world.validate()?;
    Ok(world)
}

/// A TOML syntax error, located by line and column.
fn not_toml(text: &str, e: &TomlError) -> SceneError {
    let at = e.span().map_or(0, |s| s.start).min(text.len());
    let before = &text.as_bytes()[..at];
    let line_start = before
        .iter()
        .rposition(|&b| b == b'\n')
        .map_or(0, |i| i + 1);
    // Characters, not bytes: count the bytes that start a UTF-8 sequence.
    let column = 1 + before[line_start..]
        .iter()
        .filter(|&&b| b & 0xC0 != 0x80)
        .count();
    let line = 1 + before.iter().filter(|&&b| b == b'\n').count();
    SceneError::NotToml {
        line,
        column,
        message: e.message().trim().to_string(),
    }
}

/// A table (`[header]` or inline) and its path.
struct Table<'a> {
    t: &'a dyn TableLike,
    path: FieldPath,
}

impl<'a> Table<'a> {
    /// The root table of a document.
    fn root(t: &'a dyn TableLike) -> Table<'a> {
        Table {
            t,
            path: FieldPath::default(),
        }
    }
    /// `item` at `path`, which must be a table.
    fn open(item: &'a Item, path: FieldPath) -> Result<Table<'a>> {
        match item.as_table_like() {
            Some(t) => Ok(Table { t, path }),
            None => Err(SceneError::WrongType {
                field: path.to_field(),
                expected: TomlType::Table,
                found: item_type(item),
            }),
        }
    }
    /// Rejects any key not in `allowed`.
    fn only(&self, allowed: &[&str]) -> Result<()> {
        match self.t.iter().find(|(k, _)| !allowed.contains(k)) {
            Some((k, _)) => Err(SceneError::Unknown {
                field: self.path.key(k).to_field(),
            }),
            None => Ok(()),
        }
    }
    /// The item at `key`, if present, with its path.
    fn get(&self, key: &str) -> Option<(&'a Item, FieldPath)> {
        self.t
            .get(key)
            .filter(|item| !item.is_none())
            .map(|item| (item, self.path.key(key)))
    }
    /// The item at `key`, which must be present.
    fn require(&self, key: &str) -> Result<(&'a Item, FieldPath)> {
        self.get(key).ok_or_else(|| SceneError::Missing {
            field: self.path.key(key).to_field(),
        })
    }
    /// The sub-table at `key`, which must be present.
    fn child(&self, key: &str) -> Result<Table<'a>> {
        let (item, path) = self.require(key)?;
        Table::open(item, path)
    }
    /// The value at `key` read by `read`, if present; `expected` names what
    /// `read` wants, for an error when a `[table]` stands there instead.
    fn optional<T>(&self, key: &str, expected: TomlType, read: impl Read<T>) -> Result<Option<T>> {
        self.get(key)
            .map(|(item, path)| read(plain(item, &path, expected)?, &path))
            .transpose()
    }
    /// The value at `key` read by `read`, which must be present.
    fn required<T>(&self, key: &str, expected: TomlType, read: impl Read<T>) -> Result<T> {
        let (item, path) = self.require(key)?;
        read(plain(item, &path, expected)?, &path)
    }
}

/// `item` as a plain value (not a `[table]` or `[[array of tables]]`).
fn plain<'a>(item: &'a Item, path: &FieldPath, expected: TomlType) -> Result<&'a Value> {
    match item {
        Item::Value(v) => Ok(v),
        other => Err(SceneError::WrongType {
            field: path.to_field(),
            expected,
            found: item_type(other),
        }),
    }
}

/// `v` as a string.
fn string<'a>(v: &'a Value, path: &FieldPath) -> Result<&'a str> {
    match v {
        Value::String(s) => Ok(s.value()),
        other => Err(SceneError::WrongType {
            field: path.to_field(),
            expected: TomlType::String,
            found: value_type(other),
        }),
    }
}

/// How many elements an array must have.
#[derive(Clone, Copy)]
enum Len {
    /// Exactly this many.
    Exact(usize),
    /// A list of Bézier control points: 1 to [`crate::MAX_CONTROL_POINTS`].
    Curve,
}

/// The elements of the array `v`, each read by `read` at its indexed path,
/// after checking the array's length.
fn elements<T>(v: &Value, path: &FieldPath, len: Len, read: impl Read<T>) -> Result<Vec<T>> {
    let a: &Array = match v {
        Value::Array(a) => a,
        other => {
            return Err(SceneError::WrongType {
                field: path.to_field(),
                expected: TomlType::Array,
                found: value_type(other),
            })
        }
    };
    match len {
        Len::Exact(n) if a.len() != n => {
            return Err(SceneError::Length {
                field: path.to_field(),
                expected: n,
                found: a.len(),
            })
        }
        Len::Exact(_) => {}
        Len::Curve => control_count(a.len(), path)?,
    }
    a.iter()
        .enumerate()
        .map(|(i, x)| read(x, &path.index(i)))
        .collect()
}

/// A reader of arrays of exactly `N` elements, each read by `read`.
fn fixed<T, const N: usize>(read: impl Read<T>) -> impl Read<[T; N]> {
    move |v: &Value, path: &FieldPath| {
        let items = elements(v, path, Len::Exact(N), &read)?;
        items
            .try_into()
            .map_err(|items: Vec<T>| SceneError::Length {
                field: path.to_field(),
                expected: N,
                found: items.len(),
            })
    }
}

/// A 3-vector.
fn vec3(v: &Value, path: &FieldPath) -> Result<Vec3> {
    fixed(number)(v, path)
}

/// A quaternion `[w, x, y, z]`.
fn quat(v: &Value, path: &FieldPath) -> Result<Quat> {
    fixed(number)(v, path)
}

/// A 3×4 matrix `[L | d]` written as 3 rows of 4.
fn mat34(v: &Value, path: &FieldPath) -> Result<Mat34> {
    fixed(fixed(number))(v, path)
}

/// The zero 3-vector.
fn zero3() -> Vec3 {
    [Rat::zero(), Rat::zero(), Rat::zero()]
}

/// One `[a]` / `[b]` table (keys `radii`, `motion`), or a world's
/// `[[body]]` table (also `name`, which the caller reads).
fn body(t: &Table<'_>, keys: &[&str]) -> Result<Body> {
    t.only(keys)?;
    let radii = t.required("radii", TomlType::Array, vec3)?;
    let motion = match t.get("motion") {
        Some((item, path)) => motion(&Table::open(item, path)?)?,
        None => Motion::at_origin(),
    };
    Ok(Body { radii, motion })
}

/// The Bézier curve whose control points are at `key`, read by `read`, with
/// the motion's `weights` when `weighted`.
fn curve<P>(t: &Table<'_>, key: &str, read: impl Read<P>, weighted: bool) -> Result<Bezier<P>> {
    let (item, path) = t.require(key)?;
    let points = elements(
        plain(item, &path, TomlType::Array)?,
        &path,
        Len::Curve,
        read,
    )?;
    let n = points.len();
    let weights = if weighted {
        t.optional("weights", TomlType::Array, |v: &Value, p: &FieldPath| {
            elements(v, p, Len::Exact(n), number)
        })?
    } else {
        None
    };
    Ok(Bezier { points, weights })
}

/// A `motion` table.
fn motion(t: &Table<'_>) -> Result<Motion> {
    let (item, kind_path) = t.require("kind")?;
    let kind = string(plain(item, &kind_path, TomlType::String)?, &kind_path)?;
    let orientation = || {
        Ok::<_, SceneError>(
            t.optional("orientation", TomlType::Array, quat)?
                .unwrap_or_else(Motion::identity),
        )
    };
    Ok(match kind {
        "static" => {
            t.only(&["kind", "center", "orientation"])?;
            let center = t
                .optional("center", TomlType::Array, vec3)?
                .unwrap_or_else(zero3);
            Motion::Static {
                center,
                orientation: orientation()?,
            }
        }
        "translation" => {
            t.only(&["kind", "center", "weights", "orientation"])?;
            Motion::Translation {
                center: curve(t, "center", vec3, true)?,
                orientation: orientation()?,
            }
        }
        "rigid" => {
            t.only(&["kind", "orientation", "center", "weights"])?;
            Motion::Rigid {
                orientation: curve(t, "orientation", quat, false)?,
                center: curve(t, "center", vec3, true)?,
            }
        }
        "affine" => {
            t.only(&["kind", "matrix", "weights"])?;
            Motion::Affine {
                matrix: curve(t, "matrix", mat34, true)?,
            }
        }
        "helical" => {
            t.only(&["kind", "orientation", "axis", "rate", "center"])?;
            let orientation = orientation()?;
            let axis = t.required("axis", TomlType::Array, vec3)?;
            let rate = t.required("rate", TomlType::Number, number)?;
            let center = match t.get("center") {
                Some((item, path)) => helical_center(&Table::open(item, path)?)?,
                None => HelicalCenter {
                    base: zero3(),
                    velocity: zero3(),
                    cos: zero3(),
                    sin: zero3(),
                    frequency: Rat::zero(),
                },
            };
            Motion::Helical {
                orientation,
                axis,
                rate,
                center,
            }
        }
        other => {
            return Err(SceneError::UnknownKind {
                field: kind_path.to_field(),
                kind: excerpt(other),
            })
        }
    })
}

/// A helical `center` table; every field defaults to zero.
fn helical_center(t: &Table<'_>) -> Result<HelicalCenter> {
    t.only(&["base", "velocity", "cos", "sin", "frequency"])?;
    let v = |key: &str| {
        Ok::<_, SceneError>(
            t.optional(key, TomlType::Array, vec3)?
                .unwrap_or_else(zero3),
        )
    };
    Ok(HelicalCenter {
        base: v("base")?,
        velocity: v("velocity")?,
        cos: v("cos")?,
        sin: v("sin")?,
        frequency: t
            .optional("frequency", TomlType::Number, number)?
            .unwrap_or_else(Rat::zero),
    })
}
