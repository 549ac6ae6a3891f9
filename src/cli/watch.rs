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

/// Regrades in a new process of this binary, whose first step rebuilds the student's crate
/// (`rebuild::ensure_current`: cargo's progress and the compiler's messages shown as they
/// come, a task that does not compile built from its stub); the grader's own table is the
/// output, and watching goes on whatever happens.
fn regrade(exe: &Path, tasks: &[String]) -> anyhow::Result<()> {
    let status = Command::new(exe)
        .arg("grade")
        .args(tasks)
        .status()
        .with_context(|| format!("running {}", exe.display()))?;
    if !status.success() {
        eprintln!("(not graded: fix the error above and save again)");
    }
    Ok(())
}

/// Regrades every time a file in `exercises/` is saved.
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
    let mut seen = snapshot(&exercises);
    regrade(&exe, &args.tasks)?;
    println!(
        "\nWatching {} — save a file to regrade, Ctrl-C to stop.",
        exercises.display()
    );
    loop {
        std::thread::sleep(poll);
        let now = snapshot(&exercises);
        if now != seen {
            // Editors often write a file in several steps; let the save settle.
            std::thread::sleep(poll);
            seen = snapshot(&exercises);
            // Clear the screen now: unflushed, the escape went out after the new table and
            // erased it.
            print!("\x1b[2J\x1b[H");
            println!("{} changed: rebuilding and regrading…", exercises.display());
            std::io::Write::flush(&mut std::io::stdout())?;
            regrade(&exe, &args.tasks)?;
            println!(
                "\nWatching {} — save a file to regrade, Ctrl-C to stop.",
                exercises.display()
            );
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
}
