use glam::Vec3;

/// A ray: the points `origin + t dir` for `t > 0`. `dir` has unit length and is the
/// direction of travel (so a direction *away from the surface* at the ray's origin, and
/// the negative of the `wo` that the point it hits sees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// Where the ray starts (already offset from the surface it leaves, see
    /// [`super::Hit::spawn`]).
    pub origin: Vec3,
    /// Unit direction of travel.
    pub dir: Vec3,
}

impl Ray {
    /// A ray from `origin` along `dir`, which must have unit length.
    pub fn new(origin: Vec3, dir: Vec3) -> Self {
        Self { origin, dir }
    }

    /// The point at distance `t` along the ray.
    #[inline]
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.dir
    }
}
