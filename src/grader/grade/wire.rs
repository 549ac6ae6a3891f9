//! What crosses the sandbox: a worker's input (the calls and setups of a task's checks,
//! never an expected value or a reference density) and its raw outputs (measurements only,
//! never a verdict), written and read as JSON lines by [`super::worker`] and
//! [`super::isolation`].

use super::call::{Call, SampleCall};
use super::estimator;
use super::image_check::ImageStats;
use super::output::Output;
use super::sampling::{HemisphereBins, SampleCounts};
use crate::panics::Panic;
use crate::stability::Value;
use serde::{Deserialize, Serialize};

/// The calls of one values check, without their expected outputs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ValueCalls {
    /// The check's name.
    pub check: String,
    /// The calls, in order.
    pub calls: Vec<Call>,
}

/// A sampler to draw from, and the cells to bin its directions in: no reference density.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SamplingSetup {
    /// Which sampler, with which parameters.
    pub call: SampleCall,
    /// The cells.
    pub bins: HemisphereBins,
    /// True when the sampler may return no direction.
    pub may_reject: bool,
}

/// What a worker needs to run a task's checks: no expected value, no reference density.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct WorkerInput {
    /// The calls of each values check.
    pub values: Vec<ValueCalls>,
    /// The samplers of the sampling checks.
    pub sampling: Vec<SamplingSetup>,
    /// Seed of the statistical checks.
    pub seed: u64,
    /// Run the value calls and nothing else (the worker of the hidden cases).
    #[serde(default)]
    pub values_only: bool,
    /// Run the estimators and nothing else (the reference's run beside the student's, for
    /// the time comparison, in a worker of its own).
    #[serde(default)]
    pub estimators_only: bool,
}

/// What one sampling check's sampler produced in a worker: its binned directions, the
/// first invalid sample, or the panic that stopped it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SampleOutputs {
    /// Which of the task's sampling checks, in order.
    pub index: usize,
    /// The counts, or the invalid sample described.
    pub outcome: Result<Result<SampleCounts, String>, Panic>,
    /// Seconds the sampling took.
    pub seconds: f64,
}

/// A worker's raw output for the grader to judge: measurements only, never a verdict.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "raw", rename_all = "snake_case")]
pub enum Raw {
    /// The outputs of a values check.
    Values(ValueOutputs),
    /// The samples of a sampling check.
    Samples(SampleOutputs),
    /// The estimates of an estimator check.
    Estimate(EstimateOutputs),
    /// The variances of the two estimators of a variance pair.
    Variances(VarianceOutputs),
    /// What the task returned on one stability case.
    Stability(StabilityOutput),
    /// A render of a graded scene.
    Image(ImageOutputs),
}

/// What the task returned on one stability case, or the panic that stopped it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct StabilityOutput {
    /// The case's name (`smith_g1/alpha_zero`).
    pub case: String,
    /// The value returned, or the panic.
    pub outcome: Result<Value, Panic>,
    /// Seconds the call took.
    pub seconds: f64,
}

/// A graded scene's render made in a worker: its per-pixel mean and variance, or why there
/// is none.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImageOutputs {
    /// The scene.
    pub scene: String,
    /// The render, the scene's load error, or the panic that stopped the render.
    pub outcome: Result<Result<Rendered, String>, Panic>,
    /// Seconds the render took.
    pub seconds: f64,
}

/// A render's statistics and the samples the renderer had to drop.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Rendered {
    /// Mean and variance of the mean per pixel-channel.
    pub stats: ImageStats,
    /// Samples that were NaN, infinite or negative and were dropped.
    pub rejected: u64,
}

/// What one estimator check measured in a worker, or why it could not.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EstimateOutputs {
    /// Which of the task's estimators, in order.
    pub index: usize,
    /// The measured runs, a refused or non-finite estimate, or the panic that stopped it.
    pub outcome: Result<Result<estimator::Measured, String>, Panic>,
    /// Seconds the estimates took.
    pub seconds: f64,
}

/// What one call returned: its output, or the panic that stopped it.
pub type Evaluated = Result<Output, Panic>;

/// The outputs of one values check, as a worker sends them.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ValueOutputs {
    /// The check's name (`values`, `values (hidden cases)`).
    pub check: String,
    /// One per call, in order.
    pub outputs: Vec<Evaluated>,
    /// Seconds the calls took.
    pub seconds: f64,
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
    /// Of [`super::variance_pair::VariancePair::first`].
    #[serde(with = "super::lenient_f64")]
    pub first: f64,
    /// Of [`super::variance_pair::VariancePair::second`].
    #[serde(with = "super::lenient_f64")]
    pub second: f64,
}
