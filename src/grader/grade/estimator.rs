//! The estimator check: a Monte Carlo estimator built on student code against an analytic
//! value, by Student's t-test with the estimator's own sample variance.
//!
//! The check is generic over "a closure that returns one i.i.d. estimate per call", so it
//! applies to anything from a cosine-weighted irradiance estimate to one pixel sample of a
//! white furnace or a delta-tracking transmittance. When the reference estimator is at hand
//! it runs at the same sample count, and the report compares error and run time.

use super::output::fmt_num;
use super::stats::{Moments, t_test};
use crate::sampling::Sampler;
use serde::{Deserialize, Serialize};
use std::time::Instant;

/// One estimator run: its mean, standard error and cost.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct EstimatorRun {
    /// Mean of the estimates.
    #[serde(with = "super::lenient_f64")]
    pub mean: f64,
    /// Standard error of the mean (from the sample variance).
    #[serde(with = "super::lenient_f64")]
    pub std_error: f64,
    /// |mean − analytic| / |analytic| (absolute error when the analytic value is 0).
    #[serde(with = "super::lenient_f64")]
    pub error: f64,
    /// Wall time for all samples, in seconds.
    pub seconds: f64,
}

impl EstimatorRun {
    /// Efficiency `1 / (variance per sample × time per sample)`; larger is better. `None`
    /// where it means nothing: an estimator without variance (every estimate the same) or
    /// a run too fast to time.
    pub fn efficiency(&self, samples: usize) -> Option<f64> {
        let var = self.std_error * self.std_error * samples as f64;
        let time = self.seconds / samples as f64;
        let cost = var * time;
        (cost.is_finite() && cost > 0.0).then(|| 1.0 / cost)
    }

    /// The 95 % confidence interval of the mean (normal approximation: the checks draw
    /// tens of thousands of estimates).
    pub fn interval(&self) -> (f64, f64) {
        let half = 1.959_964 * self.std_error;
        (self.mean - half, self.mean + half)
    }
}

/// The statistics of one estimator test (shown in reports).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct EstimatorStats {
    /// What is estimated, e.g. `irradiance from a quad light by cosine sampling`.
    pub name: String,
    /// The analytic value.
    pub analytic: f64,
    /// Number of estimates.
    pub samples: usize,
    /// The student's estimator.
    pub student: EstimatorRun,
    /// The reference estimator at the same sample count, when available.
    pub reference: Option<EstimatorRun>,
    /// Two-sided p-value of the t-test of the student's mean against `analytic`.
    pub p_value: f64,
}

impl EstimatorStats {
    /// One line: mean ± standard error against the analytic value, and the comparison
    /// with the reference's run.
    pub fn describe(&self) -> String {
        let mut s = format!(
            "{}: {} ± {} (analytic {}, p = {})",
            self.name,
            fmt_num(self.student.mean),
            fmt_num(self.student.std_error),
            fmt_num(self.analytic),
            fmt_num(self.p_value)
        );
        if let Some(r) = &self.reference {
            s += &format!(
                "; reference {} ± {}; time {} s vs reference {} s",
                fmt_num(r.mean),
                fmt_num(r.std_error),
                fmt_num(self.student.seconds),
                fmt_num(r.seconds)
            );
        }
        s
    }
}

/// Why an estimator failed: the message names the estimator and the problem; the
/// statistics are there when all estimates were finite.
#[derive(Clone, Debug, PartialEq)]
pub struct EstimatorFailure {
    /// What failed.
    pub message: String,
    /// The run's statistics, if it completed.
    pub stats: Option<EstimatorStats>,
}

/// A Monte Carlo estimator: one i.i.d. estimate per call, drawing from the sampler, or why
/// the code under test gave none (an output outside its domain, in words).
pub type Estimator<'a> = dyn FnMut(&mut Sampler) -> Result<f64, String> + 'a;

/// What a worker measured of an estimator: the student's run with its moments, and the
/// reference's run at the same sample count when the worker has the reference.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Measured {
    /// The student's run.
    pub student: EstimatorRun,
    /// Its moments, for the t-test.
    pub moments: Moments,
    /// The reference's run.
    pub reference: Option<EstimatorRun>,
}

/// Runs `estimator` `n` times: the worker's half. `Err` names the first estimate that was
/// refused or not finite. The reference's run is added by the grader, from a worker of its
/// own ([`Measured::reference`]).
pub fn measure(
    analytic: f64,
    n: usize,
    seed: (u64, u64),
    estimator: &mut Estimator<'_>,
) -> Result<Measured, String> {
    let (student, moments) = run(analytic, n, seed, estimator)?;
    Ok(Measured {
        student,
        moments,
        reference: None,
    })
}

/// Tests a measured mean against `analytic` at significance `alpha`: the grader's half.
pub fn judge(
    name: &str,
    analytic: f64,
    n: usize,
    alpha: f64,
    measured: Result<Measured, String>,
) -> Result<EstimatorStats, Box<EstimatorFailure>> {
    let measured = measured.map_err(|message| {
        Box::new(EstimatorFailure {
            message: format!("{name}: {message}"),
            stats: None,
        })
    })?;
    let student = measured.student;
    let stats = EstimatorStats {
        name: name.into(),
        analytic,
        samples: n,
        student,
        reference: measured.reference,
        p_value: t_test(&measured.moments, analytic),
    };
    if stats.p_value < alpha {
        let off = if student.std_error > 0.0 {
            format!(
                "the mean is off by {:.1} standard errors (relative error {})",
                (student.mean - analytic).abs() / student.std_error,
                fmt_num(student.error)
            )
        } else {
            format!(
                "every estimate is {}, the analytic value {}",
                fmt_num(student.mean),
                fmt_num(analytic)
            )
        };
        Err(Box::new(EstimatorFailure {
            message: format!("{} — {off}", stats.describe()),
            stats: Some(stats),
        }))
    } else {
        Ok(stats)
    }
}

/// Runs `estimator` `n` times and tests its mean against `analytic` at significance `alpha`
/// in one process: [`measure`] then [`judge`].
pub fn test_estimator(
    name: &str,
    analytic: f64,
    n: usize,
    alpha: f64,
    seed: (u64, u64),
    estimator: &mut Estimator<'_>,
) -> Result<EstimatorStats, Box<EstimatorFailure>> {
    let measured = measure(analytic, n, seed, estimator);
    judge(name, analytic, n, alpha, measured)
}

/// Variance of an estimator run: `std_error² · n`.
pub fn variance(run: &EstimatorRun, samples: usize) -> f64 {
    run.std_error * run.std_error * samples as f64
}

/// Runs two estimators of the same quantity (the same scene in two units of length) on the
/// same random numbers and returns their per-sample variances; `Err` names a failed run.
pub fn variances(
    n: usize,
    seed: (u64, u64),
    a: &mut Estimator<'_>,
    b: &mut Estimator<'_>,
    analytic: f64,
) -> Result<(f64, f64), String> {
    let (ra, _) = run(analytic, n, seed, a)?;
    let (rb, _) = run(analytic, n, seed, b)?;
    Ok((variance(&ra, n), variance(&rb, n)))
}

fn run(
    analytic: f64,
    n: usize,
    (seed, stream): (u64, u64),
    estimator: &mut Estimator<'_>,
) -> Result<(EstimatorRun, Moments), String> {
    let mut sampler = Sampler::new(seed, stream);
    let mut moments = Moments::default();
    let start = Instant::now();
    for i in 0..n {
        let x = estimator(&mut sampler).map_err(|e| format!("estimate {i}: {e}"))?;
        if !x.is_finite() {
            return Err(format!("estimate {i} is {}", fmt_num(x)));
        }
        moments.push(x);
    }
    let seconds = start.elapsed().as_secs_f64();
    let error = if analytic == 0.0 {
        moments.mean.abs()
    } else {
        (moments.mean - analytic).abs() / analytic.abs()
    };
    Ok((
        EstimatorRun {
            mean: moments.mean,
            std_error: moments.std_error(),
            error,
            seconds,
        },
        moments,
    ))
}

/// How an estimator of radiance (RGB) turns it into one number: a weighted sum whose
/// weights differ per channel and sum to 1. A grey radiance keeps its value, and in a
/// coloured scene code that mixes up channels (uses one channel for all, or a scalar
/// where the contract has a colour) changes the mean.
pub const CHANNEL_WEIGHTS: glam::DVec3 = glam::DVec3::new(1.0 / 7.0, 2.0 / 7.0, 4.0 / 7.0);

/// An estimator with a known mean, built on an implementation's task functions.
pub struct EstimatorSpec<'a> {
    /// What it estimates.
    pub name: String,
    /// The analytic value of its mean.
    pub analytic: f64,
    /// How many estimates the check draws.
    pub samples: usize,
    /// One estimate per call.
    pub estimate: Box<Estimator<'a>>,
}

/// A colour in the scene format, for the grader's own scenes.
pub(crate) fn yaml_rgb(c: glam::DVec3) -> String {
    format!("[{}, {}, {}]", c.x, c.y, c.z)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unbiased_estimator_passes_and_a_biased_one_fails() {
        // E[2u] = 1 for u uniform on [0, 1).
        let mut good = |s: &mut Sampler| Ok(2.0 * s.next_f64());
        let stats = test_estimator("2u", 1.0, 20_000, 1e-3, (1, 0), &mut good).unwrap();
        assert!(stats.p_value > 1e-3, "{}", stats.describe());
        let mut biased = |s: &mut Sampler| Ok(2.1 * s.next_f64());
        let failure = test_estimator("2.1u", 1.0, 20_000, 1e-3, (1, 0), &mut biased).unwrap_err();
        assert!(
            failure.message.contains("standard errors"),
            "{}",
            failure.message
        );
        assert!(failure.stats.unwrap().p_value < 1e-3);
    }

    #[test]
    fn efficiency_means_nothing_without_variance_and_the_interval_covers_the_mean() {
        let exact = EstimatorRun {
            mean: 2.0,
            std_error: 0.0,
            error: 0.0,
            seconds: 0.5,
        };
        assert_eq!(exact.efficiency(100), None);
        let noisy = EstimatorRun {
            std_error: 0.1,
            ..exact
        };
        // variance per sample 1, time per sample 5 ms.
        assert!((noisy.efficiency(100).unwrap() - 200.0).abs() < 1e-9);
        let (lo, hi) = noisy.interval();
        assert!(lo < 2.0 && hi > 2.0 && ((hi - lo) / 2.0 - 0.196).abs() < 1e-3);
    }

    #[test]
    fn a_nan_estimate_is_reported_with_its_index() {
        let mut count = 0;
        let mut nan_at_3 = |_: &mut Sampler| {
            count += 1;
            Ok(if count == 4 { f64::NAN } else { 1.0 })
        };
        let failure = test_estimator("x", 1.0, 10, 1e-3, (1, 0), &mut nan_at_3).unwrap_err();
        assert!(
            failure.message.contains("estimate 3 is NaN"),
            "{}",
            failure.message
        );
    }
}
