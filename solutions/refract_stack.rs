//! Task `refract_stack`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    todo!()
}
