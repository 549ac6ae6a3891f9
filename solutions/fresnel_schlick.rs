//! Task `fresnel_schlick`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn schlick_r0(eta_i: f32, eta_t: f32) -> f32 {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn fresnel_schlick(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    todo!()
}
