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

/// Rebuilds with cargo and regrades with the new binary; the grader's own table is the
/// output. Cargo's progress and any build error are shown as cargo prints them, and
/// watching goes on.
fn regrade(root: &Path, tasks: &[String]) -> anyhow::Result<()> {
    let mut cargo = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    cargo.current_dir(root).args(["run", "--release"]);
    if !cfg!(feature = "solutions") {
        cargo.arg("--no-default-features");
    }
    cargo.args(["--", "grade"]).args(tasks);
    let status = cargo.status().context("running cargo")?;
    if !status.success() {
        eprintln!("(not graded: fix the build error above and save again)");
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
    let poll = Duration::from_millis(args.poll_ms.max(50));
    let mut seen = snapshot(&exercises);
    regrade(root, &args.tasks)?;
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
            regrade(root, &args.tasks)?;
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
