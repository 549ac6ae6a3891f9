//! Every check of one task, run on one implementation: the values, sampling, estimator and
//! stability checks that fit the task, with the task's points split between them.

use super::call::SampleCall;
use super::case::ValueCase;
use super::catalogue;
use super::estimator;
use super::estimator::EstimatorSpec;
use super::expected::TaskData;
use super::measure::{SAMPLING_SAMPLES, run_task};
use super::output::fmt_num;
use super::sampling::{self, SamplingFailure, SamplingTarget};
use super::stability;
use super::stats::sidak;
use super::values;
use super::variance_check;
use super::verdict::{CheckKind, CheckResult, Detail, TaskStatus, Visibility};
use super::wire::{EstimateOutputs, Raw, SampleOutputs, SamplingSetup, ValueCalls, WorkerInput};
use crate::worksheet::{TaskId, Tasks};
use serde::{Deserialize, Serialize};

/// The declared false-failure rate of each task's statistical checks together: a correct
/// implementation fails a task's sampling and estimator checks with this probability
/// (Šidák-corrected over the sub-tests).
pub const TASK_ALPHA: f64 = 1e-3;

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
            Raw::Variances(v) if v.index == index => Some(variance_check::judge(
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
