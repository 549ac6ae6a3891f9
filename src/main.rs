//! The `pbrlab` binary: see `pbrlab --help`. It links the student's crate (`exercises/`)
//! and, in the instructor build, the reference's (`solutions/`), and hands their task
//! tables to the framework.

use clap::Parser;
use pbrlab::implementation::{Implementations, install};

fn main() -> std::process::ExitCode {
    install(Implementations {
        student: pbrlab_exercises::TASKS,
        #[cfg(feature = "solutions")]
        reference: Some(pbrlab_solutions::TASKS),
        #[cfg(not(feature = "solutions"))]
        reference: None,
    });
    match pbrlab::cli::run(pbrlab::cli::Cli::parse()) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
