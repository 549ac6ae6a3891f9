//! The sandbox a worker process enters after it has read its job and before any student code
//! runs, with the kernel mechanisms Linux offers an unprivileged process:
//!
//! - **Landlock** (through the `landlock` crate): the file system is closed except for reading
//!   what the job needs (the scene folder) and reading and writing the job's private
//!   temporary directory (a render of the student's code: the image's folder); no TCP bind or connect; no signals to processes outside the
//!   sandbox (the grader) and no abstract UNIX sockets outside it. Reading
//!   `/proc/self/mem`, the repository, `target/` or the stored expected data fails.
//! - **seccomp** (through `seccompiler`): no new processes (`fork`, `vfork`, `clone`
//!   without `CLONE_THREAD`, `execve`), no sockets, no `ptrace` or cross-process memory
//!   access, no `kill` of other processes, no new sessions or namespaces, no executable
//!   memory (`mmap`/`mprotect` with `PROT_EXEC`: no library or generated code can be
//!   loaded; the binary's own libraries are loaded before the filter). Threads still work
//!   (`clone3` answers `ENOSYS`, so the C library falls back to `clone`, which is checked).
//! - **Resource limits** (through `rlimit`): address space, CPU seconds, size of a written
//!   file, open files, and no core dumps; and threads, when the grader runs as root and so
//!   starts each worker as a user of its own (`RLIMIT_NPROC` is counted per user and does
//!   not bind root).
//!
//! What could not be put in force is reported, not fatal: [`Protections`] says what was,
//! and the grade report prints it.

use serde::{Deserialize, Serialize};
use std::path::PathBuf;

/// What a worker is allowed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Policy {
    /// Address-space limit in bytes (0: none).
    pub memory_limit: u64,
    /// CPU-time limit in seconds, for all of the worker's threads together (0: none).
    pub cpu_seconds: u64,
    /// Folders the worker may read (the scenes).
    pub readable: Vec<PathBuf>,
    /// Folders the worker may read and write: its private temporary directory (and, for a
    /// render of the student's code, the folder the image goes to).
    pub writable: Vec<PathBuf>,
    /// The most threads (processes) the worker's user may have (0: no limit). Set only
    /// when the worker runs as a user of its own ([`crate::grade::isolation`] drops root
    /// to one): the kernel counts this limit per user, and does not apply it to root.
    #[serde(default)]
    pub threads: u64,
}

/// The largest file a worker may write, in bytes.
pub const MAX_FILE_SIZE: u64 = 256 << 20;

/// The most files a worker may hold open at once.
pub const MAX_OPEN_FILES: u64 = 256;

/// Which protections a worker put in force, each in words (`"in force"`, `"partly: …"`,
/// `"not available: …"`).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Protections {
    /// File system, network and IPC scoping by Landlock.
    pub landlock: String,
    /// The system-call filter.
    pub seccomp: String,
    /// Resource limits.
    pub limits: String,
}

impl Protections {
    /// True when every protection is fully in force.
    pub fn complete(&self) -> bool {
        all_in_force(&self.to_string())
    }
}

/// True when every protection in `text`, [`Protections`] in the words a report stores
/// (`landlock in force; seccomp partly: …; limits in force`), is fully in force.
pub fn all_in_force(text: &str) -> bool {
    text.split("; ").all(|part| {
        part.split_once(' ')
            .is_some_and(|(_, state)| state.starts_with(IN_FORCE))
    })
}

impl std::fmt::Display for Protections {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "landlock {}; seccomp {}; limits {}",
            self.landlock, self.seccomp, self.limits
        )
    }
}

const IN_FORCE: &str = "in force";

/// Puts `policy` in force for this process and every thread it starts later. Call before
/// any other thread exists: Landlock restricts the calling thread and the threads it starts.
pub fn enter(policy: &Policy) -> Protections {
    // Limits first: they need no privileges and must not depend on the others.
    let limits = describe(limit_resources(policy));
    let landlock = describe(landlock::restrict(policy));
    let seccomp = describe(syscalls::restrict());
    Protections {
        landlock,
        seccomp,
        limits,
    }
}

fn describe(result: anyhow::Result<Option<String>>) -> String {
    match result {
        Ok(None) => IN_FORCE.into(),
        Ok(Some(partly)) => format!("partly: {partly}"),
        Err(e) => format!("not available: {e:#}"),
    }
}

fn limit_resources(policy: &Policy) -> anyhow::Result<Option<String>> {
    use anyhow::Context;
    use rlimit::Resource;
    if policy.memory_limit > 0 {
        Resource::AS
            .set(policy.memory_limit, policy.memory_limit)
            .context("address space")?;
    }
    if policy.cpu_seconds > 0 {
        // The soft limit sends SIGXCPU, the hard one a second later SIGKILL.
        Resource::CPU
            .set(policy.cpu_seconds, policy.cpu_seconds + 1)
            .context("CPU time")?;
    }
    Resource::FSIZE
        .set(MAX_FILE_SIZE, MAX_FILE_SIZE)
        .context("file size")?;
    Resource::NOFILE
        .set(MAX_OPEN_FILES, MAX_OPEN_FILES)
        .context("open files")?;
    Resource::CORE.set(0, 0).context("core dumps")?;
    if policy.threads > 0 {
        Resource::NPROC
            .set(policy.threads, policy.threads)
            .context("threads")?;
    }
    Ok(None)
}

#[cfg(target_os = "linux")]
mod landlock {
    use super::Policy;
    use anyhow::Context;
    use landlock::{
        ABI, Access, AccessFs, AccessNet, Ruleset, RulesetAttr, RulesetCreatedAttr, RulesetStatus,
        Scope, path_beneath_rules,
    };

    /// The newest Landlock ABI this code knows; older kernels enforce what they can.
    const ABI: ABI = ABI::V6;

    pub(super) fn restrict(policy: &Policy) -> anyhow::Result<Option<String>> {
        let mut ruleset = Ruleset::default()
            .handle_access(AccessFs::from_all(ABI))?
            .handle_access(AccessNet::from_all(ABI))?
            .scope(Scope::from_all(ABI))?
            .create()?
            .add_rules(path_beneath_rules(
                &policy.readable,
                AccessFs::from_read(ABI),
            ))?;
        ruleset = ruleset.add_rules(path_beneath_rules(
            &policy.writable,
            AccessFs::from_all(ABI),
        ))?;
        // Writing to /dev/null is harmless and some code does it.
        ruleset = ruleset.add_rules(path_beneath_rules(
            ["/dev/null"],
            AccessFs::WriteFile | AccessFs::ReadFile,
        ))?;
        let status = ruleset.restrict_self().context("landlock_restrict_self")?;
        match status.ruleset {
            RulesetStatus::FullyEnforced => Ok(None),
            RulesetStatus::PartiallyEnforced => Ok(Some(format!(
                "the kernel has an older Landlock ABI than {ABI:?}"
            ))),
            RulesetStatus::NotEnforced => anyhow::bail!("the kernel does not enforce Landlock"),
        }
    }
}

#[cfg(not(target_os = "linux"))]
mod landlock {
    pub(super) fn restrict(_: &super::Policy) -> anyhow::Result<Option<String>> {
        anyhow::bail!("Landlock is Linux only")
    }
}

#[cfg(target_os = "linux")]
mod syscalls {
    use anyhow::Context;
    use seccompiler::{
        BpfProgram, SeccompAction, SeccompCmpArgLen, SeccompCmpOp, SeccompCondition, SeccompFilter,
        SeccompRule, TargetArch,
    };
    use std::collections::BTreeMap;

    /// System calls refused outright (with `EPERM`).
    const REFUSED: &[i64] = &[
        libc::SYS_execve,
        libc::SYS_execveat,
        #[cfg(target_arch = "x86_64")]
        libc::SYS_fork,
        #[cfg(target_arch = "x86_64")]
        libc::SYS_vfork,
        libc::SYS_socket,
        libc::SYS_socketpair,
        libc::SYS_ptrace,
        libc::SYS_process_vm_readv,
        libc::SYS_process_vm_writev,
        libc::SYS_kill,
        libc::SYS_pidfd_open,
        libc::SYS_pidfd_send_signal,
        libc::SYS_setsid,
        libc::SYS_setpgid,
        libc::SYS_unshare,
        libc::SYS_setns,
        libc::SYS_mount,
        libc::SYS_bpf,
        libc::SYS_perf_event_open,
        libc::SYS_userfaultfd,
        libc::SYS_keyctl,
        libc::SYS_add_key,
        libc::SYS_request_key,
        libc::SYS_personality,
    ];

    fn program(
        rules: BTreeMap<i64, Vec<SeccompRule>>,
        errno: i32,
        arch: TargetArch,
    ) -> anyhow::Result<BpfProgram> {
        let filter = SeccompFilter::new(
            rules,
            SeccompAction::Allow,
            SeccompAction::Errno(errno as u32),
            arch,
        )?;
        Ok(filter.try_into()?)
    }

    pub(super) fn restrict() -> anyhow::Result<Option<String>> {
        let arch: TargetArch = std::env::consts::ARCH.try_into().map_err(|e| {
            anyhow::anyhow!("no seccomp filter for {}: {e:?}", std::env::consts::ARCH)
        })?;
        let mut refused: BTreeMap<i64, Vec<SeccompRule>> =
            REFUSED.iter().map(|&call| (call, Vec::new())).collect();
        // `clone` makes a process unless it makes a thread.
        let process = SeccompCondition::new(
            0,
            SeccompCmpArgLen::Qword,
            SeccompCmpOp::MaskedEq(libc::CLONE_THREAD as u64),
            0,
        )?;
        refused.insert(libc::SYS_clone, vec![SeccompRule::new(vec![process])?]);
        // No new machine code: memory cannot be mapped or made executable, so no library
        // (the handout's compiled reference carried in a submission, say) can be loaded.
        let executable = || {
            SeccompCondition::new(
                2,
                SeccompCmpArgLen::Dword,
                SeccompCmpOp::MaskedEq(libc::PROT_EXEC as u64),
                libc::PROT_EXEC as u64,
            )
            .and_then(|c| SeccompRule::new(vec![c]))
        };
        for call in [libc::SYS_mmap, libc::SYS_mprotect, libc::SYS_pkey_mprotect] {
            refused.insert(call, vec![executable()?]);
        }
        // `clone3` passes its flags in memory, out of a filter's reach: answer "no such call"
        // and the C library uses `clone` instead.
        let clone3 = program(
            [(libc::SYS_clone3, Vec::new())].into_iter().collect(),
            libc::ENOSYS,
            arch,
        )?;
        let rest = program(refused, libc::EPERM, arch)?;
        seccompiler::apply_filter_all_threads(&clone3).context("installing the clone3 filter")?;
        seccompiler::apply_filter_all_threads(&rest).context("installing the filter")?;
        Ok(None)
    }
}

#[cfg(not(target_os = "linux"))]
mod syscalls {
    pub(super) fn restrict() -> anyhow::Result<Option<String>> {
        anyhow::bail!("seccomp is Linux only")
    }
}

#[cfg(all(test, target_os = "linux"))]
mod tests {
    use super::{Protections, all_in_force};

    #[test]
    fn the_words_a_report_stores_say_whether_every_protection_was_in_force() {
        let protections = |landlock: &str| Protections {
            landlock: landlock.into(),
            seccomp: "in force".into(),
            limits: "in force".into(),
        };
        assert!(protections("in force").complete());
        assert!(all_in_force(&protections("in force").to_string()));
        for partial in [
            "partly: no network scoping",
            "not in force: kernel 5.10",
            "absent",
        ] {
            assert!(!protections(partial).complete(), "{partial}");
            assert!(
                !all_in_force(&protections(partial).to_string()),
                "{partial}"
            );
        }
    }
}
