//! The child side of isolation: a worker process grades one task and reports back.
//!
//! The grader starts a worker (the `pbrlab-worker` binary, which has no expected data in
//! it) per task and writes a [`Job`]
//! to its stdin. The worker reads the whole job before any student code runs, limits its own
//! address space, runs the checks, and prints one line `PBRLAB-RESULT <nonce> <json>` on
//! stdout. What it sends back is raw outputs only (values, samples, estimates, images,
//! stability values: [`Raw`]), never a verdict: the grader holds the expected data and
//! judges them. The nonce is a fresh random string the student's code never sees (stdin is
//! drained first), and a worker that exits without a result line has crashed.

use super::measure::{Progress, ProgressSink, run_task};
use super::sandbox::{self, Policy};
use super::wire::{Raw, StabilityOutput, WorkerInput};
use crate::panics;
use crate::worksheet::{TaskId, Tasks};
use anyhow::anyhow;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::{Read, Write};
use std::path::PathBuf;

/// The marker that starts the result line.
pub const RESULT_MARKER: &str = "PBRLAB-RESULT";

/// The marker of the line a worker prints before each check (and each stability case)
/// runs, followed by the nonce and the check's name: when the worker dies, the last such
/// line says where.
pub const STEP_MARKER: &str = "PBRLAB-STEP";

/// The marker of the line a worker prints when raw outputs are ready (a values check's
/// outputs, a sampling check's counts, …), followed by the nonce and the [`Raw`] as JSON:
/// the grader judges them, and keeps them when the worker dies later.
pub const RAW_MARKER: &str = "PBRLAB-RAW";

/// The marker of the line a worker prints after each [`RAW_MARKER`] line, followed by the
/// nonce and the most resident memory the worker has held so far, in KiB: the peak memory
/// of the checks up to that one, for the class's item analysis (data, never a verdict).
pub const PEAK_MARKER: &str = "PBRLAB-PEAK";

/// The marker of the line a worker prints once it has its job and has entered its sandbox,
/// before any student code runs, followed by the nonce and the [`sandbox::Protections`] in
/// force as JSON: a worker that ends without it failed to start (the grader's fault, not the
/// code's).
pub const STARTED_MARKER: &str = "PBRLAB-STARTED";

/// Which implementation a worker runs for the graded task.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(tag = "impl", rename_all = "snake_case")]
pub enum ImplSpec {
    /// The reference for every task.
    Reference,
    /// The student's code for every task.
    Student,
    /// The student's code for the listed tasks, the reference for the rest.
    Mixed {
        /// Task ids that run the student's code.
        student: Vec<String>,
    },
}

impl ImplSpec {
    /// The tasks that run the student's code.
    pub fn student_tasks(&self) -> crate::task_set::TaskSet {
        match self {
            ImplSpec::Reference => crate::task_set::TaskSet::EMPTY,
            ImplSpec::Student => crate::task_set::TaskSet::all(),
            ImplSpec::Mixed { student } => student
                .iter()
                .filter_map(|s| TaskId::parse(s).ok())
                .collect(),
        }
    }
}

/// What a worker is asked to do.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "job", rename_all = "snake_case")]
pub enum JobKind {
    /// Run every check of a task.
    Grade {
        /// The task id.
        task: String,
        /// Its calls, samplers and seed: no expected value, no reference density.
        input: WorkerInput,
    },
    /// Only tell whether the student has written the task.
    Probe {
        /// The task id.
        task: String,
    },
    /// Run one case of the stability catalogue (`pbrlab stability` runs each in a worker,
    /// so a case that crashes its process is reported and the others still run).
    Stability {
        /// The case's name (`smith_g1/alpha_zero`).
        case: String,
    },
    /// Render a scene (the grader compares it with the stored reference render).
    Render {
        /// The scene's name (see [`super::renders::RENDER_CHECKS`]).
        scene: String,
        /// Seed of the render.
        seed: u64,
    },
}

/// What the grader writes to a worker's stdin: the job, the reference libraries it may
/// load, and the sandbox to run it in.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Delivery {
    /// The job.
    pub job: Job,
    /// For each task the job takes from the reference (every task its [`ImplSpec`] does not
    /// take from the student), the shared library that holds it
    /// ([`super::references`]): one task's reference per library in the instructor's build,
    /// so the graded task's is never in the worker. Loaded before the sandbox closes.
    #[serde(default)]
    pub references: BTreeMap<String, PathBuf>,
    /// What the worker may do while it runs the job.
    pub sandbox: Policy,
}

/// A job for a worker process.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Job {
    /// The string the result line must carry.
    pub nonce: String,
    /// The implementation to grade.
    pub implementation: ImplSpec,
    /// The job.
    pub kind: JobKind,
    /// Address-space limit in bytes (0: none).
    pub memory_limit: u64,
}

/// What a worker sends back.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "record", rename_all = "snake_case")]
pub enum Record {
    /// The raw outputs of a graded task's checks, or of a render.
    Outputs {
        /// The raw outputs, for the grader to judge.
        raw: Vec<Raw>,
    },
    /// The answer to a probe.
    Attempted {
        /// What the probe found.
        attempt: crate::implementation::Attempt,
    },
    /// What the task returned on a stability case.
    Stability {
        /// The value or the panic, for the caller to judge.
        output: StabilityOutput,
    },
    /// The worker could not run the job (not the student's fault).
    Error {
        /// What went wrong.
        message: String,
    },
}

/// Runs a job on the implementation `t`, telling `progress` how a grading job goes.
pub fn run_job<T: Tasks>(t: &T, kind: &JobKind, progress: &mut ProgressSink<'_>) -> Record {
    let task_of = |name: &str| TaskId::parse(name).map_err(|e| anyhow!(e));
    let result = match kind {
        JobKind::Grade { task, input } => task_of(task).map(|task| Record::Outputs {
            raw: run_task(t, task, input, progress),
        }),
        JobKind::Render { scene, seed } => Ok(Record::Outputs {
            raw: vec![Raw::Image(super::renders::render_raw(t, scene, *seed))],
        }),
        JobKind::Stability { case } => crate::stability::cases::<T>()
            .iter()
            .find(|c| c.name == case)
            .map(|c| Record::Stability { output: c.run(t) })
            .ok_or_else(|| anyhow!("the stability catalogue has no case `{case}`")),
        JobKind::Probe { task } => task_of(task).map(|task| Record::Attempted {
            attempt: match panics::catch(|| super::probe::probe_task(t, task)) {
                Ok(()) => crate::implementation::Attempt::Written,
                Err(p) if p.is_todo_of(task) => crate::implementation::Attempt::NotAttempted,
                Err(p) => crate::implementation::Attempt::Panics(p.message),
            },
        }),
    };
    result.unwrap_or_else(|e| Record::Error {
        message: format!("{e:#}"),
    })
}

/// The worker's main loop: reads the [`Delivery`] from stdin, builds the implementation with
/// `make` (which loads the reference libraries), enters its sandbox, runs the job and prints
/// the result line. Never returns: the process exits right after the result line, so
/// nothing the student left running can print after it.
pub fn serve<T: Tasks>(
    make: impl FnOnce(&ImplSpec, &BTreeMap<String, PathBuf>) -> anyhow::Result<T>,
) -> ! {
    let mut text = String::new();
    let delivery: Result<Delivery, String> = std::io::stdin()
        .read_to_string(&mut text)
        .map_err(|e| e.to_string())
        .and_then(|_| serde_json::from_str(&text).map_err(|e| e.to_string()));
    let Delivery {
        job,
        references,
        sandbox,
    } = match delivery {
        Ok(delivery) => delivery,
        Err(e) => {
            eprintln!("pbrlab-worker: cannot read the job on stdin: {e}");
            std::process::exit(2);
        }
    };
    drop(text);
    // The reference libraries are read before the sandbox closes the file system.
    let implementation = make(&job.implementation, &references);
    // Before any other thread exists and before any student code runs.
    let protections = sandbox::enter(&sandbox);
    {
        let mut out = std::io::stdout().lock();
        let json = serde_json::to_string(&protections).unwrap_or_default();
        let _ = writeln!(out, "\n{STARTED_MARKER} {} {json}", job.nonce);
        let _ = out.flush();
    }
    let nonce = job.nonce.clone();
    let mut progress = |p: Progress<'_>| {
        let line = match p {
            Progress::Starting(name) => {
                format!("{STEP_MARKER} {nonce} {}", name.replace('\n', " "))
            }
            Progress::Raw(raw) => match serde_json::to_string(raw) {
                Ok(json) => match crate::render::peak_resident_kib() {
                    Some(peak) => {
                        format!("{RAW_MARKER} {nonce} {json}\n{PEAK_MARKER} {nonce} {peak}")
                    }
                    None => format!("{RAW_MARKER} {nonce} {json}"),
                },
                Err(_) => return,
            },
        };
        let mut out = std::io::stdout().lock();
        let _ = writeln!(out, "\n{line}");
        let _ = out.flush();
    };
    let record = match implementation {
        Ok(t) => run_job(&t, &job.kind, &mut progress),
        Err(e) => Record::Error {
            message: format!("{e:#}"),
        },
    };
    let line = serde_json::to_string(&record).unwrap_or_else(|e| {
        serde_json::to_string(&Record::Error {
            message: format!("unserialisable result: {e}"),
        })
        .unwrap_or_default()
    });
    let mut out = std::io::stdout().lock();
    let _ = writeln!(out, "\n{RESULT_MARKER} {} {line}", job.nonce);
    let _ = out.flush();
    std::process::exit(0);
}

/// The `pbrlab-worker` binary's whole work: [`serve`] with [`production_impl`]. Not generic,
/// so it is compiled once with the framework and the worker binary's own crate is a call
/// (an exercise edit then relinks it in about a second instead of recompiling the grader's
/// generic code for it).
pub fn serve_production() -> ! {
    serve(production_impl)
}

/// The implementation a production worker grades: the student's code for the tasks `spec`
/// takes from the student, and for each other task the reference from its library in
/// `references` ([`crate::compiled_reference::load`]). The worker links no reference of its
/// own.
pub fn production_impl(
    spec: &ImplSpec,
    references: &BTreeMap<String, PathBuf>,
) -> anyhow::Result<crate::worksheet::TaskFns> {
    with_references(*crate::implementation::student(), spec, references)
}

/// `table` with each task that `spec` does not take from the student replaced by the
/// reference from its library in `references`: [`production_impl`] on the student's table,
/// and the whole reference (every task from its library) on [`TaskFns::ABSENT`] for a
/// render or study of student code that needs it beside.
///
/// [`TaskFns::ABSENT`]: crate::worksheet::TaskFns::ABSENT
pub fn with_references(
    mut table: crate::worksheet::TaskFns,
    spec: &ImplSpec,
    references: &BTreeMap<String, PathBuf>,
) -> anyhow::Result<crate::worksheet::TaskFns> {
    let student = spec.student_tasks();
    // Each library once, though the handout's one library holds every task.
    let mut loaded: BTreeMap<&PathBuf, crate::worksheet::TaskFns> = BTreeMap::new();
    for task in TaskId::ALL.into_iter().filter(|t| !student.contains(*t)) {
        let path = references.get(task.name()).ok_or_else(|| {
            anyhow!(
                "{spec:?} takes `{}` from the reference, and the grader gave no library \
                 of it (a build without the reference?)",
                task.name()
            )
        })?;
        let library = match loaded.get(path) {
            Some(library) => *library,
            None => {
                let library = crate::compiled_reference::load(path)?.ok_or_else(|| {
                    anyhow!("the reference library {} is missing", path.display())
                })?;
                *loaded.entry(path).or_insert(library)
            }
        };
        table = table.with_task(&library, task);
    }
    Ok(table)
}
