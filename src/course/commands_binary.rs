//! How the `pbrlab` binary (`src/front/`) hands a command to `pbrlab-commands`
//! (`src/commands/`), kept current beside it. Cargo builds it, with its progress, when it
//! is missing, or older than the `pbrlab` binary or than any file it is built from (the
//! workspace's manifests, `src/` and `solutions/`): the same test by modification times
//! that keeps the worker binaries current. Cargo decides what to compile; a build that
//! finds nothing to do leaves a stamp, so the next command does not ask again.

use crate::selection::FRAMEWORK_SELECTION;
use anyhow::{Context, bail};
use std::ffi::OsString;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::SystemTime;

/// The binary every command but `tasks`, `hint` and `reset` runs in.
const COMMANDS_BINARY: &str = "pbrlab-commands";

/// Written beside [`COMMANDS_BINARY`] after a build that left it current.
const STAMP: &str = ".pbrlab-commands-current";

/// The files and folders of the repository `pbrlab-commands` is built from.
const SOURCES: [&str; 4] = ["Cargo.toml", "Cargo.lock", "src", "solutions"];

/// CPU time of a first build of `pbrlab-commands` after the `pbrlab` binary's (a fresh
/// handout, two cores, warm registry; measured, see the closing note of issue 44), for the
/// estimate shown before it.
const FIRST_BUILD_CPU_SECONDS: f64 = 215.0;

/// Runs `args` (the whole command line) in `pbrlab-commands` beside the running binary,
/// building it first when it is not current. On Unix this process becomes it (same process, so signals, the terminal and
/// the exit status are its own); elsewhere it waits and exits with its status.
pub fn hand_over(args: &[OsString]) -> anyhow::Result<()> {
    let exe = std::env::current_exe().context("locating the pbrlab binary")?;
    let commands = exe.with_file_name(format!("{COMMANDS_BINARY}{}", std::env::consts::EXE_SUFFIX));
    if !current(&exe, &commands, crate::repository_root()) {
        build(&exe, &commands)?;
    }
    let mut command = Command::new(&commands);
    command.args(args.iter().skip(1));
    #[cfg(unix)]
    {
        use std::os::unix::process::CommandExt;
        if let Some(typed) = args.first() {
            command.arg0(typed);
        }
        let error = command.exec();
        Err(error).with_context(|| format!("starting {}", commands.display()))
    }
    #[cfg(not(unix))]
    {
        let status = command
            .status()
            .with_context(|| format!("starting {}", commands.display()))?;
        std::process::exit(status.code().unwrap_or(1));
    }
}

/// The modification time of `path`, if it has one.
fn modified(path: &Path) -> Option<SystemTime> {
    std::fs::metadata(path).and_then(|m| m.modified()).ok()
}

/// The newest modification time of a file under `path` (itself when it is a file), not
/// counting build output (`target`) or hidden folders.
fn newest_under(path: &Path) -> Option<SystemTime> {
    let meta = std::fs::symlink_metadata(path).ok()?;
    if !meta.is_dir() {
        return meta.modified().ok();
    }
    std::fs::read_dir(path)
        .ok()?
        .flatten()
        .filter(|e| {
            let name = e.file_name();
            let name = name.to_string_lossy();
            name != "target" && !name.starts_with('.')
        })
        .filter_map(|e| newest_under(&e.path()))
        .max()
}

/// True when `commands` exists and it (or the stamp of the last build that found it
/// current) is at least as new as `exe` and every source of the repository at `root`.
fn current(exe: &Path, commands: &Path, root: &Path) -> bool {
    let Some(binary) = modified(commands) else {
        return false;
    };
    let built = binary.max(modified(&commands.with_file_name(STAMP)).unwrap_or(binary));
    let newest = SOURCES
        .iter()
        .filter_map(|s| newest_under(&root.join(s)))
        .chain(modified(exe))
        .max();
    newest.is_none_or(|newest| newest <= built)
}

/// Cargo's profile arguments for the target folder `profile_dir` (`target/release`).
fn profile_args(profile_dir: &Path) -> Vec<OsString> {
    match profile_dir.file_name().and_then(|n| n.to_str()) {
        Some("debug") => vec![],
        Some("release") => vec!["--release".into()],
        Some(other) => vec!["--profile".into(), other.into()],
        None => vec!["--release".into()],
    }
}

/// Builds `commands` with cargo into the target folder `exe` is in (outside one, uses it as
/// it is, or says how to build it), with the profile it was built with and the framework's
/// selection (so it shares the workers' compilation of the
/// framework); cargo's progress shows on a terminal, and only its errors elsewhere.
fn build(exe: &Path, commands: &Path) -> anyhow::Result<()> {
    let profile_dir = exe.parent().context("the pbrlab binary has no folder")?;
    // A cargo profile folder (`target/release`) keeps its fingerprints beside the binaries.
    let target_dir: PathBuf = match profile_dir.parent() {
        Some(target) if profile_dir.join(".fingerprint").is_dir() => target.to_path_buf(),
        // Copied out of it: used as it is, as cargo cannot build there.
        _ if commands.exists() => return Ok(()),
        _ => bail!(
            "{} is missing beside {}, which is not in cargo's target folder: build it with \
             `cargo build --release -p {COMMANDS_BINARY}` in the repository and put it there",
            commands.display(),
            exe.display()
        ),
    };
    let terminal = std::io::stderr().is_terminal();
    if terminal && !commands.exists() {
        let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
        // Cargo keeps about 90 % of up to four cores busy on this workspace.
        let seconds = FIRST_BUILD_CPU_SECONDS / (cores.min(4) as f64 * 0.9);
        eprintln!(
            "pbrlab: building the renderer and the grader, once: about {} min on {cores} \
             cores (cargo's progress below). `tasks`, `hint` and `reset` work meanwhile.",
            (seconds / 60.0).ceil()
        );
    }
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let manifest = crate::repository_root().join("Cargo.toml");
    let mut command = Command::new(&cargo);
    command
        .arg("build")
        .args(profile_args(profile_dir))
        .args(FRAMEWORK_SELECTION)
        .args(["--bin", COMMANDS_BINARY])
        .arg("--manifest-path")
        .arg(&manifest)
        .arg("--target-dir")
        .arg(&target_dir);
    if !terminal {
        command.arg("--quiet");
    }
    let status = command.status().with_context(|| {
        format!(
            "running {} to build {COMMANDS_BINARY} (is cargo installed?)",
            Path::new(&cargo).display()
        )
    })?;
    if !status.success() {
        bail!(
            "building {COMMANDS_BINARY} (the renderer and the grader) failed ({status}); \
             cargo's messages are above. It builds alone with `cargo build --release -p \
             {COMMANDS_BINARY}`"
        );
    }
    std::fs::write(commands.with_file_name(STAMP), b"")
        .with_context(|| format!("writing {}", commands.with_file_name(STAMP).display()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    /// Writes `path` (and its folder) with the modification time `at`.
    fn file_at(path: &Path, at: SystemTime) {
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::File::create(path)
            .unwrap()
            .set_modified(at)
            .unwrap();
    }

    #[test]
    fn the_commands_binary_is_current_until_a_source_or_the_front_is_newer() {
        let dir = tempfile::tempdir().unwrap();
        let (root, bin) = (dir.path().join("repo"), dir.path().join("target/release"));
        let (exe, commands) = (bin.join("pbrlab"), bin.join(COMMANDS_BINARY));
        let t = |s: u64| SystemTime::UNIX_EPOCH + Duration::from_secs(1_700_000_000 + s);
        file_at(&root.join("src/grader/lib.rs"), t(0));
        file_at(&root.join("Cargo.toml"), t(0));
        file_at(&exe, t(1));
        assert!(!current(&exe, &commands, &root), "missing");
        file_at(&commands, t(2));
        assert!(current(&exe, &commands, &root));
        // A source edited since; build output and hidden folders do not count.
        file_at(&root.join("src/target/x.rs"), t(9));
        file_at(&root.join("src/.pbrlab/x.json"), t(9));
        assert!(current(&exe, &commands, &root));
        file_at(&root.join("solutions/reflect.rs"), t(3));
        assert!(!current(&exe, &commands, &root), "older than a source");
        // A build that found it current leaves a stamp.
        file_at(&bin.join(STAMP), t(4));
        assert!(current(&exe, &commands, &root));
        file_at(&exe, t(5));
        assert!(!current(&exe, &commands, &root), "older than the front");
    }

    #[test]
    fn cargo_builds_with_the_profile_of_the_folder_the_front_is_in() {
        let args = |dir: &str| profile_args(Path::new(dir));
        assert!(args("target/debug").is_empty());
        assert_eq!(args("target/release"), ["--release"]);
        assert_eq!(args("target/profiling"), ["--profile", "profiling"]);
    }

    #[test]
    fn outside_a_target_folder_a_copy_is_used_as_it_is_and_a_missing_one_is_explained() {
        let dir = tempfile::tempdir().unwrap();
        let (exe, commands) = (dir.path().join("pbrlab"), dir.path().join(COMMANDS_BINARY));
        let error = build(&exe, &commands).unwrap_err().to_string();
        assert!(
            error.contains("cargo build --release -p pbrlab-commands"),
            "{error}"
        );
        std::fs::write(&commands, b"").unwrap();
        build(&exe, &commands).expect("the copy is used, no cargo run");
    }
}
