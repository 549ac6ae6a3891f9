//! `pbrlab autograder github-classroom DIR`: the template repository of a GitHub Classroom
//! assignment. It is the student handout ([`crate::handout`]) with one more file, the
//! workflow [`WORKFLOW`], which GitHub runs in each student's repository on every push: it
//! grades with `cargo run --release -- grade --format github-classroom` and hands each task
//! (and each scene's render check) to `classroom-resources/autograding-grading-reporter` as
//! a runner of its own, with its points ([`crate::grade::report::github_classroom`]).
//!
//! The workflow runs in the student's repository, so it holds nothing the student may not
//! read: no reference, no hidden seed, public cases only (README: "GitHub Classroom").

use crate::grade::renders::RENDER_CHECKS;
use crate::grade::report::github_classroom::runner_id;
use crate::grade::runner::scene_entry;
use crate::worksheet::{TaskId, task_functions};
use anyhow::Context;
use std::path::{Path, PathBuf};

/// Where the workflow goes in the template repository.
pub const WORKFLOW: &str = ".github/workflows/classroom.yml";

/// The id of the workflow's grading step, whose outputs are the runners' results.
pub const GRADE_STEP: &str = "pbrlab";

const TEMPLATE: &str = include_str!("templates/classroom.yml");

/// The report entries the workflow reports, by runner id: every task the student writes,
/// then every scene's render check, in the order of the grade.
pub fn runners() -> Vec<String> {
    let tasks = TaskId::ALL
        .into_iter()
        .filter(|t| !task_functions(*t).is_empty() && t.info().points > 0)
        .map(|t| t.name().to_string());
    let scenes = RENDER_CHECKS.iter().map(|c| scene_entry(c.scene));
    tasks.chain(scenes).map(|e| runner_id(&e)).collect()
}

/// The workflow's text: the toolchain CI tests pbrlab with, the grading step, and the
/// reporter reading each runner's result from the step's output of the same name.
pub fn workflow() -> String {
    let runners = runners();
    let env: String = runners
        .iter()
        .map(|r| {
            format!(
                "          {}_RESULTS: \"${{{{ steps.{GRADE_STEP}.outputs.{r} }}}}\"\n",
                r.to_uppercase()
            )
        })
        .collect();
    TEMPLATE
        .replace("@TOOLCHAIN@", super::package::TOOLCHAIN)
        .replace("@STEP@", GRADE_STEP)
        .replace("@ENV@\n", &env)
        .replace("@RUNNERS@", &runners.join(","))
}

/// Writes the template repository of the repository at `root` into the new or empty folder
/// `out`: the handout and the workflow. Returns the files written, relative to `out`.
pub fn write(root: &Path, out: &Path) -> anyhow::Result<Vec<PathBuf>> {
    let mut files = crate::handout::write(root, out)?;
    let file = out.join(WORKFLOW);
    if let Some(dir) = file.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    crate::atomic_file::write(&file, workflow().as_bytes())?;
    files.push(WORKFLOW.into());
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_runner_is_listed_and_read_from_the_grading_step() {
        let text = workflow();
        for placeholder in ["@TOOLCHAIN@", "@STEP@", "@ENV@", "@RUNNERS@"] {
            assert!(TEMPLATE.contains(placeholder) && !text.contains(placeholder));
        }
        let runners = runners();
        assert!(runners.contains(&"smith_g1".to_string()), "{runners:?}");
        assert!(
            runners.contains(&"scene_cornell".to_string()),
            "{runners:?}"
        );
        assert!(text.contains(&format!("runners: {}\n", runners.join(","))));
        for r in &runners {
            let line = format!(
                "{}_RESULTS: \"${{{{ steps.pbrlab.outputs.{r} }}}}\"",
                r.to_uppercase()
            );
            assert!(text.contains(&line), "{line}");
        }
    }
}
