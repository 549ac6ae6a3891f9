use crate::prelude::*;

pub fn delta_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let sigma_bar = medium.majorant();
    if !(sigma_bar > 0.0) {
        return FreeFlight::Escape;
    }
    let mut dist = 0.0;
    let mut steps = 0;
    loop {
        if steps == max_steps {
            return FreeFlight::Exhausted;
        }
        steps += 1;
        let u = sampler.next_1d();
        dist += -(1.0 - u).ln() / sigma_bar;
        if dist >= t_max {
            return FreeFlight::Escape;
        }
        let coeffs = medium.coefficients(ray.at(dist));
        let xi = sampler.next_1d();
        let absorb_p = coeffs.sigma_a / sigma_bar;
        let scatter_p = coeffs.sigma_s / sigma_bar;
        if xi < absorb_p {
            return FreeFlight::Absorb { t: dist };
        } else if xi < absorb_p + scatter_p {
            return FreeFlight::Scatter { t: dist };
        }
        // null collision, keep going
    }
}
