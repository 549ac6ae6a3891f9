//! Task `delta_tracking`: reference solution.

use crate::prelude::*;

/// The first real collision along `ray` within `(0, t_max)`, by delta tracking.
pub fn delta_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let majorant = medium.majorant();
    if majorant.is_nan() || majorant <= 0.0 {
        return FreeFlight::Escape;
    }
    let mut t = 0.0f32;
    for _ in 0..max_steps {
        t -= (1.0 - sampler.next_1d()).ln() / majorant;
        if t >= t_max {
            return FreeFlight::Escape;
        }
        let c = medium.coefficients(ray.at(t));
        let xi = sampler.next_1d() * majorant;
        if xi < c.sigma_a {
            return FreeFlight::Absorb { t };
        }
        if xi < c.sigma_a + c.sigma_s {
            return FreeFlight::Scatter { t };
        }
    }
    FreeFlight::Exhausted
}
