use super::{KajiyaKayParams, PhongParams};
use crate::task_set::TaskSet;
use crate::worksheet::TaskId;
use glam::Vec3;

/// How a diffuse surface picks the direction a path continues in.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum HemisphereSampling {
    /// Density cos θ / π (the `cosine_sample` task): the estimator weight is the albedo.
    #[default]
    Cosine,
    /// Density 1 / (2π) (framework code): unbiased too, noisier; for the convergence study.
    Uniform,
}

/// Which Fresnel reflectance a smooth dielectric uses.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FresnelModel {
    /// The exact unpolarised Fresnel equations (what other renderers use).
    #[default]
    Exact,
    /// Schlick's approximation (the `fresnel_schlick` task).
    Schlick,
}

/// A surface's reflection model and its parameters. Every opaque material is two-sided:
/// seen from behind its normal it looks as it does from the front. A dielectric is not:
/// its normal side is the outside (index `ext_ior`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Material {
    /// Lambertian reflection `albedo / π`.
    Diffuse {
        /// Reflectance per RGB channel, in [0, 1].
        albedo: Vec3,
        /// How directions are sampled.
        sampling: HemisphereSampling,
    },
    /// A perfect mirror (a delta lobe) with RGB reflectance.
    Mirror {
        /// Reflectance per RGB channel.
        reflectance: Vec3,
    },
    /// A smooth dielectric interface (glass, water): delta reflection and refraction.
    Dielectric {
        /// Index of refraction on the side opposite the normal (inside).
        int_ior: f32,
        /// Index of refraction on the side of the normal (outside).
        ext_ior: f32,
        /// Which Fresnel reflectance to use.
        fresnel: FresnelModel,
    },
    /// A rough conductor: the Cook-Torrance BRDF with anisotropic GGX.
    Conductor {
        /// GGX roughness along the frame's tangent `s`.
        alpha_x: f32,
        /// GGX roughness along the frame's bitangent `t`.
        alpha_y: f32,
        /// Its Fresnel reflectance.
        fresnel: ConductorFresnel,
    },
    /// The energy-normalised Phong BRDF.
    Phong(PhongParams),
    /// The Kajiya-Kay hair fibre model (for fibres; the shading tangent is the fibre).
    KajiyaKay(KajiyaKayParams),
    /// Reflects nothing (the surface of a light that only emits).
    Black,
}

/// How a rough conductor's Fresnel reflectance is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ConductorFresnel {
    /// Schlick's curve through an RGB reflectance at normal incidence (the `cook_torrance`
    /// task's own Fresnel term).
    Schlick {
        /// Reflectance at normal incidence per RGB channel.
        f0: Vec3,
    },
    /// The exact conductor Fresnel equations for the complex index of refraction
    /// `eta + i k` (as pbrt and Mitsuba use): the `cook_torrance` task is called with
    /// `f0 = 1`, which makes its Schlick term exactly 1, and the framework multiplies by
    /// [`crate::optics::fresnel_conductor`] at the half vector.
    Complex {
        /// Real part of the index of refraction per RGB channel.
        eta: Vec3,
        /// Extinction coefficient per RGB channel.
        k: Vec3,
    },
}

impl ConductorFresnel {
    /// The `f0` argument for the `cook_torrance` task.
    pub fn task_f0(&self) -> Vec3 {
        match *self {
            ConductorFresnel::Schlick { f0 } => f0,
            ConductorFresnel::Complex { .. } => Vec3::ONE,
        }
    }

    /// The factor the framework applies on top of the task's value for the pair `wo`, `wi`
    /// (local frame, both above the surface): 1 for Schlick, the exact Fresnel reflectance
    /// at `wo · h` for a complex index.
    pub fn framework_factor(&self, wo: Vec3, wi: Vec3) -> Vec3 {
        match *self {
            ConductorFresnel::Schlick { .. } => Vec3::ONE,
            ConductorFresnel::Complex { eta, k } => {
                let h = (wo + wi).normalize_or_zero();
                crate::optics::fresnel_conductor(wo.dot(h), eta, k)
            }
        }
    }
}

impl Material {
    /// True when every direction the material scatters into is a delta lobe (so light
    /// sampling can never help it).
    pub fn is_delta(&self) -> bool {
        matches!(self, Material::Mirror { .. } | Material::Dielectric { .. })
    }

    /// The worksheet tasks the material calls directly.
    pub fn tasks(&self) -> TaskSet {
        let ids: &[TaskId] = match self {
            Material::Diffuse {
                sampling: HemisphereSampling::Cosine,
                ..
            } => &[TaskId::CosineSample],
            Material::Diffuse {
                sampling: HemisphereSampling::Uniform,
                ..
            }
            | Material::Black => &[],
            Material::Mirror { .. } => &[TaskId::Reflect],
            Material::Dielectric {
                fresnel: FresnelModel::Exact,
                ..
            } => &[TaskId::Reflect, TaskId::RefractStack],
            Material::Dielectric {
                fresnel: FresnelModel::Schlick,
                ..
            } => &[
                TaskId::Reflect,
                TaskId::RefractStack,
                TaskId::FresnelSchlick,
            ],
            Material::Conductor { .. } => &[TaskId::CookTorrance, TaskId::NdfSample],
            Material::Phong(_) => &[TaskId::Phong, TaskId::Reflect, TaskId::CosineSample],
            Material::KajiyaKay(_) => &[TaskId::KajiyaKay],
        };
        ids.iter().copied().collect()
    }
}
