use super::Ray;
use super::bvh::{Bvh, LEAF_SLOTS};
use super::hit::{Hit, ShapeId, offset_epsilon};
use super::packs::nearest_lane;
use super::triangle::{TrianglePack, WatertightRay};
use crate::math::Frame;
use glam::{Vec3, Vec3A, Vec4};
use obvhs::aabb::Aabb;

/// Every triangle of the scene's meshes, in world space, under one BVH. Triangles are
/// stored by the BVH's slots, so a leaf indexes them directly: one by one for hit records,
/// and as one four-lane `TrianglePack` per leaf for the intersection tests.
pub struct TriangleSet {
    bvh: Bvh,
    /// By slot; the padding slots of a leaf hold NaN triangles.
    tris: Vec<[Vec3; 3]>,
    /// By leaf: the triangles of slots `4k .. 4k + 4`.
    packs: Vec<TrianglePack>,
    /// By slot (0 for padding, which is never hit).
    shapes: Vec<ShapeId>,
    count: usize,
}

impl TriangleSet {
    /// Builds the BVH over `tris` (at least one), each belonging to the shape in `shapes`.
    pub fn new(tris: Vec<[Vec3; 3]>, shapes: Vec<ShapeId>) -> Self {
        let boxes: Vec<Aabb> = tris
            .iter()
            .map(|v| Aabb::from_points(&v.map(Vec3A::from)))
            .collect();
        let bvh = Bvh::build(&boxes);
        let sorted_tris = bvh.by_slot(&tris, [Vec3::NAN; 3]);
        Self {
            packs: sorted_tris
                .chunks(LEAF_SLOTS)
                .map(TrianglePack::new)
                .collect(),
            tris: sorted_tris,
            shapes: bvh.by_slot(&shapes, 0),
            count: tris.len(),
            bvh,
        }
    }

    /// Number of triangles.
    pub fn len(&self) -> usize {
        self.count
    }

    /// True when there are no triangles.
    pub fn is_empty(&self) -> bool {
        self.count == 0
    }

    /// The triangles (for benchmarks that build another BVH over them).
    pub fn triangles(&self) -> impl Iterator<Item = &[Vec3; 3]> {
        self.tris.iter().filter(|v| !v[0].is_nan())
    }

    /// The nearest triangle hit in `(0, t_max)`: its distance and slot. Not inlined into
    /// `Geometry::intersect`, where it slowed the analytic shapes' tests beside it (furnace
    /// 9 % fewer paths per CPU-second); it is one call per ray.
    #[inline(never)]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<(f32, usize)> {
        let wray = WatertightRay::new(ray);
        self.bvh.closest(ray, t_max, |slots, t_max| {
            let t = wray.intersect_pack(&self.packs[slots.start / LEAF_SLOTS], t_max);
            nearest_lane(t, t_max).map(|(t, lane)| (t, slots.start + lane))
        })
    }

    /// True when some triangle lies in `(0, t_max)` along the ray (not inlined, as
    /// [`TriangleSet::intersect`]).
    #[inline(never)]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        let wray = WatertightRay::new(ray);
        self.bvh.any(ray, t_max, |slots, t_max| {
            wray.intersect_pack(&self.packs[slots.start / LEAF_SLOTS], t_max)
                .cmplt(Vec4::INFINITY)
                .any()
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{Sampler, uniform_sphere};

    /// A random triangle soup in the unit cube: small, large, thin and repeated triangles,
    /// and triangles on a grid whose shared vertices and edges rays are aimed at below.
    fn soup(sampler: &mut Sampler) -> Vec<[Vec3; 3]> {
        let mut point = || Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
        let mut tris = Vec::new();
        for i in 0..700 {
            let a = point();
            let scale = [0.02, 0.2, 1.0][i % 3];
            tris.push([a, a + scale * (point() - 0.5), a + scale * (point() - 0.5)]);
        }
        tris.extend_from_within(0..20);
        for x in 0..8 {
            for y in 0..8 {
                let p = |dx: u32, dy: u32| Vec3::new((x + dx) as f32, (y + dy) as f32, 0.5) / 8.0;
                tris.push([p(0, 0), p(1, 0), p(1, 1)]);
                tris.push([p(0, 0), p(1, 1), p(0, 1)]);
            }
        }
        tris
    }

    #[test]
    fn the_bvh_finds_what_testing_every_triangle_finds() {
        let mut sampler = Sampler::new(1, 2);
        for round in 0..3 {
            let tris = soup(&mut sampler);
            let set = TriangleSet::new(tris.clone(), vec![0; tris.len()]);
            assert_eq!(set.len(), tris.len());
            for i in 0..4000 {
                let ray = if i % 4 == 0 {
                    // Straight down at a grid vertex or edge midpoint.
                    let (x, y) = ((i / 4 % 17) as f32 / 16.0, (i / 68 % 17) as f32 / 16.0);
                    Ray::new(Vec3::new(x, y, 2.0), -Vec3::Z)
                } else {
                    let o = Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d());
                    Ray::new(3.0 * o - 1.0, uniform_sphere(sampler.next_2d()))
                };
                let t_max = if i % 3 == 0 { 0.4 } else { f32::INFINITY };
                let wray = WatertightRay::new(&ray);
                let brute = tris
                    .iter()
                    .filter_map(|v| wray.intersect(v, t_max))
                    .min_by(f32::total_cmp);
                let found = set.intersect(&ray, t_max);
                assert_eq!(found.map(|f| f.0), brute, "round {round}, ray {i}: {ray:?}");
                if let Some((t, slot)) = found {
                    assert_eq!(wray.intersect(&set.tris[slot], t_max), Some(t));
                }
                assert_eq!(set.occluded(&ray, t_max), brute.is_some(), "ray {i}");
            }
        }
    }

    #[test]
    fn a_pack_of_triangles_gives_the_scalar_tests_distances_bit_for_bit() {
        let mut sampler = Sampler::new(3, 4);
        let tris = soup(&mut sampler);
        for i in 0..3000 {
            let ray = if i % 2 == 0 {
                let (x, y) = ((i % 9) as f32 / 8.0, (i / 9 % 9) as f32 / 8.0);
                Ray::new(Vec3::new(x, y, -1.0), Vec3::Z)
            } else {
                Ray::new(Vec3::splat(0.5), uniform_sphere(sampler.next_2d()))
            };
            let wray = WatertightRay::new(&ray);
            for chunk in tris.chunks(4).skip(i % 7).step_by(7) {
                let t = wray.intersect_pack(&TrianglePack::new(chunk), f32::INFINITY);
                for (lane, v) in chunk.iter().enumerate() {
                    let scalar = wray.intersect(v, f32::INFINITY).unwrap_or(f32::INFINITY);
                    assert_eq!(t[lane].to_bits(), scalar.to_bits(), "ray {i}, {v:?}");
                }
                assert!(t.to_array()[chunk.len()..].iter().all(|t| t.is_infinite()));
            }
        }
    }

    #[test]
    fn one_triangle_and_a_few_make_a_bvh() {
        for n in 1..6 {
            let tris: Vec<[Vec3; 3]> = (0..n)
                .map(|i| {
                    let z = i as f32;
                    [
                        Vec3::new(-1.0, -1.0, z),
                        Vec3::new(1.0, -1.0, z),
                        Vec3::new(0.0, 1.0, z),
                    ]
                })
                .collect();
            let set = TriangleSet::new(tris, vec![7; n]);
            let ray = Ray::new(Vec3::new(0.0, 0.0, -1.0), Vec3::Z);
            let (t, slot) = set.intersect(&ray, f32::INFINITY).expect("a hit");
            assert_eq!(t, 1.0);
            assert_eq!(set.hit(&ray, t, slot).shape, 7);
            assert!(set.occluded(&ray, f32::INFINITY));
            assert!(!set.occluded(&ray, 0.5));
        }
    }
}
