//! Keeping the binaries that link the student's code current. The `pbrlab` binary links
//! none: it runs in `pbrlab-worker` (grading jobs) and `pbrlab-student` (a render or study
//! of student code), package `src/worker/`. Before a command that runs student code, this
//! compares both with the newest `exercises/*.rs` and with the running binary (a newer
//! framework), and when one is older, missing, or built from another folder (a class run's
//! submission), rebuilds both with cargo: the student's crate and two links, seconds, with cargo's progress and the compiler's
//! messages as cargo prints them. An exercise file that does not compile is built from its
//! shipped stub ([`crate::grade::student_build`]): the other tasks still grade and render,
//! and the grade reports the compiler's message on it. Commands that run no student code
//! (`tasks`, `needs`, `hint`, a render of the reference) never build anything, and a compile
//! error in an exercise file never stops `pbrlab` itself from starting.

use crate::grade::isolation::{STUDENT_BINARY, beside, worker_beside};
use crate::grade::student_build::{BuildRecord, StudentBuild, same_path};
use anyhow::Context;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// How long a rebuild may take (a first build compiles the framework's worker side too).
const BUILD_DEADLINE: Duration = Duration::from_secs(1800);

/// The newest modification time of a `.rs` file in `dir`.
fn newest_source(dir: &Path) -> Option<SystemTime> {
    std::fs::read_dir(dir)
        .ok()?
        .flatten()
        .filter(|e| e.path().extension().is_some_and(|x| x == "rs"))
        .filter_map(|e| e.metadata().and_then(|m| m.modified()).ok())
        .max()
}

/// The binaries that run the student's code, current.
#[derive(Clone, Debug)]
pub struct StudentBinaries {
    /// `pbrlab-worker`: grading jobs and probes.
    pub worker: PathBuf,
    /// `pbrlab-student`: a render or convergence study of student code.
    pub student: PathBuf,
}

/// The binaries beside the running one that run the student's code, rebuilt first when
/// one is older than an exercise file or than the running binary, missing, or built from
/// another folder.
pub fn ensure_student_binaries() -> anyhow::Result<StudentBinaries> {
    let exe = std::env::current_exe().context("locating this binary")?;
    ensure_student_binaries_beside(&exe)
}

/// [`ensure_student_binaries`] for the binaries beside `exe` (a test names the `pbrlab` it runs),
/// once per process: later calls return the first one's answer.
pub fn ensure_student_binaries_beside(exe: &Path) -> anyhow::Result<StudentBinaries> {
    static ENSURED: std::sync::OnceLock<Result<StudentBinaries, String>> =
        std::sync::OnceLock::new();
    ENSURED
        .get_or_init(|| rebuild_if_stale(exe).map_err(|e| format!("{e:#}")))
        .clone()
        .map_err(anyhow::Error::msg)
}

fn rebuild_if_stale(exe: &Path) -> anyhow::Result<StudentBinaries> {
    let root = crate::repository_root();
    let exercises = root.join("exercises");
    let binaries = StudentBinaries {
        worker: worker_beside(exe),
        student: beside(exe, STUDENT_BINARY),
    };
    let worker = &binaries.worker;
    let modified = |file: &Path| std::fs::metadata(file).and_then(|m| m.modified()).ok();
    // A build from another folder (`grade-class` builds each submission here) is not the
    // student's.
    let elsewhere = BuildRecord::of(worker).is_some_and(|r| !same_path(&r.exercises, &exercises));
    // Cargo links `pbrlab` and the two binaries in one build in any order, so a binary a
    // few milliseconds older than `pbrlab` may be current: the stamp of the last rebuild
    // says which `pbrlab` cargo found them current for.
    let confirmed =
        Confirmed::of(exe, &binaries).is_some_and(|now| Confirmed::read(&binaries) == Some(now));
    let newest = [
        newest_source(&exercises),
        modified(exe).filter(|_| !confirmed),
    ]
    .into_iter()
    .flatten()
    .max();
    let current = |binary: &Path| match (modified(binary), newest) {
        (Some(built), Some(newest)) => built >= newest,
        (built, _) => built.is_some(),
    };
    if current(worker) && current(&binaries.student) && !elsewhere {
        return Ok(binaries);
    }
    eprintln!(
        "pbrlab: building pbrlab-worker and pbrlab-student, which run your code\n\
         (exercises/ or pbrlab is newer than them, or one is missing)"
    );
    let stub = |task| crate::handout::stubs::shipped(root, task);
    let record = StudentBuild {
        root,
        exercises: &exercises,
        commands: true,
        handout: !cfg!(feature = "solutions"),
        stub: &stub,
        echo: true,
        deadline: BUILD_DEADLINE,
        offline: false,
        output: None,
        bounded: false,
    }
    .run()
    .context("fix the error above and run the command again")?;
    anyhow::ensure!(
        same_path(&record.worker, worker),
        "cargo built the worker at {}, not beside this binary ({}): run pbrlab from the \
         target folder cargo builds into",
        record.worker.display(),
        worker.display()
    );
    if let Some(stamp) = Confirmed::of(exe, &binaries) {
        stamp.write(&binaries);
    }
    Ok(binaries)
}

/// The modification times (nanoseconds since 1970) of `pbrlab` and the two binaries when
/// cargo last found the two current for that `pbrlab`: [`CONFIRMED`] beside them.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
struct Confirmed {
    pbrlab: u128,
    worker: u128,
    student: u128,
}

/// The file, beside the binaries, of [`Confirmed`].
const CONFIRMED: &str = "pbrlab-binaries-confirmed.json";

impl Confirmed {
    /// The times of `exe` and `binaries` now (`None` when one is missing).
    fn of(exe: &Path, binaries: &StudentBinaries) -> Option<Self> {
        let nanos = |file: &Path| {
            let time = std::fs::metadata(file).and_then(|m| m.modified()).ok()?;
            Some(time.duration_since(std::time::UNIX_EPOCH).ok()?.as_nanos())
        };
        Some(Self {
            pbrlab: nanos(exe)?,
            worker: nanos(&binaries.worker)?,
            student: nanos(&binaries.student)?,
        })
    }

    /// The stamp written by the last rebuild (`None` when there is none that reads).
    fn read(binaries: &StudentBinaries) -> Option<Self> {
        let text = std::fs::read_to_string(binaries.worker.with_file_name(CONFIRMED)).ok()?;
        serde_json::from_str(&text).ok()
    }

    /// Writes the stamp; a stamp that cannot be written costs a no-op cargo call next time.
    fn write(&self, binaries: &StudentBinaries) {
        if let Ok(text) = serde_json::to_string(self) {
            let _ = crate::atomic_file::write(
                &binaries.worker.with_file_name(CONFIRMED),
                text.as_bytes(),
            );
        }
    }
}
