// The variants of `kajiya_kay` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::bsdf::KajiyaKayParams;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;
use std::f32::consts::PI;

/// Known-wrong implementations of `kajiya_kay`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
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
        variant(
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
        variant("cone cosine not clamped before powf", KajiyaKay, |p| {
            p.kajiya_kay = Some(|wo, wi, t, params| {
                let (ci, co) = (t.dot(wi).clamp(-1.0, 1.0), t.dot(wo).clamp(-1.0, 1.0));
                let (si, so) = ((1.0 - ci * ci).sqrt(), (1.0 - co * co).sqrt());
                params.kd * si + params.ks * (si * so - ci * co).powf(params.exponent)
            })
        }),
    ]
}

/// Correct implementations of `kajiya_kay` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
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
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `kajiya_kay` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("Kajiya-Kay in f64 throughout", KajiyaKay, |p| {
            p.kajiya_kay = Some(|wo, wi, t, params| {
                let (wo, wi, t) = (wo.as_dvec3(), wi.as_dvec3(), t.as_dvec3());
                let (ci, co) = (t.dot(wi).clamp(-1.0, 1.0), t.dot(wo).clamp(-1.0, 1.0));
                let (si, so) = ((1.0 - ci * ci).sqrt(), (1.0 - co * co).sqrt());
                let cone = (si * so - ci * co).max(0.0);
                let (kd, ks) = (params.kd.as_dvec3(), params.ks.as_dvec3());
                (kd * si + ks * cone.powf(f64::from(params.exponent))).as_vec3()
            })
        }),
        variant("Kajiya-Kay with sines from cross products", KajiyaKay, |p| {
            p.kajiya_kay = Some(|wo, wi, t, params| {
                let (si, so) = (t.cross(wi).length(), t.cross(wo).length());
                let cone = (si * so - t.dot(wi) * t.dot(wo)).max(0.0);
                params.kd * si + params.ks * cone.powf(params.exponent)
            })
        }),
    ]

}

/// Naive implementations of `kajiya_kay` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`kajiya_kay` is the worksheet's form",
        KajiyaKay,
        |p| {
            p.kajiya_kay = Some(textbook::kajiya_kay);
        },
        vec![
            ("kajiya_kay/wi_along_tangent", NaN),
            ("kajiya_kay/mirror_cone", OutOfRange),
            ("kajiya_kay/tangent_dot_above_one", NaN),
            ("kajiya_kay/exponent_zero_off_the_cone", WrongValue),
            ("kajiya_kay/fractional_exponent_negative_cone", WrongValue),
            ("kajiya_kay/highlight_underflow", WrongValue),
        ],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// The worksheet's fibre model: kd + ks (wi·wo)/(sin θi sin θo) sin^p θh.
    pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
        let (cos_i, cos_o) = (tangent.dot(wi), tangent.dot(wo));
        let (sin_i, sin_o) = ((1.0 - cos_i * cos_i).sqrt(), (1.0 - cos_o * cos_o).sqrt());
        let h = (wi + wo).normalize();
        let cos_h = tangent.dot(h);
        let sin_h = (1.0 - cos_h * cos_h).sqrt();
        params.kd + params.ks * (wi.dot(wo) / (sin_i * sin_o) * sin_h.powf(params.exponent))
    }
}
