//! The variance check's grader half: a variance pair's two variances per sample, measured in
//! a worker ([`super::wire::VarianceOutputs`]), judged against the bound the pair declares
//! ([`super::variance_pair`]).

use super::output::fmt_num;
use super::variance_pair::{BALANCE_SLACK, UNIT_VARIANCE_RATIO, VarianceBound};
use super::verdict::{CheckKind, CheckResult};
use super::wire::{VarianceOutputs, Variances};

/// Judges a worker's `outputs` for the pair `name` with bound `bound` and analytic mean
/// `mean`. Every comparison is written so that a NaN variance fails.
pub fn judge(
    name: &str,
    bound: VarianceBound,
    mean: f64,
    outputs: &VarianceOutputs,
) -> CheckResult {
    let mut result = CheckResult::new(name, CheckKind::Estimator);
    result.total = 1;
    match &outputs.outcome {
        Ok(Ok(Variances { first, second })) => match bound {
            VarianceBound::SameInAnyUnits => {
                let ratio = second / first;
                result.summary = format!(
                    "variance per sample {} in the original units, {} with lengths scaled (ratio {})",
                    fmt_num(*first),
                    fmt_num(*second),
                    fmt_num(ratio)
                );
                if !(1.0 / UNIT_VARIANCE_RATIO..=UNIT_VARIANCE_RATIO).contains(&ratio) {
                    // Both variances are the student's own: nothing expected in it.
                    let message = format!(
                        "{name}: the variance changes {}× with the unit of length (a weight that adds a pdf per unit area to one per solid angle?)",
                        fmt_num(ratio)
                    );
                    result.fail_own(message);
                }
            }
            VarianceBound::BalanceBelowOther => {
                let limit = second + mean * mean / 2.0;
                result.summary = format!(
                    "variance per sample {} with balance weights, {} with the other weights; Veach's bound {}",
                    fmt_num(*first),
                    fmt_num(*second),
                    fmt_num(limit)
                );
                if !(0.0..=limit * BALANCE_SLACK).contains(first) {
                    result.fail(
                        format!(
                            "{name}: the balance heuristic's variance {} exceeds the bound {} (the other weighting's variance + μ²/2) {}× — weights that sum to one but are not p_a/(p_a + p_b)?",
                            fmt_num(*first),
                            fmt_num(limit),
                            fmt_num(first / limit)
                        ),
                        format!(
                            "{name}: the balance heuristic's variance {} is above Veach's bound",
                            fmt_num(*first)
                        ),
                    );
                }
            }
        },
        // What went wrong in the student's run.
        Ok(Err(message)) => result.fail_own(message.clone()),
        Err(p) => result.fail_panic(name, p),
    }
    result.finish();
    result.seconds = outputs.seconds;
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outputs(first: f64, second: f64) -> VarianceOutputs {
        VarianceOutputs {
            index: 0,
            outcome: Ok(Ok(Variances { first, second })),
            seconds: 0.0,
        }
    }

    #[test]
    fn the_balance_bound_adds_half_the_squared_mean_and_fails_nan() {
        let judge = |first, second| {
            judge(
                "b",
                VarianceBound::BalanceBelowOther,
                2.0,
                &outputs(first, second),
            )
            .passed
        };
        // Bound 1 + 2²/2 = 3.
        assert!(judge(3.0 * BALANCE_SLACK * 0.99, 1.0));
        assert!(!judge(3.0 * BALANCE_SLACK * 1.01, 1.0));
        assert!(!judge(f64::NAN, 1.0));
        assert!(!judge(1.0, f64::NAN));
    }

    #[test]
    fn units_allow_noise_but_not_a_changed_variance_or_nan() {
        let judge = |first, second| {
            judge(
                "u",
                VarianceBound::SameInAnyUnits,
                1.0,
                &outputs(first, second),
            )
            .passed
        };
        assert!(judge(1.0, 1.1));
        assert!(!judge(1.0, 2.0));
        assert!(!judge(1.0, f64::NAN));
    }
}
