//! Exact numbers from TOML values, never through `f64`: a TOML integer is
//! that integer, a TOML float is read from its decimal text as written (with
//! `_` separators removed), and a string goes through [`Rat::parse_exact`].

use ccd_arith::{ParseRatError, Rat};
use toml_edit::{Item, Value};

use crate::error::{FieldPath, Limit, SceneError, TomlType};

/// The TOML type of an item, for [`SceneError::WrongType`].
pub(crate) fn item_type(item: &Item) -> TomlType {
    match item {
        Item::Value(v) => value_type(v),
        Item::ArrayOfTables(_) => TomlType::ArrayOfTables,
        Item::Table(_) | Item::None => TomlType::Table,
    }
}

/// The TOML type of a value, for [`SceneError::WrongType`].
pub(crate) fn value_type(v: &Value) -> TomlType {
    match v {
        Value::String(_) => TomlType::String,
        Value::Integer(_) | Value::Float(_) => TomlType::Number,
        Value::Boolean(_) => TomlType::Boolean,
        Value::Datetime(_) => TomlType::Datetime,
        Value::Array(_) => TomlType::Array,
        Value::InlineTable(_) => TomlType::Table,
    }
}

/// The exact value of `v`, which must be a number or a number string.
pub(crate) fn number(v: &Value, path: &FieldPath) -> Result<Rat, SceneError> {
    match v {
        Value::Integer(i) => Ok(Rat::from(*i.value())),
        Value::Float(f) => match f.as_repr().and_then(|r| r.as_raw().as_str()) {
            Some(raw) => exact_text(&raw.replace('_', ""), path),
            // A parsed document keeps every float's text; a value built in
            // code may not, and its binary value is not what was meant.
            None => Err(SceneError::Number {
                field: path.to_field(),
                source: ParseRatError::Invalid(f.display_repr().into_owned()),
            }),
        },
        Value::String(s) => exact_text(s.value(), path),
        other => Err(SceneError::WrongType {
            field: path.to_field(),
            expected: TomlType::Number,
            found: value_type(other),
        }),
    }
}

/// `text` as an exact rational (integer, decimal or fraction).
pub(crate) fn exact_text(text: &str, path: &FieldPath) -> Result<Rat, SceneError> {
    let too_large = || SceneError::TooLarge {
        field: path.to_field(),
        limit: Limit::Number,
    };
    Rat::parse_exact(text).map_err(|e| match e {
        ParseRatError::TooLarge(_) => too_large(),
        source => SceneError::Number {
            field: path.to_field(),
            source,
        },
    })
}
