//! The implementations of [`Tasks`](crate::worksheet::Tasks) a binary links: the student's
//! (`exercises/`) and, in the instructor build, the reference (`solutions/`), each a
//! [`TaskFns`] table exported by its own crate.
//!
//! The framework never names those crates: a binary [`install`]s their tables once at start,
//! and framework code reaches them through [`student`], [`reference`] and [`mixed`]. So the
//! student's crate cannot reach the reference through the framework, and an exercise edit
//! recompiles only the exercise crate and the binary's link.

use crate::panics::QuietPanics;
use crate::task_set::TaskSet;
use crate::worksheet::{TaskFns, TaskId};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::{OnceLock, mpsc};
use std::time::{Duration, Instant};

/// The task tables a binary links.
#[derive(Clone, Copy, Debug)]
pub struct Implementations {
    /// The student's code (`exercises/`).
    pub student: TaskFns,
    /// The reference (`solutions/`), absent in the student handout.
    pub reference: Option<TaskFns>,
}

static INSTALLED: OnceLock<Implementations> = OnceLock::new();

/// Makes `implementations` the ones [`student`], [`reference`] and [`mixed`] return. Called
/// once, by the binary's `main` (or a test) before anything runs task code; a second call
/// is ignored.
pub fn install(implementations: Implementations) {
    let _ = INSTALLED.set(implementations);
}

fn installed() -> &'static Implementations {
    INSTALLED.get().expect(
        "no task implementations installed: the binary's main calls \
         pbrlab::implementation::install before running task code",
    )
}

/// The student's code: every task function from `exercises/`.
pub fn student() -> &'static TaskFns {
    &installed().student
}

/// The reference solution, when this build has it (the handout does not).
pub fn try_reference() -> Option<&'static TaskFns> {
    installed().reference.as_ref()
}

/// The reference solution: every task function from `solutions/`.
///
/// # Panics
/// In a build without the reference (the handout); callers there check [`try_reference`].
pub fn reference() -> &'static TaskFns {
    try_reference().expect("this build has no reference solutions")
}

/// A per-task choice: the tasks in `student_tasks` run the student's code, the rest the
/// reference. Because task functions call each other through the table, a student's
/// `cook_torrance` in a mix uses the reference `smith_g1` unless that task is chosen too.
pub fn mixed(student_tasks: TaskSet) -> TaskFns {
    let student = student();
    student_tasks
        .iter()
        .fold(*reference(), |table, task| table.with_task(student, task))
}

/// Which implementation to run, as chosen on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ImplChoice {
    /// Every task from `exercises/`.
    Student,
    /// Every task from `solutions/`.
    Reference,
    /// The student's code for the tasks that are implemented, the reference for the rest.
    Mixed,
}

/// The message of the panic that `todo!()` raises.
const TODO_MESSAGE: &str = "not yet implemented";

/// True when a panic payload is the one `todo!()` or `unimplemented!()` raises.
pub fn is_todo_panic(payload: &(dyn std::any::Any + Send)) -> bool {
    panic_message(payload).is_some_and(|m| m.starts_with(TODO_MESSAGE))
}

/// The text of a panic payload, when it is a string.
pub fn panic_message(payload: &(dyn std::any::Any + Send)) -> Option<&str> {
    payload
        .downcast_ref::<&str>()
        .copied()
        .or_else(|| payload.downcast_ref::<String>().map(String::as_str))
}

/// Runs `f`, turning a panic on this thread into its message without printing it.
pub fn catch_quietly<R>(f: impl FnOnce() -> R) -> Result<R, String> {
    crate::panics::catch(f).map_err(|p| p.message)
}

/// How long a probe waits for the student's code of one task before calling it a hang.
pub const PROBE_TIMEOUT: Duration = Duration::from_secs(3);

/// What one harmless call of each of a task's functions found in the student's code.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Attempt {
    /// The functions still stop at `todo!()`.
    NotAttempted,
    /// The functions return.
    Written,
    /// A function panicked (other than `todo!()`), with this message.
    Panics(String),
    /// A function did not return within [`PROBE_TIMEOUT`] (an infinite loop?).
    Hangs,
}

impl Attempt {
    /// True when the student has written something for the task, working or not.
    pub fn attempted(&self) -> bool {
        !matches!(self, Attempt::NotAttempted)
    }
}

/// Probes the student's code for each of `tasks` with one harmless call per function
/// ([`crate::grade::probe::probe_task`]), all on watchdog threads at once, so code that
/// never returns is reported as [`Attempt::Hangs`] after [`PROBE_TIMEOUT`] instead of
/// hanging the caller. A hung thread keeps running until the process exits. Panics of
/// student code print nothing while the probes run.
pub fn probe_student(tasks: TaskSet) -> Vec<(TaskId, Attempt)> {
    let _quiet = QuietPanics::new();
    let deadline = Instant::now() + PROBE_TIMEOUT;
    let pending: Vec<(TaskId, mpsc::Receiver<Attempt>)> = tasks
        .iter()
        .map(|task| {
            let (tx, rx) = mpsc::channel();
            let spawned = std::thread::Builder::new()
                .name(format!("probe {task}"))
                .spawn(move || {
                    let outcome = catch_unwind(AssertUnwindSafe(|| {
                        crate::grade::probe::probe_task(student(), task)
                    }));
                    let attempt = match outcome {
                        Ok(()) => Attempt::Written,
                        Err(p) if is_todo_panic(p.as_ref()) => Attempt::NotAttempted,
                        Err(p) => Attempt::Panics(
                            panic_message(p.as_ref())
                                .unwrap_or("a non-string panic")
                                .into(),
                        ),
                    };
                    let _ = tx.send(attempt);
                });
            if let Err(e) = spawned {
                let (tx, rx) = mpsc::channel();
                let _ = tx.send(Attempt::Panics(format!("cannot start a probe thread: {e}")));
                return (task, rx);
            }
            (task, rx)
        })
        .collect();
    pending
        .into_iter()
        .map(|(task, rx)| {
            let left = deadline.saturating_duration_since(Instant::now());
            (task, rx.recv_timeout(left).unwrap_or(Attempt::Hangs))
        })
        .collect()
}

/// True when the student has written `task`: its functions no longer stop at `todo!()`
/// (code that panics or hangs counts as written; see [`probe_student`]).
pub fn student_has_attempted(task: TaskId) -> bool {
    probe_student(std::iter::once(task).collect())
        .iter()
        .all(|(_, a)| a.attempted())
}

/// Every task that [`student_has_attempted`], probed all at once.
pub fn student_attempted() -> TaskSet {
    probe_student(TaskSet::all())
        .into_iter()
        .filter(|(_, a)| a.attempted())
        .map(|(t, _)| t)
        .collect()
}

/// Every task whose student code returns on the probe (not a stub, no panic, no hang): what
/// `--impl mixed` takes from the student.
pub fn student_written() -> TaskSet {
    probe_student(TaskSet::all())
        .into_iter()
        .filter(|(_, a)| *a == Attempt::Written)
        .map(|(t, _)| t)
        .collect()
}
