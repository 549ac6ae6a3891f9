//! Analytic shapes tested four at a time: spheres and quads stored as structures of arrays
//! of four lanes (glam's SIMD `Vec4`), intersected without a branch per shape. A scene has
//! few of them, and testing them all this way costs less than one mispredicted branch each.
//! The one branch is a sphere pack's return when the ray passes all four spheres, before
//! the square root and division that make the longest chain of a ray's test.

use super::{Quad, Ray, Sphere};
use glam::{BVec4A, Vec4};

/// Four spheres. Unused lanes have a negative squared radius and never hit.
#[derive(Clone, Copy, Debug)]
pub struct SpherePack {
    cx: Vec4,
    cy: Vec4,
    cz: Vec4,
    r2: Vec4,
}

/// Four quads. Unused lanes have a NaN plane offset and never hit.
#[derive(Clone, Copy, Debug)]
pub struct QuadPack {
    nx: Vec4,
    ny: Vec4,
    nz: Vec4,
    plane: Vec4,
    ox: Vec4,
    oy: Vec4,
    oz: Vec4,
    ax: Vec4,
    ay: Vec4,
    az: Vec4,
    bx: Vec4,
    by: Vec4,
    bz: Vec4,
}

/// A ray broadcast to four lanes.
#[derive(Clone, Copy, Debug)]
pub struct Ray4 {
    pub(super) ox: Vec4,
    pub(super) oy: Vec4,
    pub(super) oz: Vec4,
    pub(super) dx: Vec4,
    pub(super) dy: Vec4,
    pub(super) dz: Vec4,
}

impl Ray4 {
    /// `ray` in every lane.
    #[inline]
    pub fn new(ray: &Ray) -> Self {
        Self {
            ox: Vec4::splat(ray.origin.x),
            oy: Vec4::splat(ray.origin.y),
            oz: Vec4::splat(ray.origin.z),
            dx: Vec4::splat(ray.dir.x),
            dy: Vec4::splat(ray.dir.y),
            dz: Vec4::splat(ray.dir.z),
        }
    }
}

impl SpherePack {
    /// Packs `spheres` four by four.
    pub fn pack(spheres: &[Sphere]) -> Vec<SpherePack> {
        spheres
            .chunks(4)
            .map(|chunk| {
                let mut c = [[0.0f32; 4]; 3];
                let mut r2 = [-1.0f32; 4];
                for (lane, s) in chunk.iter().enumerate() {
                    for (axis, row) in c.iter_mut().enumerate() {
                        row[lane] = s.center[axis];
                    }
                    r2[lane] = s.radius * s.radius;
                }
                SpherePack {
                    cx: Vec4::from(c[0]),
                    cy: Vec4::from(c[1]),
                    cz: Vec4::from(c[2]),
                    r2: Vec4::from(r2),
                }
            })
            .collect()
    }

    /// Per lane, the nearest distance in `(0, t_max)`, or infinity.
    #[inline]
    pub fn intersect(&self, r: &Ray4, t_max: f32) -> Vec4 {
        let fx = r.ox - self.cx;
        let fy = r.oy - self.cy;
        let fz = r.oz - self.cz;
        let b = fx * r.dx + fy * r.dy + fz * r.dz;
        // As in `Sphere::intersect`: the discriminant from the closest approach.
        let px = fx - b * r.dx;
        let py = fy - b * r.dy;
        let pz = fz - b * r.dz;
        let disc = self.r2 - (px * px + py * py + pz * pz);
        let valid = disc.cmpge(Vec4::ZERO);
        // Most rays pass every sphere of a pack: they skip the square root and division.
        if !valid.any() {
            return Vec4::INFINITY;
        }
        let q = -b - b.signum() * disc.max(Vec4::ZERO).sqrt();
        let c = fx * fx + fy * fy + fz * fz - self.r2;
        let a = c / q;
        let t0 = a.min(q);
        let t1 = a.max(q);
        let tmax = Vec4::splat(t_max);
        let ok0 = t0.cmpgt(Vec4::ZERO) & t0.cmplt(tmax);
        let ok1 = t1.cmpgt(Vec4::ZERO) & t1.cmplt(tmax);
        let valid = valid & q.cmpne(Vec4::ZERO);
        let t = Vec4::select(ok0, t0, Vec4::select(ok1, t1, Vec4::INFINITY));
        Vec4::select(valid, t, Vec4::INFINITY)
    }
}

impl QuadPack {
    /// Packs `quads` four by four.
    pub fn pack(quads: &[Quad]) -> Vec<QuadPack> {
        quads
            .chunks(4)
            .map(|chunk| {
                // Rows: n (3), plane, origin (3), dual1 (3), dual2 (3).
                let mut rows = [[0.0f32; 4]; 13];
                rows[3] = [f32::NAN; 4];
                for (lane, q) in chunk.iter().enumerate() {
                    let values = [
                        q.n.x,
                        q.n.y,
                        q.n.z,
                        q.n.dot(q.origin),
                        q.origin.x,
                        q.origin.y,
                        q.origin.z,
                        q.dual1().x,
                        q.dual1().y,
                        q.dual1().z,
                        q.dual2().x,
                        q.dual2().y,
                        q.dual2().z,
                    ];
                    for (row, v) in rows.iter_mut().zip(values) {
                        row[lane] = v;
                    }
                }
                let r = rows.map(Vec4::from);
                QuadPack {
                    nx: r[0],
                    ny: r[1],
                    nz: r[2],
                    plane: r[3],
                    ox: r[4],
                    oy: r[5],
                    oz: r[6],
                    ax: r[7],
                    ay: r[8],
                    az: r[9],
                    bx: r[10],
                    by: r[11],
                    bz: r[12],
                }
            })
            .collect()
    }

    /// Per lane, the distance in `(0, t_max)`, or infinity.
    #[inline]
    pub fn intersect(&self, r: &Ray4, t_max: f32) -> Vec4 {
        let denom = self.nx * r.dx + self.ny * r.dy + self.nz * r.dz;
        let t = (self.plane - (self.nx * r.ox + self.ny * r.oy + self.nz * r.oz)) / denom;
        let px = r.ox + t * r.dx - self.ox;
        let py = r.oy + t * r.dy - self.oy;
        let pz = r.oz + t * r.dz - self.oz;
        let u = px * self.ax + py * self.ay + pz * self.az;
        let v = px * self.bx + py * self.by + pz * self.bz;
        let inside: BVec4A = t.cmpgt(Vec4::ZERO)
            & t.cmplt(Vec4::splat(t_max))
            & u.cmpge(Vec4::ZERO)
            & u.cmple(Vec4::ONE)
            & v.cmpge(Vec4::ZERO)
            & v.cmple(Vec4::ONE);
        Vec4::select(inside, t, Vec4::INFINITY)
    }
}

/// The smallest lane of `t` and its index, when it is below `best`.
#[inline]
pub fn nearest_lane(t: Vec4, best: f32) -> Option<(f32, usize)> {
    let m = t.min_element();
    if m < best {
        Some((
            m,
            t.cmpeq(Vec4::splat(m)).bitmask().trailing_zeros() as usize,
        ))
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{Sampler, uniform_sphere};
    use glam::Vec3;

    /// Rays from random points of the box [-1, 2]³ in random directions, half of them
    /// aimed at a point from `target` (so that hits are common), a third of them with a
    /// distance limit.
    fn rays(sampler: &mut Sampler, target: impl Fn(&mut Sampler) -> Vec3) -> Vec<(Ray, f32)> {
        (0..4000)
            .map(|i| {
                let o =
                    3.0 * Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d()) - 1.0;
                let dir = if i % 2 == 0 {
                    (target(sampler) - o).normalize()
                } else {
                    uniform_sphere(sampler.next_2d())
                };
                (
                    Ray::new(o, dir),
                    if i % 3 == 0 { 0.8 } else { f32::INFINITY },
                )
            })
            .collect()
    }

    /// Asserts that pack `k` (`pack(k, ray, t_max)`) gives, in each lane, what `scalar`
    /// gives for shape `4k + lane`, bit for bit, and +∞ in the unused lanes, for every
    /// ray. Returns how many shapes the rays hit.
    fn same_distances<S: std::fmt::Debug>(
        rays: &[(Ray, f32)],
        shapes: &[S],
        pack: impl Fn(usize, &Ray4, f32) -> Vec4,
        scalar: impl Fn(&S, &Ray, f32) -> Option<f32>,
    ) -> usize {
        let mut hits = 0;
        for (ray, t_max) in rays {
            for (k, chunk) in shapes.chunks(4).enumerate() {
                let t = pack(k, &Ray4::new(ray), *t_max);
                for (lane, shape) in chunk.iter().enumerate() {
                    let expected = scalar(shape, ray, *t_max).unwrap_or(f32::INFINITY);
                    assert_eq!(t[lane].to_bits(), expected.to_bits(), "{ray:?}, {shape:?}");
                    hits += expected.is_finite() as usize;
                }
                assert!(t.to_array()[chunk.len()..].iter().all(|t| t.is_infinite()));
            }
        }
        hits
    }

    #[test]
    fn a_pack_of_spheres_gives_the_scalar_tests_distances_bit_for_bit() {
        let mut sampler = Sampler::new(13, 14);
        let spheres: Vec<Sphere> = (0..11)
            .map(|i| Sphere {
                center: Vec3::new(sampler.next_1d(), sampler.next_1d(), sampler.next_1d()),
                radius: [0.01, 0.1, 0.4][i % 3],
                shape: 0,
            })
            .collect();
        let packs = SpherePack::pack(&spheres);
        let rays = rays(&mut sampler, |s| {
            Vec3::new(s.next_1d(), s.next_1d(), s.next_1d())
        });
        let hits = same_distances(
            &rays,
            &spheres,
            |k, r, t_max| packs[k].intersect(r, t_max),
            Sphere::intersect,
        );
        assert!(hits > 1000, "{hits} hits");
    }

    #[test]
    fn a_pack_of_quads_gives_the_scalar_tests_distances_bit_for_bit() {
        let mut sampler = Sampler::new(15, 16);
        let point = |s: &mut Sampler| Vec3::new(s.next_1d(), s.next_1d(), s.next_1d());
        let quads: Vec<Quad> = (0..7)
            .filter_map(|i| {
                // Some quads axis-aligned on a grid of eighths, as a box's walls are.
                let (origin, e1, e2) = if i % 2 == 0 {
                    (
                        (8.0 * point(&mut sampler)).floor() / 8.0,
                        Vec3::X,
                        0.5 * Vec3::Z,
                    )
                } else {
                    let e = (point(&mut sampler) - 0.5, point(&mut sampler) - 0.5);
                    (point(&mut sampler), e.0, e.1)
                };
                Quad::new(origin, e1, e2, 0)
            })
            .collect();
        let packs = QuadPack::pack(&quads);
        let mut rays = rays(&mut sampler, point);
        // Straight down onto the grid quads' corners and edges: u and v exactly 0, ½ or 1.
        for q in quads.iter().step_by(2) {
            for u in [0.0, 0.5, 1.0] {
                for v in [0.0, 0.5, 1.0] {
                    let above = q.origin + u * q.edge1 + v * q.edge2 + Vec3::Y;
                    rays.push((Ray::new(above, -Vec3::Y), f32::INFINITY));
                }
            }
        }
        let hits = same_distances(
            &rays,
            &quads,
            |k, r, t_max| packs[k].intersect(r, t_max),
            Quad::intersect,
        );
        assert!(hits > 500, "{hits} hits");
    }
}
