// The variants of `smith_g1` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;

/// Known-wrong implementations of `smith_g1`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "G1 by Λ from tan²θ = (1 − c²)/c², NaN where c² underflows",
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
        variant("G1 negative for back-facing directions", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                let c = w.z;
                2.0 * c / (c + (alpha * alpha * (1.0 - c * c) + c * c).sqrt())
            })
        }),
        variant("Λ without the 1/2", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                if w.z <= 0.0 {
                    return 0.0;
                }
                let tan2 = (1.0 - w.z * w.z) / (w.z * w.z);
                1.0 / (1.0 + (-1.0 + (1.0 + alpha * alpha * tan2).sqrt()))
            })
        }),
    ]
}

/// Correct implementations of `smith_g1` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
        "G1 in the tangent form 1/(1 + Λ) with a stable Λ",
        SmithG1,
        |p| {
            p.smith_g1 = Some(|w, alpha| {
                if w.z <= 0.0 {
                    return 0.0;
                }
                if alpha == 0.0 {
                    return 1.0;
                }
                let c2 = (w.z * w.z).min(1.0);
                let a = alpha * alpha * (1.0 - c2) / c2;
                if a > 1e30 {
                    // cos²θ (nearly) underflows: the grazing limit 2 cos θ / (α sin θ).
                    return 2.0 * w.z / (alpha * (1.0 - c2).sqrt());
                }
                let lambda = a / (2.0 * (1.0 + (1.0 + a).sqrt()));
                1.0 / (1.0 + lambda)
            })
        },
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `smith_g1` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("G1 in f64 throughout", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                let c = f64::from(w.z).min(1.0);
                if c <= 0.0 {
                    return 0.0;
                }
                let (a, s2) = (f64::from(alpha), (1.0 - c * c).max(0.0));
                (2.0 * c / (c + (c * c + a * a * s2).sqrt())) as f32
            })
        }),
        variant("G1 with tan²θ from the direction's x and y", SmithG1, |p| {
            p.smith_g1 = Some(|w, alpha| {
                if w.z <= 0.0 {
                    return 0.0;
                }
                if alpha == 0.0 {
                    return 1.0;
                }
                let tan2 = (w.x * w.x + w.y * w.y) / (w.z * w.z);
                2.0 / (1.0 + (1.0 + alpha * alpha * tan2).sqrt())
            })
        }),
    ]

}

/// Naive implementations of `smith_g1` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`smith_g1` has no χ⁺ factor",
        SmithG1,
        |p| {
            p.smith_g1 = Some(textbook::smith_g1);
        },
        vec![
            ("smith_g1/back_facing", OutOfRange),
            ("smith_g1/grazing_alpha_zero", NaN),
        ],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// The cosine form of G1 without the χ⁺ factor.
    pub fn smith_g1(w: Vec3, alpha: f32) -> f32 {
        let (c, a2) = (w.z, alpha * alpha);
        2.0 * c / (c + (a2 + (1.0 - a2) * c * c).sqrt())
    }
}
