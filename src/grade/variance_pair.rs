//! Variance comparisons: two estimators of one quantity, run on the same random numbers,
//! whose variances per sample must relate in a known way. They catch what a test of the
//! mean cannot: weights that still sum to one, so that every estimate stays unbiased, but
//! mix measures or are not the heuristic they claim to be.

use super::catalogue::EstimatorSpec;
use super::output::fmt_num;
use super::verdict::{CheckKind, CheckResult};
use crate::panics::Panic;
use serde::{Deserialize, Serialize};

/// Largest accepted ratio between the variances of one estimator in two units of length.
/// Sampling noise of the two variances stays within a few percent at the sample counts used;
/// weights that mix measures change the variance many times over.
pub const UNIT_VARIANCE_RATIO: f64 = 1.5;

/// Slack on Veach's bound for the balance heuristic, for the sampling noise of the two
/// variances (a few percent at the sample counts used; the reference's balance variance is
/// about 0.4 of the bound in the graded scene).
pub const BALANCE_SLACK: f64 = 1.2;

/// How the variances of a pair must relate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarianceBound {
    /// The same estimator in the same scene with every length scaled: the variances agree
    /// within [`UNIT_VARIANCE_RATIO`].
    SameInAnyUnits,
    /// `first` weights one light sample and one BSDF sample by the balance heuristic,
    /// `second` weights the same two samples another unbiased way. Veach's theorem 9.2 (one
    /// sample per strategy): `V[first] ≤ V[second] + μ²/2`, with `μ` the analytic mean.
    BalanceBelowOther,
}

/// Two estimators of one quantity and the bound between their variances.
pub struct VariancePair<'a> {
    /// The estimator the bound is about.
    pub first: EstimatorSpec<'a>,
    /// The one it is compared with.
    pub second: EstimatorSpec<'a>,
    /// How their variances must relate.
    pub bound: VarianceBound,
}

impl VariancePair<'_> {
    /// The check's name.
    pub fn name(&self) -> String {
        match self.bound {
            VarianceBound::SameInAnyUnits => format!(
                "estimator: variance independent of units ({})",
                self.second.name
            ),
            VarianceBound::BalanceBelowOther => format!(
                "estimator: variance of the balance heuristic within Veach's bound ({} against {})",
                self.first.name, self.second.name
            ),
        }
    }
}

/// What one pair measured in a worker: the two variances per sample, or why there are
/// none.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct VarianceOutputs {
    /// Which of the task's pairs, in order.
    pub index: usize,
    /// The two variances, a refused or non-finite estimate, or the panic that stopped it.
    pub outcome: Result<Result<Variances, String>, Panic>,
    /// Seconds the estimates took.
    pub seconds: f64,
}

/// The variance per sample of the two estimators of a pair.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct Variances {
    /// Of [`VariancePair::first`].
    #[serde(with = "super::lenient_f64")]
    pub first: f64,
    /// Of [`VariancePair::second`].
    #[serde(with = "super::lenient_f64")]
    pub second: f64,
}

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
