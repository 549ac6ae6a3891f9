//! Known-wrong `path_trace`, `mis` and `delta_tracking`: the worksheet's three code bugs as
//! the errata demonstrate them, and the usual slips (roulette without dividing by q).

use super::patch::{Patch, Variant, variant as wrong};
use glam::Vec3;
use pbrlab::bsdf::Bsdf;
use pbrlab::geometry::{Hit, Ray};
use pbrlab::integrator::{Bounce, DirectLight, Heuristic, Segment};
use pbrlab::light::LightSample;
use pbrlab::medium::{FreeFlight, Medium};
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::worksheet::{TaskId, Tasks};

/// How a `path_trace` variant goes wrong.
#[derive(Clone, Copy, PartialEq)]
enum PathFlaw {
    /// The sheet: the recursion never adds emission or direct light after the camera hit.
    NoLightAfterCamera,
    /// Russian roulette that forgets to divide by the survival probability.
    RouletteWithoutDivision,
    /// Emission added again where `mis` already counted it.
    EmissionTwice,
    /// The sky added again when a bounce escapes, though `mis` already counted it.
    SkyTwice,
    /// A survival probability not capped at 1 (`q = max(weight)`): a bounce weight above 1
    /// always survives and is still divided by q.
    UncappedSurvival,
    /// The roulette test inverted: the path ends with probability q instead of 1 − q.
    InvertedRoulette,
    /// The sheet's `depth == 0` test: a depth below 0 goes on.
    OnlyDepthZeroStops,
    /// A survival probability from the smallest channel of the weight: a channel that
    /// reflects nothing ends every path.
    SurvivalFromSmallestChannel,
    /// The throughput kept as one number (the weight's largest channel).
    ScalarThroughput,
    /// Black returned when `mis` gives no bounce, losing the light gathered so far.
    BlackWithoutBounce,
}

fn path_variant(
    t: &Patch,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
    flaw: PathFlaw,
) -> Vec3 {
    if depth <= 0 && !(flaw == PathFlaw::OnlyDepthZeroStops && depth < 0) {
        return Vec3::ZERO;
    }
    let counted = segment.emission_counted && flaw != PathFlaw::EmissionTwice;
    let Some(hit) = &segment.hit else {
        return if counted && flaw != PathFlaw::SkyTwice {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let mut radiance = if counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return radiance;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    if flaw != PathFlaw::NoLightAfterCamera {
        radiance += direct.radiance;
    }
    let Some(bounce) = direct.bounce else {
        return if flaw == PathFlaw::BlackWithoutBounce {
            Vec3::ZERO
        } else {
            radiance
        };
    };
    if depth == 2 {
        return radiance;
    }
    let mut weight = if flaw == PathFlaw::ScalarThroughput {
        Vec3::splat(bounce.weight.max_element())
    } else {
        bounce.weight
    };
    if scene.settings().roulette_applies(depth) {
        let q = match flaw {
            PathFlaw::UncappedSurvival => weight.max_element(),
            PathFlaw::SurvivalFromSmallestChannel => weight.min_element().min(0.95),
            _ => weight.max_element().min(0.95),
        };
        let u = sampler.next_1d();
        let ends = match flaw {
            PathFlaw::InvertedRoulette => u < q,
            _ => u >= q,
        };
        if q <= 0.0 || ends {
            return radiance;
        }
        if flaw != PathFlaw::RouletteWithoutDivision {
            weight /= q;
        }
    }
    let further = t.path_trace(scene, &bounce.segment, depth - 1, sampler);
    radiance
        + weight
            * if flaw == PathFlaw::NoLightAfterCamera {
                Vec3::ZERO
            } else {
                further
            }
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

/// How a `delta_tracking` variant goes wrong.
#[derive(Clone, Copy, PartialEq)]
enum TrackingFlaw {
    /// The sheet: two random numbers drawn once and reused at every step.
    ReusedRandomNumbers,
    /// An escape returned as an absorption at the end of the segment.
    EscapeAsAbsorption,
    /// Every tentative collision taken as real (no null collisions).
    NoNullCollisions,
    /// `majorant <= 0` as the only guard: a NaN majorant walks on with NaN distances.
    UnguardedNanMajorant,
    /// A walk that ran out of steps reported as an escape.
    ExhaustedAsEscape,
    /// The medium looked up at `t · dir`, as if every ray started at the origin.
    RayFromOrigin,
    /// One tentative collision fewer than `max_steps`.
    OneStepShort,
    /// One tentative collision more than `max_steps`.
    OneStepTooMany,
    /// A walk that ran out of steps reported as an absorption where it stopped.
    ExhaustedAsAbsorption,
}

fn tracking_variant(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
    flaw: TrackingFlaw,
) -> FreeFlight {
    let majorant = medium.majorant();
    let nan_guard = flaw != TrackingFlaw::UnguardedNanMajorant;
    if majorant <= 0.0 || (nan_guard && majorant.is_nan()) {
        return FreeFlight::Escape;
    }
    let reused = (sampler.next_1d(), sampler.next_1d());
    let mut t = 0.0f32;
    let steps = match flaw {
        TrackingFlaw::OneStepShort => max_steps.saturating_sub(1),
        TrackingFlaw::OneStepTooMany => max_steps.saturating_add(1),
        _ => max_steps,
    };
    for _ in 0..steps {
        let (u0, u1) = if flaw == TrackingFlaw::ReusedRandomNumbers {
            reused
        } else {
            (sampler.next_1d(), sampler.next_1d())
        };
        t -= (1.0 - u0).ln() / majorant;
        if t >= t_max {
            return if flaw == TrackingFlaw::EscapeAsAbsorption {
                FreeFlight::Absorb { t: t_max }
            } else {
                FreeFlight::Escape
            };
        }
        let c = medium.coefficients(if flaw == TrackingFlaw::RayFromOrigin {
            ray.dir * t
        } else {
            ray.at(t)
        });
        let scale = if flaw == TrackingFlaw::NoNullCollisions {
            c.sigma_t()
        } else {
            majorant
        };
        let xi = u1 * scale;
        if xi < c.sigma_a {
            return FreeFlight::Absorb { t };
        }
        if xi < c.sigma_a + c.sigma_s {
            return FreeFlight::Scatter { t };
        }
    }
    match flaw {
        TrackingFlaw::ExhaustedAsEscape => FreeFlight::Escape,
        TrackingFlaw::ExhaustedAsAbsorption => FreeFlight::Absorb { t },
        _ => FreeFlight::Exhausted,
    }
}

/// The catalogue.
pub fn catalogue() -> Vec<Variant> {
    use TaskId::*;
    vec![
        wrong(
            "the sheet's recursion: no light after the camera hit",
            PathTrace,
            |p| {
                p.path_trace = Some(|t, s, seg, d, sa| {
                    path_variant(t, s, seg, d, sa, PathFlaw::NoLightAfterCamera)
                })
            },
        ),
        wrong("Russian roulette without dividing by q", PathTrace, |p| {
            p.path_trace = Some(|t, s, seg, d, sa| {
                path_variant(t, s, seg, d, sa, PathFlaw::RouletteWithoutDivision)
            })
        }),
        wrong("emission counted twice", PathTrace, |p| {
            p.path_trace =
                Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::EmissionTwice))
        }),
        wrong("the sky added again after an escape", PathTrace, |p| {
            p.path_trace =
                Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::SkyTwice))
        }),
        wrong("a survival probability not capped at 1", PathTrace, |p| {
            p.path_trace =
                Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::UncappedSurvival))
        }),
        wrong("the roulette test inverted", PathTrace, |p| {
            p.path_trace =
                Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::InvertedRoulette))
        }),
        wrong("the sheet's G without the cosine at the light", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::MissingLightCosine)
            })
        }),
        wrong("the sheet's inverted visibility test", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| mis_variant(t, s, h, wo, he, sa, MisFlaw::NoShadows))
        }),
        wrong("the sheet's mixed pdf measures in the weights", Mis, |p| {
            p.mis =
                Some(|t, s, h, wo, he, sa| mis_variant(t, s, h, wo, he, sa, MisFlaw::MixedMeasures))
        }),
        wrong(
            "the light's pdf converted with the cosine at the shading point",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::CosineAtShadingPoint)
                })
            },
        ),
        wrong("an environment sample without its MIS weight", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::UnweightedSkySample)
            })
        }),
        wrong("point-light samples dropped", Mis, |p| {
            p.mis =
                Some(|t, s, h, wo, he, sa| mis_variant(t, s, h, wo, he, sa, MisFlaw::NoPointLights))
        }),
        wrong(
            "weights p_a / (p_a − p_b): they sum to one, but are not the balance heuristic",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::DifferenceWeights)
                })
            },
        ),
        wrong("the light sample's radiance left out", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::LightRadianceIgnored)
            })
        }),
        wrong(
            "the point light's direction taken from the origin",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::PointLightFromOrigin)
                })
            },
        ),
        wrong("a point light at distance 0 divides 0 by 0", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::UnguardedPointLight)
            })
        }),
        wrong(
            "an environment sample never tested for occlusion",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::UnoccludedSky)
                })
            },
        ),
        wrong("`depth == 0` as the only stop", PathTrace, |p| {
            p.path_trace = Some(|t, s, seg, d, sa| {
                path_variant(t, s, seg, d, sa, PathFlaw::OnlyDepthZeroStops)
            })
        }),
        wrong("survival from the smallest channel", PathTrace, |p| {
            p.path_trace = Some(|t, s, seg, d, sa| {
                path_variant(t, s, seg, d, sa, PathFlaw::SurvivalFromSmallestChannel)
            })
        }),
        wrong("a scalar throughput", PathTrace, |p| {
            p.path_trace =
                Some(|t, s, seg, d, sa| path_variant(t, s, seg, d, sa, PathFlaw::ScalarThroughput))
        }),
        wrong("black where mis gives no bounce", PathTrace, |p| {
            p.path_trace = Some(|t, s, seg, d, sa| {
                path_variant(t, s, seg, d, sa, PathFlaw::BlackWithoutBounce)
            })
        }),
        wrong(
            "the Lambertian density in the light sample's weight",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::LambertianPdfInWeight)
                })
            },
        ),
        wrong(
            "the Lambertian density in the BSDF sample's weight",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::LambertianPdfInBsdfWeight)
                })
            },
        ),
        wrong("point lights skipped under BSDF weights", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::NoPointLightsUnderBsdfWeights)
            })
        }),
        wrong("area lights taken as two-sided", Mis, |p| {
            p.mis = Some(|t, s, h, wo, he, sa| {
                mis_variant(t, s, h, wo, he, sa, MisFlaw::TwoSidedLights)
            })
        }),
        wrong(
            "the bounce returned with its emission not counted",
            Mis,
            |p| {
                p.mis = Some(|t, s, h, wo, he, sa| {
                    mis_variant(t, s, h, wo, he, sa, MisFlaw::BounceEmissionNotCounted)
                })
            },
        ),
        wrong(
            "the medium looked up as if the ray started at the origin",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::RayFromOrigin)
                })
            },
        ),
        wrong(
            "one tentative collision fewer than allowed",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::OneStepShort)
                })
            },
        ),
        wrong(
            "one tentative collision more than allowed",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::OneStepTooMany)
                })
            },
        ),
        wrong(
            "a walk out of steps reported as an absorption",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::ExhaustedAsAbsorption)
                })
            },
        ),
        wrong("the sheet's reused random numbers", DeltaTracking, |p| {
            p.delta_tracking = Some(|m, r, tm, n, s| {
                tracking_variant(m, r, tm, n, s, TrackingFlaw::ReusedRandomNumbers)
            })
        }),
        wrong(
            "the sheet's escape reported as absorption",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::EscapeAsAbsorption)
                })
            },
        ),
        wrong("every tentative collision is real", DeltaTracking, |p| {
            p.delta_tracking = Some(|m, r, tm, n, s| {
                tracking_variant(m, r, tm, n, s, TrackingFlaw::NoNullCollisions)
            })
        }),
        wrong("a NaN majorant is not guarded", DeltaTracking, |p| {
            p.delta_tracking = Some(|m, r, tm, n, s| {
                tracking_variant(m, r, tm, n, s, TrackingFlaw::UnguardedNanMajorant)
            })
        }),
        wrong(
            "a walk out of steps reported as an escape",
            DeltaTracking,
            |p| {
                p.delta_tracking = Some(|m, r, tm, n, s| {
                    tracking_variant(m, r, tm, n, s, TrackingFlaw::ExhaustedAsEscape)
                })
            },
        ),
    ]
}
