// The variants of `ndf_sample` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Patch, Variant, variant};
use crate::support::variants::Naive;
use crate::support::warps::cosine_direction;
use glam::{Vec2, Vec3};
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;
use std::f32::consts::{PI, TAU};

/// Known-wrong implementations of `ndf_sample`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("pdf without the 1/(4 wo·h) Jacobian", NdfSample, |p| {
            p.ndf_pdf = Some(|t, wo, wi, ax, ay| {
                let h = (wo + wi).normalize();
                if wi.z <= 0.0 || h.z <= 0.0 {
                    return 0.0;
                }
                t.aniso_ndf(h, ax, ay) * h.z
            })
        }),
        variant("pdf without cos θh", NdfSample, |p| {
            p.ndf_pdf = Some(|t, wo, wi, ax, ay| {
                sol::ndf_sample::ndf_pdf(t, wo, wi, ax, ay) / (wo + wi).normalize().z
            })
        }),
        variant("half vectors with swapped roughnesses", NdfSample, |p| {
            p.ndf_sample = Some(|t, wo, ax, ay, u| sol::ndf_sample::ndf_sample(t, wo, ay, ax, u))
        }),
        variant("wi below the surface not rejected", NdfSample, |p| {
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
    ]
}

/// Correct implementations of `ndf_sample` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
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
        variant(
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
    ]
}

/// Naive implementations of `ndf_sample` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![
        Naive::new(
            "`ndf_pdf` with no test of the directions",
            NdfSample,
            |p| {
                p.ndf_pdf = Some(textbook::ndf_pdf);
            },
            vec![("ndf_pdf/opposite", NaN), ("ndf_pdf/wi_below", WrongValue)],
        ),
        Naive::new(
            "`ndf_pdf` without the reflection Jacobian 1/(4 wo·h)",
            NdfSample,
            |p| {
                p.ndf_pdf = Some(textbook::ndf_pdf_no_jacobian);
            },
            vec![
                ("ndf_pdf/grazing_pair", WrongValue),
                ("ndf_pdf/alpha_1e-4_mirror", WrongValue),
            ],
        ),
    ]
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

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// D(h) cos θh / (4 wo·h) for any pair.
    pub fn ndf_pdf(t: &impl Tasks, wo: Vec3, wi: Vec3, alpha_x: f32, alpha_y: f32) -> f32 {
        let h = (wo + wi).normalize();
        t.aniso_ndf(h, alpha_x, alpha_y) * h.z / (4.0 * wo.dot(h))
    }

    /// The density of h, D(h) cos θh, returned as the density of wi: the Jacobian
    /// 1/(4 wo·h) of the reflection is missing (a pdf in the wrong measure).
    pub fn ndf_pdf_no_jacobian(
        t: &impl Tasks,
        wo: Vec3,
        wi: Vec3,
        alpha_x: f32,
        alpha_y: f32,
    ) -> f32 {
        if wo.z <= 0.0 || wi.z <= 0.0 {
            return 0.0;
        }
        let h = (wo + wi).normalize();
        if wo.dot(h) <= 0.0 {
            return 0.0;
        }
        t.aniso_ndf(h, alpha_x, alpha_y) * h.z
    }
}
