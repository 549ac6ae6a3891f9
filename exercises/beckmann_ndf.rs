//! Task `beckmann_ndf`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    todo!()
}
