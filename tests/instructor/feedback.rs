//! Feedback levels (`--feedback full|actual|none`): a report a student sees at `actual` or
//! `none` holds no expected value in any format, a hidden case is shown at no level, and
//! the points are the same at every level.

use crate::support::{grade, outcome, variants};
use pbrlab::grade::feedback::Feedback;
use pbrlab::grade::report::redact::redact;
use pbrlab::grade::report::{Detail, gradescope, prairielearn, text, write_html};
use pbrlab::grade::runner::{GradeOptions, prepare};
use pbrlab::grade::verdict::{CheckKind, GradeReport};
use pbrlab::worksheet::TaskId;
use std::collections::BTreeSet;

/// The numbers written with a decimal point or an exponent in `text` (`0.7071`, `1.2e-3`),
/// at least four characters long, without their sign: values, not counts or case numbers.
fn numbers(text: &str) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let mut current = String::new();
    let flush = |current: &mut String, found: &mut BTreeSet<String>| {
        let n = current.trim_end_matches(['.', 'e', '-']).to_string();
        if n.len() >= 4 && (n.contains('.') || n.contains('e')) && n.parse::<f64>().is_ok() {
            found.insert(n);
        }
        current.clear();
    };
    for c in text.chars() {
        let continues = c.is_ascii_digit()
            || (c == '.' && !current.is_empty())
            || (c == 'e' && !current.is_empty() && !current.contains('e'))
            || (c == '-' && current.ends_with('e'));
        if continues {
            current.push(c);
        } else {
            flush(&mut current, &mut found);
        }
    }
    flush(&mut current, &mut found);
    found
}

/// Whether `page` writes the number `n` (not as a part of a longer number).
fn writes(page: &str, n: &str) -> bool {
    let number = |c: char| c.is_ascii_digit() || c == '.';
    page.match_indices(n)
        .any(|(i, _)| !page[..i].ends_with(number) && !page[i + n.len()..].starts_with(number))
}

/// The first wrong variant of every task graded in this process, with hidden cases: a
/// report in which values, stability, sampling and estimator checks fail.
fn failing_report() -> GradeReport {
    crate::support::install();
    let inputs = prepare(&GradeOptions {
        seed: 1,
        hidden_seed: Some(2026),
        ..GradeOptions::default()
    })
    .expect("inputs");
    let catalogue = variants::wrong();
    let mut tasks = Vec::new();
    for task in TaskId::ALL {
        let Some(variant) = catalogue.iter().find(|v| v.task == task) else {
            continue;
        };
        tasks.push(outcome(task, grade(&variant.patch, task, &inputs[&task])));
    }
    GradeReport::new("student", 1, true, tasks, 1.0)
}

/// `value` without the numbers that say how a report is laid out and scored (weights,
/// credit, points, counts, times), which are not answers.
fn without_bookkeeping(value: &mut serde_json::Value) {
    const BOOKKEEPING: [&str; 13] = [
        "weight",
        "credit",
        "seconds",
        "score",
        "max_score",
        "points",
        "max_points",
        "alpha",
        "total",
        "failed",
        "seed",
        "execution_time",
        "peak_memory_kib",
    ];
    match value {
        serde_json::Value::Object(map) => {
            map.retain(|k, v| !(BOOKKEEPING.contains(&k.as_str()) && v.is_number()));
            map.values_mut().for_each(without_bookkeeping);
        }
        serde_json::Value::Array(items) => items.iter_mut().for_each(without_bookkeeping),
        _ => {}
    }
}

/// `value` as JSON, without its bookkeeping numbers.
fn json(value: impl serde::Serialize) -> String {
    let mut value = serde_json::to_value(value).unwrap();
    without_bookkeeping(&mut value);
    serde_json::to_string_pretty(&value).unwrap()
}

/// Every format a student sees of `report`, by name.
fn rendered(report: &GradeReport) -> Vec<(&'static str, String)> {
    let dir = tempfile::tempdir().unwrap();
    let html = std::fs::read_to_string(write_html(report, dir.path()).unwrap()).unwrap();
    vec![
        ("text", text(report, Detail::Verbose)),
        ("JSON", json(report)),
        ("Gradescope", json(gradescope(report))),
        ("PrairieLearn", json(prairielearn::prairielearn(report, ""))),
        ("HTML", html),
    ]
}

#[test]
fn no_expected_value_reaches_a_student_at_actual_or_none_and_no_hidden_case_at_any_level() {
    let full = failing_report();
    let failing: Vec<CheckKind> = full
        .tasks
        .iter()
        .flat_map(|t| &t.checks)
        .filter(|c| !c.passed)
        .map(|c| c.kind)
        .collect();
    for kind in [
        CheckKind::Values,
        CheckKind::Stability,
        CheckKind::Sampling,
        CheckKind::Estimator,
    ] {
        assert!(
            failing.contains(&kind),
            "no {kind:?} check fails: {failing:?}"
        );
    }
    // What only the expected side of a message holds: its numbers that neither the case's
    // student-safe line nor anything else the student produced holds; and every number of
    // a hidden case.
    let visible = || {
        full.tasks
            .iter()
            .flat_map(|t| &t.checks)
            .filter(|c| c.visibility == pbrlab::grade::verdict::Visibility::Visible)
    };
    // What a student may see: the inputs and outputs of failing cases, and the checks'
    // names, which are their configurations (`α = 0.25`).
    let safe: BTreeSet<String> = visible()
        .flat_map(|c| c.shown.iter().chain([&c.name]))
        .flat_map(|s| numbers(s))
        .collect();
    let expected: BTreeSet<String> = visible()
        .flat_map(|c| c.failures.iter().chain([&c.summary]))
        .flat_map(|m| numbers(m))
        .filter(|n| !safe.contains(n))
        .collect();
    // In full, the JSON report is the instructor's record (a class run's
    // `students/<name>.json`), hidden cases and all; every other format is the student's.
    let students = |report: &GradeReport| {
        rendered(report)
            .into_iter()
            .filter(|(name, _)| report.feedback != Feedback::Full || *name != "JSON")
            .collect::<Vec<_>>()
    };
    let public_full: String = students(&full).into_iter().map(|(_, r)| r).collect();
    // Every number of a hidden case's message, but those a public case prints too.
    let hidden: BTreeSet<String> = full
        .tasks
        .iter()
        .flat_map(|t| &t.checks)
        .filter(|c| c.visibility == pbrlab::grade::verdict::Visibility::Hidden)
        .flat_map(|c| &c.failures)
        .flat_map(|f| numbers(f))
        .filter(|n| !writes(&public_full, n) && !safe.contains(n))
        .collect();
    assert!(
        expected.len() > 20,
        "too few expected values to test: {expected:?}"
    );
    assert!(
        hidden.len() > 20,
        "too few hidden inputs to test: {hidden:?}"
    );
    // The test can fail: the full report shows the expected values.
    let shown_in_full = expected.iter().filter(|n| writes(&public_full, n)).count();
    assert!(
        shown_in_full * 2 > expected.len(),
        "{shown_in_full}/{}",
        expected.len()
    );
    for (name, page) in students(&full) {
        let leaked: Vec<&String> = hidden.iter().filter(|n| writes(&page, n)).collect();
        assert!(
            leaked.is_empty(),
            "full {name} report shows hidden inputs {leaked:?}"
        );
    }
    for level in [Feedback::Actual, Feedback::None] {
        let shown = redact(&full, level);
        assert_eq!(shown.score, full.score, "{level:?} changes no points");
        for (name, page) in rendered(&shown) {
            let leaked: Vec<&String> = expected
                .iter()
                .chain(&hidden)
                .filter(|n| writes(&page, n))
                .collect();
            let context: Vec<&str> = leaked
                .iter()
                .flat_map(|n| page.lines().filter(|l| writes(l, n)))
                .collect();
            assert!(
                leaked.is_empty(),
                "{level:?}: the {name} report shows {} values a student must not see: \
                 {leaked:?}, in:\n{}",
                leaked.len(),
                context.join("\n")
            );
            for word in ["expected ", "analytic", "reference "] {
                let lower = page.to_lowercase();
                let at = lower.match_indices(word).find(|(i, _)| {
                    lower[i + word.len()..]
                        .chars()
                        .next()
                        .is_some_and(|c| c.is_ascii_digit() || c == '(' || c == '-')
                });
                assert!(
                    at.is_none(),
                    "{level:?}: the {name} report names a value after `{word}`"
                );
            }
        }
    }
    // At `actual`, a failing value case still shows its input and what came back.
    let actual = text(&redact(&full, Feedback::Actual), Detail::Verbose);
    assert!(actual.contains(": got "), "{actual}");
    let none = text(&redact(&full, Feedback::None), Detail::Verbose);
    assert!(!none.contains(": got "), "{none}");
}

/// A check's name is shown at every feedback level, so no name writes the value its check
/// expects: an estimator is named by what it estimates, never by its analytic answer. (A
/// number of three or more significant digits in a name, within 1e-3 of the answer, is
/// the answer; shorter ones are the inputs a name states, `ρ = 0.5`.)
#[test]
fn no_estimator_is_named_with_the_value_it_expects() {
    crate::support::install();
    let reference = pbrlab::implementation::reference();
    let digits = |n: &str| n.trim_start_matches(['0', '.']).replace('.', "").len();
    let mut named = Vec::new();
    for task in TaskId::ALL {
        for spec in pbrlab::grade::catalogue::estimators(task, reference) {
            let answer = spec.analytic;
            let written = spec.name.split(|c: char| !(c.is_ascii_digit() || c == '.'));
            if written
                .filter(|n| n.contains('.') && digits(n) >= 3)
                .filter_map(|n| n.trim_end_matches('.').parse::<f64>().ok())
                .any(|x| (x - answer).abs() <= 1e-3 * answer.abs())
            {
                named.push(format!("{task}: {} (expects {answer})", spec.name));
            }
        }
    }
    assert!(named.is_empty(), "{named:#?}");
}
