//! Stability cases of the `cosine_sample` task: the corners of [0, 1)² (the sampler never
//! returns 1, but it does return 1 − 2⁻²⁴) and pdf queries on and below the horizon.

use crate::stability::case::{ANY, Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::inputs::{U_MAX, cos_above_one};
use crate::stability::summary::{max_nan, min_nan};
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};
use glam::{Vec2, Vec3};
use std::f64::consts::FRAC_1_PI;

/// Samples every `u` and summarises: the smallest cos θ, the largest deviation from unit
/// length, the smallest pdf the task reports for its own samples, and the largest
/// disagreement between that pdf and cos θ / π.
fn summarise_samples<T: Tasks>(t: &T, us: &[Vec2]) -> Value {
    let (mut min_z, mut len_err, mut min_pdf, mut pdf_err) =
        (f64::INFINITY, 0.0, f64::INFINITY, 0.0);
    for &u in us {
        let w = t.cosine_sample(u);
        let pdf = t.cosine_pdf(w) as f64;
        let z = w.z as f64;
        min_z = min_nan(min_z, z);
        len_err = max_nan(len_err, (w.as_dvec3().length() - 1.0).abs());
        min_pdf = min_nan(min_pdf, pdf);
        pdf_err = max_nan(pdf_err, (pdf - z * FRAC_1_PI).abs());
    }
    Value::record([
        ("min_z", min_z),
        ("len_err", len_err),
        ("min_pdf", min_pdf),
        ("pdf_err", pdf_err),
    ])
}

fn corners() -> Vec<Vec2> {
    let ends = [0.0, U_MAX];
    ends.iter()
        .flat_map(|&x| ends.iter().map(move |&y| Vec2::new(x, y)))
        .collect()
}

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::CosineSample,
            name: "cosine_sample/corners",
            input: "u ∈ {0, 1 − 2⁻²⁴}² (all four corners), pdf of each sample",
            eval: |t| summarise_samples(t, &corners()),
            range: ANY,
            expect: Expect::Fields(vec![
                ("min_z", Bound::Within(0.0, 1.0)),
                ("len_err", Bound::Within(0.0, 1e-5)),
                ("min_pdf", Bound::Within(1e-30, f64::INFINITY)),
                ("pdf_err", Bound::Within(0.0, 1e-6)),
            ]),
            guard: "u = 1 − 2⁻²⁴ must still give a direction above the horizon (cos θ > 0), so \
                    that f·cos/pdf stays finite; clamp square-root arguments at 0",
        },
        Case {
            task: TaskId::CosineSample,
            name: "cosine_pdf/below_horizon",
            input: "w = (0, 0.6, −0.8)",
            eval: |t| t.cosine_pdf(Vec3::new(0.0, 0.6, -0.8)).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "the density is 0 below the surface, never negative",
        },
        Case {
            task: TaskId::CosineSample,
            name: "cosine_pdf/horizon",
            input: "w = (1, 0, 0)",
            eval: |t| t.cosine_pdf(Vec3::X).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "cos θ / π is 0 on the horizon",
        },
        Case {
            task: TaskId::CosineSample,
            name: "cosine_pdf/cos_above_one",
            input: "w = (0, 0, 1 + 2⁻²³)",
            eval: |t| t.cosine_pdf(cos_above_one()).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(FRAC_1_PI, Tolerance::rel(1e-6)),
            guard: "cos θ / π; nothing here needs sin θ",
        },
    ]
}
