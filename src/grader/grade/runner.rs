//! Grading a set of tasks: load the expected data, decide which implementation grades which
//! task, run one isolated worker per task (in parallel), and assemble the report.

use super::call::Call;
use super::checks::{TaskInput, VALUES, judge_finished, judge_task, score};
use super::credit::Credit;
use super::estimator::EstimatorRun;
use super::expected::{self, TaskData};
use super::isolation::{self, Launcher};
use super::shrink;
use super::verdict::{CheckResult, GradeReport, TaskOutcome, TaskStatus, Visibility};
use super::wire::ValueOutputs;
use super::wire::{EstimateOutputs, Raw, ValueCalls, WorkerInput};
use super::worker::{ImplSpec, Job, JobKind, Record};
use crate::implementation::ImplChoice;
use crate::task_set::TaskSet;
use crate::worksheet::TaskId;
use anyhow::bail;
pub use pbrlab_course::scenes::scene_entry;
use std::collections::BTreeMap;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Options of one grading run.
#[derive(Clone, Debug)]
pub struct GradeOptions {
    /// Tasks to grade, in worksheet order.
    pub tasks: Vec<TaskId>,
    /// Whose code: `student` grades each task with only that task from the student (the
    /// reference behind its dependencies), `mixed` with every attempted task from the
    /// student, `reference` the reference alone.
    pub implementation: ImplChoice,
    /// Seed of the statistical checks.
    pub seed: u64,
    /// Seed of hidden random cases, compared live against the reference.
    pub hidden_seed: Option<u64>,
    /// Time limit per task.
    pub timeout: Duration,
    /// Address-space limit per worker, in bytes.
    pub memory_limit: u64,
    /// Workers running at once.
    pub jobs: usize,
    /// Grade the scenes' renders too (each once the tasks it needs have passed).
    pub renders: bool,
    /// Where the HTML report goes (render checks write their pictures there).
    pub report_dir: Option<std::path::PathBuf>,
    /// How partly right checks are credited.
    pub credit: Credit,
    /// The tasks whose exercise files did not compile, with the compiler's messages
    /// ([`super::student_build`]): each is reported as a compile error, without a worker.
    pub compile_errors: BTreeMap<TaskId, String>,
}

impl Default for GradeOptions {
    fn default() -> Self {
        Self {
            tasks: TaskId::ALL.to_vec(),
            implementation: ImplChoice::Student,
            seed: DEFAULT_SEED,
            hidden_seed: None,
            timeout: Duration::from_secs_f64(DEFAULT_TASK_TIMEOUT_SECONDS),
            memory_limit: DEFAULT_MEMORY_LIMIT,
            jobs: std::thread::available_parallelism().map_or(2, |n| n.get()),
            renders: true,
            report_dir: None,
            compile_errors: BTreeMap::new(),
            credit: Credit::default(),
        }
    }
}

/// The seed of the statistical checks unless one is given.
pub const DEFAULT_SEED: u64 = 1;

/// The inputs of every task to grade: stored data plus hidden cases, all computed before
/// any student code runs.
pub fn prepare(options: &GradeOptions) -> anyhow::Result<BTreeMap<TaskId, TaskInput>> {
    let mut stored: BTreeMap<TaskId, TaskData> = expected::load_all()?;
    let mut inputs = BTreeMap::new();
    for &task in &options.tasks {
        let hidden = match options.hidden_seed {
            None => Vec::new(),
            Some(seed) => hidden_cases(task, seed)?,
        };
        inputs.insert(
            task,
            TaskInput {
                data: stored.remove(&task),
                hidden,
                seed: options.seed,
            },
        );
    }
    Ok(inputs)
}

#[cfg(feature = "solutions")]
fn hidden_cases(task: TaskId, seed: u64) -> anyhow::Result<Vec<super::case::ValueCase>> {
    use super::value_cases::{evaluate, hidden_inputs};
    evaluate(
        &hidden_inputs(task, seed),
        crate::implementation::reference(),
    )
}

#[cfg(not(feature = "solutions"))]
fn hidden_cases(_task: TaskId, _seed: u64) -> anyhow::Result<Vec<super::case::ValueCase>> {
    bail!("hidden cases are computed by the reference, which this build does not have")
}

/// The address-space limit of a worker unless told otherwise, in MiB: the one home of the
/// default that `grade`, `grade-class` and the packages' settings derive from.
pub const DEFAULT_MEMORY_LIMIT_MIB: u64 = 4096;

/// [`DEFAULT_MEMORY_LIMIT_MIB`] in bytes.
pub const DEFAULT_MEMORY_LIMIT: u64 = DEFAULT_MEMORY_LIMIT_MIB << 20;

/// The time limit per task unless told otherwise, in seconds (one home, as above).
pub const DEFAULT_TASK_TIMEOUT_SECONDS: f64 = 30.0;

/// Runs `jobs` with `options.jobs` workers at a time and `options.timeout` each.
pub fn run_all(
    launcher: &Launcher,
    jobs: Vec<Job>,
    options: &GradeOptions,
) -> Vec<isolation::WorkerRun> {
    run_jobs(launcher, &jobs, options.jobs, options.timeout)
}

/// Runs each of `jobs` in its own worker, at most `parallel` at a time, each stopped after
/// `timeout`; the runs come back in the order of the jobs.
pub fn run_jobs(
    launcher: &Launcher,
    jobs: &[Job],
    parallel: usize,
    timeout: Duration,
) -> Vec<isolation::WorkerRun> {
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<isolation::WorkerRun>>> =
        Mutex::new((0..jobs.len()).map(|_| None).collect());
    std::thread::scope(|scope| {
        for _ in 0..parallel.max(1).min(jobs.len().max(1)) {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(job) = jobs.get(i) else { break };
                    let run = isolation::run(launcher, job, timeout);
                    if let Ok(mut results) = results.lock() {
                        results[i] = Some(run);
                    }
                }
            });
        }
    });
    results
        .into_inner()
        .unwrap_or_default()
        .into_iter()
        .map(|r| {
            r.unwrap_or_else(|| {
                isolation::WorkerRun::failed(isolation::WorkerFailure::Grader(
                    "the worker thread did not report".into(),
                ))
            })
        })
        .collect()
}

/// The tasks the student has written, each probed in its own worker (a probe that crashes
/// or hangs counts as written: it is not the stub).
pub fn probe_attempted(launcher: &Launcher, options: &GradeOptions) -> Vec<TaskId> {
    let jobs: Vec<Job> = TaskId::ALL
        .iter()
        .map(|t| Job {
            nonce: isolation::nonce(),
            implementation: ImplSpec::Student,
            kind: JobKind::Probe {
                task: t.name().into(),
            },
            memory_limit: options.memory_limit,
        })
        .collect();
    let probe_options = GradeOptions {
        timeout: options.timeout.min(Duration::from_secs(5)),
        ..options.clone()
    };
    run_all(launcher, jobs, &probe_options)
        .into_iter()
        .zip(TaskId::ALL)
        .filter(|(run, _)| {
            !matches!(
                run.outcome,
                Ok(Record::Attempted {
                    attempt: crate::implementation::Attempt::NotAttempted
                })
            )
        })
        .map(|(_, task)| task)
        .collect()
}

/// The tasks whose student code runs while `task` is graded: the task alone for `student`
/// (so a mistake in a task it builds on is charged to that task only), every attempted task
/// for `mixed`, none for `reference`.
pub fn student_tasks_for(task: TaskId, choice: ImplChoice, attempted: &[TaskId]) -> TaskSet {
    match choice {
        ImplChoice::Reference => TaskSet::EMPTY,
        ImplChoice::Student => [task].into_iter().collect(),
        ImplChoice::Mixed => attempted.iter().copied().collect(),
    }
}

/// Which implementation grades `task`. Without the reference compiled in, only the student's
/// own code can run.
fn spec_for(
    task: TaskId,
    options: &GradeOptions,
    attempted: &[TaskId],
) -> anyhow::Result<ImplSpec> {
    if !cfg!(feature = "solutions") {
        if options.implementation != ImplChoice::Student {
            bail!(
                "--impl {} needs the reference solutions, which this build does not have",
                format!("{:?}", options.implementation).to_lowercase()
            );
        }
        return Ok(ImplSpec::Student);
    }
    let student = student_tasks_for(task, options.implementation, attempted);
    Ok(if student.is_empty() {
        ImplSpec::Reference
    } else {
        ImplSpec::Mixed {
            student: student.iter().map(|t| t.name().to_string()).collect(),
        }
    })
}

/// Grades `options.tasks` with workers started by `launcher`, then the scenes' renders
/// when every task was graded.
pub fn grade(options: &GradeOptions, launcher: &Launcher) -> anyhow::Result<GradeReport> {
    let start = Instant::now();
    let mut inputs = prepare(options)?;
    let attempted = if options.implementation == ImplChoice::Mixed {
        probe_attempted(launcher, options)
    } else {
        Vec::new()
    };
    let mut jobs = Vec::new();
    let mut graded = Vec::new();
    let mut outcomes = Vec::new();
    for &task in &options.tasks {
        let input = inputs.remove(&task).unwrap_or_default();
        if let Some(message) = options.compile_errors.get(&task) {
            outcomes.push((task.name().to_string(), compile_error(task, message)));
            continue;
        }
        if !task_has_checks(task, &input) {
            // Reported without starting a worker.
            outcomes.push((task.name().to_string(), no_checks(task)));
            continue;
        }
        // The expected outputs stay here; the workers get the calls only, the hidden
        // cases' in a worker of their own.
        let mut workers = input.for_workers();
        let implementation = spec_for(task, options, &attempted)?;
        // The worker of the student's code holds no reference of its task, so the
        // reference's estimators (for the time comparison) run in one of their own.
        let reference_estimators = cfg!(feature = "solutions")
            && implementation != ImplSpec::Reference
            && has_estimators(task);
        graded.push((task, input, workers.len(), reference_estimators));
        let estimators_only = WorkerInput {
            values: Vec::new(),
            sampling: Vec::new(),
            seed: options.seed,
            values_only: false,
            estimators_only: true,
        };
        let mut specs = vec![implementation; workers.len()];
        if reference_estimators {
            workers.push(estimators_only);
            specs.push(ImplSpec::Reference);
        }
        for (worker, implementation) in workers.into_iter().zip(specs) {
            jobs.push(Job {
                nonce: isolation::nonce(),
                implementation,
                kind: JobKind::Grade {
                    task: task.name().into(),
                    input: worker,
                },
                memory_limit: options.memory_limit,
            });
        }
    }
    let mut sandbox = std::collections::BTreeSet::new();
    let mut runs = run_all(launcher, jobs, options).into_iter();
    for (task, input, workers, reference_estimators) in &graded {
        let Some(mut run) = runs.next() else { break };
        sandbox.extend(run.protections.as_ref().map(ToString::to_string));
        for hidden in runs.by_ref().take(workers - 1) {
            sandbox.extend(hidden.protections.as_ref().map(ToString::to_string));
            join_hidden(&mut run, hidden);
        }
        if *reference_estimators && let Some(reference) = runs.next() {
            join_reference(&mut run, reference);
        }
        let public = public_values(&run);
        let mut task_outcome = outcome(*task, input, run, options.credit);
        if cfg!(feature = "solutions")
            && let (Some(outputs), Some(data)) = (public, &input.data)
            && let Some(check) = task_outcome
                .checks
                .iter_mut()
                .find(|c| c.name == outputs.check && !c.passed)
        {
            let student = |calls: &[Call]| shrink_run(launcher, options, &attempted, *task, calls);
            shrink::attach(
                &data.values,
                &outputs,
                check,
                crate::implementation::reference(),
                student,
                SHRINK_BUDGET,
            );
        }
        outcomes.push((task.name().to_string(), task_outcome));
    }
    outcomes.sort_by_key(|(name, _)| TaskId::parse(name).map_or(usize::MAX, |t| t as usize));
    let mut tasks: Vec<TaskOutcome> = outcomes.into_iter().map(|(_, o)| o).collect();
    if options.renders && TaskId::ALL.iter().all(|t| options.tasks.contains(t)) {
        let renders = grade_renders(options, launcher, &tasks, &attempted, &mut sandbox);
        tasks.extend(renders);
    }
    let implementation = format!("{:?}", options.implementation).to_lowercase();
    let mut report = GradeReport::new(
        &implementation,
        options.seed,
        options.hidden_seed.is_some(),
        tasks,
        start.elapsed().as_secs_f64(),
    );
    report.sandbox = sandbox.into_iter().collect();
    Ok(report)
}

fn compile_error(task: TaskId, message: &str) -> TaskOutcome {
    TaskOutcome {
        task: task.name().into(),
        status: TaskStatus::CompileError {
            message: message.into(),
        },
        points: 0.0,
        max_points: task.info().points as f64,
        checks: Vec::new(),
        output: String::new(),
        seconds: 0.0,
    }
}

fn no_checks(task: TaskId) -> TaskOutcome {
    TaskOutcome {
        task: task.name().into(),
        status: TaskStatus::NoChecks,
        points: 0.0,
        max_points: 0.0,
        checks: Vec::new(),
        output: String::new(),
        seconds: 0.0,
    }
}

/// The render checks: a scene whose tasks have not all passed is reported as needing them
/// (no worker starts); the others render in a worker with the student's code for every task
/// the scene needs.
fn grade_renders(
    options: &GradeOptions,
    launcher: &Launcher,
    graded: &[TaskOutcome],
    attempted: &[TaskId],
    sandbox: &mut std::collections::BTreeSet<String>,
) -> Vec<TaskOutcome> {
    let mut results = Vec::new();
    let mut jobs = Vec::new();
    for (i, check) in super::renders::RENDER_CHECKS.iter().enumerate() {
        let needs = match super::renders::needs(check.scene) {
            Ok(needs) => needs,
            Err(e) => {
                results.push(TaskOutcome {
                    task: scene_entry(check.scene),
                    status: TaskStatus::GraderError {
                        message: format!("{e:#}"),
                    },
                    points: 0.0,
                    max_points: check.points,
                    checks: Vec::new(),
                    output: String::new(),
                    seconds: 0.0,
                });
                continue;
            }
        };
        let missing = super::scene_gate::missing_tasks(needs, graded);
        if !missing.is_empty() {
            let names: Vec<&str> = missing.iter().map(|t| t.name()).collect();
            results.push(TaskOutcome {
                task: scene_entry(check.scene),
                status: TaskStatus::NeedsTask {
                    task: names.join(", "),
                },
                points: 0.0,
                max_points: check.points,
                checks: Vec::new(),
                output: String::new(),
                seconds: 0.0,
            });
            continue;
        }
        let implementation = if !cfg!(feature = "solutions") {
            ImplSpec::Student
        } else if options.implementation == ImplChoice::Reference {
            ImplSpec::Reference
        } else {
            let student = match options.implementation {
                ImplChoice::Mixed => attempted.iter().copied().collect(),
                _ => needs,
            };
            ImplSpec::Mixed {
                student: student.iter().map(|t| t.name().to_string()).collect(),
            }
        };
        jobs.push((
            i,
            Job {
                nonce: isolation::nonce(),
                implementation,
                kind: JobKind::Render {
                    scene: check.scene.into(),
                    seed: options.seed.wrapping_add(0x5ce4e),
                },
                memory_limit: options.memory_limit,
            },
        ));
    }
    let runs = run_all(
        launcher,
        jobs.iter().map(|(_, j)| j.clone()).collect(),
        options,
    );
    for ((i, _), run) in jobs.iter().zip(runs) {
        let check = super::renders::RENDER_CHECKS[*i];
        sandbox.extend(run.protections.as_ref().map(ToString::to_string));
        results.push(render_outcome(check, run, options.report_dir.as_deref()));
    }
    results.sort_by_key(|o| {
        super::renders::RENDER_CHECKS
            .iter()
            .position(|c| scene_entry(c.scene) == o.task)
    });
    results
}

/// True when `task` has at least one check to run.
pub fn task_has_checks(task: TaskId, input: &TaskInput) -> bool {
    input
        .data
        .as_ref()
        .is_some_and(|d| !d.values.is_empty() || !d.sampling.is_empty())
        || !input.hidden.is_empty()
        || has_code_checks(task)
}

/// Tasks whose estimator or stability checks need no stored data.
fn has_code_checks(task: TaskId) -> bool {
    has_estimators(task)
        || !crate::stability::cases_for::<crate::worksheet::TaskFns>(task).is_empty()
}

/// True when `task` has estimator checks.
fn has_estimators(task: TaskId) -> bool {
    !super::catalogue::estimators(task, crate::implementation::student()).is_empty()
}

/// Adds the raw outputs of the hidden cases' worker to the visible worker's `run`. Nothing
/// else of it reaches the report: not what it printed, not how it crashed or timed out (a
/// hidden check without outputs fails, and says only how many cases it had).
fn join_hidden(run: &mut isolation::WorkerRun, hidden: isolation::WorkerRun) {
    let raw = match hidden.outcome {
        Ok(Record::Outputs { raw }) => raw,
        _ => hidden.finished_raw,
    };
    match &mut run.outcome {
        Ok(Record::Outputs { raw: visible }) => visible.extend(raw),
        _ => run.finished_raw.extend(raw),
    }
}

/// Adds the reference's estimator runs, from a worker that ran the reference alone, to the
/// student's estimator outputs in `run` (for the time comparison; they judge nothing).
fn join_reference(run: &mut isolation::WorkerRun, reference: isolation::WorkerRun) {
    let reference_raw = match reference.outcome {
        Ok(Record::Outputs { raw }) => raw,
        _ => reference.finished_raw,
    };
    let reference_runs: BTreeMap<usize, EstimatorRun> = reference_raw
        .into_iter()
        .filter_map(|raw| match raw {
            Raw::Estimate(EstimateOutputs {
                index,
                outcome: Ok(Ok(measured)),
                ..
            }) => Some((index, measured.student)),
            _ => None,
        })
        .collect();
    let student_raw = match &mut run.outcome {
        Ok(Record::Outputs { raw }) => raw,
        _ => &mut run.finished_raw,
    };
    for raw in student_raw {
        if let Raw::Estimate(EstimateOutputs {
            index,
            outcome: Ok(Ok(measured)),
            ..
        }) = raw
        {
            measured.reference = reference_runs.get(index).cloned();
        }
    }
}

/// A task's outcome from its worker run: every check of the task, judged from the
/// worker's raw outputs against `input`'s expected data.
pub fn outcome(
    task: TaskId,
    input: &TaskInput,
    run: isolation::WorkerRun,
    credit: Credit,
) -> TaskOutcome {
    let max_points = task.info().points as f64;
    let (status, points, checks) = match run.outcome {
        Ok(Record::Outputs { raw }) => {
            let mut checks = judge_task(task, input, &raw);
            credit.apply(&mut checks);
            let (status, points) = score(task, &checks);
            (status, points, checks)
        }
        Ok(Record::Attempted { .. } | Record::Stability { .. }) => (
            TaskStatus::GraderError {
                message: "the worker answered another job instead of grading".into(),
            },
            0.0,
            Vec::new(),
        ),
        Ok(Record::Error { message }) | Err(isolation::WorkerFailure::Grader(message)) => {
            (TaskStatus::GraderError { message }, 0.0, Vec::new())
        }
        Err(isolation::WorkerFailure::Student(reason)) => {
            let reason = match &run.step {
                Some(step) => format!("{reason}, while running {step}"),
                None => reason,
            };
            let mut finished = judge_finished(task, input, &run.finished_raw);
            credit.apply(&mut finished);
            (TaskStatus::Crashed { reason }, 0.0, finished)
        }
    };
    let max_points = if status == TaskStatus::NoChecks {
        0.0
    } else {
        max_points
    };
    let mut checks = checks;
    attach_peaks(&mut checks, &run.peaks);
    TaskOutcome {
        task: task.name().into(),
        status,
        points,
        max_points,
        checks,
        output: run.output,
        seconds: run.seconds,
    }
}

/// The outputs of the public values check in a worker's `run`, if it finished.
fn public_values(run: &isolation::WorkerRun) -> Option<ValueOutputs> {
    let raw = match &run.outcome {
        Ok(Record::Outputs { raw }) => raw,
        _ => return None,
    };
    raw.iter().find_map(|r| match r {
        Raw::Values(v) if v.check == VALUES => Some(v.clone()),
        _ => None,
    })
}

/// The most time shrinking one task's failing case may take, and each of its worker jobs
/// (closed-form calls, microseconds each: a job that takes longer ends the shrinking), so
/// a package's submission stays within the service's time limit.
const SHRINK_BUDGET: Duration = Duration::from_secs(4);
const SHRINK_JOB_TIMEOUT: Duration = Duration::from_secs(2);

/// The student's outputs of `calls` of `task` (simpler inputs of a failing public case), in
/// a worker of their own like every job; none when it does not finish.
fn shrink_run(
    launcher: &Launcher,
    options: &GradeOptions,
    attempted: &[TaskId],
    task: TaskId,
    calls: &[Call],
) -> Vec<super::wire::Evaluated> {
    let Ok(implementation) = spec_for(task, options, attempted) else {
        return Vec::new();
    };
    let job = Job {
        nonce: isolation::nonce(),
        implementation,
        kind: JobKind::Grade {
            task: task.name().into(),
            input: WorkerInput {
                values: vec![ValueCalls {
                    check: "values (shrinking)".into(),
                    calls: calls.to_vec(),
                }],
                sampling: Vec::new(),
                seed: options.seed,
                values_only: true,
                estimators_only: false,
            },
        },
        memory_limit: options.memory_limit,
    };
    let options = GradeOptions {
        timeout: options.timeout.min(SHRINK_JOB_TIMEOUT),
        ..options.clone()
    };
    let run = run_all(launcher, vec![job], &options).into_iter().next();
    match run.map(|r| r.outcome) {
        Some(Ok(Record::Outputs { raw })) => raw
            .into_iter()
            .find_map(|r| match r {
                Raw::Values(v) => Some(v.outputs),
                _ => None,
            })
            .unwrap_or_default(),
        _ => Vec::new(),
    }
}

/// Gives each visible check the peak memory its worker reported at its step (the stability
/// check: at its last case). Hidden checks get none: the hidden cases' worker sends
/// outputs only.
fn attach_peaks(checks: &mut [CheckResult], peaks: &[(String, u64)]) {
    for check in checks
        .iter_mut()
        .filter(|c| c.visibility == Visibility::Visible)
    {
        let prefix = format!("{}: ", check.name);
        check.peak_memory_kib = peaks
            .iter()
            .filter(|(step, _)| *step == check.name || step.starts_with(&prefix))
            .map(|(_, kib)| *kib)
            .max();
    }
}

/// A scene's outcome from its render worker's run: the render judged against the stored
/// reference (pictures written into `report_dir` when given), all of the scene's points or
/// none.
fn render_outcome(
    check: super::renders::RenderCheck,
    run: isolation::WorkerRun,
    report_dir: Option<&std::path::Path>,
) -> TaskOutcome {
    let image = |raw: &[Raw]| {
        let rendered = raw.iter().find_map(|r| match r {
            Raw::Image(image) => Some(image),
            _ => None,
        });
        let mut result = super::render_check::judge(check.scene, rendered, report_dir);
        result.weight = 1.0;
        // A render is one statistical test: all or nothing under any policy.
        result.credit = Credit::AllOrNothing.of(&result);
        vec![result]
    };
    let (status, checks) = match run.outcome {
        Ok(Record::Outputs { raw }) => {
            let checks = image(&raw);
            let status = if checks.iter().all(|c| c.passed) {
                TaskStatus::Passed
            } else {
                TaskStatus::Failed
            };
            (status, checks)
        }
        Ok(Record::Attempted { .. } | Record::Stability { .. }) => (
            TaskStatus::GraderError {
                message: "the worker answered another job instead of rendering".into(),
            },
            Vec::new(),
        ),
        Ok(Record::Error { message }) | Err(isolation::WorkerFailure::Grader(message)) => {
            (TaskStatus::GraderError { message }, Vec::new())
        }
        Err(isolation::WorkerFailure::Student(reason)) => {
            let reason = match &run.step {
                Some(step) => format!("{reason}, while running {step}"),
                None => reason,
            };
            (TaskStatus::Crashed { reason }, image(&run.finished_raw))
        }
    };
    TaskOutcome {
        task: scene_entry(check.scene),
        points: if status == TaskStatus::Passed {
            check.points
        } else {
            0.0
        },
        status,
        max_points: check.points,
        checks,
        output: run.output,
        seconds: run.seconds,
    }
}
