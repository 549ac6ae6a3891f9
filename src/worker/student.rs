//! The `pbrlab-student` binary: a render or a convergence study of student code, the
//! command line `pbrlab` hands on (`pbrlab::cli::student_side`). It links the student's
//! crate; the reference, for a mix or a study's ground truth, comes from the reference's
//! compiled libraries, and the command enters the sandbox before the student's code runs.

fn main() -> std::process::ExitCode {
    pbrlab::cli::student_side::main(pbrlab_exercises::TASKS, std::env::args_os().skip(1))
}
