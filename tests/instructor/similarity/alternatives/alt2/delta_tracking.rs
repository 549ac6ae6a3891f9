use crate::prelude::*;

enum Event {
    Absorbed,
    Scattered,
    Null,
}

fn classify(medium: &dyn Medium, ray: &Ray, t: f32, xi: f32) -> Event {
    let c = medium.coefficients(ray.at(t));
    if xi < c.sigma_a {
        Event::Absorbed
    } else if xi < c.sigma_a + c.sigma_s {
        Event::Scattered
    } else {
        Event::Null
    }
}

pub fn delta_tracking(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let mu = medium.majorant();
    if mu.is_nan() || mu <= 0.0 {
        return FreeFlight::Escape;
    }
    let mut pos = 0.0f32;
    for _step in 0..max_steps {
        let u = sampler.next_1d();
        pos -= (1.0 - u).ln() / mu;
        if pos >= t_max {
            return FreeFlight::Escape;
        }
        let xi = mu * sampler.next_1d();
        match classify(medium, ray, pos, xi) {
            Event::Absorbed => return FreeFlight::Absorb { t: pos },
            Event::Scattered => return FreeFlight::Scatter { t: pos },
            Event::Null => continue,
        }
    }
    FreeFlight::Exhausted
}
