//! The volumetric path tracer (framework code): free flights in media by the
//! `delta_tracking` task, next-event estimation by light sampling at surfaces and in media
//! (with transmittance along shadow rays), phase-function and BSDF sampling to continue.
//!
//! Media fill closed shapes whose boundaries are index-matched (they take no material):
//! a ray crossing one just changes the medium it is in. The camera must be outside every
//! medium, and media must not overlap. Crossing a boundary is not a path segment.

use crate::bsdf::Bsdf;
use crate::geometry::{Hit, Ray};
use crate::light::LightSample;
use crate::medium::{FreeFlight, HenyeyGreenstein, homogeneous_transmittance, ratio_tracking};
use crate::sampling::Sampler;
use crate::scene::schema::TransmittanceEstimator;
use crate::scene::{MediumKind, Scene};
use crate::worksheet::Tasks;
use glam::Vec3;
use std::cmp::Ordering;

/// Iteration bound handed to `delta_tracking` and ratio tracking.
pub const MAX_TRACKING_STEPS: u32 = 100_000;
/// Boundary crossings after which a ray is given up (a guard against degenerate geometry).
const MAX_CROSSINGS: u32 = 256;

/// Where a shadow ray or a light path starts, for next-event estimation.
enum Vertex<'a> {
    /// On a surface, with its BSDF.
    Surface(&'a Hit, &'a Bsdf<'a>),
    /// Inside a medium, at a point, with its phase function.
    Medium(Vec3, HenyeyGreenstein),
}

/// An estimate of the radiance arriving at the camera along `ray`.
pub fn radiance<T: Tasks>(t: &T, scene: &Scene, mut ray: Ray, sampler: &mut Sampler) -> Vec3 {
    let settings = scene.settings();
    let mut radiance = Vec3::ZERO;
    let mut beta = Vec3::ONE;
    let mut medium: Option<u32> = None;
    let mut count_emission = true;
    let mut depth = settings.max_depth;
    let mut crossings = 0;
    while depth > 0 {
        let hit = scene.intersect(&ray);
        if let Some(m) = medium {
            let med = &scene.media()[m as usize];
            let t_surface = hit.map_or(f32::INFINITY, |h| h.t);
            match t.delta_tracking(med, &ray, t_surface, MAX_TRACKING_STEPS, sampler) {
                FreeFlight::Scatter { t: distance } => {
                    let p = ray.at(distance);
                    let wo = -ray.dir;
                    if depth >= 2 {
                        radiance += beta
                            * next_event(
                                t,
                                scene,
                                &Vertex::Medium(p, med.phase),
                                wo,
                                medium,
                                sampler,
                            );
                    }
                    if !roulette(settings.roulette_applies(depth), &mut beta, sampler) {
                        break;
                    }
                    ray = Ray::new(p, med.phase.sample(wo, sampler.next_2d()));
                    count_emission = false;
                    depth -= 1;
                    continue;
                }
                FreeFlight::Absorb { .. } | FreeFlight::Exhausted => break,
                FreeFlight::Escape => {}
            }
        }
        let Some(hit) = hit else {
            if count_emission {
                radiance += beta * scene.environment(ray.dir);
            }
            break;
        };
        let info = scene.shape(hit.shape);
        if info.material.is_none() {
            crossings += 1;
            if crossings > MAX_CROSSINGS {
                break;
            }
            medium = if ray.dir.dot(hit.n) < 0.0 {
                info.medium
            } else {
                None
            };
            ray = hit.spawn(ray.dir);
            continue;
        }
        let wo = -ray.dir;
        if count_emission {
            radiance += beta * scene.emitted(&hit, wo);
        }
        if depth == 1 {
            break;
        }
        let bsdf = scene.bsdf(&hit);
        if !bsdf.is_delta() {
            radiance +=
                beta * next_event(t, scene, &Vertex::Surface(&hit, &bsdf), wo, medium, sampler);
        }
        let Some(sample) = bsdf.sample(t, wo, sampler) else {
            break;
        };
        beta *= sample.weight;
        if !roulette(settings.roulette_applies(depth), &mut beta, sampler) {
            break;
        }
        count_emission = sample.delta;
        ray = hit.spawn(sample.wi);
        depth -= 1;
    }
    radiance
}

/// Russian roulette on the path throughput `beta`: survive with probability
/// `min(max(beta), 0.95)` and divide by it. Returns false when the path ends.
fn roulette(applies: bool, beta: &mut Vec3, sampler: &mut Sampler) -> bool {
    if !applies {
        return true;
    }
    let survival = beta.max_element().min(0.95);
    let survives =
        survival.partial_cmp(&0.0) == Some(Ordering::Greater) && sampler.next_1d() < survival;
    if survives {
        *beta /= survival;
    }
    survives
}

/// Light sampling at a vertex: one light sample, its transmittance, no MIS.
fn next_event<T: Tasks>(
    t: &T,
    scene: &Scene,
    vertex: &Vertex<'_>,
    wo: Vec3,
    medium: Option<u32>,
    sampler: &mut Sampler,
) -> Vec3 {
    let x = match vertex {
        Vertex::Surface(hit, _) => hit.p,
        Vertex::Medium(p, _) => *p,
    };
    let Some(sample) = scene.sample_light(x, sampler) else {
        return Vec3::ZERO;
    };
    let (wi, dist, emitted, pdf_solid_angle) = match sample {
        LightSample::Area {
            p,
            n,
            radiance,
            pdf_area,
        } => {
            let d = p - x;
            let dist2 = d.length_squared();
            let dist = dist2.sqrt();
            if (dist.is_nan() || dist <= 0.0) || (pdf_area.is_nan() || pdf_area <= 0.0) {
                return Vec3::ZERO;
            }
            let wi = d / dist;
            let cos_l = -n.dot(wi);
            if cos_l <= 0.0 {
                return Vec3::ZERO;
            }
            (wi, dist, radiance, pdf_area * dist2 / cos_l)
        }
        LightSample::Point { p, intensity, prob } => {
            let d = p - x;
            let dist2 = d.length_squared();
            let positive = |v: f32| v.partial_cmp(&0.0) == Some(Ordering::Greater);
            if !(positive(dist2) && positive(prob)) {
                return Vec3::ZERO;
            }
            let dist = dist2.sqrt();
            // A delta light: irradiance I/d², no density.
            (d / dist, dist, intensity / dist2, prob)
        }
        LightSample::Environment { wi, radiance, pdf } => {
            if pdf.is_nan() || pdf <= 0.0 {
                return Vec3::ZERO;
            }
            (wi, f32::INFINITY, radiance, pdf)
        }
    };
    let (f, ray, t_max) = match vertex {
        Vertex::Surface(hit, bsdf) => {
            let f = bsdf.eval(t, wo, wi);
            if dist.is_finite() {
                let (ray, t_max) = hit.spawn_to(x + wi * dist);
                (f, ray, t_max)
            } else {
                (f, hit.spawn(wi), f32::INFINITY)
            }
        }
        Vertex::Medium(p, phase) => {
            let shorten = 1e-4 * (1.0 + (x + wi * dist).abs().max_element());
            let t_max = if dist.is_finite() {
                (dist - shorten).max(0.0)
            } else {
                dist
            };
            (Vec3::splat(phase.eval(wo, wi)), Ray::new(*p, wi), t_max)
        }
    };
    if f == Vec3::ZERO {
        return Vec3::ZERO;
    }
    let tr = transmittance(t, scene, ray, t_max, medium, sampler);
    if tr <= 0.0 {
        return Vec3::ZERO;
    }
    f * emitted * (tr / pdf_solid_angle)
}

/// The transmittance along `ray` over `(0, t_max)`, starting in `medium`: 0 when a surface
/// blocks it, otherwise the product over the media it crosses of the scene's transmittance
/// estimate.
pub fn transmittance<T: Tasks>(
    t: &T,
    scene: &Scene,
    mut ray: Ray,
    mut t_max: f32,
    mut medium: Option<u32>,
    sampler: &mut Sampler,
) -> f32 {
    if scene.occluded(&ray, t_max) {
        return 0.0;
    }
    let mut tr = 1.0;
    for _ in 0..MAX_CROSSINGS {
        let boundary = scene
            .boundaries
            .as_ref()
            .and_then(|b| b.intersect(&ray, t_max));
        let end = boundary.map_or(t_max, |h| h.t);
        if let Some(m) = medium {
            tr *= medium_transmittance(t, scene, m, &ray, end, sampler);
            if tr <= 0.0 {
                return 0.0;
            }
        }
        let Some(hit) = boundary else {
            return tr;
        };
        let info = scene.shape(hit.shape);
        medium = if ray.dir.dot(hit.n) < 0.0 {
            info.medium
        } else {
            None
        };
        let target = ray.at(t_max);
        ray = hit.spawn(ray.dir);
        if t_max.is_finite() {
            t_max = (target - ray.origin).dot(ray.dir);
            if t_max <= 0.0 {
                return tr;
            }
        }
    }
    tr
}

/// The transmittance through medium `m` along `ray` over `(0, end)` by the scene's
/// estimator.
fn medium_transmittance<T: Tasks>(
    t: &T,
    scene: &Scene,
    m: u32,
    ray: &Ray,
    end: f32,
    sampler: &mut Sampler,
) -> f32 {
    let med = &scene.media()[m as usize];
    match scene.settings().transmittance {
        TransmittanceEstimator::Ratio => ratio_tracking(med, ray, end, MAX_TRACKING_STEPS, sampler),
        TransmittanceEstimator::Delta => {
            match t.delta_tracking(med, ray, end, MAX_TRACKING_STEPS, sampler) {
                FreeFlight::Escape => 1.0,
                _ => 0.0,
            }
        }
        TransmittanceEstimator::Analytic => match &med.kind {
            MediumKind::Homogeneous(h) => homogeneous_transmittance(h.coefficients.sigma_t(), end),
            // The loader refuses analytic transmittance with grids; ratio tracking is the
            // unbiased answer should one get here.
            MediumKind::Grid(_) => ratio_tracking(med, ray, end, MAX_TRACKING_STEPS, sampler),
        },
    }
}
