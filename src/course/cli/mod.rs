//! The commands that need nothing but the course's table, the student's files and the
//! progress record: `pbrlab tasks`, `pbrlab hint` and `pbrlab reset`. The `pbrlab` binary
//! runs them itself, before anything else is built (`src/front/`); the full command line
//! (the framework's `cli`) lists them with the rest and runs the same code.

pub mod hint;
pub mod reset;
pub mod tasks;

use clap::{Parser, Subcommand};

/// The commands of this crate, as the `pbrlab` binary parses them.
#[derive(Parser, Debug)]
#[command(name = "pbrlab")]
pub struct Light {
    /// What to do.
    #[command(subcommand)]
    pub command: LightCommand,
}

/// The subcommands that run no student code and need no grader (their help text is the
/// full command line's).
#[derive(Subcommand, Debug)]
pub enum LightCommand {
    /// List every task with its points and whether you have attempted it.
    Tasks(tasks::Args),
    /// Show the hints of a task, one level at a time.
    Hint(hint::Args),
    /// Put the shipped stub of a task back (your version is kept in .pbrlab/reset/).
    Reset(reset::Args),
}

impl LightCommand {
    /// The subcommand names, as typed on the command line.
    pub const NAMES: [&str; 3] = ["tasks", "hint", "reset"];

    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            LightCommand::Tasks(args) => tasks::run(args),
            LightCommand::Hint(args) => hint::run(args),
            LightCommand::Reset(args) => reset::run(args),
        }
    }
}

/// The environment variable in which `pbrlab` passes [`invocation`] to a command that
/// `pbrlab-student` runs for it.
pub const INVOCATION: &str = "PBRLAB_INVOCATION";

/// How the user started pbrlab, for messages that name another command (`{} hint TASK`):
/// `cargo run --release --` when cargo started it, the bare name when it was found on
/// `PATH`, otherwise the path as typed (`./target/release/pbrlab`).
pub fn invocation() -> String {
    if let Ok(passed) = std::env::var(INVOCATION) {
        return passed;
    }
    let exe = std::env::current_exe().unwrap_or_default();
    // `cargo run` (and `cargo test`) set the package's variables for the program it runs;
    // the root package, whose binary this is, is `pbrlab-cli`.
    if std::env::var_os("CARGO").is_some()
        && std::env::var("CARGO_PKG_NAME").as_deref() == Ok("pbrlab-cli")
    {
        let profile = if exe.components().any(|c| c.as_os_str() == "debug") {
            ""
        } else {
            " --release"
        };
        return format!("cargo run{profile} --");
    }
    match std::env::args().next() {
        Some(typed) if typed.contains(std::path::MAIN_SEPARATOR) => typed,
        _ => "pbrlab".into(),
    }
}
