//! Task `aniso_ndf`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    todo!()
}
