use crate::prelude::*;

fn mis_weight(h: Heuristic, pa: f32, pb: f32) -> f32 {
    let (a, b) = match h {
        Heuristic::Power => (pa * pa, pb * pb),
        _ => (pa, pb),
    };
    if a + b <= 0.0 { 0.0 } else { a / (a + b) }
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
    let mut result = Vec3::ZERO;

    // ---- light sampling ----
    if !bsdf.is_delta() {
        if let Some(ls) = scene.sample_light(hit.p, sampler) {
            match ls {
                LightSample::Point { p, intensity, prob } => {
                    let to_light = p - hit.p;
                    let d2 = to_light.length_squared();
                    if d2 > 0.0 {
                        let wi = to_light / d2.sqrt();
                        let f = bsdf.eval(t, wo, wi);
                        let (shadow, tmax) = hit.spawn_to(p);
                        if f != Vec3::ZERO && !scene.occluded(&shadow, tmax) {
                            result += f * intensity / d2 / prob;
                        }
                    }
                }
                LightSample::Area { p, n, radiance, pdf_area } => {
                    if heuristic != Heuristic::Bsdf {
                        let to_light = p - hit.p;
                        let d2 = to_light.length_squared();
                        let wi = to_light / d2.sqrt();
                        let cos_light = n.dot(-wi);
                        if d2 > 0.0 && cos_light > 0.0 {
                            let pdf_l = pdf_area * d2 / cos_light;
                            let f = bsdf.eval(t, wo, wi);
                            let (shadow, tmax) = hit.spawn_to(p);
                            if f != Vec3::ZERO && !scene.occluded(&shadow, tmax) {
                                let w = match heuristic {
                                    Heuristic::Light => 1.0,
                                    _ => mis_weight(heuristic, pdf_l, bsdf.pdf(t, wo, wi)),
                                };
                                result += f * radiance * w / pdf_l;
                            }
                        }
                    }
                }
                LightSample::Environment { wi, radiance, pdf } => {
                    if heuristic != Heuristic::Bsdf {
                        let f = bsdf.eval(t, wo, wi);
                        if f != Vec3::ZERO && !scene.occluded(&hit.spawn(wi), f32::INFINITY) {
                            let w = match heuristic {
                                Heuristic::Light => 1.0,
                                _ => mis_weight(heuristic, pdf, bsdf.pdf(t, wo, wi)),
                            };
                            result += f * radiance * w / pdf;
                        }
                    }
                }
            }
        }
    }

    // ---- bsdf sampling ----
    let sample = match bsdf.sample(t, wo, sampler) {
        Some(s) => s,
        None => {
            return DirectLight {
                radiance: result,
                bounce: None,
            };
        }
    };
    let ray = hit.spawn(sample.wi);
    let next = scene.intersect(&ray);
    let (le, pdf_light) = if let Some(nh) = &next {
        let le = scene.emitted(nh, -sample.wi);
        let c = nh.n.dot(sample.wi).abs();
        if le != Vec3::ZERO && c > 0.0 {
            (le, scene.light_pdf(nh) * nh.t * nh.t / c)
        } else {
            (le, 0.0)
        }
    } else {
        (scene.environment(sample.wi), scene.environment_pdf(sample.wi))
    };
    if le != Vec3::ZERO {
        let w = if sample.delta {
            1.0
        } else {
            match heuristic {
                Heuristic::Bsdf => 1.0,
                Heuristic::Light => 0.0,
                _ => mis_weight(heuristic, sample.pdf, pdf_light),
            }
        };
        result += sample.weight * le * w;
    }
    DirectLight {
        radiance: result,
        bounce: Some(Bounce {
            weight: sample.weight,
            segment: Segment {
                ray,
                hit: next,
                emission_counted: true,
            },
        }),
    }
}
