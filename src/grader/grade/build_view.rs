//! The view a build of student code compiles in: what it can read is what the framework's
//! own build read, and nothing else.
//!
//! Compiling is running the student's code (macro expansion and `const` evaluation decide
//! what `include!`, `include_bytes!`, `#[path]`, `env!` or `global_asm!`'s `.incbin` read),
//! so no check of the source text can bound what a build reads; its view of the file
//! system can. A build of the student's crate runs cargo inside `pbrlab-build-view`
//! (`src/build-view/`): new user, mount, PID, network and IPC namespaces, and a root that
//! holds only:
//!
//! - the system's programs and libraries (`/usr`, and the few files of `/etc` the dynamic
//!   loader and the C compiler driver read), `/dev/null` and the random devices;
//! - the toolchain, resolved to its folder before the build ([`Toolchain`]), and the
//!   registry's sources (read-only; no `CARGO_HOME` settings or credentials);
//! - of the repository: the workspace's manifests and lock file, and the files the view
//!   compiles (the framework-owned `exercises/lib.rs` and `build.rs`, the worker's two
//!   `main` files). Every source file that the framework's compilation read (the compiler's
//!   dep-info of each unit the worker's build shares with it) is there as an empty file of
//!   the same date, which is all cargo compares: no framework source text, no `solutions/`,
//!   no tests' variants, no `.git`, no tests;
//! - of the target folder: an empty folder of this build's own, with the framework's
//!   compiled units (those of a build of the shipped stubs, [`Framework::prepare`]) bound
//!   in read-only, and no other unit (not the reference's, not another submission's);
//! - the exercise files compiled (read-only), a `/tmp` of its own, and a `/proc` that shows
//!   only the build's processes;
//! - an environment of a few named variables ([`View::new`]).
//!
//! Everything else, the submissions and results folders of a class run, the grader's
//! command line and environment, other users' files, does not exist for the build.
//!
//! Where the kernel makes no user namespaces (Docker's default seccomp profile), the same
//! view is made by Landlock ([`Mechanism::Landlock`]): cargo runs on the host's file system,
//! reading only the files above (the framework's other sources can be dated, as cargo does,
//! not read), listing the folders cargo lists, writing only a target folder of its own into
//! which the framework's units are linked, with no `/proc` and no TCP. [`choose`] takes
//! namespaces, else Landlock, else says why neither holds.

use anyhow::{Context, bail};
use serde::Deserialize;
use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicU64, Ordering};

/// The program that makes the view (`src/build-view/`).
pub const VIEW_BINARY: &str = "pbrlab-build-view";

/// The exit status of `pbrlab-build-view` when it could not make the view.
const VIEW_FAILED: i32 = 121;

/// The packages whose units a build in the view compiles itself: the student's crate and
/// the binaries that link it. Every other unit of the worker's build is the framework's.
const STUDENT_PACKAGES: &[&str] = &["pbrlab-exercises", "pbrlab-worker", "pbrlab-commands"];

/// Variables of the grader's environment that a build in the view keeps: they change how
/// cargo compiles (and so whether the framework's units are current), and they are the
/// course's, never the student's.
const KEPT_VARIABLES: &[&str] = &[
    "RUSTFLAGS",
    "CARGO_ENCODED_RUSTFLAGS",
    "CARGO_BUILD_RUSTFLAGS",
    "CARGO_INCREMENTAL",
    "CARGO_TERM_COLOR",
    "CARGO_TERM_PROGRESS_WHEN",
    "CARGO_TERM_PROGRESS_WIDTH",
];

/// The files of `/etc` a build reads: the dynamic loader's cache and settings, and the
/// alternatives that `cc` resolves through.
const ETC_FILES: &[&str] = &["ld.so.cache", "ld.so.conf", "ld.so.conf.d", "alternatives"];

/// The devices a build uses.
const DEVICES: &[&str] = &["null", "zero", "full", "random", "urandom"];

/// The largest `/tmp` of a build, in bytes.
const TMP_SIZE: u64 = 2 << 30;

/// The Rust toolchain, resolved to its own folder before any sandbox is entered: `cargo`
/// on PATH may be rustup's proxy, whose settings (`RUSTUP_HOME`, `CARGO_HOME`) a build in
/// the view does not see.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Toolchain {
    /// The toolchain's folder (`rustc --print sysroot`).
    pub sysroot: PathBuf,
    /// Its cargo.
    pub cargo: PathBuf,
    /// Its rustc.
    pub rustc: PathBuf,
}

impl Toolchain {
    /// The toolchain that builds the workspace at `root` (rustup's overrides there
    /// included): `$RUSTC` or `rustc` on PATH is asked for its sysroot.
    pub fn resolve(root: &Path) -> anyhow::Result<Self> {
        let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
        let out = Command::new(&rustc)
            .args(["--print", "sysroot"])
            .current_dir(root)
            .stdin(Stdio::null())
            .output()
            .with_context(|| {
                format!(
                    "running `{} --print sysroot` to find the Rust toolchain (is rustc on PATH?)",
                    Path::new(&rustc).display()
                )
            })?;
        if !out.status.success() {
            bail!(
                "`{} --print sysroot` failed: {}",
                Path::new(&rustc).display(),
                String::from_utf8_lossy(&out.stderr).trim()
            );
        }
        let sysroot = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
        let sysroot = sysroot
            .canonicalize()
            .with_context(|| format!("the toolchain folder {}", sysroot.display()))?;
        let toolchain = Self {
            cargo: sysroot.join("bin").join("cargo"),
            rustc: sysroot.join("bin").join("rustc"),
            sysroot,
        };
        for program in [&toolchain.cargo, &toolchain.rustc] {
            anyhow::ensure!(
                program.is_file(),
                "the toolchain at {} has no {} (install cargo with the toolchain)",
                toolchain.sysroot.display(),
                program.display()
            );
        }
        Ok(toolchain)
    }
}

/// The framework as a build in the view finds it: the compiled units it may read, and the
/// program that makes the view.
#[derive(Clone, Debug)]
pub struct Framework {
    /// The files and folders of `target/release/{deps,build,.fingerprint}` of the units the
    /// worker's build shares with a build of the shipped stubs.
    units: Vec<PathBuf>,
    /// The source files that build read (the compiler's dep-info, and the files its build
    /// scripts watch). The view has each as an empty file of the same date: cargo compares
    /// dates, and no compilation in the view reads them (the framework is compiled).
    sources: BTreeSet<PathBuf>,
    /// The source files that a build in the view compiles (bound in whole).
    compiled: BTreeSet<PathBuf>,
    /// The folders its build scripts watch (cargo compares their contents' times).
    folders: BTreeSet<PathBuf>,
    /// `pbrlab-build-view`.
    pub helper: PathBuf,
}

/// One line of cargo's JSON messages, the fields read here.
#[derive(Deserialize)]
struct Message {
    #[serde(default)]
    package_id: String,
    #[serde(default)]
    filenames: Vec<PathBuf>,
    #[serde(default)]
    out_dir: Option<PathBuf>,
    #[serde(default)]
    executable: Option<PathBuf>,
    #[serde(default)]
    target: Option<MessageTarget>,
}

/// The target of a compiler artifact, the field read here.
#[derive(Deserialize)]
struct MessageTarget {
    src_path: PathBuf,
}

/// The package name in a cargo package id (`path+file:///x/src#pbrlab@0.1.0`,
/// `registry+…#glam@0.34.2`, or the older `glam 0.34.2 (registry+…)`).
fn package_name(id: &str) -> &str {
    if let Some((_, rest)) = id.rsplit_once('#') {
        return rest.split('@').next().unwrap_or(rest);
    }
    id.split(' ').next().unwrap_or(id)
}

/// The metadata hash at the end of a unit's file or folder name (`libglam-0123456789abcdef.rlib`,
/// `build/glam-0123456789abcdef/out`), when it has one.
fn unit_hash(name: &str) -> Option<&str> {
    let stem = name.split('.').next().unwrap_or(name);
    let (_, hash) = stem.rsplit_once('-')?;
    (hash.len() == 16 && hash.bytes().all(|b| b.is_ascii_hexdigit())).then_some(hash)
}

impl Framework {
    /// Builds the framework's libraries (trusted: the shipped stubs in place of the
    /// student's files, outside any sandbox; no binary, so that nothing replaces the
    /// student's worker) with `cargo` and `build_args`, which select what the student's
    /// build selects, and reads which units it used; then builds `pbrlab-build-view`. Both
    /// are no-ops when current.
    pub fn prepare(
        root: &Path,
        target: &Path,
        toolchain: &Toolchain,
        build_args: &[String],
        stubs: &Path,
        offline: bool,
    ) -> anyhow::Result<Self> {
        let messages = cargo_json(
            root,
            toolchain,
            build_args,
            &[("PBRLAB_EXERCISES", stubs.as_os_str())],
        )
        .context("building the framework from the shipped stubs")?;
        // The hashes of the framework's units, and of every unit the build read sources
        // for (the worker's own sources too; the stubs are under the target folder).
        let mut framework = BTreeSet::new();
        let mut all = BTreeSet::new();
        for message in &messages {
            let student = STUDENT_PACKAGES.contains(&package_name(&message.package_id));
            for file in message.filenames.iter().chain(&message.out_dir) {
                // `deps/libx-<hash>.rlib`, `build/x-<hash>/build-script-build`,
                // `build/x-<hash>/out`: the hash is in the first name below `deps` or
                // `build`.
                let hash = file
                    .ancestors()
                    .zip(file.ancestors().skip(1))
                    .find(|(_, parent)| {
                        parent
                            .file_name()
                            .is_some_and(|n| n == "deps" || n == "build")
                    })
                    .and_then(|(unit, _)| unit.file_name()?.to_str())
                    .and_then(unit_hash);
                if let Some(hash) = hash {
                    all.insert(hash.to_string());
                    if !student {
                        framework.insert(hash.to_string());
                    }
                }
            }
        }
        anyhow::ensure!(
            !framework.is_empty(),
            "cargo reported no unit of the framework's build"
        );
        let of = |set: &BTreeSet<String>, name: &std::ffi::OsStr| {
            name.to_str()
                .and_then(unit_hash)
                .is_some_and(|h| set.contains(h))
        };
        let release = target.join("release");
        let mut units = Vec::new();
        let mut read = Vec::new();
        for sub in ["deps", "build", ".fingerprint"] {
            let folder = release.join(sub);
            let Ok(entries) = std::fs::read_dir(&folder) else {
                continue;
            };
            for entry in entries.flatten() {
                let name = entry.file_name();
                if of(&framework, &name) {
                    units.push(entry.path());
                }
                if of(&all, &name) && sub != ".fingerprint" {
                    read.push(entry.path());
                }
            }
        }
        units.sort();
        let packages = workspace_packages(root)?;
        // The files the view compiles: the root file of each target of the student's
        // crate (the framework-owned `exercises/lib.rs` and `build.rs`), and the worker's
        // binaries (one file each, in the worker's package, which the framework's build
        // does not link).
        let mut compiled: BTreeSet<PathBuf> = messages
            .iter()
            .filter(|m| STUDENT_PACKAGES.contains(&package_name(&m.package_id)))
            .filter_map(|m| Some(m.target.as_ref()?.src_path.clone()))
            .collect();
        for package in &packages {
            let manifest = std::fs::read_to_string(package.join("Cargo.toml")).unwrap_or_default();
            if manifest.contains("name = \"pbrlab-worker\"") {
                for entry in std::fs::read_dir(package).into_iter().flatten().flatten() {
                    if entry.path().extension().is_some_and(|x| x == "rs") {
                        compiled.insert(entry.path());
                    }
                }
            }
        }
        let mut sources = BTreeSet::new();
        let mut folders = BTreeSet::new();
        for unit in &read {
            let dep_infos: Vec<PathBuf> = if unit.is_dir() {
                std::fs::read_dir(unit)
                    .into_iter()
                    .flatten()
                    .flatten()
                    .map(|e| e.path())
                    .filter(|p| p.extension().is_some_and(|x| x == "d"))
                    .collect()
            } else if unit.extension().is_some_and(|x| x == "d") {
                vec![unit.clone()]
            } else {
                Vec::new()
            };
            for dep_info in dep_infos {
                let text = std::fs::read_to_string(&dep_info)
                    .with_context(|| format!("reading {}", dep_info.display()))?;
                sources.extend(dep_info_sources(&text, root).iter().map(|p| normal(p)));
            }
            // A build script's watched paths (`rerun-if-changed`), which cargo compares
            // too: files among the view's, folders made in it with their times. They are
            // relative to the script's package, which the output does not name; a path
            // tried against every package of the workspace that is not there adds nothing.
            if let Ok(output) = std::fs::read_to_string(unit.join("output")) {
                for package in &packages {
                    for watched in watched_paths(&output, package) {
                        let watched = normal(&watched);
                        if watched.is_dir() {
                            if watched.starts_with(root) && !watched.starts_with(target) {
                                folders.insert(watched);
                            }
                        } else {
                            sources.insert(watched);
                        }
                    }
                }
            }
        }
        let mut helper_args = vec![
            "build".to_string(),
            "--release".into(),
            "--message-format=json".into(),
            "-p".into(),
            "pbrlab-build-view".into(),
        ];
        if offline {
            helper_args.extend(["--offline".into(), "--locked".into()]);
        }
        let helper = cargo_json(root, toolchain, &helper_args, &[])
            .context("building pbrlab-build-view")?
            .into_iter()
            .find_map(|m| m.executable)
            .context("cargo did not report the pbrlab-build-view binary")?;
        Ok(Self {
            units,
            sources,
            compiled,
            folders,
            helper,
        })
    }
}

/// Runs cargo with `args` and `env` outside any sandbox and returns its JSON messages;
/// fails with cargo's errors when the build fails.
fn cargo_json(
    root: &Path,
    toolchain: &Toolchain,
    args: &[String],
    env: &[(&str, &std::ffi::OsStr)],
) -> anyhow::Result<Vec<Message>> {
    let out = Command::new(&toolchain.cargo)
        .args(args)
        .current_dir(root)
        .env("RUSTC", &toolchain.rustc)
        .envs(env.iter().map(|(k, v)| (k, v)))
        .stdin(Stdio::null())
        .output()
        .with_context(|| format!("running {}", toolchain.cargo.display()))?;
    let messages: Vec<Message> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect();
    if !out.status.success() {
        let stderr = String::from_utf8_lossy(&out.stderr);
        let errors: Vec<&str> = stderr
            .lines()
            .filter(|l| !l.trim_start().starts_with("Compiling"))
            .collect();
        bail!("cargo failed:\n{}", errors.join("\n"));
    }
    Ok(messages)
}

/// What a build in the view compiles, and where.
pub struct ViewInputs<'a> {
    /// The workspace root.
    pub root: &'a Path,
    /// The target folder of the workspace (`target/` or `$CARGO_TARGET_DIR`).
    pub target: &'a Path,
    /// The toolchain.
    pub toolchain: &'a Toolchain,
    /// The framework's units and the view's program.
    pub framework: &'a Framework,
    /// The folder of exercise files compiled.
    pub exercises: &'a Path,
    /// Cargo's arguments.
    pub cargo_args: &'a [String],
    /// Variables set for the build beyond the view's own (`PBRLAB_EXERCISES` and the like).
    pub env: &'a [(String, String)],
}

/// How a view is made: new namespaces where the kernel allows them, Landlock where it does
/// not (containers that refuse user namespaces), never neither.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mechanism {
    /// `pbrlab-build-view`: new user, mount, PID, network and IPC namespaces, and a root of
    /// named binds. The framework's other sources are empty files of the same date.
    Namespaces,
    /// Landlock: cargo runs on the host's file system, reading only what the view would
    /// hold (other sources can be dated, not read; no `/proc`, no TCP), with a target folder
    /// of its own into which the framework's units are linked.
    Landlock,
}

impl std::fmt::Display for Mechanism {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Self::Namespaces => "namespaces (user, mount, PID, network, IPC) and a root of named binds",
            Self::Landlock => "Landlock (reads limited to the view's files, no /proc, no TCP) and a target folder of its own",
        })
    }
}

/// The variable that picks the mechanism (`namespaces` or `landlock`) instead of the first
/// that works: the grader's, for tests and for hosts where one misbehaves.
pub const MECHANISM: &str = "PBRLAB_BUILD_VIEW";

/// The mechanism a view is made with here: `$PBRLAB_BUILD_VIEW` when set, else namespaces
/// when a probe view can be made, else Landlock when the kernel enforces it; an error that
/// says why neither is there otherwise.
pub fn choose(helper: &Path, target: &Path) -> anyhow::Result<Mechanism> {
    match std::env::var(MECHANISM).ok().as_deref() {
        Some("namespaces") => return probe(helper, target).map(|()| Mechanism::Namespaces),
        Some("landlock") => return landlock_scope::probe().map(|()| Mechanism::Landlock),
        Some(other) => bail!("{MECHANISM}={other}: use `namespaces` or `landlock`"),
        None => {}
    }
    let namespaces = match probe(helper, target) {
        Ok(()) => return Ok(Mechanism::Namespaces),
        Err(e) => e,
    };
    match landlock_scope::probe() {
        Ok(()) => Ok(Mechanism::Landlock),
        Err(landlock) => bail!(
            "no build view can be made here: namespaces: {namespaces:#}; Landlock: {landlock:#}"
        ),
    }
}

/// One build's view: the folder its target folder is, and for namespaces its spec file and
/// the mount point of its root (all removed when it is dropped), or for Landlock the
/// prepared rules.
pub struct View {
    target: PathBuf,
    own_target: PathBuf,
    how: How,
}

/// The mechanism's part of a [`View`].
enum How {
    Namespaces {
        spec: PathBuf,
        mount_point: PathBuf,
        helper: PathBuf,
    },
    Landlock {
        root: PathBuf,
        cargo: PathBuf,
        args: Vec<String>,
        env: Vec<(String, String)>,
        scope: std::sync::Arc<landlock_scope::Scope>,
    },
}

/// A number that no other view of this process has.
fn next_id() -> u64 {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    NEXT.fetch_add(1, Ordering::Relaxed)
}

/// A spec file being written: one step a line, tab-separated (`src/build-view/main.rs`).
struct Spec {
    text: String,
}

impl Spec {
    fn line(&mut self, fields: &[&str]) -> anyhow::Result<()> {
        for field in fields {
            anyhow::ensure!(
                !field.contains(['\t', '\n']),
                "a path or value of the build holds a tab or a line break: {field:?}"
            );
        }
        self.text.push_str(&fields.join("\t"));
        self.text.push('\n');
        Ok(())
    }

    fn path(path: &Path) -> anyhow::Result<&str> {
        path.to_str()
            .with_context(|| format!("{} is not UTF-8", path.display()))
    }

    /// `host` bound at the same path, read-only unless `writable`.
    fn bind(&mut self, host: &Path, view: &Path, writable: bool) -> anyhow::Result<()> {
        let op = if writable { "rw" } else { "ro" };
        self.line(&[op, Self::path(host)?, Self::path(view)?])
    }

    /// The folder `path` with its host modification time.
    fn dir(&mut self, path: &Path) -> anyhow::Result<()> {
        self.dated("dir", path)
    }

    /// An empty file at `path` with the host file's modification time.
    fn placeholder(&mut self, path: &Path) -> anyhow::Result<()> {
        self.dated("file", path)
    }

    fn dated(&mut self, op: &str, path: &Path) -> anyhow::Result<()> {
        let modified = std::fs::metadata(path)
            .and_then(|m| m.modified())
            .with_context(|| format!("reading {}", path.display()))?;
        let since = modified
            .duration_since(std::time::UNIX_EPOCH)
            .unwrap_or_default();
        self.line(&[
            op,
            Self::path(path)?,
            &since.as_secs().to_string(),
            &since.subsec_nanos().to_string(),
        ])
    }
}

/// The source files named by a dep-info file (`target: a.rs b.rs`, spaces escaped with `\`),
/// relative ones resolved against `root`.
fn dep_info_sources(text: &str, root: &Path) -> Vec<PathBuf> {
    let mut sources = Vec::new();
    for line in text.lines() {
        let Some((_, deps)) = line.split_once(": ") else {
            continue;
        };
        let mut current = String::new();
        let mut chars = deps.chars().peekable();
        while let Some(c) = chars.next() {
            match c {
                '\\' if chars.peek() == Some(&' ') => {
                    current.push(' ');
                    chars.next();
                }
                ' ' => {
                    if !current.is_empty() {
                        sources.push(root.join(std::mem::take(&mut current)));
                    }
                }
                c => current.push(c),
            }
        }
        if !current.is_empty() {
            sources.push(root.join(current));
        }
    }
    sources
}

/// The paths a build script's `output` asks cargo to watch (`cargo::rerun-if-changed=P`),
/// relative ones resolved against the package folder, `package`.
fn watched_paths(output: &str, package: &Path) -> Vec<PathBuf> {
    output
        .lines()
        .filter_map(|l| {
            l.strip_prefix("cargo::rerun-if-changed=")
                .or_else(|| l.strip_prefix("cargo:rerun-if-changed="))
        })
        .map(|p| package.join(p))
        .collect()
}

/// `path` with `.` and `..` resolved by the text alone (the paths here are a build's, under
/// folders that exist).
fn normal(path: &Path) -> PathBuf {
    let mut out = PathBuf::new();
    for part in path.components() {
        match part {
            std::path::Component::ParentDir => {
                out.pop();
            }
            std::path::Component::CurDir => {}
            other => out.push(other),
        }
    }
    out
}

/// What a view holds of the repository: the files it reads whole (manifests, lock file,
/// the files the view compiles), the framework's other sources (dated, not read), and the
/// folders cargo dates.
struct Repository {
    files: Vec<PathBuf>,
    placeholders: Vec<PathBuf>,
    folders: BTreeSet<PathBuf>,
}

impl Repository {
    fn of(inputs: &ViewInputs) -> anyhow::Result<Self> {
        let root = inputs.root;
        let mut files: BTreeSet<PathBuf> = workspace_manifests(root)?.into_iter().collect();
        files.insert(root.join("Cargo.lock"));
        for name in ["Cargo.toml", "lib.rs", "build.rs"] {
            files.insert(root.join("exercises").join(name));
        }
        for name in ["config.toml", "config"] {
            files.insert(root.join(".cargo").join(name));
        }
        files.extend(inputs.framework.compiled.iter().cloned());
        // Only the repository's files: the registry and toolchain are bound whole, and
        // nothing of the target folder but the framework's units.
        let in_repository =
            |f: &PathBuf| f.starts_with(root) && !f.starts_with(inputs.target) && f.is_file();
        let files: Vec<PathBuf> = files.into_iter().filter(in_repository).collect();
        let placeholders: Vec<PathBuf> = inputs
            .framework
            .sources
            .iter()
            .filter(|f| in_repository(f) && !files.contains(f))
            .cloned()
            .collect();
        let mut folders = inputs.framework.folders.clone();
        for file in files.iter().chain(&placeholders) {
            for folder in file.ancestors().skip(1) {
                if !folder.starts_with(root) {
                    break;
                }
                folders.insert(folder.to_path_buf());
            }
        }
        Ok(Self {
            files,
            placeholders,
            folders,
        })
    }
}

/// The environment of a build in a view: a few named variables, the build-affecting ones
/// of the grader's ([`KEPT_VARIABLES`], `CARGO_PROFILE_*`), and `extra`.
fn environment(
    toolchain: &Toolchain,
    home: &Path,
    cargo_home: &Path,
    target: &Path,
    extra: &[(String, String)],
) -> anyhow::Result<Vec<(String, String)>> {
    let path = format!("{}/bin:/usr/bin:/bin", Spec::path(&toolchain.sysroot)?);
    let mut env: Vec<(String, String)> = vec![
        ("PATH".into(), path),
        ("HOME".into(), Spec::path(home)?.into()),
        ("TMPDIR".into(), Spec::path(home)?.into()),
        ("CARGO_HOME".into(), Spec::path(cargo_home)?.into()),
        ("CARGO_TARGET_DIR".into(), Spec::path(target)?.into()),
        ("RUSTC".into(), Spec::path(&toolchain.rustc)?.into()),
    ];
    for key in KEPT_VARIABLES {
        if let Ok(value) = std::env::var(key) {
            env.push((key.to_string(), value));
        }
    }
    for (key, value) in std::env::vars() {
        if key.starts_with("CARGO_PROFILE_") {
            env.push((key, value));
        }
    }
    env.extend(extra.iter().cloned());
    Ok(env)
}

/// Links `from` (a file, or a folder and everything in it) at `to`, file by file: a hard
/// link where the file system allows one, else a copy with the file's modification time
/// (cargo compares a unit's outputs' times with its dependents'). A link is safe here: the
/// build reads these units, and a unit it found out of date could not be rebuilt in place
/// (its sources cannot be read), while cargo only removes or renames what it replaces.
fn copy_all(from: &Path, to: &Path) -> anyhow::Result<()> {
    if from.is_dir() {
        std::fs::create_dir_all(to).with_context(|| format!("making {}", to.display()))?;
        for entry in
            std::fs::read_dir(from).with_context(|| format!("reading {}", from.display()))?
        {
            let entry = entry?;
            copy_all(&entry.path(), &to.join(entry.file_name()))?;
        }
    } else if std::fs::hard_link(from, to).is_err() {
        std::fs::copy(from, to).with_context(|| format!("copying {}", from.display()))?;
        let modified = std::fs::metadata(from)?.modified()?;
        std::fs::File::options()
            .write(true)
            .open(to)?
            .set_modified(modified)
            .with_context(|| format!("dating {}", to.display()))?;
    }
    Ok(())
}

impl View {
    /// Prepares a view for `inputs` made with `mechanism`, and its folders.
    pub fn new(inputs: &ViewInputs, mechanism: Mechanism) -> anyhow::Result<Self> {
        let work = inputs.target.join("pbrlab-view");
        let id = format!("{}-{}", std::process::id(), next_id());
        let own_target = work.join(format!("target-{id}"));
        std::fs::create_dir_all(own_target.join("release"))
            .with_context(|| format!("making {}", own_target.display()))?;
        let how = match mechanism {
            Mechanism::Namespaces => Self::namespaces(inputs, &work, &id, &own_target)?,
            Mechanism::Landlock => Self::landlock(inputs, &own_target)?,
        };
        Ok(Self {
            target: inputs.target.to_path_buf(),
            own_target,
            how,
        })
    }

    /// Writes the spec of a view made of namespaces.
    fn namespaces(
        inputs: &ViewInputs,
        work: &Path,
        id: &str,
        own_target: &Path,
    ) -> anyhow::Result<How> {
        let root = inputs.root;
        let spec_file = work.join(format!("spec-{id}"));
        let mount_point = work.join(format!("root-{id}"));
        std::fs::create_dir_all(&mount_point)
            .with_context(|| format!("making {}", mount_point.display()))?;
        let mut spec = Spec {
            text: String::new(),
        };
        spec.line(&["root", Spec::path(&mount_point)?])?;
        // The system: merged-/usr links as the host has them, programs and libraries.
        for top in ["bin", "sbin", "lib", "lib32", "lib64", "libx32"] {
            let host = Path::new("/").join(top);
            match std::fs::read_link(&host) {
                Ok(target) => spec.line(&["link", Spec::path(&target)?, Spec::path(&host)?])?,
                Err(_) if host.is_dir() => spec.bind(&host, &host, false)?,
                Err(_) => {}
            }
        }
        spec.bind(Path::new("/usr"), Path::new("/usr"), false)?;
        for file in ETC_FILES {
            let host = Path::new("/etc").join(file);
            if host.exists() {
                spec.bind(&host, &host, false)?;
            }
        }
        for device in DEVICES {
            let host = Path::new("/dev").join(device);
            if host.exists() {
                spec.bind(&host, &host, true)?;
            }
        }
        spec.line(&["proc", "/proc"])?;
        spec.line(&["tmpfs", "/tmp", &TMP_SIZE.to_string()])?;
        // The toolchain, and the registry's sources at their own paths (the framework's
        // units name them) in a `CARGO_HOME` that holds nothing else.
        let toolchain = inputs.toolchain;
        spec.bind(&toolchain.sysroot, &toolchain.sysroot, false)?;
        let cargo_home = cargo_home()?;
        spec.line(&[
            "tmpfs",
            Spec::path(&cargo_home)?,
            &(16u64 << 20).to_string(),
        ])?;
        let registry = cargo_home.join("registry");
        if registry.is_dir() {
            spec.bind(&registry, &registry, false)?;
        }
        // The repository: what the framework's compilation read.
        let repository = Repository::of(inputs)?;
        for file in &repository.files {
            spec.bind(file, file, false)?;
        }
        for file in &repository.placeholders {
            spec.placeholder(file)?;
        }
        // A folder the exercise files are bound on is theirs, time and all.
        for folder in repository
            .folders
            .iter()
            .filter(|f| !f.starts_with(inputs.exercises))
        {
            spec.dir(folder)?;
        }
        // The target folder: this build's own, with the framework's units in it.
        spec.bind(own_target, inputs.target, true)?;
        for unit in &inputs.framework.units {
            spec.bind(unit, unit, false)?;
        }
        spec.bind(inputs.exercises, inputs.exercises, false)?;
        spec.line(&["cwd", Spec::path(root)?])?;
        let env = environment(
            toolchain,
            Path::new("/tmp"),
            &cargo_home,
            inputs.target,
            inputs.env,
        )?;
        for (key, value) in &env {
            spec.line(&["env", key, value])?;
        }
        let cargo = Spec::path(&toolchain.cargo)?;
        let mut run = vec!["run", cargo];
        run.extend(inputs.cargo_args.iter().map(String::as_str));
        spec.line(&run)?;
        std::fs::write(&spec_file, spec.text)
            .with_context(|| format!("writing {}", spec_file.display()))?;
        Ok(How::Namespaces {
            spec: spec_file,
            mount_point,
            helper: inputs.framework.helper.clone(),
        })
    }

    /// Prepares a view made by Landlock: the framework's units linked into the build's own
    /// target folder ([`copy_all`]), and the rules.
    fn landlock(inputs: &ViewInputs, own_target: &Path) -> anyhow::Result<How> {
        let release = inputs.target.join("release");
        for unit in &inputs.framework.units {
            let rest = unit
                .strip_prefix(&release)
                .with_context(|| format!("{} is not in {}", unit.display(), release.display()))?;
            let to = own_target.join("release").join(rest);
            if let Some(parent) = to.parent() {
                std::fs::create_dir_all(parent)?;
            }
            copy_all(unit, &to)?;
        }
        let home = own_target.join("home");
        std::fs::create_dir_all(&home)?;
        let toolchain = inputs.toolchain;
        let cargo_home = cargo_home()?;
        let repository = Repository::of(inputs)?;
        let mut readable: Vec<PathBuf> = ["/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64"]
            .iter()
            .map(PathBuf::from)
            .chain(ETC_FILES.iter().map(|f| Path::new("/etc").join(f)))
            .chain(DEVICES.iter().map(|d| Path::new("/dev").join(d)))
            .collect();
        readable.extend([
            toolchain.sysroot.clone(),
            cargo_home.join("registry"),
            cargo_home.join("config.toml"),
            cargo_home.join("config"),
            inputs.exercises.to_path_buf(),
        ]);
        readable.extend(repository.files.iter().cloned());
        let writable = vec![own_target.to_path_buf()];
        let writable_files: Vec<PathBuf> =
            [".package-cache", ".package-cache-mutate", ".global-cache"]
                .iter()
                .map(|f| cargo_home.join(f))
                .chain(["/dev/null".into()])
                .collect();
        // The folders cargo lists: the framework's sources in them can be dated, not read.
        let listable: Vec<PathBuf> = repository.folders.iter().cloned().collect();
        let scope = landlock_scope::Scope::new(&readable, &listable, &writable, &writable_files)?;
        let env = environment(toolchain, &home, &cargo_home, own_target, inputs.env)?;
        Ok(How::Landlock {
            root: inputs.root.to_path_buf(),
            cargo: toolchain.cargo.clone(),
            args: inputs.cargo_args.to_vec(),
            env,
            scope: std::sync::Arc::new(scope),
        })
    }

    /// The command that runs the build in the view (its environment is the view's).
    pub fn command(&self) -> Command {
        match &self.how {
            How::Namespaces { spec, helper, .. } => {
                let mut command = Command::new(helper);
                command.arg(spec).env_clear();
                command
            }
            How::Landlock {
                root,
                cargo,
                args,
                env,
                scope,
            } => {
                let mut command = Command::new(cargo);
                command
                    .args(args)
                    .current_dir(root)
                    .env_clear()
                    .envs(env.iter().map(|(k, v)| (k, v)));
                let scope = scope.clone();
                // SAFETY: between fork and exec the closure makes the two Landlock system
                // calls of a domain prepared before the fork, and allocates nothing.
                unsafe {
                    std::os::unix::process::CommandExt::pre_exec(&mut command, move || {
                        scope.enter()
                    });
                }
                command
            }
        }
    }

    /// Where a file the build wrote at `path` (as the build names it) is on the host.
    pub fn on_host(&self, path: &Path) -> PathBuf {
        match path.strip_prefix(&self.target) {
            Ok(rest) if matches!(self.how, How::Namespaces { .. }) => self.own_target.join(rest),
            _ => path.to_path_buf(),
        }
    }

    /// Where cargo would have put a file the build wrote at `path` (as the build names it)
    /// had it built outside a view: in the workspace's own target folder.
    pub fn outside(&self, path: &Path) -> PathBuf {
        match path.strip_prefix(&self.own_target) {
            Ok(rest) => self.target.join(rest),
            Err(_) => path.to_path_buf(),
        }
    }

    /// True when `status` says that the view could not be made (cargo never ran).
    pub fn failed(&self, status: &std::process::ExitStatus) -> bool {
        matches!(self.how, How::Namespaces { .. }) && status.code() == Some(VIEW_FAILED)
    }
}

impl Drop for View {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.own_target);
        if let How::Namespaces {
            spec, mount_point, ..
        } = &self.how
        {
            let _ = std::fs::remove_file(spec);
            let _ = std::fs::remove_dir(mount_point);
        }
    }
}

/// Makes a view that holds only the system's programs and runs `true` in it: an error says
/// why the kernel makes none here (no unprivileged user namespaces, most often).
pub fn probe(helper: &Path, target: &Path) -> anyhow::Result<()> {
    let work = target.join("pbrlab-view");
    let id = format!("{}-{}", std::process::id(), next_id());
    let mount_point = work.join(format!("probe-{id}"));
    let spec_file = work.join(format!("probe-spec-{id}"));
    std::fs::create_dir_all(&mount_point)
        .with_context(|| format!("making {}", mount_point.display()))?;
    let mut spec = Spec {
        text: String::new(),
    };
    spec.line(&["root", Spec::path(&mount_point)?])?;
    spec.bind(Path::new("/usr"), Path::new("/usr"), false)?;
    for top in ["bin", "lib", "lib64"] {
        let host = Path::new("/").join(top);
        if let Ok(target) = std::fs::read_link(&host) {
            spec.line(&["link", Spec::path(&target)?, Spec::path(&host)?])?;
        }
    }
    spec.line(&["proc", "/proc"])?;
    spec.line(&["run", "/usr/bin/true"])?;
    std::fs::write(&spec_file, &spec.text)?;
    let out = Command::new(helper)
        .arg(&spec_file)
        .env_clear()
        .stdin(Stdio::null())
        .output()
        .with_context(|| format!("running {}", helper.display()));
    let _ = std::fs::remove_file(&spec_file);
    let _ = std::fs::remove_dir(&mount_point);
    let out = out?;
    anyhow::ensure!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr).trim()
    );
    Ok(())
}

/// The Landlock rules of a view made without namespaces ([`super::Mechanism::Landlock`]).
mod landlock_scope {
    use anyhow::Context;
    use std::path::{Path, PathBuf};

    /// The newest Landlock ABI this code knows; older kernels enforce what they can (the
    /// file-reading rights, which are what a view needs, are in every version).
    #[cfg(target_os = "linux")]
    const ABI: landlock::ABI = landlock::ABI::V6;

    /// A Landlock domain prepared by the grader for a process it starts, entered by that
    /// process between `fork` and `exec` ([`Scope::enter`]).
    pub struct Scope {
        #[cfg(target_os = "linux")]
        ruleset: std::sync::Mutex<Option<landlock::RulesetCreated>>,
    }

    fn existing(paths: &[PathBuf]) -> Vec<&Path> {
        paths
            .iter()
            .filter(|p| p.exists())
            .map(PathBuf::as_path)
            .collect()
    }

    impl Scope {
        /// Prepares the domain: `readable` files and folders (and what is in them) may be
        /// read and executed, `listable` folders listed, `writable` folders read and
        /// written, the `writable_files` written; no TCP. Paths that do not exist are left
        /// out.
        pub fn new(
            readable: &[PathBuf],
            listable: &[PathBuf],
            writable: &[PathBuf],
            writable_files: &[PathBuf],
        ) -> anyhow::Result<Self> {
            #[cfg(target_os = "linux")]
            {
                use landlock::{
                    Access, AccessFs, AccessNet, Ruleset, RulesetAttr, RulesetCreatedAttr,
                    path_beneath_rules,
                };
                let ruleset = Ruleset::default()
                    .handle_access(AccessFs::from_all(ABI))?
                    .handle_access(AccessNet::from_all(ABI))?
                    .create()?
                    .add_rules(path_beneath_rules(
                        existing(readable),
                        AccessFs::from_read(ABI),
                    ))?
                    .add_rules(path_beneath_rules(existing(listable), AccessFs::ReadDir))?
                    .add_rules(path_beneath_rules(
                        existing(writable),
                        AccessFs::from_all(ABI),
                    ))?
                    .add_rules(path_beneath_rules(
                        existing(writable_files),
                        AccessFs::ReadFile | AccessFs::WriteFile,
                    ))?;
                Ok(Self {
                    ruleset: std::sync::Mutex::new(Some(ruleset)),
                })
            }
            #[cfg(not(target_os = "linux"))]
            {
                let _ = (readable, listable, writable, writable_files);
                anyhow::bail!("Landlock is Linux only")
            }
        }

        /// Puts the domain in force for the calling process and what it starts, or fails
        /// when the kernel does not enforce it. Meant for the child between `fork` and
        /// `exec` (`CommandExt::pre_exec`): it makes two system calls and allocates
        /// nothing.
        pub fn enter(&self) -> std::io::Result<()> {
            #[cfg(target_os = "linux")]
            {
                use landlock::RulesetStatus;
                let ruleset = self
                    .ruleset
                    .lock()
                    .ok()
                    .and_then(|mut r| r.take())
                    .ok_or_else(|| std::io::Error::other("the Landlock domain was used already"))?;
                let status = ruleset
                    .restrict_self()
                    .map_err(|_| std::io::Error::other("landlock_restrict_self failed"))?;
                if status.ruleset == RulesetStatus::NotEnforced {
                    return Err(std::io::Error::other(
                        "the kernel does not enforce Landlock",
                    ));
                }
                Ok(())
            }
            #[cfg(not(target_os = "linux"))]
            Err(std::io::Error::other("Landlock is Linux only"))
        }
    }

    /// Runs `/usr/bin/true` in a domain that reads only the system: an error says why this
    /// kernel enforces no Landlock.
    pub fn probe() -> anyhow::Result<()> {
        let system: Vec<PathBuf> = ["/usr", "/bin", "/lib", "/lib64"].map(PathBuf::from).into();
        let scope = Scope::new(&system, &[], &[], &[])?;
        let mut command = std::process::Command::new("/usr/bin/true");
        // SAFETY: `enter` makes two system calls and allocates nothing.
        unsafe {
            std::os::unix::process::CommandExt::pre_exec(&mut command, move || scope.enter());
        }
        let status = command
            .status()
            .context("starting a process under Landlock")?;
        anyhow::ensure!(
            status.success(),
            "a process under Landlock failed: {status}"
        );
        Ok(())
    }
}

/// The cargo home of the grader (`$CARGO_HOME`, or `~/.cargo`).
fn cargo_home() -> anyhow::Result<PathBuf> {
    if let Some(home) = std::env::var_os("CARGO_HOME") {
        return Ok(PathBuf::from(home));
    }
    let home = std::env::var_os("HOME").context("neither CARGO_HOME nor HOME is set")?;
    Ok(PathBuf::from(home).join(".cargo"))
}

/// The manifests of every package of the workspace at `root` (cargo reads them all).
fn workspace_manifests(root: &Path) -> anyhow::Result<Vec<PathBuf>> {
    Ok(workspace_packages(root)?
        .into_iter()
        .map(|p| p.join("Cargo.toml"))
        .chain([root.join("Cargo.toml")])
        .collect())
}

/// The folders of the workspace's packages, from the root manifest's `members`.
fn workspace_packages(root: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let manifest = root.join("Cargo.toml");
    let text = std::fs::read_to_string(&manifest)
        .with_context(|| format!("reading {}", manifest.display()))?;
    let Some(start) = text.find("members = [") else {
        return Ok(vec![root.to_path_buf()]);
    };
    let list = &text[start + "members = [".len()..];
    let list = &list[..list.find(']').unwrap_or(list.len())];
    let mut packages: Vec<PathBuf> = list
        .split(',')
        .filter_map(|item| {
            let item = item.split('#').next()?.trim().trim_matches('"');
            (!item.is_empty()).then(|| root.join(item))
        })
        .collect();
    packages.push(root.to_path_buf());
    Ok(packages)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unit_hashes_are_read_from_file_and_folder_names() {
        assert_eq!(
            unit_hash("libglam-0123456789abcdef.rlib"),
            Some("0123456789abcdef")
        );
        assert_eq!(
            unit_hash("pbrlab-0123456789abcdef"),
            Some("0123456789abcdef")
        );
        assert_eq!(
            unit_hash("pbrlab-0123456789abcdef.d"),
            Some("0123456789abcdef")
        );
        assert_eq!(unit_hash("pbrlab-worker"), None);
        assert_eq!(unit_hash("libx-0123.rlib"), None);
        assert_eq!(unit_hash("x-0123456789abcdeg"), None);
    }

    #[test]
    fn package_names_are_read_from_both_forms_of_package_id() {
        assert_eq!(package_name("path+file:///w/src#pbrlab@0.1.0"), "pbrlab");
        assert_eq!(
            package_name("path+file:///w/src/worker#pbrlab-worker@0.1.0"),
            "pbrlab-worker"
        );
        assert_eq!(
            package_name("registry+https://github.com/rust-lang/crates.io-index#glam@0.34.2"),
            "glam"
        );
        assert_eq!(package_name("glam 0.34.2 (registry+https://x)"), "glam");
    }

    #[test]
    fn dep_info_names_every_source_escaped_spaces_included() {
        let text = "/t/deps/x-1.d: src/grader/lib.rs src/a\\ b.rs /abs/c.rs\n\nsrc/lib.rs:\n";
        assert_eq!(
            dep_info_sources(text, Path::new("/w")),
            [
                PathBuf::from("/w/src/grader/lib.rs"),
                "/w/src/a b.rs".into(),
                "/abs/c.rs".into()
            ]
        );
    }

    #[test]
    fn watched_paths_are_resolved_against_the_package() {
        let output =
            "cargo::rerun-if-changed=tasks\ncargo:rerun-if-changed=../x\ncargo::rustc-cfg=y\n";
        assert_eq!(
            watched_paths(output, Path::new("/w/src")),
            [PathBuf::from("/w/src/tasks"), "/w/src/../x".into()]
        );
        assert_eq!(
            normal(Path::new("/w/src/../x/./y")),
            PathBuf::from("/w/x/y")
        );
    }

    #[test]
    fn a_spec_refuses_tabs_and_line_breaks() {
        let mut spec = Spec {
            text: String::new(),
        };
        assert!(spec.line(&["ro", "/a\tb", "/a"]).is_err());
        assert!(spec.line(&["ro", "/a\nb", "/a"]).is_err());
        spec.line(&["ro", "/a b", "/a b"]).unwrap();
        assert_eq!(spec.text, "ro\t/a b\t/a b\n");
    }
}
