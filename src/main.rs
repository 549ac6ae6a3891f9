//! The `pbrlab` binary: see `pbrlab --help`.

use clap::Parser;

fn main() -> std::process::ExitCode {
    match pbrlab::cli::run(pbrlab::cli::Cli::parse()) {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
