use crate::grade::history::{self, Graded, Progress};
use crate::grade::renders::RENDER_CHECKS;
use crate::grade::runner::scene_entry;
use crate::grade::verdict::TaskStatus;
use crate::task_set::TaskSet;
use crate::worksheet::{TaskId, task_functions};

/// Arguments of `pbrlab tasks`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {}

/// The status column of a task: its latest grade when there is one (saying when the file
/// was edited since), otherwise whether the file is still the shipped stub (`attempted`:
/// edited, told from the files without running them).
fn status(task: TaskId, progress: &Progress, attempted: TaskSet) -> String {
    match progress.get(task.name()) {
        Some(graded) if graded.outcome.max_points > 0.0 => {
            let stale = if changed_since(task, graded) {
                ", edited since"
            } else {
                ""
            };
            let t = &graded.outcome;
            format!(
                "{} ({:.1}/{}{stale})",
                t.status.label(),
                t.points,
                t.max_points
            )
        }
        Some(graded) if graded.outcome.status == TaskStatus::NoChecks => {
            graded.outcome.status.label()
        }
        _ if task_functions(task).is_empty() => "arrives with the renderer".into(),
        _ if attempted.contains(task) => "edited, not graded yet".into(),
        _ => "not attempted".into(),
    }
}

/// True when `exercises/<task>.rs` is newer than the task's grade.
fn changed_since(task: TaskId, graded: &Graded) -> bool {
    let file = crate::repository_root()
        .join("exercises")
        .join(format!("{}.rs", task.name()));
    std::fs::metadata(file)
        .and_then(|m| m.modified())
        .is_ok_and(|modified| modified > graded.time())
}

/// The status of a scene's render check: its latest grade, or what it waits for.
fn scene_status(scene: &str, progress: &Progress) -> String {
    match progress.get(&scene_entry(scene)).map(|g| &g.outcome) {
        Some(t) => match &t.status {
            TaskStatus::NeedsTask { task } => format!("waits for {task}"),
            other => format!("{} ({:.1}/{})", other.label(), t.points, t.max_points),
        },
        None => "not graded yet (renders once the tasks it needs pass)".into(),
    }
}

/// Prints the task table and the scenes' render checks with the student's progress: each
/// one's latest `pbrlab grade`, otherwise which tasks are still stubs.
pub fn run(_args: Args) -> anyhow::Result<()> {
    let progress = history::load_progress();
    let attempted = crate::handout::stubs::edited(crate::repository_root());
    println!("{:<16} {:<62} {:>6}  status", "task", "title", "points");
    let mut total = 0.0;
    for task in TaskId::ALL {
        let info = task.info();
        total += info.points as f64;
        println!(
            "{:<16} {:<62} {:>6}  {}",
            info.id,
            info.title,
            info.points,
            status(task, &progress, attempted)
        );
    }
    for check in RENDER_CHECKS {
        total += check.points;
        println!(
            "{:<16} {:<62} {:>6}  {}",
            scene_entry(check.scene),
            format!("render of scenes/{}.yaml with your code", check.scene),
            check.points,
            scene_status(check.scene, &progress)
        );
    }
    println!("{:<16} {:<62} {:>6}", "total", "", total);
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
            "\nLatest grades: {scored:.1}/{total} ({}). Run `{} grade` again after changing your code.",
            history::progress_path().display(),
            super::invocation()
        );
    }
    Ok(())
}
