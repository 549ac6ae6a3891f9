//! Shapes and ray intersection: analytic spheres and quads tested one by one, triangle
//! meshes and hair fibres through a BVH each (built only when the scene has them).

mod bvh;
mod fibre;
mod hit;
mod mesh;
mod quad;
mod ray;
mod sphere;
mod triangle;

pub use bvh::{Bvh, to_obvhs};
pub use fibre::{FibreSegment, FibreSet};
pub use hit::{Hit, ShapeId};
pub use mesh::TriangleSet;
pub use quad::Quad;
pub use ray::Ray;
pub use sphere::Sphere;
pub use triangle::{WatertightRay, double_area};

/// A set of surfaces that rays can hit.
#[derive(Default)]
pub struct Geometry {
    /// Analytic spheres.
    pub spheres: Vec<Sphere>,
    /// Analytic parallelograms (boxes are six of them).
    pub quads: Vec<Quad>,
    /// Mesh triangles, when the scene has meshes.
    pub triangles: Option<TriangleSet>,
    /// Hair fibre segments, when the scene has fibres.
    pub fibres: Option<FibreSet>,
}

/// Which primitive a closest-hit search found.
#[derive(Clone, Copy)]
enum Primitive {
    Sphere(usize),
    Quad(usize),
    Triangle(usize),
    Fibre(usize),
}

impl Geometry {
    /// True when there is nothing to hit.
    pub fn is_empty(&self) -> bool {
        self.spheres.is_empty()
            && self.quads.is_empty()
            && self.triangles.is_none()
            && self.fibres.is_none()
    }

    /// The nearest surface along `ray` in `(0, t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let mut best = t_max;
        let mut found = None;
        for (i, s) in self.spheres.iter().enumerate() {
            if let Some(t) = s.intersect(ray, best) {
                best = t;
                found = Some(Primitive::Sphere(i));
            }
        }
        for (i, q) in self.quads.iter().enumerate() {
            if let Some(t) = q.intersect(ray, best) {
                best = t;
                found = Some(Primitive::Quad(i));
            }
        }
        if let Some(tris) = &self.triangles
            && let Some((t, slot)) = tris.intersect(ray, best)
        {
            best = t;
            found = Some(Primitive::Triangle(slot));
        }
        if let Some(fibres) = &self.fibres
            && let Some((t, slot)) = fibres.intersect(ray, best)
        {
            best = t;
            found = Some(Primitive::Fibre(slot));
        }
        match found? {
            Primitive::Sphere(i) => Some(self.spheres[i].hit(ray, best)),
            Primitive::Quad(i) => Some(self.quads[i].hit(ray, best)),
            Primitive::Triangle(slot) => self.triangles.as_ref().map(|m| m.hit(ray, best, slot)),
            Primitive::Fibre(slot) => self.fibres.as_ref().map(|f| f.hit(ray, best, slot)),
        }
    }

    /// True when any surface lies along `ray` in `(0, t_max)`.
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        self.quads.iter().any(|q| q.intersect(ray, t_max).is_some())
            || self
                .spheres
                .iter()
                .any(|s| s.intersect(ray, t_max).is_some())
            || self
                .triangles
                .as_ref()
                .is_some_and(|m| m.occluded(ray, t_max))
            || self.fibres.as_ref().is_some_and(|f| f.occluded(ray, t_max))
    }
}
