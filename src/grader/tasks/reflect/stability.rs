//! Stability cases of the `reflect` task.

use crate::stability::case::{Case, DIRECTION};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::Expect;
use crate::stability::inputs::errata_unit_vector;
use crate::worksheet::{TaskId, Tasks};
use glam::Vec3;

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![
        Case {
            task: TaskId::Reflect,
            name: "reflect/non_unit_normal",
            input: "wo = (−0.6, 0.8, 0), n = (0, 2, 0)",
            eval: |t| {
                t.reflect(Vec3::new(-0.6, 0.8, 0.0), Vec3::new(0.0, 2.0, 0.0))
                    .into()
            },
            range: DIRECTION,
            expect: Expect::vector([0.6, 0.8, 0.0], Tolerance::abs(1e-6)),
            guard: "normalise n: with |n| = 2 the textbook formula gives (0.6, 5.6, 0)",
        },
        Case {
            task: TaskId::Reflect,
            name: "reflect/grazing",
            input: "wo = (−1, 0, 0) in the surface plane, n = (0, 0, 1)",
            eval: |t| t.reflect(Vec3::new(-1.0, 0.0, 0.0), Vec3::Z).into(),
            range: DIRECTION,
            expect: Expect::vector([1.0, 0.0, 0.0], Tolerance::abs(1e-6)),
            guard: "a grazing ray continues unchanged: wo·n = 0 leaves only −wo",
        },
        Case {
            task: TaskId::Reflect,
            name: "reflect/cos_above_one",
            input: "wo = n = the errata's f32-normalised vector (wo·n = 1.0000001)",
            eval: |t| t.reflect(errata_unit_vector(), errata_unit_vector()).into(),
            range: DIRECTION,
            expect: Expect::Near(errata_unit_vector().into(), Tolerance::abs(1e-6)),
            guard: "reflecting the normal gives the normal; nothing here may take sqrt(1 − c²)",
        },
    ]
}
