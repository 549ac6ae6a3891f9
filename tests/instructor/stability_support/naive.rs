//! Deliberately naive versions of task functions: the worksheet's textbook formulas
//! without the guards. Each is the kind of code a student writes first.

use glam::Vec3;
use pbrlab::bsdf::{KajiyaKayParams, PhongParams};
use pbrlab::optics::{LayerStack, StackReport, fresnel_dielectric_f64};
use pbrlab::worksheet::Tasks;
use std::f32::consts::{FRAC_1_PI, PI};

/// No normalisation of n.
pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
    2.0 * wo.dot(n) * n - wo
}

/// Snell's law with no test for total internal reflection: the square root takes whatever
/// 1 − sin²θt comes out as.
pub fn refract(wi: Vec3, n: Vec3, eta_i: f32, eta_t: f32) -> Option<Vec3> {
    let n = n.normalize();
    let eta = eta_i / eta_t;
    let cos_i = wi.dot(n);
    let cos_t = (1.0 - eta * eta * (1.0 - cos_i * cos_i)).sqrt();
    Some(-eta * wi + (eta * cos_i - cos_t) * n)
}

/// asin of the ratio, whatever the ratio.
pub fn critical_angle(eta_i: f64, eta_t: f64) -> Option<f64> {
    Some((eta_t / eta_i).asin())
}

/// The stack followed with Snell's law and no test for total internal reflection.
pub fn refract_stack(t: &impl Tasks, theta_deg: f64, stack: &LayerStack) -> StackReport {
    let etas = stack.etas();
    let invariant = etas[0] * theta_deg.to_radians().sin();
    let mut r = StackReport {
        theta: vec![theta_deg],
        ..StackReport::default()
    };
    let (mut schlick, mut exact) = (stack.intensity, stack.intensity);
    for k in 0..stack.interfaces() {
        let sin_t = invariant / etas[k + 1];
        let cos_t = (1.0 - sin_t * sin_t).sqrt();
        let cos_i = r.theta[k].to_radians().cos();
        let rs = t.fresnel_schlick(cos_i as f32, etas[k] as f32, etas[k + 1] as f32) as f64;
        let re = fresnel_dielectric_f64(cos_i, etas[k], etas[k + 1]);
        r.reflectance_schlick.push(rs);
        r.reflectance_exact.push(re);
        schlick *= 1.0 - rs;
        exact *= 1.0 - re;
        let theta_t = cos_t.acos();
        if let Some(slab) = stack.slabs.get(k) {
            let theta_in = r.theta[k].to_radians();
            r.perpendicular_shift
                .push(slab.thickness * (theta_in - theta_t).sin() / cos_t);
            r.interface_offset.push(slab.thickness * theta_t.tan());
        }
        r.theta.push(theta_t.to_degrees());
    }
    r.transmitted_schlick = schlick;
    r.transmitted_exact = exact;
    r
}

/// Schlick's curve on cos θi with R0, for every pair of indices.
pub fn fresnel_schlick_r0_everywhere(
    t: &impl Tasks,
    cos_theta_i: f32,
    eta_i: f32,
    eta_t: f32,
) -> f32 {
    let r0 = t.schlick_r0(eta_i, eta_t);
    r0 + (1.0 - r0) * (1.0 - cos_theta_i).powi(5)
}

/// Schlick's curve on cos θt from dense to less dense, with cos θt from an unclamped
/// square root and no test for total internal reflection.
pub fn fresnel_schlick_unguarded(t: &impl Tasks, cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    if eta_i == eta_t {
        return 0.0;
    }
    let r0 = t.schlick_r0(eta_i, eta_t);
    let mut cos = cos_theta_i;
    if eta_i > eta_t {
        cos = (1.0 - (eta_i / eta_t).powi(2) * (1.0 - cos * cos)).sqrt();
    }
    r0 + (1.0 - r0) * (1.0 - cos).powi(5)
}

/// w.z / π everywhere.
pub fn cosine_pdf(w: Vec3) -> f32 {
    w.z * FRAC_1_PI
}

/// The cosine form of G1 without the χ⁺ factor.
pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
    let (c, a2) = (w.z, alpha * alpha);
    2.0 * c / (c + (a2 + (1.0 - a2) * c * c).sqrt())
}

/// The half vector normalised before any test, and no horizon test.
pub fn cook_torrance(
    t: &impl Tasks,
    wo: Vec3,
    wi: Vec3,
    alpha_x: f32,
    alpha_y: f32,
    f0: Vec3,
) -> Vec3 {
    let h = (wo + wi).normalize();
    let d = t.aniso_ndf(h, alpha_x, alpha_y);
    let g = t.smith_g1(wo, alpha_x) * t.smith_g1(wi, alpha_y);
    let f = f0 + (Vec3::ONE - f0) * (1.0 - wo.dot(h)).powi(5);
    f * (d * g / (4.0 * wo.z * wi.z))
}

/// The common isotropic GGX form α²/(π((α² − 1)cos²θ + 1)²), which cancels in f32, with no
/// test for h below the surface.
pub fn aniso_ndf(h: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    let a2 = alpha_x * alpha_y;
    let c2 = h.z * h.z;
    a2 / (PI * ((a2 - 1.0) * c2 + 1.0).powi(2))
}

/// The lobe cosine raised to the exponent without clamping it at 0.
pub fn phong(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Vec3::ZERO;
    }
    let lobe = t.reflect(wi, Vec3::Z).dot(wo).powf(params.exponent);
    params.kd * FRAC_1_PI + params.ks * ((params.exponent + 2.0) / (2.0 * PI) * lobe)
}

/// The clamped lobe cosine raised to the exponent as `exp(n ln x)`: right for every
/// exponent above 0, NaN (`0 · −∞`) behind the mirror direction at an exponent of 0.
pub fn phong_power_by_logarithm(t: &impl Tasks, wo: Vec3, wi: Vec3, params: &PhongParams) -> Vec3 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return Vec3::ZERO;
    }
    let cos = t.reflect(wi, Vec3::Z).dot(wo).max(0.0);
    let lobe = (params.exponent * cos.ln()).exp();
    params.kd * FRAC_1_PI + params.ks * ((params.exponent + 2.0) / (2.0 * PI) * lobe)
}

/// The worksheet's fibre model: kd + ks (wi·wo)/(sin θi sin θo) sin^p θh.
pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    let (cos_i, cos_o) = (tangent.dot(wi), tangent.dot(wo));
    let (sin_i, sin_o) = ((1.0 - cos_i * cos_i).sqrt(), (1.0 - cos_o * cos_o).sqrt());
    let h = (wi + wo).normalize();
    let cos_h = tangent.dot(h);
    let sin_h = (1.0 - cos_h * cos_h).sqrt();
    params.kd + params.ks * (wi.dot(wo) / (sin_i * sin_o) * sin_h.powf(params.exponent))
}

/// exp(−tan²θ/α²) / (π α² cos⁴θ) as written.
pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
    let c2 = h.z * h.z;
    let tan2 = (1.0 - c2) / c2;
    (-tan2 / (alpha * alpha)).exp() / (PI * alpha * alpha * c2 * c2)
}

/// The relative gap of every pair, 0/0 included.
pub fn reciprocity_gap(
    brdf: &dyn Fn(Vec3, Vec3) -> f32,
    sampler: &mut pbrlab::sampling::Sampler,
    pairs: usize,
) -> f32 {
    let mut gap = f32::NEG_INFINITY;
    for _ in 0..pairs {
        let a = pbrlab::sampling::uniform_hemisphere(sampler.next_2d());
        let b = pbrlab::sampling::uniform_hemisphere(sampler.next_2d());
        let (fab, fba) = (brdf(a, b), brdf(b, a));
        let g = (fab - fba).abs() / fab.abs().max(fba.abs());
        gap = if g > gap || g.is_nan() { g } else { gap };
    }
    gap
}

/// D(h) cos θh / (4 wo·h) for any pair.
pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    let h = (wo + wi).normalize();
    t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * wo.dot(h))
}

/// The density of h, D(h) cos θh, returned as the density of wi: the Jacobian
/// 1/(4 wo·h) of the reflection is missing (a pdf in the wrong measure).
pub fn ndf_pdf_no_jacobian(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return 0.0;
    }
    let h = (wo + wi).normalize();
    if wo.dot(h) <= 0.0 {
        return 0.0;
    }
    t.aniso_ndf(h, alpha_x, alpha_y) * h.z
}

/// A path tracer that stops only at depth 1 (no test for depth ≤ 0), so a path started at
/// depth 0 runs on until Russian roulette ends it.
pub fn path_trace_no_depth_guard(
    t: &impl Tasks,
    scene: &pbrlab::scene::Scene,
    segment: &pbrlab::integrator::Segment,
    depth: i32,
    sampler: &mut pbrlab::sampling::Sampler,
) -> Vec3 {
    let Some(hit) = &segment.hit else {
        return if segment.emission_counted {
            Vec3::ZERO
        } else {
            scene.environment(segment.ray.dir)
        };
    };
    let wo = -segment.ray.dir;
    let mut radiance = if segment.emission_counted {
        Vec3::ZERO
    } else {
        scene.emitted(hit, wo)
    };
    if depth == 1 {
        return radiance;
    }
    let direct = t.mis(scene, hit, wo, scene.heuristic(), sampler);
    radiance += direct.radiance;
    let Some(bounce) = direct.bounce else {
        return radiance;
    };
    let mut weight = bounce.weight;
    if scene.settings().roulette_applies(depth) {
        let q = weight.max_element().min(0.95);
        if sampler.next_1d() >= q {
            return radiance;
        }
        weight /= q;
    }
    radiance + weight * t.path_trace(scene, &bounce.segment, depth - 1, sampler)
}

/// Direct light with the textbook formulas and no guards: the light sample's area pdf is
/// converted with whatever cos θl is (0 edge-on), and the BSDF sample is weighted by the
/// heuristic even when it comes from a delta lobe (pdf 0). Area lights only.
pub fn mis_unguarded(
    t: &impl Tasks,
    scene: &pbrlab::scene::Scene,
    hit: &pbrlab::geometry::Hit,
    wo: Vec3,
    _heuristic: pbrlab::integrator::Heuristic,
    sampler: &mut pbrlab::sampling::Sampler,
) -> pbrlab::integrator::DirectLight {
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

/// The worksheet's delta tracking: two random numbers drawn once and reused at every step,
/// an escape reported as an absorption at `t_max`, and (to keep the test finite) the
/// step bound honoured.
pub fn delta_tracking_sheet(
    medium: &dyn pbrlab::medium::Medium,
    ray: &pbrlab::geometry::Ray,
    t_max: f32,
    max_steps: u32,
    sampler: &mut pbrlab::sampling::Sampler,
) -> pbrlab::medium::FreeFlight {
    use pbrlab::medium::FreeFlight;
    let (u0, u1) = (sampler.next_1d(), sampler.next_1d());
    let majorant = medium.majorant();
    let dt = -(1.0 - u0).ln() / majorant;
    let mut t = 0.0;
    for _ in 0..max_steps {
        t += dt;
        if t > t_max {
            return FreeFlight::Absorb { t: t_max };
        }
        let c = medium.coefficients(ray.at(t));
        if u1 * majorant < c.sigma_t() {
            return if u1 * majorant < c.sigma_s {
                FreeFlight::Scatter { t }
            } else {
                FreeFlight::Absorb { t }
            };
        }
    }
    FreeFlight::Exhausted
}
