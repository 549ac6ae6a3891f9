use crate::optics::schlick_weight;
use crate::prelude::*;

pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    let x = (eta_i - eta_t) / (eta_i + eta_t);
    x * x
}

fn cos_for_schlick(cos_i: f32, eta_i: f32, eta_t: f32) -> Option<f32> {
    if eta_i <= eta_t {
        return Some(cos_i);
    }
    let sin_i2 = 1.0 - cos_i * cos_i;
    let sin_t2 = sin_i2 * (eta_i * eta_i) / (eta_t * eta_t);
    if sin_t2 < 1.0 { Some((1.0 - sin_t2).sqrt()) } else { None }
}

pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if (eta_i - eta_t).abs() == 0.0 {
        0.0
    } else {
        match cos_for_schlick(cos_theta_i.abs().min(1.0), eta_i, eta_t) {
            None => 1.0,
            Some(c) => {
                let f0 = t.schlick_r0(eta_i, eta_t);
                f0 + (1.0 - f0) * schlick_weight(c)
            }
        }
    }
}
