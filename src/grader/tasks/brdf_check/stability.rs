//! Stability cases of the `brdf_check` task.

use crate::sampling::Sampler;
use crate::stability::case::{ANY, Case};
use crate::grade::tolerance::Tolerance;
use crate::stability::expect::{Bound, Expect};
use crate::stability::value::Value;
use crate::worksheet::{TaskId, Tasks};

/// The cases.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    vec![Case {
        task: TaskId::BrdfCheck,
        name: "brdf_check/zero_brdf",
        input: "brdf ≡ 0 (a black surface), 256 samples",
        eval: |t| {
            let mut sampler = Sampler::new(5, 0);
            let r = t.brdf_check(&|_, _| 0.0, &mut sampler, 256);
            Value::record([
                ("min_value", r.min_value as f64),
                ("max_reciprocity_error", r.max_reciprocity_error as f64),
                ("max_albedo", r.max_albedo as f64),
            ])
        },
        range: ANY,
        expect: Expect::Fields(vec![
            ("min_value", Bound::Near(0.0, Tolerance::abs(0.0))),
            (
                "max_reciprocity_error",
                Bound::Near(0.0, Tolerance::abs(0.0)),
            ),
            ("max_albedo", Bound::Near(0.0, Tolerance::abs(0.0))),
        ]),
        guard: "a black surface is plausible: pairs where both values are 0 differ by 0, not 0/0",
    }]
}
