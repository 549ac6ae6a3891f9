//! Runs stability cases on worker threads with a time limit, so that student code that
//! panics, stops at `todo!()` or never returns gets a verdict instead of taking the run
//! down.

use super::case::Case;
use super::expect::Expect;
use super::value::Value;
use super::verdict::Verdict;
use crate::grade::checks::StabilityOutput;
use crate::implementation::{is_todo_panic, panic_message};
use crate::panics::QuietPanics;
use crate::worksheet::{TaskId, Tasks};
use serde::{Deserialize, Serialize};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::time::{Duration, Instant};

/// The time limit per case that the command line uses unless told otherwise. Every case
/// of a sane implementation takes well under a millisecond (the slowest, 10⁵ reflections,
/// about one).
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(2);

/// Stack of each case's worker thread: as deep as the renderer's, so that a recursive
/// path tracer that does terminate is not cut short (a thread's stack is reserved, not
/// committed, so this costs address space only). Recursion without end still overflows
/// it, which aborts the process: only a child process (the grader's isolation) survives
/// that.
const WORKER_STACK: usize = 64 << 20;

/// The result of one case on one implementation.
#[derive(Clone, Debug, Serialize)]
pub struct Outcome {
    /// The task the case belongs to.
    #[serde(serialize_with = "serialize_task")]
    pub task: TaskId,
    /// The case's name (`smith_g1/back_facing`).
    pub case: &'static str,
    /// The input in words.
    pub input: &'static str,
    /// The expectation in words.
    pub expected: String,
    /// What the task returned; `None` when it panicked, stopped at `todo!()` or hung.
    pub value: Option<Value>,
    /// The value as shown in a table: for records, only the fields the case checks, plus
    /// any that are not finite.
    pub value_text: String,
    /// The verdict.
    pub verdict: Verdict,
    /// The panic message, for [`Verdict::Panic`].
    pub message: Option<String>,
    /// What a robust implementation does on this input.
    pub guard: &'static str,
    /// Wall-clock seconds the task took (the time limit for a hang).
    pub seconds: f64,
}

fn serialize_task<S: serde::Serializer>(task: &TaskId, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(task.name())
}

/// How a call of a case ended.
enum Ended {
    Returned(Value),
    Todo,
    Panicked(String),
}

/// Calls a case's evaluation on `imp` in this thread, catching panics.
fn call<T: Tasks>(eval: fn(&T) -> Value, imp: &T) -> Ended {
    match catch_unwind(AssertUnwindSafe(|| eval(imp))) {
        Ok(value) => Ended::Returned(value),
        Err(payload) if is_todo_panic(payload.as_ref()) => Ended::Todo,
        Err(payload) => Ended::Panicked(
            panic_message(payload.as_ref())
                .unwrap_or("panic with a non-string payload")
                .to_owned(),
        ),
    }
}

/// What a case gave, without the case's own (static) description: what a worker process
/// sends back for one case.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseResult {
    /// The value, when the task returned one.
    pub returned: Option<Returned>,
    /// The value as a table shows it.
    pub value_text: String,
    /// The verdict.
    pub verdict: Verdict,
    /// The panic message, for [`Verdict::Panic`].
    pub message: Option<String>,
    /// Wall-clock seconds.
    pub seconds: f64,
}

/// A value the task returned (boxed so that a returned `None`, [`Value::Absent`], is told
/// apart from no value at all).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Returned {
    /// The value.
    pub value: Value,
}

impl CaseResult {
    /// Judges how the call of `case` ended.
    fn judged<T>(case: &Case<T>, ended: Option<Ended>, elapsed: Duration) -> Self {
        let (value, verdict, message) = match ended {
            Some(Ended::Returned(v)) => {
                let verdict = case.judge(&v);
                (Some(v), verdict, None)
            }
            Some(Ended::Todo) => (None, Verdict::NotAttempted, None),
            Some(Ended::Panicked(m)) => (None, Verdict::Panic, Some(m)),
            None => (None, Verdict::Hang, None),
        };
        Self {
            value_text: value
                .as_ref()
                .map_or_else(|| "—".to_owned(), |v| shown(case, v)),
            returned: value.map(|value| Returned { value }),
            verdict,
            message,
            seconds: elapsed.as_secs_f64(),
        }
    }

    /// The result of a case that did not return within `seconds`.
    pub fn hung(seconds: f64) -> Self {
        Self {
            returned: None,
            value_text: "—".to_owned(),
            verdict: Verdict::Hang,
            message: None,
            seconds,
        }
    }

    /// The result of a case whose process died (`reason` says how) before it could report.
    pub fn crashed(reason: String, seconds: f64) -> Self {
        Self {
            returned: None,
            value_text: "—".to_owned(),
            verdict: Verdict::Crash,
            message: Some(reason),
            seconds,
        }
    }

    /// The full outcome, with the case's description.
    pub fn outcome<T>(self, case: &Case<T>) -> Outcome {
        Outcome {
            task: case.task,
            case: case.name,
            input: case.input,
            expected: case.expected_text(),
            value: self.returned.map(|r| r.value),
            value_text: self.value_text,
            verdict: self.verdict,
            message: self.message,
            guard: case.guard,
            seconds: self.seconds,
        }
    }
}

/// Judges what a worker process sent back for `case` (the value, or the panic that stopped
/// the call): the worker only runs the case, its parent judges it.
pub fn judge_output(case: &Case<impl Sized>, output: &StabilityOutput) -> CaseResult {
    let ended = match &output.outcome {
        Ok(value) => Ended::Returned(value.clone()),
        Err(p) if p.message.starts_with(crate::implementation::TODO_MESSAGE) => Ended::Todo,
        Err(p) => Ended::Panicked(p.message.clone()),
    };
    let seconds = Duration::try_from_secs_f64(output.seconds).unwrap_or_default();
    CaseResult::judged(case, Some(ended), seconds)
}

/// Runs one case on `imp` on its own thread and judges the result. A call that has not
/// returned after `timeout` is reported as [`Verdict::Hang`]; its thread cannot be
/// stopped, so it is left running (a process that ran a hanging case should exit when it
/// is done, which ends such threads).
///
/// Panics are caught on the worker; the panic hook should be silenced around the call
/// (as [`run_cases`] does) or each student panic prints its message.
pub fn run_case<T>(case: &Case<T>, imp: &T, timeout: Duration) -> Outcome
where
    T: Tasks + Clone + Send + 'static,
{
    let (tx, rx) = mpsc::channel();
    let eval = case.eval;
    let worker_imp = imp.clone();
    let spawned = std::thread::Builder::new()
        .name(format!("stability {}", case.name))
        .stack_size(WORKER_STACK)
        .spawn(move || {
            let start = Instant::now();
            let ended = call(eval, &worker_imp);
            // The receiver is gone only if the case already timed out.
            let _ = tx.send((ended, start.elapsed()));
        });
    let result = match spawned {
        Ok(_) => match rx.recv_timeout(timeout) {
            Ok((ended, t)) => CaseResult::judged(case, Some(ended), t),
            Err(RecvTimeoutError::Timeout) => CaseResult::judged(case, None, timeout),
            Err(RecvTimeoutError::Disconnected) => CaseResult::judged(
                case,
                Some(Ended::Panicked(
                    "the worker thread ended without a result".into(),
                )),
                Duration::ZERO,
            ),
        },
        Err(e) => CaseResult::judged(
            case,
            Some(Ended::Panicked(format!(
                "could not start a worker thread: {e}"
            ))),
            Duration::ZERO,
        ),
    };
    result.outcome(case)
}

/// Runs every case in order, calling `on_outcome` as each one finishes (so a caller can
/// print results as they come and lose nothing if a later case brings the process down),
/// and returns all outcomes. The panic hook is silenced for the duration; concurrent
/// calls run one after the other because the hook is global to the process.
pub fn run_cases<T>(
    cases: &[Case<T>],
    imp: &T,
    timeout: Duration,
    mut on_outcome: impl FnMut(&Outcome),
) -> Vec<Outcome>
where
    T: Tasks + Clone + Send + 'static,
{
    let _quiet = QuietPanics::new();
    cases
        .iter()
        .map(|case| {
            let outcome = run_case(case, imp, timeout);
            on_outcome(&outcome);
            outcome
        })
        .collect()
}

/// The value as a table shows it: records are cut down to the fields the expectation
/// names, plus any field that is not finite (the culprit of a NaN verdict).
fn shown<T>(case: &Case<T>, value: &Value) -> String {
    match (value, &case.expect) {
        (Value::Record(fields), Expect::Fields(bounds)) => {
            let kept: Vec<(String, f64)> = fields
                .iter()
                .filter(|(name, x)| !x.is_finite() || bounds.iter().any(|(b, _)| b == name))
                .cloned()
                .collect();
            Value::Record(kept).to_string()
        }
        _ => value.to_string(),
    }
}
