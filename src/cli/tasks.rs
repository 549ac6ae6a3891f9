use crate::implementation::student_has_attempted;
use crate::worksheet::TaskId;

/// Arguments of `pbrlab tasks`.
#[derive(clap::Args, Debug, Default)]
pub struct Args {}

/// Prints the task table with the student's status for each task.
pub fn run(_args: Args) -> anyhow::Result<()> {
    println!("{:<16} {:<62} {:>6}  status", "task", "title", "points");
    let mut total = 0;
    for task in TaskId::ALL {
        let info = task.info();
        total += info.points;
        let status = if student_has_attempted(task) {
            "implemented"
        } else {
            "not attempted"
        };
        println!(
            "{:<16} {:<62} {:>6}  {status}",
            info.id, info.title, info.points
        );
    }
    println!("{:<16} {:<62} {:>6}", "total", "", total);
    Ok(())
}
