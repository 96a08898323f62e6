//! A JSON object read field by field, so that a refusal always names the field at fault: a
//! missing field, one of the wrong type and one this version does not know alike.

use serde::de::DeserializeOwned;
use serde_json::{Map, Value};

/// A field that could not be read: its path and why.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{field}`: {why}")]
pub struct FieldError {
    /// The field's path (`display.px_per_cm`).
    pub field: String,
    /// What is wrong.
    pub why: String,
}

/// The fields of one JSON object not read yet.
#[derive(Debug)]
pub struct Fields {
    prefix: String,
    map: Map<String, Value>,
}

impl Fields {
    /// The object in `value`; `prefix` (`display.`) starts its fields' paths.
    pub fn of(value: Value, prefix: &str) -> Result<Self, FieldError> {
        match value {
            Value::Object(map) => Ok(Self {
                prefix: prefix.to_owned(),
                map,
            }),
            other => Err(FieldError {
                field: prefix.trim_end_matches('.').to_owned(),
                why: format!("expected a JSON object, got {}", kind(&other)),
            }),
        }
    }

    /// The object in `bytes`.
    pub fn parse(bytes: &[u8]) -> Result<Self, FieldError> {
        let value: Value = serde_json::from_slice(bytes).map_err(|e| FieldError {
            field: "body".into(),
            why: format!("not JSON: {e}"),
        })?;
        Self::of(value, "")
    }

    fn path(&self, name: &str) -> String {
        format!("{}{name}", self.prefix)
    }

    /// Field `name`, which must be present.
    pub fn req<T: DeserializeOwned>(
        &mut self,
        name: &str,
        expected: &str,
    ) -> Result<T, FieldError> {
        match self.map.remove(name) {
            None => Err(FieldError {
                field: self.path(name),
                why: format!("missing: expected {expected}"),
            }),
            Some(v) => self.convert(name, v, expected),
        }
    }

    /// Field `name`, absent or `null` giving `None`.
    pub fn opt<T: DeserializeOwned>(
        &mut self,
        name: &str,
        expected: &str,
    ) -> Result<Option<T>, FieldError> {
        match self.map.remove(name) {
            None | Some(Value::Null) => Ok(None),
            Some(v) => self.convert(name, v, expected).map(Some),
        }
    }

    /// Field `name` as an object of its own.
    pub fn object(&mut self, name: &str) -> Result<Self, FieldError> {
        let path = self.path(name);
        match self.map.remove(name) {
            None => Err(FieldError {
                field: path,
                why: "missing: expected an object".into(),
            }),
            Some(v) => Self::of(v, &format!("{path}.")),
        }
    }

    fn convert<T: DeserializeOwned>(
        &self,
        name: &str,
        v: Value,
        expected: &str,
    ) -> Result<T, FieldError> {
        let got = kind(&v);
        serde_json::from_value(v).map_err(|_| FieldError {
            field: self.path(name),
            why: format!("expected {expected}, got {got}"),
        })
    }

    /// Refuse any field left: a misspelt field must not pass for an absent one.
    pub fn done(self) -> Result<(), FieldError> {
        match self.map.keys().next() {
            None => Ok(()),
            Some(k) => Err(FieldError {
                field: format!("{}{}", self.prefix, k.chars().take(40).collect::<String>()),
                why: "unknown field".into(),
            }),
        }
    }
}

fn kind(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => b.to_string(),
        Value::Number(n) => n.to_string(),
        Value::String(s) => format!("{:?}", s.chars().take(40).collect::<String>()),
        Value::Array(a) => format!("an array of {}", a.len()),
        Value::Object(_) => "an object".into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_fault_names_its_field() {
        let mut f =
            Fields::parse(br#"{"a": 1, "b": "x", "d": {"e": true}, "z": 0}"#).expect("object");
        assert_eq!(f.req::<u32>("a", "a count"), Ok(1));
        let e = f.req::<f64>("b", "a number").expect_err("type");
        assert_eq!(e.to_string(), "`b`: expected a number, got \"x\"");
        assert_eq!(
            f.req::<f64>("c", "a number").expect_err("missing").field,
            "c"
        );
        let mut d = f.object("d").expect("object");
        assert_eq!(d.req::<u8>("e", "a count").expect_err("type").field, "d.e");
        assert_eq!(f.done().expect_err("unknown").field, "z");
        assert_eq!(Fields::parse(b"[1]").expect_err("not an object").field, "");
        assert_eq!(Fields::parse(b"{").expect_err("syntax").field, "body");
    }
}
