//! A scene written as JSON (one line of `ccd-exact batch`): the JSON tree
//! becomes the TOML tree the parser reads, so both spellings go through one
//! parser and give the same errors with the same field paths.
//!
//! JSON integers are exact (those beyond `i64` are kept as their decimal
//! text, which the number reader accepts); JSON numbers with a fraction or
//! an exponent are refused ([`SceneError::JsonFloat`]): once parsed they
//! are binary floating point, so an exact scene writes them as strings. A
//! key whose value is `null` is absent; `null` elsewhere (in an array) is
//! an error.

use serde_json::Value as Json;
use toml_edit::{Array, InlineTable, Item, Table, Value};

use crate::error::{FieldPath, SceneError, TomlType};

type Result<T> = std::result::Result<T, SceneError>;

/// Parses `text` as JSON whose top level is an object, as a TOML table.
pub(crate) fn to_table(text: &str) -> Result<Table> {
    let json: Json = serde_json::from_str(text).map_err(|e| {
        let at = format!(" at line {} column {}", e.line(), e.column());
        let message = e.to_string();
        SceneError::NotJson {
            line: e.line(),
            column: e.column(),
            message: message.strip_suffix(&at).unwrap_or(&message).to_string(),
        }
    })?;
    let Json::Object(map) = json else {
        return Err(SceneError::WrongType {
            field: "<file>".into(),
            expected: TomlType::Table,
            found: json_type(&json),
        });
    };
    let root = FieldPath::default();
    let mut table = Table::new();
    for (k, v) in map.iter().filter(|(_, v)| !v.is_null()) {
        table.insert(k, Item::Value(value(v, &root.key(k))?));
    }
    Ok(table)
}

/// The TOML type a JSON value stands for, for an error.
fn json_type(v: &Json) -> TomlType {
    match v {
        Json::Null => TomlType::Null,
        Json::Bool(_) => TomlType::Boolean,
        Json::Number(_) => TomlType::Number,
        Json::String(_) => TomlType::String,
        Json::Array(_) => TomlType::Array,
        Json::Object(_) => TomlType::Table,
    }
}

/// One JSON value at `path` as a TOML value. JSON's recursion limit (128)
/// bounds the depth of this recursion.
fn value(v: &Json, path: &FieldPath) -> Result<Value> {
    Ok(match v {
        Json::Null => {
            return Err(SceneError::JsonNull {
                field: path.to_field(),
            })
        }
        Json::Bool(b) => Value::from(*b),
        Json::Number(n) => match (n.as_i64(), n.as_u64()) {
            (Some(i), _) => Value::from(i),
            (None, Some(u)) => Value::from(u.to_string()),
            (None, None) => {
                return Err(SceneError::JsonFloat {
                    field: path.to_field(),
                })
            }
        },
        Json::String(s) => Value::from(s.as_str()),
        Json::Array(items) => {
            let mut a = Array::new();
            for (i, x) in items.iter().enumerate() {
                a.push(value(x, &path.index(i))?);
            }
            Value::Array(a)
        }
        Json::Object(map) => {
            let mut t = InlineTable::new();
            for (k, x) in map.iter().filter(|(_, x)| !x.is_null()) {
                t.insert(k, value(x, &path.key(k))?);
            }
            Value::InlineTable(t)
        }
    })
}
