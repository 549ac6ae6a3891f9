use super::Ray;
use super::hit::{Hit, ShapeId, offset_epsilon};
use crate::math::Frame;
use glam::Vec3;

/// A parallelogram `origin + u edge1 + v edge2`, `u, v ∈ [0, 1]`, one-sided for emission
/// only: its normal is `normalize(edge1 × edge2)`. Its anisotropy tangent is `edge1`.
#[derive(Clone, Copy, Debug)]
pub struct Quad {
    /// One corner.
    pub origin: Vec3,
    /// First edge from `origin`.
    pub edge1: Vec3,
    /// Second edge from `origin`.
    pub edge2: Vec3,
    /// Unit normal `normalize(edge1 × edge2)`.
    pub n: Vec3,
    /// `n · origin`: the plane offset.
    plane: f32,
    /// Dual basis: `u = (p − origin)·dual1`, `v = (p − origin)·dual2`.
    dual1: Vec3,
    dual2: Vec3,
    /// Shading frame (the same at every point).
    frame: Frame,
    /// The shape this quad belongs to.
    pub shape: ShapeId,
}

impl Quad {
    /// A quad, or `None` when the edges are parallel or zero (no area).
    pub fn new(origin: Vec3, edge1: Vec3, edge2: Vec3, shape: ShapeId) -> Option<Self> {
        let cross = edge1.cross(edge2);
        let area = cross.length();
        if !area.is_finite() || area <= 0.0 {
            return None;
        }
        let n = cross / area;
        let dual1 = edge2.cross(n) / edge1.dot(edge2.cross(n));
        let dual2 = n.cross(edge1) / edge2.dot(n.cross(edge1));
        Some(Self {
            origin,
            edge1,
            edge2,
            n,
            plane: n.dot(origin),
            dual1,
            dual2,
            frame: Frame::from_normal_tangent(n, edge1),
            shape,
        })
    }

    /// The first vector of the dual basis (`u = (p − origin)·dual1`).
    pub fn dual1(&self) -> Vec3 {
        self.dual1
    }

    /// The second vector of the dual basis (`v = (p − origin)·dual2`).
    pub fn dual2(&self) -> Vec3 {
        self.dual2
    }

    /// Surface area.
    pub fn area(&self) -> f32 {
        self.edge1.cross(self.edge2).length()
    }

    /// The intersection distance in `(0, t_max)`, if any.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<f32> {
        let denom = self.n.dot(ray.dir);
        if denom == 0.0 {
            return None;
        }
        let t = (self.plane - self.n.dot(ray.origin)) / denom;
        if !(t > 0.0 && t < t_max) {
            return None;
        }
        let d = ray.at(t) - self.origin;
        let u = d.dot(self.dual1);
        let v = d.dot(self.dual2);
        if (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v) {
            Some(t)
        } else {
            None
        }
    }

    /// The full hit record at distance `t` along `ray`.
    #[inline]
    pub fn hit(&self, ray: &Ray, t: f32) -> Hit {
        let p = ray.at(t);
        Hit {
            t,
            p,
            n: self.n,
            frame: self.frame,
            shape: self.shape,
            epsilon: offset_epsilon(p),
            fibre: false,
        }
    }
}
