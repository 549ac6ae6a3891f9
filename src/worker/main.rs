//! The `pbrlab-worker` binary: the one process that links the student's crate, and so the
//! only one in which student code runs (sandboxed first).
//!
//! - Without arguments it serves one grading job (see `pbrlab::grade::worker`). It links the
//!   student's crate and the renderer, and no reference and nothing of the grader's
//!   verdicts: for the tasks a job does not take from the student it loads the reference of
//!   each from a library of its own, which the grader names (`pbrlab::grade::references`),
//!   never the graded task's. Expected data and reference renders are embedded in the
//!   framework library and reachable only from the grader's code, which this `main` never
//!   calls, so the linker leaves them out of this file.
//! - After `--command` it runs a render or a convergence study of student code, the command
//!   line `pbrlab` handed it (`pbrlab::cli::student_side`).

use pbrlab::cli::student_side::{self, COMMAND_MODE};
use pbrlab::implementation::{Implementations, install};

fn main() -> std::process::ExitCode {
    let mut args = std::env::args_os().skip(1).peekable();
    if args.next_if(|a| a == COMMAND_MODE).is_some() {
        return student_side::main(pbrlab_exercises::TASKS, args);
    }
    install(Implementations {
        student: Some(pbrlab_exercises::TASKS),
        reference: None,
    });
    pbrlab::grade::worker::serve_production()
}
