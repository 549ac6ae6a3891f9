//! Stability cases in worker processes: each case runs in a `pbrlab-worker` of its own, so a
//! case that overflows the stack, aborts or never returns is reported as a crash or a hang
//! and every other case still runs. `pbrlab stability` works this way.

use super::outcome::CaseResult;
use super::{Case, Outcome, cases_for};
use crate::grade::isolation::{self, Launcher, WorkerFailure};
use crate::grade::runner::{DEFAULT_MEMORY_LIMIT, run_jobs};
use crate::grade::worker::{ImplSpec, Job, JobKind, Record};
use crate::worksheet::TaskFns;
use crate::worksheet::TaskId;
use anyhow::bail;
use std::time::Duration;

/// The cases of `task`, each run in a worker started by `launcher` with `spec`'s
/// implementation and stopped after `timeout` (plus the worker's start-up).
pub fn run_isolated(
    launcher: &Launcher,
    spec: &ImplSpec,
    task: TaskId,
    timeout: Duration,
) -> anyhow::Result<Vec<Outcome>> {
    // Only the cases' descriptions are used here; the workers run them.
    let cases: Vec<Case<TaskFns>> = cases_for::<TaskFns>(task);
    let jobs: Vec<Job> = cases
        .iter()
        .map(|case| Job {
            nonce: isolation::nonce(),
            implementation: spec.clone(),
            kind: JobKind::Stability {
                case: case.name.to_owned(),
            },
            memory_limit: DEFAULT_MEMORY_LIMIT,
        })
        .collect();
    // The limit covers the case, not the worker's start-up.
    let limit = timeout + WORKER_START;
    let runs = run_jobs(launcher, &jobs, 2, limit);
    cases
        .iter()
        .zip(runs)
        .map(|(case, run)| {
            let result = match run.outcome {
                Ok(Record::Stability { output }) if output.case == case.name => {
                    super::outcome::judge_output(case, &output)
                }
                Ok(Record::Error { message }) | Err(WorkerFailure::Grader(message)) => {
                    bail!("{}: the stability worker failed: {message}", case.name)
                }
                Ok(other) => bail!("{}: the worker answered {other:?}", case.name),
                Err(WorkerFailure::Student(_)) if run.seconds >= limit.as_secs_f64() => {
                    CaseResult::hung(timeout.as_secs_f64())
                }
                Err(WorkerFailure::Student(reason)) => {
                    CaseResult::crashed(format!("the code {reason}"), run.seconds)
                }
            };
            Ok(result.outcome(case))
        })
        .collect()
}

/// What a worker process takes to start, on top of a case's time limit.
const WORKER_START: Duration = Duration::from_millis(500);
