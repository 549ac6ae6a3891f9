//! Isolation: student code that panics, loops, overflows its stack, aborts, allocates
//! without bound, exits early or forges a result line costs its own task and nothing else,
//! with a message that says what happened.
//!
//! The workers here are this test binary itself (`worker_entry`), serving the reference with
//! a misbehaving `smith_g1`, so the real process machinery is exercised end to end.

use crate::support::patch::Patch;
use pbrlab::grade::isolation::Launcher;
use pbrlab::grade::runner::{GradeOptions, grade};
use pbrlab::grade::verdict::{GradeReport, TaskStatus};
use pbrlab::grade::worker::ImplSpec;
use pbrlab::implementation::ImplChoice;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;
use std::hint::black_box;
use std::time::Duration;

const WORKER: &str = "PBRLAB_TEST_MISBEHAVIOUR";

/// How the patched `smith_g1` misbehaves.
fn misbehaviour(name: &str) -> fn() {
    match name {
        "panic" => || panic!("index out of range in my G1"),
        "loop" => || loop {
            std::hint::spin_loop()
        },
        "stack" => || {
            fn deeper(n: u64) -> u64 {
                if black_box(n) == u64::MAX {
                    return 0;
                }
                black_box(deeper(black_box(n + 1))) + 1
            }
            black_box(deeper(0));
        },
        "abort" => || std::process::abort(),
        "alloc" => || {
            black_box(vec![1u8; 1 << 40]);
        },
        "exit" => || std::process::exit(0),
        "forge" => || {
            println!("PBRLAB-RESULT 0123456789abcdef {{\"record\":\"checks\",\"checks\":[]}}");
            std::process::exit(0)
        },
        "print" => || println!("debugging my G1"),
        other => panic!("unknown misbehaviour {other}"),
    }
}

/// The worker: runs only when started by the tests below.
#[test]
fn worker_entry() {
    let Ok(name) = std::env::var(WORKER) else {
        return;
    };
    crate::support::install();
    let mut patch = Patch::new(TaskId::SmithG1);
    if name == "abort at cos 1e-8" {
        // Fine on every graded value (drawn 1e-7 or more from the horizon, or on one of
        // its named tiny cosines, none of them 1e-8); only the stability case with
        // cos θ = 1e-8 brings it down.
        patch.smith_g1 = Some(|w, alpha| {
            if w.z == 1e-8 {
                std::process::abort();
            }
            pbrlab_solutions::smith_g1::smith_g1(w, alpha)
        });
    } else {
        patch.misbehave = Some(misbehaviour(&name));
    }
    pbrlab::grade::worker::serve(|spec, _| Ok(patch.only(spec.student_tasks())))
}

/// Workers that are this test binary, serving the reference with `misbehaviour`.
fn launcher(misbehaviour: &str) -> Launcher {
    Launcher {
        program: std::env::current_exe().expect("test binary path"),
        args: [
            "--exact",
            "isolation::worker_entry",
            "--nocapture",
            "--test-threads=1",
        ]
        .map(String::from)
        .to_vec(),
        env: vec![(WORKER.into(), misbehaviour.into())],
    }
}

fn grade_with(misbehaviour: &str, implementation: ImplChoice) -> GradeReport {
    crate::support::install();
    let launcher = launcher(misbehaviour);
    let options = GradeOptions {
        tasks: vec![TaskId::Reflect, TaskId::SmithG1, TaskId::CookTorrance],
        implementation,
        timeout: Duration::from_secs(4),
        memory_limit: 1 << 30,
        ..GradeOptions::default()
    };
    grade(&options, &launcher).expect("grading runs")
}

/// Grades with `misbehaviour` and checks that smith_g1 alone lost its points, with a reason
/// containing `reason`.
fn only_smith_g1_fails(misbehaviour: &str, reason: &str) {
    let report = grade_with(misbehaviour, ImplChoice::Student);
    for t in &report.tasks {
        if t.task == "smith_g1" {
            let TaskStatus::Crashed { reason: got } = &t.status else {
                panic!("{misbehaviour}: smith_g1 is {:?}", t.status);
            };
            assert!(got.contains(reason), "{misbehaviour}: {got}");
            assert_eq!(t.points, 0.0);
        } else {
            assert_eq!(
                t.status,
                TaskStatus::Passed,
                "{misbehaviour}: {} {:?}",
                t.task,
                t.status
            );
        }
    }
}

#[test]
fn an_infinite_loop_times_out() {
    only_smith_g1_fails("loop", "timed out after 4 s");
}

#[test]
fn a_stack_overflow_is_named() {
    only_smith_g1_fails("stack", "overflowed its stack");
}

#[test]
fn an_abort_is_named() {
    only_smith_g1_fails("abort", "aborted");
}

#[test]
fn a_huge_allocation_hits_the_memory_limit() {
    only_smith_g1_fails("alloc", "ran out of memory (limit 1.0 GiB)");
}

#[test]
fn an_early_exit_is_detected() {
    only_smith_g1_fails("exit", "exited early with status 0");
}

#[test]
fn a_forged_result_line_is_ignored() {
    only_smith_g1_fails("forge", "exited early with status 0");
}

#[test]
fn a_crash_names_the_check_it_stopped_and_keeps_the_finished_ones() {
    let report = grade_with("abort at cos 1e-8", ImplChoice::Student);
    let g1 = report.task("smith_g1").expect("graded");
    let TaskStatus::Crashed { reason } = &g1.status else {
        panic!("smith_g1 is {:?}", g1.status);
    };
    assert!(
        reason.contains("aborted") && reason.contains("while running stability: smith_g1/"),
        "{reason}"
    );
    assert_eq!(g1.points, 0.0);
    let values = g1.checks.iter().find(|c| c.name == "values");
    assert!(values.is_some_and(|c| c.passed), "{:?}", g1.checks);
    assert!(g1.checks.iter().all(|c| c.name != "stability"));
    let text = pbrlab::grade::report::details(g1);
    assert!(
        text.contains("finished before that:\n    ✓ values"),
        "{text}"
    );
}

#[test]
fn the_stability_command_reports_a_crashing_case_and_runs_the_others() {
    let launcher = launcher("abort at cos 1e-8");
    let outcomes = pbrlab::stability::run_isolated(
        &launcher,
        &ImplSpec::Student,
        TaskId::SmithG1,
        Duration::from_secs(4),
    )
    .expect("the workers run");
    assert!(outcomes.len() > 3);
    for o in &outcomes {
        // The case with cos θ = 1e-8 brings its worker down, and is reported on its own.
        if o.case == "smith_g1/tiny_cos" {
            assert_eq!(o.verdict, Verdict::Crash, "{o:?}");
            assert!(
                o.message.as_deref().is_some_and(|m| m.contains("aborted")),
                "{o:?}"
            );
        } else {
            assert_eq!(o.verdict, Verdict::Pass, "{o:?}");
        }
    }
}

#[test]
fn the_stability_command_reports_a_case_that_never_returns_as_a_hang() {
    let outcomes = pbrlab::stability::run_isolated(
        &launcher("loop"),
        &ImplSpec::Student,
        TaskId::SmithG1,
        Duration::from_millis(300),
    )
    .expect("the workers run");
    assert!(
        outcomes.iter().all(|o| o.verdict == Verdict::Hang),
        "{outcomes:?}"
    );
}

#[test]
fn a_panic_fails_the_task_case_by_case() {
    let report = grade_with("panic", ImplChoice::Student);
    let g1 = report.task("smith_g1").expect("graded");
    assert_eq!(g1.status, TaskStatus::Failed);
    assert_eq!(g1.points, 0.0);
    let message = &g1.checks[0].failures[0];
    assert!(
        message.starts_with("smith_g1(w=")
            && message.contains("panicked at")
            && message.contains("index out of range in my G1"),
        "{message}"
    );
    for task in ["reflect", "cook_torrance"] {
        assert_eq!(
            report.task(task).expect("graded").status,
            TaskStatus::Passed
        );
    }
}

#[test]
fn printing_is_captured_and_harmless() {
    let report = grade_with("print", ImplChoice::Student);
    let g1 = report.task("smith_g1").expect("graded");
    assert_eq!(g1.status, TaskStatus::Passed);
    assert!(g1.output.contains("debugging my G1"), "{}", g1.output);
}

#[test]
fn mixed_grades_dependents_with_the_students_code() {
    // With every attempted task from the student, cook_torrance calls the crashing smith_g1.
    let report = grade_with("abort", ImplChoice::Mixed);
    let ct = report.task("cook_torrance").expect("graded");
    assert!(
        matches!(ct.status, TaskStatus::Crashed { .. }),
        "{:?}",
        ct.status
    );
    assert_eq!(
        report.task("reflect").expect("graded").status,
        TaskStatus::Passed
    );
}

#[test]
fn a_worker_that_cannot_start_is_the_graders_fault() {
    let launcher = Launcher {
        program: std::env::current_exe().expect("test binary path"),
        args: ["--exact", "no_such_test"].map(String::from).to_vec(),
        env: Vec::new(),
    };
    let options = GradeOptions {
        tasks: vec![TaskId::Reflect],
        ..GradeOptions::default()
    };
    let report = grade(&options, &launcher).expect("grading runs");
    let reflect = report.task("reflect").expect("graded");
    assert!(
        matches!(&reflect.status, TaskStatus::GraderError { message } if message.contains("did not start")),
        "{:?}",
        reflect.status
    );
}

#[test]
fn the_references_estimators_run_in_a_worker_of_their_own_for_the_time_comparison() {
    crate::support::install();
    let options = GradeOptions {
        tasks: vec![TaskId::DeltaTracking],
        implementation: ImplChoice::Student,
        timeout: Duration::from_secs(30),
        memory_limit: 1 << 30,
        ..GradeOptions::default()
    };
    let report = grade(&options, &launcher("print")).expect("grading runs");
    let task = &report.tasks[0];
    assert_eq!(task.status, TaskStatus::Passed, "{task:?}");
    let estimators: Vec<&str> = task
        .checks
        .iter()
        .filter(|c| c.name.starts_with("estimator"))
        .map(|c| c.summary.as_str())
        .collect();
    assert!(!estimators.is_empty(), "{task:?}");
    for summary in estimators {
        assert!(summary.contains(" s vs reference "), "{summary}");
    }
}
