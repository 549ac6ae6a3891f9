//! A single harmless call of every function of a task: tells a stub (`todo!()`) from code.

use crate::bsdf::{KajiyaKayParams, PhongParams};
use crate::geometry::Ray;
use crate::integrator::{Heuristic, Segment};
use crate::medium::{Coefficients, Homogeneous};
use crate::optics::{LayerStack, Slab};
use crate::sampling::Sampler;
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::{TaskId, Tasks};
use glam::{Vec2, Vec3};
use std::path::Path;

/// A tiny scene for probing the integrator tasks: a floor lit by a small area light. Its
/// floor samples directions uniformly (framework code), so probing `mis` calls no other
/// task.
pub const PROBE_SCENE: &str = "\
camera: {eye: [0, 1, 3], target: [0, 0, 0], fov: 40, width: 4, height: 4}
render: {spp: 1}
materials:
  floor: {diffuse: {albedo: 0.5, sampling: uniform}}
shapes:
  - quad: {origin: [-1, 0, 1], edge1: [2, 0, 0], edge2: [0, 0, -2], material: floor}
  - quad: {origin: [-0.25, 1, -0.25], edge1: [0.5, 0, 0], edge2: [0, 0, 0.5], emission: 4}
";

/// The probe scene, built.
pub fn probe_scene() -> Scene {
    Scene::from_yaml(
        Path::new("<probe scene>"),
        PROBE_SCENE,
        &LoadOptions::default(),
    )
    .expect("the built-in probe scene is valid (tests/instructor/render_scenes.rs checks it)")
}

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
        TaskId::PathTrace => {
            // A camera ray that leaves the scene at depth 1: written code returns the
            // environment (black) without calling any other task.
            let scene = probe_scene();
            let segment = Segment {
                ray: Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y),
                hit: None,
                emission_counted: false,
            };
            t.path_trace(&scene, &segment, 1, &mut sampler);
        }
        TaskId::Mis => {
            let scene = probe_scene();
            let ray = Ray::new(Vec3::new(0.0, 0.5, 0.3), -Vec3::Y);
            let hit = scene
                .intersect(&ray)
                .expect("the probe ray hits the probe scene's floor");
            t.mis(&scene, &hit, Vec3::Y, Heuristic::Power, &mut sampler);
        }
        TaskId::DeltaTracking => {
            let medium = Homogeneous {
                coefficients: Coefficients {
                    sigma_a: 0.5,
                    sigma_s: 0.5,
                },
            };
            let ray = Ray::new(Vec3::ZERO, Vec3::Z);
            t.delta_tracking(&medium, &ray, 1.0, 1000, &mut sampler);
        }
    }
}
