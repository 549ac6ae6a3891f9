//! `pbrlab-build-view SPEC`: runs one program (cargo, for the build of a student's crate) in
//! a view of the file system that holds only what SPEC names, in new user, mount, PID,
//! network, IPC and UTS namespaces.
//!
//! The view is made, not filtered: a fresh root (a small tmpfs) into which each named host
//! path is bound at the same path, read-only unless SPEC says otherwise, then `pivot_root`
//! into it and the old root detached. What is not named does not exist for the program or
//! anything it starts: no repository beyond the named files, no `/proc` of other processes
//! (a new PID namespace, its own `/proc`), no network, no environment but SPEC's.
//!
//! SPEC is a text file, one step a line, fields separated by tabs (so no path holds a tab or
//! a newline; the grader refuses those). Steps run in order:
//!
//! | line | meaning |
//! |---|---|
//! | `root DIR` | the empty host folder the new root is mounted on (first line) |
//! | `ro HOST VIEW` / `rw HOST VIEW` | bind HOST at VIEW, read-only / writable |
//! | `dir VIEW SECS NANOS` | a folder, whose modification time is set last (cargo compares it) |
//! | `file VIEW SECS NANOS` | an empty file with that modification time: a source cargo only dates |
//! | `link TARGET VIEW` | a symbolic link |
//! | `tmpfs VIEW SIZE` | an empty writable file system of at most SIZE bytes |
//! | `proc VIEW` | the view's own `/proc` |
//! | `cwd VIEW` | the folder the program starts in |
//! | `env KEY VALUE` | one variable of the program's environment (nothing else is passed) |
//! | `run PROGRAM ARG…` | the program, last line |
//!
//! Process structure: this program unshares the namespaces, maps the calling user to root
//! inside them, and starts itself again with `--init`. That second process is PID 1 of the
//! new PID namespace: it builds the view, enters it and `exec`s the program, so PID 1 of the
//! view is the program (and `/proc/1/exe` is the program's file). The first process waits
//! and exits with the program's status (128 + the signal for a program killed by one).
//! When PID 1 ends, the kernel ends every process left in the namespace.

#[cfg(target_os = "linux")]
mod linux {
    use rustix::fs::{StatVfsMountFlags, statvfs};
    use rustix::mount::{
        MountFlags, MountPropagationFlags, UnmountFlags, mount, mount_bind_recursive, mount_change,
        mount_remount, unmount,
    };
    use rustix::thread::UnshareFlags;
    use std::ffi::{OsStr, OsString};
    use std::os::unix::ffi::OsStrExt;
    use std::os::unix::process::{CommandExt, ExitStatusExt};
    use std::path::{Path, PathBuf};
    use std::process::Command;
    use std::time::{Duration, SystemTime};

    /// One step of the view.
    enum Step {
        Bind {
            host: PathBuf,
            view: PathBuf,
            writable: bool,
        },
        Dir {
            view: PathBuf,
            modified: SystemTime,
        },
        File {
            view: PathBuf,
            modified: SystemTime,
        },
        Link {
            target: PathBuf,
            view: PathBuf,
        },
        Tmpfs {
            view: PathBuf,
            size: u64,
        },
        Proc {
            view: PathBuf,
        },
    }

    /// A parsed SPEC file.
    struct Spec {
        root: PathBuf,
        steps: Vec<Step>,
        cwd: PathBuf,
        env: Vec<(OsString, OsString)>,
        program: Vec<OsString>,
    }

    fn parse(text: &[u8]) -> Result<Spec, String> {
        let mut spec = Spec {
            root: PathBuf::new(),
            steps: Vec::new(),
            cwd: PathBuf::from("/"),
            env: Vec::new(),
            program: Vec::new(),
        };
        for (n, line) in text.split(|&b| b == b'\n').enumerate() {
            if line.is_empty() {
                continue;
            }
            let fields: Vec<&OsStr> = line.split(|&b| b == b'\t').map(OsStr::from_bytes).collect();
            let bad = || format!("line {} of the view's spec is malformed", n + 1);
            let path = |i: usize| -> Result<PathBuf, String> {
                fields.get(i).map(PathBuf::from).ok_or_else(bad)
            };
            let number = |i: usize| -> Result<u64, String> {
                fields
                    .get(i)
                    .and_then(|f| f.to_str())
                    .and_then(|f| f.parse().ok())
                    .ok_or_else(bad)
            };
            match fields[0].as_bytes() {
                b"root" => spec.root = path(1)?,
                b"ro" | b"rw" => spec.steps.push(Step::Bind {
                    host: path(1)?,
                    view: path(2)?,
                    writable: fields[0] == "rw",
                }),
                b"dir" | b"file" => {
                    let view = path(1)?;
                    let modified = SystemTime::UNIX_EPOCH
                        + Duration::new(number(2)?, u32::try_from(number(3)?).map_err(|_| bad())?);
                    spec.steps.push(if fields[0] == "dir" {
                        Step::Dir { view, modified }
                    } else {
                        Step::File { view, modified }
                    });
                }
                b"link" => spec.steps.push(Step::Link {
                    target: path(1)?,
                    view: path(2)?,
                }),
                b"tmpfs" => spec.steps.push(Step::Tmpfs {
                    view: path(1)?,
                    size: number(2)?,
                }),
                b"proc" => spec.steps.push(Step::Proc { view: path(1)? }),
                b"cwd" => spec.cwd = path(1)?,
                b"env" => spec.env.push((
                    fields.get(1).ok_or_else(bad)?.to_os_string(),
                    fields.get(2).ok_or_else(bad)?.to_os_string(),
                )),
                b"run" => spec.program = fields[1..].iter().map(|f| f.to_os_string()).collect(),
                _ => return Err(bad()),
            }
        }
        if spec.root.as_os_str().is_empty() || spec.program.is_empty() {
            return Err("the view's spec names no root or no program".into());
        }
        Ok(spec)
    }

    /// `path` (absolute, in the view) under `root`.
    fn under(root: &Path, path: &Path) -> PathBuf {
        root.join(path.strip_prefix("/").unwrap_or(path))
    }

    fn context<T, E: std::fmt::Display>(
        result: Result<T, E>,
        what: impl FnOnce() -> String,
    ) -> Result<T, String> {
        result.map_err(|e| format!("{}: {e}", what()))
    }

    /// The first process: new namespaces, the user mapped to root in them, then PID 1.
    pub fn outer(spec: &OsStr) -> Result<i32, String> {
        let uid = rustix::process::getuid().as_raw();
        let gid = rustix::process::getgid().as_raw();
        let flags = UnshareFlags::NEWUSER
            | UnshareFlags::NEWNS
            | UnshareFlags::NEWPID
            | UnshareFlags::NEWNET
            | UnshareFlags::NEWIPC
            | UnshareFlags::NEWUTS;
        // SAFETY: the process has one thread and no file descriptor is shared with another
        // (no FILES flag), which is all `unshare_unsafe` asks.
        context(unsafe { rustix::thread::unshare_unsafe(flags) }, || {
            "making the build's namespaces (are unprivileged user namespaces allowed?)".into()
        })?;
        for (file, text) in [
            ("/proc/self/setgroups", "deny".to_string()),
            ("/proc/self/uid_map", format!("0 {uid} 1")),
            ("/proc/self/gid_map", format!("0 {gid} 1")),
        ] {
            context(std::fs::write(file, text), || format!("writing {file}"))?;
        }
        let status = context(
            Command::new("/proc/self/exe")
                .arg("--init")
                .arg(spec)
                .status(),
            || "starting the view's first process".into(),
        )?;
        Ok(status
            .code()
            .unwrap_or_else(|| 128 + status.signal().unwrap_or(0)))
    }

    /// PID 1 of the view: builds it, enters it and becomes the program.
    pub fn init(spec: &OsStr) -> Result<(), String> {
        let text = context(std::fs::read(spec), || "reading the view's spec".into())?;
        let spec = parse(&text)?;
        let root = &spec.root;
        // Nothing mounted here reaches the host's namespace.
        context(
            mount_change(
                "/",
                MountPropagationFlags::REC | MountPropagationFlags::PRIVATE,
            ),
            || "making the mounts private".into(),
        )?;
        context(
            mount(
                "tmpfs",
                root,
                "tmpfs",
                MountFlags::NOSUID | MountFlags::NODEV,
                c"mode=0755,size=16m",
            ),
            || format!("mounting the view's root on {}", root.display()),
        )?;
        let mut times = Vec::new();
        for step in &spec.steps {
            apply(root, step, &mut times)?;
        }
        // Folders' times last, deepest first: making anything in a folder changes its time.
        times.sort_by_key(|(path, _): &(PathBuf, SystemTime)| {
            std::cmp::Reverse(path.components().count())
        });
        for (path, modified) in times {
            let folder = context(std::fs::File::open(&path), || {
                format!("opening {}", path.display())
            })?;
            context(folder.set_modified(modified), || {
                format!("dating {}", path.display())
            })?;
        }
        let old = root.join(".old-root");
        context(std::fs::create_dir(&old), || {
            "making the old root's mount point".into()
        })?;
        context(rustix::process::pivot_root(root, &old), || {
            "entering the view".into()
        })?;
        context(std::env::set_current_dir("/"), || {
            "entering the view".into()
        })?;
        context(unmount("/.old-root", UnmountFlags::DETACH), || {
            "detaching the host's file system".into()
        })?;
        context(std::fs::remove_dir("/.old-root"), || {
            "removing the old root".into()
        })?;
        // The root itself is not writable: only what SPEC binds writable, and its tmpfs.
        context(
            mount_remount(
                "/",
                MountFlags::RDONLY | MountFlags::NOSUID | MountFlags::NODEV,
                "",
            ),
            || "making the view's root read-only".into(),
        )?;
        context(std::env::set_current_dir(&spec.cwd), || {
            format!("entering {}", spec.cwd.display())
        })?;
        let error = Command::new(&spec.program[0])
            .args(&spec.program[1..])
            .env_clear()
            .envs(spec.env.iter().map(|(k, v)| (k, v)))
            .exec();
        Err(format!(
            "running {}: {error}",
            Path::new(&spec.program[0]).display()
        ))
    }

    /// Makes the folder `path` and its parents.
    fn folder(path: &Path) -> Result<(), String> {
        context(std::fs::create_dir_all(path), || {
            format!("making {}", path.display())
        })
    }

    /// Makes the parents of `path`.
    fn parent(path: &Path) -> Result<(), String> {
        path.parent().map_or(Ok(()), folder)
    }

    /// Makes the empty file `path` (and its parents).
    fn empty_file(path: &Path) -> Result<std::fs::File, String> {
        parent(path)?;
        context(std::fs::File::create(path), || {
            format!("making {}", path.display())
        })
    }

    fn apply(
        root: &Path,
        step: &Step,
        times: &mut Vec<(PathBuf, SystemTime)>,
    ) -> Result<(), String> {
        match step {
            Step::Bind {
                host,
                view,
                writable,
            } => {
                let target = under(root, view);
                let meta = context(std::fs::metadata(host), || {
                    format!("binding {}", host.display())
                })?;
                if meta.is_dir() {
                    folder(&target)?;
                } else {
                    empty_file(&target)?;
                }
                context(mount_bind_recursive(host, &target), || {
                    format!("binding {}", host.display())
                })?;
                if !writable {
                    // A remount must keep the flags the host's mount locks (a user
                    // namespace may not lift them).
                    let host_flags = context(statvfs(&target), || {
                        format!("reading the mount flags of {}", host.display())
                    })?
                    .f_flag;
                    let mut flags = MountFlags::BIND | MountFlags::RDONLY;
                    for (theirs, ours) in [
                        (StatVfsMountFlags::NOSUID, MountFlags::NOSUID),
                        (StatVfsMountFlags::NODEV, MountFlags::NODEV),
                        (StatVfsMountFlags::NOEXEC, MountFlags::NOEXEC),
                        (StatVfsMountFlags::NOATIME, MountFlags::NOATIME),
                        (StatVfsMountFlags::NODIRATIME, MountFlags::NODIRATIME),
                        (StatVfsMountFlags::RELATIME, MountFlags::RELATIME),
                    ] {
                        if host_flags.contains(theirs) {
                            flags |= ours;
                        }
                    }
                    context(mount_remount(&target, flags, ""), || {
                        format!("making {} read-only", host.display())
                    })?;
                }
            }
            Step::Dir { view, modified } => {
                let target = under(root, view);
                folder(&target)?;
                times.push((target, *modified));
            }
            Step::File { view, modified } => {
                let target = under(root, view);
                let file = empty_file(&target)?;
                context(file.set_modified(*modified), || {
                    format!("dating {}", target.display())
                })?;
            }
            Step::Link { target, view } => {
                let link = under(root, view);
                parent(&link)?;
                context(std::os::unix::fs::symlink(target, &link), || {
                    format!("linking {}", link.display())
                })?;
            }
            Step::Tmpfs { view, size } => {
                let target = under(root, view);
                folder(&target)?;
                let data = std::ffi::CString::new(format!("mode=1777,size={size}"))
                    .map_err(|e| e.to_string())?;
                context(
                    mount(
                        "tmpfs",
                        &target,
                        "tmpfs",
                        MountFlags::NOSUID | MountFlags::NODEV,
                        data.as_c_str(),
                    ),
                    || format!("mounting a tmpfs on {}", view.display()),
                )?;
            }
            Step::Proc { view } => {
                let target = under(root, view);
                folder(&target)?;
                context(
                    mount(
                        "proc",
                        &target,
                        "proc",
                        MountFlags::NOSUID | MountFlags::NODEV | MountFlags::NOEXEC,
                        None,
                    ),
                    || "mounting the view's /proc".into(),
                )?;
            }
        }
        Ok(())
    }
}

fn main() -> std::process::ExitCode {
    let args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    #[cfg(target_os = "linux")]
    let result = match args.as_slice() {
        [flag, spec] if flag == "--init" => linux::init(spec).map(|()| 0),
        [spec] => linux::outer(spec),
        _ => Err("usage: pbrlab-build-view SPEC".into()),
    };
    #[cfg(not(target_os = "linux"))]
    let result: Result<i32, String> = {
        let _ = args;
        Err("the build's view needs Linux namespaces".into())
    };
    match result {
        Ok(code) => std::process::ExitCode::from(u8::try_from(code).unwrap_or(1)),
        Err(message) => {
            eprintln!("pbrlab-build-view: {message}");
            // Distinct from any status cargo exits with: the view was never entered.
            std::process::ExitCode::from(VIEW_FAILED)
        }
    }
}

/// The exit status when the view could not be made (cargo never ran).
const VIEW_FAILED: u8 = 121;
