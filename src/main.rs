//! The `pbrlab` binary: see `pbrlab --help`. It links the student's crate (`exercises/`)
//! and, in the instructor build, the reference's (`solutions/`), and hands their task
//! tables to the framework.

mod cli;
mod linked_tables;

use clap::Parser;

fn main() -> std::process::ExitCode {
    linked_tables::install_linked();
    match cli::run(cli::Cli::parse()) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
