//! Per-student variants (`--variant-key`): two students share under 10 % of their hidden
//! numeric targets. (That the reference fails no more often than declared across students'
//! seeds and hidden cases is measured by the calibration test, whose runs each grade a new
//! pair of them.)

use pbrlab::grade::output::Output;
use pbrlab::grade::value_cases::{evaluate, hidden_inputs};
use pbrlab::grade::variant::Variant;
use pbrlab::worksheet::TaskId;
use pbrlab_solutions::TASKS as Reference;
use rayon::prelude::*;
use std::collections::BTreeSet;

/// The course secret of these tests.
const KEY: &str = "a course secret";

/// Every number of `out`.
fn numbers(out: &Output) -> Vec<f64> {
    match out {
        Output::Nothing => Vec::new(),
        Output::Number(x) => vec![*x],
        Output::Numbers(v) => v.clone(),
        Output::Record(m) => m.values().flat_map(numbers).collect(),
    }
}

/// The distinct numeric targets of a student's hidden cases of `task`: the bits of every
/// number the reference answers them with, where the answer is judged by its value (a
/// plausibility report or a reciprocity gap is judged by its verdict: not a target).
fn targets(task: TaskId, variant: &Variant) -> BTreeSet<u64> {
    let cases = evaluate(&hidden_inputs(task, variant.hidden_seed), &Reference).unwrap();
    cases
        .iter()
        .filter(|c| !c.rule.judges_verdicts())
        .flat_map(|c| numbers(&c.expected))
        .map(|x| if x == 0.0 { 0 } else { x.to_bits() })
        .collect()
}

#[test]
fn two_students_share_under_a_tenth_of_their_hidden_targets() {
    let students: Vec<Variant> = (0..24)
        .map(|i| Variant::of(KEY, &format!("student{i}")))
        .collect();
    let ids: BTreeSet<&str> = students.iter().map(|v| v.id.as_str()).collect();
    assert_eq!(ids.len(), students.len(), "every variant has its own id");
    let mut report = String::from("task | targets per student | largest share between two\n");
    let mut worst_overall = 0.0_f64;
    let pairs = students.len() * (students.len() - 1) / 2;
    let (mut all_shared, mut all_total) = (vec![0usize; pairs], vec![0usize; pairs]);
    for task in TaskId::ALL {
        let sets: Vec<BTreeSet<u64>> = students.par_iter().map(|v| targets(task, v)).collect();
        if sets.iter().all(BTreeSet::is_empty) {
            continue;
        }
        let mut worst = 0.0_f64;
        let mut pair = 0;
        for a in 0..sets.len() {
            for b in a + 1..sets.len() {
                let shared = sets[a].intersection(&sets[b]).count();
                let size = sets[a].len().min(sets[b].len()).max(1);
                worst = worst.max(shared as f64 / size as f64);
                all_shared[pair] += shared;
                all_total[pair] += size;
                pair += 1;
            }
        }
        worst_overall = worst_overall.max(worst);
        report += &format!("{task} | {} | {:.1} %\n", sets[0].len(), 100.0 * worst);
    }
    let overall = all_shared
        .iter()
        .zip(&all_total)
        .map(|(s, t)| *s as f64 / (*t).max(1) as f64)
        .fold(0.0, f64::max);
    println!(
        "{report}all tasks: largest share between two students {:.2} %",
        100.0 * overall
    );
    assert!(
        overall < 0.10,
        "two students share {:.1} % of their hidden targets:\n{report}",
        100.0 * overall
    );
    // And no task alone comes near it.
    assert!(worst_overall < 0.10, "{report}");
}
