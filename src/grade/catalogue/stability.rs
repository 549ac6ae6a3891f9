//! Extreme inputs for the stability check.
//!
//! Only the first few cases live here; the catalogue of `pbrlab stability`
//! (`crate::stability`) supplies the rest through the same [`StabilityCase`] type.

use crate::grade::output::IntoOutput;
use crate::grade::stability::{Expect, StabilityCase};
use crate::worksheet::{TaskId, Tasks};
use glam::{Vec2, Vec3};

/// The stability cases of `task` on `t`.
pub fn cases<T: Tasks>(task: TaskId, t: &T) -> Vec<StabilityCase<'_>> {
    match task {
        TaskId::SmithG1 => vec![
            StabilityCase {
                input: "smith_g1(w=(1, 0, 0), α=0)".into(),
                why: "grazing on a perfectly smooth surface: 0 · ∞ in the naive form".into(),
                eval: Box::new(move || t.smith_g1(Vec3::X, 0.0).into_output()),
                expect: Expect::near(0.0, 1e-6),
            },
            StabilityCase {
                input: "smith_g1(w=(1, 0, 1e-8), α=0.5)".into(),
                why: "almost grazing: G1 ≈ 2 cos θ / α".into(),
                eval: Box::new(move || t.smith_g1(Vec3::new(1.0, 0.0, 1e-8), 0.5).into_output()),
                expect: Expect::in_range(0.0, 1e-6),
            },
        ],
        TaskId::CosineSample => {
            let below_one = 1.0 - f32::EPSILON / 2.0;
            vec![StabilityCase {
                input: format!("cosine_sample(u=({below_one}, {below_one}))"),
                why: "the largest uniform numbers: cos θ → 0".into(),
                eval: Box::new(move || {
                    let w = t.cosine_sample(Vec2::splat(below_one));
                    vec![w.length() as f64, w.z as f64].into_output()
                }),
                expect: Expect::new(
                    "a unit vector with cos θ ≥ 0 (|w| and cos θ shown)",
                    |o| {
                        matches!(o, crate::grade::output::Output::Numbers(v)
                        if (v[0] - 1.0).abs() < 1e-3 && v[1] >= 0.0 && v[1].is_finite())
                    },
                ),
            }]
        }
        _ => Vec::new(),
    }
}
