//! The `pbrlab` binary: see `pbrlab --help`. The commands are the framework's
//! (`pbrlab::cli`); this binary hands them the reference's task table (in the instructor
//! build the crate in `solutions/`, in the handout the compiled reference when it fits) and
//! links no student code: the commands that run it start the worker binary, `pbrlab-worker`.

mod linked_tables;

fn main() -> std::process::ExitCode {
    linked_tables::install_linked();
    pbrlab::cli::main()
}
