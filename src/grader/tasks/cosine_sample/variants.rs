// The variants of `cosine_sample` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use crate::support::warps::concentric_disk;
use glam::Vec3;
use pbrlab::sampling::{uniform_hemisphere, uniform_hemisphere_pdf};
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;
use std::f32::consts::{FRAC_1_PI, PI, TAU};

/// Known-wrong implementations of `cosine_sample`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("uniform samples with the cosine pdf", CosineSample, |p| {
            p.cosine_sample = Some(uniform_hemisphere)
        }),
        variant("cosine samples with the uniform pdf", CosineSample, |p| {
            p.cosine_pdf = Some(|w| {
                if w.z > 0.0 {
                    uniform_hemisphere_pdf()
                } else {
                    0.0
                }
            })
        }),
        variant("pdf missing 1/π", CosineSample, |p| {
            p.cosine_pdf = Some(|w| w.z.max(0.0))
        }),
        variant("the sheet's cos θ = sqrt(1 − π u)", CosineSample, |p| {
            p.cosine_sample = Some(|u| {
                let c = (1.0 - PI * u.y).sqrt();
                let s = (1.0 - c * c).max(0.0).sqrt();
                let phi = 2.0 * PI * u.x;
                Vec3::new(s * phi.cos(), s * phi.sin(), c)
            })
        }),
        variant(
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
    ]
}

/// Correct implementations of `cosine_sample` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
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
        variant(
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
    ]
}

/// Naive implementations of `cosine_sample` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`cosine_pdf` is w.z/π also below the surface",
        CosineSample,
        |p| {
            p.cosine_pdf = Some(textbook::cosine_pdf);
        },
        vec![("cosine_pdf/below_horizon", OutOfRange)],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// w.z / π everywhere.
    pub fn cosine_pdf(w: Vec3) -> f32 {
        w.z * FRAC_1_PI
    }
}
