//! Implementations of [`Tasks`] for the stability tests: the reference with one function
//! replaced by a deliberately naive one. Every other function is the reference's, called
//! with the flawed implementation as its `t`, so a flaw propagates to the tasks that use
//! it, as a student's would under `Mixed`.

pub mod naive;

use glam::Vec3;
use pbrlab::bsdf::{KajiyaKayParams, PhongParams};
use pbrlab::geometry::{Hit, Ray};
use pbrlab::integrator::{DirectLight, Heuristic, Segment};
use pbrlab::medium::{FreeFlight, Medium};
use pbrlab::optics::{LayerStack, StackReport};
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::solutions as reference;
use pbrlab::worksheet::Tasks;
use std::time::Duration;

/// The one thing a [`Flawed`] implementation gets wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flaw {
    /// Nothing: the reference.
    None,
    /// `reflect` does not normalise n.
    ReflectUnnormalised,
    /// `refract`, `refract_stack` and `fresnel_schlick` use Snell's law with no test for
    /// total internal reflection (an unclamped square root at and past θc).
    UnguardedSnell,
    /// `critical_angle` returns asin(eta_t/eta_i) for every pair.
    CriticalAngleAsin,
    /// `fresnel_schlick` is R0 + (1 − R0)(1 − cos θi)^5 for every pair of indices.
    SchlickR0Everywhere,
    /// `cosine_pdf` is w.z/π also below the surface.
    CosinePdfSigned,
    /// `smith_g1` has no χ⁺ factor.
    SmithNoChi,
    /// `cook_torrance` normalises wo + wi before any horizon test.
    HalfVectorUnguarded,
    /// `aniso_ndf` is the cancelling isotropic form, with no χ⁺.
    CancellingGgx,
    /// `phong` raises an unclamped lobe cosine to the exponent.
    PhongUnclamped,
    /// `reciprocity_gap` divides 0 by 0 and starts its maximum at −∞.
    GapZeroOverZero,
    /// `kajiya_kay` is the worksheet's form.
    SheetKajiyaKay,
    /// `beckmann_ndf` as written, no guards.
    BeckmannUnguarded,
    /// `ndf_pdf` with no test of the directions.
    NdfPdfUnguarded,
    /// `ndf_pdf` without the reflection Jacobian 1/(4 wo·h).
    NdfPdfNoJacobian,
    /// `path_trace` has no test for depth ≤ 0.
    PathTraceNoDepthGuard,
    /// `mis` converts pdfs and weights delta samples without guards.
    MisUnguarded,
    /// `delta_tracking` as on the worksheet (reused random numbers, escape as absorption).
    DeltaTrackingSheet,
    /// `smith_g1` never returns.
    SmithHangs,
    /// `reflect` panics.
    ReflectPanics,
}

/// The reference with at most one [`Flaw`]. Functions without a flaw come from the
/// trait's reference defaults.
#[derive(Clone, Copy, Debug)]
pub struct Flawed(pub Flaw);

impl Tasks for Flawed {
    fn reflect(&self, wo: Vec3, n: Vec3) -> Vec3 {
        match self.0 {
            Flaw::ReflectUnnormalised => naive::reflect(wo, n),
            Flaw::ReflectPanics => panic!("index out of bounds: the len is 3 but the index is 3"),
            _ => reference::reflect::reflect(wo, n),
        }
    }
    fn refract(&self, wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
        match self.0 {
            Flaw::UnguardedSnell => naive::refract(wi, n, eta_i, eta_t),
            _ => reference::refract_stack::refract(wi, n, eta_i, eta_t),
        }
    }
    fn critical_angle(&self, eta_i: f64, eta_t: f64) -> Option<f64> {
        match self.0 {
            Flaw::CriticalAngleAsin => naive::critical_angle(eta_i, eta_t),
            _ => reference::refract_stack::critical_angle(eta_i, eta_t),
        }
    }
    fn refract_stack(&self, theta_deg: f64, stack: &LayerStack) -> StackReport {
        match self.0 {
            Flaw::UnguardedSnell => naive::refract_stack(self, theta_deg, stack),
            _ => reference::refract_stack::refract_stack(self, theta_deg, stack),
        }
    }
    fn fresnel_schlick(&self, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
        match self.0 {
            Flaw::SchlickR0Everywhere => {
                naive::fresnel_schlick_r0_everywhere(self, cos_theta_i, eta_i, eta_t)
            }
            Flaw::UnguardedSnell => {
                naive::fresnel_schlick_unguarded(self, cos_theta_i, eta_i, eta_t)
            }
            _ => reference::fresnel_schlick::fresnel_schlick(self, cos_theta_i, eta_i, eta_t),
        }
    }
    fn cosine_pdf(&self, w: Vec3) -> f32 {
        match self.0 {
            Flaw::CosinePdfSigned => naive::cosine_pdf(w),
            _ => reference::cosine_sample::cosine_pdf(w),
        }
    }
    fn smith_g1(&self, w: Vec3, alpha: f32) -> f32 {
        match self.0 {
            Flaw::SmithNoChi => naive::smith_g1(w, alpha),
            Flaw::SmithHangs => loop {
                // Sleeps rather than spins, so the abandoned thread costs no CPU.
                std::thread::sleep(Duration::from_secs(3600));
            },
            _ => reference::smith_g1::smith_g1(w, alpha),
        }
    }
    fn cook_torrance(&self, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32, f0: Vec3) -> Vec3 {
        match self.0 {
            Flaw::HalfVectorUnguarded => naive::cook_torrance(self, wo, wi, alpha_x, alpha_y, f0),
            _ => reference::cook_torrance::cook_torrance(self, wo, wi, alpha_x, alpha_y, f0),
        }
    }
    fn aniso_ndf(&self, h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        match self.0 {
            Flaw::CancellingGgx => naive::aniso_ndf(h, alpha_x, alpha_y),
            _ => reference::aniso_ndf::aniso_ndf(h, alpha_x, alpha_y),
        }
    }
    fn phong(&self, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
        match self.0 {
            Flaw::PhongUnclamped => naive::phong(self, wo, wi, params),
            _ => reference::phong::phong(self, wo, wi, params),
        }
    }
    fn reciprocity_gap(
        &self,
        brdf: &dyn Fn(Vec3, Vec3) -> f32,
        sampler: &mut Sampler,
        pairs: usize,
    ) -> f32 {
        match self.0 {
            Flaw::GapZeroOverZero => naive::reciprocity_gap(brdf, sampler, pairs),
            _ => reference::phong::reciprocity_gap(brdf, sampler, pairs),
        }
    }
    fn kajiya_kay(&self, wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
        match self.0 {
            Flaw::SheetKajiyaKay => naive::kajiya_kay(wo, wi, tangent, params),
            _ => reference::kajiya_kay::kajiya_kay(wo, wi, tangent, params),
        }
    }
    fn beckmann_ndf(&self, h: Vec3, alpha: f32) -> f32 {
        match self.0 {
            Flaw::BeckmannUnguarded => naive::beckmann_ndf(h, alpha),
            _ => reference::beckmann_ndf::beckmann_ndf(h, alpha),
        }
    }
    fn ndf_pdf(&self, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        match self.0 {
            Flaw::NdfPdfUnguarded => naive::ndf_pdf(self, wo, wi, alpha_x, alpha_y),
            Flaw::NdfPdfNoJacobian => naive::ndf_pdf_no_jacobian(self, wo, wi, alpha_x, alpha_y),
            _ => reference::ndf_sample::ndf_pdf(self, wo, wi, alpha_x, alpha_y),
        }
    }
    fn path_trace(
        &self,
        scene: &Scene,
        segment: &Segment,
        depth: i32,
        sampler: &mut Sampler,
    ) -> Vec3 {
        match self.0 {
            Flaw::PathTraceNoDepthGuard => {
                naive::path_trace_no_depth_guard(self, scene, segment, depth, sampler)
            }
            _ => reference::path_trace::path_trace(self, scene, segment, depth, sampler),
        }
    }
    fn mis(
        &self,
        scene: &Scene,
        hit: &Hit,
        wo: Vec3,
        heuristic: Heuristic,
        sampler: &mut Sampler,
    ) -> DirectLight {
        match self.0 {
            Flaw::MisUnguarded => naive::mis_unguarded(self, scene, hit, wo, heuristic, sampler),
            _ => reference::mis::mis(self, scene, hit, wo, heuristic, sampler),
        }
    }
    fn delta_tracking(
        &self,
        medium: &dyn Medium,
        ray: &Ray,
        t_max: f32,
        max_steps: u32,
        sampler: &mut Sampler,
    ) -> FreeFlight {
        match self.0 {
            Flaw::DeltaTrackingSheet => {
                naive::delta_tracking_sheet(medium, ray, t_max, max_steps, sampler)
            }
            _ => reference::delta_tracking::delta_tracking(medium, ray, t_max, max_steps, sampler),
        }
    }
}
