use crate::grade::report::screen::screen;
use crate::grade::report::{self, Detail, WIDTH};
use crate::grade::verdict::GradeReport;
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
/// student's crate (`rebuild::ensure_student_binaries`: cargo's progress and the compiler's
/// messages shown as they come, a task that does not compile built from its stub). The
/// report comes back as JSON in `report_file`; `None` when the grade did not run (its
/// messages are on the screen), and watching goes on whatever happens.
fn regrade(
    exe: &Path,
    tasks: &[String],
    report_file: &Path,
) -> anyhow::Result<Option<GradeReport>> {
    let status = Command::new(exe)
        .arg("grade")
        .args(tasks)
        .args(["--format", "json", "--output"])
        .arg(report_file)
        .status()
        .with_context(|| format!("running {}", exe.display()))?;
    if !status.success() {
        eprintln!("(not graded: fix the error above and save again)");
        return Ok(None);
    }
    let text = std::fs::read_to_string(report_file)
        .with_context(|| format!("reading {}", report_file.display()))?;
    Ok(Some(serde_json::from_str(&text).with_context(|| {
        format!("reading the report in {}", report_file.display())
    })?))
}

/// The rows of the smallest terminal the watch is drawn for (with [`WIDTH`] columns).
pub const ROWS: usize = 24;

/// The most rows a hint takes under the view (the rest is cut, and `hint` shows it all).
const HINT_ROWS: usize = 12;

/// The keys line: at most [`WIDTH`] characters.
fn keys_line(hint_for: TaskId) -> String {
    report::fit(
        &format!("h: next hint for {hint_for}   f: full report   r: regrade   q: quit"),
        WIDTH,
    )
}

/// Clears the terminal and draws one screen: the view of `report` (the full text with
/// `verbose`), the lines `below` it (the hint of `h`, or none), and the keys.
fn draw(
    report: Option<&GradeReport>,
    previous: Option<&GradeReport>,
    below: &[String],
    hint_for: TaskId,
    verbose: bool,
) -> anyhow::Result<()> {
    let mut out = String::from("\x1b[2J\x1b[H");
    match report {
        Some(r) if verbose => out += &report::text(r, Detail::Verbose),
        Some(r) => {
            for line in screen(r, previous, ROWS - 1 - below.len()) {
                out += &line;
                out.push('\n');
            }
        }
        None => out += "not graded: fix the error and save again\n",
    }
    for line in below {
        out += line;
        out.push('\n');
    }
    out += &keys_line(hint_for);
    out.push('\n');
    print!("{out}");
    std::io::Write::flush(&mut std::io::stdout())?;
    Ok(())
}

/// The next hint of `task` as lines of at most [`WIDTH`] characters, a blank line first,
/// cut to [`HINT_ROWS`].
fn hint_lines(task: TaskId) -> anyhow::Result<Vec<String>> {
    let args = super::hint::Args {
        task: Some(task.name().into()),
        level: None,
        all: false,
    };
    let text = super::hint::hints(task, &args, "`h` again")?;
    let mut lines = vec![String::new()];
    lines.extend(text.lines().flat_map(report::wrap));
    if lines.len() > HINT_ROWS {
        lines.truncate(HINT_ROWS - 1);
        lines.push(format!("… (`hint {task}` shows all of it)"));
    }
    Ok(lines)
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

/// Regrades every time a file in `exercises/` is saved, and redraws one screen (the view
/// of [`screen`], which fits [`WIDTH`]×[`ROWS`] in every state); h shows the next hint
/// under it, f the full report, r regrades, q (or Ctrl-C) stops.
pub fn run(args: Args) -> anyhow::Result<()> {
    let root = crate::repository_root();
    let exercises = root.join("exercises");
    if !exercises.is_dir() {
        bail!("no exercises/ directory in {}", root.display());
    }
    // Taken once: after a rebuild replaces the file, this process's own path names the
    // deleted one.
    let exe = std::env::current_exe().context("locating this binary")?;
    let scratch = tempfile::Builder::new()
        .prefix("pbrlab-watch-")
        .tempdir()
        .context("making a scratch folder")?;
    let report_file = scratch.path().join("report.json");
    let poll = Duration::from_millis(args.poll_ms.max(50));
    let keys = super::keys::Keys::start();
    let mut seen = snapshot(&exercises);
    let mut saved = None;
    let mut report = regrade(&exe, &args.tasks, &report_file)?;
    let mut previous: Option<GradeReport> = None;
    draw(
        report.as_ref(),
        None,
        &[],
        hint_task(saved, &args.tasks),
        args.verbose,
    )?;
    loop {
        let key = keys.next(poll);
        let now = snapshot(&exercises);
        let regrade_now = match key {
            Some('q') => return Ok(()),
            Some('h') => {
                let task = hint_task(saved, &args.tasks);
                let below = hint_lines(task)?;
                draw(
                    report.as_ref(),
                    previous.as_ref(),
                    &below,
                    task,
                    args.verbose,
                )?;
                false
            }
            Some('f') => {
                if let Some(r) = &report {
                    print!("\n{}", report::text(r, Detail::Verbose));
                }
                println!("{}", keys_line(hint_task(saved, &args.tasks)));
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
        // Cargo's progress and the compiler's messages scroll below this line until the
        // grade is in; then the screen is redrawn.
        print!("\x1b[2J\x1b[H");
        println!("{}: rebuilding and regrading…", exercises.display());
        std::io::Write::flush(&mut std::io::stdout())?;
        let graded = regrade(&exe, &args.tasks, &report_file)?;
        if graded.is_some() {
            previous = report.take();
            report = graded;
            draw(
                report.as_ref(),
                previous.as_ref(),
                &[],
                hint_task(saved, &args.tasks),
                args.verbose,
            )?;
        } else {
            // The grade did not run: its messages stay on the screen.
            println!("{}", keys_line(hint_task(saved, &args.tasks)));
        }
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
