use super::Ray;
use super::bvh::Bvh;
use super::hit::{Hit, ShapeId, offset_epsilon};
use super::triangle::WatertightRay;
use crate::math::Frame;
use glam::{Vec3, Vec3A};
use obvhs::aabb::Aabb;

/// Every triangle of the scene's meshes, in world space, under one BVH. Triangles are
/// stored in the BVH's traversal order so a leaf indexes them directly.
pub struct TriangleSet {
    bvh: Bvh,
    tris: Vec<[Vec3; 3]>,
    shapes: Vec<ShapeId>,
}

impl TriangleSet {
    /// Builds the BVH over `tris` (at least one), each belonging to the shape in `shapes`.
    pub fn new(tris: Vec<[Vec3; 3]>, shapes: Vec<ShapeId>) -> Self {
        let boxes: Vec<Aabb> = tris
            .iter()
            .map(|v| Aabb::from_points(&v.map(Vec3A::from)))
            .collect();
        let bvh = Bvh::build(&boxes);
        let order = bvh.order();
        let sorted_tris = order.iter().map(|&i| tris[i as usize]).collect();
        let sorted_shapes = order.iter().map(|&i| shapes[i as usize]).collect();
        Self {
            bvh,
            tris: sorted_tris,
            shapes: sorted_shapes,
        }
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.tris.len()
    }

    /// True when there are no triangles.
    pub fn is_empty(&self) -> bool {
        self.tris.is_empty()
    }

    /// The triangles in traversal order (for benchmarks that traverse the BVH directly).
    pub fn triangles(&self) -> &[[Vec3; 3]] {
        &self.tris
    }

    /// The BVH (for benchmarks that traverse it directly).
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// The nearest triangle hit in `(0, t_max)`: its distance and slot.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, usize)> {
        let wray = WatertightRay::new(ray);
        self.bvh.closest(ray, t_max, |slot, t_max| {
            wray.intersect(&self.tris[slot], t_max)
        })
    }

    /// True when some triangle lies in `(0, t_max)` along the ray.
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        let wray = WatertightRay::new(ray);
        self.bvh.any(ray, t_max, |slot, t_max| {
            wray.intersect(&self.tris[slot], t_max)
        })
    }

    /// The hit record for the triangle in `slot` at distance `t`.
    pub fn hit(&self, ray: &Ray, t: f32, slot: usize) -> Hit {
        let [v0, v1, v2] = self.tris[slot];
        let e1 = v1 - v0;
        let n = e1.cross(v2 - v0).normalize_or(Vec3::Z);
        let p = ray.at(t);
        Hit {
            t,
            p,
            n,
            frame: Frame::from_normal_tangent(n, e1),
            shape: self.shapes[slot],
            epsilon: offset_epsilon(p),
            fibre: false,
        }
    }
}
