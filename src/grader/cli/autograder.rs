//! `pbrlab autograder`: write a Gradescope or PrairieLearn package or a GitHub Classroom
//! template repository, and (inside a package) grade a submission.

use crate::autograder::config::Config;
use crate::autograder::package;
use crate::autograder::run::Submission;
use crate::autograder::schema::Service;
use crate::autograder::try_package::{Platform, try_package};
use anyhow::Context;
use std::path::{Path, PathBuf};

/// Arguments of `pbrlab autograder`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// What to do.
    #[command(subcommand)]
    pub command: Step,
}

/// The steps of `pbrlab autograder`.
#[derive(clap::Subcommand, Debug)]
pub enum Step {
    /// Write a Gradescope autograder (zip the folder's contents and upload them).
    Gradescope(PackageArgs),
    /// Write a PrairieLearn external grader (a Dockerfile) and an example question.
    Prairielearn(PackageArgs),
    /// Write a GitHub Classroom template repository: the student handout and a workflow
    /// that grades the public cases on every push and reports each task's points.
    GithubClassroom(ClassroomArgs),
    /// Grade one submission inside a package (what its scripts call).
    #[command(hide = true)]
    Run(RunArgs),
}

/// Arguments of the package writers.
#[derive(clap::Args, Debug)]
pub struct PackageArgs {
    /// The new (or empty) folder to write the package into.
    pub out: PathBuf,
    /// The seed of the hidden cases (default: drawn at random and kept in the package).
    #[arg(long, conflicts_with = "hidden_seed_file")]
    pub hidden_seed: Option<u64>,
    /// A file holding the hidden seed.
    #[arg(long)]
    pub hidden_seed_file: Option<PathBuf>,
    /// How much of a failing case a student sees: full, actual (input and their output,
    /// never the expected answer) or none (which checks failed). Kept in the package's
    /// settings (`feedback`).
    #[arg(long, value_enum, default_value = "full")]
    pub feedback: crate::grade::feedback::Feedback,
    /// A course secret for per-student variants: each student's hidden cases and seeds
    /// come from it and their id (Gradescope's user id, PrairieLearn's variant seed), in
    /// place of the hidden seed. Kept in the package's settings (`variant_key`).
    #[arg(long, conflicts_with_all = ["hidden_seed", "hidden_seed_file", "variant_key_file"])]
    pub variant_key: Option<String>,
    /// A file holding the course secret of --variant-key.
    #[arg(long, conflicts_with_all = ["hidden_seed", "hidden_seed_file"])]
    pub variant_key_file: Option<PathBuf>,
    /// Run the package on this submission (a folder of exercise files, or a zip) as the
    /// platform would, in a scratch folder, and print what the platform would show. Writes
    /// the package first when the folder is new or empty; builds it once, as the platform
    /// does.
    #[arg(long = "try", value_name = "SUBMISSION")]
    pub try_submission: Option<PathBuf>,
}

/// Arguments of `pbrlab autograder github-classroom`.
#[derive(clap::Args, Debug)]
pub struct ClassroomArgs {
    /// The template repository, as `handout` writes it.
    #[command(flatten)]
    pub handout: super::handout::Args,
    /// Run the workflow's grading step on this submission (a folder of exercise files, a
    /// zip, or a student's repository) as GitHub would: in the template with the
    /// submission's task files over its stubs, which are put back afterwards. Prints what
    /// the grading reporter would read. Writes the template first when the folder is new or
    /// empty.
    #[arg(long = "try", value_name = "SUBMISSION")]
    pub try_submission: Option<PathBuf>,
}

/// True when `dir` exists and holds anything (a package written before).
fn written(dir: &Path) -> bool {
    std::fs::read_dir(dir).is_ok_and(|mut d| d.next().is_some())
}

/// `--try`: the package in `dir` run on `submission` as `platform` runs it.
fn try_it(platform: Platform, dir: &Path, submission: &Path) -> anyhow::Result<()> {
    let view = try_package(platform, dir, submission).with_context(|| {
        format!(
            "trying the package in {} on {}",
            dir.display(),
            submission.display()
        )
    })?;
    print!("{view}");
    Ok(())
}

/// Arguments of `pbrlab autograder run`.
#[derive(clap::Args, Debug)]
pub struct RunArgs {
    /// The package's settings file.
    #[arg(long)]
    pub config: PathBuf,
    /// The submission: a folder or a zip file.
    #[arg(long)]
    pub submission: PathBuf,
    /// Where to write the results file.
    #[arg(long)]
    pub results: PathBuf,
    /// The results format.
    #[arg(long, value_enum)]
    pub service: Service,
    /// The service's description of the submission, for the student's id when the package
    /// grades per-student variants: Gradescope's submission_metadata.json, PrairieLearn's
    /// data.json.
    #[arg(long)]
    pub metadata: Option<PathBuf>,
}

/// Runs `pbrlab autograder`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let root = crate::repository_root();
    match args.command {
        Step::Gradescope(p) => package_step(root, p, Service::Gradescope, Platform::Gradescope),
        Step::Prairielearn(p) => {
            package_step(root, p, Service::Prairielearn, Platform::Prairielearn)
        }
        Step::GithubClassroom(c) => {
            let h = &c.handout;
            if c.try_submission.is_none() || !written(&h.dir) {
                let files = super::handout::write_student_repository(
                    &h.dir,
                    h.without_reference,
                    crate::autograder::github_classroom::write,
                )?;
                eprintln!(
                    "wrote {files} files into {}\nnext: push it to a new GitHub repository, \
                     mark it a template, and choose it as the assignment's starter code in \
                     GitHub Classroom (README: GitHub Classroom)",
                    h.dir.display()
                );
            }
            match &c.try_submission {
                Some(submission) => try_it(Platform::GithubClassroom, &h.dir, submission),
                None => Ok(()),
            }
        }
        Step::Run(r) => {
            let config = match Config::load(&r.config) {
                Ok(config) => config,
                Err(e) => {
                    // Still a results file.
                    let json = crate::autograder::run::failed(
                        r.service,
                        &format!("{e:#}"),
                        std::time::Instant::now(),
                    );
                    crate::atomic_file::write(&r.results, json.as_bytes())?;
                    return Err(e);
                }
            };
            Submission {
                root,
                config: &config,
                service: r.service,
                files: &r.submission,
                results: &r.results,
                metadata: r.metadata.as_deref(),
            }
            .run()
        }
    }
}

/// A package writer's step: write the package (unless `--try` finds one written), then try
/// it when asked.
fn package_step(
    root: &Path,
    p: PackageArgs,
    service: Service,
    platform: Platform,
) -> anyhow::Result<()> {
    let submission = p.try_submission.clone();
    let dir = p.out.clone();
    if submission.is_none() || !written(&dir) {
        write(root, p, service)?;
    }
    match submission {
        Some(submission) => try_it(platform, &dir, &submission),
        None => Ok(()),
    }
}

fn write(root: &Path, p: PackageArgs, service: Service) -> anyhow::Result<()> {
    let hidden_seed =
        super::secret::seed("hidden-seed", p.hidden_seed, p.hidden_seed_file.as_deref())?;
    let config = Config {
        feedback: p.feedback,
        variant_key: super::secret::key(
            "variant-key",
            p.variant_key,
            p.variant_key_file.as_deref(),
        )?,
        ..Config::new(hidden_seed.unwrap_or_else(crate::entropy::random_u64))
    };
    let files = package::write(root, &p.out, service, &config)
        .with_context(|| format!("writing the package into {}", p.out.display()))?;
    eprintln!("wrote {} files into {}", files.len(), p.out.display());
    match service {
        Service::Gradescope => eprintln!(
            "next: try it with --try SUBMISSION, then (cd {} && zip -r ../autograder.zip . -x \
             'pbrlab/target/*') and upload autograder.zip as the assignment's autograder \
             (README: Grading a class)",
            p.out.display()
        ),
        Service::Prairielearn => eprintln!(
            "next: docker build -t YOURNAME/pbrlab-grader {}, push it, and copy question/ \
             into your course (README: Grading a class)",
            p.out.display()
        ),
    }
    Ok(())
}
