// The variants of `cook_torrance` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::bsdf::{MIN_ALPHA, projected_alpha};
use pbrlab::optics::schlick_weight;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;

/// Known-wrong implementations of `cook_torrance`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "D G / (4 cos θo cos θi), 0/0 where the cosines' product underflows",
            CookTorrance,
            |p| {
                p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                    if wo.z <= 0.0 || wi.z <= 0.0 {
                        return Vec3::ZERO;
                    }
                    let h = (wi + wo).normalize();
                    let g = t.smith_g1(wi, projected_alpha(wi, ax, ay))
                        * t.smith_g1(wo, projected_alpha(wo, ax, ay));
                    let f = f0 + (Vec3::ONE - f0) * schlick_weight(wo.dot(h));
                    t.aniso_ndf(h, ax, ay) * g * f / (4.0 * wi.z * wo.z)
                })
            },
        ),
        variant("missing factor 4", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                sol::cook_torrance::cook_torrance(t, wo, wi, ax, ay, f0) * 4.0
            })
        }),
        variant("G = 1 (no masking)", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                if wo.z <= 0.0 || wi.z <= 0.0 {
                    return Vec3::ZERO;
                }
                let h = (wo + wi).normalize();
                let f = f0 + (Vec3::ONE - f0) * schlick_weight(wo.dot(h));
                f * t.aniso_ndf(h, ax, ay) / (4.0 * wo.z * wi.z)
            })
        }),
        variant("swapped anisotropic roughnesses", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                sol::cook_torrance::cook_torrance(t, wo, wi, ay, ax, f0)
            })
        }),
        variant("Fresnel of cos θo instead of wo·h", CookTorrance, |p| {
            p.cook_torrance = Some(|t, wo, wi, ax, ay, f0| {
                let base = sol::cook_torrance::cook_torrance(t, wo, wi, ax, ay, Vec3::ONE);
                base * (f0 + (Vec3::ONE - f0) * schlick_weight(wo.z))
            })
        }),
    ]
}

/// Correct implementations of `cook_torrance` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
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
                // Each G1 over its own cosine, so a subnormal cosine cannot give 0/0.
                let g = t.smith_g1(wi, proj(wi)) / wi.z * (t.smith_g1(wo, proj(wo)) / wo.z);
                let f = f0 + (Vec3::ONE - f0) * (1.0 - wi.dot(h)).clamp(0.0, 1.0).powi(5);
                t.aniso_ndf(h, ax, ay) * g * f / 4.0
            })
        },
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `cook_torrance` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("Cook-Torrance in f64 throughout", CookTorrance, |p| {
        p.cook_torrance = Some(|_, wo, wi, alpha_x, alpha_y, f0| {
            use glam::DVec3;
            if wo.z <= 0.0 || wi.z <= 0.0 {
                return Vec3::ZERO;
            }
            let (wo, wi) = (wo.as_dvec3(), wi.as_dvec3());
            let h = (wo + wi).normalize();
            let (fx, fy) = (
                f64::from(alpha_x.abs().max(MIN_ALPHA)),
                f64::from(alpha_y.abs().max(MIN_ALPHA)),
            );
            let s = (h.x / fx).powi(2) + (h.y / fy).powi(2) + h.z * h.z;
            let d = 1.0 / (std::f64::consts::PI * fx * fy * s * s);
            let (ax, ay) = (f64::from(alpha_x), f64::from(alpha_y));
            let g1 = |w: DVec3| {
                let r2 = w.x * w.x + w.y * w.y;
                let a2 = if r2 == 0.0 {
                    ax * ax
                } else {
                    (w.x * w.x * ax * ax + w.y * w.y * ay * ay) / r2
                };
                let c = w.z.min(1.0);
                2.0 * c / (c + (c * c + a2 * (1.0 - c * c).max(0.0)).sqrt())
            };
            let weight = (1.0 - wo.dot(h)).clamp(0.0, 1.0).powi(5);
            let f0 = f0.as_dvec3();
            let fresnel = f0 + (DVec3::ONE - f0) * weight;
            (fresnel * (d * g1(wo) * g1(wi) / (4.0 * wo.z * wi.z))).as_vec3()
        })
    })]

}

/// Naive implementations of `cook_torrance` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`cook_torrance` normalises wo + wi before any horizon test",
        CookTorrance,
        |p| {
            p.cook_torrance = Some(textbook::cook_torrance);
        },
        vec![
            ("cook_torrance/opposite_normal", NaN),
            ("cook_torrance/opposite_tilted", NaN),
            ("cook_torrance/horizon", NaN),
        ],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

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
}
