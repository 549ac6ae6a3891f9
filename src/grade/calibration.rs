//! False-failure rates: grade one implementation (the reference) with many fresh seeds and
//! count how often each task fails, against the rate its checks declare.
//!
//! Every statistical sub-test also records its p-value; for a correct implementation these
//! are uniform on [0, 1], so the share below 5 % (or 1 %) should be about 5 % (1 %). That
//! shows the calibration with far fewer runs than observing the declared rate itself.

use super::isolation::Launcher;
use super::runner::{GradeOptions, grade};
use super::verdict::{CheckKind, TaskStatus};
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
    /// The false-failure rate its checks declare (0 for tasks without statistical checks).
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

/// Grades with seeds `options.seed`, `options.seed + 1`, … `runs` times.
pub fn repeat(
    options: &GradeOptions,
    launcher: &Launcher,
    runs: usize,
) -> anyhow::Result<Calibration> {
    let mut tasks: Vec<TaskRates> = Vec::new();
    for k in 0..runs {
        let seeded = GradeOptions {
            seed: options.seed.wrapping_add(k as u64),
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
            let statistical = t
                .checks
                .iter()
                .any(|c| matches!(c.kind, CheckKind::Sampling | CheckKind::Estimator));
            rates.declared_alpha = if statistical {
                super::checks::TASK_ALPHA
            } else {
                0.0
            };
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
    Ok(Calibration { runs, tasks })
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
                "{:<16} {:>9} {:>9.4} {:>9} {:>10.3} {shares}",
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
