//! The `pbrlab-worker` binary: the process in which the grader runs student code, one job
//! per process (see `pbrlab::grade::worker`). It links the student's crate and the
//! renderer, and no reference and nothing of the grader's verdicts: for the tasks a job does
//! not take from the student it loads the reference of each from a library of its own,
//! which the grader names (`pbrlab::grade::references`), never the graded task's. Expected
//! data and reference renders are embedded in the framework library and reachable only
//! from the grader's code, which this `main` never calls, so the linker leaves them out of
//! this file.

use pbrlab::implementation::{Implementations, install};

fn main() {
    install(Implementations {
        student: Some(pbrlab_exercises::TASKS),
        reference: None,
        reference_render: None,
    });
    pbrlab::grade::worker::serve_production()
}
