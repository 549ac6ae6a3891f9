use super::clock::timed;
use super::fit::{Fit, log_log};
use super::metrics::image_error;
use super::strategy::Strategy;
use crate::implementation::{is_todo_panic, panic_message};
use crate::panics::QuietPanics;
use anyhow::{Context, Result};
use indicatif::ProgressBar;
use serde::Serialize;
use std::panic::{AssertUnwindSafe, catch_unwind};

/// A study ready to run: its strategies and the reference they are measured against.
pub struct Study {
    /// What is being estimated, for the plot's title.
    pub title: String,
    /// The competing strategies.
    pub strategies: Vec<Box<dyn Strategy>>,
    /// The reference values, one per pixel channel.
    pub reference: Vec<f32>,
    /// How the reference was obtained, for the report.
    pub reference_note: String,
    /// The relMSE the reference's own noise adds to every measurement (0 for an exact
    /// reference). Measurements near it say more about the reference than the strategy:
    /// [`summarise`] leaves them out of the fits.
    pub reference_floor: f64,
}

/// The sample counts and seed of a study.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StudyConfig {
    /// Samples per pixel of the first level (≥ 1).
    pub min_spp: u32,
    /// Largest samples per pixel; the levels double from `min_spp` up to it.
    pub max_spp: u32,
    /// Seed of the first level; level `k` uses `seed + k`, so levels are independent.
    pub seed: u64,
}

impl StudyConfig {
    /// The sample counts: `min_spp`, doubled while it stays ≤ `max_spp`.
    pub fn levels(&self) -> Vec<u32> {
        let mut levels = Vec::new();
        let mut spp = self.min_spp.max(1);
        while spp <= self.max_spp {
            levels.push(spp);
            match spp.checked_mul(2) {
                Some(next) => spp = next,
                None => break,
            }
        }
        levels
    }
}

/// One strategy at one sample count: its cost and its error.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The strategy's name.
    pub strategy: String,
    /// Samples per pixel.
    pub spp: u32,
    /// Wall-clock seconds of the estimate.
    pub wall_s: f64,
    /// Process CPU seconds of the estimate, where the platform reports it.
    pub cpu_s: Option<f64>,
    /// Relative mean squared error against the reference.
    pub rel_mse: f64,
    /// Root mean squared error against the reference.
    pub rmse: f64,
    /// Inverse work-normalised error, `1 / (relMSE · wall seconds)`: higher is better.
    pub efficiency: f64,
    /// Values of the estimate that were NaN or infinite, plus samples the estimator
    /// dropped as NaN, infinite or negative.
    pub non_finite: u64,
}

/// A strategy that stopped: its estimate returned an error or panicked.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Failure {
    /// The strategy's name.
    pub strategy: String,
    /// The sample count it failed at.
    pub spp: u32,
    /// The error or panic message.
    pub message: String,
}

/// Everything a study measured.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct StudyResult {
    /// One point per strategy and level that completed.
    pub points: Vec<Point>,
    /// Strategies that failed; each is dropped from the levels after its failure.
    pub failures: Vec<Failure>,
}

/// Runs every strategy at every level of `config` and measures each estimate against
/// `reference`. Levels run in increasing order and, within a level, strategies run one
/// after the other, so a change in machine load affects every strategy alike.
/// `progress` advances once per estimate.
///
/// A strategy whose estimate fails or panics (student code at `todo!()`, say) is recorded
/// in [`StudyResult::failures`] and skipped from then on; the others carry on. A reference
/// of the wrong length is an error for the whole study.
pub fn run_study(
    strategies: &[&dyn Strategy],
    reference: &[f32],
    config: &StudyConfig,
    progress: &ProgressBar,
) -> Result<StudyResult> {
    run_study_reporting(strategies, reference, config, progress, &mut |_| {})
}

/// [`run_study`], handing what has been measured so far to `level_done` after each level,
/// so a caller can save it: a study stopped part-way keeps its finished levels.
pub fn run_study_reporting(
    strategies: &[&dyn Strategy],
    reference: &[f32],
    config: &StudyConfig,
    progress: &ProgressBar,
    level_done: &mut dyn FnMut(&StudyResult),
) -> Result<StudyResult> {
    let levels = config.levels();
    progress.set_length((levels.len() * strategies.len()) as u64);
    let mut result = StudyResult::default();
    for (k, &spp) in levels.iter().enumerate() {
        for s in strategies {
            if result.failures.iter().any(|f| f.strategy == s.name()) {
                progress.inc(1);
                continue;
            }
            progress.set_message(format!("{} at {spp} spp", s.name()));
            let seed = config.seed.wrapping_add(k as u64);
            let (estimate, timing) = timed(|| {
                let _quiet = QuietPanics::new();
                catch_unwind(AssertUnwindSafe(|| s.estimate(spp, seed)))
            });
            let estimate = match estimate {
                Ok(Ok(e)) => e,
                Ok(Err(e)) => {
                    result.failures.push(failure(*s, spp, format!("{e:#}")));
                    progress.inc(1);
                    continue;
                }
                Err(payload) => {
                    let message = if is_todo_panic(payload.as_ref()) {
                        "not attempted: a task it calls is still todo!()".to_owned()
                    } else {
                        let m = panic_message(payload.as_ref()).unwrap_or("non-string payload");
                        format!("panicked: {m}")
                    };
                    result.failures.push(failure(*s, spp, message));
                    progress.inc(1);
                    continue;
                }
            };
            let error = image_error(&estimate.values, reference)
                .with_context(|| format!("strategy {} at {spp} spp", s.name()))?;
            let wall_s = timing.wall.as_secs_f64();
            result.points.push(Point {
                strategy: s.name().to_owned(),
                spp,
                wall_s,
                cpu_s: timing.cpu.map(|d| d.as_secs_f64()),
                rel_mse: error.rel_mse,
                rmse: error.rmse,
                efficiency: 1.0 / (error.rel_mse * wall_s),
                non_finite: error.non_finite as u64 + estimate.dropped_samples,
            });
            progress.inc(1);
        }
        level_done(&result);
    }
    Ok(result)
}

fn failure(s: &dyn Strategy, spp: u32, message: String) -> Failure {
    Failure {
        strategy: s.name().to_owned(),
        spp,
        message,
    }
}

/// What a study says about one strategy.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// The strategy's name.
    pub strategy: String,
    /// Slope of log relMSE against log wall time over the upper levels (see
    /// [`upper_levels`]); about −1 for an unbiased estimator whose cost grows with spp.
    pub slope_time: Option<Fit>,
    /// Slope of log relMSE against log spp over the upper levels: −1 for an unbiased
    /// estimator, flattening towards 0 when bias dominates; free of timing noise.
    pub slope_spp: Option<Fit>,
    /// Median efficiency over the upper levels.
    pub efficiency: f64,
    /// relMSE at the largest sample count.
    pub final_rel_mse: f64,
    /// Non-finite values and dropped samples over all levels.
    pub non_finite: u64,
    /// Levels left out of the fits because their relMSE is within
    /// [`FLOOR_MARGIN`] × the reference's noise floor.
    pub at_floor: usize,
}

/// Levels whose relMSE is below this multiple of the reference's noise floor are left out
/// of the slope fits: there the reference's noise, not the strategy's, sets the error.
pub const FLOOR_MARGIN: f64 = 3.0;

/// A slope flatter than this over the upper levels is reported as flattening.
pub const FLATTENING_SLOPE: f64 = -0.75;

impl Summary {
    /// True when relMSE stops falling like 1/spp: the estimator is biased (or its
    /// reference is).
    pub fn flattening(&self) -> bool {
        self.slope_spp.is_some_and(|f| f.slope > FLATTENING_SLOPE)
    }
}

/// The points the slopes are fitted on: the upper half of the levels, and at least three
/// when there are that many. At low spp fixed costs (threads, setup) dominate the time,
/// which would steepen a fit against time.
pub fn upper_levels(points: &[&Point]) -> usize {
    let n = points.len();
    n.div_ceil(2).max(3.min(n))
}

/// One [`Summary`] per strategy, in order of first appearance. `reference_floor` is the
/// study's [`Study::reference_floor`]: the slopes are fitted to relMSE minus that floor,
/// on the levels above [`FLOOR_MARGIN`] times it.
pub fn summarise(points: &[Point], reference_floor: f64) -> Vec<Summary> {
    let mut names: Vec<&str> = Vec::new();
    for p in points {
        if !names.contains(&p.strategy.as_str()) {
            names.push(&p.strategy);
        }
    }
    names
        .into_iter()
        .map(|name| {
            let mut mine: Vec<&Point> = points.iter().filter(|p| p.strategy == name).collect();
            mine.sort_by_key(|p| p.spp);
            let above: Vec<&Point> = mine
                .iter()
                .copied()
                .filter(|p| p.rel_mse.is_nan() || p.rel_mse > FLOOR_MARGIN * reference_floor)
                .collect();
            let upper = &above[above.len() - upper_levels(&above)..];
            let col = |f: fn(&Point) -> f64| upper.iter().map(|p| f(p)).collect::<Vec<f64>>();
            let (time, spp) = (col(|p| p.wall_s), col(|p| p.spp as f64));
            // The measured relMSE is the strategy's plus the reference's own noise, which is
            // known: the fits take it out (the levels kept are well above it).
            let err: Vec<f64> = upper.iter().map(|p| p.rel_mse - reference_floor).collect();
            let mut eff = col(|p| p.efficiency);
            eff.sort_by(f64::total_cmp);
            Summary {
                strategy: name.to_owned(),
                slope_time: log_log(&time, &err),
                slope_spp: log_log(&spp, &err),
                efficiency: eff.get(eff.len() / 2).copied().unwrap_or(f64::NAN),
                final_rel_mse: mine.last().map_or(f64::NAN, |p| p.rel_mse),
                non_finite: mine.iter().map(|p| p.non_finite).sum(),
                at_floor: mine.len() - above.len(),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_double_up_to_the_maximum() {
        let c = StudyConfig {
            min_spp: 1,
            max_spp: 20,
            seed: 0,
        };
        assert_eq!(c.levels(), vec![1, 2, 4, 8, 16]);
        let c = StudyConfig {
            min_spp: 4,
            max_spp: 4,
            seed: 0,
        };
        assert_eq!(c.levels(), vec![4]);
        let c = StudyConfig {
            min_spp: 0,
            max_spp: u32::MAX,
            seed: 0,
        };
        assert_eq!(c.levels().len(), 32);
    }

    #[test]
    fn upper_levels_are_half_and_at_least_three() {
        let p = Point {
            strategy: String::new(),
            spp: 1,
            wall_s: 1.0,
            cpu_s: None,
            rel_mse: 1.0,
            rmse: 1.0,
            efficiency: 1.0,
            non_finite: 0,
        };
        let of = |n: usize| upper_levels(&vec![&p; n]);
        assert_eq!(
            (of(1), of(2), of(3), of(4), of(10), of(11)),
            (1, 2, 3, 3, 5, 6)
        );
    }

    #[test]
    fn the_references_own_noise_is_taken_out_of_the_slopes() {
        let floor = 1e-3;
        let points: Vec<Point> = [1u32, 2, 4, 8, 16, 32]
            .iter()
            .map(|&spp| Point {
                strategy: "s".into(),
                spp,
                wall_s: spp as f64,
                cpu_s: None,
                rel_mse: 0.1 / spp as f64 + floor,
                rmse: 0.0,
                efficiency: 1.0,
                non_finite: 0,
            })
            .collect();
        let s = &summarise(&points, floor)[0];
        let slope = s.slope_spp.expect("fitted").slope;
        assert!((slope + 1.0).abs() < 1e-9, "slope {slope}");
    }
}
