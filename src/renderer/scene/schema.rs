//! The scene file format: YAML read by serde-saphyr into these types. Unknown keys are
//! errors. Enums are externally tagged (`- sphere: {...}`), which keeps every error at the
//! exact line and column of the value at fault.
//!
//! ```yaml
//! camera: {eye: [0, 1, 3.4], target: [0, 1, 0], up: [0, 1, 0], fov: 40, width: 256, height: 256}
//! render: {spp: 64, max_depth: ~, rr_depth: 5, strategy: mis, heuristic: power, seed: 0}
//! materials:
//!   white: {diffuse: {albedo: 0.73}}
//! shapes:
//!   - sphere: {center: [0, 0.5, 0], radius: 0.5, material: white}
//!   - quad: {origin: [-0.25, 1.99, -0.25], edge1: [0.5, 0, 0], edge2: [0, 0, 0.5], emission: 15}
//! lights:
//!   - environment: {radiance: 1}
//! ```

use super::values::{
    Asymmetry, Direction, FovDegrees, Ior, NonNegative, Point, Positive, Rgb, Roughness,
};
use crate::bsdf::{FresnelModel, HemisphereSampling};
pub use crate::integrator::MisHeuristic;
use serde::Deserialize;
use serde_saphyr::Spanned;
use std::collections::BTreeMap;

/// A whole scene file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    /// The pinhole camera.
    pub camera: CameraSpec,
    /// Render settings.
    #[serde(default)]
    pub render: RenderSpec,
    /// Named materials.
    #[serde(default)]
    pub materials: BTreeMap<String, Spanned<MaterialSpec>>,
    /// Named media.
    #[serde(default)]
    pub media: BTreeMap<String, Spanned<MediumSpec>>,
    /// The shapes.
    #[serde(default)]
    pub shapes: Vec<Spanned<ShapeSpec>>,
    /// Lights that are not shapes.
    #[serde(default)]
    pub lights: Vec<Spanned<LightSpec>>,
}

/// A pinhole camera.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CameraSpec {
    /// Position of the pinhole.
    pub eye: Spanned<Point>,
    /// A point the camera looks at (the image centre).
    pub target: Point,
    /// Which way is up (need not be orthogonal to the view direction).
    #[serde(default = "default_up")]
    pub up: Spanned<Direction>,
    /// Full vertical field of view, degrees.
    pub fov: FovDegrees,
    /// Image width in pixels.
    pub width: Spanned<u32>,
    /// Image height in pixels.
    pub height: Spanned<u32>,
}

fn default_up() -> Spanned<Direction> {
    let here = serde_saphyr::Location::UNKNOWN;
    Spanned::new(Direction(glam::Vec3::Y), here, here)
}

/// Which estimator of direct light the renderer uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "snake_case")]
pub enum Strategy {
    /// BSDF sampling only.
    Bsdf,
    /// Light sampling only.
    Light,
    /// Both, combined by multiple importance sampling.
    Mis,
}

/// How shadow rays estimate the transmittance through media.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum TransmittanceEstimator {
    /// Ratio tracking (framework).
    #[default]
    Ratio,
    /// Delta tracking (the task): 1 if the path escapes, 0 otherwise.
    Delta,
    /// The closed form `exp(−σt d)`; homogeneous media only.
    Analytic,
}

/// Render settings.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RenderSpec {
    /// Samples (paths) per pixel.
    #[serde(default = "default_spp")]
    pub spp: Spanned<u32>,
    /// Maximum number of path segments (1: emitters seen directly; 2: direct lighting);
    /// absent or `~` for unbounded (Russian roulette ends paths).
    #[serde(default)]
    pub max_depth: Option<Spanned<u32>>,
    /// Segments beyond this many face Russian roulette.
    #[serde(default = "default_rr_depth")]
    pub rr_depth: u32,
    /// Direct-light estimator: `bsdf`, `light` or `mis` (default `mis`; `light` in scenes
    /// with media, which only support light sampling).
    #[serde(default)]
    pub strategy: Option<Spanned<Strategy>>,
    /// The MIS weighting when `strategy: mis` (`balance` or `power`, default `power`).
    #[serde(default)]
    pub heuristic: Option<MisHeuristic>,
    /// Seed of every pixel's random sequence.
    #[serde(default)]
    pub seed: u64,
    /// Transmittance estimator for shadow rays in media.
    #[serde(default)]
    pub transmittance: Option<Spanned<TransmittanceEstimator>>,
}

fn default_spp() -> Spanned<u32> {
    let here = serde_saphyr::Location::UNKNOWN;
    Spanned::new(16, here, here)
}

fn default_rr_depth() -> u32 {
    5
}

impl Default for RenderSpec {
    fn default() -> Self {
        Self {
            spp: default_spp(),
            max_depth: None,
            rr_depth: default_rr_depth(),
            strategy: None,
            heuristic: None,
            seed: 0,
            transmittance: None,
        }
    }
}

/// A material.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum MaterialSpec {
    /// Lambertian.
    Diffuse {
        /// Reflectance (a warning above 1).
        albedo: Spanned<Rgb>,
        /// `cosine` (default) or `uniform` hemisphere sampling.
        #[serde(default)]
        sampling: HemisphereSampling,
    },
    /// A perfect mirror.
    Mirror {
        /// Reflectance (default 1).
        #[serde(default)]
        reflectance: Option<Spanned<Rgb>>,
    },
    /// Smooth glass or water.
    Dielectric {
        /// Index inside (opposite the normal).
        ior: Ior,
        /// Index outside (on the normal's side), default 1.
        #[serde(default)]
        ext_ior: Option<Ior>,
        /// `exact` (default) or `schlick`.
        #[serde(default)]
        fresnel: FresnelModel,
    },
    /// A rough conductor (GGX microfacets).
    Conductor(ConductorSpec),
    /// Phong.
    Phong {
        /// Diffuse coefficient.
        kd: Rgb,
        /// Specular coefficient.
        ks: Rgb,
        /// Specular exponent.
        exponent: NonNegative,
    },
    /// Kajiya-Kay hair.
    KajiyaKay {
        /// Diffuse coefficient.
        kd: Rgb,
        /// Specular coefficient.
        ks: Rgb,
        /// Specular exponent.
        exponent: NonNegative,
    },
}

/// A rough conductor: one roughness form and one colour form.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConductorSpec {
    /// Isotropic roughness α.
    #[serde(default)]
    pub roughness: Option<Roughness>,
    /// Roughness along the surface tangent.
    #[serde(default)]
    pub alpha_x: Option<Roughness>,
    /// Roughness across the surface tangent.
    #[serde(default)]
    pub alpha_y: Option<Roughness>,
    /// Reflectance at normal incidence.
    #[serde(default)]
    pub reflectance: Option<Spanned<Rgb>>,
    /// Real part of the complex index of refraction, per channel.
    #[serde(default)]
    pub eta: Option<Rgb>,
    /// Imaginary part (extinction coefficient), per channel.
    #[serde(default)]
    pub k: Option<Rgb>,
}

/// A participating medium.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum MediumSpec {
    /// Constant coefficients.
    Homogeneous {
        /// Absorption coefficient per unit length.
        sigma_a: NonNegative,
        /// Scattering coefficient per unit length.
        sigma_s: NonNegative,
        /// Henyey-Greenstein asymmetry (default 0).
        #[serde(default)]
        g: Option<Asymmetry>,
    },
    /// Coefficients scaled by a density grid spanning the bounding box of its shape.
    Grid {
        /// Where the densities come from.
        density: DensitySpec,
        /// Absorption coefficient at density 1.
        sigma_a: NonNegative,
        /// Scattering coefficient at density 1.
        sigma_s: NonNegative,
        /// Henyey-Greenstein asymmetry (default 0).
        #[serde(default)]
        g: Option<Asymmetry>,
    },
}

/// The source of a density grid.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum DensitySpec {
    /// A text file: `nx ny nz`, then the values, x fastest (see `crate::scene::grid_file`).
    File(Spanned<String>),
    /// A procedural cloud: fractal value noise under a spherical falloff.
    Cloud {
        /// Grid points per axis (2 to 256).
        resolution: Spanned<u32>,
        /// Seed of the noise.
        #[serde(default)]
        seed: u64,
        /// Noise frequency across the box (default 4).
        #[serde(default)]
        frequency: Option<Positive>,
        /// Octaves of noise (1 to 8, default 4).
        #[serde(default)]
        octaves: Option<Spanned<u32>>,
    },
}

/// A shape. Every kind but `fibres` also takes `material` (a material's name), `emission`
/// (radiance emitted on the normal's side: the shape becomes an area light) and `medium`
/// (a medium's name: the medium fills the closed shape, whose boundary is then
/// index-matched and takes no material).
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum ShapeSpec {
    /// A sphere.
    Sphere {
        /// Centre.
        center: Point,
        /// Radius.
        radius: Positive,
        /// Material name.
        #[serde(default)]
        material: Option<Spanned<String>>,
        /// Emitted radiance.
        #[serde(default)]
        emission: Option<Spanned<Rgb>>,
        /// Medium inside.
        #[serde(default)]
        medium: Option<Spanned<String>>,
    },
    /// A parallelogram `origin + u edge1 + v edge2`, normal `edge1 × edge2`.
    Quad {
        /// Corner.
        origin: Point,
        /// First edge.
        edge1: Point,
        /// Second edge.
        edge2: Point,
        /// Material name.
        #[serde(default)]
        material: Option<Spanned<String>>,
        /// Emitted radiance.
        #[serde(default)]
        emission: Option<Spanned<Rgb>>,
    },
    /// An axis-aligned box (six quads, normals outwards).
    Box {
        /// Lower corner.
        min: Point,
        /// Upper corner.
        max: Point,
        /// Material name.
        #[serde(default)]
        material: Option<Spanned<String>>,
        /// Emitted radiance.
        #[serde(default)]
        emission: Option<Spanned<Rgb>>,
        /// Medium inside.
        #[serde(default)]
        medium: Option<Spanned<String>>,
    },
    /// A triangle mesh from an OBJ file.
    Mesh {
        /// Path of the OBJ file, relative to the scene file.
        file: Spanned<String>,
        /// Placement of the model.
        #[serde(default)]
        transform: TransformSpec,
        /// Material name.
        #[serde(default)]
        material: Option<Spanned<String>>,
        /// Emitted radiance.
        #[serde(default)]
        emission: Option<Spanned<Rgb>>,
        /// Medium inside (the mesh must be closed).
        #[serde(default)]
        medium: Option<Spanned<String>>,
    },
    /// Hair fibres.
    Fibres {
        /// Where the strands come from.
        strands: StrandsSpec,
        /// Half-width of every fibre.
        radius: Positive,
        /// Material name (normally a `kajiya_kay` one).
        material: Spanned<String>,
    },
}

/// The material, emission and medium of a shape, borrowed from its spec.
pub struct SurfaceRefs<'a> {
    /// Material name.
    pub material: Option<&'a Spanned<String>>,
    /// Emitted radiance.
    pub emission: Option<&'a Spanned<Rgb>>,
    /// Medium name.
    pub medium: Option<&'a Spanned<String>>,
}

impl ShapeSpec {
    /// The shape's material, emission and medium.
    pub fn surface(&self) -> SurfaceRefs<'_> {
        match self {
            ShapeSpec::Sphere {
                material,
                emission,
                medium,
                ..
            }
            | ShapeSpec::Box {
                material,
                emission,
                medium,
                ..
            }
            | ShapeSpec::Mesh {
                material,
                emission,
                medium,
                ..
            } => SurfaceRefs {
                material: material.as_ref(),
                emission: emission.as_ref(),
                medium: medium.as_ref(),
            },
            ShapeSpec::Quad {
                material, emission, ..
            } => SurfaceRefs {
                material: material.as_ref(),
                emission: emission.as_ref(),
                medium: None,
            },
            ShapeSpec::Fibres { material, .. } => SurfaceRefs {
                material: Some(material),
                emission: None,
                medium: None,
            },
        }
    }
}

/// Placement of a mesh: `p' = translate + R (scale ∘ p)`, with `R` rotating about x, then y,
/// then z.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct TransformSpec {
    /// Scale per axis, or one number for all.
    #[serde(default = "unit_scale")]
    pub scale: Spanned<Rgb>,
    /// Rotation angles about x, y and z in degrees.
    #[serde(default = "zero_point")]
    pub rotate: Point,
    /// Translation.
    #[serde(default = "zero_point")]
    pub translate: Point,
}

fn unit_scale() -> Spanned<Rgb> {
    let here = serde_saphyr::Location::UNKNOWN;
    Spanned::new(Rgb(glam::Vec3::ONE), here, here)
}

fn zero_point() -> Point {
    Point(glam::Vec3::ZERO)
}

impl Default for TransformSpec {
    fn default() -> Self {
        Self {
            scale: unit_scale(),
            rotate: zero_point(),
            translate: zero_point(),
        }
    }
}

/// Where hair strands come from.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum StrandsSpec {
    /// A text file of strands (see `crate::scene::strands`).
    File(Spanned<String>),
    /// A ball of hair: strands rooted on a sphere growing outwards and curling.
    Ball {
        /// Centre of the ball.
        center: Point,
        /// Radius of the sphere the strands grow from.
        radius: Positive,
        /// Number of strands (1 to 200 000).
        count: Spanned<u32>,
        /// Length of every strand.
        length: Positive,
        /// Segments per strand (1 to 64).
        segments: Spanned<u32>,
        /// How strongly strands wander sideways (0: straight).
        #[serde(default)]
        curl: Option<NonNegative>,
        /// Seed for the random roots and curls.
        #[serde(default)]
        seed: u64,
    },
}

/// A light that is not an emitting shape.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum LightSpec {
    /// A point light.
    Point {
        /// Position.
        position: Point,
        /// Radiant intensity (W/sr).
        intensity: Rgb,
    },
    /// Constant radiance from every direction.
    Environment {
        /// Radiance.
        radiance: Rgb,
    },
}
