use crate::prelude::*;

/// Weight of a strategy with density `mine` against `theirs`.
fn combine(heuristic: Heuristic, mine: f32, theirs: f32) -> f32 {
    let (x, y) = if heuristic == Heuristic::Power {
        (mine * mine, theirs * theirs)
    } else {
        (mine, theirs)
    };
    let s = x + y;
    if s > 0.0 { x / s } else { 0.0 }
}

fn light_weight(heuristic: Heuristic, pdf_light: f32, pdf_bsdf: f32) -> f32 {
    match heuristic {
        Heuristic::Light => 1.0,
        Heuristic::Bsdf => 0.0,
        Heuristic::Balance | Heuristic::Power => combine(heuristic, pdf_light, pdf_bsdf),
    }
}

fn bsdf_weight(heuristic: Heuristic, pdf_bsdf: f32, pdf_light: f32) -> f32 {
    match heuristic {
        Heuristic::Light => 0.0,
        Heuristic::Bsdf => 1.0,
        Heuristic::Balance | Heuristic::Power => combine(heuristic, pdf_bsdf, pdf_light),
    }
}

/// The weighted contribution of one light sample (zero when occluded or skipped).
fn sample_one_light(
    t: &impl Tasks,
    scene: &Scene,
    hit: &Hit,
    bsdf: &Bsdf<'_>,
    wo: Vec3,
    heuristic: Heuristic,
    sampler: &mut Sampler,
) -> Vec3 {
    let Some(sample) = scene.sample_light(hit.p, sampler) else {
        return Vec3::ZERO;
    };
    match sample {
        LightSample::Environment { wi, radiance, pdf } => {
            if heuristic == Heuristic::Bsdf {
                return Vec3::ZERO;
            }
            let f = bsdf.eval(t, wo, wi);
            if f == Vec3::ZERO {
                return Vec3::ZERO;
            }
            if scene.occluded(&hit.spawn(wi), f32::INFINITY) {
                return Vec3::ZERO;
            }
            f * radiance * light_weight(heuristic, pdf, bsdf.pdf(t, wo, wi)) / pdf
        }
        LightSample::Area { p, n, radiance, pdf_area } => {
            if heuristic == Heuristic::Bsdf {
                return Vec3::ZERO;
            }
            let offset = p - hit.p;
            let dist = offset.length();
            if !(dist > 0.0) {
                return Vec3::ZERO;
            }
            let wi = offset / dist;
            let cos_at_light = -wi.dot(n);
            if cos_at_light <= 0.0 {
                return Vec3::ZERO;
            }
            let (shadow_ray, limit) = hit.spawn_to(p);
            if scene.occluded(&shadow_ray, limit) {
                return Vec3::ZERO;
            }
            let f = bsdf.eval(t, wo, wi);
            let solid_angle_pdf = pdf_area * dist * dist / cos_at_light;
            let w = light_weight(heuristic, solid_angle_pdf, bsdf.pdf(t, wo, wi));
            f * radiance * w / solid_angle_pdf
        }
        LightSample::Point { p, intensity, prob } => {
            let offset = p - hit.p;
            let dist = offset.length();
            if !(dist > 0.0) {
                return Vec3::ZERO;
            }
            let wi = offset / dist;
            let (shadow_ray, limit) = hit.spawn_to(p);
            if scene.occluded(&shadow_ray, limit) {
                return Vec3::ZERO;
            }
            bsdf.eval(t, wo, wi) * intensity / (dist * dist * prob)
        }
    }
}

pub fn mis(
    t: &impl Tasks,
    scene: &Scene,
    hit: &Hit,
    wo: Vec3,
    heuristic: Heuristic,
    sampler: &mut Sampler,
) -> DirectLight {
    let bsdf = scene.bsdf(hit);
    let mut radiance = if bsdf.is_delta() {
        Vec3::ZERO
    } else {
        sample_one_light(t, scene, hit, &bsdf, wo, heuristic, sampler)
    };
    let bounce = bsdf.sample(t, wo, sampler).map(|bs| {
        let ray = hit.spawn(bs.wi);
        let found = scene.intersect(&ray);
        let (le, light_pdf) = match found.as_ref() {
            None => (scene.environment(bs.wi), scene.environment_pdf(bs.wi)),
            Some(lh) => {
                let le = scene.emitted(lh, -bs.wi);
                let cos = lh.n.dot(bs.wi).abs();
                let pdf = if le == Vec3::ZERO || cos <= 0.0 {
                    0.0
                } else {
                    scene.light_pdf(lh) * lh.t * lh.t / cos
                };
                (le, pdf)
            }
        };
        if le != Vec3::ZERO {
            let w = if bs.delta { 1.0 } else { bsdf_weight(heuristic, bs.pdf, light_pdf) };
            radiance += bs.weight * le * w;
        }
        Bounce {
            weight: bs.weight,
            segment: Segment { ray, hit: found, emission_counted: true },
        }
    });
    DirectLight { radiance, bounce }
}
