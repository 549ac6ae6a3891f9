//! Task `reflect`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    todo!()
}
