//! The sampling check: a student's direction sampler against the reference density.
//!
//! Directions are binned on the upper hemisphere in cells of equal solid angle (uniform in
//! cos θ and in φ). The expected probability of each cell is the reference pdf integrated
//! over the cell; a sampler that may reject (`None`) gets one more cell for rejections. The
//! counts of `n` student samples are compared by Pearson's χ² with pooling. Any valid
//! sampling method passes (another warp, another use of the random numbers): only the
//! distribution of the directions matters. Before the χ² test every sample must be a
//! finite unit vector above the surface.

use super::output::fmt_num;
use super::output::fmt_vec;
use super::stats::{ChiSquare, chi_square};
use crate::sampling::Sampler;
use glam::{Vec2, Vec3};
use serde::{Deserialize, Serialize};
use std::f64::consts::TAU;

/// Cells of equal solid angle on the upper hemisphere: `n_cos` bands uniform in cos θ
/// times `n_phi` sectors uniform in φ; each cell spans 2π / (n_cos · n_phi) sr.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct HemisphereBins {
    /// Bands in cos θ ∈ [0, 1].
    pub n_cos: usize,
    /// Sectors in φ ∈ [0, 2π).
    pub n_phi: usize,
}

impl HemisphereBins {
    /// Number of cells.
    pub fn len(&self) -> usize {
        self.n_cos * self.n_phi
    }

    /// True when there are no cells.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The cell of a unit direction with `w.z ≥ 0`.
    pub fn index(&self, w: Vec3) -> usize {
        let z = (w.z as f64).clamp(0.0, 1.0);
        let i = ((z * self.n_cos as f64) as usize).min(self.n_cos - 1);
        let phi = (w.y as f64).atan2(w.x as f64).rem_euclid(TAU);
        let j = ((phi / TAU * self.n_phi as f64) as usize).min(self.n_phi - 1);
        i * self.n_phi + j
    }

    /// The probability of every cell under `pdf` (per steradian), by the midpoint rule on
    /// `sub × sub` points per cell in (cos θ, φ), where the solid-angle measure is flat.
    pub fn integrate(&self, pdf: impl Fn(Vec3) -> f64, sub: usize) -> Vec<f64> {
        let dz = 1.0 / (self.n_cos * sub) as f64;
        let dphi = TAU / (self.n_phi * sub) as f64;
        let mut cells = vec![0.0; self.len()];
        for i in 0..self.n_cos * sub {
            let z = (i as f64 + 0.5) * dz;
            let r = (1.0 - z * z).max(0.0).sqrt();
            for j in 0..self.n_phi * sub {
                let phi = (j as f64 + 0.5) * dphi;
                let w = Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
                cells[(i / sub) * self.n_phi + j / sub] += pdf(w) * dz * dphi;
            }
        }
        cells
    }
}

/// The reference's distribution of one sampler setup, as stored in the expected data.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SamplingTarget {
    /// The setup, for messages: `cosine_sample`, `ndf_sample(wo=(…), alpha_x=0.3, alpha_y=0.3)`.
    pub name: String,
    /// The cells.
    pub bins: HemisphereBins,
    /// Probability of each cell.
    pub probabilities: Vec<f64>,
    /// Probability that the sampler rejects (returns `None`).
    pub rejected: f64,
}

impl SamplingTarget {
    /// A target from cell probabilities integrated from the reference pdf. For a sampler that
    /// never rejects the cells are normalised to 1 (absorbing quadrature error); otherwise
    /// what the cells miss is the rejection probability.
    pub fn from_cells(
        name: String,
        bins: HemisphereBins,
        mut cells: Vec<f64>,
        rejects: bool,
    ) -> Self {
        let total: f64 = cells.iter().sum();
        let rejected = if rejects {
            (1.0 - total).max(0.0)
        } else {
            cells.iter_mut().for_each(|c| *c /= total);
            0.0
        };
        Self {
            name,
            bins,
            probabilities: cells,
            rejected,
        }
    }
}

/// Observed against expected counts of one sampling test (drawn in the HTML report).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Histogram {
    /// The setup.
    pub name: String,
    /// The cells.
    pub bins: HemisphereBins,
    /// Student samples per cell.
    pub observed: Vec<u64>,
    /// Expected count per cell.
    pub expected: Vec<f64>,
    /// Student rejections and the expected number.
    pub rejected: (u64, f64),
    /// χ² statistic (infinite when samples land where the reference density is 0).
    #[serde(with = "super::lenient_f64")]
    pub chi2: f64,
    /// Degrees of freedom after pooling.
    pub dof: usize,
    /// The p-value.
    pub p_value: f64,
}

/// Why a sampling test failed before or at the χ² stage.
#[derive(Clone, Debug, PartialEq)]
pub enum SamplingFailure {
    /// A sample was not a finite unit vector above the surface.
    Domain(String),
    /// The χ² test rejected the distribution.
    Distribution(Box<Histogram>),
}

/// Largest accepted deviation of a sample's length from 1.
const UNIT_TOLERANCE: f32 = 1e-3;
/// Largest accepted depth below the surface (rounding of a grazing sample).
const HORIZON_TOLERANCE: f32 = 1e-5;

/// A sampler's directions binned by a worker: no reference density involved.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct SampleCounts {
    /// Samples per cell.
    pub observed: Vec<u64>,
    /// Samples the sampler rejected (`None`).
    pub rejected: u64,
}

/// Draws `n` samples from `sample` (fed with uniform points from `sampler`), checks each is
/// a finite unit vector above the surface (and, when the sampler `may_reject` not, that it
/// returned one), and bins them in `bins`: the worker's half of the check. The error names
/// the first bad sample.
pub fn draw(
    bins: HemisphereBins,
    may_reject: bool,
    n: usize,
    sampler: &mut Sampler,
    mut sample: impl FnMut(Vec2) -> Option<Vec3>,
) -> Result<SampleCounts, String> {
    let mut counts = SampleCounts {
        observed: vec![0u64; bins.len()],
        rejected: 0,
    };
    for _ in 0..n {
        let u = sampler.next_2d();
        let Some(w) = sample(u) else {
            if !may_reject {
                return Err(format!(
                    "u=({}, {}): returned no direction, but this sampler never rejects",
                    fmt_num(u.x as f64),
                    fmt_num(u.y as f64)
                ));
            }
            counts.rejected += 1;
            continue;
        };
        let problem = if !w.is_finite() {
            Some("is not finite")
        } else if (w.length() - 1.0).abs() > UNIT_TOLERANCE {
            Some("is not a unit vector")
        } else if w.z < -HORIZON_TOLERANCE {
            Some("is below the surface (z < 0)")
        } else {
            None
        };
        if let Some(problem) = problem {
            return Err(format!(
                "u=({}, {}): sample {} {problem}",
                fmt_num(u.x as f64),
                fmt_num(u.y as f64),
                fmt_vec(w)
            ));
        }
        counts.observed[bins.index(w)] += 1;
    }
    Ok(counts)
}

/// Compares a worker's `counts` of `n` samples with `target` at significance `alpha`: the
/// grader's half of the check. Counts of the wrong shape (a worker that sent something else)
/// are a distribution failure with an infinite χ².
pub fn compare(
    target: &SamplingTarget,
    counts: &SampleCounts,
    n: usize,
    alpha: f64,
) -> Result<Histogram, SamplingFailure> {
    let scale = n as f64;
    let expected: Vec<f64> = target.probabilities.iter().map(|p| p * scale).collect();
    let consistent = counts.observed.len() == expected.len()
        && counts.observed.iter().sum::<u64>() + counts.rejected == n as u64;
    let mut all_obs = counts.observed.clone();
    let mut all_exp = expected.clone();
    if target.rejected > 0.0 {
        all_obs.push(counts.rejected);
        all_exp.push(target.rejected * scale);
    }
    let fit = match chi_square(&all_obs, &all_exp) {
        Some(fit) if consistent => fit,
        None if consistent => ChiSquare {
            statistic: 0.0,
            dof: 0,
            p_value: 1.0,
        },
        _ => ChiSquare {
            statistic: f64::INFINITY,
            dof: 0,
            p_value: 0.0,
        },
    };
    let histogram = Histogram {
        name: target.name.clone(),
        bins: target.bins,
        observed: counts.observed.clone(),
        expected,
        rejected: (counts.rejected, target.rejected * scale),
        chi2: fit.statistic,
        dof: fit.dof,
        p_value: fit.p_value,
    };
    if fit.p_value < alpha {
        Err(SamplingFailure::Distribution(Box::new(histogram)))
    } else {
        Ok(histogram)
    }
}

/// Draws, checks and compares in one process: [`draw`] then [`compare`].
pub fn test_sampler(
    target: &SamplingTarget,
    n: usize,
    alpha: f64,
    sampler: &mut Sampler,
    sample: impl FnMut(Vec2) -> Option<Vec3>,
) -> Result<Histogram, SamplingFailure> {
    let counts = draw(target.bins, target.rejected > 0.0, n, sampler, sample)
        .map_err(SamplingFailure::Domain)?;
    compare(target, &counts, n, alpha)
}

impl Histogram {
    /// The cell where observed and expected counts differ most, in standard deviations,
    /// described for a message.
    pub fn worst_cell(&self) -> String {
        let worst = self
            .observed
            .iter()
            .zip(&self.expected)
            .enumerate()
            .filter(|(_, (_, e))| **e >= 1.0)
            .max_by(|a, b| {
                let z = |(o, e): (&u64, &f64)| (*o as f64 - e).abs() / e.sqrt();
                z(a.1).total_cmp(&z(b.1))
            });
        match worst {
            Some((i, (o, e))) => {
                let (band, sector) = (i / self.bins.n_phi, i % self.bins.n_phi);
                let z0 = band as f64 / self.bins.n_cos as f64;
                let z1 = (band + 1) as f64 / self.bins.n_cos as f64;
                let p0 = 360.0 * sector as f64 / self.bins.n_phi as f64;
                let p1 = 360.0 * (sector + 1) as f64 / self.bins.n_phi as f64;
                format!(
                    "most off: cos θ ∈ [{}, {}), φ ∈ [{}°, {}°): {o} samples, expected {}",
                    fmt_num(z0),
                    fmt_num(z1),
                    fmt_num(p0),
                    fmt_num(p1),
                    fmt_num(*e)
                )
            }
            None => String::new(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};
    use std::f32::consts::FRAC_1_PI;

    fn cosine_target() -> SamplingTarget {
        let bins = HemisphereBins {
            n_cos: 10,
            n_phi: 20,
        };
        let cells = bins.integrate(|w| (w.z * FRAC_1_PI) as f64, 4);
        SamplingTarget::from_cells("cosine".into(), bins, cells, false)
    }

    /// Malley's method: a uniform disk point lifted to the hemisphere.
    fn malley(u: Vec2) -> Option<Vec3> {
        let r = u.x.sqrt();
        let phi = std::f32::consts::TAU * u.y;
        Some(Vec3::new(
            r * phi.cos(),
            r * phi.sin(),
            (1.0 - u.x).max(0.0).sqrt(),
        ))
    }

    #[test]
    fn quadrature_of_a_density_sums_to_one() {
        let bins = HemisphereBins {
            n_cos: 8,
            n_phi: 16,
        };
        let total: f64 = bins.integrate(|w| (w.z * FRAC_1_PI) as f64, 3).iter().sum();
        assert!((total - 1.0).abs() < 1e-4, "{total}");
        let uniform = bins.integrate(|_| uniform_hemisphere_pdf() as f64, 1);
        assert!(uniform.iter().all(|p| (p - 1.0 / 128.0).abs() < 1e-6));
    }

    #[test]
    fn bins_cover_the_hemisphere() {
        let bins = HemisphereBins { n_cos: 4, n_phi: 8 };
        assert_eq!(bins.index(Vec3::Z), 3 * 8);
        assert_eq!(bins.index(Vec3::new(1.0, 0.0, 0.0)), 0);
        assert_eq!(bins.index(Vec3::new(0.0, -1.0, 0.0)), 6);
    }

    #[test]
    fn a_valid_cosine_sampler_passes_and_uniform_fails() {
        let target = cosine_target();
        let mut s = Sampler::new(1, 0);
        let h = test_sampler(&target, 50_000, 1e-3, &mut s, malley).unwrap();
        assert!(h.p_value > 1e-3);
        let failure = test_sampler(&target, 50_000, 1e-3, &mut s, |u| {
            Some(uniform_hemisphere(u))
        });
        assert!(matches!(failure, Err(SamplingFailure::Distribution(_))));
    }

    #[test]
    fn samples_outside_the_domain_are_named() {
        let target = cosine_target();
        let mut s = Sampler::new(1, 0);
        let below = test_sampler(&target, 10, 1e-3, &mut s, |u| malley(u).map(|w| -w));
        let Err(SamplingFailure::Domain(message)) = below else {
            panic!("{below:?}")
        };
        assert!(message.contains("below the surface"), "{message}");
        let long = test_sampler(&target, 10, 1e-3, &mut s, |u| malley(u).map(|w| 2.0 * w));
        assert!(matches!(long, Err(SamplingFailure::Domain(m)) if m.contains("unit")));
    }
}
