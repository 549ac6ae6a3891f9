//! The `pbrlab-worker` binary: the process in which the grader runs student code, one job
//! per process (see `pbrlab::grade::worker`). It links the student's crate, the reference's
//! (in the instructor build, for the tasks a job does not take from the student) and the
//! renderer, but nothing of the grader's verdicts: no expected data, no reference render.
//! Those are embedded in the framework library and reachable only from the grader's code,
//! which this `main` never calls, so the linker leaves them out of this file.

use pbrlab::implementation::{Implementations, install};

fn main() {
    install(Implementations {
        student: pbrlab_exercises::TASKS,
        #[cfg(feature = "solutions")]
        reference: Some(pbrlab_solutions::TASKS),
        #[cfg(not(feature = "solutions"))]
        reference: None,
    });
    pbrlab::grade::worker::serve_production()
}
