//! The implementations the tests grade the grader with, from each task's
//! `src/grader/tasks/<task>/variants.rs` (one module per task, generated from
//! [`pbrlab::for_each_task!`]): known-wrong, correct-but-different and naive ones.

use super::patch::{Patch, Variant};
use pbrlab::stability::Verdict;
use pbrlab::task_set::TaskSet;
use pbrlab::worksheet::TaskId;

/// A naive implementation of a task (the textbook formula without its guards): the
/// reference with the naive functions, in force for every task (so a flaw propagates to
/// the tasks that use it, as a student's would), and the stability cases it must fail.
pub struct Naive {
    /// What it gets wrong.
    pub name: &'static str,
    /// The implementation.
    pub patch: Patch,
    /// Exactly the stability cases it fails, with the verdict of each.
    pub fails: Vec<(&'static str, Verdict)>,
}

impl Naive {
    /// The naive implementation `name` of `task`, whose patch `set` fills in.
    pub fn new(
        name: &'static str,
        task: TaskId,
        set: impl FnOnce(&mut Patch),
        fails: Vec<(&'static str, Verdict)>,
    ) -> Self {
        let mut patch = Patch::new(task).only(TaskSet::all());
        set(&mut patch);
        Self { name, patch, fails }
    }
}

/// One module per task holding its `variants.rs`, and the catalogues over all tasks.
macro_rules! variants {
    ($($variant:ident => $module:ident { $($item:ident),* }),* $(,)?) => {
        $(
            #[doc = concat!("The variants of `", stringify!($module), "`.")]
            pub mod $module {
                include!(concat!(
                    env!("CARGO_MANIFEST_DIR"), "/src/grader/tasks/", stringify!($module), "/variants.rs"
                ));
            }
        )*

        /// Every known-wrong implementation, in worksheet order: each must fail its own
        /// task and no other.
        pub fn wrong() -> Vec<Variant> {
            [$($module::wrong()),*].into_iter().flatten().collect()
        }

        /// Every correct implementation that differs from the reference: each gets full
        /// marks.
        pub fn different() -> Vec<Variant> {
            [$($module::different()),*].into_iter().flatten().collect()
        }

        /// Every naive implementation, with the stability cases it must fail.
        pub fn naive() -> Vec<Naive> {
            [$($module::naive()),*].into_iter().flatten().collect()
        }
    };
}

pbrlab::for_each_task!(variants);

/// The naive implementation named `name`.
pub fn naive_named(name: &str) -> Patch {
    naive()
        .into_iter()
        .find(|n| n.name == name)
        .unwrap_or_else(|| panic!("no naive implementation is named {name:?}"))
        .patch
}
