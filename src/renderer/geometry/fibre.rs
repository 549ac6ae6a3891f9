use super::Ray;
use super::bvh::{Bvh, LEAF_SLOTS};
use super::hit::{Hit, ShapeId};
use super::packs::{Ray4, nearest_lane};
use crate::math::Frame;
use glam::{Vec3, Vec3A, Vec4};
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

/// Four fibre segments as structure-of-arrays lanes (one BVH leaf), with what
/// [`FibreSegment::intersect`] derives from each segment alone computed once. Unused lanes
/// are NaN and never hit.
#[derive(Clone, Copy, Debug)]
struct FibrePack {
    a: [Vec4; 3],
    /// `b − a`.
    w: [Vec4; 3],
    /// `w · w`.
    ww: Vec4,
    radius: Vec4,
    radius2: Vec4,
}

impl FibrePack {
    /// Packs up to four segments; the lanes after them are unused.
    fn new(segments: &[FibreSegment]) -> Self {
        let mut pack = Self {
            a: [Vec4::NAN; 3],
            w: [Vec4::NAN; 3],
            ww: Vec4::NAN,
            radius: Vec4::NAN,
            radius2: Vec4::NAN,
        };
        for (lane, seg) in segments.iter().take(4).enumerate() {
            let w = seg.b - seg.a;
            for axis in 0..3 {
                pack.a[axis][lane] = seg.a[axis];
                pack.w[axis][lane] = w[axis];
            }
            pack.ww[lane] = w.dot(w);
            pack.radius[lane] = seg.radius;
            pack.radius2[lane] = seg.radius * seg.radius;
        }
        pack
    }

    /// Per lane, the distance [`FibreSegment::intersect`] finds for its segment, or +∞:
    /// the same operations in the same order, so the same distance bit for bit.
    #[inline]
    fn intersect(&self, ray: &Ray4, t_max: f32) -> Vec4 {
        let (o, d) = ([ray.ox, ray.oy, ray.oz], [ray.dx, ray.dy, ray.dz]);
        let dot = |p: &[Vec4; 3], q: &[Vec4; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
        // `f32::clamp(x, 0, 1)`, NaN kept.
        let unit = |x: Vec4| {
            let low = Vec4::select(x.cmpgt(Vec4::ONE), Vec4::ONE, x);
            Vec4::select(x.cmplt(Vec4::ZERO), Vec4::ZERO, low)
        };
        let (a, w) = (&self.a, &self.w);
        let r = [o[0] - a[0], o[1] - a[1], o[2] - a[2]];
        let dw = dot(&d, w);
        let dr = dot(&d, &r);
        let wr = dot(w, &r);
        let denom = self.ww - dw * dw;
        let crossing = unit((wr - dw * dr) / denom);
        let parallel = Vec4::select(self.ww.cmpgt(Vec4::ZERO), unit(wr / self.ww), Vec4::ZERO);
        let s = Vec4::select(
            denom.cmpgt(Vec4::splat(1e-12) * self.ww),
            crossing,
            parallel,
        );
        let axis = [a[0] + s * w[0], a[1] + s * w[1], a[2] + s * w[2]];
        let t = dot(&[axis[0] - o[0], axis[1] - o[1], axis[2] - o[2]], &d);
        let off = [
            o[0] + t * d[0] - axis[0],
            o[1] + t * d[1] - axis[1],
            o[2] + t * d[2] - axis[2],
        ];
        let hit = t.cmpgt(self.radius)
            & t.cmplt(Vec4::splat(t_max))
            & dot(&off, &off).cmple(self.radius2);
        Vec4::select(hit, t, Vec4::INFINITY)
    }
}

/// Every hair fibre segment of the scene under one BVH, in traversal order.
pub struct FibreSet {
    bvh: Bvh,
    /// By the BVH's slots.
    segments: Vec<FibreSegment>,
    /// By leaf: the segments of slots `4k .. 4k + 4`.
    packs: Vec<FibrePack>,
    /// By slot.
    shapes: Vec<ShapeId>,
    count: usize,
}

impl FibreSet {
    /// Builds the BVH over `segments` (at least one), each belonging to the shape in `shapes`.
    pub fn new(segments: Vec<FibreSegment>, shapes: Vec<ShapeId>) -> Self {
        let boxes: Vec<Aabb> = segments.iter().map(FibreSegment::aabb).collect();
        let bvh = Bvh::build(&boxes);
        // Padding: a segment that no ray hits (every comparison with NaN fails).
        let nowhere = FibreSegment {
            a: Vec3::NAN,
            b: Vec3::NAN,
            radius: f32::NAN,
        };
        let sorted = bvh.by_slot(&segments, nowhere);
        Self {
            packs: sorted.chunks(LEAF_SLOTS).map(FibrePack::new).collect(),
            segments: sorted,
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

    /// The nearest fibre hit in `(0, t_max)`: its distance and slot. Not inlined into
    /// `Geometry::intersect`: in there it slowed the mesh traversal beside it (12 % fewer
    /// paths per CPU-second on knot_115k), and it is one call per ray.
    #[inline(never)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, usize)> {
        let ray4 = Ray4::new(ray);
        self.bvh.closest(ray, t_max, |slots, t_max| {
            let t = self.packs[slots.start / LEAF_SLOTS].intersect(&ray4, t_max);
            nearest_lane(t, t_max).map(|(t, lane)| (t, slots.start + lane))
        })
    }

    /// True when some fibre lies in `(0, t_max)` along the ray (not inlined, as
    /// [`FibreSet::intersect`]).
    #[inline(never)]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        let ray4 = Ray4::new(ray);
        self.bvh.any(ray, t_max, |slots, t_max| {
            self.packs[slots.start / LEAF_SLOTS]
                .intersect(&ray4, t_max)
                .cmplt(Vec4::INFINITY)
                .any()
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

    #[test]
    fn a_pack_of_fibres_gives_the_scalar_tests_distances_bit_for_bit() {
        let mut sampler = Sampler::new(9, 10);
        let mut point = || Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
        let mut segments: Vec<FibreSegment> = (0..400)
            .map(|i| {
                let a = point();
                // Some segments of zero length, some along the rays' axis below.
                let b = match i % 5 {
                    0 => a,
                    1 => a + Vec3::new(0.0, 0.0, 0.2),
                    _ => a + 0.2 * (point() - 0.5),
                };
                FibreSegment { a, b, radius: 0.02 }
            })
            .collect();
        segments.truncate(398);
        let mut sampler = Sampler::new(11, 12);
        for i in 0..2000 {
            let o = Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
            let dir = if i % 3 == 0 {
                Vec3::Z
            } else {
                uniform_sphere(sampler.next_2d())
            };
            let ray = Ray::new(o - 0.5 * dir, dir);
            let t_max = if i % 2 == 0 { 0.7 } else { f32::INFINITY };
            for chunk in segments.chunks(4) {
                let t = FibrePack::new(chunk).intersect(&Ray4::new(&ray), t_max);
                for (lane, seg) in chunk.iter().enumerate() {
                    let scalar = seg.intersect(&ray, t_max).map_or(f32::INFINITY, |h| h.0);
                    assert_eq!(t[lane].to_bits(), scalar.to_bits(), "ray {i}, {seg:?}");
                }
                assert!(t.to_array()[chunk.len()..].iter().all(|t| t.is_infinite()));
            }
        }
    }
}
