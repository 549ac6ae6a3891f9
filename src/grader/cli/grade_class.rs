//! `pbrlab grade-class`: grade every submission in a folder.

use crate::autograder::class::ClassRun;
use crate::grade::credit::Credit;
use crate::grade::feedback::Feedback;
use std::path::PathBuf;
use std::time::Duration;

/// Arguments of `pbrlab grade-class`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The folder of submissions: one subfolder or zip file per student.
    pub submissions: PathBuf,
    /// Where the results go (students/<name>.json, class.csv, summary.md, junit.xml). A run that
    /// stopped continues where it stopped.
    #[arg(long)]
    pub out: PathBuf,
    /// Add hidden random cases drawn with this seed (readable by every local user while
    /// the run lasts: prefer --hidden-seed-file).
    #[arg(long, conflicts_with = "hidden_seed_file")]
    pub hidden_seed: Option<u64>,
    /// A file holding the hidden seed.
    #[arg(long)]
    pub hidden_seed_file: Option<PathBuf>,
    /// Students graded at once (default: the number of cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Time limit per task, in seconds.
    #[arg(long, default_value_t = crate::grade::runner::DEFAULT_TASK_TIMEOUT_SECONDS)]
    pub timeout: f64,
    /// How a partly right check is credited: per-region, per-case, all-or-nothing or
    /// threshold:F (see `pbrlab grade --help`).
    #[arg(long, default_value = "per-region")]
    pub credit: Credit,
    /// Memory limit per task, in MiB.
    #[arg(long, default_value_t = crate::grade::runner::DEFAULT_MEMORY_LIMIT_MIB)]
    pub memory_limit_mb: u64,
    /// Grade every submission again (a changed grader, a new hidden seed, late files):
    /// the replaced results go to OUT/history/<time>/, and OUT/changes.md lists, per
    /// student and task, old → new points and the checks whose verdict changed. A regrade
    /// that fails for reasons not the student's keeps the saved grade.
    #[arg(long)]
    pub regrade: bool,
    /// How much of a failing case the feedback handed back shows (students/<name>.txt and
    /// students/<name>/index.html): full, actual (input and the student's output, never
    /// the expected answer) or none (which checks failed). The saved results stay in full.
    #[arg(long, value_enum, default_value = "full")]
    pub feedback: Feedback,
    /// A course secret for per-student variants: each student's hidden cases and seeds
    /// come from it and the submission's name, and each report records the variant, so a
    /// regrade with the same key reproduces it. Replaces --hidden-seed. (Readable by every
    /// local user while the run lasts: prefer --variant-key-file.)
    #[arg(long, conflicts_with_all = ["hidden_seed", "hidden_seed_file", "variant_key_file"])]
    pub variant_key: Option<String>,
    /// A file holding the course secret of --variant-key.
    #[arg(long, conflicts_with_all = ["hidden_seed", "hidden_seed_file"])]
    pub variant_key_file: Option<PathBuf>,
    /// A class list (CSV with a header, e.g. Canvas's gradebook export) that maps
    /// submission names to the students of canvas.csv and moodle.csv: a submission matches
    /// the row whose SIS Login ID, SIS User ID, Username, Login, Email address, Email, ID
    /// number, ID or Student is its name.
    #[arg(long)]
    pub roster: Option<PathBuf>,
}

/// Runs `pbrlab grade-class`.
pub fn run(args: Args) -> anyhow::Result<()> {
    anyhow::ensure!(
        args.timeout > 0.0 && args.timeout.is_finite(),
        "--timeout must be a positive number of seconds"
    );
    let parallel = args
        .jobs
        .unwrap_or_else(|| std::thread::available_parallelism().map_or(2, |n| n.get()));
    let seconds = ClassRun {
        root: crate::repository_root(),
        submissions: &args.submissions,
        out: &args.out,
        hidden_seed: super::secret::seed(
            "hidden-seed",
            args.hidden_seed,
            args.hidden_seed_file.as_deref(),
        )?,
        parallel,
        task_timeout: Duration::from_secs_f64(args.timeout),
        memory_limit: args.memory_limit_mb << 20,
        credit: args.credit,
        progress: true,
        regrade: args.regrade,
        feedback: args.feedback,
        variant_key: super::secret::key(
            "variant-key",
            args.variant_key,
            args.variant_key_file.as_deref(),
        )?,
        roster: args.roster,
    }
    .run()?;
    eprintln!(
        "{:.2} s per submission; results in {} (class.csv, canvas.csv, moodle.csv, summary.md, \
         summary.html, students/{})",
        seconds,
        args.out.display(),
        if args.regrade {
            ", changes.md: what the regrade changed"
        } else {
            ""
        }
    );
    Ok(())
}
