use crate::grade::history;
use crate::grade::isolation::Launcher;
use crate::grade::verdict::{GradeReport, TaskStatus};
use crate::implementation::student_attempted;
use crate::task_set::TaskSet;
use crate::worksheet::{TaskId, task_functions};

/// Arguments of `pbrlab tasks`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {}

/// The status column of a task: the last grade's verdict when there is one (older than the
/// code, maybe: the table says when it was graded), otherwise whether the stub is replaced
/// (`attempted`, probed in workers).
fn status(task: TaskId, last: Option<&GradeReport>, attempted: TaskSet) -> String {
    match last.and_then(|r| r.task(task.name())) {
        Some(t) if t.max_points > 0.0 => {
            let stale = if changed_since_grade(task) {
                ", edited since"
            } else {
                ""
            };
            format!(
                "{} ({:.1}/{}{stale})",
                t.status.label(),
                t.points,
                t.max_points
            )
        }
        Some(t) if t.status == TaskStatus::NoChecks => t.status.label(),
        _ if task_functions(task).is_empty() => "arrives with the renderer".into(),
        _ if attempted.contains(task) => "implemented, not graded yet".into(),
        _ => "not attempted".into(),
    }
}

/// True when `exercises/<task>.rs` is newer than the last grade.
fn changed_since_grade(task: TaskId) -> bool {
    let modified = |p: &std::path::Path| std::fs::metadata(p).and_then(|m| m.modified()).ok();
    let file = crate::repository_root()
        .join("exercises")
        .join(format!("{}.rs", task.name()));
    matches!((modified(&file), modified(&history::last_grade_path())), (Some(f), Some(g)) if f > g)
}

/// Prints the task table with the student's progress: the last `pbrlab grade` where there
/// is one, otherwise which tasks are still stubs.
pub fn run(_args: Args) -> anyhow::Result<()> {
    let last = history::load().filter(|r| r.implementation != "reference");
    let attempted = student_attempted(&Launcher::current_exe()?);
    println!("{:<16} {:<62} {:>6}  status", "task", "title", "points");
    let mut total = 0;
    for task in TaskId::ALL {
        let info = task.info();
        total += info.points;
        println!(
            "{:<16} {:<62} {:>6}  {}",
            info.id,
            info.title,
            info.points,
            status(task, last.as_ref(), attempted)
        );
    }
    println!("{:<16} {:<62} {:>6}", "total", "", total);
    // Render checks of the last grade: what each scene is waiting for, or how it went.
    for t in last
        .iter()
        .flat_map(|r| &r.tasks)
        .filter(|t| t.task.starts_with("scene: "))
    {
        let status = match &t.status {
            TaskStatus::NeedsTask { task } => format!("waits for {task}"),
            other => format!("{} ({:.1}/{})", other.label(), t.points, t.max_points),
        };
        println!("{:<30} {status}", t.task);
    }
    match &last {
        Some(r) => println!(
            "\nLast grade: {:.1}/{} ({}). Run `pbrlab grade` again after changing your code.",
            r.score,
            r.max_score,
            history::last_grade_path().display()
        ),
        None => println!("\nNot graded yet: run `pbrlab grade` (or `pbrlab watch`)."),
    }
    Ok(())
}
