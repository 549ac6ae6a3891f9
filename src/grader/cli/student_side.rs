//! The commands that run student code in their own process: a render (`--impl student` or
//! `mixed`) and a convergence study of it. The `pbrlab` binary links no student code, so it
//! hands such a command line to `pbrlab-student` (package `src/worker/`), which links the
//! student's crate: `delegate` (`src/grader/cli/delegate.rs`) rebuilds it when an exercise file is newer
//! ([`super::rebuild`]) and runs it with the same arguments; its `main` calls [`main`],
//! which takes the reference (for a mix, or a study's ground truth) from its compiled
//! libraries, as a grading worker does, and enters the sandbox before the student's code
//! runs (`render::run`, `converge::run`). The grading worker, `pbrlab-worker`, stays
//! without any of this.

use super::{Cli, Command, converge, render};
use crate::grade::references;
use crate::grade::worker::{ImplSpec, with_references};
use crate::implementation::{ImplChoice, Implementations, install};
use crate::worksheet::TaskFns;
use anyhow::bail;
use clap::Parser;
use std::ffi::OsString;

/// In `pbrlab-student`: runs the command line `args` (`pbrlab`'s, without the program name)
/// with `student`, the student's table this binary links. Only the commands that
/// `delegate` hands on run here.
pub fn main(student: TaskFns, args: impl Iterator<Item = OsString>) -> std::process::ExitCode {
    let cli = Cli::parse_from(std::iter::once(OsString::from("pbrlab")).chain(args));
    super::finish(run(student, cli))
}

fn run(student: TaskFns, cli: Cli) -> anyhow::Result<()> {
    // A mix takes the reference for the tasks not written; a study renders its ground truth
    // with it unless given an image.
    let wants_reference = match &cli.command {
        Some(Command::Render(args)) => args.implementation == Some(ImplChoice::Mixed),
        Some(Command::Converge(args)) => {
            args.implementation == ImplChoice::Mixed || args.reference.is_none()
        }
        _ => false,
    };
    install(Implementations {
        student: Some(student),
        reference: wants_reference.then(reference_from_libraries).flatten(),
        reference_render: None,
    });
    match cli.command {
        None => render::run(render::Args::default()),
        Some(Command::Render(args)) => render::run(args),
        Some(Command::Converge(args)) => converge::run(args),
        Some(other) => bail!("pbrlab-student runs renders and convergence studies, not {other:?}"),
    }
}

/// The whole reference, from the libraries a grading worker loads its tasks' references
/// from ([`references`]): built by cargo in the instructor's repository when stale, the
/// compiled reference in the handout. `None` where there is none.
fn reference_from_libraries() -> Option<TaskFns> {
    if !cfg!(feature = "solutions") {
        return crate::compiled_reference::load_in(crate::repository_root());
    }
    let spec = ImplSpec::Reference;
    let libraries = references::for_spec(&spec)
        .inspect_err(|e| eprintln!("warning: the reference's libraries: {e:#}"))
        .ok()?;
    with_references(TaskFns::ABSENT, &spec, &libraries)
        .inspect_err(|e| eprintln!("warning: the reference's libraries: {e:#}"))
        .ok()
}
