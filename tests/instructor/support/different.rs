//! Correct implementations written differently from the reference: another sampling
//! mapping, another use of the random numbers, another algebraic form. Every one must pass
//! every task.

use super::patch::{Patch, Variant, variant as different};
use glam::{Vec2, Vec3};
use pbrlab::bsdf::PlausibilityReport;
use pbrlab::geometry::Ray;
use pbrlab::integrator::Segment;
use pbrlab::medium::{FreeFlight, Medium};
use pbrlab::optics::{StackReport, fresnel_dielectric_f64};
use pbrlab::sampling::Sampler;
use pbrlab::scene::Scene;
use pbrlab::worksheet::{TaskId, Tasks};
use std::f32::consts::{FRAC_1_PI, PI, TAU};

/// Shirley-Chiu concentric map of the unit square onto the unit disk.
fn concentric_disk(u: Vec2) -> Vec2 {
    let o = 2.0 * u - Vec2::ONE;
    if o == Vec2::ZERO {
        return Vec2::ZERO;
    }
    let (r, theta) = if o.x.abs() > o.y.abs() {
        (o.x, PI / 4.0 * (o.y / o.x))
    } else {
        (o.y, PI / 2.0 - PI / 4.0 * (o.x / o.y))
    };
    r * Vec2::new(theta.cos(), theta.sin())
}

/// The catalogue.
pub fn catalogue() -> Vec<Variant> {
    use TaskId::*;
    vec![
        different("reflect with a normalised normal", Reflect, |p| {
            p.reflect = Some(|wo, n| {
                let n = n.normalize();
                2.0 * wo.dot(n) * n - wo
            })
        }),
        different(
            "refraction by angles (asin, then rotate)",
            RefractStack,
            |p| {
                p.refract = Some(|wi, n, eta_i, eta_t| {
                    let (wi, n) = (wi.normalize(), n.normalize());
                    let cos_i = wi.dot(n).clamp(-1.0, 1.0);
                    let sin_t = eta_i / eta_t * (1.0 - cos_i * cos_i).max(0.0).sqrt();
                    if sin_t >= 1.0 {
                        return None;
                    }
                    let tangent = wi - cos_i * n;
                    let tangent = if tangent.length_squared() > 0.0 {
                        tangent.normalize()
                    } else {
                        Vec3::ZERO
                    };
                    let theta_t = sin_t.asin();
                    Some((-tangent * theta_t.sin() - n * theta_t.cos()).normalize())
                })
            },
        ),
        different(
            "layer stack interface by interface (Snell step by step)",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta_deg, stack| {
                    let etas = stack.etas();
                    let mut r = StackReport {
                        theta: vec![theta_deg],
                        ..StackReport::default()
                    };
                    let (mut i_s, mut i_e) = (stack.intensity, stack.intensity);
                    for k in 0..etas.len() - 1 {
                        let theta_in = r.theta[k].to_radians();
                        let sin_t = etas[k] / etas[k + 1] * theta_in.sin();
                        let cos_in = theta_in.cos();
                        let rs =
                            t.fresnel_schlick(cos_in as f32, etas[k] as f32, etas[k + 1] as f32)
                                as f64;
                        r.reflectance_schlick.push(rs);
                        r.reflectance_exact.push(fresnel_dielectric_f64(
                            cos_in,
                            etas[k],
                            etas[k + 1],
                        ));
                        if sin_t >= 1.0 {
                            r.tir_at = Some(k);
                            i_s = 0.0;
                            i_e = 0.0;
                            break;
                        }
                        i_s *= 1.0 - rs;
                        i_e *= 1.0 - r.reflectance_exact[k];
                        let theta_t = sin_t.asin();
                        r.theta.push(theta_t.to_degrees());
                        if k < stack.slabs.len() {
                            let d = stack.slabs[k].thickness;
                            r.perpendicular_shift
                                .push(d * (theta_in - theta_t).sin() / theta_t.cos());
                            r.interface_offset.push(d * theta_t.tan());
                        }
                    }
                    r.transmitted_schlick = i_s;
                    r.transmitted_exact = i_e;
                    r
                })
            },
        ),
        different(
            "Schlick with powi(5) and an explicit TIR test on sin θt",
            FresnelSchlick,
            |p| {
                p.fresnel_schlick = Some(|t, cos, eta_i, eta_t| {
                    let r0 = t.schlick_r0(eta_i, eta_t);
                    if r0 == 0.0 {
                        return 0.0;
                    }
                    let cos = cos.clamp(0.0, 1.0);
                    let sin_t = eta_i / eta_t * (1.0 - cos * cos).sqrt();
                    if sin_t >= 1.0 {
                        return 1.0;
                    }
                    let c = if eta_i > eta_t {
                        (1.0 - sin_t * sin_t).sqrt()
                    } else {
                        cos
                    };
                    r0 + (1.0 - r0) * (1.0 - c).powi(5)
                })
            },
        ),
        different(
            "Malley's method on the concentric disk",
            CosineSample,
            |p| {
                p.cosine_sample = Some(|u| {
                    let d = concentric_disk(u);
                    // u = 0 maps onto the rim: keep cos θ (and the pdf) above 0 there.
                    Vec3::new(
                        d.x,
                        d.y,
                        (1.0 - d.length_squared()).max(f32::EPSILON).sqrt(),
                    )
                })
            },
        ),
        different(
            "cos θ = sqrt(1 − u.x), φ from u.y (other random-number order)",
            CosineSample,
            |p| {
                p.cosine_sample = Some(|u| {
                    let c = (1.0 - u.x).sqrt();
                    let s = u.x.sqrt();
                    let phi = TAU * u.y;
                    Vec3::new(s * phi.cos(), s * phi.sin(), c)
                })
            },
        ),
        different(
            "G1 in the tangent form 1/(1 + Λ) with a stable Λ",
            SmithG1,
            |p| {
                p.smith_g1 = Some(|w, alpha| {
                    if w.z <= 0.0 {
                        return 0.0;
                    }
                    let c2 = (w.z * w.z).min(1.0);
                    let a = alpha * alpha * (1.0 - c2) / c2;
                    let lambda = a / (2.0 * (1.0 + (1.0 + a).sqrt()));
                    1.0 / (1.0 + lambda)
                })
            },
        ),
        different(
            "Cook-Torrance with G1(wi) and a half vector from normalize",
            CookTorrance,
            |p| {
                p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                    if wo.z <= 0.0 || wi.z <= 0.0 {
                        return Vec3::ZERO;
                    }
                    let h = (wi + wo).normalize();
                    let proj = |w: Vec3| {
                        let r2 = w.x * w.x + w.y * w.y;
                        if r2 == 0.0 {
                            ax
                        } else {
                            ((w.x * w.x * ax * ax + w.y * w.y * ay * ay) / r2).sqrt()
                        }
                    };
                    let g = t.smith_g1(wi, proj(wi)) * t.smith_g1(wo, proj(wo));
                    let f = f0 + (Vec3::ONE - f0) * (1.0 - wi.dot(h)).clamp(0.0, 1.0).powi(5);
                    t.aniso_ndf(h, ax, ay) * g * f / (4.0 * wi.z * wo.z)
                })
            },
        ),
        different("anisotropic GGX in the polar form", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                // α = 0 is a mirror, which no density represents: keep a tall finite peak.
                let (ax, ay) = (ax.max(1e-4), ay.max(1e-4));
                let c2 = h.z * h.z;
                let s2 = (1.0 - c2).max(0.0);
                let tan2 = s2 / c2;
                let (cos2_phi, sin2_phi) = if s2 == 0.0 {
                    (1.0, 0.0)
                } else {
                    (h.x * h.x / s2, h.y * h.y / s2)
                };
                let e = tan2 * (cos2_phi / (ax * ax) + sin2_phi / (ay * ay));
                1.0 / (PI * ax * ay * c2 * c2 * (1.0 + e) * (1.0 + e))
            })
        }),
        different(
            "Phong with the mirror computed inline and a cosine-sampled reciprocity test",
            Phong,
            |p| {
                p.phong = Some(|_, wo, wi, params| {
                    if wo.z <= 0.0 || wi.z <= 0.0 {
                        return Vec3::ZERO;
                    }
                    let r = Vec3::new(-wi.x, -wi.y, wi.z);
                    let c = r.dot(wo);
                    let lobe = if c > 0.0 {
                        c.powf(params.exponent)
                    } else {
                        0.0
                    };
                    params.kd / PI + params.ks * (params.exponent + 2.0) / TAU * lobe
                });
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    let mut gap = 0.0f32;
                    for _ in 0..pairs {
                        let a = cosine_direction(sampler.next_2d());
                        let b = cosine_direction(sampler.next_2d());
                        let (x, y) = (brdf(a, b), brdf(b, a));
                        let scale = x.abs().max(y.abs());
                        if !(x.is_finite() && y.is_finite()) {
                            return f32::INFINITY;
                        }
                        if scale > 0.0 {
                            gap = gap.max((x - y).abs() / scale);
                        }
                    }
                    gap
                });
            },
        ),
        different(
            "Kajiya-Kay by angles: cos(π − θi − θo)",
            KajiyaKay,
            |p| {
                p.kajiya_kay = Some(|wo, wi, t, params| {
                    let theta_i = t.dot(wi).clamp(-1.0, 1.0).acos();
                    let theta_o = t.dot(wo).clamp(-1.0, 1.0).acos();
                    let cone = (PI - theta_i - theta_o).cos().max(0.0);
                    params.kd * theta_i.sin() + params.ks * cone.powf(params.exponent)
                })
            },
        ),
        different(
            "Beckmann via cos⁴ and exp of (c² − 1)/(α² c²)",
            BeckmannNdf,
            |p| {
                p.beckmann_ndf = Some(|h, alpha| {
                    let alpha = alpha.max(1e-4);
                    let c = h.z.min(1.0);
                    if c <= 1e-10 {
                        return 0.0;
                    }
                    let c2 = c * c;
                    ((c2 - 1.0) / (alpha * alpha * c2)).exp() / (PI * alpha * alpha * c2 * c2)
                })
            },
        ),
        different(
            "GGX sampling by θh = atan(α tan), other random-number order",
            NdfSample,
            |p| {
                p.ndf_sample = Some(|t, wo, ax, ay, u| {
                    // φ from u.x with the anisotropic stretch, θ from u.y.
                    let phi0 = TAU * u.x;
                    let phi = (ay / ax * phi0.tan()).atan()
                        + if phi0 > PI / 2.0 && phi0 <= 3.0 * PI / 2.0 {
                            PI
                        } else {
                            0.0
                        };
                    let (sp, cp) = phi.sin_cos();
                    let alpha2 = 1.0 / (cp * cp / (ax * ax) + sp * sp / (ay * ay));
                    let tan2 = alpha2 * u.y / (1.0 - u.y);
                    let c = 1.0 / (1.0 + tan2).sqrt();
                    let s = (1.0 - c * c).max(0.0).sqrt();
                    mirror_above(t, wo, Vec3::new(s * cp, s * sp, c))
                })
            },
        ),
        different(
            "GGX sampling by stretching a concentric cosine sample",
            NdfSample,
            |p| {
                p.ndf_sample = Some(|t, wo, ax, ay, u| {
                    // (x, y, z) cosine-distributed is D·cos of GGX at α = 1; stretching the
                    // slopes by (αx, αy) gives D·cos at (αx, αy). The corners of the square
                    // land on the rim of the disk, where h is horizontal and wi is rejected.
                    let c = cosine_direction(u);
                    mirror_above(t, wo, Vec3::new(ax * c.x, ay * c.y, c.z).normalize())
                })
            },
        ),
        different(
            "a path traced in a loop, roulette on the path throughput (q capped at 1)",
            PathTrace,
            |p| {
                p.path_trace = Some(|t, scene, segment, depth, sampler| {
                    let (mut segment, mut depth) = (*segment, depth);
                    let (mut radiance, mut beta) = (Vec3::ZERO, Vec3::ONE);
                    while depth > 0 {
                        let counted = segment.emission_counted;
                        let Some(hit) = segment.hit else {
                            if !counted {
                                radiance += beta * scene.environment(segment.ray.dir);
                            }
                            break;
                        };
                        let wo = -segment.ray.dir;
                        if !counted {
                            radiance += beta * scene.emitted(&hit, wo);
                        }
                        if depth == 1 {
                            break;
                        }
                        let direct = t.mis(scene, &hit, wo, scene.heuristic(), sampler);
                        radiance += beta * direct.radiance;
                        let Some(bounce) = direct.bounce else {
                            break;
                        };
                        if depth == 2 {
                            break;
                        }
                        beta *= bounce.weight;
                        if scene.settings().roulette_applies(depth) {
                            let q = beta.max_element().min(1.0);
                            if q.is_nan() || q <= 0.0 || sampler.next_1d() >= q {
                                break;
                            }
                            beta /= q;
                        }
                        segment = bounce.segment;
                        depth -= 1;
                    }
                    radiance
                })
            },
        ),
        different(
            "plausibility with cosine-weighted albedo samples at its own angles",
            BrdfCheck,
            |p| p.brdf_check = Some(cosine_weighted_check),
        ),
        different(
            "roulette with a fixed q = 0.9 before the direct light, dividing both",
            PathTrace,
            |p| p.path_trace = Some(roulette_first),
        ),
        different(
            "delta tracking that counts a step only once it is inside the segment",
            DeltaTracking,
            |p| p.delta_tracking = Some(count_after_escape_test),
        ),
    ]
}

/// `path_trace` with Russian roulette at the start of a step (from depth 3 on), with a fixed
/// survival probability, dividing the direct light and the continuation alike.
fn roulette_first(
    t: &Patch,
    scene: &Scene,
    segment: &Segment,
    depth: i32,
    sampler: &mut Sampler,
) -> Vec3 {
    const Q: f32 = 0.9;
    if depth <= 0 {
        return Vec3::ZERO;
    }
    let Some(hit) = &segment.hit else {
        return if segment.emission_counted {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let emitted = if segment.emission_counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return emitted;
    }
    let mut scale = 1.0;
    if depth >= 3 && scene.settings().roulette_applies(depth) {
        if sampler.next_1d() >= Q {
            return emitted;
        }
        scale = 1.0 / Q;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    let mut rest = direct.radiance;
    if depth >= 3
        && let Some(b) = &direct.bounce
    {
        rest += b.weight * t.path_trace(scene, &b.segment, depth - 1, sampler);
    }
    emitted + rest * scale
}

/// Delta tracking that tests for an escape before it counts the step, so that it gives up
/// only when the step after `max_steps` null collisions lands inside the segment (the
/// other reading of "after `max_steps` tentative collisions"), and picks absorption or
/// scattering with a second random number.
fn count_after_escape_test(
    medium: &dyn Medium,
    ray: &Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut Sampler,
) -> FreeFlight {
    let majorant = medium.majorant();
    if majorant.is_nan() || majorant <= 0.0 {
        return FreeFlight::Escape;
    }
    let (mut t, mut taken) = (0.0f32, 0u32);
    loop {
        t -= (1.0 - sampler.next_1d()).ln() / majorant;
        if t >= t_max {
            return FreeFlight::Escape;
        }
        if taken >= max_steps {
            return FreeFlight::Exhausted;
        }
        taken += 1;
        let c = medium.coefficients(ray.at(t));
        let sigma_t = c.sigma_a + c.sigma_s;
        if sampler.next_1d() * majorant < sigma_t {
            return if sampler.next_1d() * sigma_t < c.sigma_a {
                FreeFlight::Absorb { t }
            } else {
                FreeFlight::Scatter { t }
            };
        }
    }
}

/// `wo` mirrored about the microfacet normal `h`, when `h` faces `wo` and the mirror
/// direction is above the surface.
fn mirror_above(t: &Patch, wo: Vec3, h: Vec3) -> Option<Vec3> {
    if !h.is_finite() || wo.dot(h) <= 0.0 {
        return None;
    }
    let wi = t.reflect(wo, h);
    (wi.z > 0.0).then_some(wi)
}

fn cosine_direction(u: Vec2) -> Vec3 {
    let d = concentric_disk(u);
    Vec3::new(d.x, d.y, (1.0 - d.length_squared()).max(0.0).sqrt())
}

fn cosine_weighted_check(
    t: &Patch,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        max_albedo: 0.0,
        worst_wi: Vec3::Z,
    };
    for deg in [0.0f32, 20.0, 40.0, 60.0, 80.0, 88.0, 89.5, 89.95] {
        let (s, c) = deg.to_radians().sin_cos();
        let wi = Vec3::new(0.0, s, c);
        let mut sum = 0.0f64;
        for _ in 0..samples {
            let wo = cosine_direction(sampler.next_2d());
            if wo.z <= 0.0 {
                continue;
            }
            let f = brdf(wi, wo);
            // A NaN reaches the report (f32::min would skip it).
            if f.is_nan() || f < report.min_value {
                report.min_value = f;
            }
            // f cos / (cos/π) = π f
            sum += (PI * f) as f64;
        }
        let albedo = (sum / samples as f64) as f32;
        if albedo.is_nan() || albedo > report.max_albedo {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    let _ = FRAC_1_PI;
    report
}
