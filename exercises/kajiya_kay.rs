//! Task `kajiya_kay`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    todo!()
}
