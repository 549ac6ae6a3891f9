use crate::grade::calibration;
use crate::grade::credit::Credit;
use crate::grade::feedback::Feedback;
use crate::grade::history;
use crate::grade::isolation::Launcher;
use crate::grade::report::redact::redact;
use crate::grade::report::{self, Format};
use crate::grade::runner::{DEFAULT_SEED, GradeOptions, grade};
use crate::grade::student_build::BuildRecord;
use crate::grade::variant::Variant;
use crate::grade::verdict::TaskStatus;
use crate::implementation::{GRADES_ONLY_STUDENT, ImplChoice};
use crate::worksheet::TaskId;
use anyhow::{Context, anyhow};
use std::path::PathBuf;
use std::time::Duration;

/// Arguments of `pbrlab grade`.
#[derive(clap::Args, Debug)]
#[command(group(clap::ArgGroup::new("variant").args(["variant_key", "variant_key_file"])))]
pub struct Args {
    /// Tasks to grade (ids or unique prefixes). Default: every task.
    pub tasks: Vec<String>,
    /// Whose code to grade (one of the possible values below).
    #[arg(long = "impl", value_enum, default_value = "student", hide = GRADES_ONLY_STUDENT)]
    pub implementation: ImplChoice,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
    /// Write the report to this file instead of the terminal.
    #[arg(short, long)]
    pub output: Option<PathBuf>,
    /// Also write an HTML report (index.html) into this directory.
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Seed of the statistical checks.
    #[arg(long, default_value_t = DEFAULT_SEED)]
    pub seed: u64,
    /// Add random hidden cases drawn with this seed, compared live against the reference
    /// (readable by every local user while the run lasts: prefer --hidden-seed-file).
    #[arg(long, conflicts_with = "hidden_seed_file", hide = GRADES_ONLY_STUDENT)]
    pub hidden_seed: Option<u64>,
    /// A file holding the hidden seed.
    #[arg(long, hide = GRADES_ONLY_STUDENT)]
    pub hidden_seed_file: Option<PathBuf>,
    /// Time limit per task, in seconds.
    #[arg(long, default_value_t = crate::grade::runner::DEFAULT_TASK_TIMEOUT_SECONDS)]
    pub timeout: f64,
    /// Memory limit per task, in MiB.
    #[arg(long, default_value_t = crate::grade::runner::DEFAULT_MEMORY_LIMIT_MIB)]
    pub memory_limit_mb: u64,
    /// Tasks graded at once (default: the number of cores).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// How a partly right check is credited: per-region (a values check's share split
    /// equally over the regions of the domain its cases lie in, each earned when all its
    /// cases pass), per-case (the fraction of its cases that pass), all-or-nothing, or
    /// threshold:F (all when a fraction F of the cases pass). Statistical checks are all
    /// or nothing under any policy.
    #[arg(long, default_value = "per-region")]
    pub credit: Credit,
    /// Show every task and scene in the table and every line of what failed (by default the
    /// table fits an 80×24 terminal: tasks not attempted and scenes waiting are a line
    /// each, and each failure's detail is cut short).
    #[arg(short, long)]
    pub verbose: bool,
    /// Skip the render checks (they run when every task is graded).
    #[arg(long)]
    pub no_renders: bool,
    /// Grade this many times with seeds seed, seed+1, … and report each task's failure rate
    /// against its declared false-failure rate (run on the reference, it calibrates the checks).
    #[arg(long)]
    pub repeat: Option<usize>,
    /// How much of a failing case the report shows: full (input, your output, the
    /// expected answer), actual (input and your output only) or none (which checks
    /// failed). Applies to every format and the HTML page.
    #[arg(long, value_enum, default_value = "full")]
    pub feedback: Feedback,
    /// Grade one student's variant: their own hidden cases and seeds, drawn from this
    /// course secret and `--student` (as `grade-class --variant-key` does). Readable by
    /// every local user while the run lasts: prefer --variant-key-file.
    #[arg(long, requires = "student", conflicts_with_all = ["hidden_seed", "hidden_seed_file", "seed", "repeat"], hide = GRADES_ONLY_STUDENT)]
    pub variant_key: Option<String>,
    /// A file holding the course secret of --variant-key.
    #[arg(long, requires = "student", conflicts_with_all = ["hidden_seed", "hidden_seed_file", "seed", "repeat", "variant_key"], hide = GRADES_ONLY_STUDENT)]
    pub variant_key_file: Option<PathBuf>,
    /// The student whose variant `--variant-key` grades (the submission's name in a
    /// class run).
    #[arg(long, requires = "variant", hide = GRADES_ONLY_STUDENT)]
    pub student: Option<String>,
}

/// Grades, prints or writes the report, and remembers the grade for `pbrlab tasks`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let tasks = if args.tasks.is_empty() {
        TaskId::ALL.to_vec()
    } else {
        let mut tasks = args
            .tasks
            .iter()
            .map(|t| TaskId::parse(t).map_err(|e| anyhow!(e)))
            .collect::<anyhow::Result<Vec<_>>>()?;
        tasks.sort();
        tasks.dedup();
        tasks
    };
    if !(args.timeout > 0.0 && args.timeout.is_finite()) {
        return Err(anyhow!("--timeout must be a positive number of seconds"));
    }
    let key = super::secret::key(
        "variant-key",
        args.variant_key.clone(),
        args.variant_key_file.as_deref(),
    )?;
    let hidden_seed = super::secret::seed(
        "hidden-seed",
        args.hidden_seed,
        args.hidden_seed_file.as_deref(),
    )?;
    let variant = key
        .as_deref()
        .zip(args.student.as_deref())
        .map(|(key, student)| Variant::of(key, student));
    let mut options = GradeOptions {
        tasks,
        implementation: args.implementation,
        seed: variant.as_ref().map_or(args.seed, |v| v.seed),
        hidden_seed: variant.as_ref().map(|v| v.hidden_seed).or(hidden_seed),
        timeout: Duration::from_secs_f64(args.timeout),
        memory_limit: args.memory_limit_mb << 20,
        renders: !args.no_renders,
        // The render checks write the reference's picture beside the page: only in full.
        report_dir: args
            .html
            .clone()
            .filter(|_| args.feedback == Feedback::Full),
        credit: args.credit,
        ..GradeOptions::default()
    };
    if let Some(jobs) = args.jobs {
        options.jobs = jobs.max(1);
    }
    let launcher = Launcher::current_exe()?;
    if let Some(record) = BuildRecord::of(&launcher.program) {
        options.compile_errors = record.errors();
    }
    if let Some(runs) = args.repeat {
        let calibration = calibration::repeat(&options, &launcher, runs)?;
        return emit(&calibration.text(), args.output.as_ref());
    }
    let mut report = grade(&options, &launcher)?;
    report.variant = variant.map(|v| v.id);
    let shown = redact(&report, args.feedback);
    if let Some(dir) = &args.html {
        let page = report::write_html(&shown, dir)?;
        eprintln!("HTML report: {}", page.display());
    }
    if args.implementation != ImplChoice::Reference && options.hidden_seed.is_none() {
        // Losing the progress record must not lose the grade itself.
        if let Err(e) = history::save(&report) {
            eprintln!("warning: could not remember this grade: {e:#}");
        }
    }
    // In the instructor's repository only: a handout's stubs are the student's to write.
    if cfg!(feature = "solutions")
        && args.format != Format::Text
        && args.implementation == ImplChoice::Student
    {
        let tasks: Vec<_> = report.tasks.iter().filter(|t| t.max_points > 0.0).collect();
        let stubs = tasks
            .iter()
            .filter(|t| t.status == TaskStatus::NotAttempted)
            .count();
        if stubs > 0
            && stubs
                == tasks
                    .iter()
                    .filter(|t| !t.task.starts_with("scene: "))
                    .count()
        {
            // A results file of the shipped stubs is rarely what was meant.
            eprintln!(
                "note: every task graded is still the shipped stub of exercises/ here; a \
                 submission is graded with `grade-class` or an autograder package \
                 (`autograder gradescope DIR`)"
            );
        }
    }
    let detail = if args.verbose {
        report::Detail::Verbose
    } else {
        report::Detail::Compact
    };
    emit(
        &report::render(&shown, args.format, detail)?,
        args.output.as_ref(),
    )
}

fn emit(text: &str, output: Option<&PathBuf>) -> anyhow::Result<()> {
    match output {
        Some(path) => crate::atomic_file::write(path, text.as_bytes())
            .with_context(|| format!("writing {}", path.display())),
        None => {
            print!("{text}");
            Ok(())
        }
    }
}
