//! The parent side of isolation: starts a worker process for one job in a private
//! temporary directory, feeds it the job and its sandbox policy, enforces the time limit on
//! the process and on its pipes, and turns whatever happened into a result or a crash
//! report. Everything a worker prints is data: lines are read as bytes (invalid UTF-8 is
//! replaced, not fatal), each cut at [`LINE_LIMIT`], and only lines with the job's nonce
//! are read as records.

use super::sandbox::{Policy, Protections};
use super::wire::Raw;
use super::worker::{
    Delivery, Job, PEAK_MARKER, RAW_MARKER, RESULT_MARKER, Record, STARTED_MARKER, STEP_MARKER,
};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

/// The name of the binary that runs student code for the grader (`src/worker/main.rs`).
pub const WORKER_BINARY: &str = "pbrlab-worker";

/// The name of the binary that runs the commands of student code, a render or a
/// convergence study (`src/worker/student.rs`, `crate::cli::student_side`).
pub const STUDENT_BINARY: &str = "pbrlab-student";

/// The worker binary built beside the binary `exe`.
pub fn worker_beside(exe: &Path) -> PathBuf {
    beside(exe, WORKER_BINARY)
}

/// The binary `name` built beside the binary `exe`.
pub fn beside(exe: &Path, name: &str) -> PathBuf {
    exe.with_file_name(format!("{name}{}", std::env::consts::EXE_SUFFIX))
}

/// Threads a worker's renders may use.
pub const WORKER_THREADS: usize = 2;

/// How to start a worker: the program, its arguments and extra environment.
#[derive(Clone, Debug)]
pub struct Launcher {
    /// The executable (normally the `pbrlab-worker` binary beside the running `pbrlab`).
    pub program: PathBuf,
    /// Arguments that make it a worker (none for `pbrlab-worker`).
    pub args: Vec<String>,
    /// Extra environment variables.
    pub env: Vec<(String, String)>,
}

impl Launcher {
    /// The `pbrlab-worker` binary built beside the running executable. It links the
    /// student's code and the renderer, but no reference (it loads the libraries of the
    /// tasks a job takes from the reference, [`super::references`]) and not the grader's
    /// expected data or reference renders (nothing reachable from its `main` uses them, so
    /// the linker leaves them out: `tests/instructor/hostile.rs` checks the file).
    pub fn current_exe() -> anyhow::Result<Self> {
        let program = worker_beside(&std::env::current_exe()?);
        anyhow::ensure!(
            program.is_file(),
            "the worker binary {} is missing: build it with `cargo build --release`",
            program.display()
        );
        Ok(Self {
            program,
            args: Vec::new(),
            env: Vec::new(),
        })
    }

    fn command(&self) -> Command {
        let mut cmd = Command::new(&self.program);
        cmd.args(&self.args);
        // Nothing of the grader's environment reaches student code (a package's settings,
        // a CI token, snapshot tooling, backtrace switches): the worker starts with an empty
        // environment plus what is set here. CI mode makes any insta use in it read-only.
        cmd.env_clear().env("CI", "true");
        // Renders use a thread pool; on a many-core machine each thread's stack and malloc
        // arena would eat into the worker's address-space limit. A few threads suffice.
        cmd.env("RAYON_NUM_THREADS", WORKER_THREADS.to_string())
            .env("MALLOC_ARENA_MAX", "2");
        cmd.envs(self.env.iter().map(|(k, v)| (k, v)));
        cmd
    }
}

/// Why a worker run has no result.
#[derive(Clone, Debug, PartialEq)]
pub enum WorkerFailure {
    /// The student's code brought the worker down (the message says how).
    Student(String),
    /// The grader failed, not the student's code (the worker could not start, or its
    /// result could not be read).
    Grader(String),
}

/// What a worker run produced.
#[derive(Debug)]
pub struct WorkerRun {
    /// The record with the right nonce, or why there is none.
    pub outcome: Result<Record, WorkerFailure>,
    /// What the student's code printed on stdout (and the worker's stderr), truncated.
    pub output: String,
    /// Wall time, in seconds.
    pub seconds: f64,
    /// The last step (check or stability case) the worker announced: where it was when it
    /// crashed or ran out of time.
    pub step: Option<String>,
    /// The raw outputs that were ready, kept for a worker that dies later.
    pub finished_raw: Vec<Raw>,
    /// The worker's peak resident memory (KiB) as it reported it after each step, with the
    /// step: untrusted data for statistics, never a verdict.
    pub peaks: Vec<(String, u64)>,
    /// The protections the worker reported in force before any student code ran.
    pub protections: Option<Protections>,
}

impl WorkerRun {
    /// A run that produced nothing, for `failure`.
    pub fn failed(failure: WorkerFailure) -> Self {
        Self {
            outcome: Err(failure),
            output: String::new(),
            seconds: 0.0,
            step: None,
            finished_raw: Vec::new(),
            peaks: Vec::new(),
            protections: None,
        }
    }
}

/// The text after `marker` and `nonce` on `line`, when the line has both.
fn marked<'l>(line: &'l str, marker: &str, nonce: &str) -> Option<&'l str> {
    let rest = line.strip_prefix(marker)?.strip_prefix(' ')?;
    let rest = rest.strip_prefix(nonce)?;
    Some(rest.strip_prefix(' ').unwrap_or(rest))
}

/// Keep at most this much of the student's output.
const OUTPUT_LIMIT: usize = 8 * 1024;

/// The longest line read from a worker, in bytes; the rest of a longer line is dropped.
pub const LINE_LIMIT: usize = 4 << 20;

/// How long the pipes may stay open after the worker has ended (a process that inherited
/// them cannot hold the grader longer than this).
const PIPE_GRACE: Duration = Duration::from_millis(500);

/// The CPU seconds a worker may use for a job with wall-clock limit `timeout`, summed over
/// its threads.
fn cpu_seconds(timeout: Duration) -> u64 {
    (timeout.as_secs_f64() * WORKER_THREADS as f64).ceil() as u64 + 5
}

/// The most threads a worker's user may run (its own user: see `worker_user`).
pub const WORKER_MAX_THREADS: u64 = 64;

/// What the report says of the limits when a worker kept the grader's user.
pub const NO_THREAD_LIMIT: &str = "no thread limit (the worker kept the grader's user: the \
                                   kernel counts that limit per user, and does not apply it \
                                   to root)";

/// True when `path` can be reached by any user: every folder above it lets others through.
fn reachable_by_others(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    path.ancestors().skip(1).all(|dir| {
        dir.as_os_str().is_empty()
            || std::fs::metadata(dir).is_ok_and(|m| m.permissions().mode() & 0o001 != 0)
    })
}

/// True when workers started from `program` run as a user of their own: the grader is
/// root, and another user can start `program` and read the scenes.
pub fn runs_as_own_user(program: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    let scenes = crate::repository_root().join("scenes");
    let mode = |p: &Path| std::fs::metadata(p).map_or(0, |m| m.permissions().mode());
    rustix::process::geteuid().is_root()
        && reachable_by_others(program)
        && mode(program) & 0o001 != 0
        && reachable_by_others(&scenes)
        && mode(&scenes) & 0o005 == 0o005
}

/// The user and group a worker runs as when the grader is root: a fresh id of its own, so
/// that the kernel's thread limit (counted per user, and never applied to root) binds it
/// and only it, and so that it owns nothing but `scratch`, which is handed to it. `None`
/// when the grader is not root (the worker keeps the grader's user) or when another user
/// could not start `program` or read the scenes.
fn worker_user(program: &Path, scratch: &Path) -> Option<u32> {
    if !runs_as_own_user(program) {
        return None;
    }
    // Above every id a system hands out to people and services.
    let id = 0x5000_0000 | (crate::entropy::random_u64() as u32 & 0x00ff_ffff);
    std::os::unix::fs::chown(scratch, Some(id), Some(id)).ok()?;
    Some(id)
}

/// Runs `job` in a new worker, killing it after `timeout`.
pub fn run(launcher: &Launcher, job: &Job, timeout: Duration) -> WorkerRun {
    // Before the clock starts: the first call may build the reference libraries.
    let references = match super::references::for_spec(&job.implementation) {
        Ok(references) => references,
        Err(e) => return WorkerRun::failed(WorkerFailure::Grader(format!("{e:#}"))),
    };
    let start = Instant::now();
    let scratch = match tempfile::Builder::new().prefix("pbrlab-worker-").tempdir() {
        Ok(dir) => dir,
        Err(e) => {
            return WorkerRun::failed(WorkerFailure::Grader(format!(
                "could not make the worker's temporary directory: {e}"
            )));
        }
    };
    let user = worker_user(&launcher.program, scratch.path());
    let delivery = Delivery {
        sandbox: Policy {
            memory_limit: job.memory_limit,
            cpu_seconds: cpu_seconds(timeout),
            readable: vec![crate::repository_root().join("scenes")],
            writable: vec![scratch.path().to_path_buf()],
            threads: if user.is_some() {
                WORKER_MAX_THREADS
            } else {
                0
            },
        },
        job: job.clone(),
        references,
    };
    run_in(launcher, &delivery, scratch.path(), user, timeout, start)
}

/// One line of a worker's stdout, as text (invalid UTF-8 replaced), at most
/// [`LINE_LIMIT`] bytes of it; `None` at the end of the stream.
pub(crate) fn read_line(reader: &mut impl BufRead) -> Option<String> {
    read_until(reader, |b| b == b'\n')
}

/// [`read_line`] ending at every byte for which `end` holds (a `\r` too, for a progress
/// line redrawn in place).
pub(crate) fn read_until(reader: &mut impl BufRead, end: impl Fn(u8) -> bool) -> Option<String> {
    let mut line = Vec::new();
    let mut any = false;
    loop {
        let buffer = match reader.fill_buf() {
            Ok(b) => b,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(_) => break,
        };
        if buffer.is_empty() {
            break;
        }
        any = true;
        let (chunk, done) = match buffer.iter().position(|&b| end(b)) {
            Some(i) => (&buffer[..i], Some(i + 1)),
            None => (buffer, None),
        };
        let room = LINE_LIMIT.saturating_sub(line.len());
        line.extend_from_slice(&chunk[..chunk.len().min(room)]);
        let used = done.unwrap_or(buffer.len());
        reader.consume(used);
        if done.is_some() {
            break;
        }
    }
    any.then(|| String::from_utf8_lossy(&line).into_owned())
}

fn run_in(
    launcher: &Launcher,
    delivery: &Delivery,
    scratch: &Path,
    user: Option<u32>,
    timeout: Duration,
    start: Instant,
) -> WorkerRun {
    let job = &delivery.job;
    let mut command = launcher.command();
    if let Some(id) = user {
        use std::os::unix::process::CommandExt;
        // No supplementary groups either: std clears them when it changes the user.
        command.uid(id).gid(id);
    }
    let spawned = command
        .current_dir(scratch)
        .env("TMPDIR", scratch)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match spawned {
        Ok(child) => child,
        Err(e) => {
            return WorkerRun::failed(WorkerFailure::Grader(format!(
                "could not start the worker {}: {e}",
                launcher.program.display()
            )));
        }
    };
    let payload = serde_json::to_vec(delivery).unwrap_or_default();
    if let Some(mut stdin) = child.stdin.take() {
        // A worker that dies early closes the pipe; its exit status tells why.
        let _ = stdin.write_all(&payload);
    }
    let nonce = job.nonce.clone();
    let stdout = child.stdout.take().map(|out| {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let mut seen = Seen::default();
            let mut reader = BufReader::new(out);
            while let Some(line) = read_line(&mut reader) {
                if let Some(json) = marked(&line, STARTED_MARKER, &nonce) {
                    if !seen.started {
                        seen.started = true;
                        seen.protections = serde_json::from_str(json.trim()).ok();
                    }
                } else if let Some(json) = marked(&line, RESULT_MARKER, &nonce) {
                    seen.record = Some(serde_json::from_str::<Record>(json.trim()));
                } else if let Some(step) = marked(&line, STEP_MARKER, &nonce) {
                    seen.step = Some(step.trim().to_owned());
                } else if let Some(json) = marked(&line, RAW_MARKER, &nonce) {
                    seen.finished_raw
                        .extend(serde_json::from_str::<Raw>(json.trim()));
                } else if let Some(kib) = marked(&line, PEAK_MARKER, &nonce) {
                    if let (Some(step), Ok(kib)) = (&seen.step, kib.trim().parse::<u64>())
                        && seen.peaks.len() < MAX_PEAKS
                    {
                        seen.peaks.push((step.clone(), kib));
                    }
                } else if seen.printed.len() < OUTPUT_LIMIT && !line.is_empty() {
                    seen.printed.push_str(&line);
                    seen.printed.push('\n');
                }
            }
            let _ = tx.send(seen);
        });
        rx
    });
    let stderr = child.stderr.take().map(|err| {
        let (tx, rx) = mpsc::channel();
        std::thread::spawn(move || {
            let mut bytes = Vec::new();
            let mut reader = BufReader::new(err).take(OUTPUT_LIMIT as u64 * 4);
            let _ = reader.read_to_end(&mut bytes);
            // Drain the rest, so a chatty worker is not blocked on a full pipe.
            let _ = std::io::copy(&mut reader.into_inner(), &mut std::io::sink());
            let _ = tx.send(String::from_utf8_lossy(&bytes).into_owned());
        });
        rx
    });
    let (status, flooded) = wait(&mut child, timeout, scratch);
    // The deadline holds for the pipes too: whatever still holds them open (a process
    // that inherited them) is not waited for.
    let pipe_deadline = Instant::now() + PIPE_GRACE;
    let left = || pipe_deadline.saturating_duration_since(Instant::now());
    let Seen {
        record,
        started,
        printed,
        step,
        finished_raw,
        peaks,
        mut protections,
    } = stdout
        .and_then(|rx| rx.recv_timeout(left()).ok())
        .unwrap_or_default();
    let errors = stderr
        .and_then(|rx| rx.recv_timeout(left()).ok())
        .unwrap_or_default();
    if user.is_none()
        && let Some(protections) = &mut protections
        && protections.limits == "in force"
    {
        protections.limits = format!("partly: {NO_THREAD_LIMIT}");
    }
    let seconds = start.elapsed().as_secs_f64();
    let mut output = printed;
    if !errors.trim().is_empty() {
        output.push_str(errors.trim());
        output.push('\n');
    }
    output.truncate(floor_char_boundary(&output, OUTPUT_LIMIT));
    let outcome = match (status, record) {
        (Some(_), None) if !started => Err(WorkerFailure::Grader(format!(
            "the worker did not start: {}",
            errors
                .lines()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("no message")
                .trim()
        ))),
        (None, _) if flooded => Err(WorkerFailure::Student(format!(
            "wrote more than {} MiB or {MAX_SCRATCH_FILES} files into its temporary folder and \
             was stopped",
            MAX_SCRATCH_BYTES >> 20
        ))),
        (None, _) => Err(WorkerFailure::Student(format!(
            "timed out after {} s and was stopped (an infinite loop?)",
            timeout.as_secs_f64()
        ))),
        (Some(_), Some(Ok(record))) => Ok(record),
        // Only the worker and the student's code write to its stdout, and the worker writes
        // its result whole: a result that does not parse was written over by student code.
        (Some(_), Some(Err(e))) => Err(WorkerFailure::Student(format!(
            "its result was garbled by the code's own writes to standard output ({e})"
        ))),
        (Some(status), None) => Err(WorkerFailure::Student(explain(
            status,
            &errors,
            job.memory_limit,
        ))),
    };
    WorkerRun {
        outcome,
        output,
        seconds,
        step,
        finished_raw,
        peaks,
        protections,
    }
}

/// What the worker's stdout held: its marked lines, and the rest as its output.
#[derive(Default)]
struct Seen {
    record: Option<serde_json::Result<Record>>,
    started: bool,
    printed: String,
    step: Option<String>,
    finished_raw: Vec<Raw>,
    peaks: Vec<(String, u64)>,
    protections: Option<Protections>,
}

/// The most peak-memory lines kept from one worker (one per step; a flood is not kept).
const MAX_PEAKS: usize = 10_000;

fn floor_char_boundary(s: &str, mut i: usize) -> usize {
    if i >= s.len() {
        return s.len();
    }
    while !s.is_char_boundary(i) {
        i -= 1;
    }
    i
}

/// The most a worker may write into its temporary folder, in bytes and in files.
pub const MAX_SCRATCH_BYTES: u64 = 512 << 20;
/// See [`MAX_SCRATCH_BYTES`].
pub const MAX_SCRATCH_FILES: usize = 10_000;

/// How often the temporary folder's size is measured.
const DISK_WATCH: Duration = Duration::from_millis(100);

/// True when `folder` holds more than [`MAX_SCRATCH_BYTES`] or [`MAX_SCRATCH_FILES`]
/// (counting stops there, so a flood of files costs the watch no more than that).
fn over_disk(folder: &Path) -> bool {
    let (mut bytes, mut files) = (0u64, 0usize);
    let mut todo = vec![folder.to_path_buf()];
    while let Some(dir) = todo.pop() {
        for entry in std::fs::read_dir(&dir).into_iter().flatten().flatten() {
            files += 1;
            if files > MAX_SCRATCH_FILES {
                return true;
            }
            match entry.metadata() {
                Ok(m) if m.is_dir() => todo.push(entry.path()),
                Ok(m) => bytes += m.len(),
                Err(_) => {}
            }
            if bytes > MAX_SCRATCH_BYTES {
                return true;
            }
        }
    }
    false
}

/// Waits for the child; kills it and returns `None` after `timeout`, or as soon as its
/// temporary folder `scratch` outgrows its bound (then with `true`). The kernel bounds
/// each file a worker writes (`RLIMIT_FSIZE`); their sum is watched from here.
fn wait(child: &mut Child, timeout: Duration, scratch: &Path) -> (Option<ExitStatus>, bool) {
    let deadline = Instant::now() + timeout;
    let mut next_watch = Instant::now() + DISK_WATCH;
    loop {
        let flooded = Instant::now() >= next_watch && {
            next_watch = Instant::now() + DISK_WATCH;
            over_disk(scratch)
        };
        match child.try_wait() {
            Ok(Some(status)) => return (Some(status), false),
            Ok(None) if Instant::now() < deadline && !flooded => {
                std::thread::sleep(Duration::from_millis(5))
            }
            _ => {
                let _ = child.kill();
                let _ = child.wait();
                return (None, flooded);
            }
        }
    }
}

/// Why a worker ended without a result, in words a student can act on.
fn explain(status: ExitStatus, stderr: &str, memory_limit: u64) -> String {
    let gib = memory_limit as f64 / (1u64 << 30) as f64;
    if stderr.contains("has overflowed its stack") {
        return "overflowed its stack (unbounded recursion?)".into();
    }
    if let Some(line) = stderr.lines().find(|l| l.contains("memory allocation of")) {
        return format!("ran out of memory (limit {gib:.1} GiB): {}", line.trim());
    }
    #[cfg(unix)]
    {
        use std::os::unix::process::ExitStatusExt;
        if let Some(signal) = status.signal() {
            return match signal {
                libc::SIGABRT => "aborted (std::process::abort, or a panic inside a panic)".into(),
                libc::SIGSEGV | libc::SIGBUS => "crashed with a memory fault (SIGSEGV)".into(),
                libc::SIGKILL => format!("was killed (out of memory? the limit is {gib:.1} GiB)"),
                libc::SIGFPE => "crashed with an arithmetic fault (SIGFPE)".into(),
                other => format!("was killed by signal {other}"),
            };
        }
    }
    match status.code() {
        Some(0) => "exited early with status 0 before its checks finished (does the code call \
                    std::process::exit?)"
            .into(),
        Some(code) => {
            let last = stderr
                .lines()
                .rev()
                .find(|l| !l.trim().is_empty())
                .unwrap_or("");
            format!("exited early with status {code} {}", last.trim())
                .trim_end()
                .to_string()
        }
        None => "ended without a result".into(),
    }
}

/// A fresh nonce for one job: not guessable by code that cannot read the job.
pub fn nonce() -> String {
    use crate::entropy::random_u64;
    format!("{:016x}{:016x}", random_u64(), random_u64())
}
