//! `pbrlab reset`: a task's shipped stub back (the student's version kept), or undone.

use crate::stubs;
use crate::task::TaskId;
use anyhow::anyhow;

/// Arguments of `pbrlab reset`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The task whose exercise file goes back to the shipped stub.
    pub task: String,
    /// Undo the last reset of the task instead: its kept version comes back.
    #[arg(long)]
    pub undo: bool,
}

/// Puts the shipped stub of a task back, keeping the student's version in `.pbrlab/reset/`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let task = TaskId::parse(&args.task).map_err(|e| anyhow!(e))?;
    let keep = crate::history::state_dir().join("reset");
    if args.undo {
        match stubs::undo_reset(crate::repository_root(), task, &keep)? {
            None => println!(
                "No reset of {task} to undo (none kept in {}).",
                keep.display()
            ),
            Some(kept) => println!(
                "exercises/{task}.rs is your version from before the reset again ({} restored).",
                kept.display()
            ),
        }
        return Ok(());
    }
    match stubs::reset(crate::repository_root(), task, &keep)? {
        None => println!("exercises/{task}.rs is already the shipped stub."),
        Some(kept) => println!(
            "exercises/{task}.rs is the shipped stub again; your version is in {} \
             (`{} reset --undo {task}` puts it back)",
            kept.display(),
            super::invocation()
        ),
    }
    Ok(())
}
