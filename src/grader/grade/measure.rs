//! The worker's half of grading a task: runs its checks' calls, samplers, estimators,
//! variance pairs and stability cases on an implementation and returns their raw outputs
//! ([`super::wire::Raw`]); the grader judges them ([`super::checks`]).

use super::call::Call;
use super::catalogue;
use super::estimator;
use super::sampling;
use super::wire::{
    EstimateOutputs, Raw, SampleOutputs, StabilityOutput, ValueOutputs, VarianceOutputs, Variances,
    WorkerInput,
};
use crate::panics;
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use std::time::Instant;

/// Samples per sampling sub-test.
pub const SAMPLING_SAMPLES: usize = 200_000;

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
        let outputs = Raw::Values(evaluate_values(&calls.check, &calls.calls, t));
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

/// Calls `t` on every call (the worker's half).
pub fn evaluate_values(check: &str, calls: &[Call], t: &impl Tasks) -> ValueOutputs {
    let start = Instant::now();
    let outputs = calls
        .iter()
        .map(|call| panics::catch(|| call.eval(t)))
        .collect();
    ValueOutputs {
        check: check.into(),
        outputs,
        seconds: start.elapsed().as_secs_f64(),
    }
}
