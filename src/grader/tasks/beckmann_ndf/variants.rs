// The variants of `beckmann_ndf` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use glam::Vec3;
use pbrlab::bsdf::MIN_ALPHA;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::TaskId;
use std::f32::consts::{FRAC_1_PI, PI};

/// Known-wrong implementations of `beckmann_ndf`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant("missing cos⁴θh", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                let tan2 = (1.0 - h.z * h.z) / (h.z * h.z);
                (-tan2 / (alpha * alpha)).exp() * FRAC_1_PI / (alpha * alpha)
            })
        }),
        variant("0 · ∞ at grazing", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                let c2 = h.z * h.z;
                let tan2 = (1.0 - c2) / c2;
                (-tan2 / (alpha * alpha)).exp() * FRAC_1_PI / (alpha * alpha * c2 * c2)
            })
        }),
        variant("α instead of α² in the exponent", BeckmannNdf, |p| {
            p.beckmann_ndf = Some(|h, alpha| {
                if h.z <= 0.0 {
                    return 0.0;
                }
                let c2 = h.z * h.z;
                let tan2 = (1.0 - c2) / c2;
                (-tan2 / alpha).exp() * FRAC_1_PI / (alpha * alpha * c2 * c2)
            })
        }),
    ]
}

/// Correct implementations of `beckmann_ndf` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
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
                let falloff = ((c2 - 1.0) / (alpha * alpha * c2)).exp();
                if falloff == 0.0 {
                    // Where the exponential underflows, the denominator may too (0/0).
                    return 0.0;
                }
                falloff / (PI * alpha * alpha * c2 * c2)
            })
        },
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `beckmann_ndf` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("Beckmann in f64 throughout", BeckmannNdf, |p| {
        p.beckmann_ndf = Some(|h, alpha| {
            let c = f64::from(h.z).min(1.0);
            if c <= 0.0 {
                return 0.0;
            }
            let a2 = f64::from(alpha.abs().max(MIN_ALPHA)).powi(2);
            let c2 = c * c;
            let tan2 = (1.0 - c2) / c2;
            ((-tan2 / a2).exp() / (std::f64::consts::PI * a2 * c2 * c2)) as f32
        })
    })]

}

/// Naive implementations of `beckmann_ndf` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`beckmann_ndf` as written, no guards",
        BeckmannNdf,
        |p| {
            p.beckmann_ndf = Some(textbook::beckmann_ndf);
        },
        vec![
            ("beckmann_ndf/horizon", NaN),
            ("beckmann_ndf/cos_1e-12", NaN),
            ("beckmann_ndf/below_horizon", WrongValue),
            ("beckmann_ndf/alpha_zero_peak", NaN),
            ("beckmann_ndf/alpha_zero_off_peak", NaN),
        ],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

    /// exp(−tan²θ/α²) / (π α² cos⁴θ) as written.
    pub fn beckmann_ndf(h: Vec3, alpha: f32) -> f32 {
        let c2 = h.z * h.z;
        let tan2 = (1.0 - c2) / c2;
        (-tan2 / (alpha * alpha)).exp() / (PI * alpha * alpha * c2 * c2)
    }
}
