//! `pbrlab tasks`: the task table and the scenes' render checks with the student's
//! progress, in 80 columns.

use crate::history::{self, Graded, Progress, Standing};
use crate::scenes::{RENDER_CHECKS, scene_entry};
use crate::status::TaskStatus;
use crate::task::TaskId;
use crate::task_set::TaskSet;

/// Arguments of `pbrlab tasks`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {}

/// The points and status columns of a task: its latest grade when there is one (`6.0/6`,
/// with `*` when the file was edited since), otherwise its points and whether the file is
/// still the shipped stub (`edited`: told from the files without running them).
fn status(task: TaskId, progress: &Progress, attempted: TaskSet) -> (String, String) {
    let points = task.info().points.to_string();
    match progress.get(task.name()) {
        Some(graded) if graded.outcome.max_points > 0.0 => {
            let t = &graded.outcome;
            let stale = if changed_since(task, graded) { "*" } else { "" };
            (
                format!("{:.1}/{}", t.points, t.max_points),
                format!("{}{stale}", t.status.label()),
            )
        }
        Some(graded) if graded.outcome.status == TaskStatus::NoChecks => {
            (points, graded.outcome.status.label())
        }
        _ if attempted.contains(task) => (points, "edited, ungraded".into()),
        _ => (points, "not attempted".into()),
    }
}

/// True when `exercises/<task>.rs` is newer than the task's grade.
fn changed_since(task: TaskId, graded: &Graded<Standing>) -> bool {
    let file = crate::repository_root()
        .join("exercises")
        .join(format!("{}.rs", task.name()));
    std::fs::metadata(file)
        .and_then(|m| m.modified())
        .is_ok_and(|modified| modified > graded.time())
}

/// The points and status columns of a scene's render check: its latest grade, or that it
/// waits for its tasks.
fn scene_status(scene: &str, points: f64, progress: &Progress) -> (String, String) {
    match progress.get(&scene_entry(scene)).map(|g| &g.outcome) {
        Some(t) => match &t.status {
            TaskStatus::NeedsTask { .. } => (points.to_string(), "waits for tasks".into()),
            other => (format!("{:.1}/{}", t.points, t.max_points), other.label()),
        },
        None => (points.to_string(), "waits for tasks".into()),
    }
}

/// The width of a terminal the table fits.
const WIDTH: usize = 80;

/// One row: the entry, its points, its status and its title, the title wrapped at spaces
/// onto lines of its own column so that every line fits in [`WIDTH`] columns.
fn row(entry: &str, points: &str, status: &str, title: &str) -> String {
    let head = format!("{entry:<16} {points:>7}  {status:<17}  ");
    let indent = head.chars().count();
    let room = WIDTH.saturating_sub(indent).max(20);
    let mut lines = vec![String::new()];
    for word in title.split_whitespace() {
        let last = lines.last_mut().expect("one line at least");
        if !last.is_empty() && last.chars().count() + 1 + word.chars().count() > room {
            lines.push(word.to_string());
        } else {
            if !last.is_empty() {
                last.push(' ');
            }
            last.push_str(word);
        }
    }
    let mut text = format!("{head}{}", lines[0]).trim_end().to_string();
    for line in &lines[1..] {
        text += &format!("\n{:indent$}{line}", "");
    }
    text
}

/// Prints the task table and the scenes' render checks with the student's progress, in 80
/// columns: each one's latest `pbrlab grade`, otherwise which tasks are still stubs.
pub fn run(_args: Args) -> anyhow::Result<()> {
    let progress: Progress = history::load_progress();
    let attempted = crate::stubs::edited(crate::repository_root());
    println!("{}", row("task", "points", "status", "title"));
    let mut total = 0.0;
    let mut stale = false;
    for task in TaskId::ALL {
        let info = task.info();
        total += info.points as f64;
        let (points, status) = status(task, &progress, attempted);
        stale |= status.ends_with('*');
        println!("{}", row(info.id, &points, &status, info.title));
    }
    for check in RENDER_CHECKS {
        total += check.points;
        let (points, status) = scene_status(check.scene, check.points, &progress);
        let title = format!("render of scenes/{}.yaml", check.scene);
        println!(
            "{}",
            row(&scene_entry(check.scene), &points, &status, &title)
        );
    }
    println!("{}", row("total", &total.to_string(), "", ""));
    if stale {
        println!("* the exercise file was edited after this grade");
    }
    let scored: f64 = progress
        .values()
        .filter(|g| g.outcome.max_points > 0.0)
        .map(|g| g.outcome.points)
        .sum();
    if progress.is_empty() {
        let pbrlab = super::invocation();
        println!("\nNot graded yet: run `{pbrlab} grade` (or `{pbrlab} watch`).");
    } else {
        println!(
            "\nLatest grades: {scored:.1}/{total} ({}).\nRun `{} grade` again after changing \
             your code.",
            history::progress_path().display(),
            super::invocation()
        );
    }
    Ok(())
}
