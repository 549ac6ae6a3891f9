//! A single harmless call of every function of a task: tells a stub (`todo!()`) from code.

use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::optics::{LayerStack, Slab};
use crate::sampling::Sampler;
use crate::worksheet::{TaskId, Tasks};
use glam::{Vec2, Vec3};

/// Calls every function of `task` once on an ordinary input and discards the results.
/// A stub panics with `todo!()`'s message; written code returns (or panics otherwise).
pub fn probe_task(t: &impl Tasks, task: TaskId) {
    let wo = Vec3::new(0.36, 0.48, 0.8);
    let wi = Vec3::new(-0.6, 0.0, 0.8);
    let mut sampler = Sampler::new(0, 0);
    let lambert = |_: Vec3, _: Vec3| std::f32::consts::FRAC_1_PI;
    match task {
        TaskId::Reflect => {
            t.reflect(wo, Vec3::Z);
        }
        TaskId::RefractStack => {
            t.refract(wo, Vec3::Z, 1.0, 1.5);
            t.critical_angle(1.5, 1.0);
            let stack = LayerStack {
                eta_incident: 1.0,
                slabs: vec![Slab {
                    eta: 1.5,
                    thickness: 10.0,
                }],
                eta_exit: 1.33,
                intensity: 100.0,
            };
            t.refract_stack(30.0, &stack);
        }
        TaskId::FresnelSchlick => {
            t.schlick_r0(1.0, 1.5);
            t.fresnel_schlick(0.8, 1.0, 1.5);
        }
        TaskId::CosineSample => {
            t.cosine_sample(Vec2::new(0.3, 0.7));
            t.cosine_pdf(wo);
        }
        TaskId::SmithG1 => {
            t.smith_g1(wo, 0.3);
        }
        TaskId::CookTorrance => {
            t.cook_torrance(wo, wi, 0.3, 0.3, Vec3::splat(0.04));
        }
        TaskId::AnisoNdf => {
            t.aniso_ndf(Vec3::Z, 0.3, 0.5);
        }
        TaskId::Phong => {
            let params = PhongParams {
                kd: Vec3::splat(0.5),
                ks: Vec3::splat(0.4),
                exponent: 20.0,
            };
            t.phong(wo, wi, &params);
            t.reciprocity_gap(&lambert, &mut sampler, 4);
        }
        TaskId::KajiyaKay => {
            let params = KajiyaKayParams {
                kd: Vec3::splat(0.1),
                ks: Vec3::splat(0.9),
                exponent: 80.0,
            };
            t.kajiya_kay(wo, wi, Vec3::Z, &params);
        }
        TaskId::BeckmannNdf => {
            t.beckmann_ndf(Vec3::Z, 0.3);
        }
        TaskId::NdfSample => {
            t.ndf_sample(wo, 0.3, 0.3, Vec2::new(0.3, 0.7));
            t.ndf_pdf(wo, wi, 0.3, 0.3);
        }
        TaskId::BrdfCheck => {
            t.brdf_check(&lambert, &mut sampler, 4);
        }
        TaskId::PathTrace | TaskId::Mis | TaskId::DeltaTracking => {}
    }
}
