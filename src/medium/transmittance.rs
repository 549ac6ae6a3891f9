use super::Medium;
use crate::geometry::Ray;
use crate::sampling::Sampler;

/// Transmittance `exp(−σt d)` of a homogeneous medium over a distance `d`.
pub fn homogeneous_transmittance(sigma_t: f32, distance: f32) -> f32 {
    (-sigma_t * distance).exp()
}

/// Ratio tracking (Novák et al. 2014): an unbiased estimate of the transmittance
/// `exp(−∫ σt)` along `ray` over `(0, t_max)`. It walks the same tentative collisions as
/// delta tracking but, instead of stopping at a real one, multiplies the estimate by the
/// probability of a null collision `1 − σt/σ̄` at each. Once the estimate drops below 0.1,
/// Russian roulette ends the walk without bias; it returns 0 if `max_steps` collisions
/// were not enough.
pub fn ratio_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> f32 {
    let majorant = medium.majorant();
    if majorant.is_nan() || majorant <= 0.0 {
        return 1.0;
    }
    let mut t = 0.0f32;
    let mut transmittance = 1.0f32;
    for _ in 0..max_steps {
        t -= (1.0 - sampler.next_1d()).ln() / majorant;
        if t >= t_max {
            return transmittance;
        }
        let sigma_t = medium.coefficients(ray.at(t)).sigma_t();
        transmittance *= (1.0 - sigma_t / majorant).max(0.0);
        if transmittance < 0.1 {
            if sampler.next_1d() * 0.1 >= transmittance {
                return 0.0;
            }
            transmittance = 0.1;
        }
    }
    0.0
}
