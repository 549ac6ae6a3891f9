//! `pbrlab stability`: every task on stiff and extreme inputs, as a table or JSON.

use crate::grade::isolation::Launcher;
use crate::grade::worker::ImplSpec;
use crate::implementation::ImplChoice;
use crate::stability::{Outcome, Verdict, run_isolated};
use crate::worksheet::TaskId;
use anyhow::{anyhow, bail};
use serde::Serialize;
use std::collections::BTreeMap;
use std::time::Duration;

/// Output formats of `pbrlab stability`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, clap::ValueEnum)]
pub enum Format {
    /// A table, printed row by row as the cases run.
    #[default]
    Text,
    /// One JSON document with every outcome and a summary.
    Json,
}

/// Arguments of `pbrlab stability`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Tasks to check (ids or unique prefixes); all tasks when none are given.
    pub tasks: Vec<String>,
    /// Whose code to run.
    #[arg(long = "impl", value_enum, default_value = "student", hide = crate::implementation::GRADES_ONLY_STUDENT)]
    pub implementation: ImplChoice,
    /// Output format.
    #[arg(long, value_enum, default_value = "text")]
    pub format: Format,
    /// Time limit per case in seconds; a case that takes longer is reported as a hang.
    #[arg(long, default_value_t = crate::stability::DEFAULT_TIMEOUT.as_secs_f64())]
    pub timeout: f64,
}

/// Runs the catalogue on the chosen implementation and prints the verdicts. Fails (exit
/// status 1) when any attempted case does not pass.
///
/// Each case runs in a worker process of its own (the grader's `pbrlab-worker`), so a case
/// that overflows the stack or aborts is reported as a crash and every other case still
/// runs; the rows of a task are printed as soon as its cases are done.
pub fn run(args: Args) -> anyhow::Result<()> {
    let tasks = selected_tasks(&args.tasks)?;
    if !(args.timeout > 0.0 && args.timeout.is_finite()) {
        bail!(
            "--timeout must be a positive number of seconds, not {}",
            args.timeout
        );
    }
    let timeout = Duration::from_secs_f64(args.timeout);
    let launcher = Launcher::current_exe()?;
    let (spec, label, reference_tasks) = match args.implementation {
        ImplChoice::Student => (ImplSpec::Student, "student", Vec::new()),
        #[cfg(feature = "solutions")]
        ImplChoice::Reference => (ImplSpec::Reference, "reference", Vec::new()),
        #[cfg(feature = "solutions")]
        ImplChoice::Mixed => {
            let student = crate::implementation::student_attempted(&launcher);
            let reference: Vec<TaskId> = tasks
                .iter()
                .copied()
                .filter(|t| !student.contains(*t))
                .collect();
            let spec = ImplSpec::Mixed {
                student: student.iter().map(|t| t.name().to_owned()).collect(),
            };
            (spec, "mixed", reference)
        }
        #[cfg(not(feature = "solutions"))]
        ImplChoice::Reference | ImplChoice::Mixed => {
            bail!("this build has no reference solutions; use --impl student")
        }
    };
    if args.format == Format::Text {
        println!(
            "{:<44} {:<15} {:<36} {:<36} verdict",
            "case", "task", "value", "expected"
        );
    }
    let mut outcomes = Vec::new();
    for &task in &tasks {
        let task_outcomes = run_isolated(&launcher, &spec, task, timeout)?;
        if args.format == Format::Text {
            task_outcomes.iter().for_each(print_row);
        }
        outcomes.extend(task_outcomes);
    }
    report(&outcomes, label, args.format, &reference_tasks)
}

fn selected_tasks(names: &[String]) -> anyhow::Result<Vec<TaskId>> {
    if names.is_empty() {
        return Ok(TaskId::ALL.to_vec());
    }
    names
        .iter()
        .map(|n| TaskId::parse(n).map_err(|e| anyhow!(e)))
        .collect()
}

/// Everything `--format json` prints.
#[derive(Serialize)]
struct JsonReport<'a> {
    implementation: &'a str,
    reference_tasks: Vec<&'static str>,
    summary: BTreeMap<&'static str, usize>,
    outcomes: &'a [Outcome],
}

/// The summary line (text) or the whole report (JSON); an error when a case failed.
fn report(
    outcomes: &[Outcome],
    label: &str,
    format: Format,
    reference_tasks: &[TaskId],
) -> anyhow::Result<()> {
    let mut summary: BTreeMap<&'static str, usize> = BTreeMap::new();
    for o in outcomes {
        *summary.entry(o.verdict.label()).or_default() += 1;
    }
    match format {
        Format::Text => {
            let parts: Vec<String> = summary.iter().map(|(v, n)| format!("{n} {v}")).collect();
            println!(
                "\n{} cases on the {label} code: {}",
                outcomes.len(),
                parts.join(", ")
            );
            if !reference_tasks.is_empty() {
                let names: Vec<&str> = reference_tasks.iter().map(|t| t.name()).collect();
                println!(
                    "not attempted, so run with the reference: {}",
                    names.join(", ")
                );
            }
        }
        Format::Json => {
            let doc = JsonReport {
                implementation: label,
                reference_tasks: reference_tasks.iter().map(|t| t.name()).collect(),
                summary,
                outcomes,
            };
            println!("{}", serde_json::to_string_pretty(&doc)?);
        }
    }
    let failed = outcomes.iter().filter(|o| o.verdict.failed()).count();
    if failed > 0 {
        bail!("{failed} of {} stability cases failed", outcomes.len());
    }
    Ok(())
}

/// One table row, and for a failure the guard (and panic message) underneath.
fn print_row(o: &Outcome) {
    println!(
        "{:<44} {:<15} {:<36} {:<36} {}",
        o.case,
        o.task.name(),
        clip(&o.value_text, 36),
        clip(&o.expected, 36),
        o.verdict
    );
    if let Some(message) = &o.message {
        println!("    {}: {message}", o.verdict);
    }
    if o.verdict.failed() && !matches!(o.verdict, Verdict::Panic | Verdict::Crash) {
        println!("    input: {}\n    guard: {}", o.input, o.guard);
    }
}

/// `s` cut to `width` characters, with an ellipsis when something was cut.
fn clip(s: &str, width: usize) -> String {
    if s.chars().count() <= width {
        s.to_owned()
    } else {
        let mut cut: String = s.chars().take(width - 1).collect();
        cut.push('…');
        cut
    }
}
