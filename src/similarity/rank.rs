//! All tasks: every pair's shared fingerprints and denominators summed over the tasks, and
//! the pairs ranked by the result.
//!
//! Summing before dividing weights each task by its size: a copied `mis` (150 lines) says
//! more than a matching `reflect` (one line), and a short task that every student writes
//! alike cannot push a pair up on its own.

use super::{Options, PairSummary, TaskComparison, TaskScore};
use std::collections::BTreeMap;

/// Sums every pair over `tasks` and ranks the pairs: aggregate score (highest first), then
/// shared fingerprints, then names. Lists every pair that shares a fingerprint in some task;
/// the denominator counts every task both students have a file for, shared or not.
pub fn rank(tasks: &[TaskComparison], options: &Options) -> Vec<PairSummary> {
    let mut pairs: BTreeMap<(&str, &str), Vec<TaskScore>> = BTreeMap::new();
    for task in tasks {
        for pair in &task.pairs {
            pairs
                .entry((pair.a.as_str(), pair.b.as_str()))
                .or_default()
                .push(TaskScore {
                    task: task.task.clone(),
                    shared: pair.shared,
                    score: pair.score,
                    flagged: pair.flagged,
                });
        }
    }
    let mut ranked: Vec<PairSummary> = pairs
        .into_iter()
        .map(|((a, b), scores)| {
            let compared: usize = tasks
                .iter()
                .filter_map(|t| Some(*t.fingerprints.get(a)?.min(t.fingerprints.get(b)?)))
                .sum();
            let shared: usize = scores.iter().map(|s| s.shared).sum();
            let score = if compared == 0 {
                0.0
            } else {
                (shared as f64 / compared as f64).min(1.0)
            };
            PairSummary {
                a: a.to_string(),
                b: b.to_string(),
                shared,
                compared,
                score,
                flagged: score >= options.aggregate_min_score
                    && shared >= options.aggregate_min_shared,
                flagged_tasks: scores.iter().filter(|s| s.flagged).count(),
                tasks: scores,
            }
        })
        .collect();
    ranked.sort_by(|x, y| {
        y.score
            .total_cmp(&x.score)
            .then(y.shared.cmp(&x.shared))
            .then_with(|| (&x.a, &x.b).cmp(&(&y.a, &y.b)))
    });
    ranked
}
