//! Closeness of numbers and of whole outputs: absolute plus relative tolerance, NaN never
//! equal to anything.

use super::output::Output;
use serde::{Deserialize, Serialize};

/// `|got − expected| ≤ abs + rel · |expected|`. NaN is never close to anything, and an
/// infinity only to the same infinity.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Tolerance {
    /// Absolute part.
    pub abs: f64,
    /// Relative part, a fraction of |expected|.
    pub rel: f64,
}

impl Tolerance {
    /// A tolerance of `abs` plus `rel` times the expected magnitude.
    pub const fn new(abs: f64, rel: f64) -> Self {
        Self { abs, rel }
    }

    /// A purely absolute tolerance.
    pub const fn abs(abs: f64) -> Self {
        Self { abs, rel: 0.0 }
    }

    /// A purely relative tolerance.
    pub const fn rel(rel: f64) -> Self {
        Self { abs: 0.0, rel }
    }

    /// For f32 task outputs computed by any reasonable algebraic form.
    pub const F32: Tolerance = Tolerance::new(1e-5, 2e-4);

    /// For the f64 outputs of the layer-stack calculator (answers checked to 6 digits).
    pub const F64: Tolerance = Tolerance::new(1e-7, 1e-6);

    /// True when `got` is within tolerance of `expected`.
    pub fn close(&self, got: f64, expected: f64) -> bool {
        if got.is_nan() || expected.is_nan() {
            return false;
        }
        if got.is_infinite() || expected.is_infinite() {
            return got == expected;
        }
        (got - expected).abs() <= self.abs + self.rel * expected.abs()
    }

    /// Compares two outputs leaf by leaf; on the first difference returns where it is.
    pub fn compare(&self, got: &Output, expected: &Output) -> Result<(), Mismatch> {
        self.compare_at(got, expected, &mut String::new())
    }

    fn compare_at(
        &self,
        got: &Output,
        expected: &Output,
        path: &mut String,
    ) -> Result<(), Mismatch> {
        let mismatch = |path: &str, got: &Output, expected: &Output| Mismatch {
            path: path.to_string(),
            got: got.clone(),
            expected: expected.clone(),
            error: error(got, expected),
        };
        match (got, expected) {
            (Output::Nothing, Output::Nothing) => Ok(()),
            (Output::Number(g), Output::Number(e)) if self.close(*g, *e) => Ok(()),
            (Output::Numbers(g), Output::Numbers(e))
                if g.len() == e.len() && g.iter().zip(e).all(|(g, e)| self.close(*g, *e)) =>
            {
                Ok(())
            }
            (Output::Record(g), Output::Record(e)) => {
                for (name, e_field) in e {
                    let len = path.len();
                    if !path.is_empty() {
                        path.push('.');
                    }
                    path.push_str(name);
                    let g_field = g.get(name).unwrap_or(&Output::Nothing);
                    self.compare_at(g_field, e_field, path)?;
                    path.truncate(len);
                }
                Ok(())
            }
            _ => Err(mismatch(path, got, expected)),
        }
    }
}

/// Where and how two outputs differ.
#[derive(Clone, Debug, PartialEq)]
pub struct Mismatch {
    /// The field that differs (`""` for the whole output, `theta` for a record field).
    pub path: String,
    /// The student's value there.
    pub got: Output,
    /// The expected value there.
    pub expected: Output,
    /// The absolute and relative error there (infinite when not comparable).
    pub error: Error,
}

/// The size of a difference: the largest absolute error over the components, and the
/// relative error at that component.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Error {
    /// Absolute error (infinite when a value is NaN or the shapes differ).
    #[serde(with = "super::lenient_f64")]
    pub abs: f64,
    /// Relative error, `abs / |expected|` (infinite when expected is 0 and abs > 0).
    #[serde(with = "super::lenient_f64")]
    pub rel: f64,
}

impl Error {
    /// The error of an output that cannot be compared at all.
    pub const UNBOUNDED: Error = Error {
        abs: f64::INFINITY,
        rel: f64::INFINITY,
    };

    fn of(got: f64, expected: f64) -> Error {
        if got == expected {
            // Equal infinities too, whose difference is NaN.
            return Error::default();
        }
        let abs = (got - expected).abs();
        if abs.is_nan() {
            return Error::UNBOUNDED;
        }
        let rel = if abs == 0.0 {
            0.0
        } else {
            abs / expected.abs()
        };
        Error { abs, rel }
    }

    /// The larger (by absolute error) of two errors.
    pub fn max(self, other: Error) -> Error {
        if other.abs > self.abs || (other.abs == self.abs && other.rel > self.rel) {
            other
        } else {
            self
        }
    }
}

/// The error between two outputs of the same shape (the worst component), or
/// [`Error::UNBOUNDED`] when the shapes differ.
pub fn error(got: &Output, expected: &Output) -> Error {
    match (got, expected) {
        (Output::Nothing, Output::Nothing) => Error::default(),
        (Output::Number(g), Output::Number(e)) => Error::of(*g, *e),
        (Output::Numbers(g), Output::Numbers(e)) if g.len() == e.len() => g
            .iter()
            .zip(e)
            .map(|(g, e)| Error::of(*g, *e))
            .fold(Error::default(), Error::max),
        (Output::Record(g), Output::Record(e)) => e
            .iter()
            .map(|(k, e)| error(g.get(k).unwrap_or(&Output::Nothing), e))
            .fold(Error::default(), Error::max),
        _ => Error::UNBOUNDED,
    }
}

/// True when two JSON documents have the same structure and strings, and every pair of
/// numbers is within `tol`. Used to compare regenerated expected data with the stored data,
/// where the reference's rounding may differ between machines.
pub fn json_close(a: &serde_json::Value, b: &serde_json::Value, tol: Tolerance) -> bool {
    use serde_json::Value as J;
    match (a, b) {
        (J::Number(x), J::Number(y)) => match (x.as_f64(), y.as_f64()) {
            (Some(x), Some(y)) => tol.close(x, y),
            _ => false,
        },
        (J::Array(x), J::Array(y)) => {
            x.len() == y.len() && x.iter().zip(y).all(|(x, y)| json_close(x, y, tol))
        }
        (J::Object(x), J::Object(y)) => {
            x.len() == y.len()
                && x.iter()
                    .all(|(k, v)| y.get(k).is_some_and(|w| json_close(v, w, tol)))
        }
        _ => a == b,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::output::IntoOutput;
    use glam::Vec3;

    #[test]
    fn nan_is_never_close() {
        let tol = Tolerance::new(1.0, 1.0);
        assert!(!tol.close(f64::NAN, f64::NAN));
        assert!(!tol.close(f64::NAN, 0.0));
        assert!(tol.close(f64::INFINITY, f64::INFINITY));
        assert!(!tol.close(1e300, f64::INFINITY));
    }

    #[test]
    fn absolute_and_relative_parts_add() {
        let tol = Tolerance::new(1e-3, 1e-2);
        assert!(tol.close(100.9, 100.0));
        assert!(!tol.close(101.1, 100.0));
        assert!(tol.close(0.0009, 0.0));
        assert!(!tol.close(0.0011, 0.0));
    }

    #[test]
    fn comparison_names_the_differing_field() {
        let expected = crate::optics::StackReport {
            theta: vec![30.0, 19.47],
            ..Default::default()
        }
        .into_output();
        let got = crate::optics::StackReport {
            theta: vec![30.0, 19.5],
            ..Default::default()
        }
        .into_output();
        let m = Tolerance::F64.compare(&got, &expected).unwrap_err();
        assert_eq!(m.path, "theta");
        assert!((m.error.abs - 0.03).abs() < 1e-9);
    }

    #[test]
    fn json_documents_compare_numbers_within_tolerance() {
        let a: serde_json::Value =
            serde_json::from_str(r#"{"x": [1.0, 2.0], "name": "a"}"#).unwrap();
        let b: serde_json::Value =
            serde_json::from_str(r#"{"x": [1.000001, 2], "name": "a"}"#).unwrap();
        let c: serde_json::Value = serde_json::from_str(r#"{"x": [1.1, 2], "name": "a"}"#).unwrap();
        let d: serde_json::Value =
            serde_json::from_str(r#"{"x": [1.0, 2.0], "name": "b"}"#).unwrap();
        let tol = Tolerance::new(0.0, 1e-5);
        assert!(json_close(&a, &b, tol));
        assert!(!json_close(&a, &c, tol));
        assert!(!json_close(&a, &d, tol));
    }

    #[test]
    fn shapes_must_agree() {
        let some = Some(Vec3::X).into_output();
        let none = None::<Vec3>.into_output();
        assert!(Tolerance::F32.compare(&none, &some).is_err());
        assert_eq!(error(&none, &some), Error::UNBOUNDED);
        assert!(Tolerance::F32.compare(&none, &none).is_ok());
    }
}
