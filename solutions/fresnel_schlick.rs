//! Reference for task `fresnel_schlick`.

use crate::optics::schlick_weight;
use crate::prelude::*;

/// `((eta_i − eta_t) / (eta_i + eta_t))²`; symmetric in the two indices.
pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    let r = (eta_i - eta_t) / (eta_i + eta_t);
    r * r
}

/// Schlick's approximation, evaluated with the cosine on the less dense side.
///
/// Schlick's curve fits the exact Fresnel reflectance as a function of the angle in the
/// *optically thinner* medium. Going from dense to less dense that is the transmitted angle:
/// with the incident cosine, glass → air at 40° would give 0.0407 where the exact value is
/// 0.2453. Past the critical angle (decided on `sin²θt ≥ 1`) the reflectance is 1. Equal
/// indices reflect nothing, whereas the bare formula would still return `(1 − cos θ)^5`.
pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if eta_i == eta_t {
        return 0.0;
    }
    let cos_i = cos_theta_i.abs().min(1.0);
    let cos = if eta_i > eta_t {
        let sin2_t = (eta_i / eta_t).powi(2) * (1.0 - cos_i * cos_i).max(0.0);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    } else {
        cos_i
    };
    let r0 = t.schlick_r0(eta_i, eta_t);
    r0 + (1.0 - r0) * schlick_weight(cos)
}
