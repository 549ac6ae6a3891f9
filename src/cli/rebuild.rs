//! A binary older than the exercise files it links would grade, render or probe code the
//! student has since changed. Before such a command runs, the binary compares the newest
//! `exercises/*.rs` with its own file and the worker binary's (`pbrlab-worker`, which runs
//! the code for the grader) and, when an exercise is newer or the worker is missing,
//! rebuilds both with cargo
//! (only the student's crate and the link: about a second), compiler messages shown as
//! cargo prints them, and runs the command again in the new binary. An exercise file that
//! does not compile is built from its shipped stub ([`pbrlab::grade::student_build`]): the
//! other tasks still grade and render, and the grade reports the compiler's message on it.

use anyhow::Context;
use pbrlab::grade::isolation::{WORKER_BINARY, worker_beside};
use pbrlab::grade::student_build::{BuildRecord, StudentBuild};
use std::path::Path;
use std::process::Command;
use std::time::{Duration, SystemTime};

/// How long a rebuild may take (the framework is built already: the student's crate and a
/// link take seconds).
const BUILD_DEADLINE: Duration = Duration::from_secs(600);

/// Set in the environment of the re-run, so a rebuild that does not refresh the binary
/// cannot loop.
const REBUILT: &str = "PBRLAB_REBUILT";

/// The newest modification time of a `.rs` file in `dir`.
fn newest_source(dir: &Path) -> Option<SystemTime> {
    std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "rs"))
        .filter_map(|e| e.metadata().and_then(|m| m.modified()).ok())
        .max()
}

/// Rebuilds and re-runs this command when an exercise file is newer than this binary;
/// returns normally when the binary is current (or has just been rebuilt).
pub fn ensure_current() -> anyhow::Result<()> {
    if std::env::var_os(REBUILT).is_some() {
        return Ok(());
    }
    let root = pbrlab::repository_root();
    let Some(source) = newest_source(&root.join("exercises")) else {
        return Ok(());
    };
    let exe = std::env::current_exe().context("locating this binary")?;
    // The worker binary runs the student's code: it must be current too (`cargo run`
    // builds only this one).
    let worker = worker_beside(&exe);
    let built = |file: &Path| std::fs::metadata(file).and_then(|m| m.modified());
    // A build from another folder (`grade-class` builds each submission here) is not the
    // student's.
    let elsewhere = BuildRecord::of(&worker).is_some_and(|r| {
        r.exercises.canonicalize().ok() != root.join("exercises").canonicalize().ok()
    });
    if !elsewhere
        && [&exe, &worker]
            .iter()
            .all(|file| built(file).is_ok_and(|b| b >= source))
    {
        return Ok(());
    }
    eprintln!("rebuilding: exercises/ is newer than the binaries (or pbrlab-worker is missing)");
    let stub = |task| pbrlab::handout::stubs::shipped(root, task);
    StudentBuild {
        root,
        exercises: &root.join("exercises"),
        bins: &["pbrlab", WORKER_BINARY],
        handout: !cfg!(feature = "solutions"),
        stub: &stub,
        echo: true,
        deadline: BUILD_DEADLINE,
        offline: false,
        bounded: false,
    }
    .run()
    .context("fix the error above and run the command again")?;
    let err = exec_again(&exe);
    Err(err).context(format!("running the rebuilt {}", exe.display()))
}

/// Replaces this process with `exe` and the same arguments.
#[cfg(unix)]
fn exec_again(exe: &Path) -> std::io::Error {
    use std::os::unix::process::CommandExt;
    Command::new(exe)
        .args(std::env::args_os().skip(1))
        .env(REBUILT, "1")
        .exec()
}

#[cfg(not(unix))]
fn exec_again(exe: &Path) -> std::io::Error {
    match Command::new(exe)
        .args(std::env::args_os().skip(1))
        .env(REBUILT, "1")
        .status()
    {
        Ok(status) => std::process::exit(status.code().unwrap_or(1)),
        Err(e) => e,
    }
}
