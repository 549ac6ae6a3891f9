//! Directional albedo of the Cook-Torrance BRDF, `ρ(wo) = ∫ f(wo, wi) cos θi dωi`, by
//! uniform, cosine-weighted and NDF sampling and by MIS of the last two.
//!
//! Each "pixel" is one outgoing direction and roughness, with a white `f0 = 1` (so the
//! Fresnel factor is 1 and ρ is the fraction the microfacet model keeps after masking).
//! The reference is a deterministic quadrature of the same implementation's
//! `cook_torrance`, so a sampler or pdf that does not match shows up as bias, whatever
//! the BRDF code does.

use crate::converge::{Estimate, Strategy};
use crate::integrator::MisHeuristic;
use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use crate::worksheet::Tasks;
use glam::{Vec2, Vec3};
use rayon::prelude::*;
use std::sync::Arc;

/// Outgoing polar angles, degrees.
pub const THETA_DEG: [f32; 12] = [
    0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 65.0, 70.0, 75.0, 80.0, 85.0,
];
/// Roughnesses `(αx, αy)`; the last is anisotropic.
pub const ALPHAS: [(f32, f32); 5] = [(0.2, 0.2), (0.3, 0.3), (0.5, 0.5), (0.8, 0.8), (0.2, 0.6)];
/// Quadrature nodes per axis of [0, 1)² for the reference.
pub const QUADRATURE_NODES: usize = 768;

/// One pixel: an outgoing direction and a roughness.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Outgoing direction (local frame), at azimuth 30° so anisotropy matters.
    pub wo: Vec3,
    /// Roughness along local x.
    pub alpha_x: f32,
    /// Roughness along local y.
    pub alpha_y: f32,
}

/// Every pixel: each roughness at each outgoing angle.
pub fn configs() -> Vec<Config> {
    let phi = 30f32.to_radians();
    ALPHAS
        .iter()
        .flat_map(|&(alpha_x, alpha_y)| {
            THETA_DEG.iter().map(move |deg| {
                let (s, c) = deg.to_radians().sin_cos();
                Config {
                    wo: Vec3::new(s * phi.cos(), s * phi.sin(), c),
                    alpha_x,
                    alpha_y,
                }
            })
        })
        .collect()
}

/// `f(wo, wi) cos θi` for one pixel (red channel, f0 = 1).
fn integrand<T: Tasks>(t: &T, c: &Config, wi: Vec3) -> f32 {
    if wi.z <= 0.0 {
        return 0.0;
    }
    t.cook_torrance(c.wo, wi, c.alpha_x, c.alpha_y, Vec3::ONE).x * wi.z
}

/// The reference: the midpoint rule on a `QUADRATURE_NODES²` grid over [0, 1)², mapped
/// to the hemisphere by the cosine-weighted (Malley) map, whose density `cos θ/π` is
/// divided out in closed form. The BRDF is smooth for α ≥ 0.2, so the rule converges far
/// below the Monte Carlo errors a study reaches.
pub fn reference<T: Tasks>(t: &T, configs: &[Config]) -> Vec<f32> {
    let n = QUADRATURE_NODES;
    configs
        .par_iter()
        .map(|c| {
            let sum: f64 = (0..n)
                .map(|i| {
                    let r2 = (i as f64 + 0.5) / n as f64;
                    let (r, z) = (r2.sqrt(), (1.0 - r2).sqrt());
                    (0..n)
                        .map(|k| {
                            let phi = std::f64::consts::TAU * (k as f64 + 0.5) / n as f64;
                            let wi =
                                Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
                            // f cos / (cos/π) = π f
                            if z > 0.0 {
                                std::f64::consts::PI * integrand(t, c, wi) as f64 / z
                            } else {
                                0.0
                            }
                        })
                        .sum::<f64>()
                })
                .sum();
            (sum / (n * n) as f64) as f32
        })
        .collect()
}

/// Estimates every pixel with its own random stream.
fn estimate_each(
    configs: &[Config],
    spp: u32,
    seed: u64,
    sample: impl Fn(&Config, &mut Sampler) -> f32 + Sync,
) -> Vec<f32> {
    configs
        .par_iter()
        .enumerate()
        .map(|(j, c)| {
            let mut s = Sampler::new(seed, j as u64);
            let sum: f64 = (0..spp).map(|_| sample(c, &mut s) as f64).sum();
            (sum / spp as f64) as f32
        })
        .collect()
}

/// `value / pdf`, 0 where the pdf is 0 (a direction the strategy cannot produce).
fn ratio(value: f32, pdf: f32) -> f32 {
    if pdf > 0.0 { value / pdf } else { 0.0 }
}

/// Which directions a [`Sampled`] strategy draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Technique {
    /// Uniform over the hemisphere (framework).
    Uniform,
    /// The implementation's `cosine_sample` / `cosine_pdf`.
    Cosine,
    /// The implementation's `ndf_sample` / `ndf_pdf`.
    Ndf,
}

/// One sampling technique alone.
pub struct Sampled<T> {
    /// The implementation.
    pub tasks: T,
    /// The pixels.
    pub configs: Arc<Vec<Config>>,
    /// The technique.
    pub technique: Technique,
}

/// One sample of `technique`: the direction and its pdf (`None` when rejected).
fn draw<T: Tasks>(t: &T, c: &Config, technique: Technique, u: Vec2) -> Option<(Vec3, f32)> {
    match technique {
        Technique::Uniform => Some((uniform_hemisphere(u), uniform_hemisphere_pdf())),
        Technique::Cosine => {
            let wi = t.cosine_sample(u);
            Some((wi, t.cosine_pdf(wi)))
        }
        Technique::Ndf => {
            let wi = t.ndf_sample(c.wo, c.alpha_x, c.alpha_y, u)?;
            Some((wi, t.ndf_pdf(c.wo, wi, c.alpha_x, c.alpha_y)))
        }
    }
}

impl<T: Tasks> Strategy for Sampled<T> {
    fn name(&self) -> &str {
        match self.technique {
            Technique::Uniform => "uniform",
            Technique::Cosine => "cosine",
            Technique::Ndf => "ndf",
        }
    }

    fn estimate(&self, spp: u32, seed: u64) -> anyhow::Result<Estimate> {
        let t = &self.tasks;
        Ok(estimate_each(&self.configs, spp, seed, |c, s| {
            draw(t, c, self.technique, s.next_2d())
                .map_or(0.0, |(wi, pdf)| ratio(integrand(t, c, wi), pdf))
        })
        .into())
    }
}

/// One cosine sample and one NDF sample per spp, combined by a MIS heuristic.
pub struct Mis<T> {
    /// The implementation.
    pub tasks: T,
    /// The pixels.
    pub configs: Arc<Vec<Config>>,
    /// The weighting.
    pub heuristic: MisHeuristic,
}

impl<T: Tasks> Strategy for Mis<T> {
    fn name(&self) -> &str {
        match self.heuristic {
            MisHeuristic::Balance => "mis_balance",
            MisHeuristic::Power => "mis_power",
        }
    }

    fn estimate(&self, spp: u32, seed: u64) -> anyhow::Result<Estimate> {
        let t = &self.tasks;
        let weight = |a: f32, b: f32| match self.heuristic {
            MisHeuristic::Balance => ratio(a, a + b),
            MisHeuristic::Power => ratio(a * a, a * a + b * b),
        };
        Ok(estimate_each(&self.configs, spp, seed, |c, s| {
            let mut total = 0.0;
            let (u_cos, u_ndf) = (s.next_2d(), s.next_2d());
            if let Some((wi, pdf)) = draw(t, c, Technique::Cosine, u_cos) {
                let other = t.ndf_pdf(c.wo, wi, c.alpha_x, c.alpha_y);
                total += weight(pdf, other) * ratio(integrand(t, c, wi), pdf);
            }
            if let Some((wi, pdf)) = draw(t, c, Technique::Ndf, u_ndf) {
                let other = t.cosine_pdf(wi);
                total += weight(pdf, other) * ratio(integrand(t, c, wi), pdf);
            }
            total
        })
        .into())
    }
}
