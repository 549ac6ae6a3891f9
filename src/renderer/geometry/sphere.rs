use super::Ray;
use super::hit::{Hit, ShapeId, offset_epsilon};
use crate::math::Frame;
use glam::Vec3;
use std::f32::consts::PI;

/// An analytic sphere. Its normal points outwards; its anisotropy tangent runs along the
/// parallels around the world y axis (so a brushed sphere is brushed "around its pole").
#[derive(Clone, Copy, Debug)]
pub struct Sphere {
    /// Centre, world space.
    pub center: Vec3,
    /// Radius (> 0).
    pub radius: f32,
    /// The shape this sphere belongs to.
    pub shape: ShapeId,
}

impl Sphere {
    /// Surface area.
    pub fn area(&self) -> f32 {
        4.0 * PI * self.radius * self.radius
    }

    /// The nearest intersection distance in `(0, t_max)`, if any.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let f = ray.origin - self.center;
        let b = f.dot(ray.dir);
        // The discriminant from the ray's closest approach to the centre (Ray Tracing Gems,
        // ch. 7): the textbook b² − c loses every digit for a ray passing far away.
        let r2 = self.radius * self.radius;
        let disc = r2 - (f - b * ray.dir).length_squared();
        if disc < 0.0 {
            return None;
        }
        let q = -b - b.signum() * disc.sqrt();
        if q == 0.0 {
            return None;
        }
        let c = f.length_squared() - r2;
        let (t0, t1) = if c / q < q { (c / q, q) } else { (q, c / q) };
        if t0 > 0.0 && t0 < t_max {
            Some(t0)
        } else if t1 > 0.0 && t1 < t_max {
            Some(t1)
        } else {
            None
        }
    }

    /// The full hit record at distance `t` along `ray`.
    #[inline]
    pub fn hit(&self, ray: &Ray, t: f32) -> Hit {
        let p = ray.at(t);
        let n = ((p - self.center) / self.radius).normalize_or(Vec3::Y);
        let p = self.center + n * self.radius;
        Hit {
            t,
            p,
            n,
            frame: Frame::from_normal_tangent(n, Vec3::Y.cross(n)),
            shape: self.shape,
            epsilon: offset_epsilon(p).max(1e-5 * self.radius),
            fibre: false,
        }
    }
}
