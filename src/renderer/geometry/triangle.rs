use super::Ray;
use glam::{DVec3, Vec3, Vec4};

/// A ray prepared for the watertight ray-triangle test of Woop, Benthin and Wald (2013):
/// the coordinate axes are permuted so the ray runs along +z, and the other two axes are
/// sheared so it becomes the z axis itself. Triangles are then tested in 2D with edge
/// functions, which give every point of a shared edge to exactly one of the two triangles
/// (or both): no ray slips between neighbouring triangles, unlike the Möller-Trumbore test.
///
/// A vertex `a` relative to the origin maps to `(a[kx] − sx a[kz], a[ky] − sy a[kz],
/// sz a[kz])`, with the axes `kx, ky, kz` and the shear `sx, sy, sz` of the paper.
/// [`WatertightRay::intersect_pack`] tests four triangles at once with the same operations
/// in the same order as the scalar [`WatertightRay::intersect`], lane by lane, so it finds
/// the same distances bit for bit.
#[derive(Clone, Copy, Debug)]
pub struct WatertightRay {
    /// The axes `[kx, ky, kz]`.
    axes: [usize; 3],
    /// The origin's coordinates on the axes `kx, ky, kz`, each in all four lanes (the
    /// scalar test reads lane x).
    origin4: [Vec4; 3],
    /// The shear `[−sx, −sy, sz]`, each in all four lanes.
    shear4: [Vec4; 3],
}

/// Four triangles as structure-of-arrays lanes (one BVH leaf): `v[k][axis]` holds vertex
/// `k`'s coordinate on `axis` of every lane. Unused lanes are NaN and never hit.
#[derive(Clone, Copy, Debug)]
pub struct TrianglePack {
    v: [[Vec4; 3]; 3],
}

impl TrianglePack {
    /// Packs up to four triangles; the lanes after them are unused.
    pub fn new(tris: &[[Vec3; 3]]) -> Self {
        let mut v = [[Vec4::NAN; 3]; 3];
        for (lane, tri) in tris.iter().take(4).enumerate() {
            for (k, vertex) in tri.iter().enumerate() {
                for axis in 0..3 {
                    v[k][axis][lane] = vertex[axis];
                }
            }
        }
        Self { v }
    }

    /// The triangle in `lane`.
    fn lane(&self, lane: usize) -> [Vec3; 3] {
        self.v
            .map(|vertex| Vec3::new(vertex[0][lane], vertex[1][lane], vertex[2][lane]))
    }
}

impl WatertightRay {
    /// Precomputes the permutation and shear for `ray`.
    pub fn new(ray: &Ray) -> Self {
        let d = ray.dir.to_array();
        let o = ray.origin.to_array();
        let a = ray.dir.abs();
        let kz = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let (mut kx, mut ky) = ((kz + 1) % 3, (kz + 2) % 3);
        // Swapping keeps the winding, so the sign of the determinant stays meaningful.
        if d[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        let dz = d[kz];
        let origin = [o[kx], o[ky], o[kz]];
        let shear = [-d[kx] / dz, -d[ky] / dz, 1.0 / dz];
        let splat = |v: [f32; 3]| [Vec4::splat(v[0]), Vec4::splat(v[1]), Vec4::splat(v[2])];
        Self {
            axes: [kx, ky, kz],
            origin4: splat(origin),
            shear4: splat(shear),
        }
    }

    /// Per lane of `pack`, the distance to its triangle when it lies in `(0, t_max)`, or
    /// +∞: what [`WatertightRay::intersect`] gives for each lane. A lane with an edge
    /// function of exactly zero is decided by that scalar test (in double precision).
    #[inline]
    pub fn intersect_pack(&self, pack: &TrianglePack, t_max: f32) -> Vec4 {
        let [kx, ky, kz] = self.axes;
        let [ox, oy, oz] = &self.origin4;
        let [nsx, nsy, sz] = &self.shear4;
        let sheared = |k: usize| {
            let v = &pack.v[k];
            let z = v[kz] - *oz;
            ((v[kx] - *ox) + *nsx * z, (v[ky] - *oy) + *nsy * z, *sz * z)
        };
        let ((ax, ay, az), (bx, by, bz), (cx, cy, cz)) = (sheared(0), sheared(1), sheared(2));
        let u = cx * by - cy * bx;
        let v = ax * cy - ay * cx;
        let w = bx * ay - by * ax;
        let zero = Vec4::ZERO;
        let exact_zero = u.cmpeq(zero) | v.cmpeq(zero) | w.cmpeq(zero);
        let mixed = (u.cmplt(zero) | v.cmplt(zero) | w.cmplt(zero))
            & (u.cmpgt(zero) | v.cmpgt(zero) | w.cmpgt(zero));
        let det = u + v + w;
        let t_scaled = u * az + v * bz + w * cz;
        let limit = Vec4::splat(t_max) * det;
        let outside = (det.cmplt(zero) & (t_scaled.cmpge(zero) | t_scaled.cmple(limit)))
            | (det.cmpgt(zero) & (t_scaled.cmple(zero) | t_scaled.cmpge(limit)));
        let t = t_scaled / det;
        let inside = t.cmpgt(zero) & t.cmplt(Vec4::splat(t_max));
        let hit = inside & !(mixed | outside | det.cmpeq(zero));
        let mut result = Vec4::select(hit, t, Vec4::INFINITY);
        let mut fallback = exact_zero.bitmask();
        while fallback != 0 {
            let lane = fallback.trailing_zeros() as usize;
            fallback &= fallback - 1;
            result[lane] = self
                .intersect(&pack.lane(lane), t_max)
                .unwrap_or(f32::INFINITY);
        }
        result
    }

    /// The distance to the triangle `v` along the ray when it lies in `(0, t_max)`.
    /// Both faces count.
    #[inline]
    pub fn intersect(&self, v: &[Vec3; 3], t_max: f32) -> Option<f32> {
        let [kx, ky, kz] = self.axes;
        let [ox, oy, oz] = self.origin4.map(|v| v.x);
        let [nsx, nsy, sz] = self.shear4.map(|v| v.x);
        let sheared = |v: Vec3| {
            let z = v[kz] - oz;
            ((v[kx] - ox) + nsx * z, (v[ky] - oy) + nsy * z, sz * z)
        };
        let ((ax, ay, az), (bx, by, bz), (cx, cy, cz)) =
            (sheared(v[0]), sheared(v[1]), sheared(v[2]));
        let mut u = cx * by - cy * bx;
        let mut v_ = ax * cy - ay * cx;
        let mut w = bx * ay - by * ax;
        // An edge function that rounds to exactly zero is decided in double precision, as
        // the paper prescribes; otherwise a ray through a shared edge could miss both sides.
        if u == 0.0 || v_ == 0.0 || w == 0.0 {
            let (ax, ay, bx, by, cx, cy) = (
                ax as f64, ay as f64, bx as f64, by as f64, cx as f64, cy as f64,
            );
            u = (cx * by - cy * bx) as f32;
            v_ = (ax * cy - ay * cx) as f32;
            w = (bx * ay - by * ax) as f32;
        }
        if (u < 0.0 || v_ < 0.0 || w < 0.0) && (u > 0.0 || v_ > 0.0 || w > 0.0) {
            return None;
        }
        let det = u + v_ + w;
        if det == 0.0 {
            return None;
        }
        let t_scaled = u * az + v_ * bz + w * cz;
        if det < 0.0 && (t_scaled >= 0.0 || t_scaled <= t_max * det)
            || det > 0.0 && (t_scaled <= 0.0 || t_scaled >= t_max * det)
        {
            return None;
        }
        let t = t_scaled / det;
        (t > 0.0 && t < t_max).then_some(t)
    }
}

/// Twice the area of a triangle, computed in f64 (0 for a degenerate triangle).
pub fn double_area(v: &[Vec3; 3]) -> f64 {
    let a = v[0].as_dvec3();
    let e1: DVec3 = v[1].as_dvec3() - a;
    let e2: DVec3 = v[2].as_dvec3() - a;
    e1.cross(e2).length()
}
