// The variants of `reflect` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;

/// Known-wrong implementations of `reflect`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "§1.1 formula in the away convention (sign flipped)",
            Reflect,
            |p| p.reflect = Some(|wo, n| wo - 2.0 * wo.dot(n) * n),
        ),
        variant("normal not normalised", Reflect, |p| {
            p.reflect = Some(|wo, n| 2.0 * wo.dot(n) * n - wo)
        }),
    ]
}

/// Correct implementations of `reflect` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("reflect with a normalised normal", Reflect, |p| {
        p.reflect = Some(|wo, n| {
            let n = n.normalize();
            2.0 * wo.dot(n) * n - wo
        })
    })]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `reflect` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("reflect in f64 throughout", Reflect, |p| {
        p.reflect = Some(|wo, n| {
            let (wo, n) = (wo.as_dvec3(), n.as_dvec3());
            (n * (2.0 * wo.dot(n) / n.length_squared()) - wo).as_vec3()
        })
    })]

}

/// Naive implementations of `reflect` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`reflect` does not normalise n",
        Reflect,
        |p| {
            p.reflect = Some(textbook::reflect);
        },
        vec![("reflect/non_unit_normal", OutOfRange)],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// No normalisation of n.
    pub fn reflect(wo: Vec3, n: Vec3) -> Vec3 {
        2.0 * wo.dot(n) * n - wo
    }
}
