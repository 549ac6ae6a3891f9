//! What a stability case expects of a number: bounds and tolerances.

use super::value::{Value, format_number};
use crate::grade::tolerance::Tolerance;

/// The tolerance as the stability table shows it.
impl std::fmt::Display for Tolerance {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match (self.abs, self.rel) {
            (a, 0.0) => write!(f, "± {}", format_number(a)),
            (0.0, r) => write!(f, "rel {}", format_number(r)),
            (a, r) => write!(f, "± {} + rel {}", format_number(a), format_number(r)),
        }
    }
}

/// A condition on one number.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Bound {
    /// Within a tolerance of a target.
    Near(f64, Tolerance),
    /// In the closed interval `[lo, hi]` (either end may be infinite).
    Within(f64, f64),
}

impl Bound {
    /// True when `x` satisfies the bound (never for NaN).
    pub fn accepts(&self, x: f64) -> bool {
        match *self {
            Bound::Near(target, tol) => tol.close(x, target),
            Bound::Within(lo, hi) => lo <= x && x <= hi,
        }
    }
}

impl std::fmt::Display for Bound {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match *self {
            Bound::Near(target, tol) => write!(f, "{} {tol}", format_number(target)),
            Bound::Within(lo, f64::INFINITY) => write!(f, "≥ {}", format_number(lo)),
            Bound::Within(f64::NEG_INFINITY, hi) => write!(f, "≤ {}", format_number(hi)),
            Bound::Within(lo, hi) => write!(f, "in [{}, {}]", format_number(lo), format_number(hi)),
        }
    }
}

/// The right answer of a stability case, or the limit it must approach.
#[derive(Clone, Debug)]
pub enum Expect {
    /// A scalar or vector whose every component is within the tolerance of the target's.
    Near(Value, Tolerance),
    /// `None`: the task must report that there is no result.
    Absent,
    /// Any finite value; the case's range does the rest.
    Finite,
    /// Conditions on the named fields of a [`Value::Record`].
    Fields(Vec<(&'static str, Bound)>),
    /// A property the value must have, described in words.
    Rule {
        /// What the property is, for the table.
        text: &'static str,
        /// Decides the property.
        holds: fn(&Value) -> bool,
    },
    /// Any one of several answers (for inputs where more than one behaviour is right).
    AnyOf(Vec<Expect>),
}

impl Expect {
    /// A scalar target.
    pub fn scalar(target: f64, tol: Tolerance) -> Self {
        Expect::Near(Value::Scalar(target), tol)
    }

    /// A vector target.
    pub fn vector(target: [f64; 3], tol: Tolerance) -> Self {
        Expect::Near(Value::Vector(target), tol)
    }

    /// True when `value` is an acceptable answer.
    pub fn accepts(&self, value: &Value) -> bool {
        match self {
            Expect::Near(target, tol) => {
                let (got, want) = (value.numbers(), target.numbers());
                same_shape(value, target) && got.iter().zip(&want).all(|(x, t)| tol.close(*x, *t))
            }
            Expect::Absent => *value == Value::Absent,
            Expect::Finite => *value != Value::Absent,
            Expect::Fields(bounds) => bounds
                .iter()
                .all(|(name, b)| value.field(name).is_some_and(|x| b.accepts(x))),
            Expect::Rule { holds, .. } => holds(value),
            Expect::AnyOf(options) => options.iter().any(|e| e.accepts(value)),
        }
    }
}

fn same_shape(a: &Value, b: &Value) -> bool {
    matches!(
        (a, b),
        (Value::Scalar(_), Value::Scalar(_)) | (Value::Vector(_), Value::Vector(_))
    )
}

impl std::fmt::Display for Expect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Expect::Near(target, tol) => write!(f, "{target} {tol}"),
            Expect::Absent => f.write_str("None"),
            Expect::Finite => f.write_str("finite"),
            Expect::Fields(bounds) => {
                let parts: Vec<String> = bounds.iter().map(|(n, b)| format!("{n} {b}")).collect();
                f.write_str(&parts.join(", "))
            }
            Expect::Rule { text, .. } => f.write_str(text),
            Expect::AnyOf(options) => {
                let parts: Vec<String> = options.iter().map(ToString::to_string).collect();
                f.write_str(&parts.join(" or "))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_compares_every_component_and_rejects_nan() {
        let e = Expect::vector([0.6, 0.8, 0.0], Tolerance::abs(1e-6));
        assert!(e.accepts(&Value::Vector([0.6, 0.8, 1e-7])));
        assert!(!e.accepts(&Value::Vector([0.6, 5.6, 0.0])));
        assert!(!e.accepts(&Value::Vector([0.6, f64::NAN, 0.0])));
        assert!(!e.accepts(&Value::Scalar(0.6)));
        assert!(!e.accepts(&Value::Absent));
    }

    #[test]
    fn fields_need_every_named_field() {
        let e = Expect::Fields(vec![
            ("a", Bound::Within(0.0, 1.0)),
            ("b", Bound::Near(2.0, Tolerance::rel(0.1))),
        ]);
        assert!(e.accepts(&Value::record([("a", 0.5), ("b", 2.1)])));
        assert!(!e.accepts(&Value::record([("a", 0.5)])));
        assert!(!e.accepts(&Value::record([("a", -0.5), ("b", 2.0)])));
    }

    #[test]
    fn any_of_accepts_either_answer() {
        let e = Expect::AnyOf(vec![
            Expect::Absent,
            Expect::scalar(1.0, Tolerance::abs(0.0)),
        ]);
        assert!(e.accepts(&Value::Absent));
        assert!(e.accepts(&Value::Scalar(1.0)));
        assert!(!e.accepts(&Value::Scalar(0.0)));
        assert_eq!(e.to_string(), "None or 1 ± 0");
    }
}
