use super::Ray;
use glam::{DVec3, Vec3};

/// A ray prepared for the watertight ray-triangle test of Woop, Benthin and Wald (2013):
/// the coordinate axes are permuted so the ray runs along +z, and the other two axes are
/// sheared so it becomes the z axis itself. Triangles are then tested in 2D with edge
/// functions, which give every point of a shared edge to exactly one of the two triangles
/// (or both): no ray slips between neighbouring triangles, unlike the Möller-Trumbore test.
#[derive(Clone, Copy, Debug)]
pub struct WatertightRay {
    origin: Vec3,
    kx: usize,
    ky: usize,
    kz: usize,
    sx: f32,
    sy: f32,
    sz: f32,
}

impl WatertightRay {
    /// Precomputes the permutation and shear for `ray`.
    pub fn new(ray: &Ray) -> Self {
        let a = ray.dir.abs();
        let kz = if a.x >= a.y && a.x >= a.z {
            0
        } else if a.y >= a.z {
            1
        } else {
            2
        };
        let mut kx = (kz + 1) % 3;
        let mut ky = (kx + 1) % 3;
        // Swapping keeps the winding, so the sign of the determinant stays meaningful.
        if ray.dir[kz] < 0.0 {
            std::mem::swap(&mut kx, &mut ky);
        }
        let dz = ray.dir[kz];
        Self {
            origin: ray.origin,
            kx,
            ky,
            kz,
            sx: ray.dir[kx] / dz,
            sy: ray.dir[ky] / dz,
            sz: 1.0 / dz,
        }
    }

    /// The distance to the triangle `v` along the ray when it lies in `(0, t_max)`.
    /// Both faces count.
    #[inline]
    pub fn intersect(&self, v: &[Vec3; 3], t_max: f32) -> Option<f32> {
        let (kx, ky, kz) = (self.kx, self.ky, self.kz);
        let a = v[0] - self.origin;
        let b = v[1] - self.origin;
        let c = v[2] - self.origin;
        let ax = a[kx] - self.sx * a[kz];
        let ay = a[ky] - self.sy * a[kz];
        let bx = b[kx] - self.sx * b[kz];
        let by = b[ky] - self.sy * b[kz];
        let cx = c[kx] - self.sx * c[kz];
        let cy = c[ky] - self.sy * c[kz];
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
        let t_scaled = u * (self.sz * a[kz]) + v_ * (self.sz * b[kz]) + w * (self.sz * c[kz]);
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
