// The variants of `fresnel_schlick` the tests grade the grader with (see `src/grader/tasks/mod.rs`).
// `tests/instructor/support/variants.rs` includes this file into a module of the tests,
// so it has no inner attributes or doc; the student handout leaves it out.

use crate::support::patch::{Variant, variant};
use crate::support::variants::Naive;
use pbrlab::optics::schlick_weight;
use pbrlab::stability::Verdict;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions as sol;

/// Known-wrong implementations of `fresnel_schlick`: each must fail this task and no other.
pub fn wrong() -> Vec<Variant> {
    use TaskId::*;
    vec![
        variant(
            "Schlick with cos θi from dense to less dense",
            FresnelSchlick,
            |p| {
                p.fresnel_schlick = Some(|t, cos, eta_i, eta_t| {
                    let r0 = t.schlick_r0(eta_i, eta_t);
                    r0 + (1.0 - r0) * schlick_weight(cos)
                })
            },
        ),
        variant("no special case for equal indices", FresnelSchlick, |p| {
            p.fresnel_schlick = Some(|t, cos, eta_i, eta_t| {
                if eta_i == eta_t {
                    return schlick_weight(cos);
                }
                sol::fresnel_schlick::fresnel_schlick(t, cos, eta_i, eta_t)
            })
        }),
        variant("R0 not squared", FresnelSchlick, |p| {
            p.schlick_r0 = Some(|a, b| ((a - b) / (a + b)).abs())
        }),
    ]
}

/// Correct implementations of `fresnel_schlick` that differ from the reference: each gets full marks.
pub fn different() -> Vec<Variant> {
    use TaskId::*;
    vec![variant(
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
    )]
    .into_iter()
    .chain(other_arithmetic())
    .collect()
}

/// Correct implementations of `fresnel_schlick` in other arithmetic (f64, other algebraic forms):
/// each gets full marks, whatever its rounding.
fn other_arithmetic() -> Vec<Variant> {
    use TaskId::*;
    vec![variant("Schlick in f64 throughout", FresnelSchlick, |p| {
        p.schlick_r0 = Some(|eta_i, eta_t| {
            let (ei, et) = (f64::from(eta_i), f64::from(eta_t));
            ((ei - et) / (ei + et)).powi(2) as f32
        });
        p.fresnel_schlick = Some(|_, cos, eta_i, eta_t| {
            if eta_i == eta_t {
                return 0.0;
            }
            let (ei, et) = (f64::from(eta_i), f64::from(eta_t));
            let c = f64::from(cos.abs()).min(1.0);
            let c = if ei > et {
                let sin2_t = (ei / et).powi(2) * (1.0 - c * c).max(0.0);
                if sin2_t >= 1.0 {
                    return 1.0;
                }
                (1.0 - sin2_t).sqrt()
            } else {
                c
            };
            let r0 = ((ei - et) / (ei + et)).powi(2);
            (r0 + (1.0 - r0) * (1.0 - c).powi(5)) as f32
        });
    })]

}

/// Naive implementations of `fresnel_schlick` (the textbook formula without its guards), each with
/// exactly the stability cases it must fail and the verdict of each.
pub fn naive() -> Vec<Naive> {
    use TaskId::*;
    use Verdict::*;
    vec![Naive::new(
        "`fresnel_schlick` is R0 + (1 − R0)(1 − cos θi)^5 for every pair of indices",
        FresnelSchlick,
        |p| {
            p.fresnel_schlick = Some(textbook::fresnel_schlick_r0_everywhere);
        },
        vec![
            ("fresnel_schlick/equal_indices_60deg", WrongValue),
            ("fresnel_schlick/equal_indices_80deg", WrongValue),
            ("fresnel_schlick/equal_indices_89deg", WrongValue),
            ("fresnel_schlick/dense_to_less_40deg", WrongValue),
            ("fresnel_schlick/tir_45deg", WrongValue),
            ("fresnel_schlick/at_critical_f32", WrongValue),
            ("fresnel_schlick/past_critical_2ulp_f32", WrongValue),
        ],
    )]
}

/// The naive functions of [`naive`].
mod textbook {
    use super::*;

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
}
