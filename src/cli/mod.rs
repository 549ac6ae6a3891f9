//! The `pbrlab` command line: one file per subcommand.

mod autograder;
mod converge;
mod grade;
mod grade_class;
mod handout;
mod hint;
mod keys;
mod needs;
mod power;
mod rebuild;
pub mod render;
mod reset;
mod stability;
mod tasks;
mod watch;

use clap::{Parser, Subcommand};

/// pbrlab: exercises, reference, renderer and grader for a physically based rendering course.
#[derive(Parser, Debug)]
#[command(name = "pbrlab", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// List every task with its points and whether you have attempted it.
    Tasks(tasks::Args),
    /// Show the hints of a task, one level at a time.
    Hint(hint::Args),
    /// Grade your tasks (or the reference) and print a report.
    Grade(grade::Args),
    /// Grade every submission in a folder (a subfolder or zip per student): CSV and summary.
    #[command(hide = !cfg!(feature = "solutions"))]
    GradeClass(grade_class::Args),
    /// Write a Gradescope or PrairieLearn autograder package.
    #[command(hide = !cfg!(feature = "solutions"))]
    Autograder(autograder::Args),
    /// Regrade every time you save a file in exercises/.
    Watch(watch::Args),
    /// Put the shipped stub of a task back (your version is kept in .pbrlab/reset/).
    Reset(reset::Args),
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

/// Runs the command line.
pub fn run(cli: Cli) -> anyhow::Result<()> {
    // Commands that run the student's code run the code as it is now (the default, a
    // render, renders the student's code in the handout).
    if matches!(
        cli.command,
        None | Some(
            Command::Tasks(_)
                | Command::Grade(_)
                | Command::Handout(_)
                | Command::Render(_)
                | Command::Needs(_)
                | Command::Stability(_)
                | Command::Converge(_)
        )
    ) {
        rebuild::ensure_current()?;
    }
    match cli.command {
        Some(Command::Tasks(args)) => tasks::run(args),
        Some(Command::Hint(args)) => hint::run(args),
        Some(Command::Grade(args)) => grade::run(args),
        Some(Command::GradeClass(args)) => grade_class::run(args),
        Some(Command::Autograder(args)) => autograder::run(args),
        Some(Command::Watch(args)) => watch::run(args),
        Some(Command::Reset(args)) => reset::run(args),
        Some(Command::Handout(args)) => handout::run(args),
        Some(Command::Render(args)) => render::run(args),
        Some(Command::Needs(args)) => needs::run(args),
        Some(Command::Stability(args)) => stability::run(args),
        Some(Command::Converge(args)) => converge::run(args),
        Some(Command::Power(args)) => power::run(args),
        None => render::run(render::Args::default()),
    }
}
