//! The stability catalogue on known implementations: the reference passes every case, the
//! stubs are "not attempted" everywhere, each deliberately naive function fails exactly
//! the cases it should with the verdict it should, and hangs and panics are reported.

use pbrlab::stability::outcome::{CaseResult, judge_output};
use pbrlab::stability::{Case, Outcome, Verdict, cases};
use pbrlab::worksheet::Tasks;
use pbrlab_exercises::TASKS as Student;
use std::sync::{Arc, mpsc};
use std::time::Duration;
#[cfg(feature = "solutions")]
use {
    crate::support::patch::Patch, crate::support::variants, pbrlab::stability::cases_for,
    pbrlab::task_set::TaskSet, pbrlab::worksheet::TaskId, std::collections::BTreeMap,
};

/// Far longer than any case takes; only the hang test uses a short limit.
const TIMEOUT: Duration = Duration::from_secs(20);

/// Stack of each case's thread: as deep as the renderer's, so that a recursive path tracer
/// that does terminate is not cut short.
const CASE_STACK: usize = 64 << 20;

/// Runs every case on `imp` the way a worker does ([`Case::run`]), each on a thread of its
/// own here (a `Patch` is not a table a worker process could load), and judges what came
/// back as the grader does ([`judge_output`]); a case that has not returned after
/// `timeout` is a hang, and its thread is left behind (it sleeps, see the hang test).
fn run_all<T: Tasks + Clone + Send + 'static>(
    imp: T,
    cases: Vec<Case<T>>,
    timeout: Duration,
) -> Vec<Outcome> {
    let _quiet = pbrlab::panics::QuietPanics::new();
    let cases = Arc::new(cases);
    (0..cases.len())
        .map(|i| {
            let (tx, rx) = mpsc::channel();
            let (shared, imp) = (Arc::clone(&cases), imp.clone());
            std::thread::Builder::new()
                .stack_size(CASE_STACK)
                .spawn(move || {
                    // The receiver is gone only if the case already timed out.
                    let _ = tx.send(shared[i].run(&imp));
                })
                .expect("a thread for the case");
            let result = match rx.recv_timeout(timeout) {
                Ok(output) => judge_output(&cases[i], &output),
                Err(_) => CaseResult::hung(timeout.as_secs_f64()),
            };
            result.outcome(&cases[i])
        })
        .collect()
}

/// The cases that did not pass, with their verdicts.
#[cfg(feature = "solutions")]
fn failures(imp: Patch) -> BTreeMap<&'static str, Verdict> {
    run_all(imp, cases(), TIMEOUT)
        .into_iter()
        .filter(|o| o.verdict != Verdict::Pass)
        .map(|o| (o.case, o.verdict))
        .collect()
}

/// The reference with `task`'s functions replaced as `set` says, in force for every task.
#[cfg(feature = "solutions")]
fn patched(task: TaskId, set: impl FnOnce(&mut Patch)) -> Patch {
    let mut patch = Patch::new(task).only(TaskSet::all());
    set(&mut patch);
    patch
}

fn table(outcomes: &[Outcome]) -> String {
    outcomes
        .iter()
        .map(|o| {
            format!(
                "{:<46} {:<14} {} (expected {})",
                o.case,
                o.verdict.label(),
                o.value_text,
                o.expected
            )
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn stubs_are_not_attempted_everywhere() {
    let untouched = crate::shipped_stubs::untouched();
    let stub_cases: Vec<Case<_>> = cases()
        .into_iter()
        .filter(|c| untouched.contains(&c.task))
        .collect();
    let outcomes = run_all(Student, stub_cases, TIMEOUT);
    let other: Vec<Outcome> = outcomes
        .into_iter()
        .filter(|o| o.verdict != Verdict::NotAttempted)
        .collect();
    assert!(
        other.is_empty(),
        "stubs gave other verdicts:\n{}",
        table(&other)
    );
}

#[cfg(feature = "solutions")]
#[test]
fn the_reference_passes_every_case() {
    use pbrlab_solutions::TASKS as Reference;
    let outcomes = run_all(Reference, cases(), TIMEOUT);
    assert!(outcomes.len() >= 70, "only {} cases", outcomes.len());
    let failed: Vec<Outcome> = outcomes
        .into_iter()
        .filter(|o| o.verdict != Verdict::Pass)
        .collect();
    assert!(
        failed.is_empty(),
        "the reference fails:\n{}",
        table(&failed)
    );
}

#[cfg(feature = "solutions")]
#[test]
fn a_patch_that_replaces_nothing_is_the_reference() {
    let failed = failures(Patch::new(TaskId::Reflect).only(TaskSet::all()));
    assert!(failed.is_empty(), "{failed:?}");
}

#[cfg(feature = "solutions")]
#[test]
fn each_naive_implementation_fails_exactly_its_cases() {
    let mut report = String::new();
    let all = variants::naive();
    assert!(
        all.len() >= TaskId::ALL.len(),
        "too few naive implementations"
    );
    for naive in all {
        let expected: BTreeMap<&str, Verdict> = naive.fails.into_iter().collect();
        let got = failures(naive.patch);
        if got != expected {
            report += &format!(
                "{}:\n  expected {expected:?}\n  got      {got:?}\n",
                naive.name
            );
        }
    }
    assert!(report.is_empty(), "{report}");
}

#[cfg(feature = "solutions")]
#[test]
fn code_that_never_returns_is_reported_as_a_hang() {
    let start = std::time::Instant::now();
    let outcomes = run_all(
        patched(TaskId::SmithG1, |p| {
            p.smith_g1 = Some(|_, _| {
                loop {
                    // Sleeps rather than spins, so the abandoned thread costs no CPU.
                    std::thread::sleep(Duration::from_secs(3600));
                }
            })
        }),
        cases_for(TaskId::SmithG1),
        Duration::from_millis(150),
    );
    assert!(!outcomes.is_empty());
    assert!(
        outcomes.iter().all(|o| o.verdict == Verdict::Hang),
        "{}",
        table(&outcomes)
    );
    assert!(
        start.elapsed() < Duration::from_secs(10),
        "the run waited for the hung threads"
    );
}

#[cfg(feature = "solutions")]
#[test]
fn a_panic_is_reported_with_its_message() {
    let outcomes = run_all(
        patched(TaskId::Reflect, |p| {
            p.reflect = Some(|_, _| panic!("index out of bounds: the len is 3 but the index is 3"))
        }),
        cases_for(TaskId::Reflect),
        TIMEOUT,
    );
    for o in &outcomes {
        assert_eq!(o.verdict, Verdict::Panic, "{}", o.case);
        assert!(
            o.message
                .as_deref()
                .is_some_and(|m| m.contains("index out of bounds")),
            "{:?}",
            o.message
        );
    }
}

#[cfg(feature = "solutions")]
#[test]
fn json_output_names_the_task_and_spells_out_nan() {
    let outcomes = run_all(
        variants::naive_named("`phong` raises an unclamped lobe cosine to the exponent"),
        cases_for(TaskId::Phong),
        TIMEOUT,
    );
    let json = serde_json::to_value(&outcomes).unwrap();
    let nan_case = json
        .as_array()
        .unwrap()
        .iter()
        .find(|o| o["case"] == "phong/fractional_exponent_negative_lobe")
        .unwrap();
    assert_eq!(nan_case["task"], "phong");
    assert_eq!(nan_case["verdict"], "nan");
    assert_eq!(nan_case["value"][0], "NaN");
}
