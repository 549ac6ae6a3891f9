//! Bounding volume hierarchies through obvhs: a compressed wide BVH (CWBVH, Ylitie et al.
//! 2017) built with PLOC. Only triangle meshes and hair fibres use one; analytic spheres
//! and quads are few and tested directly.

use super::Ray;
use glam::Vec3A;
use obvhs::BvhBuildParams;
use obvhs::aabb::Aabb;
use obvhs::cwbvh::CwBvh;
use std::time::Duration;

/// A CWBVH over primitives given by their bounding boxes. Its leaves refer to primitives by
/// traversal slot: slot `i` holds input primitive [`Bvh::order`]`()[i]`, so callers store
/// their primitives in that order.
pub struct Bvh {
    /// The hierarchy.
    pub cwbvh: CwBvh,
}

impl Bvh {
    /// Builds a BVH over `boxes` (at least one).
    pub fn build(boxes: &[Aabb]) -> Self {
        let cwbvh = obvhs::cwbvh::builder::build_cwbvh(
            boxes,
            BvhBuildParams::medium_build(),
            &mut Duration::default(),
        );
        Self { cwbvh }
    }

    /// For each traversal slot, the index of the input primitive stored there.
    pub fn order(&self) -> &[u32] {
        &self.cwbvh.primitive_indices
    }

    /// Closest hit: `test(slot, t_max)` returns the distance to the primitive in traversal
    /// slot `slot` when it is below `t_max`. Returns the distance and slot of the nearest.
    #[inline]
    pub fn closest(
        &self,
        ray: &Ray,
        t_max: f32,
        mut test: impl FnMut(usize, f32) -> Option<f32>,
    ) -> Option<(f32, usize)> {
        let mut hit = obvhs::ray::RayHit::none();
        let found = self
            .cwbvh
            .ray_traverse(to_obvhs(ray, t_max), &mut hit, |r, slot| {
                test(slot, r.tmax).unwrap_or(f32::INFINITY)
            });
        found.then_some((hit.t, hit.primitive_id as usize))
    }

    /// Any hit below `t_max`, stopping at the first one found (the early-out traversal:
    /// obvhs' any-hit traversal visits every hit instead).
    #[inline]
    pub fn any(
        &self,
        ray: &Ray,
        t_max: f32,
        mut test: impl FnMut(usize, f32) -> Option<f32>,
    ) -> bool {
        !self
            .cwbvh
            .ray_traverse_miss(to_obvhs(ray, t_max), |r, slot| {
                test(slot, r.tmax).unwrap_or(f32::INFINITY)
            })
    }
}

/// The obvhs form of a ray segment `(0, t_max)`.
#[inline]
pub fn to_obvhs(ray: &Ray, t_max: f32) -> obvhs::ray::Ray {
    obvhs::ray::Ray::new(Vec3A::from(ray.origin), Vec3A::from(ray.dir), 0.0, t_max)
}
