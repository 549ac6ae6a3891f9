//! Stability cases of the `kajiya_kay` task: a direction along the fibre, the true mirror
//! cone, a tangent dot product above one, a fractional exponent on a negative cone cosine,
//! an exponent of 0 off the cone and an underflowing highlight.

use crate::bsdf::KajiyaKayParams;
use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::inputs::errata_unit_vector;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// kd = 0.1, ks = 0.9 and exponent `p`.
fn params(p: f32) -> KajiyaKayParams {
    KajiyaKayParams {
        kd: Vec3::splat(0.1),
        ks: Vec3::splat(0.9),
        exponent: p,
    }
}

/// A unit direction at `theta` radians from the fibre tangent +z (in the x-z plane).
fn from_tangent(theta: f64) -> Vec3 {
    Vec3::new(theta.sin() as f32, 0.0, theta.cos() as f32)
}

/// The angle from the tangent at which wi = wo has cone cosine 1/√7.
fn underflow_angle() -> f64 {
    (std::f64::consts::PI - (1.0 / 7f64.sqrt()).acos()) / 2.0
}

const CLAMP: &str = "compute sin θ = sqrt(max(0, 1 − cos²θ)) and take max(0, cone cosine) \
                     before the power";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/wi_along_tangent",
            input: "t = (0, 0, 1), wi = t, wo = (0.5, 0, 0.866), kd 0.1, ks 0.9, p 80",
            eval: |t| {
                let wo = from_tangent(30f64.to_radians());
                t.kajiya_kay(wo, Vec3::Z, Vec3::Z, &params(80.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(1e-6)),
            guard: "kd sin θi = 0 and wo is far off the reflection cone, so the highlight is 0: no \
                    division by sin θi",
        },
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/exponent_zero_off_the_cone",
            input: "t = (0, 0, 1), wi = wo = (0.5, 0, 0.866) (cone cosine −0.5), p 0",
            eval: |t| {
                let w = from_tangent(30f64.to_radians());
                t.kajiya_kay(w, w, Vec3::Z, &params(0.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::AnyOf(vec![
                Expect::vector([0.95; 3], Tolerance::rel(1e-5)),
                Expect::vector([0.05; 3], Tolerance::rel(1e-5)),
            ]),
            guard: "kd sin θi = 0.05, and max(0, c)^0 is 1 as written or 0 as the limit p → 0⁺; a \
                    power computed as exp(p ln c) gives NaN",
        },
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/mirror_cone",
            input: "t = (0, 0, 1), wi = (0.5, 0, 0.866), wo = (0.5, 0, −0.866), p 80",
            eval: |t| {
                let wi = from_tangent(30f64.to_radians());
                let wo = from_tangent(150f64.to_radians());
                t.kajiya_kay(wo, wi, Vec3::Z, &params(80.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.95; 3], Tolerance::rel(1e-4)),
            guard: "the specular peak is on the cone t·wo = −t·wi: kd·0.5 + ks·1 = 0.95 (the \
                    worksheet's form gives −1.7 here)",
        },
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/tangent_dot_above_one",
            input: "wi = wo = t = the errata's f32-normalised vector (t·wi = 1.0000001)",
            eval: |t| {
                let w = errata_unit_vector();
                t.kajiya_kay(w, w, w, &params(80.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(1e-6)),
            guard: CLAMP,
        },
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/fractional_exponent_negative_cone",
            input: "wi = wo at 30° from t (a negative cone cosine), p = 80.5",
            eval: |t| {
                let w = from_tangent(30f64.to_radians());
                t.kajiya_kay(w, w, Vec3::Z, &params(80.5)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.05; 3], Tolerance::rel(1e-5)),
            guard: CLAMP,
        },
        Case {
            task: TaskId::KajiyaKay,
            name: "kajiya_kay/highlight_underflow",
            input: "wi = wo with cone cosine 1/√7, p = 200 ((1/√7)^200 = 3e-85)",
            eval: |t| {
                let w = from_tangent(underflow_angle());
                t.kajiya_kay(w, w, Vec3::Z, &params(200.0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.1 * underflow_angle().sin(); 3], Tolerance::rel(1e-5)),
            guard: "an underflowing highlight is 0, which is harmless; only kd sin θi remains",
        },
    ]
}
