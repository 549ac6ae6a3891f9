use glam::Vec3;

/// An orthonormal basis `(s, t, n)`: the local shading frame, with `n` as +z.
///
/// `to_local` maps world directions into the frame (so `to_local(n) = (0, 0, 1)`), and
/// `to_world` maps back. For anisotropic materials `s` is the tangent along which the
/// roughness `alpha_x` applies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// First tangent (local +x).
    pub s: Vec3,
    /// Second tangent (local +y).
    pub t: Vec3,
    /// Normal (local +z).
    pub n: Vec3,
}

impl Frame {
    /// A frame around the unit normal `n`, with tangents chosen by the branchless method of
    /// Duff et al. 2017 ("Building an Orthonormal Basis, Revisited").
    pub fn from_normal(n: Vec3) -> Self {
        let sign = 1.0f32.copysign(n.z);
        let a = -1.0 / (sign + n.z);
        let b = n.x * n.y * a;
        let s = Vec3::new(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
        let t = Vec3::new(b, sign + n.y * n.y * a, -n.y);
        Self { s, t, n }
    }

    /// A frame with normal `n` whose first tangent is `tangent` made orthogonal to `n`
    /// (Gram-Schmidt). Falls back to [`Frame::from_normal`] when `tangent` is parallel to `n`.
    pub fn from_normal_tangent(n: Vec3, tangent: Vec3) -> Self {
        let s = tangent - n * n.dot(tangent);
        let len2 = s.length_squared();
        if len2 < 1e-12 || !len2.is_finite() {
            return Self::from_normal(n);
        }
        let s = s / len2.sqrt();
        Self {
            s,
            t: n.cross(s),
            n,
        }
    }

    /// Expresses the world direction `v` in this frame.
    pub fn to_local(&self, v: Vec3) -> Vec3 {
        Vec3::new(v.dot(self.s), v.dot(self.t), v.dot(self.n))
    }

    /// Expresses the local direction `v` in world coordinates.
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        self.s * v.x + self.t * v.y + self.n * v.z
    }
}
