//! Task `cook_torrance`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    todo!()
}
