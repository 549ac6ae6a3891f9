use crate::prelude::*;

pub fn delta_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let majorant = medium.majorant();
    let valid = majorant > 0.0 && majorant.is_finite();
    if !valid {
        return FreeFlight::Escape;
    }
    let mut t = 0.0;
    let mut remaining = max_steps;
    while remaining > 0 {
        remaining -= 1;
        let step = -(1.0f32 - sampler.next_1d()).ln() / majorant;
        t += step;
        if t >= t_max {
            return FreeFlight::Escape;
        }
        let sigma = medium.coefficients(ray.at(t));
        let sigma_t = sigma.sigma_a + sigma.sigma_s;
        let r = sampler.next_1d() * majorant;
        if r >= sigma_t {
            continue;
        }
        return if r < sigma.sigma_a {
            FreeFlight::Absorb { t }
        } else {
            FreeFlight::Scatter { t }
        };
    }
    FreeFlight::Exhausted
}
