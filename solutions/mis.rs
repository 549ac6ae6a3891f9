//! Task `mis`: reference solution.

use crate::prelude::*;

/// The MIS weight of a sample drawn with density `pdf_this` when the other strategy has
/// density `pdf_other` there; `from_light` says which strategy drew it.
fn weight(heuristic: Heuristic, from_light: bool, pdf_this: f32, pdf_other: f32) -> f32 {
    let ratio = |a: f32, b: f32| if a + b > 0.0 { a / (a + b) } else { 0.0 };
    match heuristic {
        Heuristic::Bsdf => (!from_light) as u8 as f32,
        Heuristic::Light => from_light as u8 as f32,
        Heuristic::Balance => ratio(pdf_this, pdf_other),
        Heuristic::Power => ratio(pdf_this * pdf_this, pdf_other * pdf_other),
    }
}

/// Direct light at `hit` towards `wo` by a light sample and a BSDF sample, and that BSDF
/// sample, traced.
pub fn mis(
    t: &impl Tasks,
    scene: &Scene,
    hit: &Hit,
    wo: Vec3,
    heuristic: Heuristic,
    sampler: &mut Sampler,
) -> DirectLight {
    let bsdf = scene.bsdf(hit);
    let mut radiance = Vec3::ZERO;

    if !bsdf.is_delta()
        && let Some(light) = scene.sample_light(hit.p, sampler)
    {
        radiance += light_sample(t, scene, hit, &bsdf, wo, heuristic, &light);
    }

    let Some(s) = bsdf.sample(t, wo, sampler) else {
        return DirectLight {
            radiance,
            bounce: None,
        };
    };
    let ray = hit.spawn(s.wi);
    let next = scene.intersect(&ray);
    let (emitted, pdf_light) = match &next {
        Some(h) => {
            let le = scene.emitted(h, -s.wi);
            let cos_l = h.n.dot(s.wi).abs();
            let pdf = if le != Vec3::ZERO && cos_l > 0.0 {
                scene.light_pdf(h) * h.t * h.t / cos_l
            } else {
                0.0
            };
            (le, pdf)
        }
        None => (scene.environment(s.wi), scene.environment_pdf(s.wi)),
    };
    if emitted != Vec3::ZERO {
        let w = if s.delta {
            1.0
        } else {
            weight(heuristic, false, s.pdf, pdf_light)
        };
        radiance += s.weight * emitted * w;
    }
    DirectLight {
        radiance,
        bounce: Some(Bounce {
            weight: s.weight,
            segment: Segment {
                ray,
                hit: next,
                emission_counted: true,
            },
        }),
    }
}

/// The weighted contribution of one light sample.
fn light_sample(
    t: &impl Tasks,
    scene: &Scene,
    hit: &Hit,
    bsdf: &Bsdf<'_>,
    wo: Vec3,
    heuristic: Heuristic,
    light: &LightSample,
) -> Vec3 {
    match *light {
        LightSample::Area {
            p,
            n,
            radiance,
            pdf_area,
        } => {
            if heuristic == Heuristic::Bsdf {
                return Vec3::ZERO;
            }
            let d = p - hit.p;
            let dist2 = d.length_squared();
            if dist2.is_nan() || dist2 <= 0.0 {
                return Vec3::ZERO;
            }
            let wi = d / dist2.sqrt();
            let cos_l = -n.dot(wi);
            if cos_l <= 0.0 {
                return Vec3::ZERO;
            }
            let f = bsdf.eval(t, wo, wi);
            if f == Vec3::ZERO {
                return Vec3::ZERO;
            }
            let (ray, t_max) = hit.spawn_to(p);
            if scene.occluded(&ray, t_max) {
                return Vec3::ZERO;
            }
            let pdf_light = pdf_area * dist2 / cos_l;
            let w = weight(heuristic, true, pdf_light, bsdf.pdf(t, wo, wi));
            f * radiance * (w / pdf_light)
        }
        LightSample::Point { p, intensity, prob } => {
            let d = p - hit.p;
            let dist2 = d.length_squared();
            // A point light on the shading point: every other point of the surface sees it
            // at cos θ = 0, so it lights nothing here either.
            if dist2.is_nan() || dist2 <= 0.0 {
                return Vec3::ZERO;
            }
            let wi = d / dist2.sqrt();
            let f = bsdf.eval(t, wo, wi);
            if f == Vec3::ZERO {
                return Vec3::ZERO;
            }
            let (ray, t_max) = hit.spawn_to(p);
            if scene.occluded(&ray, t_max) {
                return Vec3::ZERO;
            }
            f * intensity / (dist2 * prob)
        }
        LightSample::Environment { wi, radiance, pdf } => {
            if heuristic == Heuristic::Bsdf {
                return Vec3::ZERO;
            }
            let f = bsdf.eval(t, wo, wi);
            if f == Vec3::ZERO || scene.occluded(&hit.spawn(wi), f32::INFINITY) {
                return Vec3::ZERO;
            }
            let w = weight(heuristic, true, pdf, bsdf.pdf(t, wo, wi));
            f * radiance * (w / pdf)
        }
    }
}
