//! Serde for f64 fields that may hold NaN or an infinity (an error of "not comparable", a χ²
//! of a sample where none can be): JSON has no such numbers, so they are written as the
//! strings `"NaN"`, `"inf"` and `"-inf"` and read back from those (or from `null`, as NaN).

use serde::{Deserialize, Deserializer, Serializer};

/// Writes finite values as numbers and the others as strings.
pub fn serialize<S: Serializer>(x: &f64, s: S) -> Result<S::Ok, S::Error> {
    if x.is_finite() {
        s.serialize_f64(*x)
    } else if x.is_nan() {
        s.serialize_str("NaN")
    } else if *x > 0.0 {
        s.serialize_str("inf")
    } else {
        s.serialize_str("-inf")
    }
}

#[derive(Deserialize)]
#[serde(untagged)]
enum Lenient {
    Number(f64),
    Text(String),
    Null(()),
}

/// Reads what [`serialize`] writes.
pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    match Lenient::deserialize(d)? {
        Lenient::Number(x) => Ok(x),
        Lenient::Null(()) => Ok(f64::NAN),
        Lenient::Text(t) => match t.as_str() {
            "NaN" => Ok(f64::NAN),
            "inf" => Ok(f64::INFINITY),
            "-inf" => Ok(f64::NEG_INFINITY),
            other => Err(serde::de::Error::custom(format!("not a number: {other}"))),
        },
    }
}

/// The same for a list of f64 (`#[serde(with = "lenient_f64::seq")]`).
pub mod seq {
    use serde::ser::SerializeSeq;
    use serde::{Deserialize, Deserializer, Serializer};

    /// One element, read as [`super::deserialize`] reads it.
    #[derive(Deserialize)]
    struct Element(#[serde(deserialize_with = "super::deserialize")] f64);

    /// Writes each element as [`super::serialize`] does.
    pub fn serialize<S: Serializer>(xs: &[f64], s: S) -> Result<S::Ok, S::Error> {
        struct Element(f64);
        impl serde::Serialize for Element {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                super::serialize(&self.0, s)
            }
        }
        let mut seq = s.serialize_seq(Some(xs.len()))?;
        for &x in xs {
            seq.serialize_element(&Element(x))?;
        }
        seq.end()
    }

    /// Reads what [`serialize`] writes.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f64>, D::Error> {
        Ok(Vec::<Element>::deserialize(d)?
            .into_iter()
            .map(|e| e.0)
            .collect())
    }
}

#[cfg(test)]
mod tests {
    #[derive(serde::Serialize, serde::Deserialize, Debug)]
    struct X {
        #[serde(with = "super")]
        v: f64,
    }

    #[test]
    fn non_finite_values_round_trip() {
        for v in [1.5, f64::INFINITY, f64::NEG_INFINITY] {
            let json = serde_json::to_string(&X { v }).unwrap();
            assert_eq!(serde_json::from_str::<X>(&json).unwrap().v, v, "{json}");
        }
        let json = serde_json::to_string(&X { v: f64::NAN }).unwrap();
        assert_eq!(json, r#"{"v":"NaN"}"#);
        assert!(serde_json::from_str::<X>(&json).unwrap().v.is_nan());
        assert!(
            serde_json::from_str::<X>(r#"{"v":null}"#)
                .unwrap()
                .v
                .is_nan()
        );
    }
}
