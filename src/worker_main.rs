//! The `pbrlab-worker` binary: the process in which the grader runs student code, one job
//! per process (see `pbrlab::grade::worker`). It links the student's crate, the reference's
//! (in the instructor build, for the tasks a job does not take from the student) and the
//! renderer, but nothing of the grader's verdicts: no expected data, no reference render.
//! Those are embedded in the framework library and reachable only from the grader's code,
//! which this `main` never calls, so the linker leaves them out of this file.

mod linked_tables;

fn main() {
    linked_tables::install_linked();
    pbrlab::grade::worker::serve_production()
}
