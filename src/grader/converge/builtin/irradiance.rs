//! Irradiance under smooth sky lighting, estimated with uniform and with cosine-weighted
//! hemisphere sampling: the worksheet's §2.7 estimator as a convergence study.
//!
//! Each "pixel" is a different lighting `L(ω) = c0 + c1 ωx + c2 ωy + c3 ωz + c4 ωz²`
//! (non-negative), whose irradiance `E = ∫ L cos θ dω = π c0 + 2π/3 c3 + π/2 c4` is known
//! exactly, so the reference is analytic.

use crate::converge::{Estimate, Strategy};
use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use crate::worksheet::Tasks;
use glam::Vec3;
use rayon::prelude::*;
use std::f64::consts::PI;
use std::sync::Arc;

/// Number of lightings (a 64 × 64 "image").
pub const PIXELS: usize = 64 * 64;

/// One lighting: `L(ω) = c0 + c1 ωx + c2 ωy + c3 ωz + c4 ωz²`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sky {
    c: [f32; 5],
}

impl Sky {
    /// Radiance arriving from the local direction `w` (z = normal).
    pub fn radiance(&self, w: Vec3) -> f32 {
        let c = self.c;
        c[0] + c[1] * w.x + c[2] * w.y + c[3] * w.z + c[4] * w.z * w.z
    }

    /// The exact irradiance `∫ L cos θ dω` over the upper hemisphere.
    pub fn irradiance(&self) -> f64 {
        let c = self.c.map(f64::from);
        PI * c[0] + 2.0 * PI / 3.0 * c[3] + PI / 2.0 * c[4]
    }
}

/// `n` lightings with `c0 = 1` and the other coefficients in [−¼, ¼), so `L ≥ 0`.
pub fn skies(n: usize) -> Vec<Sky> {
    let mut s = Sampler::new(2024, 0);
    (0..n)
        .map(|_| {
            let mut c = [1.0; 5];
            for ci in &mut c[1..] {
                *ci = 0.5 * s.next_1d() - 0.25;
            }
            Sky { c }
        })
        .collect()
}

/// The analytic reference: each sky's irradiance.
pub fn reference(skies: &[Sky]) -> Vec<f32> {
    skies.iter().map(|s| s.irradiance() as f32).collect()
}

/// Mean of `spp` samples of `weight` for every sky, each sky with its own random stream.
fn estimate_each(
    skies: &[Sky],
    spp: u32,
    seed: u64,
    weight: impl Fn(&Sky, &mut Sampler) -> f32 + Sync,
) -> Vec<f32> {
    skies
        .par_iter()
        .enumerate()
        .map(|(j, sky)| {
            let mut sampler = Sampler::new(seed, j as u64);
            let sum: f64 = (0..spp).map(|_| weight(sky, &mut sampler) as f64).sum();
            (sum / spp as f64) as f32
        })
        .collect()
}

/// Directions uniform over the hemisphere: weight `L cos θ / (1/2π)`.
pub struct Uniform {
    /// The lightings.
    pub skies: Arc<Vec<Sky>>,
}

impl Strategy for Uniform {
    fn name(&self) -> &str {
        "uniform"
    }

    fn estimate(&self, spp: u32, seed: u64) -> anyhow::Result<Estimate> {
        Ok(estimate_each(&self.skies, spp, seed, |sky, s| {
            let w = uniform_hemisphere(s.next_2d());
            sky.radiance(w) * w.z / uniform_hemisphere_pdf()
        })
        .into())
    }
}

/// Directions from the implementation's `cosine_sample`, weighted by its own
/// `cosine_pdf`: `L cos θ / pdf` (0 where the pdf is 0). A pdf that does not match the
/// sampler shows up as bias: the error stops falling.
pub struct Cosine<T> {
    /// The implementation whose sampler is measured.
    pub tasks: T,
    /// The lightings.
    pub skies: Arc<Vec<Sky>>,
}

impl<T: Tasks> Strategy for Cosine<T> {
    fn name(&self) -> &str {
        "cosine"
    }

    fn estimate(&self, spp: u32, seed: u64) -> anyhow::Result<Estimate> {
        Ok(estimate_each(&self.skies, spp, seed, |sky, s| {
            let w = self.tasks.cosine_sample(s.next_2d());
            let pdf = self.tasks.cosine_pdf(w);
            if pdf > 0.0 {
                sky.radiance(w) * w.z / pdf
            } else {
                0.0
            }
        })
        .into())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::uniform_sphere;

    #[test]
    fn skies_are_non_negative_and_their_irradiance_matches_quadrature() {
        let skies = skies(8);
        let mut s = Sampler::new(1, 1);
        for sky in &skies {
            for _ in 0..100 {
                assert!(sky.radiance(uniform_sphere(s.next_2d())) >= 0.0);
            }
            // Midpoint rule in (cos θ, φ): dω = d(cos θ) dφ.
            let n = 400;
            let mut e = 0.0;
            for i in 0..n {
                let z = (i as f64 + 0.5) / n as f64;
                for k in 0..n {
                    let phi = 2.0 * PI * (k as f64 + 0.5) / n as f64;
                    let r = (1.0 - z * z).sqrt();
                    let w = Vec3::new((r * phi.cos()) as f32, (r * phi.sin()) as f32, z as f32);
                    e += sky.radiance(w) as f64 * z;
                }
            }
            e *= 2.0 * PI / (n * n) as f64;
            assert!(
                (e - sky.irradiance()).abs() < 1e-4,
                "{e} vs {}",
                sky.irradiance()
            );
        }
    }
}
