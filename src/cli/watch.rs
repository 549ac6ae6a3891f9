use crate::worksheet::TaskId;
use anyhow::{Context, bail};
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, SystemTime};

/// Arguments of `pbrlab watch`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Tasks to regrade (default: every task).
    pub tasks: Vec<String>,
    /// How often to look for changes, in milliseconds.
    #[arg(long, default_value_t = 500)]
    pub poll_ms: u64,
    /// Every row and every line of what failed (`grade --verbose`).
    #[arg(short, long)]
    pub verbose: bool,
}

/// Modification times of every file under `dir`.
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, SystemTime> {
    let mut times = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).into_iter().flatten().flatten() {
            let path = entry.path();
            match entry.metadata() {
                Ok(m) if m.is_dir() => stack.push(path),
                Ok(m) => {
                    times.insert(path, m.modified().unwrap_or(SystemTime::UNIX_EPOCH));
                }
                Err(_) => {}
            }
        }
    }
    times
}

/// Regrades in a new process of this binary, whose first step rebuilds the worker with the
/// student's crate (`rebuild::ensure_student_binaries`: cargo's progress and the compiler's messages shown as they
/// come, a task that does not compile built from its stub); the grader's own table is the
/// output, and watching goes on whatever happens.
fn regrade(exe: &Path, tasks: &[String], verbose: bool) -> anyhow::Result<()> {
    let status = Command::new(exe)
        .arg("grade")
        .args(tasks)
        .args(verbose.then_some("--verbose"))
        .status()
        .with_context(|| format!("running {}", exe.display()))?;
    if !status.success() {
        eprintln!("(not graded: fix the error above and save again)");
    }
    Ok(())
}

/// The task whose hint `h` shows: the task of the file saved last, else the first task
/// named on the command line, else the first task in worksheet order whose latest grade
/// is not full marks.
fn hint_task(saved: Option<TaskId>, named: &[String]) -> TaskId {
    saved
        .or_else(|| named.iter().find_map(|n| TaskId::parse(n).ok()))
        .unwrap_or_else(super::hint::next_task)
}

/// The task of the most recently modified exercise file among those that changed.
fn saved_task(
    before: &BTreeMap<PathBuf, SystemTime>,
    now: &BTreeMap<PathBuf, SystemTime>,
) -> Option<TaskId> {
    now.iter()
        .filter(|(path, time)| before.get(*path) != Some(time))
        .filter_map(|(path, time)| {
            let stem = path.file_stem()?.to_str()?;
            let task = TaskId::ALL.into_iter().find(|t| t.name() == stem)?;
            Some((task, *time))
        })
        .max_by_key(|(_, time)| *time)
        .map(|(task, _)| task)
}

/// Prints what the keys do.
fn prompt(exercises: &Path, hint_for: TaskId) {
    println!(
        "\nWatching {} — save a file to regrade.\n  h: next hint for {hint_for}   r: regrade   q: quit",
        exercises.display()
    );
}

/// Regrades every time a file in `exercises/` is saved; h shows the next hint, r regrades,
/// q (or Ctrl-C) stops.
pub fn run(args: Args) -> anyhow::Result<()> {
    let root = crate::repository_root();
    let exercises = root.join("exercises");
    if !exercises.is_dir() {
        bail!("no exercises/ directory in {}", root.display());
    }
    // Taken once: after a rebuild replaces the file, this process's own path names the
    // deleted one.
    let exe = std::env::current_exe().context("locating this binary")?;
    let poll = Duration::from_millis(args.poll_ms.max(50));
    let keys = super::keys::Keys::start();
    let mut seen = snapshot(&exercises);
    let mut saved = None;
    regrade(&exe, &args.tasks, args.verbose)?;
    prompt(&exercises, hint_task(saved, &args.tasks));
    loop {
        let key = keys.next(poll);
        let now = snapshot(&exercises);
        let regrade_now = match key {
            Some('q') => return Ok(()),
            Some('h') => {
                let task = hint_task(saved, &args.tasks);
                println!();
                let args = super::hint::Args {
                    task: Some(task.name().into()),
                    level: None,
                    all: false,
                };
                super::hint::show(task, &args, "`h` again")?;
                prompt(&exercises, task);
                false
            }
            Some('r') => true,
            _ => now != seen,
        };
        if !regrade_now {
            continue;
        }
        if now != seen {
            // Editors often write a file in several steps; let the save settle.
            std::thread::sleep(poll);
        }
        let settled = snapshot(&exercises);
        saved = saved_task(&seen, &settled).or(saved);
        seen = settled;
        // Clear the screen now: unflushed, the escape went out after the new table and
        // erased it.
        print!("\x1b[2J\x1b[H");
        println!("{}: rebuilding and regrading…", exercises.display());
        std::io::Write::flush(&mut std::io::stdout())?;
        regrade(&exe, &args.tasks, args.verbose)?;
        prompt(&exercises, hint_task(saved, &args.tasks));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_save_changes_the_snapshot() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("reflect.rs");
        std::fs::write(&file, "todo!()").unwrap();
        let before = snapshot(dir.path());
        assert_eq!(before.len(), 1);
        let later = SystemTime::now() + Duration::from_secs(5);
        std::fs::File::options()
            .write(true)
            .open(&file)
            .unwrap()
            .set_modified(later)
            .unwrap();
        assert_ne!(snapshot(dir.path()), before);
        std::fs::create_dir(dir.path().join("sub")).unwrap();
        std::fs::write(dir.path().join("sub/new.rs"), "").unwrap();
        assert_eq!(
            snapshot(dir.path()).len(),
            2,
            "files in subfolders count too"
        );
    }

    #[test]
    fn the_hint_follows_the_task_file_saved_last() {
        let t0 = SystemTime::UNIX_EPOCH + Duration::from_secs(100);
        let later = t0 + Duration::from_secs(5);
        let before: BTreeMap<PathBuf, SystemTime> = [
            ("exercises/smith_g1.rs", t0),
            ("exercises/reflect.rs", t0),
            ("exercises/notes.rs", t0),
        ]
        .into_iter()
        .map(|(p, t)| (PathBuf::from(p), t))
        .collect();
        let mut now = before.clone();
        assert_eq!(saved_task(&before, &now), None);
        now.insert("exercises/smith_g1.rs".into(), later);
        now.insert("exercises/notes.rs".into(), later + Duration::from_secs(1));
        // notes.rs is no task's file: the task saved last is smith_g1.
        assert_eq!(saved_task(&before, &now), Some(TaskId::SmithG1));
        assert_eq!(
            hint_task(Some(TaskId::SmithG1), &["reflect".into()]),
            TaskId::SmithG1
        );
        assert_eq!(hint_task(None, &["reflect".into()]), TaskId::Reflect);
    }
}
