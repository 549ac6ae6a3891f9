use crate::geometry::{Quad, Sphere};
use crate::sampling::uniform_sphere;
use glam::{Vec2, Vec3};

/// A piece of an emitting surface that can be sampled uniformly by area.
#[derive(Clone, Copy, Debug)]
pub enum Patch {
    /// A whole sphere (points on its back are sampled too; they face away from the
    /// shading point and contribute nothing).
    Sphere {
        /// Centre.
        center: Vec3,
        /// Radius.
        radius: f32,
    },
    /// A parallelogram `origin + u edge1 + v edge2`.
    Quad {
        /// Corner.
        origin: Vec3,
        /// First edge.
        edge1: Vec3,
        /// Second edge.
        edge2: Vec3,
        /// Unit normal (the emitting side).
        n: Vec3,
    },
    /// A triangle.
    Triangle {
        /// Vertices.
        v: [Vec3; 3],
        /// Unit normal `(v1 − v0) × (v2 − v0)`, normalised.
        n: Vec3,
    },
}

impl Patch {
    /// A patch for a sphere.
    pub fn sphere(s: &Sphere) -> Self {
        Patch::Sphere {
            center: s.center,
            radius: s.radius,
        }
    }

    /// A patch for a quad.
    pub fn quad(q: &Quad) -> Self {
        Patch::Quad {
            origin: q.origin,
            edge1: q.edge1,
            edge2: q.edge2,
            n: q.n,
        }
    }

    /// Surface area.
    pub fn area(&self) -> f32 {
        match self {
            Patch::Sphere { radius, .. } => 4.0 * std::f32::consts::PI * radius * radius,
            Patch::Quad { edge1, edge2, .. } => edge1.cross(*edge2).length(),
            Patch::Triangle { v, .. } => 0.5 * (v[1] - v[0]).cross(v[2] - v[0]).length(),
        }
    }

    /// A point uniform by area and the unit normal there.
    pub fn sample(&self, u: Vec2) -> (Vec3, Vec3) {
        match *self {
            Patch::Sphere { center, radius } => {
                let n = uniform_sphere(u);
                (center + radius * n, n)
            }
            Patch::Quad {
                origin,
                edge1,
                edge2,
                n,
            } => (origin + u.x * edge1 + u.y * edge2, n),
            Patch::Triangle { v, n } => {
                // Uniform barycentrics by the square-root warp.
                let su = u.x.sqrt();
                let (b1, b2) = (1.0 - su, u.y * su);
                (v[0] + b1 * (v[1] - v[0]) + b2 * (v[2] - v[0]), n)
            }
        }
    }
}
