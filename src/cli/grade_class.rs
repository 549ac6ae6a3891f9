//! `pbrlab grade-class`: grade every submission in a folder.

use crate::autograder::class::ClassRun;
use crate::grade::credit::Credit;
use std::path::PathBuf;
use std::time::Duration;

/// Arguments of `pbrlab grade-class`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The folder of submissions: one subfolder or zip file per student.
    pub submissions: PathBuf,
    /// Where the results go (students/<name>.json, class.csv, summary.md). A run that
    /// stopped continues where it stopped.
    #[arg(long)]
    pub out: PathBuf,
    /// Add hidden random cases drawn with this seed.
    #[arg(long)]
    pub hidden_seed: Option<u64>,
    /// Students graded at once (default: the number of cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Time limit per task, in seconds.
    #[arg(long, default_value_t = 30.0)]
    pub timeout: f64,
    /// How a partly right check is credited: per-case, all-or-nothing or threshold:F
    /// (see `pbrlab grade --help`).
    #[arg(long, default_value = "per-case")]
    pub credit: Credit,
    /// Memory limit per task, in MiB.
    #[arg(long, default_value_t = 4096)]
    pub memory_limit_mb: u64,
    /// Grade every submission again (a changed grader, a new hidden seed, late files):
    /// the replaced results go to OUT/history/<time>/, and OUT/changes.md lists, per
    /// student and task, old → new points and the checks whose verdict changed. A regrade
    /// that fails for reasons not the student's keeps the saved grade.
    #[arg(long)]
    pub regrade: bool,
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
        hidden_seed: args.hidden_seed,
        parallel,
        task_timeout: Duration::from_secs_f64(args.timeout),
        memory_limit: args.memory_limit_mb << 20,
        credit: args.credit,
        progress: true,
        regrade: args.regrade,
    }
    .run()?;
    eprintln!(
        "{:.2} s per submission; results in {} (class.csv, summary.md, students/{})",
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
