//! Task `ndf_sample`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn ndf_sample(t: &impl Tasks, wo: Vec3, alpha_x: f32, alpha_y: f32, u: Vec2) -> Option<Vec3> {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    todo!()
}
