//! False failures: the reference graded with fresh seeds fails no task more often than the
//! task declares, and the p-values of the statistical sub-tests are uniform (so the
//! declared rates are the real ones).

use pbrlab::grade::calibration::repeat;
use pbrlab::grade::isolation::Launcher;
use pbrlab::grade::runner::GradeOptions;
use pbrlab::implementation::ImplChoice;

/// Gradings of the reference, each with seeds and hidden cases of its own (as a class of
/// 50 students would be graded). The per-task false-failure rates of the estimator and
/// sampling checks are also measured in-process, at 200 seeds, by the power test
/// (`power.rs`, its level 0); these runs add the whole path (workers, renders, hidden
/// cases) and the p-values' uniformity.
const RUNS: usize = 50;

#[test]
#[ignore = "slow: grades the reference with hidden cases and renders its scenes 50 times (about 2 minutes on two cores)"]
fn the_reference_fails_no_more_often_than_declared() {
    // The grader's own process consults the task tables (which checks a task has); like the
    // `pbrlab` binary, it links no student code.
    pbrlab::implementation::install(pbrlab::implementation::Implementations {
        student: None,
        reference: Some(pbrlab_solutions::TASKS),
        reference_render: None,
    });
    let launcher = Launcher {
        program: crate::support::worker(),
        args: Vec::new(),
        env: Vec::new(),
    };
    let options = GradeOptions {
        implementation: ImplChoice::Reference,
        seed: 10_000,
        hidden_seed: Some(20_000),
        ..GradeOptions::default()
    };
    let calibration = repeat(&options, &launcher, RUNS).expect("grading runs");
    println!("{}", calibration.text());
    let excessive = calibration.excessive(1e-3);
    assert!(
        excessive.is_empty(),
        "{}",
        excessive
            .iter()
            .map(|t| format!(
                "{}: {} failures\n{}",
                t.task,
                t.failures,
                t.example.as_deref().unwrap_or("")
            ))
            .collect::<Vec<_>>()
            .join("\n")
    );
    // Uniform p-values: the share below 5 % (and 1 %) within 4 standard deviations.
    let p: Vec<f64> = calibration
        .tasks
        .iter()
        .flat_map(|t| t.p_values.iter().copied())
        .collect();
    assert!(p.len() >= RUNS * 8, "{} p-values", p.len());
    for level in [0.05, 0.01] {
        let share = p.iter().filter(|&&x| x < level).count() as f64 / p.len() as f64;
        let sd = (level * (1.0 - level) / p.len() as f64).sqrt();
        assert!(
            (share - level).abs() < 4.0 * sd,
            "{:.2} % of p-values below {level}",
            100.0 * share
        );
    }
}
