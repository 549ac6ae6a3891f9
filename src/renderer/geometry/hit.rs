use super::Ray;
use crate::math::Frame;
use glam::Vec3;

/// Identifies what a ray hit, for the scene's own lookups (material, light, medium).
pub type ShapeId = u32;

/// Where a ray met a surface, with everything shading needs.
///
/// Normal convention: `n` is the shape's *geometric* normal, never flipped towards the ray.
/// It points out of closed shapes (spheres, boxes, closed meshes), along `edge1 × edge2`
/// for quads and along `(v1 − v0) × (v2 − v0)` for triangles. An emitter emits on the side
/// `n` points to; a dielectric has its outside (`ext_ior`) on that side. For a hair fibre
/// `n` points towards the ray's origin and `frame.s` is the fibre tangent.
#[derive(Clone, Copy, Debug)]
pub struct Hit {
    /// Distance from the ray origin (the ray's direction has unit length).
    pub t: f32,
    /// The point hit, in world space.
    pub p: Vec3,
    /// Unit geometric normal (see the type's documentation for its orientation).
    pub n: Vec3,
    /// Shading frame: `frame.n == n`; `frame.s` is the surface tangent along which an
    /// anisotropic material's `alpha_x` applies (the fibre direction for hair).
    pub frame: Frame,
    /// The shape hit (an index into the scene's shape table).
    pub shape: ShapeId,
    /// How far to move a ray's origin off this surface to avoid hitting it again.
    pub(crate) epsilon: f32,
    /// True for hair fibres: rays leave from the fibre's axis, which the fibre test ignores.
    pub(crate) fibre: bool,
}

impl Hit {
    /// A ray leaving this surface along the unit direction `dir`. Its origin is pushed off
    /// the surface on the side `dir` points to, so it cannot hit the same surface again at
    /// `t ≈ 0` (which a ray starting exactly on the surface would, by rounding).
    #[inline]
    pub fn spawn(&self, dir: Vec3) -> Ray {
        Ray::new(self.offset_origin(dir), dir)
    }

    /// A ray from this surface towards the point `q`, and the distance along it at which a
    /// shadow test must stop: just short of `q`, so that the surface `q` lies on (a light)
    /// does not count as a blocker. The distance is 0 when `q` is (almost) the hit point.
    #[inline]
    pub fn spawn_to(&self, q: Vec3) -> (Ray, f32) {
        let d = q - self.p;
        let dist = d.length();
        if dist.is_nan() || dist <= self.epsilon {
            return (Ray::new(self.p, self.n), 0.0);
        }
        let origin = self.offset_origin(d / dist);
        // The direction is taken from the offset origin: a ray parallel to `q − p` but
        // shifted off the surface would pass beside `q`, and near grazing it would enter
        // the light's own surface before reaching `q`.
        let to_q = q - origin;
        let length = to_q.length();
        let q_eps = 1e-4 * (1.0 + q.abs().max_element());
        (Ray::new(origin, to_q / length), (length - q_eps).max(0.0))
    }

    fn offset_origin(&self, dir: Vec3) -> Vec3 {
        if self.fibre {
            self.p
        } else if dir.dot(self.n) >= 0.0 {
            self.p + self.epsilon * self.n
        } else {
            self.p - self.epsilon * self.n
        }
    }
}

/// The origin offset used for a hit at `p`: relative to the size of the coordinates, since
/// the rounding error of an intersection grows with them.
#[inline]
pub(crate) fn offset_epsilon(p: Vec3) -> f32 {
    1e-4 * (1.0 + p.abs().max_element())
}
