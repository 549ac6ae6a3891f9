use super::{BsdfSample, FresnelModel, HemisphereSampling, Material, phong_lobe};
use crate::math::Frame;
use crate::optics::fresnel_dielectric;
use crate::sampling::{
    Sampler, uniform_hemisphere, uniform_hemisphere_pdf, uniform_sphere, uniform_sphere_pdf,
};
use crate::worksheet::Tasks;
use glam::Vec3;
use std::f32::consts::FRAC_1_PI;

/// A material at one surface point: the BSDF in its shading frame.
///
/// Every direction is in world space and points away from the surface. Values are
/// *cosine-weighted*, as in Mitsuba: [`Bsdf::eval`] returns `f(wo, wi) |cos θi|` with θi
/// measured from the shading normal, so an estimator multiplies it by the incident radiance
/// and divides by a pdf, and never multiplies by a cosine itself. (For a hair fibre the
/// Kajiya-Kay value already contains its projected-area factor `sin(t, wi)`.)
///
/// Task functions are called through `t`, so the same code renders with the student's
/// tasks or the reference.
#[derive(Clone, Copy, Debug)]
pub struct Bsdf<'a> {
    material: &'a Material,
    frame: Frame,
}

/// Mirror a local direction into the upper hemisphere (z ≥ 0) when `flip` says so: how an
/// opaque two-sided material sees a direction from behind its normal.
#[inline]
fn flip_z(w: Vec3, flip: bool) -> Vec3 {
    if flip { Vec3::new(w.x, w.y, -w.z) } else { w }
}

impl<'a> Bsdf<'a> {
    /// The BSDF of `material` with shading frame `frame`.
    pub fn new(material: &'a Material, frame: Frame) -> Self {
        Self { material, frame }
    }

    /// The material.
    pub fn material(&self) -> &Material {
        self.material
    }

    /// True when the BSDF is made only of delta lobes (mirror, glass): [`Bsdf::eval`] and
    /// [`Bsdf::pdf`] are then 0 for every pair of directions, and only [`Bsdf::sample`]
    /// can find the directions it scatters into.
    pub fn is_delta(&self) -> bool {
        self.material.is_delta()
    }

    /// `f(wo, wi) |cos θi|` per RGB channel: the BSDF times the cosine factor. 0 for delta
    /// lobes and for directions the material does not scatter between.
    pub fn eval(&self, t: &impl Tasks, wo: Vec3, wi: Vec3) -> Vec3 {
        let (wo_l, wi_l) = (self.frame.to_local(wo), self.frame.to_local(wi));
        let flip = wo_l.z < 0.0;
        let (wo_f, wi_f) = (flip_z(wo_l, flip), flip_z(wi_l, flip));
        match self.material {
            Material::Diffuse { albedo, .. } => {
                if wo_f.z > 0.0 && wi_f.z > 0.0 {
                    *albedo * (FRAC_1_PI * wi_f.z)
                } else {
                    Vec3::ZERO
                }
            }
            Material::Conductor {
                alpha_x,
                alpha_y,
                fresnel,
            } => {
                if wo_f.z > 0.0 && wi_f.z > 0.0 {
                    t.cook_torrance(wo_f, wi_f, *alpha_x, *alpha_y, fresnel.task_f0())
                        * fresnel.framework_factor(wo_f, wi_f)
                        * wi_f.z
                } else {
                    Vec3::ZERO
                }
            }
            Material::Phong(params) => {
                if wo_f.z > 0.0 && wi_f.z > 0.0 {
                    t.phong(wo_f, wi_f, params) * wi_f.z
                } else {
                    Vec3::ZERO
                }
            }
            Material::KajiyaKay(params) => t.kajiya_kay(wo, wi, self.frame.s, params),
            Material::Mirror { .. } | Material::Dielectric { .. } | Material::Black => Vec3::ZERO,
        }
    }

    /// The density per unit solid angle with which [`Bsdf::sample`] produces `wi` for `wo`
    /// (0 for delta lobes).
    pub fn pdf(&self, t: &impl Tasks, wo: Vec3, wi: Vec3) -> f32 {
        let (wo_l, wi_l) = (self.frame.to_local(wo), self.frame.to_local(wi));
        let flip = wo_l.z < 0.0;
        let (wo_f, wi_f) = (flip_z(wo_l, flip), flip_z(wi_l, flip));
        match self.material {
            Material::Diffuse { sampling, .. } => {
                if wo_f.z <= 0.0 || wi_f.z <= 0.0 {
                    return 0.0;
                }
                match sampling {
                    HemisphereSampling::Cosine => t.cosine_pdf(wi_f),
                    HemisphereSampling::Uniform => uniform_hemisphere_pdf(),
                }
            }
            Material::Conductor {
                alpha_x, alpha_y, ..
            } => {
                if wo_f.z <= 0.0 || wi_f.z <= 0.0 {
                    return 0.0;
                }
                t.ndf_pdf(wo_f, wi_f, *alpha_x, *alpha_y)
            }
            Material::Phong(params) => {
                if wo_f.z <= 0.0 || wi_f.z <= 0.0 {
                    return 0.0;
                }
                let p_spec = phong_specular_probability(params.kd, params.ks);
                let r = t.reflect(wo_f, Vec3::Z);
                (1.0 - p_spec) * t.cosine_pdf(wi_f)
                    + p_spec * phong_lobe::pdf(r, params.exponent, wi_f)
            }
            Material::KajiyaKay(_) => uniform_sphere_pdf(),
            Material::Mirror { .. } | Material::Dielectric { .. } | Material::Black => 0.0,
        }
    }

    /// Draws an incident direction for the outgoing direction `wo`. `None` when the
    /// material absorbs the path (a black surface, a sample below the surface, a zero pdf).
    pub fn sample(&self, t: &impl Tasks, wo: Vec3, sampler: &mut Sampler) -> Option<BsdfSample> {
        let wo_l = self.frame.to_local(wo);
        let flip = wo_l.z < 0.0;
        let wo_f = flip_z(wo_l, flip);
        let to_world = |w: Vec3| self.frame.to_world(flip_z(w, flip));
        match self.material {
            Material::Diffuse { albedo, sampling } => {
                let u = sampler.next_2d();
                let (wi_f, pdf) = match sampling {
                    HemisphereSampling::Cosine => {
                        let w = t.cosine_sample(u);
                        (w, t.cosine_pdf(w))
                    }
                    HemisphereSampling::Uniform => {
                        (uniform_hemisphere(u), uniform_hemisphere_pdf())
                    }
                };
                if (pdf.is_nan() || pdf <= 0.0) || wi_f.z <= 0.0 || wo_f.z <= 0.0 {
                    return None;
                }
                Some(BsdfSample {
                    wi: to_world(wi_f),
                    weight: *albedo * (FRAC_1_PI * wi_f.z / pdf),
                    pdf,
                    delta: false,
                })
            }
            Material::Mirror { reflectance } => Some(BsdfSample {
                wi: to_world(t.reflect(wo_f, Vec3::Z)),
                weight: *reflectance,
                pdf: 0.0,
                delta: true,
            }),
            Material::Dielectric {
                int_ior,
                ext_ior,
                fresnel,
            } => {
                let outside = wo_l.z > 0.0;
                let (eta_i, eta_t, n) = if outside {
                    (*ext_ior, *int_ior, Vec3::Z)
                } else {
                    (*int_ior, *ext_ior, -Vec3::Z)
                };
                let cos_i = wo_l.z.abs();
                let reflectance = match fresnel {
                    FresnelModel::Exact => fresnel_dielectric(cos_i, eta_i, eta_t),
                    FresnelModel::Schlick => t.fresnel_schlick(cos_i, eta_i, eta_t),
                };
                let reflect = || BsdfSample {
                    wi: self.frame.to_world(t.reflect(wo_l, n)),
                    weight: Vec3::ONE,
                    pdf: 0.0,
                    delta: true,
                };
                if sampler.next_1d() < reflectance {
                    return Some(reflect());
                }
                match t.refract(wo_l, n, eta_i, eta_t) {
                    // Radiance is compressed entering a denser medium: L scales with η².
                    Some(wt) => Some(BsdfSample {
                        wi: self.frame.to_world(wt),
                        weight: Vec3::splat((eta_i / eta_t) * (eta_i / eta_t)),
                        pdf: 0.0,
                        delta: true,
                    }),
                    None => Some(reflect()),
                }
            }
            Material::Conductor {
                alpha_x,
                alpha_y,
                fresnel,
            } => {
                if wo_f.z <= 0.0 {
                    return None;
                }
                let wi_f = t.ndf_sample(wo_f, *alpha_x, *alpha_y, sampler.next_2d())?;
                let pdf = t.ndf_pdf(wo_f, wi_f, *alpha_x, *alpha_y);
                if (pdf.is_nan() || pdf <= 0.0) || wi_f.z <= 0.0 {
                    return None;
                }
                let f = t.cook_torrance(wo_f, wi_f, *alpha_x, *alpha_y, fresnel.task_f0())
                    * fresnel.framework_factor(wo_f, wi_f)
                    * wi_f.z;
                Some(BsdfSample {
                    wi: to_world(wi_f),
                    weight: f / pdf,
                    pdf,
                    delta: false,
                })
            }
            Material::Phong(params) => {
                if wo_f.z <= 0.0 {
                    return None;
                }
                let p_spec = phong_specular_probability(params.kd, params.ks);
                let r = t.reflect(wo_f, Vec3::Z);
                let choose = sampler.next_1d();
                let u = sampler.next_2d();
                let wi_f = if choose < p_spec {
                    phong_lobe::sample(r, params.exponent, u)
                } else {
                    t.cosine_sample(u)
                };
                if wi_f.z <= 0.0 {
                    return None;
                }
                let pdf = (1.0 - p_spec) * t.cosine_pdf(wi_f)
                    + p_spec * phong_lobe::pdf(r, params.exponent, wi_f);
                if pdf.is_nan() || pdf <= 0.0 {
                    return None;
                }
                let f = t.phong(wo_f, wi_f, params) * wi_f.z;
                Some(BsdfSample {
                    wi: to_world(wi_f),
                    weight: f / pdf,
                    pdf,
                    delta: false,
                })
            }
            Material::KajiyaKay(params) => {
                let wi = uniform_sphere(sampler.next_2d());
                let pdf = uniform_sphere_pdf();
                Some(BsdfSample {
                    wi,
                    weight: t.kajiya_kay(wo, wi, self.frame.s, params) / pdf,
                    pdf,
                    delta: false,
                })
            }
            Material::Black => None,
        }
    }
}

/// How often Phong sampling picks its specular lobe rather than the diffuse one:
/// in proportion to the mean specular and diffuse coefficients.
fn phong_specular_probability(kd: Vec3, ks: Vec3) -> f32 {
    let (d, s) = (kd.element_sum(), ks.element_sum());
    if d + s > 0.0 { s / (d + s) } else { 0.5 }
}
