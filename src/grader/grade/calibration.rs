//! False-failure rates: grade one implementation (the reference) with many fresh seeds and
//! count how often each task fails, against the rate its checks declare.
//!
//! Every statistical sub-test also records its p-value; for a correct implementation these
//! are uniform on [0, 1], so the share below 5 % (or 1 %) should be about 5 % (1 %). That
//! shows the calibration with far fewer runs than observing the declared rate itself.

use super::image_check;
use super::isolation::Launcher;
use super::renders::RENDER_CHECKS;
use super::runner::{GradeOptions, grade, scene_entry};
use super::verdict::TaskStatus;
use serde::{Deserialize, Serialize};
use statrs::distribution::{Binomial, DiscreteCDF};
use std::fmt::Write;

/// The rates of one task over all runs.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TaskRates {
    /// The task id.
    pub task: String,
    /// Runs in which the task did not pass.
    pub failures: usize,
    /// The false-failure rate its checks declare (0 for tasks without statistical checks);
    /// a scene's includes the rates of the tasks its render waits for.
    pub declared_alpha: f64,
    /// The p-values of every statistical sub-test in every run.
    pub p_values: Vec<f64>,
    /// One message from a failing run, if any.
    pub example: Option<String>,
}

impl TaskRates {
    /// P(at least `failures` failures in `runs` runs) if the true rate were `declared_alpha`.
    pub fn excess_p_value(&self, runs: usize) -> f64 {
        if self.failures == 0 {
            return 1.0;
        }
        if self.declared_alpha <= 0.0 {
            return 0.0;
        }
        Binomial::new(self.declared_alpha, runs as u64)
            .map_or(0.0, |b| b.sf(self.failures as u64 - 1))
    }

    /// Share of the sub-test p-values below `level`.
    pub fn share_below(&self, level: f64) -> f64 {
        if self.p_values.is_empty() {
            return 0.0;
        }
        self.p_values.iter().filter(|&&p| p < level).count() as f64 / self.p_values.len() as f64
    }
}

/// Failure counts per task over `runs` gradings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Calibration {
    /// Number of gradings.
    pub runs: usize,
    /// Per task.
    pub tasks: Vec<TaskRates>,
}

/// Grades with seeds `options.seed`, `options.seed + 1`, … `runs` times, and hidden seeds
/// `options.hidden_seed`, `options.hidden_seed + 1`, … where one is given.
pub fn repeat(
    options: &GradeOptions,
    launcher: &Launcher,
    runs: usize,
) -> anyhow::Result<Calibration> {
    let mut tasks: Vec<TaskRates> = Vec::new();
    for k in 0..runs {
        let seeded = GradeOptions {
            seed: options.seed.wrapping_add(k as u64),
            hidden_seed: options.hidden_seed.map(|h| h.wrapping_add(k as u64)),
            ..options.clone()
        };
        let report = grade(&seeded, launcher)?;
        for t in &report.tasks {
            let rates = match tasks.iter().position(|r| r.task == t.task) {
                Some(i) => &mut tasks[i],
                None => {
                    tasks.push(TaskRates {
                        task: t.task.clone(),
                        failures: 0,
                        declared_alpha: 0.0,
                        p_values: Vec::new(),
                        example: None,
                    });
                    tasks.last_mut().expect("just pushed")
                }
            };
            rates.declared_alpha = rates
                .declared_alpha
                .max(either(t.checks.iter().map(|c| c.alpha)));
            rates
                .p_values
                .extend(t.checks.iter().flat_map(|c| c.p_values.iter().copied()));
            if !matches!(t.status, TaskStatus::Passed | TaskStatus::NoChecks) {
                rates.failures += 1;
                if rates.example.is_none() {
                    rates.example = Some(format!(
                        "seed {}:\n{}",
                        seeded.seed,
                        super::report::details(t)
                    ));
                }
            }
        }
    }
    declare_scene_rates(&mut tasks);
    Ok(Calibration { runs, tasks })
}

/// The probability that at least one of independent events with probabilities `alphas`
/// happens: 1 − ∏(1 − α).
fn either(alphas: impl IntoIterator<Item = f64>) -> f64 {
    1.0 - alphas.into_iter().map(|a| 1.0 - a).product::<f64>()
}

/// A scene's render is graded only once every task it needs has passed, so a false failure
/// of one of those tasks fails the scene too: its declared rate is that of its image check
/// or of any task it waits for.
fn declare_scene_rates(tasks: &mut [TaskRates]) {
    for check in RENDER_CHECKS {
        let Ok(needs) = super::renders::needs(check.scene) else {
            continue;
        };
        let waits_for: Vec<f64> = tasks
            .iter()
            .filter(|r| needs.iter().any(|n| n.name() == r.task))
            .map(|r| r.declared_alpha)
            .collect();
        if let Some(scene) = tasks
            .iter_mut()
            .find(|r| r.task == scene_entry(check.scene))
        {
            scene.declared_alpha = either(std::iter::once(image_check::ALPHA).chain(waits_for));
        }
    }
}

impl Calibration {
    /// Tasks that fail significantly more often than they declare (binomial tail below
    /// `significance`).
    pub fn excessive(&self, significance: f64) -> Vec<&TaskRates> {
        self.tasks
            .iter()
            .filter(|t| t.excess_p_value(self.runs) < significance)
            .collect()
    }

    /// A table: failures, observed and declared rate, and the p-value shares.
    pub fn text(&self) -> String {
        let mut s = format!(
            "{:<16} {:>9} {:>9} {:>9} {:>10} {:>9} {:>9}\n",
            "task", "failures", "rate", "declared", "P(excess)", "p<5%", "p<1%"
        );
        for t in &self.tasks {
            let shares = if t.p_values.is_empty() {
                format!("{:>9} {:>9}", "-", "-")
            } else {
                format!(
                    "{:>8.1}% {:>8.1}%",
                    100.0 * t.share_below(0.05),
                    100.0 * t.share_below(0.01)
                )
            };
            let _ = writeln!(
                s,
                "{:<16} {:>9} {:>9.4} {:>9.4} {:>10.3} {shares}",
                t.task,
                format!("{}/{}", t.failures, self.runs),
                t.failures as f64 / self.runs.max(1) as f64,
                t.declared_alpha,
                t.excess_p_value(self.runs),
            );
        }
        for t in &self.tasks {
            if let Some(example) = &t.example {
                let _ = writeln!(s, "{}, first failure at {}", t.task, example.trim_end());
            }
        }
        let p: Vec<f64> = self
            .tasks
            .iter()
            .flat_map(|t| t.p_values.iter().copied())
            .collect();
        if !p.is_empty() {
            let below =
                |level: f64| p.iter().filter(|&&x| x < level).count() as f64 / p.len() as f64;
            let _ = writeln!(
                s,
                "all {} statistical sub-tests: {:.1}% of p-values < 5%, {:.1}% < 1% (uniform: 5%, 1%)",
                p.len(),
                100.0 * below(0.05),
                100.0 * below(0.01)
            );
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rates(task: &str, declared_alpha: f64) -> TaskRates {
        TaskRates {
            task: task.into(),
            failures: 0,
            declared_alpha,
            p_values: Vec::new(),
            example: None,
        }
    }

    #[test]
    fn a_scene_declares_the_rates_of_the_tasks_it_waits_for() {
        let mut tasks = vec![
            rates("reflect", 0.0),
            rates("cosine_sample", 1e-3),
            rates("path_trace", 1e-3),
            rates(&scene_entry("cornell"), 0.0),
        ];
        declare_scene_rates(&mut tasks);
        let needs = super::super::renders::needs("cornell").expect("cornell loads");
        let waits = ["cosine_sample", "path_trace"]
            .iter()
            .filter(|t| needs.iter().any(|n| n.name() == **t))
            .count();
        assert!(waits > 0, "cornell needs {needs:?}");
        let expected = 1.0 - (1.0 - image_check::ALPHA) * (1.0 - 1e-3f64).powi(waits as i32);
        assert!((tasks[3].declared_alpha - expected).abs() < 1e-15);
        assert_eq!(tasks[0].declared_alpha, 0.0);
    }
}
