//! Stability cases of the `smith_g1` task: grazing and back-facing directions, α = 0 and 1,
//! tiny cosines, a Λ argument small enough to cancel in f32, and a cosine above one.

use crate::stability::case::{Case, UNIT_INTERVAL};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::inputs::{cos_above_one, direction_xz};
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

const CHI: &str = "return 0 when cos θ ≤ 0 (the χ⁺ factor): the textbook formula goes negative \
                   below the horizon and is 0·∞ on it when α = 0";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/grazing",
            input: "w = (1, 0, 0), α = 0.5",
            eval: |t| t.smith_g1(Vec3::X, 0.5).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-7)),
            guard: CHI,
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/grazing_alpha_zero",
            input: "w = (1, 0, 0), α = 0",
            eval: |t| t.smith_g1(Vec3::X, 0.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-7)),
            guard: CHI,
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/back_facing",
            input: "cos θ = −0.5, α = 0.5",
            eval: |t| t.smith_g1(direction_xz(120f32.to_radians()), 0.5).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: CHI,
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/alpha_zero",
            input: "cos θ = 0.5, α = 0 (a perfect mirror masks nothing)",
            eval: |t| t.smith_g1(direction_xz(60f32.to_radians()), 0.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-6)),
            guard: "Λ = 0 when α = 0, so G1 = 1",
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/alpha_one",
            input: "cos θ = 0.5, α = 1",
            eval: |t| t.smith_g1(direction_xz(60f32.to_radians()), 1.0).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(2.0 / 3.0, Tolerance::rel(1e-6)),
            guard: "α = 1, cos θ = 0.5 is the worksheet's check value: G1 = 2/3",
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/tiny_cos",
            input: "cos θ = 1e-8, α = 0.5",
            eval: |t| t.smith_g1(Vec3::new(1.0, 0.0, 1e-8), 0.5).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(3.999_999_92e-8, Tolerance::rel(1e-4)),
            guard: "near grazing G1 ≈ 2c/α; tan²θ = 1e16 is fine in f32, 1/c² overflow is not",
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/small_lambda",
            input: "tan θ = 2e-4, α = 0.5 (α² tan²θ = 1e-8)",
            eval: |t| {
                t.smith_g1(Vec3::new(2e-4, 0.0, 1.0).normalize(), 0.5)
                    .into()
            },
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-7)),
            guard: "sqrt(1 + a) − 1 cancels to 0 in f32 for a = 1e-8: rewrite Λ so nothing is \
                    subtracted, or use the cosine form (G1 then rounds to 1 either way)",
        },
        Case {
            task: TaskId::SmithG1,
            name: "smith_g1/cos_above_one",
            input: "w = (0, 0, 1 + 2⁻²³), α = 0.5",
            eval: |t| t.smith_g1(cos_above_one(), 0.5).into(),
            range: UNIT_INTERVAL,
            expect: Expect::scalar(1.0, Tolerance::abs(1e-6)),
            guard: "clamp 1 − cos²θ at 0 before any square root (tan θ = sqrt(1 − c²)/c is NaN)",
        },
    ]
}
