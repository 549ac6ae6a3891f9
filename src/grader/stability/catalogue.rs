//! The catalogue: each task's `src/grader/tasks/<task>/stability.rs` lists the stiff and extreme
//! inputs of that task (ERRATA.md, "Stiff / extreme-case catalogue"), with the right value
//! or limit and the guard that gets there.

pub use crate::tasks::aniso_ndf::stability::{DELTA_PEAK, DELTA_PEAK_MIN};
pub use crate::tasks::delta_tracking::stability::STREAM_STARTING_AT_ZERO;
pub use crate::tasks::refract_stack::stability::stack_report_value;

use super::case::Case;
use crate::worksheet::{TaskId, Tasks};

/// Every case of every task, in worksheet order.
pub fn cases<T: Tasks>() -> Vec<Case<T>> {
    TaskId::ALL.into_iter().flat_map(cases_for::<T>).collect()
}

/// The registry, generated from the list of tasks ([`crate::for_each_task!`]): it
/// dispatches by [`TaskId`] to each task's `src/grader/tasks/<task>/stability.rs`; the match is
/// exhaustive, so a task left out does not compile.
macro_rules! registry {
    ($($variant:ident => $module:ident { $($item:ident),* }),* $(,)?) => {
        /// The cases of one task.
        pub fn cases_for<T: Tasks>(task: TaskId) -> Vec<Case<T>> {
            match task {
                $(TaskId::$variant => crate::tasks::$module::stability::cases(),)*
            }
        }
    };
}

crate::for_each_task!(registry);

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
