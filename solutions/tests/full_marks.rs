//! The reference passes every value, sampling, estimator, variance and stability check of
//! every task, graded in this process against the stored expected data (the render checks
//! are the root package's tests). It is the test suite `cargo mutants` runs on the
//! reference (`.cargo/mutants.toml`): a mutant of `solutions/` that fails no check here
//! survives.

use pbrlab::grade::checks::{TaskInput, grade_task};
use pbrlab::implementation::{Implementations, install};
use pbrlab::worksheet::TaskId;
use pbrlab_solutions::TASKS;

#[test]
fn the_reference_passes_every_check() {
    install(Implementations {
        student: Some(TASKS),
        reference: Some(TASKS),
        reference_render: None,
    });
    let mut stored = pbrlab::grade::expected::load_all().expect("the stored expected data");
    let inputs: Vec<(TaskId, TaskInput)> = TaskId::ALL
        .into_iter()
        .map(|task| {
            let input = TaskInput {
                data: stored.remove(&task),
                hidden: Vec::new(),
                seed: pbrlab::grade::runner::DEFAULT_SEED,
            };
            (task, input)
        })
        .collect();
    let failures: Vec<String> = std::thread::scope(|scope| {
        let graded: Vec<_> = inputs
            .iter()
            .map(|(task, input)| {
                scope.spawn(move || {
                    grade_task(&TASKS, *task, input)
                        .into_iter()
                        .filter(|c| !c.passed)
                        .map(|c| format!("{task}: {}: {}", c.name, c.failures.join("; ")))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        graded
            .into_iter()
            .zip(&inputs)
            .flat_map(|(h, (task, _))| {
                h.join()
                    .unwrap_or_else(|_| vec![format!("{task}: grading panicked")])
            })
            .collect()
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
