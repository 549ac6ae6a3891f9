//! `pbrlab-commands`: every `pbrlab` command (`pbrlab::cli`), with the reference's task
//! table (in the instructor build the crate in `solutions/`, in the handout the compiled
//! reference when it fits) and no student code: the commands that run it start the worker
//! binary, `pbrlab-worker`. The `pbrlab` binary (`src/front/`) runs `tasks`, `hint` and
//! `reset` itself and hands every other command to this one, building it first when needed.

mod linked_tables;

fn main() -> std::process::ExitCode {
    linked_tables::install_linked();
    pbrlab::cli::main()
}
