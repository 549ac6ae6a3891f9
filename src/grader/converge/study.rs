//! Running a convergence study: every strategy at growing sample counts, timed and
//! measured.

use super::clock::timed;
use super::fit::{Fit, log_log};
use super::metrics::{ImageError, REL_MSE_EPSILON, image_error};
use super::strategy::{Estimate, Strategy};
use crate::implementation::{is_todo_panic, panic_message};
use crate::panics::QuietPanics;
use anyhow::{Context, Result};
use indicatif::ProgressBar;
use serde::Serialize;
use statrs::distribution::{ContinuousCDF, StudentsT};
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
    /// Seed of the first run of the first level; run `r` of level `k` uses
    /// `seed + k · runs + r`, so every run is independent.
    pub seed: u64,
    /// Independent runs per level (≥ 1). Their mean relMSE has a confidence interval and
    /// their spread separates variance from bias from two runs on.
    pub runs: u32,
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

/// One strategy at one sample count, over [`StudyConfig::runs`] independent runs: its
/// cost and its error, with the error split into variance and bias.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The strategy's name.
    pub strategy: String,
    /// Samples per pixel.
    pub spp: u32,
    /// Independent runs measured.
    pub runs: u32,
    /// Wall-clock seconds of one estimate (mean over the runs).
    pub wall_s: f64,
    /// Process CPU seconds of one estimate, where the platform reports it.
    pub cpu_s: Option<f64>,
    /// Relative mean squared error against the reference (mean over the runs): the
    /// expected relMSE of one estimate.
    pub rel_mse: f64,
    /// 95 % confidence interval of `rel_mse` (Student's t over the runs, cut at 0; the
    /// point itself with one run).
    pub rel_mse_interval: (f64, f64),
    /// The variance part of relMSE: every pixel-channel's variance over the runs,
    /// weighted as relMSE weighs errors. NaN with one run.
    pub rel_var: f64,
    /// `rel_mse − rel_var`: the squared bias the runs show, plus the reference's own noise
    /// (which [`Summary`] takes out). NaN with one run.
    pub rel_bias2: f64,
    /// Standard error of `rel_bias2` over the pixel-channels.
    pub rel_bias2_se: f64,
    /// Root mean squared error against the reference (mean over the runs).
    pub rmse: f64,
    /// Inverse work-normalised error, `1 / (relMSE · wall seconds)`: higher is better.
    pub efficiency: f64,
    /// Values of the estimates that were NaN or infinite, plus samples the estimator
    /// dropped as NaN, infinite or negative (over all runs).
    pub non_finite: u64,
}

/// Running moments of every value of an estimate over the runs, and what they say.
struct Spread {
    /// Runs added.
    runs: u32,
    /// Per value: mean and sum of squared deviations (Welford); NaN once a run gave a
    /// non-finite value there.
    mean: Vec<f64>,
    m2: Vec<f64>,
}

impl Spread {
    fn new(len: usize) -> Self {
        Self {
            runs: 0,
            mean: vec![0.0; len],
            m2: vec![0.0; len],
        }
    }

    fn add(&mut self, values: &[f32]) {
        self.runs += 1;
        let n = self.runs as f64;
        for ((mean, m2), &x) in self.mean.iter_mut().zip(&mut self.m2).zip(values) {
            let x = if x.is_finite() { x as f64 } else { f64::NAN };
            let delta = x - *mean;
            *mean += delta / n;
            *m2 += delta * (x - *mean);
        }
    }

    /// `(rel_var, rel_bias2, its standard error)` against `reference`: per value the
    /// variance over the runs `v` and the unbiased squared bias `(m − r)² − v/runs`,
    /// weighted by `1/(r² + ε)` and averaged over the values that stayed finite.
    fn split(&self, reference: &[f32]) -> (f64, f64, f64) {
        if self.runs < 2 {
            return (f64::NAN, f64::NAN, f64::NAN);
        }
        let runs = self.runs as f64;
        let (mut var, mut terms) = (0.0, Vec::with_capacity(self.mean.len()));
        for ((&m, &m2), &r) in self.mean.iter().zip(&self.m2).zip(reference) {
            if !(m.is_finite() && m2.is_finite()) {
                continue;
            }
            let (r, v) = (r as f64, m2 / (runs - 1.0));
            let w = 1.0 / (r * r + REL_MSE_EPSILON);
            var += w * v;
            terms.push(w * ((m - r) * (m - r) - v / runs));
        }
        let n = terms.len().max(1) as f64;
        let bias2 = terms.iter().sum::<f64>() / n;
        let spread = terms.iter().map(|t| (t - bias2).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
        (var / n, bias2, (spread / n).sqrt())
    }
}

/// The mean of `xs` and its 95 % confidence interval (Student's t); the interval is the
/// point itself for a single value.
fn mean_interval(xs: &[f64]) -> (f64, (f64, f64)) {
    let n = xs.len() as f64;
    let mean = xs.iter().sum::<f64>() / n;
    if xs.len() < 2 {
        return (mean, (mean, mean));
    }
    let sd = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let t = StudentsT::new(0.0, 1.0, n - 1.0)
        .map(|d| d.inverse_cdf(0.975))
        .unwrap_or(1.96);
    let half = t * sd / n.sqrt();
    // An error is never negative: a heavy-tailed run can push the symmetric interval
    // below 0.
    (mean, ((mean - half).max(0.0), mean + half))
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
    let runs = config.runs.max(1);
    progress.set_length((levels.len() * strategies.len() * runs as usize) as u64);
    let mut result = StudyResult::default();
    for (k, &spp) in levels.iter().enumerate() {
        for s in strategies {
            if result.failures.iter().any(|f| f.strategy == s.name()) {
                progress.inc(runs as u64);
                continue;
            }
            progress.set_message(format!("{} at {spp} spp", s.name()));
            let mut measured = Runs::new(reference.len());
            for r in 0..runs {
                let seed = config
                    .seed
                    .wrapping_add(k as u64 * runs as u64)
                    .wrapping_add(r as u64);
                progress.inc(1);
                match run_once(*s, spp, seed, reference)? {
                    Ok(run) => measured.add(run),
                    Err(message) => {
                        result.failures.push(failure(*s, spp, message));
                        progress.inc(u64::from(runs - r - 1));
                        break;
                    }
                }
            }
            if measured.spread.runs == runs {
                result.points.push(measured.point(s.name(), spp, reference));
            }
        }
        level_done(&result);
    }
    Ok(result)
}

/// One estimate, timed and measured.
struct Run {
    estimate: Estimate,
    error: ImageError,
    wall_s: f64,
    cpu_s: Option<f64>,
}

/// Runs `s` once: `Ok(Err(message))` when the strategy failed or panicked (student code at
/// `todo!()`, say), `Err` when the estimate cannot be measured against `reference`.
fn run_once(
    s: &dyn Strategy,
    spp: u32,
    seed: u64,
    reference: &[f32],
) -> Result<Result<Run, String>> {
    let (estimate, timing) = timed(|| {
        let _quiet = QuietPanics::new();
        catch_unwind(AssertUnwindSafe(|| s.estimate(spp, seed)))
    });
    let estimate = match estimate {
        Ok(Ok(e)) => e,
        Ok(Err(e)) => return Ok(Err(format!("{e:#}"))),
        Err(payload) => {
            return Ok(Err(if is_todo_panic(payload.as_ref()) {
                "not attempted: a task it calls is still todo!()".to_owned()
            } else {
                let m = panic_message(payload.as_ref()).unwrap_or("non-string payload");
                format!("panicked: {m}")
            }));
        }
    };
    let error = image_error(&estimate.values, reference)
        .with_context(|| format!("strategy {} at {spp} spp", s.name()))?;
    Ok(Ok(Run {
        estimate,
        error,
        wall_s: timing.wall.as_secs_f64(),
        cpu_s: timing.cpu.map(|d| d.as_secs_f64()),
    }))
}

/// The runs of one strategy at one level.
struct Runs {
    spread: Spread,
    rel_mse: Vec<f64>,
    rmse: Vec<f64>,
    wall_s: Vec<f64>,
    cpu_s: Vec<Option<f64>>,
    non_finite: u64,
}

impl Runs {
    fn new(len: usize) -> Self {
        Self {
            spread: Spread::new(len),
            rel_mse: Vec::new(),
            rmse: Vec::new(),
            wall_s: Vec::new(),
            cpu_s: Vec::new(),
            non_finite: 0,
        }
    }

    fn add(&mut self, run: Run) {
        self.spread.add(&run.estimate.values);
        self.rel_mse.push(run.error.rel_mse);
        self.rmse.push(run.error.rmse);
        self.wall_s.push(run.wall_s);
        self.cpu_s.push(run.cpu_s);
        self.non_finite += run.error.non_finite as u64 + run.estimate.dropped_samples;
    }

    fn point(&self, strategy: &str, spp: u32, reference: &[f32]) -> Point {
        let n = self.rel_mse.len() as f64;
        let (rel_mse, rel_mse_interval) = mean_interval(&self.rel_mse);
        let wall_s = self.wall_s.iter().sum::<f64>() / n;
        let (rel_var, rel_bias2, rel_bias2_se) = self.spread.split(reference);
        let cpu: Option<Vec<f64>> = self.cpu_s.iter().copied().collect();
        Point {
            strategy: strategy.to_owned(),
            spp,
            runs: self.spread.runs,
            wall_s,
            cpu_s: cpu.map(|c| c.iter().sum::<f64>() / n),
            rel_mse,
            rel_mse_interval,
            rel_var,
            rel_bias2,
            rel_bias2_se,
            rmse: self.rmse.iter().sum::<f64>() / n,
            efficiency: 1.0 / (rel_mse * wall_s),
            non_finite: self.non_finite,
        }
    }
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
    /// Its 95 % confidence interval over the runs.
    pub final_interval: (f64, f64),
    /// Non-finite values and dropped samples over all levels.
    pub non_finite: u64,
    /// Levels left out of the fits because their relMSE is within
    /// [`FLOOR_MARGIN`] × the reference's noise floor.
    pub at_floor: usize,
    /// The bias test at the largest sample count (two runs or more).
    pub bias: Option<BiasTest>,
    /// Seconds of work for a relative variance of 1 (`wall_s · rel_var`, the median over
    /// the upper levels): the cost of the strategy's noise, free of its bias.
    pub time_to_unit_variance: Option<f64>,
}

/// Whether the runs at the largest sample count show bias: the squared bias they
/// estimate (`rel_bias2` less the reference's own noise) against its standard error over
/// the pixel-channels, and against the variance of one estimate. Unbiased, the estimate is
/// 0 up to noise; the test is one-sided, since bias only adds error.
///
/// Heavy-tailed estimators (light or BSDF sampling alone on glossy surfaces) make the
/// per-pixel terms skewed, so their standard error is underestimated and z alone raises
/// false alarms (z of 3–6 was seen on unbiased strategies of veach_mis and smoke). The
/// verdict therefore also asks that the bias be material: at least as large as the noise
/// of one estimate, which is what makes relMSE stop falling like 1/spp. A smaller but
/// significant bias is reported as possible, to be confirmed at more samples.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BiasTest {
    /// `√max(0, relMSE − variance − reference noise)`: the relative RMS bias.
    pub bias: f64,
    /// The estimated squared bias in standard errors.
    pub z: f64,
    /// The variance part of relMSE there (`rel_var`): the noise the bias is weighed against.
    pub variance: f64,
}

/// A squared bias this many standard errors above 0 is significant (one-sided p ≈ 5 · 10⁻⁴
/// per strategy for well-behaved estimators).
pub const BIAS_Z: f64 = 3.29;

impl BiasTest {
    /// Significant: more than [`BIAS_Z`] standard errors.
    pub fn significant(&self) -> bool {
        self.z > BIAS_Z
    }

    /// Significant and material: the squared bias is at least the variance of one
    /// estimate, so the error no longer falls like 1/spp.
    pub fn biased(&self) -> bool {
        self.significant() && self.bias * self.bias >= self.variance
    }
}

/// Levels whose relMSE is below this multiple of the reference's noise floor are left out
/// of the slope fits: there the reference's noise, not the strategy's, sets the error.
pub const FLOOR_MARGIN: f64 = 3.0;

/// A slope flatter than this over the upper levels is reported as flattening.
pub const FLATTENING_SLOPE: f64 = -0.75;

impl Summary {
    /// True when relMSE stops falling like 1/spp: the estimator is biased (or its
    /// reference is), or its error is dominated by rare large samples.
    pub fn flattening(&self) -> bool {
        self.slope_spp.is_some_and(|f| f.slope > FLATTENING_SLOPE)
    }

    /// The verdict on bias: the bias test where there are runs to test, else the slope.
    pub fn biased(&self) -> bool {
        self.bias.map_or_else(|| self.flattening(), |b| b.biased())
    }
}

/// The points the slopes are fitted on: the upper half of the levels, and at least three
/// when there are that many. At low spp fixed costs (threads, setup) dominate the time,
/// which would steepen a fit against time.
pub fn upper_levels(points: &[&Point]) -> usize {
    let n = points.len();
    n.div_ceil(2).max(3.min(n))
}

/// The strategies of `points`, in order of first appearance.
pub fn strategy_names<'p>(points: impl IntoIterator<Item = &'p Point>) -> Vec<&'p str> {
    let mut names: Vec<&str> = Vec::new();
    for p in points {
        if !names.contains(&p.strategy.as_str()) {
            names.push(&p.strategy);
        }
    }
    names
}

/// One [`Summary`] per strategy, in order of first appearance. `reference_floor` is the
/// study's [`Study::reference_floor`]: the slopes are fitted to relMSE minus that floor,
/// on the levels above [`FLOOR_MARGIN`] times it.
pub fn summarise(points: &[Point], reference_floor: f64) -> Vec<Summary> {
    strategy_names(points)
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
            let mut unit: Vec<f64> = upper
                .iter()
                .map(|p| p.wall_s * p.rel_var)
                .filter(|t| t.is_finite())
                .collect();
            unit.sort_by(f64::total_cmp);
            let bias = mine
                .last()
                .filter(|p| p.rel_bias2.is_finite() && p.rel_bias2_se > 0.0)
                .map(|p| {
                    let b2 = p.rel_bias2 - reference_floor;
                    BiasTest {
                        bias: b2.max(0.0).sqrt(),
                        z: b2 / p.rel_bias2_se,
                        variance: p.rel_var,
                    }
                });
            Summary {
                strategy: name.to_owned(),
                slope_time: log_log(&time, &err),
                slope_spp: log_log(&spp, &err),
                efficiency: eff.get(eff.len() / 2).copied().unwrap_or(f64::NAN),
                final_rel_mse: mine.last().map_or(f64::NAN, |p| p.rel_mse),
                final_interval: mine
                    .last()
                    .map_or((f64::NAN, f64::NAN), |p| p.rel_mse_interval),
                non_finite: mine.iter().map(|p| p.non_finite).sum(),
                at_floor: mine.len() - above.len(),
                bias,
                time_to_unit_variance: unit.get(unit.len() / 2).copied(),
            }
        })
        .collect()
}

/// Every strategy's relMSE at one wall time, the longest that every strategy reached,
/// interpolated between its two nearest points on log-log axes (relMSE ∝ 1/time in
/// between, for an unbiased estimator). `None` without points.
pub fn equal_time(points: &[Point]) -> Option<(f64, Vec<(String, f64)>)> {
    let names = strategy_names(points);
    let curves: Vec<(&str, Vec<&Point>)> = names
        .into_iter()
        .map(|name| {
            let mut mine: Vec<&Point> = points
                .iter()
                .filter(|p| p.strategy == name && p.wall_s > 0.0 && p.rel_mse > 0.0)
                .collect();
            mine.sort_by(|a, b| a.wall_s.total_cmp(&b.wall_s));
            (name, mine)
        })
        .filter(|(_, mine)| !mine.is_empty())
        .collect();
    let time = curves
        .iter()
        .map(|(_, mine)| mine.last().map_or(0.0, |p| p.wall_s))
        .fold(f64::INFINITY, f64::min);
    if curves.is_empty() || !time.is_finite() {
        return None;
    }
    let at = |mine: &[&Point]| -> f64 {
        let after = mine
            .iter()
            .position(|p| p.wall_s >= time)
            .unwrap_or(mine.len() - 1);
        if after == 0 {
            return mine[0].rel_mse;
        }
        let (a, b) = (mine[after - 1], mine[after]);
        let f = (time / a.wall_s).ln() / (b.wall_s / a.wall_s).ln();
        (a.rel_mse.ln() + f * (b.rel_mse / a.rel_mse).ln()).exp()
    };
    let table = curves
        .iter()
        .map(|(name, mine)| ((*name).to_owned(), at(mine)))
        .collect();
    Some((time, table))
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
            runs: 1,
        };
        assert_eq!(c.levels(), vec![1, 2, 4, 8, 16]);
        let c = StudyConfig {
            min_spp: 4,
            max_spp: 4,
            seed: 0,
            runs: 1,
        };
        assert_eq!(c.levels(), vec![4]);
        let c = StudyConfig {
            min_spp: 0,
            max_spp: u32::MAX,
            seed: 0,
            runs: 1,
        };
        assert_eq!(c.levels().len(), 32);
    }

    #[test]
    fn upper_levels_are_half_and_at_least_three() {
        let p = Point {
            strategy: String::new(),
            spp: 1,
            runs: 1,
            wall_s: 1.0,
            cpu_s: None,
            rel_mse: 1.0,
            rel_mse_interval: (1.0, 1.0),
            rel_var: f64::NAN,
            rel_bias2: f64::NAN,
            rel_bias2_se: f64::NAN,
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
                runs: 1,
                wall_s: spp as f64,
                cpu_s: None,
                rel_mse: 0.1 / spp as f64 + floor,
                rel_mse_interval: (0.0, 0.0),
                rel_var: f64::NAN,
                rel_bias2: f64::NAN,
                rel_bias2_se: f64::NAN,
                rmse: 0.0,
                efficiency: 1.0,
                non_finite: 0,
            })
            .collect();
        let s = &summarise(&points, floor)[0];
        let slope = s.slope_spp.expect("fitted").slope;
        assert!((slope + 1.0).abs() < 1e-9, "slope {slope}");
    }

    #[test]
    fn the_spread_over_runs_splits_variance_from_bias() {
        // Every value is its reference plus a run's offset of ±0.1 (alternating, so the
        // mean over the runs has no error of its own), plus a constant 0.3 in the biased
        // case: variance v = 0.1²·8/7 and squared bias (m − r)² − v/8, the unbiased
        // estimate for random runs (here it lands v/8 below the bias², which these runs
        // do not have).
        let reference = vec![1.0f32; 1000];
        let v = 0.01 * 8.0 / 7.0;
        for (bias, expect_b2) in [(0.0f32, -v / 8.0), (0.3, 0.09 - v / 8.0)] {
            let mut spread = Spread::new(reference.len());
            for r in 0..8 {
                let offset = if r % 2 == 0 { 0.1 } else { -0.1 };
                let values: Vec<f32> = reference.iter().map(|x| x + offset + bias).collect();
                spread.add(&values);
            }
            let (var, b2, _) = spread.split(&reference);
            let w = 1.0 / (1.0 + REL_MSE_EPSILON);
            assert!((var - w * v).abs() < 1e-6, "{var}");
            assert!((b2 - w * expect_b2).abs() < 1e-6, "{b2}");
        }
        let mut one = Spread::new(2);
        one.add(&[1.0, f32::NAN]);
        assert!(
            one.split(&[1.0, 1.0]).0.is_nan(),
            "one run tells no variance"
        );
    }

    #[test]
    fn intervals_are_students_and_never_below_zero() {
        let (mean, (lo, hi)) = mean_interval(&[1.0, 2.0, 3.0]);
        // t(0.975, 2) = 4.303, sd = 1.
        assert_eq!(mean, 2.0);
        assert!((hi - 2.0 - 4.303 / 3f64.sqrt()).abs() < 1e-3, "{hi}");
        assert_eq!(lo, 0.0);
        assert_eq!(mean_interval(&[5.0]), (5.0, (5.0, 5.0)));
    }

    #[test]
    fn equal_time_reads_each_curve_at_the_shortest_longest_time() {
        let point = |strategy: &str, wall_s: f64, rel_mse: f64| Point {
            strategy: strategy.into(),
            spp: 1,
            runs: 1,
            wall_s,
            cpu_s: None,
            rel_mse,
            rel_mse_interval: (rel_mse, rel_mse),
            rel_var: f64::NAN,
            rel_bias2: f64::NAN,
            rel_bias2_se: f64::NAN,
            rmse: 0.0,
            efficiency: 0.0,
            non_finite: 0,
        };
        let points = [
            point("fast", 1.0, 1.0),
            point("fast", 4.0, 0.25),
            point("slow", 2.0, 1.0),
        ];
        let (time, table) = equal_time(&points).unwrap();
        assert_eq!(time, 2.0);
        // Halfway (in log time) from 1 to 4 s, relMSE ∝ 1/t gives 0.5.
        assert!((table[0].1 - 0.5).abs() < 1e-12, "{table:?}");
        assert_eq!(table[1], ("slow".into(), 1.0));
    }
}
