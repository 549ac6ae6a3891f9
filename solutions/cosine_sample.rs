//! Task `cosine_sample`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn cosine_sample(u: Vec2) -> Vec3 {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn cosine_pdf(w: Vec3) -> f32 {
    todo!()
}
