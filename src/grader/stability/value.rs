//! What a task function returned on a stability case, widened to f64.

use glam::Vec3;
use serde::de::{Deserialize, Deserializer};
use serde::ser::{Serialize, SerializeMap, Serializer};

/// What a task function returned on one stability case, widened to f64 so f32 and f64
/// tasks compare alike. Non-finite numbers are kept as they are: spotting them is the point.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// The task returned `None` (for example "no refraction: total internal reflection").
    Absent,
    /// One number.
    Scalar(f64),
    /// A vector (a direction or an RGB triple).
    Vector([f64; 3]),
    /// Named numbers: a struct the task returned, or a summary a case computed from many
    /// calls (for example the smallest `wi.z` over a grid of samples).
    Record(Vec<(String, f64)>),
}

impl Value {
    /// Every number in the value, in order (none for [`Value::Absent`]).
    pub fn numbers(&self) -> Vec<f64> {
        match self {
            Value::Absent => Vec::new(),
            Value::Scalar(x) => vec![*x],
            Value::Vector(v) => v.to_vec(),
            Value::Record(fields) => fields.iter().map(|(_, x)| *x).collect(),
        }
    }

    /// The field `name` of a [`Value::Record`].
    pub fn field(&self, name: &str) -> Option<f64> {
        match self {
            Value::Record(fields) => fields.iter().find(|(n, _)| n == name).map(|(_, x)| *x),
            _ => None,
        }
    }

    /// A record from `(name, number)` pairs.
    pub fn record<'a>(fields: impl IntoIterator<Item = (&'a str, f64)>) -> Value {
        Value::Record(fields.into_iter().map(|(n, x)| (n.to_owned(), x)).collect())
    }
}

impl From<f32> for Value {
    fn from(x: f32) -> Self {
        Value::Scalar(x as f64)
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Self {
        Value::Scalar(x)
    }
}

impl From<Vec3> for Value {
    fn from(v: Vec3) -> Self {
        Value::Vector([v.x as f64, v.y as f64, v.z as f64])
    }
}

impl<T: Into<Value>> From<Option<T>> for Value {
    fn from(x: Option<T>) -> Self {
        x.map_or(Value::Absent, Into::into)
    }
}

/// Formats a number for a table: 7 significant digits
/// ([`format_significant`](crate::grade::output::format_significant)).
pub fn format_number(x: f64) -> String {
    crate::grade::output::format_significant(x, 7)
}

impl std::fmt::Display for Value {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Value::Absent => f.write_str("None"),
            Value::Scalar(x) => f.write_str(&format_number(*x)),
            Value::Vector(v) => write!(
                f,
                "({}, {}, {})",
                format_number(v[0]),
                format_number(v[1]),
                format_number(v[2])
            ),
            Value::Record(fields) => {
                let parts: Vec<String> = fields
                    .iter()
                    .map(|(n, x)| format!("{n}={}", format_number(*x)))
                    .collect();
                f.write_str(&parts.join(", "))
            }
        }
    }
}

/// A number for JSON: finite numbers as numbers, the others as the strings `"NaN"`, `"inf"`
/// and `"-inf"` (JSON has no non-finite numbers, and serde_json would write `null`).
struct JsonNumber(f64);

impl Serialize for JsonNumber {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        if self.0.is_finite() {
            s.serialize_f64(self.0)
        } else {
            s.serialize_str(&format_number(self.0))
        }
    }
}

/// JSON form: `null` for [`Value::Absent`], a number, an array of three, or an object.
impl Serialize for Value {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self {
            Value::Absent => s.serialize_none(),
            Value::Scalar(x) => JsonNumber(*x).serialize(s),
            Value::Vector(v) => v.map(JsonNumber).serialize(s),
            Value::Record(fields) => {
                let mut map = s.serialize_map(Some(fields.len()))?;
                for (name, x) in fields {
                    map.serialize_entry(name, &JsonNumber(*x))?;
                }
                map.end()
            }
        }
    }
}

/// Reads what the `Serialize` impl writes (non-finite numbers from their strings).
impl<'de> Deserialize<'de> for Value {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        use serde_json::Value as Json;
        let number = |v: &Json| -> Result<f64, String> {
            match v {
                Json::Number(n) => n.as_f64().ok_or_else(|| format!("not a number: {n}")),
                Json::String(s) => match s.as_str() {
                    "NaN" => Ok(f64::NAN),
                    "inf" => Ok(f64::INFINITY),
                    "-inf" => Ok(f64::NEG_INFINITY),
                    other => Err(format!("not a number: {other}")),
                },
                other => Err(format!("not a number: {other}")),
            }
        };
        let value = match Json::deserialize(d)? {
            Json::Null => Ok(Value::Absent),
            Json::Array(items) if items.len() == 3 => {
                let mut v = [0.0; 3];
                items
                    .iter()
                    .zip(&mut v)
                    .try_for_each(|(item, slot)| number(item).map(|x| *slot = x))
                    .map(|()| Value::Vector(v))
            }
            Json::Object(fields) => fields
                .iter()
                .map(|(name, x)| number(x).map(|x| (name.clone(), x)))
                .collect::<Result<_, _>>()
                .map(Value::Record),
            other => number(&other).map(Value::Scalar),
        };
        value.map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_formatted_to_seven_digits() {
        assert_eq!(format_number(1.0 / std::f64::consts::PI), "0.3183099");
        assert_eq!(format_number(318309.886), "318309.9");
        assert_eq!(format_number(31830988.6), "31830989");
        assert_eq!(format_number(318309886.0), "3.183099e8");
        assert_eq!(format_number(4e-8), "4e-8");
        assert_eq!(format_number(3.999_999_92e-8), "4e-8");
        assert_eq!(format_number(-2.5e-9), "-2.5e-9");
        assert_eq!(format_number(0.5), "0.5");
        assert_eq!(format_number(f64::NAN), "NaN");
        assert_eq!(format_number(f64::NEG_INFINITY), "-inf");
    }

    #[test]
    fn json_keeps_non_finite_numbers_visible() {
        let v = Value::Vector([1.0, f64::NAN, f64::INFINITY]);
        assert_eq!(serde_json::to_string(&v).unwrap(), r#"[1.0,"NaN","inf"]"#);
        assert_eq!(serde_json::to_string(&Value::Absent).unwrap(), "null");
        let r = Value::record([("pdf", 0.5)]);
        assert_eq!(serde_json::to_string(&r).unwrap(), r#"{"pdf":0.5}"#);
    }

    #[test]
    fn json_round_trip_keeps_non_finite_numbers() {
        for v in [
            Value::Absent,
            Value::Scalar(f64::NAN),
            Value::Scalar(-2.5),
            Value::Vector([1.0, f64::INFINITY, f64::NEG_INFINITY]),
            Value::record([("pdf", 0.25), ("min_z", f64::NAN)]),
        ] {
            let json = serde_json::to_string(&v).expect("serialises");
            let back: Value = serde_json::from_str(&json).expect("deserialises");
            assert_eq!(back.to_string(), v.to_string(), "{json}");
        }
    }
}
