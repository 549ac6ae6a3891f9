use crate::prelude::*;

fn power_or_balance(heuristic: Heuristic, a: f32, b: f32) -> f32 {
    if heuristic == Heuristic::Power {
        let (a2, b2) = (a * a, b * b);
        if a2 + b2 == 0.0 { 0.0 } else { a2 / (a2 + b2) }
    } else if a + b == 0.0 {
        0.0
    } else {
        a / (a + b)
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
    let use_light = heuristic != Heuristic::Bsdf;
    let use_bsdf = heuristic != Heuristic::Light;
    let mut sum = Vec3::ZERO;

    if !bsdf.is_delta() {
        let light = scene.sample_light(hit.p, sampler);
        // (direction, radiance over pdf, solid-angle pdf or None for a delta light, shadow ray, its end)
        let candidate = match light {
            Some(LightSample::Point { p, intensity, prob }) => {
                let v = p - hit.p;
                let r2 = v.dot(v);
                if r2 > 0.0 && r2.is_finite() {
                    let (sray, smax) = hit.spawn_to(p);
                    Some((v / r2.sqrt(), intensity / (r2 * prob), None, sray, smax))
                } else {
                    None
                }
            }
            Some(LightSample::Area { p, n, radiance, pdf_area }) if use_light => {
                let v = p - hit.p;
                let r2 = v.dot(v);
                let dir = v / r2.sqrt();
                let cos_l = -(n.dot(dir));
                if r2 > 0.0 && cos_l > 0.0 {
                    let (sray, smax) = hit.spawn_to(p);
                    let pdf = pdf_area * r2 / cos_l;
                    Some((dir, radiance / pdf, Some(pdf), sray, smax))
                } else {
                    None
                }
            }
            Some(LightSample::Environment { wi, radiance, pdf }) if use_light => {
                Some((wi, radiance / pdf, Some(pdf), hit.spawn(wi), f32::INFINITY))
            }
            _ => None,
        };
        if let Some((dir, le_over_pdf, pdf, sray, smax)) = candidate {
            let f = bsdf.eval(t, wo, dir);
            if f != Vec3::ZERO && !scene.occluded(&sray, smax) {
                let w = match pdf {
                    None => 1.0,
                    Some(_) if !use_bsdf => 1.0,
                    Some(pl) => power_or_balance(heuristic, pl, bsdf.pdf(t, wo, dir)),
                };
                sum += f * le_over_pdf * w;
            }
        }
    }

    let Some(bs) = bsdf.sample(t, wo, sampler) else {
        return DirectLight { radiance: sum, bounce: None };
    };
    let next_ray = hit.spawn(bs.wi);
    let next_hit = scene.intersect(&next_ray);
    let arriving = match &next_hit {
        Some(nh) => scene.emitted(nh, -bs.wi),
        None => scene.environment(bs.wi),
    };
    if arriving != Vec3::ZERO && (bs.delta || use_bsdf) {
        let weight = if bs.delta || !use_light {
            1.0
        } else {
            let other = match &next_hit {
                Some(nh) => {
                    let cosine = nh.n.dot(bs.wi).abs();
                    if cosine > 0.0 { scene.light_pdf(nh) * nh.t * nh.t / cosine } else { 0.0 }
                }
                None => scene.environment_pdf(bs.wi),
            };
            power_or_balance(heuristic, bs.pdf, other)
        };
        sum += bs.weight * arriving * weight;
    }
    DirectLight {
        radiance: sum,
        bounce: Some(Bounce {
            weight: bs.weight,
            segment: Segment { ray: next_ray, hit: next_hit, emission_counted: true },
        }),
    }
}
