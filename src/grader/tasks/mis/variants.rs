// The variants of `mis` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Patch, Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::bsdf::Bsdf;
use pbrlab::geometry::Hit;
use pbrlab::integrator::{Bounce, DirectLight, Heuristic, Segment};
use pbrlab::light::LightSample;
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};

/// A wrong `mis`: the reference's algorithm with one flaw (a task function is a plain
/// `fn`, which cannot capture the flaw, hence a macro).
macro_rules! flawed {
    ($name:expr, $flaw:ident) => {
        variant($name, TaskId::Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| mis_variant(t, s, h, wo, he, sa, MisFlaw::$flaw))
        })
    };
}

/// Known-wrong implementations of `mis`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    vec![
        flawed!(
            "the sheet's G without the cosine at the light",
            MissingLightCosine
        ),
        flawed!("the sheet's inverted visibility test", NoShadows),
        flawed!(
            "the sheet's mixed pdf measures in the weights",
            MixedMeasures
        ),
        flawed!(
            "the light's pdf converted with the cosine at the shading point",
            CosineAtShadingPoint
        ),
        flawed!(
            "an environment sample without its MIS weight",
            UnweightedSkySample
        ),
        flawed!("point-light samples dropped", NoPointLights),
        flawed!(
            "weights p_a / (p_a − p_b): they sum to one, but are not the balance heuristic",
            DifferenceWeights
        ),
        flawed!("the light sample's radiance left out", LightRadianceIgnored),
        flawed!(
            "the point light's direction taken from the origin",
            PointLightFromOrigin
        ),
        flawed!(
            "a point light at distance 0 divides 0 by 0",
            UnguardedPointLight
        ),
        flawed!(
            "an environment sample never tested for occlusion",
            UnoccludedSky
        ),
        flawed!(
            "the Lambertian density in the light sample's weight",
            LambertianPdfInWeight
        ),
        flawed!(
            "the Lambertian density in the BSDF sample's weight",
            LambertianPdfInBsdfWeight
        ),
        flawed!(
            "point lights skipped under BSDF weights",
            NoPointLightsUnderBsdfWeights
        ),
        flawed!("area lights taken as two-sided", TwoSidedLights),
        flawed!(
            "the bounce returned with its emission not counted",
            BounceEmissionNotCounted
        ),
    ]
}

/// Correct implementations of `mis` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    Vec::new()
}

/// Naive implementations of `mis` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`mis` converts pdfs and weights delta samples without guards",
        Mis,
        |p| {
            p.mis = Some(textbook::mis_unguarded);
        },
        vec![
            ("mis/delta_bsdf", WrongValue),
            ("mis/light_edge_on", NaN),
            ("mis/shading_point_on_the_light", NaN),
        ],
    )]
}

/// How an `mis` variant goes wrong.
#[derive(Clone, Copy, PartialEq)]
enum MisFlaw {
    /// `G = cos θ / d²`: the cosine at the light is missing from the area-to-solid-angle
    /// conversion of the light sample.
    MissingLightCosine,
    /// The shadow test never finds an occluder (the sheet's inverted comparison).
    NoShadows,
    /// Both weights use the light's pdf per unit area next to the BSDF's per solid angle
    /// (reading I1: unbiased, but the variance depends on the unit of length).
    MixedMeasures,
    /// The area-to-solid-angle conversion with the cosine at the shading point instead of
    /// at the light (equal only where the light is parallel to the surface).
    CosineAtShadingPoint,
    /// An environment light sample added without its MIS weight.
    UnweightedSkySample,
    /// Point-light samples dropped.
    NoPointLights,
    /// Weights `p_a / (p_a − p_b)` in place of `p_a / (p_a + p_b)`: the two still sum to one,
    /// so every mean is right, but near `p_a = p_b` they explode.
    DifferenceWeights,
    /// The light sample's radiance left out (right only for lights of radiance 1).
    LightRadianceIgnored,
    /// The point light's direction taken as its position (right only when shading at the
    /// origin).
    PointLightFromOrigin,
    /// No guard for a point light at distance 0: `0/0` where it lies on the shading point.
    UnguardedPointLight,
    /// An environment sample never tested for occlusion.
    UnoccludedSky,
    /// The light sample's MIS weight with the Lambertian density `cos θ / π` for the BSDF's
    /// (right on diffuse surfaces only).
    LambertianPdfInWeight,
    /// Point lights skipped under BSDF weights, like area lights.
    NoPointLightsUnderBsdfWeights,
    /// The BSDF sample's MIS weight with the Lambertian density `cos θ / π` for its own
    /// pdf (right on diffuse surfaces only).
    LambertianPdfInBsdfWeight,
    /// Area lights taken as two-sided (`|cos θl|`).
    TwoSidedLights,
    /// The bounce returned with `emission_counted: false`, so the caller adds the light it
    /// reaches again.
    BounceEmissionNotCounted,
}

/// The MIS weight of a sample drawn with density `a` when the other strategy has `b`, as
/// `flaw` computes it.
fn weight(heuristic: Heuristic, from_light: bool, a: f32, b: f32, flaw: MisFlaw) -> f32 {
    let r = |a: f32, b: f32| match flaw {
        MisFlaw::DifferenceWeights => a / (a - b),
        _ if a + b > 0.0 => a / (a + b),
        _ => 0.0,
    };
    match heuristic {
        Heuristic::Bsdf => (!from_light) as u8 as f32,
        Heuristic::Light => from_light as u8 as f32,
        Heuristic::Balance => r(a, b),
        Heuristic::Power => r(a * a, b * b),
    }
}

fn mis_variant(
    t: &Patch,
    scene: &Scene,
    hit: &Hit,
    wo: Vec3,
    heuristic: Heuristic,
    sampler: &mut Sampler,
    flaw: MisFlaw,
) -> DirectLight {
    let bsdf = scene.bsdf(hit);
    let mut radiance = Vec3::ZERO;
    if !bsdf.is_delta()
        && let Some(light) = scene.sample_light(hit.p, sampler)
    {
        radiance += light_sample(t, scene, hit, &bsdf, wo, heuristic, light, flaw);
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
            let pdf = match flaw {
                _ if le == Vec3::ZERO || cos_l <= 0.0 => 0.0,
                MisFlaw::MixedMeasures => scene.light_pdf(h),
                _ => scene.light_pdf(h) * h.t * h.t / cos_l,
            };
            (le, pdf)
        }
        None => (scene.environment(s.wi), scene.environment_pdf(s.wi)),
    };
    if emitted != Vec3::ZERO {
        let w = if s.delta {
            1.0
        } else {
            let pdf_bsdf = if flaw == MisFlaw::LambertianPdfInBsdfWeight {
                hit.n.dot(s.wi).abs() * std::f32::consts::FRAC_1_PI
            } else {
                s.pdf
            };
            weight(heuristic, false, pdf_bsdf, pdf_light, flaw)
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
                emission_counted: flaw != MisFlaw::BounceEmissionNotCounted,
            },
        }),
    }
}

#[allow(clippy::too_many_arguments)]
fn light_sample(
    t: &Patch,
    scene: &Scene,
    hit: &Hit,
    bsdf: &Bsdf<'_>,
    wo: Vec3,
    heuristic: Heuristic,
    light: LightSample,
    flaw: MisFlaw,
) -> Vec3 {
    let (p, n, le, pdf_area) = match light {
        LightSample::Area {
            p,
            n,
            radiance,
            pdf_area,
        } => (p, n, radiance, pdf_area),
        LightSample::Point { p, intensity, prob } => {
            if flaw == MisFlaw::NoPointLights
                || (flaw == MisFlaw::NoPointLightsUnderBsdfWeights && heuristic == Heuristic::Bsdf)
            {
                return Vec3::ZERO;
            }
            let d = if flaw == MisFlaw::PointLightFromOrigin {
                p
            } else {
                p - hit.p
            };
            let dist2 = d.length_squared();
            if dist2 == 0.0 && flaw != MisFlaw::UnguardedPointLight {
                return Vec3::ZERO;
            }
            let (ray, t_max) = hit.spawn_to(p);
            if scene.occluded(&ray, t_max) {
                return Vec3::ZERO;
            }
            return bsdf.eval(t, wo, d / dist2.sqrt()) * intensity / (dist2 * prob);
        }
        LightSample::Environment { wi, radiance, pdf } => {
            if heuristic == Heuristic::Bsdf || pdf <= 0.0 {
                return Vec3::ZERO;
            }
            if flaw != MisFlaw::UnoccludedSky && scene.occluded(&hit.spawn(wi), f32::INFINITY) {
                return Vec3::ZERO;
            }
            let w = if flaw == MisFlaw::UnweightedSkySample {
                1.0
            } else {
                weight(heuristic, true, pdf, bsdf.pdf(t, wo, wi), flaw)
            };
            return bsdf.eval(t, wo, wi) * radiance * (w / pdf);
        }
    };
    if heuristic == Heuristic::Bsdf {
        return Vec3::ZERO;
    }
    let d = p - hit.p;
    let dist2 = d.length_squared();
    let wi = d / dist2.sqrt();
    let cos_l = if flaw == MisFlaw::TwoSidedLights {
        n.dot(wi).abs()
    } else {
        -n.dot(wi)
    };
    if cos_l <= 0.0 {
        return Vec3::ZERO;
    }
    let f = bsdf.eval(t, wo, wi);
    let (ray, t_max) = hit.spawn_to(p);
    if flaw != MisFlaw::NoShadows && scene.occluded(&ray, t_max) {
        return Vec3::ZERO;
    }
    let pdf_light = match flaw {
        MisFlaw::MissingLightCosine => pdf_area * dist2,
        MisFlaw::CosineAtShadingPoint => pdf_area * dist2 / hit.n.dot(wi).abs(),
        _ => pdf_area * dist2 / cos_l,
    };
    let pdf_in_weight = if flaw == MisFlaw::MixedMeasures {
        pdf_area
    } else {
        pdf_light
    };
    let le = if flaw == MisFlaw::LightRadianceIgnored {
        Vec3::ONE
    } else {
        le
    };
    let bsdf_pdf = if flaw == MisFlaw::LambertianPdfInWeight {
        hit.n.dot(wi).abs() * std::f32::consts::FRAC_1_PI
    } else {
        bsdf.pdf(t, wo, wi)
    };
    f * le * (weight(heuristic, true, pdf_in_weight, bsdf_pdf, flaw) / pdf_light)
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// Direct light with the textbook formulas and no guards: the light sample's area pdf is
    /// converted with whatever cos θl is (0 edge-on), and the BSDF sample is weighted by the
    /// heuristic even when it comes from a delta lobe (pdf 0). Area lights only.
    pub fn mis_unguarded(
        t: &impl Tasks,
        scene: &Scene,
        hit: &Hit,
        wo: Vec3,
        _heuristic: Heuristic,
        sampler: &mut Sampler,
    ) -> DirectLight {
        use pbrlab::integrator::{Bounce, DirectLight, Segment};
        use pbrlab::light::LightSample;
        let power = |a: f32, b: f32| a * a / (a * a + b * b);
        let bsdf = scene.bsdf(hit);
        let mut radiance = Vec3::ZERO;
        if let Some(LightSample::Area {
            p,
            n,
            radiance: le,
            pdf_area,
        }) = scene.sample_light(hit.p, sampler)
        {
            let d = p - hit.p;
            let dist2 = d.length_squared();
            let wi = d / dist2.sqrt();
            let cos_l = -n.dot(wi);
            let pdf_light = pdf_area * dist2 / cos_l;
            let (ray, t_max) = hit.spawn_to(p);
            if !scene.occluded(&ray, t_max) {
                let w = power(pdf_light, bsdf.pdf(t, wo, wi));
                radiance += bsdf.eval(t, wo, wi) * le * w / pdf_light;
            }
        }
        let Some(s) = bsdf.sample(t, wo, sampler) else {
            return DirectLight {
                radiance,
                bounce: None,
            };
        };
        let ray = hit.spawn(s.wi);
        let next = scene.intersect(&ray);
        if let Some(h) = &next {
            let le = scene.emitted(h, -s.wi);
            let pdf_light = scene.light_pdf(h) * h.t * h.t / h.n.dot(s.wi).abs();
            radiance += s.weight * le * power(s.pdf, pdf_light);
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
}
