use super::Medium;
use crate::geometry::Ray;
use crate::sampling::Sampler;
use std::cmp::Ordering;

/// Transmittance `exp(−σt d)` of a homogeneous medium over a distance `d`.
pub fn homogeneous_transmittance(sigma_t: f32, distance: f32) -> f32 {
    (-sigma_t * distance).exp()
}

/// Ratio tracking (Novák et al. 2014): an unbiased estimate of the transmittance
/// `exp(−∫ σt)` along `ray` over `(0, t_max)`: the product, over the tentative collisions
/// of the medium's majorant `σ̄`, of the probability `1 − σt/σ̄` that each is a null one.
///
/// The tentative collisions are a Poisson process of rate `σ̄`, drawn here as such: their
/// number in each stretch of the segment is Poisson distributed, and each lies uniformly in
/// its stretch; the product does not depend on their order. Once the estimate drops below
/// 0.1, Russian roulette ends the walk without bias. It returns 0 if more than `max_steps`
/// collisions would be needed, and 1 when the majorant is 0 or NaN (nothing collides).
pub fn ratio_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> f32 {
    let majorant = medium.majorant();
    if majorant.partial_cmp(&0.0) != Some(Ordering::Greater) || t_max <= 0.0 {
        return 1.0;
    }
    let expected = f64::from(majorant) * f64::from(t_max);
    if !expected.is_finite() {
        return 0.0;
    }
    let stretches = (expected / MEAN_PER_STRETCH).ceil().max(1.0);
    let mut left = max_steps;
    let mut transmittance = 1.0f32;
    let mut stretch = 0.0;
    while stretch < stretches {
        let count = poisson(expected / stretches, sampler);
        if count > left {
            return 0.0;
        }
        left -= count;
        for _ in 0..count {
            let along = (stretch + f64::from(sampler.next_1d())) / stretches;
            let sigma_t = medium.coefficients(ray.at(along as f32 * t_max)).sigma_t();
            transmittance *= (1.0 - sigma_t / majorant).max(0.0);
            if transmittance < 0.1 {
                if sampler.next_1d() * 0.1 >= transmittance {
                    return 0.0;
                }
                transmittance = 0.1;
            }
        }
        stretch += 1.0;
    }
    transmittance
}

/// The largest expected number of collisions in one stretch of [`ratio_tracking`], where
/// `e^{−mean}` is still far from underflow.
const MEAN_PER_STRETCH: f64 = 64.0;

/// A Poisson-distributed count with the given `mean` (at most [`MEAN_PER_STRETCH`]), by
/// inverting its distribution function with one uniform number.
fn poisson(mean: f64, sampler: &mut Sampler) -> u32 {
    let u = sampler.next_f64();
    let mut probability = (-mean).exp();
    let mut cumulative = probability;
    let mut k = 0u32;
    // Past 16 mean-widths the remaining mass is below the uniform number's resolution.
    let last = (mean + 16.0 * mean.sqrt() + 16.0) as u32;
    while u >= cumulative && k < last {
        k += 1;
        probability *= mean / f64::from(k);
        cumulative += probability;
    }
    k
}
