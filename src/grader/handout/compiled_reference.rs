//! Builds the compiled reference a handout ships in `tools/reference/`
//! ([`crate::compiled_reference`]): `tools/reference-library/` compiled as a shared library,
//! stripped of symbols and debug information, from this repository's sources and lock file,
//! which the handout's build shares.

use crate::compiled_reference::{file_name, path_in};
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Compiles the reference library of the repository at `root` (in its target folder, with
/// the cargo that runs this, `$CARGO` or `cargo`) and copies it into the handout at `dest`.
/// Returns the path written.
pub fn build(root: &Path, dest: &Path) -> anyhow::Result<PathBuf> {
    let target = std::env::var_os("CARGO_TARGET_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|| root.join("target"));
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    // Selected as the workers' one-task libraries are, so the library reuses the
    // repository's compiled framework and dependencies.
    let status = Command::new(&cargo)
        .current_dir(root)
        .args(["build", "--release", "--locked", "--lib"])
        .args(crate::grade::references::selection())
        .args([
            "--config",
            "profile.release.package.pbrlab-reference.strip=\"symbols\"",
        ])
        .env("CARGO_TARGET_DIR", &target)
        .status()
        .with_context(|| format!("running {}", cargo.to_string_lossy()))?;
    if !status.success() {
        bail!("compiling the reference library (tools/reference-library/) failed: {status}");
    }
    let built = target.join("release").join(file_name());
    let to = path_in(dest);
    if let Some(dir) = to.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    std::fs::copy(&built, &to)
        .with_context(|| format!("copying {} to {}", built.display(), to.display()))?;
    Ok(to)
}
