//! `pbrlab similarity`: the exercise files of a class compared per task on normalised
//! tokens ([`crate::similarity`]), on this machine: nothing is sent anywhere.

use crate::autograder::class::submissions;
use crate::autograder::submission;
use crate::similarity::{self, Options, Source};
use crate::worksheet::TaskId;
use anyhow::Context;
use std::collections::BTreeMap;
use std::path::PathBuf;

/// Arguments of `pbrlab similarity`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// The folder of submissions: one subfolder or zip file per student (as grade-class).
    pub submissions: PathBuf,
    /// Where the page (similarity.html) and the data (similarity.json) go.
    #[arg(long, default_value = "similarity")]
    pub out: PathBuf,
    /// Also leave out code that the reference solution has (by default only the shipped
    /// stub is left out: a copy of a leaked reference then still shows).
    #[arg(long)]
    pub exclude_reference: bool,
    /// How many pairs the terminal lists (the page lists every flagged pair).
    #[arg(long, default_value_t = 10)]
    pub top: usize,
}

/// Runs `pbrlab similarity`.
pub fn run(args: Args) -> anyhow::Result<()> {
    let root = crate::repository_root();
    let mut files: BTreeMap<TaskId, Vec<Source>> = BTreeMap::new();
    let mut texts = BTreeMap::new();
    let students = submissions(&args.submissions)?;
    for (student, path) in &students {
        // One unreadable submission (a broken zip) is left out, as grade-class grades on.
        let intake = match submission::take(path) {
            Ok(intake) => intake,
            Err(e) => {
                eprintln!("warning: {student} left out: {e:#}");
                continue;
            }
        };
        for (task, (_, text)) in intake.taken {
            texts.insert((task.name().to_string(), student.clone()), text.clone());
            files.entry(task).or_default().push(Source {
                student: student.clone(),
                text,
            });
        }
    }
    let options = Options::default();
    let mut tasks = Vec::new();
    for (task, sources) in &files {
        let mut exclude = vec![crate::handout::stubs::shipped(root, *task)?];
        if args.exclude_reference {
            let reference = root.join("solutions").join(format!("{}.rs", task.name()));
            exclude.push(
                std::fs::read_to_string(&reference)
                    .with_context(|| format!("reading {}", reference.display()))?,
            );
        }
        let exclude: Vec<&str> = exclude.iter().map(String::as_str).collect();
        tasks.push(similarity::compare_task(
            task.name(),
            sources,
            &exclude,
            &options,
        ));
    }
    let ranked = similarity::rank(&tasks, &options);
    std::fs::create_dir_all(&args.out).with_context(|| format!("making {}", args.out.display()))?;
    let page = args.out.join("similarity.html");
    crate::atomic_file::write(&page, similarity::html(&ranked, &tasks, &texts).as_bytes())?;
    // The data of the flagged pairs (every pair of a large class would be large).
    let flagged: Vec<_> = ranked
        .iter()
        .filter(|p| p.flagged || p.flagged_tasks > 0)
        .collect();
    let json = serde_json::json!({ "options": options, "flagged": flagged });
    crate::atomic_file::write(
        &args.out.join("similarity.json"),
        serde_json::to_string_pretty(&json)?.as_bytes(),
    )?;
    println!(
        "{} submissions, {} pairs flagged over all tasks, {} with a flagged task",
        students.len(),
        ranked.iter().filter(|p| p.flagged).count(),
        flagged.len()
    );
    for p in ranked.iter().take(args.top) {
        println!(
            "{:>5.1} %  {} ~ {}{}",
            100.0 * p.score,
            p.a,
            p.b,
            if p.flagged {
                format!("  FLAGGED ({} tasks flagged)", p.flagged_tasks)
            } else if p.flagged_tasks > 0 {
                format!("  {} tasks flagged", p.flagged_tasks)
            } else {
                String::new()
            }
        );
    }
    println!("side by side: {}", page.display());
    Ok(())
}
