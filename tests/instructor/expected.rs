//! Instructor test: the grader's stored expected data (src/grader/tasks/<task>/expected.snap)
//! is what the grader computes today (each task's contract in f64, the reference where a
//! task has none).
//!
//! Each task's data is generated as the grader generates it and compared with the stored
//! snapshot by a tolerance comparator (rounding may differ between machines; a real change
//! may not). After a deliberate change to a contract, the reference or the graded cases,
//! accept the new data with `INSTA_UPDATE=always cargo test --release --test instructor
//! expected::` and commit the snapshots: `build.rs` embeds them in the grader. Not part of
//! the student handout.

use insta::internals::SnapshotContents;
use insta::{Comparator, Snapshot};
use pbrlab::grade::expected::generate;
use pbrlab::grade::tolerance::{Tolerance, json_close};
use pbrlab::grade::value_cases::public_inputs;
use pbrlab::worksheet::TaskId;

/// Regenerated data agrees with the stored data when every number is within this.
const REGENERATION: Tolerance = Tolerance::new(1e-9, 1e-5);

struct TolerantJson;

impl Comparator for TolerantJson {
    fn matches(&self, reference: &Snapshot, test: &Snapshot) -> bool {
        let parse = |s: &Snapshot| match s.contents() {
            SnapshotContents::Text(t) => {
                serde_json::from_str::<serde_json::Value>(&t.to_string()).ok()
            }
            SnapshotContents::Binary(_) => None,
        };
        match (parse(reference), parse(test)) {
            (Some(a), Some(b)) => json_close(&a, &b, REGENERATION),
            _ => false,
        }
    }

    fn dyn_clone(&self) -> Box<dyn Comparator> {
        Box::new(TolerantJson)
    }
}

#[test]
fn stored_expected_data_is_what_the_grader_computes_today() {
    install();
    let mut settings = insta::Settings::clone_current();
    settings.set_prepend_module_to_snapshot(false);
    settings.set_omit_expression(true);
    settings.set_comparator(Box::new(TolerantJson));
    for task in TaskId::ALL {
        let has_cases = !public_inputs(task).is_empty()
            || !pbrlab::grade::catalogue::sampling_setups(task).is_empty();
        if !has_cases {
            continue;
        }
        let data = generate(task).unwrap_or_else(|e| panic!("{task}: {e:#}"));
        let json = serde_json::to_string_pretty(&data).expect("serialisable");
        // The task's folder, from this file's (tests/instructor/).
        settings.set_snapshot_path(format!("../../src/grader/tasks/{task}"));
        settings.bind(|| insta::assert_snapshot!("expected", json));
    }
}

/// Makes the shipped exercises and the reference the framework's implementations in this
/// test process, as the `pbrlab` binary does at start.
fn install() {
    pbrlab::implementation::install(pbrlab::implementation::Implementations {
        student: Some(pbrlab_exercises::TASKS),
        reference: Some(pbrlab_solutions::TASKS),
        reference_render: None,
    });
}
