//! The last grade, kept for `pbrlab tasks` and `pbrlab watch`: the JSON report of the last
//! `pbrlab grade` of the student's code, in `.pbrlab/last-grade.json` at the project root
//! (or in `$PBRLAB_STATE_DIR`).

use super::verdict::GradeReport;
use anyhow::Context;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Where pbrlab keeps its state.
pub fn state_dir() -> PathBuf {
    std::env::var_os("PBRLAB_STATE_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| crate::repository_root().join(".pbrlab"))
}

/// The file of the last grade.
pub fn last_grade_path() -> PathBuf {
    state_dir().join("last-grade.json")
}

/// Writes `bytes` to `path` through a temporary file in the same directory, so a reader
/// never sees half a file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> anyhow::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let mut tmp = tempfile::NamedTempFile::new_in(dir)
        .with_context(|| format!("writing in {}", dir.display()))?;
    tmp.write_all(bytes)?;
    // Temporary files are private (0600); a report is meant to be read like any other file.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(0o644))?;
    }
    tmp.persist(path)
        .with_context(|| format!("writing {}", path.display()))?;
    Ok(())
}

/// Stores `report` as the last grade.
pub fn save(report: &GradeReport) -> anyhow::Result<()> {
    write_atomic(
        &last_grade_path(),
        serde_json::to_string_pretty(report)?.as_bytes(),
    )
}

/// The last grade, if there is a readable one.
pub fn load() -> Option<GradeReport> {
    let text = std::fs::read_to_string(last_grade_path()).ok()?;
    serde_json::from_str(&text).ok()
}
