//! Stability cases of the `ndf_sample` task: grids of random numbers (including 0 and
//! 1 − 2⁻²⁴) for a grazing `wo` and a near-delta lobe, and pdf queries where `wo·h` is 0,
//! tiny, or where `wi` is below the surface.

use crate::stability::case::{ANY, Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::inputs::U_MAX;
use crate::stability::summary::{max_nan, min_nan};
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};
use glam::{Vec2, Vec3};
use std::f64::consts::PI;

/// `n × n` points spread over [0, 1 − 2⁻²⁴]², both ends included.
fn grid(n: usize) -> Vec<Vec2> {
    let at = |i: usize| U_MAX * i as f32 / (n - 1) as f32;
    (0..n)
        .flat_map(|i| (0..n).map(move |j| Vec2::new(at(i), at(j))))
        .collect()
}

/// Samples `wo` at every `u` and summarises the samples that were not rejected: how many,
/// the smallest cos θi, the largest deviation from unit length, and the smallest and
/// largest pdf the task gives its own samples.
fn summarise<T: Tasks>(t: &T, wo: Vec3, alpha: f32, us: &[Vec2]) -> Value {
    let (mut valid, mut min_z, mut len_err) = (0.0, 1.0, 0.0);
    let (mut min_pdf, mut max_pdf) = (f64::MAX, 0.0);
    for &u in us {
        if let Some(wi) = t.ndf_sample(wo, alpha, alpha, u) {
            let pdf = t.ndf_pdf(wo, wi, alpha, alpha) as f64;
            valid += 1.0;
            min_z = min_nan(min_z, wi.z as f64);
            len_err = max_nan(len_err, (wi.as_dvec3().length() - 1.0).abs());
            min_pdf = min_nan(min_pdf, pdf);
            max_pdf = max_nan(max_pdf, pdf);
        }
    }
    Value::record([
        ("valid", valid),
        ("min_z", min_z),
        ("len_err", len_err),
        ("min_pdf", min_pdf),
        ("max_pdf", max_pdf),
    ])
}

/// What every sample must satisfy: at least `accepted` of them accepted, none below the
/// surface, unit length, and a positive finite pdf.
fn valid_samples(accepted: f64) -> Expect {
    Expect::Fields(vec![
        ("valid", Bound::Within(accepted, f64::INFINITY)),
        ("min_z", Bound::Within(0.0, 1.0)),
        ("len_err", Bound::Within(0.0, 1e-5)),
        ("min_pdf", Bound::Within(1e-30, f64::INFINITY)),
    ])
}

const REJECT: &str = "reject (None) when wo·h ≤ 0 or wi ends below the surface; the pdf \
                      D(h) cos θh / (4 wo·h) is inf or negative there";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::NdfSample,
            name: "ndf_sample/grazing_wo_grid",
            input: "wo = (1, 0, 1e-6), α = 0.3, u on a 17 × 17 grid over [0, 1 − 2⁻²⁴]²",
            eval: |t| summarise(t, Vec3::new(1.0, 0.0, 1e-6), 0.3, &grid(17)),
            range: ANY,
            expect: valid_samples(1.0),
            guard: REJECT,
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_sample/corners",
            input: "wo = (0.6, 0, 0.8), α = 0.3, u ∈ {0, 1 − 2⁻²⁴}²",
            eval: |t| summarise(t, Vec3::new(0.6, 0.0, 0.8), 0.3, &grid(2)),
            range: ANY,
            // A valid mapping may send every corner of the square to the rim of the disk
            // (a concentric mapping does), where rejecting all four is right: what is
            // returned must be valid, nothing more.
            expect: valid_samples(0.0),
            guard: "u = 1 − 2⁻²⁴ gives a steep h (θh close to 90°): it must stay finite, and the \
                    sample is rejected if wi ends below the surface",
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_sample/tiny_alpha_grid",
            input: "wo = (0.6, 0, 0.8), α = 1e-3, u on a 9 × 9 grid",
            eval: |t| summarise(t, Vec3::new(0.6, 0.0, 0.8), 1e-3, &grid(9)),
            range: ANY,
            expect: valid_samples(1.0),
            guard: "a near-delta lobe has a huge but finite pdf (about 1e5 here)",
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_pdf/opposite",
            input: "wo = (0.6, 0, 0.8), wi = −wo, α = 0.3 (wo + wi = 0)",
            eval: |t| {
                let wo = Vec3::new(0.6, 0.0, 0.8);
                t.ndf_pdf(wo, -wo, 0.3, 0.3).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "no half vector exists (0/0): wi below the surface has density 0",
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_pdf/wi_below",
            input: "wo = (0.6, 0, 0.8), wi = (−0.8, 0, −0.6), α = 0.3",
            eval: |t| {
                let wi = Vec3::new(-0.8, 0.0, -0.6);
                t.ndf_pdf(Vec3::new(0.6, 0.0, 0.8), wi, 0.3, 0.3).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "sampling never returns wi below the surface, so its density there is 0",
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_pdf/grazing_pair",
            input: "wo = (1, 0, 1e-6), wi = (−1, 0, 1e-6), α = 0.3 (wo·h = 1e-6)",
            eval: |t| {
                let (wo, wi) = (Vec3::new(1.0, 0.0, 1e-6), Vec3::new(-1.0, 0.0, 1e-6));
                t.ndf_pdf(wo, wi, 0.3, 0.3).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::AnyOf(vec![
                Expect::scalar(1.0 / (PI * 0.09) / 4e-6, Tolerance::rel(1e-3)),
                Expect::scalar(0.0, Tolerance::abs(0.0)),
            ]),
            guard: "D(n)/(4·1e-6) = 884194 is large but finite (0 from a near-opposite guard \
                    is acceptable too)",
        },
        Case {
            task: TaskId::NdfSample,
            name: "ndf_pdf/alpha_1e-4_mirror",
            input: "wo = (0.6, 0, 0.8), wi = (−0.6, 0, 0.8), α = 1e-4 (f32)",
            eval: |t| {
                let (wo, wi) = (Vec3::new(0.6, 0.0, 0.8), Vec3::new(-0.6, 0.0, 0.8));
                t.ndf_pdf(wo, wi, 1e-4, 1e-4).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(1.0 / (PI * 1e-8) / 3.2, Tolerance::rel(1e-3)),
            guard: "D(n) = 1/(π α²) must not cancel in f32; then divide by 4 wo·h = 3.2",
        },
    ]
}
