//! The `pbrlab` command line: one file per subcommand. The `pbrlab` binary runs it with the
//! reference's table and no student code; the commands that run student code (a render or
//! a convergence study of it) run in `pbrlab-student` instead ([`student_side`]), and the
//! grader's commands send jobs to `pbrlab-worker` ([`crate::grade::isolation`]).

mod autograder;
mod converge;
mod delegate;
mod grade;
mod grade_class;
mod handout;
mod keys;
mod needs;
mod power;
pub mod rebuild;
mod render;
mod secret;
mod similarity;
mod stability;
pub mod student_side;
mod watch;

use clap::{Parser, Subcommand};
use pbrlab_course::cli::{LightCommand, hint};

/// pbrlab: exercises, reference, renderer and grader for a physically based rendering course.
#[derive(Parser, Debug)]
#[command(name = "pbrlab", bin_name = "pbrlab", version)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// `tasks`, `hint` and `reset`: the commands the `pbrlab` binary runs before the rest
    /// is built.
    #[command(flatten)]
    Light(LightCommand),
    /// Grade your tasks (or the reference) and print a report.
    Grade(grade::Args),
    /// Grade every submission in a folder (a subfolder or zip per student): CSV and summary.
    #[command(hide = !cfg!(feature = "solutions"))]
    GradeClass(grade_class::Args),
    /// Compare a class's exercise files for copied code, per task, on this machine (an
    /// HTML page with the matched regions side by side).
    #[command(hide = !cfg!(feature = "solutions"))]
    Similarity(similarity::Args),
    /// Write a Gradescope or PrairieLearn autograder package.
    #[command(hide = !cfg!(feature = "solutions"))]
    Autograder(autograder::Args),
    /// Regrade every time you save a file in exercises/.
    Watch(watch::Args),
    /// Write the student repository (no solutions) into a directory.
    #[command(hide = !cfg!(feature = "solutions"))]
    Handout(handout::Args),
    /// Render a scene to EXR and PNG.
    Render(render::Args),
    /// Show the tasks and subsystems a scene needs.
    Needs(needs::Args),
    /// Run every task on stiff and extreme inputs (grazing angles, α → 0, the critical angle, …).
    Stability(stability::Args),
    /// Error against run time for each sampling strategy: CSV, log-log plot and slopes.
    Converge(converge::Args),
    /// How large an error the statistical checks catch, measured on the reference.
    #[command(hide = !cfg!(feature = "solutions"))]
    Power(power::Args),
}

pub use pbrlab_course::cli::{INVOCATION, invocation};

/// Parses the command line and runs it; an error is printed with its causes. The `main` of
/// the `pbrlab` binary, after it installs the reference's table.
pub fn main() -> std::process::ExitCode {
    finish(run(Cli::parse()))
}

/// The exit code of a command's result, printing the error (and its causes) of a failure.
/// A command `pbrlab-student` ran has printed its own.
pub fn finish(result: anyhow::Result<()>) -> std::process::ExitCode {
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(e) => match e.downcast_ref::<delegate::WorkerExit>() {
            Some(exit) => exit.code(),
            None => {
                eprintln!("error: {e:#}");
                std::process::ExitCode::FAILURE
            }
        },
    }
}

/// Runs the command line.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    // The grader's commands run every job in the worker binary, which must hold the
    // student's code as it is now. (A render or a study of student code hands itself to
    // `pbrlab-student`, rebuilding both first: `student_side`.)
    if matches!(cli.command, Some(Command::Grade(_) | Command::Stability(_))) {
        rebuild::ensure_student_binaries()?;
    }
    match cli.command {
        Some(Command::Light(light)) => light.run(),
        Some(Command::Grade(args)) => grade::run(args),
        Some(Command::GradeClass(args)) => grade_class::run(args),
        Some(Command::Similarity(args)) => similarity::run(args),
        Some(Command::Autograder(args)) => autograder::run(args),
        Some(Command::Watch(args)) => watch::run(args),
        Some(Command::Handout(args)) => handout::run(args),
        Some(Command::Render(args)) => render::run(args),
        Some(Command::Needs(args)) => needs::run(args),
        Some(Command::Stability(args)) => stability::run(args),
        Some(Command::Converge(args)) => converge::run(args),
        Some(Command::Power(args)) => power::run(args),
        None => render::run(render::Args::default()),
    }
}
