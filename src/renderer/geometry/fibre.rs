use super::Ray;
use super::bvh::Bvh;
use super::hit::{Hit, ShapeId};
use crate::math::Frame;
use glam::{Vec3, Vec3A};
use obvhs::aabb::Aabb;

/// One straight piece of a hair strand: the axis from `a` to `b`, seen as a ribbon of
/// half-width `radius` that always faces the ray (a "flat" curve, as in pbrt). Its tangent
/// `normalize(b − a)` is what the Kajiya-Kay model shades with.
#[derive(Clone, Copy, Debug)]
pub struct FibreSegment {
    /// Start of the axis.
    pub a: Vec3,
    /// End of the axis.
    pub b: Vec3,
    /// Half-width of the fibre (> 0).
    pub radius: f32,
}

impl FibreSegment {
    /// Unit tangent from `a` to `b`.
    pub fn tangent(&self) -> Vec3 {
        (self.b - self.a).normalize_or(Vec3::Y)
    }

    /// The ray's closest approach to the axis, when it passes within `radius` at a distance
    /// `t ∈ (radius, t_max)`: returns `t` and the axis parameter `s ∈ [0, 1]`.
    ///
    /// Distances below `radius` are ignored on purpose: a ray leaving a fibre starts on its
    /// axis, and must not find the fibre it leaves.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, f32)> {
        let w = self.b - self.a;
        let r = ray.origin - self.a;
        let ww = w.dot(w);
        let dw = ray.dir.dot(w);
        let dr = ray.dir.dot(r);
        let wr = w.dot(r);
        let denom = ww - dw * dw;
        let s = if denom > 1e-12 * ww {
            ((wr - dw * dr) / denom).clamp(0.0, 1.0)
        } else {
            // Ray parallel to the axis: take the nearer end.
            if ww > 0.0 {
                (wr / ww).clamp(0.0, 1.0)
            } else {
                0.0
            }
        };
        let axis_point = self.a + s * w;
        let t = (axis_point - ray.origin).dot(ray.dir);
        if !(t > self.radius && t < t_max) {
            return None;
        }
        let miss = (ray.at(t) - axis_point).length_squared();
        (miss <= self.radius * self.radius).then_some((t, s))
    }

    /// Bounding box of the ribbon.
    pub fn aabb(&self) -> Aabb {
        let r = Vec3A::splat(self.radius);
        let (a, b) = (Vec3A::from(self.a), Vec3A::from(self.b));
        Aabb::new(a.min(b) - r, a.max(b) + r)
    }
}

/// Every hair fibre segment of the scene under one BVH, in traversal order.
pub struct FibreSet {
    bvh: Bvh,
    /// By the BVH's slots.
    segments: Vec<FibreSegment>,
    /// By slot.
    shapes: Vec<ShapeId>,
    count: usize,
}

impl FibreSet {
    /// Builds the BVH over `segments` (at least one), each belonging to the shape in `shapes`.
    pub fn new(segments: Vec<FibreSegment>, shapes: Vec<ShapeId>) -> Self {
        let boxes: Vec<Aabb> = segments.iter().map(FibreSegment::aabb).collect();
        let bvh = Bvh::build(&boxes);
        // Padding slots are never tested (a leaf's slot range ends before them).
        Self {
            segments: bvh.by_slot(&segments, segments[0]),
            shapes: bvh.by_slot(&shapes, 0),
            count: segments.len(),
            bvh,
        }
    }

    /// Number of segments.
    pub fn len(&self) -> usize {
        self.count
    }

    /// True when there are no segments.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The nearest fibre hit in `(0, t_max)`: its distance and slot.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, usize)> {
        self.bvh.closest(ray, t_max, |slots, mut best| {
            let mut found = None;
            for slot in slots {
                if let Some((t, _)) = self.segments[slot].intersect(ray, best) {
                    best = t;
                    found = Some((t, slot));
                }
            }
            found
        })
    }

    /// True when some fibre lies in `(0, t_max)` along the ray.
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        self.bvh.any(ray, t_max, |mut slots, t_max| {
            slots.any(|slot| self.segments[slot].intersect(ray, t_max).is_some())
        })
    }

    /// The hit record for the segment in `slot` at distance `t`: the point is on the axis,
    /// the normal faces the ray, and the frame's first tangent is the fibre direction.
    pub fn hit(&self, ray: &Ray, t: f32, slot: usize) -> Hit {
        let seg = &self.segments[slot];
        let tangent = seg.tangent();
        let w = seg.b - seg.a;
        let ww = w.dot(w);
        let s = if ww > 0.0 {
            ((ray.at(t) - seg.a).dot(w) / ww).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let p = seg.a + s * w;
        let towards_eye = -ray.dir;
        let n = (towards_eye - tangent * tangent.dot(towards_eye))
            .try_normalize()
            .unwrap_or_else(|| Frame::from_normal(tangent).s);
        Hit {
            t,
            p,
            n,
            frame: Frame::from_normal_tangent(n, tangent),
            shape: self.shapes[slot],
            epsilon: seg.radius,
            fibre: true,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{Sampler, uniform_sphere};

    #[test]
    fn the_bvh_finds_what_testing_every_fibre_finds() {
        let mut sampler = Sampler::new(5, 6);
        let mut point = || Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
        let segments: Vec<FibreSegment> = (0..500)
            .map(|_| {
                let a = point();
                FibreSegment {
                    a,
                    b: a + 0.1 * (point() - 0.5),
                    radius: 0.01,
                }
            })
            .collect();
        let set = FibreSet::new(segments.clone(), vec![0; segments.len()]);
        let mut sampler = Sampler::new(7, 8);
        let mut hits = 0;
        for i in 0..3000 {
            let o = Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
            let ray = Ray::new(o, uniform_sphere(sampler.next_2d()));
            let t_max = if i % 2 == 0 { 0.3 } else { f32::INFINITY };
            let brute = segments
                .iter()
                .filter_map(|s| s.intersect(&ray, t_max).map(|(t, _)| t))
                .min_by(f32::total_cmp);
            assert_eq!(set.intersect(&ray, t_max).map(|f| f.0), brute, "ray {i}");
            assert_eq!(set.occluded(&ray, t_max), brute.is_some(), "ray {i}");
            hits += brute.is_some() as u32;
        }
        assert!(hits > 300, "{hits} rays hit");
    }
}
