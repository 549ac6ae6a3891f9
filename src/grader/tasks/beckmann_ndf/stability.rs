//! Stability cases of the `beckmann_ndf` task: grazing normals whose cos⁴θ underflows in
//! f32, α = 0 and α → 0.

use crate::tasks::aniso_ndf::stability::DELTA_PEAK;
use crate::stability::case::{Case, NON_NEGATIVE};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;
use std::f64::consts::PI;

const GRAZING: &str = "return 0 when cos θh ≤ 0 or when cos⁴θh underflows: exp(−tan²θ/α²) is \
                       already 0 there, and 0/0 is NaN";

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/horizon",
            input: "h = (1, 0, 0), α = 0.1",
            eval: |t| t.beckmann_ndf(Vec3::X, 0.1).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: GRAZING,
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/cos_1e-10",
            input: "h = (1, 0, 1e-10), α = 0.5 (cos⁴θ = 1e-40, subnormal in f32)",
            eval: |t| t.beckmann_ndf(Vec3::new(1.0, 0.0, 1e-10), 0.5).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-30)),
            guard: GRAZING,
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/cos_1e-12",
            input: "h = (1, 0, 1e-12), α = 0.5 (cos⁴θ underflows to 0 in f32)",
            eval: |t| t.beckmann_ndf(Vec3::new(1.0, 0.0, 1e-12), 0.5).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-30)),
            guard: GRAZING,
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/below_horizon",
            input: "h = (0.6, 0, −0.8), α = 0.5",
            eval: |t| t.beckmann_ndf(Vec3::new(0.6, 0.0, -0.8), 0.5).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(0.0)),
            guard: "normals below the surface have density 0",
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/alpha_1e-3_peak",
            input: "h = (0, 0, 1), α = 1e-3",
            eval: |t| t.beckmann_ndf(Vec3::Z, 1e-3).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(1.0 / (PI * 1e-6), Tolerance::rel(1e-4)),
            guard: "1/(π α²) at the peak",
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/alpha_zero_peak",
            input: "h = (0, 0, 1), α = 0",
            eval: |t| t.beckmann_ndf(Vec3::Z, 0.0).into(),
            range: DELTA_PEAK,
            expect: Expect::Finite,
            guard: "α = 0 is a mirror: clamp α to a small floor (1e-4) so that 0/0 never happens",
        },
        Case {
            task: TaskId::BeckmannNdf,
            name: "beckmann_ndf/alpha_zero_off_peak",
            input: "h = (0.6, 0, 0.8), α = 0",
            eval: |t| t.beckmann_ndf(Vec3::new(0.6, 0.0, 0.8), 0.0).into(),
            range: NON_NEGATIVE,
            expect: Expect::scalar(0.0, Tolerance::abs(1e-3)),
            guard: "α = 0 is a mirror: clamp α to a small floor (1e-4) so that exp(−∞)/0 never happens",
        },
    ]
}
