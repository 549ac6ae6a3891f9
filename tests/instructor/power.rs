//! The power of the statistical checks: errors of known size put into the reference are
//! caught as often as each task declares (`POWER` in its `src/grader/tasks/<task>/cases.rs`), while
//! the reference itself fails no more often than the grader's significance says.

use pbrlab::grade::catalogue::{declared_power, estimators, sampling_setups};
use pbrlab::grade::power::{CAUGHT, PowerRow, estimator_power, sampler_power};
use pbrlab::worksheet::TaskId;
use pbrlab_solutions::TASKS as Reference;

/// Seeds per error level in the slow test.
const SEEDS: usize = 200;

/// The most seeds out of [`SEEDS`] at which the reference may fail a task's checks of one
/// kind: its false-failure rate is declared at most 1e-3 per task, so 200 seeds expect 0.2
/// failures, and 4 or more would happen with probability 6e-5.
const MOST_FALSE_FAILURES: usize = 3;

fn assert_declared(row: &PowerRow, declared: Option<f64>) {
    let declared = declared.unwrap_or_else(|| {
        panic!(
            "{} has {} checks but declares no power for them",
            row.subject, row.injection
        )
    });
    let rate = row
        .rate_at(declared)
        .unwrap_or_else(|| panic!("{}: {declared} is not a measured level", row.subject));
    assert!(
        rate >= CAUGHT,
        "{} ({}): an error of {} % is caught at {:.1} % of seeds, declared ≥ {} %",
        row.subject,
        row.injection,
        declared * 100.0,
        rate * 100.0,
        CAUGHT * 100.0
    );
    assert!(
        row.failures[0] <= MOST_FALSE_FAILURES,
        "{} ({}): the reference failed at {} of {} seeds",
        row.subject,
        row.injection,
        row.failures[0],
        row.seeds
    );
}

#[test]
#[ignore = "slow: every estimator and sampler check of the reference at 200 seeds (about 5 minutes on two cores)"]
fn every_task_catches_the_error_it_declares() {
    for task in TaskId::ALL {
        let declared = declared_power(task);
        let has_estimators = !estimators(task, &Reference).is_empty();
        let has_sampling = !sampling_setups(task).is_empty();
        assert_eq!(
            declared.and_then(|d| d.estimator_bias).is_some(),
            has_estimators,
            "{task}: a declared estimator power exactly when it has estimator checks"
        );
        assert_eq!(
            declared.and_then(|d| d.sampler_distortion).is_some(),
            has_sampling,
            "{task}: a declared sampler power exactly when it has sampling checks"
        );
        if let Some(row) = estimator_power(task, &Reference, SEEDS) {
            assert_declared(&row, declared.and_then(|d| d.estimator_bias));
        }
        if let Some(row) = sampler_power(task, &Reference, SEEDS) {
            assert_declared(&row, declared.and_then(|d| d.sampler_distortion));
        }
    }
}

#[test]
fn a_ten_percent_bias_is_always_caught_and_none_is_not() {
    let row = estimator_power(TaskId::AnisoNdf, &Reference, 8).expect("estimators");
    assert_eq!(row.failures.first(), Some(&0), "{row:?}");
    assert_eq!(row.failures.last(), Some(&8), "{row:?}");
    let row = sampler_power(TaskId::CosineSample, &Reference, 4).expect("a sampler");
    assert_eq!(row.failures.first(), Some(&0), "{row:?}");
    assert_eq!(row.failures.last(), Some(&4), "{row:?}");
}
