//! How `pbrlab`, which links no student code, runs a command that does
//! ([`super::student_side`]): it hands its command line to `pbrlab-student`, rebuilt first
//! when an exercise file is newer ([`super::rebuild`]), and passes on its exit status.

use anyhow::Context;
use std::process::ExitStatus;

/// `pbrlab-student` ran the command and it failed: it has printed its error, and `pbrlab`
/// exits with its status.
#[derive(Debug, thiserror::Error)]
#[error("pbrlab-student {0}")]
pub struct WorkerExit(pub ExitStatus);

impl WorkerExit {
    /// The exit code to pass on (1 for a process killed by a signal).
    pub fn code(&self) -> std::process::ExitCode {
        let code = self
            .0
            .code()
            .and_then(|c| u8::try_from(c).ok())
            .unwrap_or(1);
        std::process::ExitCode::from(code.max(1))
    }
}

/// In `pbrlab`: runs this process's command line in `pbrlab-student` (rebuilt first when
/// stale), which prints to the same terminal.
pub fn delegate() -> anyhow::Result<()> {
    let student = super::rebuild::ensure_student_binaries()?.student;
    let status = std::process::Command::new(&student)
        .env(super::INVOCATION, super::invocation())
        .args(std::env::args_os().skip(1))
        .status()
        .with_context(|| format!("running {}", student.display()))?;
    if status.success() {
        Ok(())
    } else {
        Err(WorkerExit(status).into())
    }
}
