//! The power of the statistical checks (`pbrlab power`): how often each task's estimator
//! and sampling checks, and each scene's render check, catch an error of known size put into
//! an implementation (the reference), over many seeds, beside how often they fail it as it
//! is (the false-failure rate).
//!
//! The errors, at each of [`LEVELS`]:
//! - estimators: a relative bias, every estimate times `1 + e`. A biased run's moments are
//!   the unbiased run's scaled, so one run per seed is judged at every level;
//! - samplers: a distortion of the first uniform number, `u.x^(1 + e)`, which moves samples
//!   the way a wrong warp does (the pdf is left alone); drawn anew per level;
//! - renders: a relative bias, every pixel's mean times `1 + e` and its variance times
//!   `(1 + e)²`; one render per seed.
//!
//! Each check is judged exactly as the grader judges it (same significance, same sample
//! counts), with seeds `0..seeds` in place of the grade's seed.

use super::catalogue;
use super::checks::statistical_alpha;
use super::estimator::{Measured, judge, measure};
use super::measure::SAMPLING_SAMPLES;
use super::render_check::stored_reference;
use super::renders::{RENDER_CHECKS, STUDENT_SPP, load, render_stats};
use super::sampling::{compare, draw};
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use anyhow::Context;
use glam::Vec2;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

/// The relative sizes of the injected errors; the first, none, measures false failures.
pub const LEVELS: [f64; 6] = [0.0, 0.005, 0.01, 0.02, 0.05, 0.10];

/// Per entry of [`LEVELS`], whether one seed's checks caught the error of that size.
type Caught = [bool; LEVELS.len()];

/// The share of seeds at which an error counts as caught.
pub const CAUGHT: f64 = 0.9;

/// What a row's checks are given.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Injection {
    /// Every estimate times `1 + e`.
    EstimatorBias,
    /// Samples drawn from `(u.x^(1 + e), u.y)`.
    SamplerDistortion,
    /// Every pixel times `1 + e`.
    RenderBias,
}

impl std::fmt::Display for Injection {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Injection::EstimatorBias => "estimators, bias",
            Injection::SamplerDistortion => "χ² sampling, distortion",
            Injection::RenderBias => "render, bias",
        })
    }
}

/// One row of the power table: a task's (or a scene's) checks of one kind.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PowerRow {
    /// The task, or `scene: NAME`.
    pub subject: String,
    /// What was injected.
    pub injection: Injection,
    /// How many checks of the kind judge it together (any failing fails the row).
    pub checks: usize,
    /// How many seeds each level was measured with.
    pub seeds: usize,
    /// Per entry of [`LEVELS`], at how many seeds a check failed.
    pub failures: Vec<usize>,
}

impl PowerRow {
    fn new(subject: String, injection: Injection, checks: usize, failed: &[Caught]) -> Self {
        let failures = (0..LEVELS.len())
            .map(|level| failed.iter().filter(|f| f[level]).count())
            .collect();
        PowerRow {
            subject,
            injection,
            checks,
            seeds: failed.len(),
            failures,
        }
    }

    /// The share of seeds at which the error of `LEVELS[level]` was caught.
    pub fn rate(&self, level: usize) -> f64 {
        self.failures[level] as f64 / self.seeds.max(1) as f64
    }

    /// The share of seeds at which the checks failed with no error injected.
    pub fn false_failure_rate(&self) -> f64 {
        self.rate(0)
    }

    /// The smallest injected error caught at [`CAUGHT`] of the seeds, if any.
    pub fn smallest_caught(&self) -> Option<f64> {
        (1..LEVELS.len())
            .find(|&level| self.rate(level) >= CAUGHT)
            .map(|level| LEVELS[level])
    }

    /// The share of seeds at which an error of `size` (one of [`LEVELS`]) was caught.
    pub fn rate_at(&self, size: f64) -> Option<f64> {
        LEVELS
            .iter()
            .position(|&l| l == size)
            .map(|level| self.rate(level))
    }
}

/// The estimator checks of `task` on `t` with every estimate biased, or `None` when the task
/// has none.
pub fn estimator_power<T: Tasks + Sync>(task: TaskId, t: &T, seeds: usize) -> Option<PowerRow> {
    let checks = catalogue::estimators(task, t).len();
    if checks == 0 {
        return None;
    }
    let alpha = statistical_alpha(task, catalogue::sampling_setups(task).len(), t);
    let failed: Vec<Caught> = (0..seeds as u64)
        .into_par_iter()
        .map(|seed| {
            let mut failed = [false; LEVELS.len()];
            for (index, mut spec) in catalogue::estimators(task, t).into_iter().enumerate() {
                let seed = (seed, 200 + index as u64);
                let run = measure(spec.analytic, spec.samples, seed, spec.estimate.as_mut());
                for (level, e) in LEVELS.iter().enumerate() {
                    let biased = run.clone().map(|m| Measured {
                        moments: m.moments.scaled(1.0 + e),
                        ..m
                    });
                    failed[level] |=
                        judge(&spec.name, spec.analytic, spec.samples, alpha, biased).is_err();
                }
            }
            failed
        })
        .collect();
    Some(PowerRow::new(
        task.name().into(),
        Injection::EstimatorBias,
        checks,
        &failed,
    ))
}

/// The sampling checks of `task` on `t` with the sampler distorted, or `None` when the task
/// has none.
pub fn sampler_power<T: Tasks + Sync>(task: TaskId, t: &T, seeds: usize) -> Option<PowerRow> {
    let calls = catalogue::sampling_setups(task);
    if calls.is_empty() {
        return None;
    }
    let alpha = statistical_alpha(task, calls.len(), t);
    let targets: Vec<_> = calls.iter().map(|c| c.target(t)).collect();
    let failed: Vec<Caught> = (0..seeds as u64)
        .into_par_iter()
        .map(|seed| {
            let mut failed = [false; LEVELS.len()];
            for (level, e) in LEVELS.iter().enumerate() {
                let exponent = 1.0 + *e as f32;
                for (index, (call, target)) in calls.iter().zip(&targets).enumerate() {
                    let mut sampler = Sampler::new(seed, 100 + index as u64);
                    let counts = draw(
                        call.bins(),
                        call.rejects(),
                        SAMPLING_SAMPLES,
                        &mut sampler,
                        |u| call.sample(t, Vec2::new(u.x.powf(exponent), u.y)),
                    );
                    failed[level] |= counts.map_or(true, |c| {
                        compare(target, &c, SAMPLING_SAMPLES, alpha).is_err()
                    });
                }
            }
            failed
        })
        .collect();
    Some(PowerRow::new(
        task.name().into(),
        Injection::SamplerDistortion,
        calls.len(),
        &failed,
    ))
}

/// The render check of every graded scene on `t` with the render biased: one render per
/// seed, each compared with the stored reference render at every level.
pub fn render_power<T: Tasks + Sync>(t: &T, seeds: usize) -> anyhow::Result<Vec<PowerRow>> {
    let mut rows = Vec::new();
    for check in RENDER_CHECKS {
        let scene = load(check.scene)?;
        let stored = stored_reference(check.scene)?
            .with_context(|| format!("no stored reference render of {}", check.scene))?;
        let mut failed = Vec::with_capacity(seeds);
        for seed in 0..seeds as u64 {
            let (fresh, _) = render_stats(&scene, t, STUDENT_SPP, seed);
            let mut row = [false; LEVELS.len()];
            for (level, e) in LEVELS.iter().enumerate() {
                let mut biased = fresh.clone();
                let factor = 1.0 + *e as f32;
                biased.mean.iter_mut().for_each(|m| *m *= factor);
                biased
                    .variance
                    .iter_mut()
                    .for_each(|v| *v *= factor * factor);
                row[level] = super::image_check::compare(check.scene, &biased, &stored)
                    .map_or(true, |(detail, _)| !detail.passed());
            }
            failed.push(row);
        }
        rows.push(PowerRow::new(
            format!("scene: {}", check.scene),
            Injection::RenderBias,
            1,
            &failed,
        ));
    }
    Ok(rows)
}

/// The power rows of `tasks` on `t`: estimators, then samplers, task by task.
pub fn task_power<T: Tasks + Sync>(tasks: &[TaskId], t: &T, seeds: usize) -> Vec<PowerRow> {
    tasks
        .iter()
        .flat_map(|&task| {
            [
                estimator_power(task, t, seeds),
                sampler_power(task, t, seeds),
            ]
        })
        .flatten()
        .collect()
}

/// The table: per row the false failures, the detection rate at each level and the
/// smallest error caught at [`CAUGHT`] of the seeds.
pub fn table(rows: &[PowerRow]) -> String {
    use std::fmt::Write;
    let mut out = format!(
        "{:<18} {:<24} {:>6} {:>16}",
        "task", "checks (injected)", "seeds", "false failures"
    );
    for level in &LEVELS[1..] {
        let _ = write!(out, " {:>6}", format!("{}%", level * 100.0));
    }
    let _ = writeln!(out, "  caught ≥ {:.0} %", CAUGHT * 100.0);
    for row in rows {
        let _ = write!(
            out,
            "{:<18} {:<24} {:>6} {:>16}",
            row.subject,
            row.injection.to_string(),
            row.seeds,
            format!(
                "{}/{} ({:.1} %)",
                row.failures[0],
                row.seeds,
                row.false_failure_rate() * 100.0
            )
        );
        for level in 1..LEVELS.len() {
            let _ = write!(out, " {:>6}", format!("{:.0}%", row.rate(level) * 100.0));
        }
        let caught = row
            .smallest_caught()
            .map_or("not at 10 %".to_string(), |e| format!("{} %", e * 100.0));
        let _ = writeln!(out, "  {caught}");
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_smallest_error_caught_is_the_first_level_at_the_rate() {
        let failed: Vec<Caught> = (0..10)
            .map(|i| [false, false, i < 5, i < 9, true, true])
            .collect();
        let row = PowerRow::new("x".into(), Injection::EstimatorBias, 1, &failed);
        assert_eq!(row.failures, [0, 0, 5, 9, 10, 10]);
        assert_eq!(row.false_failure_rate(), 0.0);
        assert_eq!(row.smallest_caught(), Some(0.02));
        assert_eq!(row.rate_at(0.01), Some(0.5));
        assert!(table(&[row]).contains("2 %"));
    }
}
