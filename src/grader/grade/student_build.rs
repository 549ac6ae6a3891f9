//! Building the student's crate so that a compile error costs only its task: cargo builds
//! the binaries, the compiler's JSON diagnostics (and the exercise build script's refusals)
//! name the exercise files at fault, and the build runs again from a copy of the exercise
//! files in which the shipped stub has replaced each of those, until it succeeds. Only the
//! copy is compiled then, so nothing refused stays reachable from the files that are. The tasks built from their stubs are recorded beside
//! the binaries ([`BuildRecord`]); the grader reports each as a compile error with the
//! compiler's message, and grades every other task as written.
//!
//! Every round compiles in the build's view ([`super::build_view`]): the student's crate
//! sees the framework's compiled units, the toolchain and its own files, and nothing else,
//! made with namespaces or, where the kernel has none, Landlock. Where neither works, a
//! graded build (`bounded`) is refused, and a student's own build of a handout (which
//! holds nothing but the student's files) runs as a plain cargo build.

use super::build_view::{Framework, Mechanism, Toolchain, View, ViewInputs};
use crate::worksheet::TaskId;
use anyhow::{Context, bail};
use pbrlab_course::selection::FRAMEWORK_SELECTION;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The file, beside the binaries, that says what they were built from.
pub const RECORD: &str = "pbrlab-build.json";

/// The longest compiler message kept per task, in bytes.
const MAX_MESSAGE: usize = 8 << 10;

/// What a build of the student's crate compiled.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct BuildRecord {
    /// The folder the exercise files were compiled from.
    pub exercises: PathBuf,
    /// The tasks whose files did not compile, each with the compiler's messages: their
    /// shipped stubs were built in their place.
    pub compile_errors: BTreeMap<String, String>,
    /// The worker binary built.
    pub worker: PathBuf,
    /// The worker binary's modification time when the record was written, in nanoseconds
    /// since the Unix epoch: a binary rebuilt since (by plain cargo) has no record.
    pub worker_modified: u128,
}

fn modified_nanos(file: &Path) -> Option<u128> {
    let time = std::fs::metadata(file).and_then(|m| m.modified()).ok()?;
    Some(time.duration_since(std::time::UNIX_EPOCH).ok()?.as_nanos())
}

impl BuildRecord {
    /// The record of the build that produced `worker`, if the binary is still that build's.
    pub fn of(worker: &Path) -> Option<Self> {
        let text = std::fs::read_to_string(worker.with_file_name(RECORD)).ok()?;
        let record: Self = serde_json::from_str(&text).ok()?;
        (Some(record.worker_modified) == modified_nanos(worker)).then_some(record)
    }

    /// The compile errors by task.
    pub fn errors(&self) -> BTreeMap<TaskId, String> {
        self.compile_errors
            .iter()
            .filter_map(|(task, message)| Some((TaskId::parse(task).ok()?, message.clone())))
            .collect()
    }
}

/// A build of the student's crate.
pub struct StudentBuild<'a> {
    /// The workspace root (where `Cargo.toml` is).
    pub root: &'a Path,
    /// The folder of the exercise files to compile (`exercises/`, or a submission's copy).
    pub exercises: &'a Path,
    /// Build the binary of the commands that run student code too (`pbrlab-student`: a
    /// local build, for `render` and `converge`; a class run needs only the worker).
    pub commands: bool,
    /// Build without the reference (the student handout).
    pub handout: bool,
    /// The shipped stub of a task.
    pub stub: &'a dyn Fn(TaskId) -> anyhow::Result<String>,
    /// Print cargo's progress and the compiler's messages as they come.
    pub echo: bool,
    /// How long all rounds of the build may take.
    pub deadline: Duration,
    /// Build offline with the lock file as it is (an autograder: no network at grading).
    pub offline: bool,
    /// The folder the binaries go to (a class run's or an autograder's scratch folder, so
    /// that no other build replaces them while they grade); `None`: where cargo puts them,
    /// beside `pbrlab`.
    pub output: Option<&'a Path>,
    /// Compile under [`BOUNDS`]: the framework is built already (a class run's first
    /// build, an autograder's set-up), so what is left is the student's crate and a link,
    /// and a compile-time bomb in it costs this build, never the grader.
    pub bounded: bool,
}

/// The limits of a bounded build ([`StudentBuild::bounded`]), each compiler process's own.
#[derive(Clone, Copy, Debug)]
pub struct Bounds {
    /// Address space, in bytes.
    pub memory: u64,
    /// CPU seconds.
    pub cpu_seconds: u64,
    /// Wall time of all rounds together.
    pub wall: Duration,
    /// The largest file written, in bytes.
    pub file_size: u64,
}

/// What a bounded build may use: a student's crate compiles in seconds and links in well
/// under a GiB, so a build that needs more is a compile-time bomb (a const-eval loop, a
/// macro, type or static-data explosion).
pub const BOUNDS: Bounds = Bounds {
    memory: 2 << 30,
    cpu_seconds: 60,
    wall: Duration::from_secs(90),
    file_size: 1 << 30,
};

/// The variable that turns the exercise check of `exercises/build.rs` off when it is `off`
/// in the grader's environment: the tests that prove the build's view holds without it set
/// it.
pub const SOURCE_CHECK: &str = "PBRLAB_SOURCE_CHECK";

/// What cargo builds: the worker binary of its package (`src/worker/`; with
/// [`StudentBuild::commands`], `pbrlab-student` beside it), in the framework's selection
/// ([`FRAMEWORK_SELECTION`]), so it links the one compilation of the framework that
/// `pbrlab-commands` links.
pub fn worker_selection() -> Vec<&'static str> {
    let worker = ["--bin", super::isolation::WORKER_BINARY];
    FRAMEWORK_SELECTION.iter().copied().chain(worker).collect()
}

/// The most compiler output kept from one build, in bytes (beyond [`MAX_MESSAGE`] per task).
const MAX_OUTPUT: usize = 64 << 10;

/// Where the copy of `exercises` with stubs in place of the failing files goes: beside it,
/// in `.pbrlab/`.
fn stub_folder(exercises: &Path) -> PathBuf {
    exercises
        .parent()
        .unwrap_or(exercises)
        .join(".pbrlab")
        .join("stubbed")
}

/// What one round of cargo reported.
#[derive(Default)]
struct Round {
    success: bool,
    /// Per exercise file at fault, its messages.
    blamed: BTreeMap<TaskId, String>,
    /// Every error message, for a failure that names no exercise file.
    errors: Vec<String>,
    /// The worker binary cargo produced (as the build names it).
    worker: Option<PathBuf>,
    /// Every binary cargo produced (as the build names it).
    binaries: Vec<PathBuf>,
}

impl StudentBuild<'_> {
    /// Builds, putting the stub back for every task whose file does not compile, and writes
    /// the record beside the worker binary. Fails when the build fails outside the
    /// exercise files, or when the deadline passes.
    pub fn run(&self) -> anyhow::Result<BuildRecord> {
        let start = Instant::now();
        let deadline = if self.bounded {
            self.deadline.min(BOUNDS.wall)
        } else {
            self.deadline
        };
        let stubs = stub_folder(self.exercises);
        let mut errors: BTreeMap<TaskId, String> = BTreeMap::new();
        loop {
            self.place_stubs(&stubs, &errors)?;
            let left = deadline.saturating_sub(start.elapsed());
            let round = self.cargo(&stubs, !errors.is_empty(), left, deadline)?;
            if round.success {
                let worker = round
                    .worker
                    .context("cargo did not report the worker binary it built")?;
                let record = BuildRecord {
                    exercises: self.exercises.to_path_buf(),
                    worker: worker.clone(),
                    compile_errors: errors
                        .into_iter()
                        .map(|(t, m)| (t.name().to_string(), m))
                        .collect(),
                    worker_modified: modified_nanos(&worker).unwrap_or(0),
                };
                let json = serde_json::to_string_pretty(&record)?;
                crate::atomic_file::write(&worker.with_file_name(RECORD), json.as_bytes())?;
                return Ok(record);
            }
            let new: Vec<_> = round
                .blamed
                .into_iter()
                .filter(|(task, _)| !errors.contains_key(task))
                .collect();
            let new = if new.is_empty() {
                // Nothing named an exercise file: the file whose stub lets the build
                // succeed is the cause (a renamed task function, a limit reached).
                let culprits = self.culprits(&stubs, &errors, start, deadline)?;
                if culprits.is_empty() {
                    bail!(
                        "the build failed outside the exercise files, with every task file \
                         of the submission replaced by its stub too:\n{}",
                        round.errors.join("\n")
                    );
                }
                let message = format!(
                    "the build failed outside the exercise files with this file compiled \
                     in, and succeeded with its stub in its place (a task function renamed? \
                     its signature is in the stub):\n{}",
                    round.errors.join("\n")
                );
                culprits.into_iter().map(|t| (t, message.clone())).collect()
            } else {
                new
            };
            if self.echo {
                let names: Vec<_> = new
                    .iter()
                    .map(|(t, _)| format!("{}.rs", t.name()))
                    .collect();
                eprintln!(
                    "pbrlab: {} does not compile; building its shipped stub in its place (0 \
                     points for that task), the rest as written",
                    names.join(", ")
                );
            }
            errors.extend(new);
        }
    }

    /// The submission's task files whose stubs make a failing build succeed: each alone,
    /// in task order, then all together; none when even that fails (the fault is not the
    /// submission's). `errors` are the tasks stubbed already.
    fn culprits(
        &self,
        stubs: &Path,
        errors: &BTreeMap<TaskId, String>,
        start: Instant,
        deadline: Duration,
    ) -> anyhow::Result<Vec<TaskId>> {
        let mut candidates = Vec::new();
        for task in TaskId::ALL {
            let file = self.exercises.join(format!("{}.rs", task.name()));
            let written = std::fs::read_to_string(&file)
                .is_ok_and(|text| (self.stub)(task).is_ok_and(|stub| stub != text));
            if written && !errors.contains_key(&task) {
                candidates.push(task);
            }
        }
        let trials = candidates
            .iter()
            .map(|&task| vec![task])
            .chain((candidates.len() > 1).then(|| candidates.clone()));
        for trial in trials {
            let mut stubbed = errors.clone();
            stubbed.extend(trial.iter().map(|&t| (t, String::new())));
            self.place_stubs(stubs, &stubbed)?;
            let left = deadline.saturating_sub(start.elapsed());
            if self.cargo(stubs, true, left, deadline)?.success {
                return Ok(trial);
            }
        }
        Ok(Vec::new())
    }

    /// Makes `folder` a copy of the exercise files with the shipped stub in place of each
    /// task in `errors` (no folder when there are none).
    fn place_stubs(&self, folder: &Path, errors: &BTreeMap<TaskId, String>) -> anyhow::Result<()> {
        if folder.exists() {
            std::fs::remove_dir_all(folder)
                .with_context(|| format!("clearing {}", folder.display()))?;
        }
        if errors.is_empty() {
            return Ok(());
        }
        std::fs::create_dir_all(folder).with_context(|| format!("making {}", folder.display()))?;
        for task in TaskId::ALL {
            let name = format!("{}.rs", task.name());
            let file = folder.join(&name);
            if errors.contains_key(&task) {
                let text = (self.stub)(task)?;
                std::fs::write(&file, text)
                    .with_context(|| format!("writing {}", file.display()))?;
            } else {
                let source = self.exercises.join(&name);
                // A missing file stays missing: the build script refuses it by name.
                if source.is_file() {
                    std::fs::copy(&source, &file)
                        .with_context(|| format!("copying {}", source.display()))?;
                }
            }
        }
        Ok(())
    }

    /// Puts the binaries of a successful round where they are used: [`StudentBuild::output`],
    /// or where cargo puts them outside the view (beside `pbrlab`); each replaced whole,
    /// so that a worker running from the old file is not disturbed.
    fn place_binaries(&self, round: &mut Round, view: Option<&View>) -> anyhow::Result<()> {
        for binary in &mut round.binaries {
            let built = view.map_or_else(|| binary.clone(), |v| v.on_host(binary));
            let outside = view.map_or_else(|| binary.clone(), |v| v.outside(binary));
            let name = binary.file_name().context("a binary without a name")?;
            let placed = self.output.map_or(outside, |o| o.join(name));
            if placed == built {
                continue;
            }
            let temporary = placed.with_file_name(format!(
                ".{}.{}.new",
                name.to_string_lossy(),
                std::process::id()
            ));
            std::fs::copy(&built, &temporary)
                .with_context(|| format!("copying {}", built.display()))?;
            std::fs::rename(&temporary, &placed)
                .with_context(|| format!("placing {}", placed.display()))?;
            if round.worker.as_ref() == Some(binary) {
                round.worker = Some(placed.clone());
            }
            *binary = placed;
        }
        Ok(())
    }

    /// Cargo's arguments for a build of the worker (and the student binary with
    /// [`StudentBuild::commands`]), `offline` or not.
    fn cargo_args(&self, offline: bool) -> Vec<String> {
        let mut args: Vec<String> = ["build", "--release", "--message-format=json"]
            .into_iter()
            .chain(worker_selection())
            .map(String::from)
            .collect();
        if self.commands {
            args.extend(["--bin".into(), super::isolation::STUDENT_BINARY.into()]);
        }
        args.extend(self.feature_and_network_args(offline));
        args
    }

    /// The arguments every build here shares: no default features for a build without
    /// the reference, and no network when `offline`.
    fn feature_and_network_args(&self, offline: bool) -> Vec<String> {
        let mut args = Vec::new();
        // A build without the reference in the instructor's repository (whose default
        // features include it) must say so. The handout has no default features to turn
        // off.
        if self.handout && self.root.join("solutions").is_dir() {
            args.push("--no-default-features".into());
        }
        if offline {
            args.extend(["--offline".into(), "--locked".into()]);
        }
        args
    }

    /// Cargo's arguments for the framework's build ([`Framework::prepare`]): the libraries
    /// the worker links, with the features the student's build resolves (the same packages
    /// selected), and no binary.
    fn framework_args(&self, offline: bool) -> Vec<String> {
        let mut args: Vec<String> = [
            "build",
            "--release",
            "--message-format=json",
            FRAMEWORK_SELECTION[0],
            FRAMEWORK_SELECTION[1],
            FRAMEWORK_SELECTION[2],
            FRAMEWORK_SELECTION[3],
            "-p",
            "pbrlab",
            "-p",
            "pbrlab-exercises",
            "--lib",
        ]
        .map(String::from)
        .into();
        args.extend(self.feature_and_network_args(offline));
        args
    }

    /// The shipped stubs, in the folder the framework's own build compiles
    /// ([`Framework::prepare`]); a file is written only when it changed, so that cargo
    /// finds that build current.
    fn shipped_stubs(&self, target: &Path) -> anyhow::Result<PathBuf> {
        let folder = target.join("pbrlab-view").join("stubs");
        std::fs::create_dir_all(&folder).with_context(|| format!("making {}", folder.display()))?;
        for task in TaskId::ALL {
            let file = folder.join(format!("{}.rs", task.name()));
            let text = (self.stub)(task)?;
            if std::fs::read_to_string(&file).ok().as_deref() != Some(text.as_str()) {
                std::fs::write(&file, text)
                    .with_context(|| format!("writing {}", file.display()))?;
            }
        }
        Ok(folder)
    }

    /// The toolchain and the framework a view needs, prepared once per process (a class
    /// run builds many submissions on one framework); `None` where the kernel makes no
    /// view and this build may run without one.
    fn prepare_view(
        &self,
        target: &Path,
    ) -> anyhow::Result<Option<(Toolchain, Framework, Mechanism)>> {
        type Prepared = (PathBuf, Vec<String>, Toolchain, Framework, Mechanism);
        static PREPARED: std::sync::Mutex<Option<Prepared>> = std::sync::Mutex::new(None);
        let args = self.framework_args(self.offline || self.bounded);
        let mut prepared = PREPARED.lock().unwrap_or_else(|e| e.into_inner());
        if let Some((root, cached, toolchain, framework, mechanism)) = prepared.as_ref()
            && root == self.root
            && *cached == args
        {
            return Ok(Some((toolchain.clone(), framework.clone(), *mechanism)));
        }
        let toolchain = Toolchain::resolve(self.root)?;
        let stubs = self.shipped_stubs(target)?;
        let framework = Framework::prepare(
            self.root,
            target,
            &toolchain,
            &args,
            &stubs,
            self.offline || self.bounded,
        )?;
        let mechanism = match super::build_view::choose(&framework.helper, target) {
            Ok(mechanism) => mechanism,
            Err(why) => {
                // A student's own build of a handout holds nothing but the student's files.
                let handout = !self.root.join("solutions").exists();
                if self.bounded || !handout {
                    return Err(why.context(
                        "refusing to build student code without the build's view: it would read \
                     the whole repository and every process's command line",
                    ));
                }
                if self.echo {
                    eprintln!("pbrlab: building without the build's view ({why:#})");
                }
                return Ok(None);
            }
        };
        *prepared = Some((
            self.root.to_path_buf(),
            args,
            toolchain.clone(),
            framework.clone(),
            mechanism,
        ));
        Ok(Some((toolchain, framework, mechanism)))
    }

    /// Runs cargo once, reading its JSON messages; `left` of the build's `deadline`
    /// remains.
    /// The cargo command that builds `compiled` (the exercise folder the build script
    /// compiles) into `target`: in the build's view where this kernel makes one, with the
    /// progress bar it drives on a terminal.
    fn command(
        &self,
        compiled: &Path,
        target: &Path,
    ) -> anyhow::Result<(Command, Option<View>, Option<indicatif::ProgressBar>)> {
        let mut env: Vec<(String, String)> = Vec::new();
        // The switch that turns the exercise check off, for the tests that prove the view
        // holds without it: the grader's to set, never the student's.
        if let Ok(value) = std::env::var(SOURCE_CHECK) {
            env.push((SOURCE_CHECK.into(), value));
        }
        // On a terminal, cargo's count of units built (its own progress line, which it
        // draws only on a terminal, asked for here and read back) drives a bar with the
        // time left: a first build compiles the framework for minutes.
        let bar =
            (self.echo && std::io::IsTerminal::is_terminal(&std::io::stderr())).then(build_bar);
        if bar.is_some() {
            env.push(("CARGO_TERM_PROGRESS_WHEN".into(), "always".into()));
            env.push(("CARGO_TERM_PROGRESS_WIDTH".into(), "100".into()));
        }
        let view = match self.prepare_view(target)? {
            Some((toolchain, framework, mechanism)) => {
                env.push((
                    "PBRLAB_EXERCISES".into(),
                    compiled
                        .to_str()
                        .context("the exercise folder's path is not UTF-8")?
                        .into(),
                ));
                Some(View::new(
                    &ViewInputs {
                        root: self.root,
                        target,
                        toolchain: &toolchain,
                        framework: &framework,
                        exercises: compiled,
                        cargo_args: &self.cargo_args(true),
                        env: &env,
                    },
                    mechanism,
                )?)
            }
            None => None,
        };
        let cargo = match &view {
            Some(view) => view.command(),
            None => {
                let mut cargo =
                    Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
                cargo
                    .current_dir(self.root)
                    .args(self.cargo_args(self.offline))
                    .envs(env.iter().map(|(k, v)| (k, v)));
                // Unset, it compiles exercises/ as it is: plain cargo builds and this one
                // then agree, and neither rebuilds after the other.
                if same_path(compiled, &self.root.join("exercises")) {
                    cargo.env_remove("PBRLAB_EXERCISES");
                } else {
                    cargo.env("PBRLAB_EXERCISES", compiled);
                }
                cargo
            }
        };
        Ok((cargo, view, bar))
    }

    fn cargo(
        &self,
        stubs: &Path,
        stubbed: bool,
        left: Duration,
        deadline: Duration,
    ) -> anyhow::Result<Round> {
        let target = std::env::var_os("CARGO_TARGET_DIR")
            .map(PathBuf::from)
            .unwrap_or_else(|| self.root.join("target"));
        // The one folder the build script compiles.
        let compiled = if stubbed { stubs } else { self.exercises };
        let (mut cargo, view, bar) = self.command(compiled, &target)?;
        bound(&mut cargo, self.bounded);
        let mut child = cargo
            .spawn()
            .context("running cargo to build the exercises")?;
        let stderr = child.stderr.take().context("cargo's stderr")?;
        let side = read_diagnostics(stderr, bar, self.echo);
        let stdout = child.stdout.take().context("cargo's stdout")?;
        let rx = read_messages(stdout, compiled.to_path_buf(), self.echo);
        let group = child.id();
        let mut round = match rx.recv_timeout(left) {
            Ok(round) => round,
            Err(_) => {
                kill_group(group);
                let _ = child.wait();
                return Err(BuildFailure::TimedOut(deadline).into());
            }
        };
        let status = child.wait().context("waiting for cargo")?;
        kill_group(group);

        round.success = round.success && status.success();
        let lines = side.join().unwrap_or_default();
        if view.as_ref().is_some_and(|v| v.failed(&status)) {
            bail!("the build's view could not be made:\n{}", lines.join("\n"));
        }
        if round.success {
            self.place_binaries(&mut round, view.as_ref())?;
        }
        self.diagnose(round, &status, lines)
    }

    /// What a finished build's diagnostics (`lines`, cargo's stderr) say beyond its JSON
    /// messages: a compiler stopped by the build's bounds (an error of the submission), and
    /// the exercise check's refusals, each charged to its task.
    fn diagnose(
        &self,
        mut round: Round,
        status: &std::process::ExitStatus,
        lines: Vec<String>,
    ) -> anyhow::Result<Round> {
        // A compiler stopped by a bound: cargo names the signal that stopped it (SIGXCPU,
        // 24, for CPU time, SIGKILL after it) or the allocation that failed. (A constant
        // too large for the memory bound is a compile error of its file, charged to its
        // task like any other.)
        let over_limit = |l: &String| {
            ["(signal: ", "memory allocation of", "File size limit"]
                .iter()
                .any(|sign| l.contains(sign))
        };
        if self.bounded && !status.success() && lines.iter().any(over_limit) {
            // What stopped it, without the compiler's command line.
            let shown: Vec<_> = lines
                .iter()
                .filter(|l| over_limit(l))
                .map(|l| l.find("(signal: ").map_or(l.trim(), |at| &l[at..]))
                .collect();
            return Err(BuildFailure::OverLimit(shown.join("\n")).into());
        }
        for line in lines {
            // The exercise build script's refusals: `exercises/<task>.rs:line:col: …`.
            if let Some(task) = refused_task(&line) {
                add_message(round.blamed.entry(task).or_default(), &line);
            }
            if line.trim_start().starts_with("error") {
                round.errors.push(line);
            }
        }
        Ok(round)
    }
}

/// Puts `cargo` in a process group of its own, so that the whole tree (rustc, the linker)
/// is killed with it and nothing outlives the build, with its output piped; when
/// `bounded`, under the build's [`BOUNDS`] (address space, CPU time, file size, no core).
fn bound(cargo: &mut Command, bounded: bool) {
    use std::os::unix::process::CommandExt;
    cargo.stdout(Stdio::piped()).stderr(Stdio::piped());
    cargo.process_group(0);
    if bounded {
        // SAFETY: between fork and exec the closure only makes setrlimit calls, which are
        // async-signal-safe, and allocates nothing.
        unsafe {
            cargo.pre_exec(move || {
                use rlimit::Resource;
                Resource::AS.set(BOUNDS.memory, BOUNDS.memory)?;
                Resource::CPU.set(BOUNDS.cpu_seconds, BOUNDS.cpu_seconds + 1)?;
                Resource::FSIZE.set(BOUNDS.file_size, BOUNDS.file_size)?;
                Resource::CORE.set(0, 0)
            });
        }
    }
}

/// Reads cargo's `stderr` on a thread of its own: its progress line drives `bar` (on a
/// terminal), every other line is shown (`echo`) and kept, up to [`MAX_OUTPUT`] bytes.
fn read_diagnostics(
    stderr: std::process::ChildStderr,
    bar: Option<indicatif::ProgressBar>,
    echo: bool,
) -> std::thread::JoinHandle<Vec<String>> {
    std::thread::spawn(move || {
        let mut lines = Vec::new();
        let mut kept = 0;
        let mut reader = BufReader::new(stderr);
        // Cargo redraws its progress line after `\r`.
        let end = |b: u8| b == b'\n' || (bar.is_some() && b == b'\r');
        while let Some(line) = super::isolation::read_until(&mut reader, end) {
            if let Some(bar) = &bar {
                if let Some((done, total)) = cargo_progress(&line) {
                    bar.set_length(total);
                    bar.set_position(done);
                    continue;
                }
                if line.trim().is_empty() {
                    continue;
                }
                bar.println(&line);
            } else if echo {
                eprintln!("{line}");
            }
            if kept + line.len() <= MAX_OUTPUT {
                kept += line.len();
                lines.push(line);
            }
        }
        if let Some(bar) = bar {
            bar.finish_and_clear();
        }
        lines
    })
}

/// Reads cargo's JSON messages from `stdout` on a thread of its own into a [`Round`]
/// (`exercises` is the folder compiled), sent when cargo closes its output.
fn read_messages(
    stdout: std::process::ChildStdout,
    exercises: PathBuf,
    echo: bool,
) -> std::sync::mpsc::Receiver<Round> {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let mut round = Round::default();
        let mut reader = BufReader::new(stdout);
        while let Some(line) = super::isolation::read_line(&mut reader) {
            read_message(&line, &exercises, echo, &mut round);
        }
        let _ = tx.send(round);
    });
    rx
}

/// Why a build of the student's code ended without binaries, when the student's code is the
/// cause: a compile-time bomb that ran into the build's time or resource bounds.
#[derive(Debug, thiserror::Error)]
pub enum BuildFailure {
    /// The build ran past its wall deadline.
    #[error(
        "the build did not finish within {} s (a loop in a `const` evaluation, or a macro or \
         type that grows without end?)",
        .0.as_secs()
    )]
    TimedOut(Duration),
    /// A compiler process ran into its memory or CPU-time bound.
    #[error(
        "the compiler ran out of its memory or CPU-time bound on this code (a huge constant, a \
         macro or type explosion?):\n{0}"
    )]
    OverLimit(String),
}

/// Kills the process group `group` (the build's cargo and everything it started).
fn kill_group(group: u32) {
    if let Ok(pid) = i32::try_from(group)
        && let Some(pid) = rustix::process::Pid::from_raw(pid)
    {
        let _ = rustix::process::kill_process_group(pid, rustix::process::Signal::KILL);
    }
}

/// The bar of a build shown on a terminal.
fn build_bar() -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(0);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "building {bar:30} {pos}/{len} crates, {elapsed} (ETA {eta})",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
    );
    bar
}

/// The units built and the units in all from cargo's progress line
/// (`    Building [=====>     ] 57/220: serde, syn`).
fn cargo_progress(line: &str) -> Option<(u64, u64)> {
    let rest = line.trim_start().strip_prefix("Building [")?;
    let (_, counts) = rest.split_once("] ")?;
    let (done, rest) = counts.split_once('/')?;
    let total = rest.split(|c: char| !c.is_ascii_digit()).next()?;
    Some((done.parse().ok()?, total.parse().ok()?))
}

/// Whether `a` and `b` name the same file or folder (compared after resolving links;
/// as written when either does not resolve).
pub(crate) fn same_path(a: &Path, b: &Path) -> bool {
    match (a.canonicalize(), b.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => a == b,
    }
}

fn add_message(to: &mut String, message: &str) {
    if to.len() + message.len() <= MAX_MESSAGE {
        if !to.is_empty() {
            to.push('\n');
        }
        to.push_str(message.trim_end());
    }
}

/// The task of a build-script refusal line, which names `exercises/<task>.rs`.
fn refused_task(line: &str) -> Option<TaskId> {
    let (_, rest) = line.split_once("exercises/")?;
    let (stem, _) = rest.split_once(".rs:")?;
    TaskId::parse(stem).ok().filter(|t| t.name() == stem)
}

/// The task whose exercise file is `file` (as the compiler names it), if any.
fn task_of(file: &str, exercises: &Path) -> Option<TaskId> {
    let path = Path::new(file);
    let stem = path.file_stem()?.to_str()?;
    let task = TaskId::parse(stem).ok().filter(|t| t.name() == stem)?;
    let parent = path.parent()?;
    let parent = if parent.is_relative() {
        // Relative to the workspace root: `exercises/<task>.rs`.
        exercises.parent().unwrap_or(exercises).join(parent)
    } else {
        parent.to_path_buf()
    };
    same_path(&parent, exercises).then_some(task)
}

/// Every file a diagnostic points at, its children's included.
fn files_of(message: &serde_json::Value, into: &mut Vec<String>) {
    for span in message["spans"].as_array().into_iter().flatten() {
        if let Some(file) = span["file_name"].as_str() {
            into.push(file.to_string());
        }
        let mut expansion = &span["expansion"];
        while let Some(site) = expansion.get("span") {
            if let Some(file) = site["file_name"].as_str() {
                into.push(file.to_string());
            }
            expansion = &site["expansion"];
        }
    }
    for child in message["children"].as_array().into_iter().flatten() {
        files_of(child, into);
    }
}

/// What a compiler message that quotes another file than the student's says instead.
const FOREIGN: &str = "  (the compiler's message quotes a file other than your exercise files, so it is \
                       not shown: the build reached outside them)";

/// Reads one line of cargo's JSON output into `round`.
fn read_message(line: &str, exercises: &Path, echo: bool, round: &mut Round) {
    let Ok(value) = serde_json::from_str::<serde_json::Value>(line) else {
        return;
    };
    match value["reason"].as_str() {
        Some("compiler-message") => {
            let message = &value["message"];
            let rendered = message["rendered"].as_str().unwrap_or_default();
            let mut files = Vec::new();
            files_of(message, &mut files);
            // A message that quotes a file other than the student's own shows its first
            // line only: what the build reached outside the exercise files is not shown.
            let foreign = files.iter().any(|f| task_of(f, exercises).is_none());
            let headline = rendered.lines().next().unwrap_or_default();
            let shown = if foreign {
                format!("{headline}\n{FOREIGN}\n")
            } else {
                rendered.replace(&format!("{}/", exercises.display()), "exercises/")
            };
            if echo {
                eprint!("{shown}");
            }
            if message["level"].as_str() != Some("error") {
                return;
            }
            round.errors.push(headline.to_string());
            let mut tasks: Vec<_> = files.iter().filter_map(|f| task_of(f, exercises)).collect();
            // A task function renamed, or with a signature that is not the task's, is found
            // where `lib.rs` builds the task table; the message names the task's module
            // (`crate::reflect`) or the function's type (`{reflect::reflect}`).
            tasks.extend(TaskId::ALL.into_iter().filter(|t| {
                rendered.contains(&format!("{{{}::", t.name()))
                    || rendered.contains(&format!("`crate::{}`", t.name()))
            }));
            tasks.sort();
            tasks.dedup();
            for task in tasks {
                add_message(round.blamed.entry(task).or_default(), &shown);
            }
        }
        Some("compiler-artifact") => {
            if let Some(executable) = value["executable"].as_str().map(PathBuf::from) {
                if value["target"]["name"].as_str() == Some(super::isolation::WORKER_BINARY) {
                    round.worker = Some(executable.clone());
                }
                round.binaries.push(executable);
            }
        }
        Some("build-finished") => round.success = value["success"].as_bool() == Some(true),
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cargo_progress_lines_give_the_units_built_and_in_all() {
        let drawn = "    Building [====>                    ] 57/220: serde, syn(build.rs)     ";
        assert_eq!(cargo_progress(drawn), Some((57, 220)));
        assert_eq!(cargo_progress("    Building [ ] 0/5: anyhow"), Some((0, 5)));
        for other in [
            "   Compiling syn v2.0.1",
            "error: Building [x] failed",
            "    Building [==>  ] a/b: x",
            "",
        ] {
            assert_eq!(cargo_progress(other), None, "{other:?}");
        }
    }

    #[test]
    fn the_compiled_copy_has_the_stub_in_place_of_each_failing_file() {
        let dir = tempfile::tempdir().unwrap();
        let exercises = dir.path().join("exercises");
        std::fs::create_dir(&exercises).unwrap();
        std::fs::write(exercises.join("reflect.rs"), "// refused: mod stolen;").unwrap();
        std::fs::write(exercises.join("mis.rs"), "// mine").unwrap();
        let stub = |task: TaskId| Ok(format!("// the stub of {}", task.name()));
        let build = StudentBuild {
            root: dir.path(),
            exercises: &exercises,
            commands: false,
            handout: false,
            stub: &stub,
            echo: false,
            deadline: Duration::from_secs(1),
            offline: true,
            output: None,
            bounded: true,
        };
        let copy = stub_folder(&exercises);
        let errors = [(TaskId::Reflect, "refused".to_string())].into();
        build.place_stubs(&copy, &errors).unwrap();
        let read = |name: &str| std::fs::read_to_string(copy.join(name)).ok();
        assert_eq!(
            read("reflect.rs").as_deref(),
            Some("// the stub of reflect")
        );
        assert_eq!(read("mis.rs").as_deref(), Some("// mine"));
        assert_eq!(read("smith_g1.rs"), None, "a missing file stays missing");
        assert!(
            !copy.starts_with(&exercises),
            "the copy is not the student's folder"
        );
        build.place_stubs(&copy, &BTreeMap::new()).unwrap();
        assert!(!copy.exists(), "no copy when nothing failed");
    }

    #[test]
    fn a_refusal_line_names_its_task() {
        let line = "error: pbrlab-exercises@0.1.0: exercises/smith_g1.rs:4:9: not allowed";
        assert_eq!(refused_task(line), Some(TaskId::SmithG1));
        assert_eq!(refused_task("error: exercises/lib.rs:1:1: x"), None);
        assert_eq!(refused_task("error: could not compile"), None);
    }

    #[test]
    fn a_diagnostic_is_charged_to_the_exercise_files_it_points_at() {
        let dir = tempfile::tempdir().unwrap();
        let exercises = dir.path().join("exercises");
        std::fs::create_dir(&exercises).unwrap();
        let file = exercises.join("mis.rs");
        let line = serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "rendered": format!("error: expected `;`\n --> {}:3:5\n", file.display()),
                "spans": [{"file_name": exercises.join("lib.rs").display().to_string(),
                           "expansion": {"span": {"file_name": file.display().to_string()}}}],
                "children": [{"spans": [{"file_name": "src/integrator/mis.rs"}]}]
            }
        });
        let mut round = Round::default();
        read_message(&line.to_string(), &exercises, false, &mut round);
        assert_eq!(
            round.blamed.keys().copied().collect::<Vec<_>>(),
            [TaskId::Mis]
        );
        let signature = serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "rendered": "error[E0308]: mismatched types\n --> exercises/lib.rs:31:48\n                              = note: found fn item `fn(Vec3) -> Vec3 {reflect::reflect}`",
                "spans": [{"file_name": "exercises/lib.rs"}],
            }
        });
        read_message(&signature.to_string(), &exercises, false, &mut round);
        assert_eq!(
            round.blamed.keys().copied().collect::<Vec<_>>(),
            [TaskId::Reflect, TaskId::Mis],
            "a signature that is not the task's is charged to the task"
        );
        assert!(
            round.blamed[&TaskId::Mis].starts_with("error: expected `;`")
                && round.blamed[&TaskId::Mis].contains(FOREIGN)
                && !round.blamed[&TaskId::Mis].contains("-->"),
            "a message that quotes another file shows its first line only: {:?}",
            round.blamed
        );
        let renamed = serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "rendered": "error[E0425]: cannot find value `smith_g1` in module `crate::smith_g1`\n --> exercises/lib.rs:40:40\n   | pub static TASKS",
                "spans": [{"file_name": "exercises/lib.rs"}],
            }
        });
        read_message(&renamed.to_string(), &exercises, false, &mut round);
        assert!(
            round.blamed.contains_key(&TaskId::SmithG1),
            "a renamed task function is charged to its task: {:?}",
            round.blamed
        );
        assert!(!round.blamed[&TaskId::SmithG1].contains("pub static TASKS"));
        let own = serde_json::json!({
            "reason": "compiler-message",
            "message": {
                "level": "error",
                "rendered": format!("error: expected `;`\n --> {}:7:1\n", exercises.join("phong.rs").display()),
                "spans": [{"file_name": exercises.join("phong.rs").display().to_string()}],
            }
        });
        read_message(&own.to_string(), &exercises, false, &mut round);
        assert!(
            round.blamed[&TaskId::Phong].contains("--> exercises/phong.rs:7:1"),
            "a message on the student's own file is shown whole, naming the file as the \
             student knows it: {:?}",
            round.blamed
        );
    }

    #[test]
    fn a_record_of_another_binary_is_ignored() {
        let dir = tempfile::tempdir().unwrap();
        let worker = dir.path().join("pbrlab-worker");
        std::fs::write(&worker, "old").unwrap();
        let record = BuildRecord {
            exercises: dir.path().into(),
            worker: worker.clone(),
            compile_errors: [("reflect".to_string(), "error".to_string())].into(),
            worker_modified: modified_nanos(&worker).unwrap(),
        };
        std::fs::write(
            worker.with_file_name(RECORD),
            serde_json::to_string(&record).unwrap(),
        )
        .unwrap();
        assert_eq!(BuildRecord::of(&worker), Some(record.clone()));
        assert_eq!(
            record.errors().keys().copied().collect::<Vec<_>>(),
            [TaskId::Reflect]
        );
        let later = std::time::SystemTime::now() + Duration::from_secs(5);
        std::fs::File::options()
            .write(true)
            .open(&worker)
            .unwrap()
            .set_modified(later)
            .unwrap();
        assert_eq!(BuildRecord::of(&worker), None, "rebuilt since: no record");
    }
}
