//! The catalogue: one file per task, mirroring `exercises/`. Each file's `cases` lists
//! the stiff and extreme inputs of that task (ERRATA.md, "Stiff / extreme-case
//! catalogue"), with the right value or limit and the guard that gets there.

mod aniso_ndf;
mod beckmann_ndf;
mod brdf_check;
mod cook_torrance;
mod cosine_sample;
mod delta_tracking;
mod fresnel_schlick;
mod kajiya_kay;
mod mis;
mod ndf_sample;
mod path_trace;
mod phong;
mod reflect;
mod refract_stack;
mod smith_g1;

pub use aniso_ndf::{DELTA_PEAK, DELTA_PEAK_MIN};
pub use delta_tracking::STREAM_STARTING_AT_ZERO;
pub use refract_stack::stack_report_value;

use super::case::Case;
use crate::worksheet::{TaskId, Tasks};

/// Every case of every task, in worksheet order.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    TaskId::ALL.into_iter().flat_map(cases_for::<T>).collect()
}

/// The cases of one task.
pub fn cases_for<T: Tasks>(task: TaskId) -> Vec<Case<T>> {
    match task {
        TaskId::Reflect => reflect::cases(),
        TaskId::RefractStack => refract_stack::cases(),
        TaskId::FresnelSchlick => fresnel_schlick::cases(),
        TaskId::CosineSample => cosine_sample::cases(),
        TaskId::SmithG1 => smith_g1::cases(),
        TaskId::CookTorrance => cook_torrance::cases(),
        TaskId::AnisoNdf => aniso_ndf::cases(),
        TaskId::Phong => phong::cases(),
        TaskId::KajiyaKay => kajiya_kay::cases(),
        TaskId::BeckmannNdf => beckmann_ndf::cases(),
        TaskId::NdfSample => ndf_sample::cases(),
        TaskId::BrdfCheck => brdf_check::cases(),
        TaskId::PathTrace => path_trace::cases(),
        TaskId::Mis => mis::cases(),
        TaskId::DeltaTracking => delta_tracking::cases(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::worksheet::TaskFns;
    use std::collections::HashSet;

    #[test]
    fn names_are_unique_and_start_with_a_function_of_their_task() {
        let all = cases::<TaskFns>();
        let names: HashSet<&str> = all.iter().map(|c| c.name).collect();
        assert_eq!(names.len(), all.len(), "duplicate case names");
        for c in &all {
            let function = c.name.split('/').next().unwrap();
            assert!(
                crate::worksheet::task_functions(c.task).contains(&function),
                "{} does not name a function of task {}",
                c.name,
                c.task
            );
        }
    }

    #[test]
    fn every_task_in_the_trait_has_cases() {
        for task in TaskId::ALL {
            let in_trait = !crate::worksheet::task_functions(task).is_empty();
            let n = cases_for::<TaskFns>(task).len();
            assert!(
                !in_trait || n > 0,
                "task {task} is in the Tasks trait but has no stability cases"
            );
        }
    }
}
