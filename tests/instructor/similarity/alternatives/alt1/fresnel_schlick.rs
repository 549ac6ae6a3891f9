use crate::prelude::*;

pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    let num = eta_t - eta_i;
    let den = eta_t + eta_i;
    (num / den).powi(2)
}

pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if eta_i == eta_t {
        return 0.0;
    }
    let r0 = t.schlick_r0(eta_i, eta_t);
    let mut c = cos_theta_i.clamp(0.0, 1.0);
    if eta_i > eta_t {
        // going into the less dense medium: use the transmitted angle
        let ratio = eta_i / eta_t;
        let s2 = ratio * ratio * (1.0 - c * c);
        if s2 >= 1.0 {
            return 1.0;
        }
        c = (1.0 - s2).sqrt();
    }
    let m = 1.0 - c;
    r0 + (1.0 - r0) * m * m * m * m * m
}
