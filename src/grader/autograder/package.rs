//! Writing an autograder package: the instructor repository's tracked files (the reference
//! included, `exercises/` as shipped: the stubs), the settings with a fresh hidden seed, and
//! the service's scripts (`templates/`). The package stays with the instructor and the
//! service; students never see it.
//!
//! - Gradescope: the folder's contents are the autograder zip (`setup.sh`, `run_autograder`,
//!   the source under `pbrlab/`).
//! - PrairieLearn: a `Dockerfile` and `entrypoint.sh` beside the source, and an example
//!   question (`question/info.json` with `externalGradingOptions`, `question/question.html`).

use super::config::{self, Config};
use super::schema::Service;
use crate::entropy::random_u64;
use crate::worksheet::TaskId;
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};

/// The Rust toolchain the package installs: the one CI tests pbrlab with.
pub const TOOLCHAIN: &str = "1.95.0";

const SETUP: &str = include_str!("templates/setup.sh");
const RUN_AUTOGRADER: &str = include_str!("templates/run_autograder");
const DOCKERFILE: &str = include_str!("templates/Dockerfile");
const ENTRYPOINT: &str = include_str!("templates/entrypoint.sh");
const INFO: &str = include_str!("templates/info.json");
const QUESTION: &str = include_str!("templates/question.html");

/// The folder under the package that holds the source tree.
pub const SOURCE: &str = "pbrlab";

/// A random (version 4) UUID for the example question.
fn uuid() -> String {
    let (a, b) = (random_u64(), random_u64());
    let hex = format!("{a:016x}{b:016x}");
    format!(
        "{}-{}-4{}-a{}-{}",
        &hex[0..8],
        &hex[8..12],
        &hex[13..16],
        &hex[17..20],
        &hex[20..32]
    )
}

/// Writes the package for `service` into the new or empty folder `out`, from the
/// repository at `root`, grading with `config` (see [`Config::new`]; the CLI draws the
/// hidden seed at random). Returns the files written, relative to `out`.
pub fn write(
    root: &Path,
    out: &Path,
    service: Service,
    config: &Config,
) -> anyhow::Result<Vec<PathBuf>> {
    crate::handout::refuse_non_empty(out)?;
    let mut written = write_source(root, &out.join(SOURCE))?;
    let settings = out.join(SOURCE).join(config::FILE);
    std::fs::write(&settings, serde_json::to_string_pretty(&config)?)
        .with_context(|| format!("writing {}", settings.display()))?;
    written.push(Path::new(SOURCE).join(config::FILE));
    let reference_libraries = crate::grade::references::shell_command();
    let files: Vec<(&str, String, bool)> = match service {
        Service::Gradescope => vec![
            (
                "setup.sh",
                SETUP
                    .replace("@TOOLCHAIN@", TOOLCHAIN)
                    .replace("@REFERENCE_LIBRARIES@", &reference_libraries),
                true,
            ),
            ("run_autograder", RUN_AUTOGRADER.to_string(), true),
        ],
        Service::Prairielearn => {
            let names: Vec<String> = TaskId::ALL
                .iter()
                .map(|t| format!("{}.rs", t.name()))
                .collect();
            vec![
                (
                    "Dockerfile",
                    DOCKERFILE
                        .replace("@TOOLCHAIN@", TOOLCHAIN)
                        .replace("@REFERENCE_LIBRARIES@", &reference_libraries),
                    false,
                ),
                ("entrypoint.sh", ENTRYPOINT.to_string(), true),
                // A `--try` builds in pbrlab/target: never part of the image's context.
                (".dockerignore", "pbrlab/target\n".to_string(), false),
                ("question/info.json", INFO.replace("@UUID@", &uuid()), false),
                (
                    "question/question.html",
                    QUESTION.replace("@FILES@", &names.join(", ")),
                    false,
                ),
            ]
        }
    };
    for (name, text, executable) in files {
        let file = out.join(name);
        if let Some(dir) = file.parent() {
            std::fs::create_dir_all(dir)?;
        }
        std::fs::write(&file, text).with_context(|| format!("writing {}", file.display()))?;
        if executable {
            use std::os::unix::fs::PermissionsExt;
            std::fs::set_permissions(&file, std::fs::Permissions::from_mode(0o755))?;
        }
        written.push(name.into());
    }
    Ok(written)
}

/// Copies the repository's tracked files into `dest`, the exercises as shipped.
fn write_source(root: &Path, dest: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let listed = std::process::Command::new("git")
        .current_dir(root)
        .args(["ls-files", "-z"])
        .output()
        .context("running git ls-files (the package is written from a git checkout)")?;
    if !listed.status.success() {
        bail!(
            "git ls-files in {}: {}",
            root.display(),
            String::from_utf8_lossy(&listed.stderr).trim()
        );
    }
    let mut written = Vec::new();
    for name in listed.stdout.split(|b| *b == 0).filter(|n| !n.is_empty()) {
        let name = PathBuf::from(String::from_utf8_lossy(name).into_owned());
        let from = root.join(&name);
        if !from.is_file() {
            continue;
        }
        let to = dest.join(&name);
        if let Some(dir) = to.parent() {
            std::fs::create_dir_all(dir).with_context(|| format!("making {}", dir.display()))?;
        }
        std::fs::copy(&from, &to).with_context(|| format!("copying {}", name.display()))?;
        written.push(Path::new(SOURCE).join(&name));
    }
    for task in TaskId::ALL {
        let stub = crate::handout::stubs::shipped(root, task)?;
        let file = dest.join("exercises").join(format!("{}.rs", task.name()));
        std::fs::write(&file, stub).with_context(|| format!("writing {}", file.display()))?;
    }
    Ok(written)
}
