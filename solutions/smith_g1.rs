//! Task `smith_g1`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    todo!()
}
