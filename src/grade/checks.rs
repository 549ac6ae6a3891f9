//! Every check of one task, run on one implementation: the values, sampling, estimator and
//! stability checks that fit the task, with the task's points split between them.

use super::call::Call;
use super::call::SampleCall;
use super::case::ValueCase;
use super::catalogue::{self, EstimatorSpec};
use super::estimator;
use super::expected::TaskData;
use super::image_check::ImageStats;
use super::output::fmt_num;
use super::sampling::{self, HemisphereBins, SampleCounts, SamplingFailure, SamplingTarget};
use super::stability;
use super::stats::sidak;
use super::values;
use super::values::ValueOutputs;
use super::variance_pair::{self, VarianceOutputs, Variances};
use super::verdict::{CheckKind, CheckResult, Detail, TaskStatus, Visibility};
use crate::panics::{self, Panic};
use crate::sampling::Sampler;
use crate::stability::Value;
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
    /// What the workers get of this input, one process each, none of it expected values
    /// (those stay with the grader): first the visible checks (the stored value cases'
    /// calls, the sampler setups and the seed; estimator and stability checks run there
    /// too), then, when there are hidden cases, their calls alone in a worker of their own.
    /// So no process that saw a hidden input prints, crashes or returns anything a student
    /// sees outside the hidden checks.
    pub fn for_workers(&self) -> Vec<WorkerInput> {
        let calls = |cases: &[ValueCase]| cases.iter().map(|c| c.call.clone()).collect();
        let data = self.data.clone().unwrap_or_default();
        let mut values = Vec::new();
        if !data.values.is_empty() {
            values.push(ValueCalls {
                check: VALUES.into(),
                calls: calls(&data.values),
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
        let mut inputs = vec![WorkerInput {
            values,
            sampling,
            seed: self.seed,
            values_only: false,
            estimators_only: false,
        }];
        if !self.hidden.is_empty() {
            inputs.push(WorkerInput {
                values: vec![ValueCalls {
                    check: HIDDEN_VALUES.into(),
                    calls: calls(&self.hidden),
                }],
                sampling: Vec::new(),
                seed: self.seed,
                values_only: true,
                estimators_only: false,
            });
        }
        inputs
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

/// The name of the values check on the stored (public) cases.
pub const VALUES: &str = "values";

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

/// What grading a task reports as it goes, so that a worker that dies part-way through can
/// say where, and the raw outputs ready before are not lost.
#[derive(Debug)]
pub enum Progress<'a> {
    /// A check (or one stability case within the stability check) is about to run.
    Starting(&'a str),
    /// Raw outputs are ready for the grader.
    Raw(&'a Raw),
}

/// Where grading reports its [`Progress`].
pub type ProgressSink<'s> = dyn FnMut(Progress<'_>) + 's;

/// Runs every check of `task` on `t` in this process: [`run_task`] then [`judge_task`].
pub fn grade_task<T: Tasks>(t: &T, task: TaskId, input: &TaskInput) -> Vec<CheckResult> {
    let raw: Vec<Raw> = input
        .for_workers()
        .iter()
        .flat_map(|worker| run_task(t, task, worker, &mut |_| {}))
        .collect();
    judge_task(task, input, &raw)
}

/// Significance of each statistical sub-test of `task`: [`TASK_ALPHA`] Šidák-split over its
/// sampling and estimator checks.
pub fn statistical_alpha(task: TaskId, sampling: usize, t: &impl Tasks) -> f64 {
    sidak(TASK_ALPHA, sampling + catalogue::estimators(task, t).len())
}

/// The grader's half: every check `task` has, each judged from the worker's raw output for
/// it: value outputs against the expected outputs, sample counts against the reference
/// density, estimates against the analytic values by the t-test, variance pairs against
/// their bounds, stability values against their cases. The list of checks is the
/// grader's own (from `input` and the catalogues), so a check whose output never came back
/// fails instead of dropping out of the score.
pub fn judge_task(task: TaskId, input: &TaskInput, raw: &[Raw]) -> Vec<CheckResult> {
    let mut judged: Vec<CheckResult> = judge_all(task, input, raw)
        .into_iter()
        .map(|(check, _)| check)
        .collect();
    spread_weights(&mut judged);
    judged
}

/// The checks of `task` whose every raw output is in `raw`, judged: what a worker that
/// crashed part-way through had finished.
pub fn judge_finished(task: TaskId, input: &TaskInput, raw: &[Raw]) -> Vec<CheckResult> {
    let mut judged: Vec<CheckResult> = judge_all(task, input, raw)
        .into_iter()
        .filter_map(|(check, complete)| complete.then_some(check))
        .collect();
    spread_weights(&mut judged);
    judged
}

/// Every check of `task` judged from `raw`, each with whether all of its outputs were there.
fn judge_all(task: TaskId, input: &TaskInput, raw: &[Raw]) -> Vec<(CheckResult, bool)> {
    let t = crate::implementation::student();
    let sampling = input
        .data
        .as_ref()
        .map_or(&[][..], |d| d.sampling.as_slice());
    let alpha = statistical_alpha(task, sampling.len(), t);
    let mut judged: Vec<(CheckResult, bool)> = Vec::new();
    for check in [VALUES, HIDDEN_VALUES] {
        let Some((cases, visibility)) = input.value_cases(check).filter(|(c, _)| !c.is_empty())
        else {
            continue;
        };
        judged.push(from_raw(raw, check, CheckKind::Values, |r| match r {
            Raw::Values(outputs) if outputs.check == check => {
                Some(values::judge(cases, outputs, visibility))
            }
            _ => None,
        }));
    }
    for (index, case) in sampling.iter().enumerate() {
        let name = format!("sampling: {}", case.call);
        judged.push(from_raw(raw, &name, CheckKind::Sampling, |r| match r {
            Raw::Samples(s) if s.index == index => {
                Some(sampling_check(&case.call, &case.target, s, alpha))
            }
            _ => None,
        }));
    }
    for (index, spec) in catalogue::estimators(task, t).iter().enumerate() {
        let name = format!("estimator: {}", spec.name);
        judged.push(from_raw(raw, &name, CheckKind::Estimator, |r| match r {
            Raw::Estimate(e) if e.index == index => Some(estimator_check(spec, e, alpha)),
            _ => None,
        }));
    }
    for (index, pair) in catalogue::variance_pairs(task, t).iter().enumerate() {
        let name = pair.name();
        judged.push(from_raw(raw, &name, CheckKind::Estimator, |r| match r {
            Raw::Variances(v) if v.index == index => Some(variance_pair::judge(
                &name,
                pair.bound,
                pair.first.analytic,
                v,
            )),
            _ => None,
        }));
    }
    let cases = crate::stability::cases_for::<crate::worksheet::TaskFns>(task);
    if !cases.is_empty() {
        judged.push(stability::judge(&cases, raw));
    }
    judged
}

/// The check `judge` makes of the first raw output it accepts, complete; or, when there is
/// none, the check `name` failed as [`missing`], incomplete.
fn from_raw(
    raw: &[Raw],
    name: &str,
    kind: CheckKind,
    judge: impl FnMut(&Raw) -> Option<CheckResult>,
) -> (CheckResult, bool) {
    raw.iter()
        .find_map(judge)
        .map_or_else(|| (missing(name, kind), false), |check| (check, true))
}

/// A check whose raw output never came back (the worker stopped first, or did not send it):
/// failed.
fn missing(name: &str, kind: CheckKind) -> CheckResult {
    let mut result = CheckResult::new(name, kind);
    result.total = 1;
    let message =
        format!("{name}: no output came back from the worker (it stopped before this check)");
    result.fail_own(message);
    result.finish();
    result
}

/// The worker's half: evaluates the value calls of `input` and runs the samplers,
/// estimators, variance pairs and stability cases of `task` on `t`, returning their raw
/// outputs only (the grader judges them), and telling `progress` before each step runs and
/// when its output is ready.
pub fn run_task<T: Tasks>(
    t: &T,
    task: TaskId,
    input: &WorkerInput,
    progress: &mut ProgressSink<'_>,
) -> Vec<Raw> {
    let mut raw = Vec::new();
    if input.estimators_only {
        run_estimators(t, task, input, progress, &mut raw);
        return raw;
    }
    for calls in &input.values {
        progress(Progress::Starting(&calls.check));
        let outputs = Raw::Values(values::evaluate(&calls.check, &calls.calls, t));
        progress(Progress::Raw(&outputs));
        raw.push(outputs);
    }
    if input.values_only {
        return raw;
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
    run_estimators(t, task, input, progress, &mut raw);
    for (index, mut pair) in catalogue::variance_pairs(task, t).into_iter().enumerate() {
        raw.push(measure_raw(&pair.name(), progress, || {
            let outcome = panics::catch(|| {
                estimator::variances(
                    pair.first.samples,
                    (input.seed, 300 + index as u64),
                    pair.first.estimate.as_mut(),
                    pair.second.estimate.as_mut(),
                    pair.first.analytic,
                )
                .map(|(first, second)| Variances { first, second })
            });
            |seconds| {
                Raw::Variances(VarianceOutputs {
                    index,
                    outcome,
                    seconds,
                })
            }
        }));
    }
    for case in crate::stability::cases_for::<T>(task) {
        raw.push(measure_raw(
            &format!("stability: {}", case.name),
            progress,
            || {
                let outcome = panics::catch(|| (case.eval)(t));
                |seconds| {
                    Raw::Stability(StabilityOutput {
                        case: case.name.into(),
                        outcome,
                        seconds,
                    })
                }
            },
        ));
    }
    raw
}

/// Runs each of `task`'s estimators with `t`, adding their outputs to `raw`.
fn run_estimators<T: Tasks>(
    t: &T,
    task: TaskId,
    input: &WorkerInput,
    progress: &mut ProgressSink<'_>,
    raw: &mut Vec<Raw>,
) {
    for (index, mut spec) in catalogue::estimators(task, t).into_iter().enumerate() {
        let name = format!("estimator: {}", spec.name);
        raw.push(measure_raw(&name, progress, || {
            let outcome = panics::catch(|| {
                estimator::measure(
                    spec.analytic,
                    spec.samples,
                    (input.seed, 200 + index as u64),
                    spec.estimate.as_mut(),
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
            // The sample the student's sampler returned, and what is wrong with it.
            let message = format!("{call}, {message}");
            result.fail_own(message);
        }
        Ok(Err(SamplingFailure::Distribution(histogram))) => {
            result.summary = format!(
                "the samples do not follow the reference density (χ² = {:.1}, {} dof, p = {:.2e} < α = {:.1e})",
                histogram.chi2, histogram.dof, histogram.p_value, alpha
            );
            result.fail(
                format!("{call}: {}", histogram.worst_cell()),
                format!("{call}: the samples do not follow the density of the pdf (χ² test)"),
            );
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
            let shown = failure.stats.as_ref().map_or_else(
                || failure.message.clone(),
                |stats| {
                    format!(
                        "{}: your estimate {} ± {} (standard error) is off",
                        spec.name,
                        fmt_num(stats.student.mean),
                        fmt_num(stats.student.std_error)
                    )
                },
            );
            result.fail(failure.message, shown);
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

/// The status and points of a task from its checks.
///
/// A task whose cases all stopped at its own stub is not attempted. One whose failures all
/// stopped at other tasks' stubs (possible only without the reference, where the student's
/// own dependencies run) needs those tasks first. Otherwise the points are split by check
/// weight, each check earning its `credit` (set by the course's policy,
/// [`super::credit::Credit::apply`]); a task with a failing check that keeps at least
/// [`PASS_SHARE`] of its points is [`TaskStatus::Partial`].
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
    let earned = super::verdict::total(checks.iter().map(|c| c.weight * c.credit));
    if checks.iter().all(|c| c.passed) {
        (TaskStatus::Passed, points)
    } else if earned >= PASS_SHARE * total {
        (TaskStatus::Partial, points * earned / total)
    } else {
        (TaskStatus::Failed, points * earned / total)
    }
}

/// The share of its points a task with a failing check must keep to be
/// [`TaskStatus::Partial`] rather than failed: the scenes that need it are then graded.
pub const PASS_SHARE: f64 = 0.9;
