//! `--try SUBMISSION` of the package writers: a package run as its platform runs it, on one
//! submission, before anything is uploaded. The package is built the way the platform
//! builds it (Gradescope: `setup.sh`; PrairieLearn: the Dockerfile's build step, in place;
//! GitHub Classroom: the workflow's own `cargo run`), the submission is laid out where the
//! platform puts it (in a scratch folder; for GitHub Classroom in the template itself, whose
//! stubs are put back afterwards), the platform's script runs, and what the
//! platform would read comes back checked (Gradescope's and PrairieLearn's results against
//! their schemas, GitHub Classroom's step outputs against the grading reporter's fields)
//! and as the platform would show it. Each step that fails says which step, with the last
//! lines it printed.

use super::github_classroom::{GRADE_STEP, runners};
use super::schema::{Service, validate};
use anyhow::{Context, bail};
use std::fmt::Write;
use std::path::Path;
use std::process::Command;

/// The platforms a package is written for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Platform {
    /// Gradescope's autograder (`setup.sh`, `run_autograder`).
    Gradescope,
    /// PrairieLearn's external grader (a Dockerfile, `entrypoint.sh`).
    Prairielearn,
    /// GitHub Classroom's autograding (a template repository and its workflow).
    GithubClassroom,
}

/// The last lines of what a failed step printed.
fn tail(output: &std::process::Output) -> String {
    let text = String::from_utf8_lossy(&output.stderr).into_owned()
        + &String::from_utf8_lossy(&output.stdout);
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(15)..].join("\n")
}

/// Runs the bash script `script` in `dir` with `env` (and no outer `CARGO_TARGET_DIR`); a
/// failure names `step`, with the last lines it printed.
fn bash(step: &str, dir: &Path, script: &str, env: &[(&str, &Path)]) -> anyhow::Result<()> {
    let output = Command::new("bash")
        .args(["-e", "-c", script])
        .current_dir(dir)
        .envs(env.iter().map(|(k, v)| (*k, *v)))
        .env_remove("CARGO_TARGET_DIR")
        .output()
        .with_context(|| format!("{step}: could not start bash"))?;
    if !output.status.success() {
        bail!(
            "{step} failed ({}); its last lines:\n{}",
            output.status,
            tail(&output)
        );
    }
    Ok(())
}

/// Copies the submission (a folder's files, or one file such as a zip) into `to`.
fn lay_out(submission: &Path, to: &Path) -> anyhow::Result<()> {
    std::fs::create_dir_all(to).with_context(|| format!("making {}", to.display()))?;
    let meta = std::fs::metadata(submission)
        .with_context(|| format!("reading the submission {}", submission.display()))?;
    if meta.is_dir() {
        for entry in std::fs::read_dir(submission)? {
            let entry = entry?;
            let target = to.join(entry.file_name());
            if entry.file_type()?.is_dir() {
                lay_out(&entry.path(), &target)?;
            } else {
                std::fs::copy(entry.path(), &target)
                    .with_context(|| format!("copying {}", entry.path().display()))?;
            }
        }
    } else {
        let name = submission
            .file_name()
            .context("the submission has no file name")?;
        std::fs::copy(submission, to.join(name))
            .with_context(|| format!("copying {}", submission.display()))?;
    }
    Ok(())
}

/// Builds the package in `package` as `platform` builds it, unless its `pbrlab` is built.
fn build(platform: Platform, package: &Path) -> anyhow::Result<()> {
    let source = package.join(super::package::SOURCE);
    // GitHub Classroom's workflow builds in its grading step (`cargo run`).
    if platform == Platform::GithubClassroom || source.join("target/release/pbrlab").is_file() {
        return Ok(());
    }
    eprintln!("building the package as the platform does (minutes; once)…");
    match platform {
        Platform::Gradescope => bash(
            "setup.sh (Gradescope's image build)",
            package,
            "bash ./setup.sh",
            &[("PBRLAB_SKIP_TOOLCHAIN", Path::new("1"))],
        ),
        Platform::Prairielearn => bash(
            "the Dockerfile's build step",
            &source,
            &format!(
                "cargo build --release --locked --bins && {}",
                crate::grade::references::shell_command()
            ),
            &[],
        ),
        Platform::GithubClassroom => Ok(()),
    }
}

/// Runs the package in `package` on `submission` as `platform` would, in a scratch folder,
/// and returns what the platform would show.
pub fn try_package(
    platform: Platform,
    package: &Path,
    submission: &Path,
) -> anyhow::Result<String> {
    let package = package
        .canonicalize()
        .with_context(|| format!("reading the package {}", package.display()))?;
    let submission = submission
        .canonicalize()
        .with_context(|| format!("reading the submission {}", submission.display()))?;
    build(platform, &package)?;
    let scratch = tempfile::Builder::new()
        .prefix("pbrlab-try-")
        .tempdir()
        .context("making a scratch folder")?;
    let root = scratch.path();
    let source = package.join(super::package::SOURCE);
    match platform {
        Platform::Gradescope => {
            lay_out(&submission, &root.join("submission"))?;
            std::fs::write(
                root.join("submission_metadata.json"),
                r#"{"users": [{"id": "pbrlab-try", "name": "--try", "email": ""}]}"#,
            )?;
            bash(
                "run_autograder (Gradescope's run of a submission)",
                &package,
                "bash ./run_autograder",
                &[("PBRLAB_AUTOGRADER_ROOT", root), ("PBRLAB_SOURCE", &source)],
            )?;
            results_view(Service::Gradescope, &root.join("results/results.json"))
        }
        Platform::Prairielearn => {
            lay_out(&submission, &root.join("student"))?;
            std::fs::create_dir_all(root.join("data"))?;
            std::fs::write(
                root.join("data/data.json"),
                r#"{"variant_seed": "pbrlab-try"}"#,
            )?;
            bash(
                "entrypoint.sh (PrairieLearn's run of a submission)",
                &package,
                "bash ./entrypoint.sh",
                &[("PBRLAB_GRADE_ROOT", root), ("PBRLAB_SOURCE", &source)],
            )?;
            results_view(Service::Prairielearn, &root.join("results/results.json"))
        }
        Platform::GithubClassroom => classroom(&package, &submission, root),
    }
}

/// Gradescope's or PrairieLearn's results file, checked against the service's schema, as
/// the service shows it: the score, then a line per test.
fn results_view(service: Service, file: &Path) -> anyhow::Result<String> {
    let text = std::fs::read_to_string(file)
        .with_context(|| format!("the package wrote no results file ({})", file.display()))?;
    validate(service, &text).context("the results file is not what the platform reads")?;
    let results: serde_json::Value = serde_json::from_str(&text)?;
    let mut view = String::new();
    let score = results["score"].as_f64().unwrap_or_default();
    match service {
        Service::Gradescope => {
            let tests = results["tests"].as_array().cloned().unwrap_or_default();
            let max: f64 = tests.iter().filter_map(|t| t["max_score"].as_f64()).sum();
            writeln!(view, "Gradescope would show {score:.2} / {max:.2}:")?;
            for t in &tests {
                let shown = match t["visibility"].as_str() {
                    Some("after_published") => " (shown once grades are published)",
                    _ => "",
                };
                writeln!(
                    view,
                    "  {:>6.2}/{:<6.2} {:<7} {}{shown}",
                    t["score"].as_f64().unwrap_or_default(),
                    t["max_score"].as_f64().unwrap_or_default(),
                    t["status"].as_str().unwrap_or("-"),
                    t["name"].as_str().unwrap_or("?"),
                )?;
            }
        }
        Service::Prairielearn => {
            writeln!(view, "PrairieLearn would show {:.1} %:", 100.0 * score)?;
            for t in results["tests"].as_array().into_iter().flatten() {
                writeln!(
                    view,
                    "  {:>6.2}/{:<6.2} {}",
                    t["points"].as_f64().unwrap_or_default(),
                    t["max_points"].as_f64().unwrap_or_default(),
                    t["name"].as_str().unwrap_or("?"),
                )?;
            }
        }
    }
    Ok(view)
}

/// Puts the shipped stub of every task back into a template's `exercises/` when dropped,
/// however the try ended.
struct Stubs<'a>(&'a Path);

impl Drop for Stubs<'_> {
    fn drop(&mut self) {
        for task in crate::worksheet::TaskId::ALL {
            if let Ok(stub) = crate::handout::stubs::shipped(self.0, task) {
                let file = self.0.join("exercises").join(format!("{}.rs", task.name()));
                let _ = crate::atomic_file::write(&file, stub.as_bytes());
            }
        }
    }
}

/// GitHub Classroom: a student's repository is the template with the student's files, so
/// the try is the template itself with the submission's task files over its stubs (which
/// must be the shipped ones, and are put back afterwards), its own state in a scratch
/// folder: a copy elsewhere would rebuild the whole framework, cargo's build being tied to
/// the folder. The workflow's grading step runs as GitHub runs it, and each runner's result
/// is read as the grading reporter reads it.
fn classroom(template: &Path, submission: &Path, scratch: &Path) -> anyhow::Result<String> {
    use base64::Engine;
    let edited: Vec<String> = crate::handout::stubs::edited(template)
        .iter()
        .filter(|t| !crate::worksheet::task_functions(*t).is_empty())
        .map(|t| format!("exercises/{t}.rs"))
        .collect();
    if !edited.is_empty() {
        bail!(
            "the template's exercises are not the shipped stubs ({}): a try writes the \
             submission's files over the stubs and puts the stubs back, so commit or reset \
             these first",
            edited.join(", ")
        );
    }
    let intake = super::submission::take(submission)?;
    let workflow = std::fs::read_to_string(template.join(super::github_classroom::WORKFLOW))
        .context(
            "the template repository has no workflow: write it with `autograder github-classroom`",
        )?;
    let script = workflow
        .lines()
        .skip_while(|l| l.trim() != format!("id: {GRADE_STEP}"))
        .find_map(|l| l.trim().strip_prefix("run: "))
        .context("the workflow has no grading step")?
        .to_string();
    let restore = Stubs(template);
    intake.write(&template.join("exercises"), &|task| {
        crate::handout::stubs::shipped(template, task)
    })?;
    let outputs = scratch.join("github-output");
    let ran = bash(
        "the workflow's grading step",
        template,
        &script,
        &[
            ("GITHUB_OUTPUT", &outputs),
            ("PBRLAB_STATE_DIR", &scratch.join("state")),
        ],
    );
    drop(restore);
    ran?;
    let text = std::fs::read_to_string(&outputs).context("the grading step wrote no outputs")?;
    let mut view = String::from("GitHub Classroom's grading reporter would read:\n");
    let (mut score, mut max) = (0.0, 0.0);
    for runner in runners() {
        let encoded = text
            .lines()
            .find_map(|l| l.strip_prefix(&format!("{runner}=")))
            .with_context(|| format!("the grading step gave no output `{runner}`"))?;
        let json = base64::engine::general_purpose::STANDARD
            .decode(encoded)
            .with_context(|| format!("the output `{runner}` is not base64"))?;
        let result: crate::grade::report::github_classroom::RunnerResult =
            serde_json::from_slice(&json)
                .with_context(|| format!("the output `{runner}` is not the reporter's JSON"))?;
        let got: f64 = result.tests.iter().map(|t| t.score).sum();
        score += got;
        max += result.max_score;
        writeln!(
            view,
            "  {:>6.2}/{:<6.2} {:<5} {runner} ({} tests)",
            got,
            result.max_score,
            result.status,
            result.tests.len()
        )?;
    }
    writeln!(view, "Total points: {score:.2}/{max:.2}")?;
    Ok(view)
}
