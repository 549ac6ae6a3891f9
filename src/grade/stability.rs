//! The stability check: task functions on stiff and extreme inputs (grazing angles, α → 0,
//! equal indices, exactly the critical angle, …) must return finite values in range with the
//! right limit.
//!
//! The check takes any list of [`StabilityCase`]s; the catalogue of cases per task lives
//! with `pbrlab stability` (`crate::stability`), which builds them for any implementation.

use super::output::Output;
use super::panics;
use super::verdict::{CheckKind, CheckResult};
use std::time::Instant;

/// What a stability case requires of its output.
pub struct Expect {
    /// In words, for messages: `finite and in [0, 1]`, `≈ 0.00857`.
    pub description: String,
    holds: Box<dyn Fn(&Output) -> bool + Send + Sync>,
}

impl Expect {
    /// A requirement described by `description` and decided by `holds`.
    pub fn new(
        description: impl Into<String>,
        holds: impl Fn(&Output) -> bool + Send + Sync + 'static,
    ) -> Self {
        Self {
            description: description.into(),
            holds: Box::new(holds),
        }
    }

    /// Every number finite and within `[lo, hi]`.
    pub fn in_range(lo: f64, hi: f64) -> Self {
        Self::new(
            format!(
                "finite and in [{}, {}]",
                super::output::fmt_num(lo),
                super::output::fmt_num(hi)
            ),
            move |o| {
                numbers(o).is_some_and(|v| {
                    !v.is_empty() && v.iter().all(|x| x.is_finite() && (lo..=hi).contains(x))
                })
            },
        )
    }

    /// Every number within `tol` (absolute) of `value`.
    pub fn near(value: f64, tol: f64) -> Self {
        Self::new(
            format!(
                "≈ {} (±{})",
                super::output::fmt_num(value),
                super::output::fmt_num(tol)
            ),
            move |o| {
                numbers(o)
                    .is_some_and(|v| !v.is_empty() && v.iter().all(|x| (x - value).abs() <= tol))
            },
        )
    }

    /// `None`.
    pub fn nothing() -> Self {
        Self::new("None", |o| *o == Output::Nothing)
    }

    /// True when `output` meets the requirement.
    pub fn holds(&self, output: &Output) -> bool {
        (self.holds)(output)
    }
}

/// The numbers of a scalar or vector output.
fn numbers(o: &Output) -> Option<Vec<f64>> {
    match o {
        Output::Number(x) => Some(vec![*x]),
        Output::Numbers(v) => Some(v.clone()),
        _ => None,
    }
}

/// One extreme input of a task function and what it must return.
pub struct StabilityCase<'a> {
    /// The call with its input, as shown in messages: `smith_g1(w=(0.87, 0, -0.5), α=0.5)`.
    pub input: String,
    /// Why this input is hard: `back-facing direction`.
    pub why: String,
    /// Calls the function.
    pub eval: Box<dyn Fn() -> Output + 'a>,
    /// The requirement.
    pub expect: Expect,
}

/// Runs every case, each isolated from panics, into one check named `name`.
pub fn run(name: &str, cases: &[StabilityCase<'_>]) -> CheckResult {
    let start = Instant::now();
    let mut result = CheckResult::new(name, CheckKind::Stability);
    result.total = cases.len();
    for case in cases {
        match panics::catch(|| (case.eval)()) {
            Ok(out) if case.expect.holds(&out) => {}
            Ok(out) => {
                result.fail(format!(
                    "{}: got {out}, expected {} ({})",
                    case.input, case.expect.description, case.why
                ));
            }
            Err(p) => result.fail_panic(&format!("{} ({})", case.input, case.why), &p),
        }
    }
    result.finish();
    result.summary = format!(
        "{}/{} extreme inputs handled",
        result.total - result.failed,
        result.total
    );
    result.seconds = start.elapsed().as_secs_f64();
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::output::IntoOutput;

    #[test]
    fn cases_report_input_value_and_reason() {
        let naive_g1 = |c: f32| 2.0 * c / (c + (0.25 + 0.75 * c * c).sqrt());
        let cases = [
            StabilityCase {
                input: "g1(cos=-0.5)".into(),
                why: "back-facing direction".into(),
                eval: Box::new(move || naive_g1(-0.5).into_output()),
                expect: Expect::near(0.0, 1e-6),
            },
            StabilityCase {
                input: "g1(cos=1)".into(),
                why: "normal incidence".into(),
                eval: Box::new(move || naive_g1(1.0).into_output()),
                expect: Expect::in_range(0.0, 1.0),
            },
            StabilityCase {
                input: "boom".into(),
                why: "panics".into(),
                eval: Box::new(|| panic!("boom")),
                expect: Expect::nothing(),
            },
        ];
        let r = run("stability", &cases);
        assert!(!r.passed);
        assert_eq!(r.failed, 2);
        assert!(
            r.failures[0].contains("g1(cos=-0.5): got -6.194")
                && r.failures[0].contains("back-facing"),
            "{:?}",
            r.failures
        );
        assert!(r.failures[1].contains("panicked"), "{:?}", r.failures);
        assert!(!r.not_attempted);
    }

    #[test]
    fn nan_is_never_in_range() {
        assert!(!Expect::in_range(0.0, 1.0).holds(&f32::NAN.into_output()));
        assert!(Expect::in_range(0.0, 1.0).holds(&glam::Vec3::splat(0.5).into_output()));
        assert!(!Expect::near(0.0, 1.0).holds(&Output::Nothing));
    }
}
