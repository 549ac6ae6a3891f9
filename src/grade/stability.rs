//! The stability check: a task's functions on stiff and extreme inputs (grazing angles,
//! α → 0, equal indices, exactly the critical angle, …) must return finite values in range
//! with the right limit.
//!
//! The cases are the catalogue of `pbrlab stability` ([`crate::stability::cases_for`]);
//! here they run inside the grader's worker, so a case that hangs or crashes is covered by
//! the worker's time limit instead of a thread per case.

use super::verdict::{CheckKind, CheckResult};
use crate::panics;
use crate::stability::{Case, Verdict};
use crate::worksheet::Tasks;
use std::time::Instant;

/// Runs every case on `t`, each isolated from panics, into one check; `starting` hears each
/// case's name before it runs.
pub fn run<T: Tasks>(t: &T, cases: &[Case<T>], starting: &mut dyn FnMut(&str)) -> CheckResult {
    let start = Instant::now();
    let mut result = CheckResult::new("stability", CheckKind::Stability);
    result.total = cases.len();
    for case in cases {
        starting(case.name);
        let context = format!("{} [{}]", case.input, case.name);
        match panics::catch(|| (case.eval)(t)) {
            Ok(value) => {
                let verdict = case.judge(&value);
                if verdict != Verdict::Pass {
                    result.fail(format!(
                        "{context}: got {value} ({verdict}), expected {} ({})",
                        case.expected_text(),
                        case.guard
                    ));
                }
            }
            Err(p) => result.fail_panic(&context, &p),
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
