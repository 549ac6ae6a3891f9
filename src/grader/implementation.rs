//! The implementations of [`Tasks`](crate::worksheet::Tasks) a binary links: the student's
//! (`exercises/`, linked only by `pbrlab-worker` and `pbrlab-student`) and, in the instructor build,
//! the reference (`solutions/`), each a [`TaskFns`] table exported by its own crate.
//!
//! The framework never names those crates: a binary [`install`]s their tables once at start,
//! and framework code reaches them through [`student`], [`reference()`] and [`mixed`]. So the
//! student's crate cannot reach the reference through the framework, and an exercise edit
//! recompiles only the exercise crate and the links of its two binaries. The `pbrlab` binary links no
//! student code at all: its [`student`] table is [`TaskFns::ABSENT`], and its commands that
//! run student code hand them to `pbrlab-student` or the grader's workers
//! (`crate::cli::student_side`, `crate::grade::isolation`).

use crate::grade::isolation::Launcher;
use crate::render::{RenderOptions, RenderOutput, RenderState};
use crate::scene::Scene;
use crate::task_set::TaskSet;
use crate::worksheet::{TaskFns, TaskId};
use std::sync::OnceLock;
use std::time::Duration;

/// The task tables a binary links.
#[derive(Clone, Copy, Debug)]
pub struct Implementations {
    /// The student's code (`exercises/`), in the binaries that link it (`src/worker/`).
    pub student: Option<TaskFns>,
    /// The reference (`solutions/`), absent in the student handout.
    pub reference: Option<TaskFns>,
    /// A render with the reference's functions called directly rather than through
    /// `reference` (so the compiler inlines them), in the binary that links `solutions/`:
    /// `pbrlab render --impl reference` uses it. Never for student code.
    pub reference_render: Option<DirectRender>,
}

/// [`render_from`](crate::render::render_from) compiled for an implementation whose task
/// functions are called directly (`pbrlab_solutions::Direct`): same arguments, same image
/// bit for bit as with its table, without an indirect call per task function.
pub type DirectRender = fn(&Scene, &RenderOptions<'_>, RenderState) -> RenderOutput;

static INSTALLED: OnceLock<Implementations> = OnceLock::new();

/// Makes `implementations` the ones [`student`], [`reference()`] and [`mixed`] return. Called
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

/// The student's code: every task function from `exercises/`; in a process that does not
/// link it, the table whose every function panics ([`TaskFns::ABSENT`]), which is enough for
/// the grader's bookkeeping (which estimators a task has) and runs no student code.
pub fn student() -> &'static TaskFns {
    installed().student.as_ref().unwrap_or(&TaskFns::ABSENT)
}

/// True in a process that links the student's code (`pbrlab-worker`, `pbrlab-student`).
pub fn links_student() -> bool {
    installed().student.is_some()
}

/// The reference solution, when this build has it (the handout does not).
pub fn try_reference() -> Option<&'static TaskFns> {
    installed().reference.as_ref()
}

/// The error for a command that needs the reference in a build without it, with the reason
/// when the handout's compiled reference is missing or unusable
/// ([`crate::compiled_reference`]).
pub fn no_reference() -> String {
    match crate::compiled_reference::unavailable() {
        Some(why) => format!("this build has no reference solutions ({why})"),
        None => "this build has no reference solutions".to_string(),
    }
}

/// The direct render of the reference ([`Implementations::reference_render`]), when this
/// binary links it.
pub fn reference_render() -> Option<DirectRender> {
    installed().reference_render
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

/// Which implementation to run, as chosen on the command line. The commands that render
/// (`render`, `converge`) take every choice everywhere: a handout renders with its compiled
/// reference. The commands that grade take only `student` in a build without the
/// reference (the handout), and hide their `--impl` there ([`GRADES_ONLY_STUDENT`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ImplChoice {
    /// Every task from `exercises/` (a grade takes each task's own code, with the reference,
    /// where the build has it, behind the tasks it builds on).
    Student,
    /// Every task from the reference (`solutions/`, or the handout's compiled reference).
    Reference,
    /// The student's code for the tasks that are implemented, the reference for the rest.
    Mixed,
}

/// True in a build without the reference's source (the handout): grading takes the
/// student's code only, and the options that need the reference (another `--impl`, hidden
/// cases, per-student variants) are left out of `--help`, since they would only fail.
pub const GRADES_ONLY_STUDENT: bool = !cfg!(feature = "solutions");

/// The message of the panic that `todo!()` raises.
pub const TODO_MESSAGE: &str = "not yet implemented";

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
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(tag = "attempt", content = "message", rename_all = "snake_case")]
pub enum Attempt {
    /// The functions still stop at `todo!()`.
    NotAttempted,
    /// The functions return.
    Written,
    /// A function panicked (other than `todo!()`) or brought its process down, with this
    /// message.
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
/// ([`crate::grade::probe::probe_task`]), each task in a sandboxed worker process started by
/// `launcher` ([`crate::grade::isolation`]), so this process never runs student code: code
/// that never returns is reported as [`Attempt::Hangs`] after [`PROBE_TIMEOUT`], code that
/// crashes its worker as [`Attempt::Panics`].
pub fn probe_student(launcher: &Launcher, tasks: TaskSet) -> Vec<(TaskId, Attempt)> {
    use crate::grade::isolation::WorkerFailure;
    use crate::grade::worker::{ImplSpec, Job, JobKind, Record};
    let tasks: Vec<TaskId> = tasks.iter().collect();
    let jobs = tasks
        .iter()
        .map(|task| Job {
            nonce: crate::grade::isolation::nonce(),
            implementation: ImplSpec::Student,
            kind: JobKind::Probe {
                task: task.name().into(),
            },
            memory_limit: crate::grade::runner::DEFAULT_MEMORY_LIMIT,
        })
        .collect();
    let options = crate::grade::runner::GradeOptions {
        timeout: PROBE_TIMEOUT,
        ..Default::default()
    };
    let runs = crate::grade::runner::run_all(launcher, jobs, &options);
    tasks
        .into_iter()
        .zip(runs)
        .map(|(task, run)| {
            let attempt = match run.outcome {
                Ok(Record::Attempted { attempt }) => attempt,
                Ok(other) => Attempt::Panics(format!("the probe answered {other:?}")),
                Err(WorkerFailure::Student(reason)) if reason.starts_with("timed out") => {
                    Attempt::Hangs
                }
                Err(WorkerFailure::Student(reason) | WorkerFailure::Grader(reason)) => {
                    Attempt::Panics(reason)
                }
            };
            (task, attempt)
        })
        .collect()
}

/// True when the student has written `task`: its functions no longer stop at `todo!()`
/// (code that panics or hangs counts as written; see [`probe_student`]).
pub fn student_has_attempted(launcher: &Launcher, task: TaskId) -> bool {
    probe_student(launcher, std::iter::once(task).collect())
        .iter()
        .all(|(_, a)| a.attempted())
}

/// Every task that [`student_has_attempted`], probed all at once.
pub fn student_attempted(launcher: &Launcher) -> TaskSet {
    probe_student(launcher, TaskSet::all())
        .into_iter()
        .filter(|(_, a)| a.attempted())
        .map(|(t, _)| t)
        .collect()
}

/// Every task whose student code returns on the probe (not a stub, no panic, no hang): what
/// `--impl mixed` takes from the student.
pub fn student_written(launcher: &Launcher) -> TaskSet {
    probe_student(launcher, TaskSet::all())
        .into_iter()
        .filter(|(_, a)| *a == Attempt::Written)
        .map(|(t, _)| t)
        .collect()
}
