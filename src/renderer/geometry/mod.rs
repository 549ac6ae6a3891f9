//! Shapes and ray intersection: analytic spheres and quads tested four at a time, triangle
//! meshes and hair fibres through a BVH each (built only when the scene has them).

mod bvh;
mod fibre;
mod hit;
mod mesh;
mod packs;
mod quad;
mod ray;
mod sphere;
mod triangle;

pub use fibre::{FibreSegment, FibreSet};
pub use hit::{Hit, ShapeId};
pub use mesh::TriangleSet;
pub use quad::Quad;
pub use ray::Ray;
pub use sphere::Sphere;
pub use triangle::{WatertightRay, double_area};

use packs::{QuadPack, Ray4, SpherePack, nearest_lane};

/// A set of surfaces that rays can hit.
#[derive(Default)]
pub struct Geometry {
    spheres: Vec<Sphere>,
    quads: Vec<Quad>,
    sphere_packs: Vec<SpherePack>,
    quad_packs: Vec<QuadPack>,
    triangles: Option<TriangleSet>,
    fibres: Option<FibreSet>,
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
    /// A set of surfaces; the BVHs of `triangles` and `fibres` are built already.
    pub fn new(
        spheres: Vec<Sphere>,
        quads: Vec<Quad>,
        triangles: Option<TriangleSet>,
        fibres: Option<FibreSet>,
    ) -> Self {
        Self {
            sphere_packs: SpherePack::pack(&spheres),
            quad_packs: QuadPack::pack(&quads),
            spheres,
            quads,
            triangles,
            fibres,
        }
    }

    /// True when there is nothing to hit.
    pub fn is_empty(&self) -> bool {
        self.spheres.is_empty()
            && self.quads.is_empty()
            && self.triangles.is_none()
            && self.fibres.is_none()
    }

    /// The analytic spheres.
    pub fn spheres(&self) -> &[Sphere] {
        &self.spheres
    }

    /// The analytic quads (boxes are six of them).
    pub fn quads(&self) -> &[Quad] {
        &self.quads
    }

    /// The mesh triangles, when there are meshes.
    pub fn triangles(&self) -> Option<&TriangleSet> {
        self.triangles.as_ref()
    }

    /// The hair fibres, when there are fibres.
    pub fn fibres(&self) -> Option<&FibreSet> {
        self.fibres.as_ref()
    }

    /// The nearest surface along `ray` in `(0, t_max)`.
    #[inline]
    pub fn intersect(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        let mut best = t_max;
        let mut found = None;
        let r4 = Ray4::new(ray);
        for (p, pack) in self.sphere_packs.iter().enumerate() {
            if let Some((t, lane)) = nearest_lane(pack.intersect(&r4, best), best) {
                best = t;
                found = Some(Primitive::Sphere(4 * p + lane));
            }
        }
        for (p, pack) in self.quad_packs.iter().enumerate() {
            if let Some((t, lane)) = nearest_lane(pack.intersect(&r4, best), best) {
                best = t;
                found = Some(Primitive::Quad(4 * p + lane));
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
        let r4 = Ray4::new(ray);
        self.quad_packs
            .iter()
            .any(|p| p.intersect(&r4, t_max).cmplt(glam::Vec4::INFINITY).any())
            || self
                .sphere_packs
                .iter()
                .any(|p| p.intersect(&r4, t_max).cmplt(glam::Vec4::INFINITY).any())
            || self
                .triangles
                .as_ref()
                .is_some_and(|m| m.occluded(ray, t_max))
            || self.fibres.as_ref().is_some_and(|f| f.occluded(ray, t_max))
    }
}
