//! Task `phong`.

use crate::prelude::*;

/// TODO: documented by the exercise text.
pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    todo!()
}

/// TODO: documented by the exercise text.
pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
) -> f32 {
    todo!()
}
