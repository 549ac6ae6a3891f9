//! Every check of one task, run on one implementation: the values, sampling, estimator and
//! stability checks that fit the task, with the task's points split between them.

use super::call::Call;
use super::call::SampleCall;
use super::case::ValueCase;
use super::catalogue::{self, EstimatorSpec};
use super::estimator;
use super::expected::TaskData;
use super::sampling::{self, HemisphereBins, SampleCounts, SamplingFailure, SamplingTarget};
use super::stability;
use super::stats::sidak;
use super::values;
use super::values::ValueOutputs;
use super::verdict::{CheckKind, CheckResult, Detail, TaskStatus, Visibility};
use crate::panics::{self, Panic};
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// The declared false-failure rate of each task's statistical checks together: a correct
/// implementation fails a task's sampling and estimator checks with this probability
/// (Šidák-corrected over the sub-tests).
pub const TASK_ALPHA: f64 = 1e-3;

/// Samples per sampling sub-test.
pub const SAMPLING_SAMPLES: usize = 200_000;

/// Relative weights of the check kinds within a task (split evenly between a kind's
/// sub-tests).
fn kind_weight(kind: CheckKind) -> f64 {
    match kind {
        CheckKind::Values => 2.0,
        CheckKind::Sampling | CheckKind::Estimator | CheckKind::Stability => 1.0,
        CheckKind::Image => 2.0,
    }
}

/// What grading a task needs besides the implementation: its stored data, the hidden cases
/// and the seed of the statistical checks.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TaskInput {
    /// The stored expected data (`None` when the task has no stored file).
    pub data: Option<TaskData>,
    /// Hidden cases with the reference's outputs.
    pub hidden: Vec<ValueCase>,
    /// Seed of the statistical checks.
    pub seed: u64,
}

impl TaskInput {
    /// What a worker gets of this input: the value cases' calls without their expected
    /// outputs (those stay with the grader, hidden ones included), the sampler setups and
    /// the seed.
    pub fn for_worker(&self) -> WorkerInput {
        let calls = |cases: &[ValueCase]| cases.iter().map(|c| c.call.clone()).collect();
        let data = self.data.clone().unwrap_or_default();
        let mut values = Vec::new();
        if !data.values.is_empty() {
            values.push(ValueCalls {
                check: VALUES.into(),
                calls: calls(&data.values),
            });
        }
        if !self.hidden.is_empty() {
            values.push(ValueCalls {
                check: HIDDEN_VALUES.into(),
                calls: calls(&self.hidden),
            });
        }
        let sampling = data
            .sampling
            .iter()
            .map(|case| SamplingSetup {
                call: case.call.clone(),
                bins: case.target.bins,
                may_reject: case.target.rejected > 0.0,
            })
            .collect();
        WorkerInput {
            values,
            sampling,
            seed: self.seed,
        }
    }

    /// The value cases of the check named `check`, with their visibility.
    fn value_cases(&self, check: &str) -> Option<(&[ValueCase], Visibility)> {
        match check {
            VALUES => self
                .data
                .as_ref()
                .map(|d| (d.values.as_slice(), Visibility::Visible)),
            HIDDEN_VALUES => Some((self.hidden.as_slice(), Visibility::Hidden)),
            _ => None,
        }
    }
}

/// The name of the values check on the stored cases.
const VALUES: &str = "values";

/// The name of the values check on the hidden cases.
const HIDDEN_VALUES: &str = "values (hidden cases)";

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

/// A worker's raw output for the grader to judge.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "raw", rename_all = "snake_case")]
pub enum Raw {
    /// The outputs of a values check.
    Values(ValueOutputs),
    /// The samples of a sampling check.
    Samples(SampleOutputs),
    /// The estimates of an estimator check.
    Estimate(EstimateOutputs),
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

/// What grading a task reports as it goes, so that a worker that dies part-way through can
/// say where, and the checks that finished before are not lost.
#[derive(Debug)]
pub enum Progress<'a> {
    /// A check (or one stability case within the stability check) is about to run.
    Starting(&'a str),
    /// A check has finished.
    Finished(&'a CheckResult),
    /// Raw outputs (a values, sampling or estimator check's) are ready for the grader.
    Raw(&'a Raw),
}

/// Where grading reports its [`Progress`].
pub type ProgressSink<'s> = dyn FnMut(Progress<'_>) + 's;

/// Runs every check of `task` on `t` in this process: [`run_task`] then [`judge_task`].
pub fn grade_task<T: Tasks>(t: &T, task: TaskId, input: &TaskInput) -> Vec<CheckResult> {
    let (checks, raw) = run_task(t, task, &input.for_worker(), &mut |_| {});
    judge_task(task, input, checks, &raw)
}

/// Significance of each statistical sub-test of `task`: [`TASK_ALPHA`] Šidák-split over its
/// sampling and estimator checks.
fn statistical_alpha(task: TaskId, sampling: usize, t: &impl Tasks) -> f64 {
    sidak(TASK_ALPHA, sampling + catalogue::estimators(task, t).len())
}

/// The grader's half: judges a worker's raw outputs against `input` (value outputs against
/// the expected outputs, sample counts against the reference density, estimates against
/// the analytic values by the t-test) and puts those checks
/// first, then the worker's other checks, with the kinds' weights.
pub fn judge_task(
    task: TaskId,
    input: &TaskInput,
    checks: Vec<CheckResult>,
    raw: &[Raw],
) -> Vec<CheckResult> {
    let sampling = input
        .data
        .as_ref()
        .map_or(&[][..], |d| d.sampling.as_slice());
    let alpha = || statistical_alpha(task, sampling.len(), crate::implementation::student());
    let estimators = std::cell::OnceCell::new();
    let mut judged: Vec<CheckResult> = raw
        .iter()
        .filter_map(|raw| match raw {
            Raw::Values(outputs) => {
                let (cases, visibility) = input.value_cases(&outputs.check)?;
                Some(values::judge(cases, outputs, visibility))
            }
            Raw::Samples(samples) => {
                let case = sampling.get(samples.index)?;
                Some(sampling_check(&case.call, &case.target, samples, alpha()))
            }
            Raw::Estimate(estimate) => {
                let specs = estimators
                    .get_or_init(|| catalogue::estimators(task, crate::implementation::student()));
                let spec = specs.get(estimate.index)?;
                Some(estimator_check(spec, estimate, alpha()))
            }
        })
        .collect();
    judged.extend(checks);
    spread_weights(&mut judged);
    judged
}

/// The worker's half: evaluates the value calls of `input` (outputs only, judged by the
/// grader) and runs the sampling, estimator and stability checks of `task` on `t`, telling
/// `progress` before each check (and each stability case) runs and after each finishes.
pub fn run_task<T: Tasks>(
    t: &T,
    task: TaskId,
    input: &WorkerInput,
    progress: &mut ProgressSink<'_>,
) -> (Vec<CheckResult>, Vec<Raw>) {
    let mut raw = Vec::new();
    for calls in &input.values {
        progress(Progress::Starting(&calls.check));
        let outputs = Raw::Values(values::evaluate(&calls.check, &calls.calls, t));
        progress(Progress::Raw(&outputs));
        raw.push(outputs);
    }
    for (index, setup) in input.sampling.iter().enumerate() {
        let name = format!("sampling: {}", setup.call);
        raw.push(measure_raw(&name, progress, || {
            let mut sampler = Sampler::new(input.seed, 100 + index as u64);
            let outcome = panics::catch(|| {
                sampling::draw(
                    setup.bins,
                    setup.may_reject,
                    SAMPLING_SAMPLES,
                    &mut sampler,
                    |u| setup.call.sample(t, u),
                )
            });
            |seconds| {
                Raw::Samples(SampleOutputs {
                    index,
                    outcome,
                    seconds,
                })
            }
        }));
    }
    // The reference's estimators run beside the student's, for the time comparison.
    let mut reference: Vec<Option<EstimatorSpec<'_>>> = crate::implementation::try_reference()
        .map(|r| {
            catalogue::estimators(task, r)
                .into_iter()
                .map(Some)
                .collect()
        })
        .unwrap_or_default();
    let estimators = catalogue::estimators(task, t);
    reference.resize_with(estimators.len(), || None);
    for (index, (mut spec, reference)) in estimators.into_iter().zip(reference).enumerate() {
        let name = format!("estimator: {}", spec.name);
        raw.push(measure_raw(&name, progress, || {
            let mut reference = reference.map(|r| r.estimate);
            let outcome = panics::catch(|| {
                estimator::measure(
                    spec.analytic,
                    spec.samples,
                    (input.seed, 200 + index as u64),
                    spec.estimate.as_mut(),
                    reference.as_deref_mut(),
                )
            });
            |seconds| {
                Raw::Estimate(EstimateOutputs {
                    index,
                    outcome,
                    seconds,
                })
            }
        }));
    }
    let mut checks = Vec::new();
    let mut record = |name: &str, check: &mut dyn FnMut(&mut ProgressSink<'_>) -> CheckResult| {
        progress(Progress::Starting(name));
        let result = check(progress);
        progress(Progress::Finished(&result));
        checks.push(result);
    };
    for (i, (a, b)) in catalogue::unit_pairs(task, t).into_iter().enumerate() {
        let name = format!("estimator: variance independent of units ({})", b.name);
        let mut pair = Some((a, b));
        record(&name, &mut |_| {
            let (a, b) = pair.take().expect("each pair runs once");
            units_check(a, b, (input.seed, 300 + i as u64))
        });
    }
    let cases = crate::stability::cases_for::<T>(task);
    if !cases.is_empty() {
        record("stability", &mut |progress| {
            stability::run(t, &cases, &mut |case| {
                progress(Progress::Starting(&format!("stability: {case}")))
            })
        });
    }
    (checks, raw)
}

/// Runs `measure` as the step `name`, times it, and reports the raw output it makes (from
/// the seconds taken) to `progress`.
fn measure_raw<F: FnOnce(f64) -> Raw>(
    name: &str,
    progress: &mut ProgressSink<'_>,
    measure: impl FnOnce() -> F,
) -> Raw {
    progress(Progress::Starting(name));
    let start = Instant::now();
    let make = measure();
    let raw = make(start.elapsed().as_secs_f64());
    progress(Progress::Raw(&raw));
    raw
}

/// Gives each kind its weight, split between the kind's checks.
fn spread_weights(checks: &mut [CheckResult]) {
    for kind in [
        CheckKind::Values,
        CheckKind::Sampling,
        CheckKind::Estimator,
        CheckKind::Image,
        CheckKind::Stability,
    ] {
        let count = checks.iter().filter(|c| c.kind == kind).count();
        for c in checks.iter_mut().filter(|c| c.kind == kind) {
            c.weight = kind_weight(kind) / count as f64;
        }
    }
}

/// The sampling check of a worker's `samples` against `target`.
fn sampling_check(
    call: &SampleCall,
    target: &SamplingTarget,
    samples: &SampleOutputs,
    alpha: f64,
) -> CheckResult {
    let mut result = CheckResult::new(format!("sampling: {call}"), CheckKind::Sampling);
    result.total = 1;
    result.alpha = alpha;
    let outcome = samples.outcome.clone().map(|drawn| {
        drawn
            .map_err(SamplingFailure::Domain)
            .and_then(|counts| sampling::compare(target, &counts, SAMPLING_SAMPLES, alpha))
    });
    match outcome {
        Ok(Ok(histogram)) => {
            result.summary = format!(
                "{} samples match the reference density (χ² = {:.1}, {} dof, p = {:.3})",
                SAMPLING_SAMPLES, histogram.chi2, histogram.dof, histogram.p_value
            );
            result.p_values.push(histogram.p_value);
            result.detail = Some(Detail::Sampling(histogram));
        }
        Ok(Err(SamplingFailure::Domain(message))) => {
            result.summary = "a sample is not a valid direction".into();
            result.fail(format!("{call}, {message}"));
        }
        Ok(Err(SamplingFailure::Distribution(histogram))) => {
            result.summary = format!(
                "the samples do not follow the reference density (χ² = {:.1}, {} dof, p = {:.2e} < α = {:.1e})",
                histogram.chi2, histogram.dof, histogram.p_value, alpha
            );
            result.fail(format!("{call}: {}", histogram.worst_cell()));
            result.p_values.push(histogram.p_value);
            result.detail = Some(Detail::Sampling(*histogram));
        }
        Err(p) => {
            result.summary = "the sampler panicked".into();
            result.fail_panic(&call.to_string(), &p);
        }
    }
    result.finish();
    result.seconds = samples.seconds;
    result
}

/// The estimator check of a worker's `estimate` of `spec` (its name, analytic value and
/// sample count are the grader's).
fn estimator_check(
    spec: &EstimatorSpec<'_>,
    estimate: &EstimateOutputs,
    alpha: f64,
) -> CheckResult {
    let mut result = CheckResult::new(format!("estimator: {}", spec.name), CheckKind::Estimator);
    result.total = 1;
    result.alpha = alpha;
    let outcome = estimate
        .outcome
        .clone()
        .map(|measured| estimator::judge(&spec.name, spec.analytic, spec.samples, alpha, measured));
    match outcome {
        Ok(Ok(stats)) => {
            result.summary = stats.describe();
            result.p_values.push(stats.p_value);
            result.detail = Some(Detail::Estimator(stats));
        }
        Ok(Err(failure)) => {
            result.summary = "the estimator is biased or not finite".into();
            result.fail(failure.message);
            if let Some(stats) = failure.stats {
                result.p_values.push(stats.p_value);
                result.detail = Some(Detail::Estimator(stats));
            }
        }
        Err(p) => {
            result.summary = "the estimator panicked".into();
            result.fail_panic(&spec.name, &p);
        }
    }
    result.finish();
    result.seconds = estimate.seconds;
    result
}

/// Largest accepted ratio between the variances of one estimator in two units of length.
/// Sampling noise of the two variances stays within a few percent at the sample counts used;
/// weights that mix measures change the variance many times over.
pub const UNIT_VARIANCE_RATIO: f64 = 1.5;

fn units_check(
    mut a: EstimatorSpec<'_>,
    mut b: EstimatorSpec<'_>,
    seed: (u64, u64),
) -> CheckResult {
    let start = Instant::now();
    let mut result = CheckResult::new(
        format!("estimator: variance independent of units ({})", b.name),
        CheckKind::Estimator,
    );
    result.total = 1;
    let outcome = panics::catch(|| {
        estimator::variances(
            a.samples,
            seed,
            a.estimate.as_mut(),
            b.estimate.as_mut(),
            a.analytic,
        )
    });
    match outcome {
        Ok(Ok((va, vb))) => {
            let ratio = vb / va;
            result.summary = format!(
                "variance per sample {} in the original units, {} with lengths scaled (ratio {})",
                super::output::fmt_num(va),
                super::output::fmt_num(vb),
                super::output::fmt_num(ratio)
            );
            if !(1.0 / UNIT_VARIANCE_RATIO..=UNIT_VARIANCE_RATIO).contains(&ratio) {
                result.fail(format!(
                    "{}: the variance changes {}× with the unit of length (a weight that adds a pdf per unit area to one per solid angle?)",
                    b.name,
                    super::output::fmt_num(ratio)
                ));
            }
        }
        Ok(Err(message)) => result.fail(message),
        Err(p) => result.fail_panic(&b.name, &p),
    }
    result.finish();
    result.seconds = start.elapsed().as_secs_f64();
    result
}

/// The status and points of a task from its checks.
///
/// A task whose cases all stopped at its own stub is not attempted. One whose failures all
/// stopped at other tasks' stubs (possible only without the reference, where the student's
/// own dependencies run) needs those tasks first. Otherwise the points are split by check
/// weight.
pub fn score(task: TaskId, checks: &[CheckResult]) -> (TaskStatus, f64) {
    let points = task.info().points as f64;
    if checks.is_empty() {
        return (TaskStatus::NoChecks, 0.0);
    }
    let failing = || checks.iter().filter(|c| !c.passed);
    let stubbed: Vec<&str> = failing()
        .flat_map(|c| c.todo_in.iter().map(String::as_str))
        .collect();
    let only_stubs = failing().all(|c| c.todo_failed == c.failed);
    if checks.iter().all(|c| c.not_attempted)
        && (stubbed.is_empty() || stubbed.contains(&task.name()))
    {
        return (TaskStatus::NotAttempted, 0.0);
    }
    if let Some(other) = stubbed.iter().find(|t| **t != task.name())
        && only_stubs
    {
        let task = other.to_string();
        return (TaskStatus::NeedsTask { task }, 0.0);
    }
    let total = super::verdict::total(checks.iter().map(|c| c.weight));
    let passed = super::verdict::total(checks.iter().filter(|c| c.passed).map(|c| c.weight));
    if checks.iter().all(|c| c.passed) {
        (TaskStatus::Passed, points)
    } else {
        (TaskStatus::Failed, points * passed / total)
    }
}
