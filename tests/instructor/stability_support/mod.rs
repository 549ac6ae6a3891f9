//! Implementations of [`pbrlab::worksheet::Tasks`] for the stability tests: the reference
//! with one function replaced by a deliberately naive one (a [`Patch`] of the grader's
//! tests). Every other function is the reference's, called with the flawed implementation
//! as its `t`, so a flaw propagates to the tasks that use it, as a student's would under
//! `Mixed`.

pub mod naive;
// Shared with the grader's tests, which also use its catalogue variants.
use crate::support::patch;

use glam::Vec3;
use patch::Patch;
use pbrlab::task_set::TaskSet;
use pbrlab::worksheet::TaskId;
use std::time::Duration;

/// The one thing a [`flawed`] implementation gets wrong.
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
    /// `phong` takes the power of the clamped lobe cosine as `exp(n ln x)`.
    PhongPowerByLogarithm,
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

/// The reference with `flaw`, in force for every task.
pub fn flawed(flaw: Flaw) -> Patch {
    let task = match flaw {
        Flaw::None | Flaw::ReflectUnnormalised | Flaw::ReflectPanics => TaskId::Reflect,
        Flaw::UnguardedSnell | Flaw::CriticalAngleAsin => TaskId::RefractStack,
        Flaw::SchlickR0Everywhere => TaskId::FresnelSchlick,
        Flaw::CosinePdfSigned => TaskId::CosineSample,
        Flaw::SmithNoChi | Flaw::SmithHangs => TaskId::SmithG1,
        Flaw::HalfVectorUnguarded => TaskId::CookTorrance,
        Flaw::CancellingGgx => TaskId::AnisoNdf,
        Flaw::PhongUnclamped | Flaw::PhongPowerByLogarithm | Flaw::GapZeroOverZero => TaskId::Phong,
        Flaw::SheetKajiyaKay => TaskId::KajiyaKay,
        Flaw::BeckmannUnguarded => TaskId::BeckmannNdf,
        Flaw::NdfPdfUnguarded | Flaw::NdfPdfNoJacobian => TaskId::NdfSample,
        Flaw::PathTraceNoDepthGuard => TaskId::PathTrace,
        Flaw::MisUnguarded => TaskId::Mis,
        Flaw::DeltaTrackingSheet => TaskId::DeltaTracking,
    };
    let mut p = Patch::new(task).only(TaskSet::all());
    match flaw {
        Flaw::None => {}
        Flaw::ReflectUnnormalised => p.reflect = Some(naive::reflect),
        Flaw::ReflectPanics => {
            p.reflect = Some(|_: Vec3, _: Vec3| -> Vec3 {
                panic!("index out of bounds: the len is 3 but the index is 3")
            })
        }
        Flaw::UnguardedSnell => {
            p.refract = Some(naive::refract);
            p.refract_stack = Some(naive::refract_stack);
            p.fresnel_schlick = Some(naive::fresnel_schlick_unguarded);
        }
        Flaw::CriticalAngleAsin => p.critical_angle = Some(naive::critical_angle),
        Flaw::SchlickR0Everywhere => p.fresnel_schlick = Some(naive::fresnel_schlick_r0_everywhere),
        Flaw::CosinePdfSigned => p.cosine_pdf = Some(naive::cosine_pdf),
        Flaw::SmithNoChi => p.smith_g1 = Some(naive::smith_g1),
        Flaw::SmithHangs => {
            p.smith_g1 = Some(|_: Vec3, _: f32| -> f32 {
                loop {
                    // Sleeps rather than spins, so the abandoned thread costs no CPU.
                    std::thread::sleep(Duration::from_secs(3600));
                }
            })
        }
        Flaw::HalfVectorUnguarded => p.cook_torrance = Some(naive::cook_torrance),
        Flaw::CancellingGgx => p.aniso_ndf = Some(naive::aniso_ndf),
        Flaw::PhongUnclamped => p.phong = Some(naive::phong),
        Flaw::PhongPowerByLogarithm => p.phong = Some(naive::phong_power_by_logarithm),
        Flaw::GapZeroOverZero => p.reciprocity_gap = Some(naive::reciprocity_gap),
        Flaw::SheetKajiyaKay => p.kajiya_kay = Some(naive::kajiya_kay),
        Flaw::BeckmannUnguarded => p.beckmann_ndf = Some(naive::beckmann_ndf),
        Flaw::NdfPdfUnguarded => p.ndf_pdf = Some(naive::ndf_pdf),
        Flaw::NdfPdfNoJacobian => p.ndf_pdf = Some(naive::ndf_pdf_no_jacobian),
        Flaw::PathTraceNoDepthGuard => p.path_trace = Some(naive::path_trace_no_depth_guard),
        Flaw::MisUnguarded => p.mis = Some(naive::mis_unguarded),
        Flaw::DeltaTrackingSheet => p.delta_tracking = Some(naive::delta_tracking_sheet),
    }
    p
}
