//! Building a [`Scene`] from its YAML description: parsing (errors at the value's line and
//! column), checking what parsing cannot (names that refer to nothing, shapes without a
//! surface, parallel quad edges, …), reading the files the scene refers to, and building
//! only the parts the scene needs.

use super::error::{SceneError, SceneWarning};
use super::medium::{MediumKind, SceneMedium};
use super::needs::Needs;
use super::obj::load_obj;
use super::schema::{
    CameraSpec, ConductorSpec, DensitySpec, LightSpec, MaterialSpec, MediumSpec, MisHeuristic,
    SceneSpec, ShapeSpec, StrandsSpec, Strategy, TransformSpec, TransmittanceEstimator,
};
use super::settings::{RenderSettings, UNBOUNDED_DEPTH};
use super::{Camera, Scene, ShapeInfo, density, strands};
use crate::bsdf::{ConductorFresnel, HemisphereSampling, KajiyaKayParams, Material, PhongParams};
use crate::geometry::{FibreSegment, FibreSet, Geometry, Quad, Sphere, TriangleSet};
use crate::integrator::Heuristic;
use crate::light::{Light, Lights, Patch};
use crate::medium::{Coefficients, GridMedium, HenyeyGreenstein, Homogeneous};
use crate::task_set::TaskSet;
use crate::worksheet::TaskId;
use glam::{Mat4, Quat, Vec3};
use serde_saphyr::{Location, MessageFormatter, Spanned};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Largest image width or height.
pub const MAX_PIXELS_PER_SIDE: u32 = 8192;
/// Most pixels in an image: 4096 × 4096. A render keeps about 85 bytes per pixel (film
/// sums and a sampler), so this is about 1.4 GB; 8192 × 8192 took 5–6 GB and over a
/// minute at one sample per pixel.
pub const MAX_PIXELS: u64 = 4096 * 4096;
const MAX_SPP: u32 = 1 << 20;
const MAX_STRANDS: u32 = 200_000;
const MAX_STRAND_SEGMENTS: u32 = 64;

/// Settings that override the scene file's (from the command line, tests and studies).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct LoadOptions {
    /// Image width.
    pub width: Option<u32>,
    /// Image height.
    pub height: Option<u32>,
    /// Samples per pixel.
    pub spp: Option<u32>,
    /// Seed.
    pub seed: Option<u64>,
    /// Maximum path depth (segments).
    pub max_depth: Option<u32>,
    /// Russian roulette start depth.
    pub rr_depth: Option<u32>,
    /// Direct-light strategy.
    pub strategy: Option<Strategy>,
    /// MIS weighting for `strategy: mis`.
    pub heuristic: Option<MisHeuristic>,
    /// Hemisphere sampling of every diffuse material.
    pub diffuse_sampling: Option<HemisphereSampling>,
    /// Transmittance estimator for shadow rays through media.
    pub transmittance: Option<TransmittanceEstimator>,
}

/// Reads and builds the scene at `path`.
pub fn load(path: &Path, options: &LoadOptions) -> Result<Scene, SceneError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| SceneError::file(path, format!("cannot read the scene: {e}")))?;
    from_yaml(path, &text, options)
}

/// Builds a scene from YAML `text` that came from `file`.
pub fn from_yaml(file: &Path, text: &str, options: &LoadOptions) -> Result<Scene, SceneError> {
    if text.trim().is_empty() {
        return Err(SceneError::file(file, "the scene file is empty"));
    }
    let spec: SceneSpec = serde_saphyr::from_str(text).map_err(|e| yaml_error(file, text, &e))?;
    let builder = Builder {
        file,
        source: text,
        dir: file.parent().map(Path::to_path_buf).unwrap_or_default(),
        options,
        warnings: Vec::new(),
    };
    builder.build(spec)
}

fn yaml_error(file: &Path, text: &str, e: &serde_saphyr::Error) -> SceneError {
    let message = match e.without_snippet() {
        serde_saphyr::Error::Budget { breach, .. } => too_large(breach),
        other => serde_saphyr::DefaultMessageFormatter
            .format_message(other)
            .escape_debug()
            .to_string(),
    };
    match e.location() {
        Some(l) if l.line() > 0 => {
            let length = usize::try_from(l.line() - 1)
                .ok()
                .and_then(|n| text.lines().nth(n))
                .map_or(0, |line| line.chars().count());
            let message = if length > MAX_KEY {
                format!(
                    "{message} (line {} is {length} characters long: a YAML key may have at \
                     most {MAX_KEY}, and no name or value of a scene is that long)",
                    l.line()
                )
            } else {
                message
            };
            SceneError::at(file, text, l.line(), l.column(), message)
        }
        _ => SceneError::file(file, message),
    }
}

/// The longest key YAML allows without quotes (its implicit-key limit), in characters.
const MAX_KEY: usize = 1024;

/// What a scene file that breaches the YAML loader's limits (set against hostile input:
/// billions of nodes, deep nesting) is told.
fn too_large(breach: &serde_saphyr::budget::BudgetBreach) -> String {
    use serde_saphyr::budget::BudgetBreach;
    let limits = serde_saphyr::Budget::default();
    let what = match breach {
        BudgetBreach::Nodes { .. } => format!(
            "more than {} values (numbers, strings, lists and maps)",
            limits.max_nodes
        ),
        BudgetBreach::Depth { depth } => format!("lists or maps nested {depth} deep"),
        BudgetBreach::ScalarBytes { .. } => "more text than the loader reads".into(),
        other => format!("{other:?}"),
    };
    format!(
        "the scene file is too large for the loader: {what}. Put large geometry in an OBJ \
         mesh or a strand file and refer to it from the scene"
    )
}

struct Builder<'a> {
    file: &'a Path,
    source: &'a str,
    dir: PathBuf,
    options: &'a LoadOptions,
    warnings: Vec<SceneWarning>,
}

/// How far from the origin (in any coordinate) a shape may reach, its size included. Rays
/// are single precision: at 10⁶ a step between two floats is already 0.06 units, and far
/// beyond it a BVH's bounds overflow (a mesh at 3e38 crashed the builder, a fibre radius of
/// 1e8 hung it). Scenes are a few units across.
pub const MAX_REACH: f32 = 1e6;

/// The largest coordinate magnitude of `points` (NaN when one is NaN, so the reach check
/// refuses it).
fn farthest<'p>(points: impl Iterator<Item = &'p Vec3>) -> f32 {
    points.map(|p| p.abs().max_element()).fold(0.0, |a, b| {
        if a.is_nan() || b.is_nan() {
            f32::NAN
        } else {
            a.max(b)
        }
    })
}

/// True when a shape reaching `reach` from the origin is within [`MAX_REACH`] (false for
/// NaN).
fn within_reach(reach: f32) -> bool {
    (0.0..=MAX_REACH).contains(&reach)
}

/// The error for a shape that reaches `reach` from the origin.
fn beyond_reach(reach: f32) -> String {
    format!(
        "this shape reaches {reach:e} from the origin; coordinates and sizes must stay within \
         ±{MAX_REACH:e} (single-precision rays lose their precision beyond): scale the scene down"
    )
}

/// The primitives of one [`Geometry`], collected before its BVHs are built.
#[derive(Default)]
struct GeometryParts {
    spheres: Vec<Sphere>,
    quads: Vec<Quad>,
    triangles: Vec<[Vec3; 3]>,
    triangle_shapes: Vec<u32>,
    fibres: Vec<FibreSegment>,
    fibre_shapes: Vec<u32>,
}

impl GeometryParts {
    fn is_empty(&self) -> bool {
        self.spheres.is_empty()
            && self.quads.is_empty()
            && self.triangles.is_empty()
            && self.fibres.is_empty()
    }

    /// Builds the geometry: a BVH only for what has triangles or fibres.
    fn build(self) -> Geometry {
        let triangles = (!self.triangles.is_empty())
            .then(|| TriangleSet::new(self.triangles, self.triangle_shapes));
        let fibres =
            (!self.fibres.is_empty()).then(|| FibreSet::new(self.fibres, self.fibre_shapes));
        Geometry::new(self.spheres, self.quads, triangles, fibres)
    }
}

/// Everything collected while going through the shapes.
#[derive(Default)]
struct Parts {
    surfaces: GeometryParts,
    boundaries: GeometryParts,
    shapes: Vec<ShapeInfo>,
    lights: Vec<Light>,
    media: Vec<SceneMedium>,
    black: Option<u32>,
}

impl Parts {
    /// Where a shape's geometry goes: the boundaries of media, or the surfaces.
    fn geometry(&mut self, is_boundary: bool) -> &mut GeometryParts {
        if is_boundary {
            &mut self.boundaries
        } else {
            &mut self.surfaces
        }
    }
}

impl Builder<'_> {
    fn error(&self, at: &Location, message: impl Into<String>) -> SceneError {
        if at.line() == 0 {
            SceneError::file(self.file, message)
        } else {
            SceneError::at(self.file, self.source, at.line(), at.column(), message)
        }
    }

    /// The error for a reference to a `kind` that no entry of the scene's `kinds` defines,
    /// listing the names it does define.
    fn unknown_name<'n>(
        &self,
        name: &Spanned<String>,
        kind: &str,
        kinds: &str,
        known: impl Iterator<Item = &'n str>,
    ) -> SceneError {
        let known: Vec<&str> = known.collect();
        let list = if known.is_empty() {
            "(none)".to_string()
        } else {
            known.join(", ")
        };
        self.error(
            &name.referenced,
            format!(
                "no {kind} is named `{}`; the {kinds} are: {list}",
                name.value
            ),
        )
    }

    fn warn(&mut self, at: &Location, message: impl Into<String>) {
        let w = self.error(at, message);
        self.warnings.push(w);
    }

    fn resolve(&self, relative: &Spanned<String>, what: &str) -> Result<PathBuf, SceneError> {
        let path = self.dir.join(&relative.value);
        if path.is_file() {
            Ok(path)
        } else {
            Err(self.error(
                &relative.referenced,
                format!(
                    "cannot find the {what} `{}` (looked for {})",
                    relative.value,
                    path.display()
                ),
            ))
        }
    }

    fn build(mut self, spec: SceneSpec) -> Result<Scene, SceneError> {
        let camera = self.camera(&spec.camera)?;

        let mut materials = Vec::new();
        let mut material_index = BTreeMap::new();
        for (name, m) in &spec.materials {
            material_index.insert(name.as_str(), materials.len() as u32);
            materials.push(self.material(m)?);
        }

        let mut parts = Parts::default();
        for shape in &spec.shapes {
            self.shape(
                shape,
                &spec,
                &material_index,
                &mut materials,
                &mut parts,
                camera.eye,
            )?;
        }
        let mut environment_seen = false;
        for light in &spec.lights {
            match &light.value {
                LightSpec::Point {
                    position,
                    intensity,
                } => parts.lights.push(Light::Point {
                    position: position.0,
                    intensity: intensity.0,
                }),
                LightSpec::Environment { radiance } => {
                    if environment_seen {
                        return Err(self.error(
                            &light.referenced,
                            "a scene can have only one environment light",
                        ));
                    }
                    environment_seen = true;
                    parts.lights.push(Light::Environment {
                        radiance: radiance.0,
                    });
                }
            }
        }

        let shape_count = parts.shapes.len();
        if shape_count == 0 && parts.lights.is_empty() {
            return Err(SceneError::file(
                self.file,
                "the scene is empty: it has no shapes and no lights",
            ));
        }
        if parts.lights.is_empty() {
            self.warnings.push(SceneError::file(
                self.file,
                "nothing in the scene emits light: the image will be black",
            ));
        }

        let settings = self.settings(&spec, &parts)?;

        let used_materials: TaskSet = parts
            .shapes
            .iter()
            .filter_map(|s| s.material)
            .flat_map(|m| materials[m as usize].tasks().iter())
            .collect();
        let integrator = if parts.media.is_empty() {
            TaskId::PathTrace
        } else {
            TaskId::DeltaTracking
        };
        let mut tasks = used_materials;
        tasks.insert(integrator);
        let geometry_count = |g: &GeometryParts| {
            (
                g.spheres.len() + g.quads.len(),
                g.triangles.len(),
                g.fibres.len(),
            )
        };
        let (sa, st, sf) = geometry_count(&parts.surfaces);
        let (ba, bt, bf) = geometry_count(&parts.boundaries);
        let needs = Needs {
            tasks,
            triangles: st + bt,
            fibre_segments: sf + bf,
            analytic_shapes: sa + ba,
            lights: parts.lights.len(),
            media: parts.media.len(),
        };

        let lights = (!parts.lights.is_empty()).then(|| Lights::new(parts.lights, shape_count));
        let boundaries = (!parts.boundaries.is_empty()).then(|| parts.boundaries.build());
        Ok(Scene {
            file: self.file.to_path_buf(),
            camera,
            settings,
            surfaces: parts.surfaces.build(),
            boundaries,
            shapes: parts.shapes,
            materials,
            lights,
            media: parts.media,
            needs,
            warnings: self.warnings,
        })
    }

    fn camera(&self, c: &CameraSpec) -> Result<Camera, SceneError> {
        let side = |spanned: &Spanned<u32>, over: Option<u32>, what: &str| {
            let v = over.unwrap_or(spanned.value);
            if (1..=MAX_PIXELS_PER_SIDE).contains(&v) {
                Ok(v)
            } else {
                Err(self.error(
                    &spanned.referenced,
                    format!(
                        "the image {what} must be from 1 to {MAX_PIXELS_PER_SIDE} pixels, found {v}"
                    ),
                ))
            }
        };
        let width = side(&c.width, self.options.width, "width")?;
        let height = side(&c.height, self.options.height, "height")?;
        let pixels = width as u64 * height as u64;
        if pixels > MAX_PIXELS {
            return Err(self.error(
                &c.width.referenced,
                format!(
                    "the image is {width} × {height} = {pixels} pixels; at most {MAX_PIXELS} \
                     (4096 × 4096, about 1.4 GB while rendering) are allowed"
                ),
            ));
        }
        let (eye, target, up) = (c.eye.value.0, c.target.0, c.up.value.0);
        if (target - eye).length_squared() == 0.0 || !(target - eye).length_squared().is_finite() {
            return Err(self.error(
                &c.eye.referenced,
                "the camera's eye and target are the same point",
            ));
        }
        Camera::look_at(eye, target, up, c.fov.0, width, height).ok_or_else(|| {
            self.error(
                &c.up.referenced,
                "the camera's up vector is parallel to its view direction",
            )
        })
    }

    fn settings(&self, spec: &SceneSpec, parts: &Parts) -> Result<RenderSettings, SceneError> {
        let r = &spec.render;
        let spp = self.options.spp.unwrap_or(r.spp.value);
        if !(1..=MAX_SPP).contains(&spp) {
            return Err(self.error(
                &r.spp.referenced,
                format!("spp must be from 1 to {MAX_SPP}, found {spp}"),
            ));
        }
        let max_depth = match (self.options.max_depth, &r.max_depth) {
            (Some(d), _) => Some(d),
            (None, Some(d)) => Some(d.value),
            (None, None) => None,
        };
        let max_depth = match max_depth {
            None => UNBOUNDED_DEPTH,
            Some(d) if (1..UNBOUNDED_DEPTH as u32).contains(&d) => d as i32,
            Some(d) => {
                let at = r
                    .max_depth
                    .as_ref()
                    .map_or(Location::UNKNOWN, |s| s.referenced);
                return Err(self.error(
                    &at,
                    format!(
                        "max_depth must be from 1 to {} (or ~ for unbounded), found {d}",
                        UNBOUNDED_DEPTH - 1
                    ),
                ));
            }
        };
        let has_media = !parts.media.is_empty();
        let strategy_at = r
            .strategy
            .as_ref()
            .map_or(Location::UNKNOWN, |s| s.referenced);
        let strategy = self
            .options
            .strategy
            .or(r.strategy.as_ref().map(|s| s.value))
            .unwrap_or(if has_media {
                Strategy::Light
            } else {
                Strategy::Mis
            });
        if has_media && strategy != Strategy::Light {
            return Err(self.error(
                &strategy_at,
                "scenes with media render with light sampling only: use `strategy: light`",
            ));
        }
        let heuristic = match strategy {
            Strategy::Bsdf => Heuristic::Bsdf,
            Strategy::Light => Heuristic::Light,
            Strategy::Mis => self
                .options
                .heuristic
                .or(r.heuristic)
                .map_or(Heuristic::Power, Heuristic::from),
        };
        let transmittance = self
            .options
            .transmittance
            .or(r.transmittance.as_ref().map(|t| t.value))
            .unwrap_or_default();
        if transmittance == TransmittanceEstimator::Analytic
            && parts
                .media
                .iter()
                .any(|m| !matches!(m.kind, MediumKind::Homogeneous(_)))
        {
            let at = r
                .transmittance
                .as_ref()
                .map_or(Location::UNKNOWN, |s| s.referenced);
            return Err(self.error(
                &at,
                "analytic transmittance needs every medium to be homogeneous",
            ));
        }
        Ok(RenderSettings {
            spp,
            max_depth,
            rr_depth: self.options.rr_depth.unwrap_or(r.rr_depth),
            strategy,
            heuristic,
            seed: self.options.seed.unwrap_or(r.seed),
            transmittance,
        })
    }

    fn warn_above_one(&mut self, value: &Spanned<super::values::Rgb>, what: &str) {
        let v = value.value.0;
        if v.max_element() > 1.0 {
            self.warn(
                &value.referenced,
                format!(
                    "{what} above 1 ([{}, {}, {}]) reflects more light than it receives",
                    v.x, v.y, v.z
                ),
            );
        }
    }

    fn material(&mut self, spec: &Spanned<MaterialSpec>) -> Result<Material, SceneError> {
        Ok(match &spec.value {
            MaterialSpec::Diffuse { albedo, sampling } => {
                self.warn_above_one(albedo, "an albedo");
                Material::Diffuse {
                    albedo: albedo.value.0,
                    sampling: self.options.diffuse_sampling.unwrap_or(*sampling),
                }
            }
            MaterialSpec::Mirror { reflectance } => {
                if let Some(r) = reflectance {
                    self.warn_above_one(r, "a reflectance");
                }
                Material::Mirror {
                    reflectance: reflectance.as_ref().map_or(Vec3::ONE, |r| r.value.0),
                }
            }
            MaterialSpec::Dielectric {
                ior,
                ext_ior,
                fresnel,
            } => Material::Dielectric {
                int_ior: ior.0,
                ext_ior: ext_ior.map_or(1.0, |e| e.0),
                fresnel: *fresnel,
            },
            MaterialSpec::Conductor(c) => self.conductor(c, &spec.referenced)?,
            MaterialSpec::Phong { kd, ks, exponent } => {
                if (kd.0 + ks.0).max_element() > 1.0 {
                    self.warn(
                        &spec.referenced,
                        "kd + ks above 1 reflects more light than it receives",
                    );
                }
                Material::Phong(PhongParams {
                    kd: kd.0,
                    ks: ks.0,
                    exponent: exponent.0,
                })
            }
            MaterialSpec::KajiyaKay { kd, ks, exponent } => Material::KajiyaKay(KajiyaKayParams {
                kd: kd.0,
                ks: ks.0,
                exponent: exponent.0,
            }),
        })
    }

    fn conductor(&mut self, c: &ConductorSpec, at: &Location) -> Result<Material, SceneError> {
        let (alpha_x, alpha_y) = match (c.roughness, c.alpha_x, c.alpha_y) {
            (Some(r), None, None) => (r.0, r.0),
            (None, Some(x), Some(y)) => (x.0, y.0),
            _ => {
                return Err(self.error(
                    at,
                    "a conductor needs either `roughness` or both `alpha_x` and `alpha_y`",
                ));
            }
        };
        let fresnel = match (&c.reflectance, c.eta, c.k) {
            (Some(r), None, None) => {
                self.warn_above_one(r, "a reflectance");
                ConductorFresnel::Schlick { f0: r.value.0 }
            }
            (None, Some(eta), Some(k)) => ConductorFresnel::Complex { eta: eta.0, k: k.0 },
            _ => {
                return Err(self.error(
                    at,
                    "a conductor needs either `reflectance` or both `eta` and `k`",
                ));
            }
        };
        Ok(Material::Conductor {
            alpha_x,
            alpha_y,
            fresnel,
        })
    }

    fn medium(
        &self,
        spec: &Spanned<MediumSpec>,
        bounds: (Vec3, Vec3),
    ) -> Result<SceneMedium, SceneError> {
        let phase = |g: Option<super::values::Asymmetry>| HenyeyGreenstein {
            g: g.map_or(0.0, |g| g.0),
        };
        Ok(match &spec.value {
            MediumSpec::Homogeneous {
                sigma_a,
                sigma_s,
                g,
            } => SceneMedium {
                kind: MediumKind::Homogeneous(Homogeneous {
                    coefficients: Coefficients {
                        sigma_a: sigma_a.0,
                        sigma_s: sigma_s.0,
                    },
                }),
                phase: phase(*g),
            },
            MediumSpec::Grid {
                density,
                sigma_a,
                sigma_s,
                g,
            } => {
                let grid = match density {
                    DensitySpec::File(f) => density::load_grid(&self.resolve(f, "density grid")?)?,
                    DensitySpec::Cloud {
                        resolution,
                        seed,
                        frequency,
                        octaves,
                    } => {
                        let res = resolution.value;
                        if !(2..=density::MAX_RESOLUTION as u32).contains(&res) {
                            return Err(self.error(
                                &resolution.referenced,
                                format!(
                                    "the resolution must be from 2 to {}, found {res}",
                                    density::MAX_RESOLUTION
                                ),
                            ));
                        }
                        let octaves_value = octaves.as_ref().map_or(4, |o| o.value);
                        if !(1..=8).contains(&octaves_value) {
                            let at = octaves.as_ref().map_or(Location::UNKNOWN, |o| o.referenced);
                            return Err(self.error(
                                &at,
                                format!("octaves must be from 1 to 8, found {octaves_value}"),
                            ));
                        }
                        density::cloud(
                            res as usize,
                            *seed,
                            frequency.map_or(4.0, |f| f.0),
                            octaves_value,
                        )
                        .ok_or_else(|| self.error(&resolution.referenced, "invalid cloud grid"))?
                    }
                };
                SceneMedium {
                    kind: MediumKind::Grid(GridMedium {
                        grid,
                        min: bounds.0,
                        max: bounds.1,
                        per_density: Coefficients {
                            sigma_a: sigma_a.0,
                            sigma_s: sigma_s.0,
                        },
                    }),
                    phase: phase(*g),
                }
            }
        })
    }

    /// Adds one shape of the scene to `parts`: its surface ([`Builder::surface`]), its
    /// geometry (one builder per kind of shape), then what the geometry decides: the
    /// shape's reach, the medium it bounds and the light it is.
    fn shape(
        &mut self,
        spanned: &Spanned<ShapeSpec>,
        spec: &SceneSpec,
        material_index: &BTreeMap<&str, u32>,
        materials: &mut Vec<Material>,
        parts: &mut Parts,
        eye: Vec3,
    ) -> Result<(), SceneError> {
        let at = spanned.referenced;
        let surface = self.surface(spanned, spec, material_index, materials, parts)?;
        let shape_id = parts.shapes.len() as u32;
        let is_boundary = surface.medium.is_some();
        let placed = match &spanned.value {
            ShapeSpec::Sphere { center, radius, .. } => {
                sphere(center.0, radius.0, shape_id, is_boundary, parts)
            }
            ShapeSpec::Quad {
                origin,
                edge1,
                edge2,
                ..
            } => self.quad(&at, [origin.0, edge1.0, edge2.0], shape_id, parts)?,
            ShapeSpec::Box { min, max, .. } => {
                self.cuboid(&at, min.0, max.0, shape_id, is_boundary, parts)?
            }
            ShapeSpec::Mesh {
                file, transform, ..
            } => {
                let emits = surface.emission.is_some();
                self.mesh(&at, file, transform, shape_id, is_boundary, emits, parts)?
            }
            ShapeSpec::Fibres {
                strands: source,
                radius,
                ..
            } => self.fibres(&at, source, radius.0, shape_id, parts)?,
        };

        if !within_reach(placed.reach) {
            return Err(self.error(&at, beyond_reach(placed.reach)));
        }
        let eye_inside = match &spanned.value {
            ShapeSpec::Sphere { center, radius, .. } => (eye - center.0).length() < radius.0,
            ShapeSpec::Box { min, max, .. } => eye.cmpgt(min.0).all() && eye.cmplt(max.0).all(),
            _ => false,
        };
        if is_boundary && eye_inside {
            return Err(self.error(
                &at,
                "the camera is inside this medium: media must not contain the camera",
            ));
        }
        let medium = match surface.medium {
            Some(m) => {
                parts.media.push(self.medium(m, placed.bounds)?);
                Some(parts.media.len() as u32 - 1)
            }
            None => None,
        };
        if let Some(radiance) = surface.emission {
            parts
                .lights
                .push(Light::area(shape_id, radiance, placed.patches));
        }
        parts.shapes.push(ShapeInfo {
            material: surface.material,
            emission: surface.emission.unwrap_or(Vec3::ZERO),
            medium,
        });
        Ok(())
    }

    /// The surface of a shape: its material (black for an emitter without one), the medium
    /// it bounds, what it emits; refused when it has none of them, or a medium beside a
    /// material or emission (the boundary of a medium is index-matched and dark).
    fn surface<'s>(
        &self,
        spanned: &Spanned<ShapeSpec>,
        spec: &'s SceneSpec,
        material_index: &BTreeMap<&str, u32>,
        materials: &mut Vec<Material>,
        parts: &mut Parts,
    ) -> Result<Surface<'s>, SceneError> {
        let at = spanned.referenced;
        let surface = spanned.value.surface();
        let material = match surface.material {
            Some(name) => Some(*material_index.get(name.value.as_str()).ok_or_else(|| {
                self.unknown_name(
                    name,
                    "material",
                    "materials",
                    material_index.keys().copied(),
                )
            })?),
            None => None,
        };
        let medium = match surface.medium {
            Some(name) => Some(spec.media.get(&name.value).ok_or_else(|| {
                self.unknown_name(
                    name,
                    "medium",
                    "media",
                    spec.media.keys().map(String::as_str),
                )
            })?),
            None => None,
        };
        let emission = surface.emission.map(|e| e.value.0);
        if medium.is_some() {
            if let Some(name) = surface.material {
                return Err(self.error(
                    &name.referenced,
                    "a shape that holds a medium is an index-matched boundary: it takes no material",
                ));
            }
            if let Some(e) = surface.emission {
                return Err(self.error(&e.referenced, "a shape that holds a medium cannot emit"));
            }
        } else if material.is_none() && emission.is_none() {
            return Err(self.error(
                &at,
                "this shape has no material, emission or medium: give it a `material`",
            ));
        }
        let material = material.or_else(|| {
            emission.map(|_| {
                *parts.black.get_or_insert_with(|| {
                    materials.push(Material::Black);
                    materials.len() as u32 - 1
                })
            })
        });
        Ok(Surface {
            material,
            medium,
            emission,
        })
    }

    /// A quad from its `[origin, edge1, edge2]`; refused without area. Quads are surfaces
    /// only (they enclose no medium).
    fn quad(
        &self,
        at: &Location,
        [origin, edge1, edge2]: [Vec3; 3],
        shape_id: u32,
        parts: &mut Parts,
    ) -> Result<Placed, SceneError> {
        let q = Quad::new(origin, edge1, edge2, shape_id).ok_or_else(|| {
            self.error(at, "the quad's edges are parallel or zero: it has no area")
        })?;
        let corners = [0.0, 1.0].map(|a| [0.0, 1.0].map(|b| q.origin + a * q.edge1 + b * q.edge2));
        let placed = Placed {
            patches: vec![Patch::quad(&q)],
            bounds: (Vec3::ZERO, Vec3::ZERO),
            reach: farthest(corners.iter().flatten()),
        };
        parts.surfaces.quads.push(q);
        Ok(placed)
    }

    /// An axis-aligned box from `lo` to `hi`, as its six quads; refused unless `lo < hi` on
    /// every axis.
    fn cuboid(
        &self,
        at: &Location,
        lo: Vec3,
        hi: Vec3,
        shape_id: u32,
        is_boundary: bool,
        parts: &mut Parts,
    ) -> Result<Placed, SceneError> {
        if !(lo.cmplt(hi).all()) {
            return Err(self.error(at, "a box needs min < max on every axis"));
        }
        let mut patches = Vec::new();
        for q in box_quads(lo, hi, shape_id) {
            patches.push(Patch::quad(&q));
            parts.geometry(is_boundary).quads.push(q);
        }
        Ok(Placed {
            patches,
            bounds: (lo, hi),
            reach: lo.abs().max(hi.abs()).max_element(),
        })
    }

    /// A triangle mesh from an OBJ file, placed by `transform` (scale > 0, rotation in
    /// degrees about x, then y, then z, translation); its triangles are light patches when
    /// it `emits`.
    #[allow(clippy::too_many_arguments)]
    fn mesh(
        &mut self,
        at: &Location,
        file: &Spanned<String>,
        transform: &TransformSpec,
        shape_id: u32,
        is_boundary: bool,
        emits: bool,
        parts: &mut Parts,
    ) -> Result<Placed, SceneError> {
        let scale = transform.scale.value.0;
        if scale.min_element() <= 0.0 {
            return Err(self.error(&transform.scale.referenced, "a scale must be > 0"));
        }
        let r = transform.rotate.0 * (std::f32::consts::PI / 180.0);
        let rotation =
            Quat::from_rotation_z(r.z) * Quat::from_rotation_y(r.y) * Quat::from_rotation_x(r.x);
        let placed = scale
            .max_element()
            .max(transform.translate.0.abs().max_element());
        if !within_reach(placed) {
            return Err(self.error(at, beyond_reach(placed)));
        }
        let matrix = Mat4::from_scale_rotation_translation(scale, rotation, transform.translate.0);
        let path = self.resolve(file, "mesh")?;
        let obj = load_obj(&path, &matrix)?;
        self.warnings.extend(obj.warning);
        let mut patches = Vec::new();
        let mut lo = Vec3::splat(f32::INFINITY);
        let mut hi = Vec3::splat(f32::NEG_INFINITY);
        for tri in &obj.triangles {
            for v in tri {
                lo = lo.min(*v);
                hi = hi.max(*v);
            }
            if emits {
                let n = (tri[1] - tri[0])
                    .cross(tri[2] - tri[0])
                    .normalize_or(Vec3::Z);
                patches.push(Patch::Triangle { v: *tri, n });
            }
        }
        let count = obj.triangles.len();
        let target = parts.geometry(is_boundary);
        target.triangles.extend(obj.triangles);
        target
            .triangle_shapes
            .extend(std::iter::repeat_n(shape_id, count));
        Ok(Placed {
            patches,
            bounds: (lo, hi),
            reach: lo.abs().max(hi.abs()).max_element(),
        })
    }

    /// Hair fibres of `radius` along the polylines of a strand file or a generated ball of
    /// strands; refused beyond the scene's limits on strands, segments and fibres.
    fn fibres(
        &self,
        at: &Location,
        source: &StrandsSpec,
        radius: f32,
        shape_id: u32,
        parts: &mut Parts,
    ) -> Result<Placed, SceneError> {
        let polylines = match source {
            StrandsSpec::File(f) => strands::load_strands(&self.resolve(f, "strand file")?)?,
            StrandsSpec::Ball {
                center,
                radius: ball_radius,
                count,
                length,
                segments,
                curl,
                seed,
            } => {
                if !(1..=MAX_STRANDS).contains(&count.value) {
                    return Err(self.error(
                        &count.referenced,
                        format!(
                            "count must be from 1 to {MAX_STRANDS}, found {}",
                            count.value
                        ),
                    ));
                }
                if !(1..=MAX_STRAND_SEGMENTS).contains(&segments.value) {
                    return Err(self.error(
                        &segments.referenced,
                        format!(
                            "segments must be from 1 to {MAX_STRAND_SEGMENTS}, found {}",
                            segments.value
                        ),
                    ));
                }
                strands::ball(
                    center.0,
                    ball_radius.0,
                    count.value as usize,
                    length.0,
                    segments.value as usize,
                    curl.map_or(0.0, |c| c.0),
                    *seed,
                )
            }
        };
        let reach = farthest(polylines.iter().flatten()) + radius;
        for line in &polylines {
            for pair in line.windows(2) {
                parts.surfaces.fibres.push(FibreSegment {
                    a: pair[0],
                    b: pair[1],
                    radius,
                });
                parts.surfaces.fibre_shapes.push(shape_id);
            }
        }
        if parts.surfaces.fibres.len() > strands::MAX_SEGMENTS {
            return Err(self.error(
                at,
                format!(
                    "too many fibre segments (at most {} in a scene)",
                    strands::MAX_SEGMENTS
                ),
            ));
        }
        Ok(Placed {
            patches: Vec::new(),
            bounds: (Vec3::ZERO, Vec3::ZERO),
            reach,
        })
    }
}

/// A sphere; its one patch is the whole sphere.
fn sphere(
    center: Vec3,
    radius: f32,
    shape_id: u32,
    is_boundary: bool,
    parts: &mut Parts,
) -> Placed {
    let s = Sphere {
        center,
        radius,
        shape: shape_id,
    };
    let placed = Placed {
        patches: vec![Patch::sphere(&s)],
        bounds: (s.center - s.radius, s.center + s.radius),
        reach: s.center.abs().max_element() + s.radius,
    };
    parts.geometry(is_boundary).spheres.push(s);
    placed
}

/// A shape's surface as its scene entry gives it ([`Builder::surface`]).
struct Surface<'s> {
    /// Its material; black for an emitter given none, `None` for a medium's boundary.
    material: Option<u32>,
    /// The medium it bounds.
    medium: Option<&'s Spanned<MediumSpec>>,
    /// The radiance it emits.
    emission: Option<Vec3>,
}

/// What building one shape's geometry tells [`Builder::shape`].
struct Placed {
    /// Its light patches, for an area light when it emits.
    patches: Vec<Patch>,
    /// Its bounding box: the extent of a medium it bounds (zero for shapes that bound none).
    bounds: (Vec3, Vec3),
    /// How far from the origin it reaches, checked against [`MAX_REACH`] before anything
    /// builds a BVH over it.
    reach: f32,
}

/// The six faces of the box `[lo, hi]`, normals pointing out.
fn box_quads(lo: Vec3, hi: Vec3, shape: u32) -> Vec<Quad> {
    let d = hi - lo;
    let (dx, dy, dz) = (Vec3::X * d.x, Vec3::Y * d.y, Vec3::Z * d.z);
    [
        (lo, dz, dy),
        (Vec3::new(hi.x, lo.y, lo.z), dy, dz),
        (lo, dx, dz),
        (Vec3::new(lo.x, hi.y, lo.z), dz, dx),
        (lo, dy, dx),
        (Vec3::new(lo.x, lo.y, hi.z), dx, dy),
    ]
    .into_iter()
    .filter_map(|(o, e1, e2)| Quad::new(o, e1, e2, shape))
    .collect()
}
