//! Stability cases of the `phong` task: negative lobe cosines with fractional and integer
//! exponents, an exponent of 0 in and behind the lobe, a huge exponent at the peak, a
//! direction below the surface, and degenerate inputs of the reciprocity test.

use crate::bsdf::PhongParams;
use crate::sampling::Sampler;
use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;
use std::f64::consts::PI;

/// A pure specular lobe (kd = 0) so that only the lobe shows.
fn lobe_only(exponent: f32) -> PhongParams {
    PhongParams {
        kd: Vec3::ZERO,
        ks: Vec3::splat(0.4),
        exponent,
    }
}

/// wi = (0.8, 0, 0.6) mirrors to r = (−0.8, 0, 0.6); this wo makes r·wo = −0.2, both
/// directions above the surface.
fn negative_lobe_pair() -> (Vec3, Vec3) {
    let (x, z) = (0.475f32, 0.3f32);
    let wo = Vec3::new(x, (1.0 - x * x - z * z).sqrt(), z);
    (wo, Vec3::new(0.8, 0.0, 0.6))
}

const CLAMP: &str = "evaluate max(0, r·wo)^n: a negative base gives NaN for a fractional n and a \
                     spurious back lobe for an even n";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::Phong,
            name: "phong/fractional_exponent_negative_lobe",
            input: "r·wo = −0.2, n = 10.5, kd = 0, ks = 0.4",
            eval: |t| {
                let (wo, wi) = negative_lobe_pair();
                t.phong(wo, wi, &lobe_only(10.5)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: CLAMP,
        },
        Case {
            task: TaskId::Phong,
            name: "phong/even_exponent_negative_lobe",
            input: "r·wo = −0.2, n = 10, kd = 0, ks = 0.4",
            eval: |t| {
                let (wo, wi) = negative_lobe_pair();
                t.phong(wo, wi, &lobe_only(10.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: CLAMP,
        },
        Case {
            task: TaskId::Phong,
            name: "phong/exponent_zero_behind_the_mirror",
            input: "r·wo = −0.2, n = 0, kd = 0, ks = 0.4",
            eval: |t| {
                let (wo, wi) = negative_lobe_pair();
                t.phong(wo, wi, &lobe_only(0.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::AnyOf(vec![
                Expect::vector([0.4 / PI; 3], Tolerance::rel(1e-5)),
                Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            ]),
            guard: "max(0, r·wo)^0 is 1 as written (ks/π) or 0 as the limit n → 0⁺; a power \
                    computed as exp(n ln x) gives NaN",
        },
        Case {
            task: TaskId::Phong,
            name: "phong/exponent_zero_in_the_lobe",
            input: "wo = wi = (0.6, 0, 0.8) (r·wo = 0.28), n = 0, kd = 0, ks = 0.4",
            eval: |t| {
                let w = Vec3::new(0.6, 0.0, 0.8);
                t.phong(w, w, &lobe_only(0.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.4 / PI; 3], Tolerance::rel(1e-5)),
            guard: "(n + 2)/(2π) (r·wo)^n is 1/π at n = 0 wherever r·wo > 0",
        },
        Case {
            task: TaskId::Phong,
            name: "phong/huge_exponent_peak",
            input: "wo = wi = (0, 0, 1), n = 10⁶, kd = 0, ks = 0.4",
            eval: |t| t.phong(Vec3::Z, Vec3::Z, &lobe_only(1e6)).into(),
            range: NON_NEGATIVE,
            expect: Expect::vector([0.4 * (1e6 + 2.0) / (2.0 * PI); 3], Tolerance::rel(1e-4)),
            guard: "ks (n+2)/(2π) at the peak; finite for any finite n",
        },
        Case {
            task: TaskId::Phong,
            name: "phong/below_horizon",
            input: "wo = (0, 0, 1), wi = (0.6, 0, −0.8), kd = 0.5, ks = 0.4, n = 20",
            eval: |t| {
                let params = PhongParams {
                    kd: Vec3::splat(0.5),
                    ks: Vec3::splat(0.4),
                    exponent: 20.0,
                };
                t.phong(Vec3::Z, Vec3::new(0.6, 0.0, -0.8), &params).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: "a reflection BRDF is 0 when either direction is below the surface",
        },
        Case {
            task: TaskId::Phong,
            name: "reciprocity_gap/zero_brdf",
            input: "brdf ≡ 0, 64 pairs",
            eval: |t| {
                let mut sampler = Sampler::new(3, 0);
                t.reciprocity_gap(&|_, _| 0.0, &mut sampler, 64).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "pairs where both values are 0 count as 0, not 0/0",
        },
        Case {
            task: TaskId::Phong,
            name: "reciprocity_gap/no_pairs",
            input: "brdf = 1/π, 0 pairs",
            eval: |t| {
                let mut sampler = Sampler::new(3, 0);
                t.reciprocity_gap(&|_, _| std::f32::consts::FRAC_1_PI, &mut sampler, 0)
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "the largest gap over no pairs is 0 (start the maximum at 0, not −∞)",
        },
    ]
}
