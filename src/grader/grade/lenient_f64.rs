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

/// The same for a list of f32 (`#[serde(with = "lenient_f64::seq_f32")]`): finite values
/// written at f32 precision, read back exactly.
pub mod seq_f32 {
    use serde::ser::SerializeSeq;
    use serde::{Deserializer, Serializer};

    /// Writes each element as [`super::serialize`] does, finite ones as f32.
    pub fn serialize<S: Serializer>(xs: &[f32], s: S) -> Result<S::Ok, S::Error> {
        struct Element(f32);
        impl serde::Serialize for Element {
            fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                if self.0.is_finite() {
                    s.serialize_f32(self.0)
                } else {
                    super::serialize(&(self.0 as f64), s)
                }
            }
        }
        let mut seq = s.serialize_seq(Some(xs.len()))?;
        for &x in xs {
            seq.serialize_element(&Element(x))?;
        }
        seq.end()
    }

    /// Reads what [`serialize`] writes.
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<f32>, D::Error> {
        Ok(super::seq::deserialize(d)?
            .into_iter()
            .map(|x| x as f32)
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

    #[derive(serde::Serialize, serde::Deserialize, Debug, PartialEq)]
    struct Xs(#[serde(with = "super::seq_f32")] Vec<f32>);

    #[test]
    fn f32_lists_round_trip_exactly_with_their_non_finite_values() {
        let xs = vec![
            0.1f32,
            1.0 / 3.0,
            f32::MAX,
            f32::MIN_POSITIVE,
            -0.0,
            f32::INFINITY,
        ];
        let json = serde_json::to_string(&Xs(xs.clone())).unwrap();
        assert_eq!(serde_json::from_str::<Xs>(&json).unwrap(), Xs(xs), "{json}");
        let back: Xs =
            serde_json::from_str(&serde_json::to_string(&Xs(vec![f32::NAN])).unwrap()).unwrap();
        assert!(back.0[0].is_nan());
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
