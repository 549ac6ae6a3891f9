//! The grader: checks that score a [`crate::worksheet::Tasks`] implementation task by task.

pub mod probe;
