//! What a task function returned, in a form the grader can store, compare and print.
//!
//! Every task output (f32, f64, `Vec3`, `Option<…>`, the report structs) converts into an
//! [`Output`] tree. Unlike JSON it keeps NaN and infinities, so a message can say "got NaN";
//! stored reference outputs are always finite.

use crate::bsdf::PlausibilityReport;
use crate::optics::StackReport;
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::fmt;

/// A task function's result: a number, a vector, nothing (`None`) or a record of named fields.
/// Non-finite numbers (a student's NaN) are written as the strings `"NaN"`, `"inf"` and
/// `"-inf"`, so an output crosses the worker's pipe unchanged.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Output {
    /// `None`.
    Nothing,
    /// A scalar.
    Number(#[serde(with = "super::lenient_f64")] f64),
    /// A list of scalars (a `Vec3`, a per-interface list, …).
    Numbers(#[serde(with = "super::lenient_f64::seq")] Vec<f64>),
    /// A struct, by field name.
    Record(BTreeMap<String, Output>),
}

impl Output {
    /// True when every number in the output is finite.
    pub fn is_finite(&self) -> bool {
        match self {
            Output::Nothing => true,
            Output::Number(x) => x.is_finite(),
            Output::Numbers(v) => v.iter().all(|x| x.is_finite()),
            Output::Record(m) => m.values().all(Output::is_finite),
        }
    }

    /// The largest magnitude of a number in the output (NaNs left out; 0 for none).
    pub fn magnitude(&self) -> f64 {
        match self {
            Output::Nothing => 0.0,
            Output::Number(x) => x.abs(),
            Output::Numbers(v) => v.iter().fold(0.0, |m: f64, x| m.max(x.abs())),
            Output::Record(m) => m.values().fold(0.0, |a: f64, o| a.max(o.magnitude())),
        }
    }

    /// True when some number in the output is NaN.
    pub fn has_nan(&self) -> bool {
        match self {
            Output::Nothing => false,
            Output::Number(x) => x.is_nan(),
            Output::Numbers(v) => v.iter().any(|x| x.is_nan()),
            Output::Record(m) => m.values().any(Output::has_nan),
        }
    }

    /// The field `name` of a record.
    pub fn field(&self, name: &str) -> Option<&Output> {
        match self {
            Output::Record(m) => m.get(name),
            _ => None,
        }
    }

    /// The scalar, when the output is one.
    pub fn as_number(&self) -> Option<f64> {
        match self {
            Output::Number(x) => Some(*x),
            _ => None,
        }
    }

    /// The largest difference between corresponding numbers of two outputs of the same
    /// shape; `None` when the shapes differ (`None` against a value, lists of other
    /// lengths, other fields) or a number is finite in one and not the other.
    pub fn max_difference(&self, other: &Output) -> Option<f64> {
        let pair = |a: f64, b: f64| match (a.is_finite(), b.is_finite()) {
            (true, true) => Some((a - b).abs()),
            (false, false) if a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()) => Some(0.0),
            _ => None,
        };
        match (self, other) {
            (Output::Nothing, Output::Nothing) => Some(0.0),
            (Output::Number(a), Output::Number(b)) => pair(*a, *b),
            (Output::Numbers(a), Output::Numbers(b)) if a.len() == b.len() => a
                .iter()
                .zip(b)
                .try_fold(0f64, |m, (a, b)| Some(m.max(pair(*a, *b)?))),
            (Output::Record(a), Output::Record(b))
                if a.len() == b.len() && a.keys().eq(b.keys()) =>
            {
                a.values()
                    .zip(b.values())
                    .try_fold(0f64, |m, (a, b)| Some(m.max(a.max_difference(b)?)))
            }
            _ => None,
        }
    }
}

/// Widens an f32 through its shortest decimal form, so that 0.1f32 is stored as 0.1 and not
/// 0.10000000149011612 (reading it back as f32 gives the same bits either way).
pub fn widen(x: f32) -> f64 {
    if x.is_finite() {
        x.to_string().parse().unwrap_or(x as f64)
    } else {
        x as f64
    }
}

/// Conversion of a task function's return type into an [`Output`].
pub trait IntoOutput {
    /// The output tree of `self`.
    fn into_output(self) -> Output;
}

impl IntoOutput for f32 {
    fn into_output(self) -> Output {
        Output::Number(widen(self))
    }
}

impl IntoOutput for f64 {
    fn into_output(self) -> Output {
        Output::Number(self)
    }
}

impl IntoOutput for Vec3 {
    fn into_output(self) -> Output {
        Output::Numbers(self.to_array().map(widen).to_vec())
    }
}

impl IntoOutput for usize {
    fn into_output(self) -> Output {
        Output::Number(self as f64)
    }
}

impl IntoOutput for Vec<f64> {
    fn into_output(self) -> Output {
        Output::Numbers(self)
    }
}

impl<T: IntoOutput> IntoOutput for Option<T> {
    fn into_output(self) -> Output {
        self.map_or(Output::Nothing, IntoOutput::into_output)
    }
}

fn record<const N: usize>(fields: [(&str, Output); N]) -> Output {
    Output::Record(
        fields
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect(),
    )
}

impl IntoOutput for StackReport {
    fn into_output(self) -> Output {
        record([
            ("theta", self.theta.into_output()),
            ("tir_at", self.tir_at.into_output()),
            (
                "perpendicular_shift",
                self.perpendicular_shift.into_output(),
            ),
            ("interface_offset", self.interface_offset.into_output()),
            (
                "reflectance_schlick",
                self.reflectance_schlick.into_output(),
            ),
            ("reflectance_exact", self.reflectance_exact.into_output()),
            (
                "transmitted_schlick",
                self.transmitted_schlick.into_output(),
            ),
            ("transmitted_exact", self.transmitted_exact.into_output()),
        ])
    }
}

impl IntoOutput for PlausibilityReport {
    fn into_output(self) -> Output {
        record([
            ("min_value", self.min_value.into_output()),
            (
                "max_reciprocity_error",
                self.max_reciprocity_error.into_output(),
            ),
            ("max_albedo", self.max_albedo.into_output()),
            ("worst_wi", self.worst_wi.into_output()),
        ])
    }
}

/// Formats a number for messages: 4 significant digits (see [`format_significant`]).
pub fn fmt_num(x: f64) -> String {
    format_significant(x, 4)
}

/// Formats a number for people with `digits` significant digits (at least 1): plain
/// decimals from 1e-3 up to below 10^(digits + 1), scientific notation beyond, trailing
/// zeros dropped (`0.5`, `4e-8`, `3.183e5`), and `NaN`, `inf`, `-inf` spelled out. The one
/// number format of the grader's messages, the stability tables and the convergence study.
pub fn format_significant(x: f64, digits: usize) -> String {
    let digits = digits.max(1);
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let trim = |s: &str| -> String {
        if s.contains('.') {
            s.trim_end_matches('0').trim_end_matches('.').into()
        } else {
            s.into()
        }
    };
    let magnitude = x.abs().log10().floor() as i64;
    if !(-3..=digits as i64).contains(&magnitude) {
        let s = format!("{x:.*e}", digits - 1);
        let (mantissa, exponent) = s.split_once('e').unwrap_or((&s, "0"));
        return format!("{}e{exponent}", trim(mantissa));
    }
    let decimals = (digits as i64 - 1 - magnitude).max(0) as usize;
    trim(&format!("{x:.decimals$}"))
}

impl fmt::Display for Output {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Output::Nothing => f.write_str("None"),
            Output::Number(x) => f.write_str(&fmt_num(*x)),
            Output::Numbers(v) => {
                let parts: Vec<String> = v.iter().map(|x| fmt_num(*x)).collect();
                write!(f, "({})", parts.join(", "))
            }
            Output::Record(m) => {
                let parts: Vec<String> = m.iter().map(|(k, v)| format!("{k}: {v}")).collect();
                write!(f, "{{{}}}", parts.join(", "))
            }
        }
    }
}

/// A vector for messages: `(0.6, -0.8, 0)`.
pub fn fmt_vec(v: Vec3) -> String {
    format!(
        "({}, {}, {})",
        fmt_num(v.x as f64),
        fmt_num(v.y as f64),
        fmt_num(v.z as f64)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn widening_keeps_the_short_decimal() {
        assert_eq!(widen(0.1), 0.1);
        assert_eq!(widen(0.245_583) as f32, 0.245_583f32);
        assert!(widen(f32::NAN).is_nan());
    }

    #[test]
    fn numbers_format_compactly() {
        assert_eq!(fmt_num(0.040_673_2), "0.04067");
        assert_eq!(fmt_num(0.245_583), "0.2456");
        assert_eq!(fmt_num(1.0), "1");
        assert_eq!(fmt_num(318_309.886), "3.183e5");
        assert_eq!(fmt_num(12_345.6), "12346");
        assert_eq!(fmt_num(1e-5), "1e-5");
        assert_eq!(fmt_num(-2.5e-9), "-2.5e-9");
        assert_eq!(fmt_num(f64::NAN), "NaN");
        assert_eq!(format_significant(0.999_96, 4), "1");
        assert_eq!(format_significant(0.123, 0), "0.1");
    }

    #[test]
    fn outputs_round_trip_through_json() {
        let out = StackReport {
            theta: vec![30.0, 19.47],
            tir_at: None,
            ..Default::default()
        }
        .into_output();
        let json = serde_json::to_string(&out).unwrap();
        let back: Output = serde_json::from_str(&json).unwrap();
        assert_eq!(back, out);
        let v: Output = serde_json::from_str("[0.6, -0.8, 0.0]").unwrap();
        assert_eq!(v, Vec3::new(0.6, -0.8, 0.0).into_output());
    }

    #[test]
    fn non_finite_outputs_cross_the_pipe_unchanged() {
        // A student's NaN must reach the grader as NaN, not as `None` (JSON's null).
        let out = Output::Numbers(vec![f64::NAN, 1.0, f64::INFINITY]);
        let json = serde_json::to_string(&out).unwrap();
        let Output::Numbers(back) = serde_json::from_str::<Output>(&json).unwrap() else {
            panic!("{json} came back as another shape");
        };
        assert!(
            back[0].is_nan() && back[1] == 1.0 && back[2] == f64::INFINITY,
            "{json}"
        );
        let nan: Output =
            serde_json::from_str(&serde_json::to_string(&Output::Number(f64::NAN)).unwrap())
                .unwrap();
        assert!(matches!(nan, Output::Number(x) if x.is_nan()), "{nan:?}");
        assert_eq!(
            serde_json::from_str::<Output>("null").unwrap(),
            Output::Nothing
        );
    }
}
