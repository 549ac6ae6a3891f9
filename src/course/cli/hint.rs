//! `pbrlab hint`: a task's hints ([`crate::task::TaskInfo::hints`]), one level at a time,
//! the levels shown remembered in `.pbrlab/hints-seen.json`.

use crate::history::{Progress, state_dir};
use crate::status::TaskStatus;
use crate::task::TaskId;
use anyhow::{Context, anyhow};
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Arguments of `pbrlab hint`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The task (its id, or a unique prefix of it); without one, the first task in worksheet
    /// order that has not passed yet.
    pub task: Option<String>,
    /// Show the hints up to this level (1 is the gentlest) instead of the next unseen one.
    #[arg(long, conflicts_with = "all")]
    pub level: Option<usize>,
    /// Show every hint of the task, the last of which comes close to the answer.
    #[arg(long)]
    pub all: bool,
}

/// The file that remembers, per task, how many hint levels have been shown.
fn seen_path() -> PathBuf {
    state_dir().join("hints-seen.json")
}

/// Levels shown so far, per task id (an unreadable file counts as nothing seen).
fn load_seen() -> BTreeMap<String, usize> {
    std::fs::read_to_string(seen_path())
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok())
        .unwrap_or_default()
}

/// Shows the task's next unseen hint (or the levels asked for) and remembers it, so the
/// next call goes one level further: one step at a time, as the hints are written.
pub fn run(args: Args) -> anyhow::Result<()> {
    let task = match &args.task {
        Some(task) => TaskId::parse(task).map_err(|e| anyhow!(e))?,
        None => {
            let task = next_task();
            println!(
                "(the first task that has not passed yet; `{} hint TASK` for another)\n",
                super::invocation()
            );
            task
        }
    };
    let again = format!("`{} hint {}` again", super::invocation(), task.name());
    show(task, &args, &again)
}

/// The first task in worksheet order whose latest grade (`pbrlab tasks`) is not full marks:
/// the one to work on next.
pub fn next_task() -> TaskId {
    let progress: Progress = crate::history::load_progress();
    TaskId::ALL
        .into_iter()
        .find(|t| {
            progress
                .get(t.name())
                .is_none_or(|g| g.outcome.status != TaskStatus::Passed)
        })
        .unwrap_or(TaskId::ALL[0])
}

/// [`run`] for `task`; `again` says how to ask for the next level (the command, or a key
/// in `pbrlab watch`).
pub fn show(task: TaskId, args: &Args, again: &str) -> anyhow::Result<()> {
    print!("{}", hints(task, args, again)?);
    Ok(())
}

/// The text [`show`] prints, the levels it shows remembered as seen.
pub fn hints(task: TaskId, args: &Args, again: &str) -> anyhow::Result<String> {
    use std::fmt::Write;
    let mut out = String::new();
    let info = task.info();
    let levels = info.hints.len();
    if levels == 0 {
        writeln!(out, "{} has no hints.", info.id)?;
        return Ok(out);
    }
    let mut seen = load_seen();
    let before = seen.get(info.id).copied().unwrap_or(0).min(levels);
    let (first, last) = match (args.all, args.level) {
        (true, _) => (1, levels),
        (false, Some(level)) => (1, level.clamp(1, levels)),
        (false, None) => {
            let next = (before + 1).min(levels);
            (next, next)
        }
    };
    writeln!(
        out,
        "{} — {} (worksheet {}, exercises/{}.rs)",
        info.id, info.title, info.section, info.id
    )?;
    for (i, hint) in info.hints.iter().enumerate().take(last).skip(first - 1) {
        writeln!(out, "\nhint {}/{}: {}", i + 1, levels, hint)?;
    }
    if first > 1 {
        let earlier = match first - 1 {
            1 => "level 1".to_string(),
            n => format!("levels 1–{n}"),
        };
        writeln!(
            out,
            "\n({earlier} shown before: `{} hint {} --level {}` shows them again)",
            super::invocation(),
            info.id,
            first - 1
        )?;
    }
    if last < levels {
        writeln!(out, "\nStill stuck? {again} shows hint {}.", last + 1)?;
    } else if args.level.is_none() && !args.all && before == levels {
        writeln!(out, "\nThat was the last hint of {}.", info.id)?;
    }
    if last > before {
        seen.insert(info.id.to_string(), last);
        let path = seen_path();
        crate::atomic_file::write(&path, serde_json::to_string_pretty(&seen)?.as_bytes())
            .with_context(|| format!("remembering the hints shown in {}", path.display()))?;
    }
    Ok(out)
}
