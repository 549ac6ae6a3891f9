//! Stability cases of the `cook_torrance` task: opposite directions (no half vector),
//! grazing outgoing directions, α = 0 and a cosine above one.

use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::inputs::cos_above_one;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;
use std::f64::consts::PI;

/// Schlick reflectance at normal incidence used by every case (grey).
const F0: f32 = 0.04;

/// The grazing limit F(45°)·D(45°)·G1(n)·(2/α)/4 for α = 0.5, F0 = 0.04, wi = n: the
/// errata's 0.008570, recomputed in f64 from the closed forms.
fn grazing_limit() -> f64 {
    let alpha: f64 = 0.5;
    let cos_h = 0.5f64.sqrt();
    let fresnel = 0.04 + 0.96 * (1.0 - cos_h).powi(5);
    let a2 = alpha * alpha;
    let ndf = a2 / (PI * ((a2 - 1.0) * cos_h * cos_h + 1.0).powi(2));
    fresnel * ndf / (2.0 * alpha)
}

const HALF: &str = "wi = −wo has no half vector (0/0): return 0 when either direction is at or \
                    below the horizon, before normalising wo + wi";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/opposite_normal",
            input: "wo = (0, 0, 1), wi = (0, 0, −1), α = 0.5",
            eval: |t| {
                t.cook_torrance(Vec3::Z, -Vec3::Z, 0.5, 0.5, Vec3::splat(F0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: HALF,
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/opposite_tilted",
            input: "wo = (0.6, 0, 0.8), wi = −wo, α = 0.5",
            eval: |t| {
                let wo = Vec3::new(0.6, 0.0, 0.8);
                t.cook_torrance(wo, -wo, 0.5, 0.5, Vec3::splat(F0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: HALF,
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/grazing_wo",
            input: "wo = (1, 0, 1e-6) (θo = 89.99994°), wi = (0, 0, 1), α = 0.5, F0 = 0.04",
            eval: |t| {
                let wo = Vec3::new(1.0, 0.0, 1e-6);
                t.cook_torrance(wo, Vec3::Z, 0.5, 0.5, Vec3::splat(F0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([grazing_limit(); 3], Tolerance::rel(1e-3)),
            guard: "G1(wo) ≈ 2 cos θo/α cancels the 1/cos θo: with G = 1 the value grows like \
                    1/cos θo (12276 at 89.99999°); the limit is 0.008570",
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/horizon",
            input: "wo = (1, 0, 0), wi = (0, 0, 1), α = 0.5",
            eval: |t| {
                t.cook_torrance(Vec3::X, Vec3::Z, 0.5, 0.5, Vec3::splat(F0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(0.0)),
            guard: "0 when a direction is on the horizon: guards the division by cos θo",
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/alpha_zero_off_specular",
            input: "wo = (0.6, 0, 0.8), wi = (0, 0, 1), α = 0",
            eval: |t| {
                let wo = Vec3::new(0.6, 0.0, 0.8);
                t.cook_torrance(wo, Vec3::Z, 0.0, 0.0, Vec3::splat(F0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.0; 3], Tolerance::abs(1e-3)),
            guard: "α = 0 is a mirror: away from the mirror direction the value is 0, not 0·∞",
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/alpha_zero_specular",
            input: "wo = wi = (0, 0, 1), α = 0",
            eval: |t| {
                t.cook_torrance(Vec3::Z, Vec3::Z, 0.0, 0.0, Vec3::splat(F0))
                    .into()
            },
            range: NON_NEGATIVE,
            expect: Expect::Finite,
            guard: "α = 0 is a mirror: clamp α to a small floor (1e-4) so the peak stays finite",
        },
        Case {
            task: TaskId::CookTorrance,
            name: "cook_torrance/cos_above_one",
            input: "wo = wi = (0, 0, 1 + 2⁻²³), α = 0.5, F0 = 0.04",
            eval: |t| {
                let w = cos_above_one();
                t.cook_torrance(w, w, 0.5, 0.5, Vec3::splat(F0)).into()
            },
            range: NON_NEGATIVE,
            expect: Expect::vector([0.04 / (PI * 0.25) / 4.0; 3], Tolerance::rel(1e-5)),
            guard: "F0·D(n)/4 with G1 = 1: clamp cosines to [−1, 1] before sqrt(1 − cos²)",
        },
    ]
}
