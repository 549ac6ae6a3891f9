//! Variance comparisons: two estimators of one quantity, run on the same random numbers,
//! whose variances per sample must relate in a known way. They catch what a test of the
//! mean cannot: weights that still sum to one, so that every estimate stays unbiased, but
//! mix measures or are not the heuristic they claim to be.

use super::estimator::EstimatorSpec;

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
