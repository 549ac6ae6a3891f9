//! Task `brdf_check`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn brdf_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    todo!()
}
