//! The stability check: a task's functions on stiff and extreme inputs (grazing angles,
//! α → 0, equal indices, exactly the critical angle, …) must return finite values in range
//! with the right limit.
//!
//! The cases are the catalogue of `pbrlab stability` ([`crate::stability::cases_for`]). The
//! worker calls each case and sends back what the task returned
//! ([`super::wire::StabilityOutput`]); the grader judges those values here, so a case
//! whose value never came back (the worker hung or crashed on it, or left it out) fails.

use super::verdict::{CheckKind, CheckResult};
use super::wire::Raw;
use crate::stability::outcome::judge_output;
use crate::stability::{Case, Verdict};

/// Judges the worker's stability outputs in `raw` against `cases`, into one check, with
/// whether every case's output was there.
pub fn judge<T>(cases: &[Case<T>], raw: &[Raw]) -> (CheckResult, bool) {
    let mut complete = true;
    let mut result = CheckResult::new("stability", CheckKind::Stability);
    result.total = cases.len();
    for case in cases {
        let context = format!("{} [{}]", case.input, case.name);
        let output = raw.iter().find_map(|r| match r {
            Raw::Stability(output) if output.case == case.name => Some(output),
            _ => None,
        });
        let Some(output) = output else {
            complete = false;
            let message = format!(
                "{context}: no value came back from the worker (it stopped before this case)"
            );
            result.fail_own(message);
            continue;
        };
        result.seconds += output.seconds;
        match &output.outcome {
            Ok(_) => {
                // Judged as `pbrlab stability` judges it: one verdict for both.
                let judged = judge_output(case, output);
                let (value, verdict) = (judged.value_text, judged.verdict);
                if verdict != Verdict::Pass {
                    result.fail(
                        format!(
                            "{context}: got {value} ({verdict}), expected {} ({})",
                            case.expected_text(),
                            case.guard
                        ),
                        format!("{context}: got {value} ({verdict})"),
                    );
                }
            }
            Err(p) => result.fail_panic(&context, p),
        }
    }
    result.finish();
    result.summary = format!(
        "{}/{} extreme inputs handled",
        result.total - result.failed,
        result.total
    );
    (result, complete)
}
