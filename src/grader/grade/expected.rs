//! The expected data: what the reference returns on every public case, and the reference
//! distribution of every sampler, stored per task so the grader works without solutions.
//!
//! # Storage
//! One insta snapshot per task, `src/grader/tasks/<task>/expected.snap`, whose body is the
//! task's [`TaskData`] as JSON. The instructor test `tests/instructor/expected.rs` computes
//! it from the reference ([`generate`]) and compares it with the stored file through a
//! tolerance comparator, so a change in the reference beyond rounding fails CI until the
//! snapshot is accepted (`INSTA_UPDATE=always`). `build.rs` embeds the files in the binary;
//! [`load_all`] parses them before any student code runs. Nothing in a snapshot is ever
//! decided by insta at grading time: `INSTA_*` settings cannot change a grade.

use super::call::SampleCall;
use super::case::ValueCase;
use super::sampling::SamplingTarget;
use crate::worksheet::TaskId;
use anyhow::{Context, anyhow, bail};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

include!(concat!(env!("OUT_DIR"), "/expected_files.rs"));

/// Version of the [`TaskData`] layout; bumped when it changes.
pub const FORMAT: u32 = 1;

/// The stored expected data of one task.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct TaskData {
    /// The task id.
    pub task: String,
    /// Layout version, [`FORMAT`].
    pub format: u32,
    /// Value cases with the reference's outputs.
    pub values: Vec<ValueCase>,
    /// Sampler setups with the reference's distribution.
    pub sampling: Vec<SamplingCase>,
}

/// A sampler setup and the reference distribution of its directions.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SamplingCase {
    /// Which sampler, with which parameters.
    pub call: SampleCall,
    /// The reference distribution over the hemisphere cells.
    pub target: SamplingTarget,
}

/// The JSON body of an insta snapshot file (the text after its `---` header).
pub fn snapshot_body(text: &str) -> anyhow::Result<&str> {
    let rest = text
        .strip_prefix("---\n")
        .or_else(|| text.strip_prefix("---\r\n"))
        .ok_or_else(|| anyhow!("no insta header"))?;
    let end = rest
        .find("\n---")
        .ok_or_else(|| anyhow!("unterminated insta header"))?;
    let body = &rest[end + 4..];
    Ok(body.trim_start_matches(['\r', '\n']))
}

/// Parses one stored file.
pub fn parse(task: TaskId, text: &str) -> anyhow::Result<TaskData> {
    let body = snapshot_body(text)?;
    let data: TaskData = serde_json::from_str(body)?;
    if data.task != task.name() {
        bail!("the file holds data of task `{}`", data.task);
    }
    if data.format != FORMAT {
        bail!(
            "format {} (this grader reads format {FORMAT}); regenerate it",
            data.format
        );
    }
    if let Some(case) = data.values.iter().find(|c| c.call.task() != task) {
        bail!(
            "case `{}` calls a function of task {}",
            case.name,
            case.call.task()
        );
    }
    Ok(data)
}

/// Every task's stored data, parsed and validated. A task without a file has no entry.
pub fn load_all() -> anyhow::Result<BTreeMap<TaskId, TaskData>> {
    let mut all = BTreeMap::new();
    for (name, text) in FILES {
        let task = TaskId::parse(name)
            .ok()
            .filter(|t| t.name() == *name)
            .ok_or_else(|| anyhow!("src/grader/tasks/{name}/expected.snap: no task `{name}`"))?;
        let data =
            parse(task, text).with_context(|| format!("src/grader/tasks/{name}/expected.snap"))?;
        all.insert(task, data);
    }
    Ok(all)
}

/// Computes a task's expected data from the reference: the public cases of
/// [`super::catalogue`] evaluated by the reference, and each sampler's distribution
/// integrated from the reference pdf.
#[cfg(feature = "solutions")]
pub fn generate(task: TaskId) -> anyhow::Result<TaskData> {
    let values = super::value_cases::evaluate(
        &super::value_cases::public_inputs(task),
        crate::implementation::reference(),
    )
    .with_context(|| format!("reference outputs of {task}"))?;
    let sampling = super::catalogue::sampling_setups(task)
        .into_iter()
        .map(|call| {
            let target = call.reference_target();
            SamplingCase { call, target }
        })
        .collect();
    Ok(TaskData {
        task: task.name().into(),
        format: FORMAT,
        values,
        sampling,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_snapshot_header_is_skipped() {
        let text = "---\nsource: tests/instructor/expected.rs\n---\n{\"a\": 1}\n";
        assert_eq!(snapshot_body(text).unwrap(), "{\"a\": 1}\n");
        assert!(snapshot_body("{}").is_err());
    }

    #[test]
    fn every_stored_file_parses() {
        let all = load_all().unwrap();
        assert_eq!(all.len(), FILES.len());
    }
}
