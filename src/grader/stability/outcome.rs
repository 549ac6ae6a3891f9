//! What came of a stability case: a worker runs it ([`Case::run`]) and sends back what the
//! task returned or the panic that stopped it; the parent judges that into a [`CaseResult`]
//! ([`judge_output`]) and, with the case's description, an [`Outcome`]. The grader's
//! stability check and `pbrlab stability` judge the same way.

use super::case::Case;
use super::expect::Expect;
use super::value::Value;
use super::verdict::Verdict;
use crate::grade::wire::StabilityOutput;
use crate::worksheet::TaskId;
use serde::{Deserialize, Serialize};
use std::time::Duration;

/// The time limit per case that the command line uses unless told otherwise. Every case
/// of a sane implementation takes well under a millisecond (the slowest, 10⁵ reflections,
/// about one).
pub const DEFAULT_TIMEOUT: Duration = Duration::from_secs(2);

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
    let (returned, verdict, message) = match &output.outcome {
        Ok(value) => (Some(value), case.judge(value), None),
        Err(p) if p.message.starts_with(crate::implementation::TODO_MESSAGE) => {
            (None, Verdict::NotAttempted, None)
        }
        Err(p) => (None, Verdict::Panic, Some(p.message.clone())),
    };
    CaseResult {
        value_text: returned.map_or_else(|| "—".to_owned(), |v| shown(case, v)),
        returned: returned.map(|value| Returned {
            value: value.clone(),
        }),
        verdict,
        message,
        seconds: output.seconds,
    }
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
