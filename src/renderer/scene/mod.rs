//! Scenes: the YAML format ([`schema`]), loading and validation with located errors
//! ([`Scene::load`], [`LoadOptions`]), the analysis of what a scene needs ([`Needs`]), and
//! [`Scene`], the framework API that integrators — the worksheet's tasks and the reference
//! alike — call.
//!
//! # Conventions (kept by every part of the renderer)
//! - Image: a pixel's value is the plain average of radiance over its square (box filter);
//!   row 0 is the top of the image; +x is the camera's right. See [`Camera`].
//! - Surfaces: opaque materials are two-sided; a dielectric's normal side is its outside;
//!   an area light emits only on the side its normal faces. See [`crate::geometry::Hit`].
//! - Microfacets: GGX with the separable Smith masking-shadowing `G1(wo) G1(wi)`.
//! - Depth: `max_depth` counts path segments: 1 shows only emitters seen directly, 2 adds
//!   direct lighting, and so on.
//! - Units: radiance and emission in linear RGB; lengths in scene units; angles in the
//!   file in degrees.

mod camera;
mod density;
mod error;
mod load;
mod medium;
mod needs;
mod obj;
pub mod schema;
mod settings;
mod strands;
mod text_file;
mod values;

pub use camera::Camera;
pub use error::{Position, SceneError, SceneWarning};
pub use load::{LoadOptions, MAX_PIXELS_PER_SIDE, MAX_REACH};
pub use medium::{MediumKind, SceneMedium};
pub use needs::{Needs, with_dependencies};
pub use settings::{RenderSettings, UNBOUNDED_DEPTH};

use crate::bsdf::{Bsdf, Material};
use crate::geometry::{Geometry, Hit, Ray, ShapeId};
use crate::integrator::Heuristic;
use crate::light::{LightSample, Lights};
use crate::sampling::Sampler;
use glam::Vec3;
use std::cell::Cell;
use std::path::{Path, PathBuf};

/// What the scene knows about each shape besides its geometry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeInfo {
    /// Index into the scene's materials; `None` for an index-matched medium boundary.
    pub material: Option<u32>,
    /// Radiance emitted on the normal's side (zero when the shape is not a light).
    pub emission: Vec3,
    /// Index of the medium inside the shape, if any.
    pub medium: Option<u32>,
}

/// A loaded scene, ready to render: only the parts it needs are built (see [`Needs`]).
///
/// The methods below are the framework API for integrators. Directions point away from
/// the surface; densities say their measure.
pub struct Scene {
    pub(crate) file: PathBuf,
    pub(crate) camera: Camera,
    pub(crate) settings: RenderSettings,
    pub(crate) surfaces: Geometry,
    pub(crate) boundaries: Option<Geometry>,
    pub(crate) shapes: Vec<ShapeInfo>,
    pub(crate) materials: Vec<Material>,
    pub(crate) lights: Option<Lights>,
    pub(crate) media: Vec<SceneMedium>,
    pub(crate) needs: Needs,
    pub(crate) warnings: Vec<SceneWarning>,
}

thread_local! {
    static RAYS: Cell<u64> = const { Cell::new(0) };
}

/// Rays this thread has cast through [`Scene::intersect`] and [`Scene::occluded`] since the
/// last call, in this build's code and in the reference libraries it loaded
/// ([`crate::compiled_reference::take_library_rays`]); resets the count.
pub fn take_ray_count() -> u64 {
    RAYS.with(|c| c.replace(0)) + crate::compiled_reference::take_library_rays()
}

#[inline]
fn count_ray() {
    RAYS.with(|c| c.set(c.get() + 1));
}

impl Scene {
    /// Loads the scene file at `path` (see [`schema`] for the format).
    pub fn load(path: &Path, options: &LoadOptions) -> Result<Scene, SceneError> {
        load::load(path, options)
    }

    /// Builds a scene from YAML text; `file` names it in messages and is the directory that
    /// relative paths (meshes, grids, strands) are resolved against.
    pub fn from_yaml(file: &Path, text: &str, options: &LoadOptions) -> Result<Scene, SceneError> {
        load::from_yaml(file, text, options)
    }

    /// The scene file.
    pub fn file(&self) -> &Path {
        &self.file
    }

    /// The camera.
    pub fn camera(&self) -> &Camera {
        &self.camera
    }

    /// The render settings.
    pub fn settings(&self) -> &RenderSettings {
        &self.settings
    }

    /// The MIS weighting the scene's strategy asks for (what `path_trace` passes to `mis`).
    pub fn heuristic(&self) -> Heuristic {
        self.settings.heuristic
    }

    /// What the scene needs.
    pub fn needs(&self) -> &Needs {
        &self.needs
    }

    /// Problems found while loading that did not stop it.
    pub fn warnings(&self) -> &[SceneWarning] {
        &self.warnings
    }

    /// Shape table entry of `shape`.
    pub fn shape(&self, shape: ShapeId) -> &ShapeInfo {
        &self.shapes[shape as usize]
    }

    /// The media of the scene.
    pub fn media(&self) -> &[SceneMedium] {
        &self.media
    }

    /// The opaque (non-boundary) surfaces: for benchmarks and tests that trace them
    /// directly.
    pub fn surfaces(&self) -> &Geometry {
        &self.surfaces
    }

    /// The first surface along `ray` (medium boundaries included), or `None` when the ray
    /// leaves the scene.
    #[inline]
    pub fn intersect(&self, ray: &Ray) -> Option<Hit> {
        count_ray();
        let hit = self.surfaces.intersect(ray, f32::INFINITY);
        match &self.boundaries {
            None => hit,
            Some(b) => b.intersect(ray, hit.map_or(f32::INFINITY, |h| h.t)).or(hit),
        }
    }

    /// True when a surface blocks `ray` before the distance `t_max` (exclusive). Medium
    /// boundaries do not block. Build the ray with [`Hit::spawn_to`] (towards a point) or
    /// [`Hit::spawn`] with `t_max = f32::INFINITY` (towards the environment), so that it
    /// neither starts on the surface it leaves nor stops on the light it aims at.
    #[inline]
    pub fn occluded(&self, ray: &Ray, t_max: f32) -> bool {
        count_ray();
        t_max > 0.0 && self.surfaces.occluded(ray, t_max)
    }

    /// The BSDF at `hit`. An index-matched medium boundary has none: it gets a black one.
    #[inline]
    pub fn bsdf(&self, hit: &Hit) -> Bsdf<'_> {
        const BLACK: Material = Material::Black;
        let material = self.shapes[hit.shape as usize]
            .material
            .map_or(&BLACK, |m| &self.materials[m as usize]);
        Bsdf::new(material, hit.frame)
    }

    /// Radiance emitted from `hit` towards `wo` (pointing away from the surface): the
    /// shape's emission if `wo` is on the side its normal faces, zero otherwise.
    #[inline]
    pub fn emitted(&self, hit: &Hit, wo: Vec3) -> Vec3 {
        let e = self.shapes[hit.shape as usize].emission;
        if hit.n.dot(wo) > 0.0 { e } else { Vec3::ZERO }
    }

    /// Radiance arriving from the environment along a ray that left the scene in direction
    /// `dir` (zero when the scene has no environment light).
    #[inline]
    pub fn environment(&self, _dir: Vec3) -> Vec3 {
        self.lights.as_ref().map_or(Vec3::ZERO, Lights::environment)
    }

    /// Picks a light (uniformly) and a point or direction on it, for a shading point at
    /// `p`. `None` when the scene has no lights.
    #[inline]
    pub fn sample_light(&self, _p: Vec3, sampler: &mut Sampler) -> Option<LightSample> {
        self.lights.as_ref()?.sample(sampler)
    }

    /// The density per unit *area* with which [`Scene::sample_light`] would have produced
    /// the point of `hit` (0 when the surface hit does not emit). Convert it to solid angle
    /// before comparing it with a BSDF pdf.
    #[inline]
    pub fn light_pdf(&self, hit: &Hit) -> f32 {
        self.lights.as_ref().map_or(0.0, |l| l.pdf_area(hit.shape))
    }

    /// The density per unit *solid angle* with which [`Scene::sample_light`] would have
    /// produced the environment direction `dir` (0 without an environment light).
    #[inline]
    pub fn environment_pdf(&self, _dir: Vec3) -> f32 {
        self.lights.as_ref().map_or(0.0, Lights::environment_pdf)
    }
}
