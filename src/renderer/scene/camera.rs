use crate::geometry::Ray;
use glam::Vec3;

/// A pinhole camera.
///
/// Image conventions (shared with other renderers so images compare): pixel `(x, y)` covers
/// the square `[x, x+1) × [y, y+1)` of the image plane, `y = 0` is the top row, `+x` is the
/// camera's right (`forward × up`), and the full vertical field of view spans the image
/// height. A pixel's value is the plain average of the radiance over its square (a box
/// filter).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Position of the pinhole.
    pub eye: Vec3,
    /// Unit view direction.
    pub forward: Vec3,
    /// Unit right vector (image +x).
    pub right: Vec3,
    /// Unit up vector (image −y), orthogonal to `forward` and `right`.
    pub up: Vec3,
    /// tan(fov / 2): half the image height at distance 1.
    pub tan_half_fov: f32,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
}

impl Camera {
    /// A camera at `eye` looking at `target`, with `up` roughly up and a full vertical field
    /// of view of `fov_deg` degrees. `None` when `eye == target` or `up` is parallel to the
    /// view direction.
    pub fn look_at(
        eye: Vec3,
        target: Vec3,
        up: Vec3,
        fov_deg: f32,
        width: u32,
        height: u32,
    ) -> Option<Self> {
        let forward = (target - eye).try_normalize()?;
        let right = forward.cross(up).try_normalize()?;
        let up = right.cross(forward);
        Some(Self {
            eye,
            forward,
            right,
            up,
            tan_half_fov: (0.5 * fov_deg.to_radians()).tan(),
            width,
            height,
        })
    }

    /// The ray through the image-plane position `(x, y)` in pixel units (`x ∈ [0, width)`,
    /// `y ∈ [0, height)`, `y` down).
    #[inline]
    pub fn ray(&self, x: f32, y: f32) -> Ray {
        let h = self.height as f32;
        let sx = (2.0 * x - self.width as f32) / h * self.tan_half_fov;
        let sy = (h - 2.0 * y) / h * self.tan_half_fov;
        Ray::new(
            self.eye,
            (self.forward + sx * self.right + sy * self.up).normalize(),
        )
    }
}
