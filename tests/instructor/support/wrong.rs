//! Known-wrong implementations: the errata's traps and common slips, one task each. Every
//! one must fail its own task and no other.

use super::patch::{Variant, variant as wrong};
use glam::{Vec2, Vec3};
use pbrlab::bsdf::PlausibilityReport;
use pbrlab::optics::schlick_weight;
use pbrlab::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;
use std::f32::consts::{FRAC_1_PI, PI};

/// GGX D in Cartesian form with free roughnesses (for slips in other tasks).
fn ggx(h: Vec3, ax: f32, ay: f32) -> f32 {
    sol::aniso_ndf::aniso_ndf(h, ax, ay)
}

/// The catalogue: the closed-form tasks here, the integrator tasks in
/// [`super::wrong_integrators`].
pub fn catalogue() -> Vec<Variant> {
    let mut all = closed_form();
    all.extend(super::wrong_integrators::catalogue());
    all
}

fn closed_form() -> Vec<Variant> {
    use TaskId::*;
    vec![
        // reflect
        wrong(
            "§1.1 formula in the away convention (sign flipped)",
            Reflect,
            |p| p.reflect = Some(|wo, n| wo - 2.0 * wo.dot(n) * n),
        ),
        wrong("normal not normalised", Reflect, |p| {
            p.reflect = Some(|wo, n| 2.0 * wo.dot(n) * n - wo)
        }),
        // refract_stack
        wrong("no total internal reflection", RefractStack, |p| {
            p.refract = Some(|wi, n, eta_i, eta_t| {
                let (wi, n) = (wi.normalize(), n.normalize());
                let eta = eta_i / eta_t;
                let c = wi.dot(n);
                let cos_t = (1.0 - eta * eta * (1.0 - c * c)).sqrt();
                Some(-eta * wi + (eta * c - cos_t) * n)
            })
        }),
        wrong(
            "critical angle without the eta_i > eta_t guard",
            RefractStack,
            |p| p.critical_angle = Some(|eta_i, eta_t| Some((eta_t / eta_i).asin())),
        ),
        wrong(
            "lateral shift taken as d tan θ (the worksheet)",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta, stack| {
                    let mut r = sol::refract_stack::refract_stack(t, theta, stack);
                    r.perpendicular_shift = r.interface_offset.clone();
                    r
                })
            },
        ),
        wrong(
            "transmitted intensity ignores the last interface",
            RefractStack,
            |p| {
                p.refract_stack = Some(|t, theta, stack| {
                    let mut r = sol::refract_stack::refract_stack(t, theta, stack);
                    if r.tir_at.is_none() {
                        let last = *r.reflectance_exact.last().unwrap_or(&0.0);
                        r.transmitted_exact /= 1.0 - last;
                    }
                    r
                })
            },
        ),
        // fresnel_schlick
        wrong(
            "Schlick with cos θi from dense to less dense",
            FresnelSchlick,
            |p| {
                p.fresnel_schlick = Some(|t, cos, eta_i, eta_t| {
                    let r0 = t.schlick_r0(eta_i, eta_t);
                    r0 + (1.0 - r0) * schlick_weight(cos)
                })
            },
        ),
        wrong("no special case for equal indices", FresnelSchlick, |p| {
            p.fresnel_schlick = Some(|t, cos, eta_i, eta_t| {
                if eta_i == eta_t {
                    return schlick_weight(cos);
                }
                sol::fresnel_schlick::fresnel_schlick(t, cos, eta_i, eta_t)
            })
        }),
        wrong("R0 not squared", FresnelSchlick, |p| {
            p.schlick_r0 = Some(|a, b| ((a - b) / (a + b)).abs())
        }),
        // cosine_sample
        wrong("uniform samples with the cosine pdf", CosineSample, |p| {
            p.cosine_sample = Some(uniform_hemisphere)
        }),
        wrong("cosine samples with the uniform pdf", CosineSample, |p| {
            p.cosine_pdf = Some(|w| {
                if w.z > 0.0 {
                    uniform_hemisphere_pdf()
                } else {
                    0.0
                }
            })
        }),
        wrong("pdf missing 1/π", CosineSample, |p| {
            p.cosine_pdf = Some(|w| w.z.max(0.0))
        }),
        wrong("the sheet's cos θ = sqrt(1 − π u)", CosineSample, |p| {
            p.cosine_sample = Some(|u| {
                let c = (1.0 - PI * u.y).sqrt();
                let s = (1.0 - c * c).max(0.0).sqrt();
                let phi = 2.0 * PI * u.x;
                Vec3::new(s * phi.cos(), s * phi.sin(), c)
            })
        }),
        wrong(
            "cos θ = u (the density of cos θ is not uniform)",
            CosineSample,
            |p| {
                p.cosine_sample = Some(|u| {
                    let c = u.y;
                    let s = (1.0 - c * c).max(0.0).sqrt();
                    let phi = 2.0 * PI * u.x;
                    Vec3::new(s * phi.cos(), s * phi.sin(), c)
                })
            },
        ),
        // smith_g1
        wrong("G1 negative for back-facing directions", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                let c = w.z;
                2.0 * c / (c + (alpha * alpha * (1.0 - c * c) + c * c).sqrt())
            })
        }),
        wrong("Λ without the 1/2", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                if w.z <= 0.0 {
                    return 0.0;
                }
                let tan2 = (1.0 - w.z * w.z) / (w.z * w.z);
                1.0 / (1.0 + (-1.0 + (1.0 + alpha * alpha * tan2).sqrt()))
            })
        }),
        // cook_torrance
        wrong("missing factor 4", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                sol::cook_torrance::cook_torrance(t, wo, wi, ax, ay, f0) * 4.0
            })
        }),
        wrong("G = 1 (no masking)", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let h = (wo + wi).normalize();
                let f = f0 + (Vec3::ONE - f0) * schlick_weight(wo.dot(h));
                f * t.aniso_ndf(h, ax, ay) / (4.0 * wo.z * wi.z)
            })
        }),
        wrong("swapped anisotropic roughnesses", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                sol::cook_torrance::cook_torrance(t, wo, wi, ay, ax, f0)
            })
        }),
        wrong("Fresnel of cos θo instead of wo·h", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                let base = sol::cook_torrance::cook_torrance(t, wo, wi, ax, ay, Vec3::ONE);
                base * (f0 + (Vec3::ONE - f0) * schlick_weight(wo.z))
            })
        }),
        // aniso_ndf
        wrong("swapped anisotropic roughnesses", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(h, ay, ax))
        }),
        wrong("missing 1/π", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(h, ax, ay) * PI)
        }),
        wrong("isotropic: αx for both directions", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, _| ggx(h, ax, ax))
        }),
        wrong("no zero below the horizon", AnisoNdf, |p| {
            p.aniso_ndf = Some(|h, ax, ay| ggx(Vec3::new(h.x, h.y, h.z.abs()), ax, ay))
        }),
        wrong(
            "`h.z < 0` for the horizon: h in the surface is not 0",
            AnisoNdf,
            |p| {
                p.aniso_ndf = Some(|h, ax, ay| {
                    if h.z == 0.0 {
                        // The formula itself at hz = 0.
                        let (x, y) = (h.x / ax, h.y / ay);
                        1.0 / (PI * ax * ay * (x * x + y * y).powi(2))
                    } else {
                        ggx(h, ax, ay)
                    }
                })
            },
        ),
        // phong
        wrong("NaN-prone pow of a negative cosine", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let r = t.reflect(wi, Vec3::Z);
                let lobe = r.dot(wo).powf(params.exponent);
                params.kd * FRAC_1_PI
                    + params.ks * ((params.exponent + 2.0) * 0.5 * FRAC_1_PI * lobe)
            })
        }),
        wrong("normalisation (n+1)/(2π)", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                let mut q = *params;
                q.ks *= (params.exponent + 1.0) / (params.exponent + 2.0);
                sol::phong::phong(t, wo, wi, &q)
            })
        }),
        wrong("Phong shading model (divides by cos θi)", Phong, |p| {
            p.phong = Some(|t, wo, wi, params| {
                let mut q = *params;
                q.kd = Vec3::ZERO;
                let lobe = sol::phong::phong(t, wo, wi, &q) / wi.z.max(1e-6);
                params.kd * FRAC_1_PI + lobe
            })
        }),
        wrong(
            "reciprocity gap without the relative scale, averaged",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    let mut sum = 0.0;
                    for _ in 0..pairs {
                        let a = uniform_hemisphere(sampler.next_2d());
                        let b = uniform_hemisphere(sampler.next_2d());
                        sum += (brdf(a, b) - brdf(b, a)).abs() * 1e-3;
                    }
                    sum / pairs.max(1) as f32
                })
            },
        ),
        wrong("reciprocity gap whose f32::max skips NaN", Phong, |p| {
            p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                    if f_ab == f_ba {
                        0.0
                    } else {
                        (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                    }
                })
            })
        }),
        wrong(
            "reciprocity gap that skips a pair NaN in one order only",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if f_ab.is_nan() && f_ba.is_nan() {
                            f32::INFINITY
                        } else if f_ab == f_ba {
                            0.0
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                        }
                    })
                })
            },
        ),
        wrong(
            "reciprocity gap that calls two equal infinities reciprocal",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if f_ab == f_ba {
                            0.0
                        } else if !(f_ab.is_finite() && f_ba.is_finite()) {
                            f32::INFINITY
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().max(f_ba.abs())
                        }
                    })
                })
            },
        ),
        wrong(
            "reciprocity gap relative to the smaller value",
            Phong,
            |p| {
                p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                    largest_pair_gap(brdf, sampler, pairs, |f_ab, f_ba| {
                        if !(f_ab.is_finite() && f_ba.is_finite()) {
                            f32::INFINITY
                        } else if f_ab == f_ba {
                            0.0
                        } else {
                            (f_ab - f_ba).abs() / f_ab.abs().min(f_ba.abs())
                        }
                    })
                })
            },
        ),
        wrong("absolute reciprocity gap", Phong, |p| {
            p.reciprocity_gap = Some(|brdf, sampler, pairs| {
                let mut gap = 0.0f32;
                for _ in 0..pairs {
                    let a = uniform_hemisphere(sampler.next_2d());
                    let b = uniform_hemisphere(sampler.next_2d());
                    let d = (brdf(a, b) - brdf(b, a)).abs();
                    gap = if d.is_nan() { d } else { gap.max(d) };
                }
                gap
            })
        }),
        // kajiya_kay
        wrong(
            "the worksheet's form (÷ sin θi sin θo, sin^p θh)",
            KajiyaKay,
            |p| {
                p.kajiya_kay = Some(|wo, wi, t, params| {
                    let (ci, co) = (t.dot(wi), t.dot(wo));
                    let (si, so) = ((1.0 - ci * ci).sqrt(), (1.0 - co * co).sqrt());
                    let h = (wo + wi).normalize();
                    let ch = t.dot(h);
                    let sh = (1.0 - ch * ch).max(0.0).sqrt();
                    params.kd + params.ks * (wi.dot(wo) / (si * so)) * sh.powf(params.exponent)
                })
            },
        ),
        wrong(
            "KK89 with the eye-ray sign (cos cos + sin sin)",
            KajiyaKay,
            |p| {
                p.kajiya_kay = Some(|wo, wi, t, params| {
                    let (ci, co) = (t.dot(wi).clamp(-1.0, 1.0), t.dot(wo).clamp(-1.0, 1.0));
                    let (si, so) = ((1.0 - ci * ci).sqrt(), (1.0 - co * co).sqrt());
                    params.kd * si + params.ks * (si * so + ci * co).max(0.0).powf(params.exponent)
                })
            },
        ),
        wrong("cone cosine not clamped before powf", KajiyaKay, |p| {
            p.kajiya_kay = Some(|wo, wi, t, params| {
                let (ci, co) = (t.dot(wi).clamp(-1.0, 1.0), t.dot(wo).clamp(-1.0, 1.0));
                let (si, so) = ((1.0 - ci * ci).sqrt(), (1.0 - co * co).sqrt());
                params.kd * si + params.ks * (si * so - ci * co).powf(params.exponent)
            })
        }),
        // beckmann_ndf
        wrong("missing cos⁴θh", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                let tan2 = (1.0 - h.z * h.z) / (h.z * h.z);
                (-tan2 / (alpha * alpha)).exp() * FRAC_1_PI / (alpha * alpha)
            })
        }),
        wrong("0 · ∞ at grazing", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                let c2 = h.z * h.z;
                let tan2 = (1.0 - c2) / c2;
                (-tan2 / (alpha * alpha)).exp() * FRAC_1_PI / (alpha * alpha * c2 * c2)
            })
        }),
        wrong("α instead of α² in the exponent", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                let c2 = h.z * h.z;
                let tan2 = (1.0 - c2) / c2;
                (-tan2 / alpha).exp() * FRAC_1_PI / (alpha * alpha * c2 * c2)
            })
        }),
        // ndf_sample
        wrong("pdf without the 1/(4 wo·h) Jacobian", NdfSample, |p| {
            p.ndf_pdf = Some(|t, wo, wi, ax, ay| {
                let h = (wo + wi).normalize();
                if wi.z <= 0.0 || h.z <= 0.0 {
                    return 0.0;
                }
                t.aniso_ndf(h, ax, ay) * h.z
            })
        }),
        wrong("pdf without cos θh", NdfSample, |p| {
            p.ndf_pdf = Some(|t, wo, wi, ax, ay| {
                sol::ndf_sample::ndf_pdf(t, wo, wi, ax, ay) / (wo + wi).normalize().z
            })
        }),
        wrong("half vectors with swapped roughnesses", NdfSample, |p| {
            p.ndf_sample = Some(|t, wo, ax, ay, u| sol::ndf_sample::ndf_sample(t, wo, ay, ax, u))
        }),
        wrong("wi below the surface not rejected", NdfSample, |p| {
            p.ndf_sample = Some(|t, wo, ax, ay, u: Vec2| {
                let h = Vec3::new(
                    ax * u.x.sqrt() * (2.0 * PI * u.y).cos(),
                    ay * u.x.sqrt() * (2.0 * PI * u.y).sin(),
                    (1.0 - u.x).sqrt(),
                )
                .normalize();
                Some(t.reflect(wo, h))
            })
        }),
        // brdf_check
        wrong("energy tested at normal incidence only", BrdfCheck, |p| {
            p.brdf_check =
                Some(|t, brdf, sampler, samples| albedo_check(t, brdf, sampler, samples, &[0.0]))
        }),
        wrong("albedo without 1/pdf", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.max_albedo *= uniform_hemisphere_pdf();
                r
            })
        }),
        wrong("f32::min and max that skip NaN", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                if r.min_value.is_nan() {
                    r.min_value = 0.5 * FRAC_1_PI;
                }
                if r.max_albedo.is_nan() {
                    r.max_albedo = 0.5;
                }
                r
            })
        }),
        wrong("energy tested up to 85° only", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                albedo_check(t, brdf, sampler, samples, &[0.0, 30.0, 60.0, 75.0, 85.0])
            })
        }),
        wrong("worst_wi pointing into the surface", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.worst_wi = -r.worst_wi;
                r
            })
        }),
        wrong(
            "worst_wi the last direction tried, not the worst",
            BrdfCheck,
            |p| {
                p.brdf_check = Some(|t, brdf, sampler, samples| {
                    let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                    r.worst_wi =
                        Vec3::new(89.9f32.to_radians().sin(), 0.0, 89.9f32.to_radians().cos());
                    r
                })
            },
        ),
        wrong("positivity of |f|", BrdfCheck, |p| {
            p.brdf_check = Some(|t, brdf, sampler, samples| {
                let mut r = sol::brdf_check::brdf_check(t, brdf, sampler, samples);
                r.min_value = r.min_value.abs();
                r
            })
        }),
    ]
}

/// A plausibility check whose albedo only looks at the incident angles `theta_deg`.
fn albedo_check(
    t: &impl Tasks,
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    samples: usize,
    theta_deg: &[f32],
) -> PlausibilityReport {
    let mut report = PlausibilityReport {
        min_value: f32::INFINITY,
        max_reciprocity_error: t.reciprocity_gap(brdf, sampler, samples),
        max_albedo: 0.0,
        worst_wi: Vec3::Z,
    };
    for &deg in theta_deg {
        let (s, c) = deg.to_radians().sin_cos();
        let wi = Vec3::new(s, 0.0, c);
        let mut sum = 0.0;
        for _ in 0..samples {
            let wo = uniform_hemisphere(sampler.next_2d());
            let f = brdf(wi, wo);
            report.min_value = report.min_value.min(f);
            sum += f * wo.z / uniform_hemisphere_pdf();
        }
        let albedo = sum / samples.max(1) as f32;
        if albedo > report.max_albedo {
            report.max_albedo = albedo;
            report.worst_wi = wi;
        }
    }
    report
}

/// The largest `pair_gap(f(a,b), f(b,a))` over `pairs` pairs drawn as the exercise says, by
/// `f32::max` (which skips NaN).
fn largest_pair_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut Sampler,
    pairs: usize,
    pair_gap: impl Fn(f32, f32) -> f32,
) -> f32 {
    (0..pairs).fold(0.0f32, |gap, _| {
        let a = uniform_hemisphere(sampler.next_2d());
        let b = uniform_hemisphere(sampler.next_2d());
        gap.max(pair_gap(brdf(a, b), brdf(b, a)))
    })
}
