//! The `pbrlab` binary: see `pbrlab --help`. It links only the course (`pbrlab-course`:
//! the task table, the student's progress, the shipped stubs), so it builds in seconds on a
//! fresh handout. It runs `tasks`, `hint` and `reset` itself, and hands every other command
//! (and `--help`) to `pbrlab-commands` (`src/commands/`: the renderer, the grader and the
//! reference), which it builds first when it is missing or older than its sources
//! ([`pbrlab_course::commands_binary`]).

use clap::Parser;
use pbrlab_course::cli::{Light, LightCommand};
use pbrlab_course::commands_binary;
use std::process::ExitCode;

fn main() -> ExitCode {
    let args: Vec<std::ffi::OsString> = std::env::args_os().collect();
    let light = args
        .get(1)
        .and_then(|a| a.to_str())
        .is_some_and(|a| LightCommand::NAMES.contains(&a));
    let result = if light {
        Light::parse().command.run()
    } else {
        commands_binary::hand_over(&args)
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}
