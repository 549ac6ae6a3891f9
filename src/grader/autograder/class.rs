//! `pbrlab grade-class`: every submission in a folder (a subfolder or a zip file per
//! student) graded with the framework built once. Builds run one at a time (they share
//! cargo's target folder: each is the student's crate and a link), each into a worker copied
//! to the student's scratch folder; grading runs in parallel beside the next builds, each
//! worker sandboxed as always. Each student's result is written as soon as it is known
//! (`students/<id>.json`), so an interrupted run continues where it stopped; the class
//! table (`class.csv`), the gradebooks and the summaries are written from all results at the end.

use super::gradebook::{self, Roster};
use super::item_analysis;
use super::regrade::StudentChange;
use super::student_result::{StudentResult, SubmissionStatus};
use super::submission::{self, Intake};
use crate::grade::credit::Credit;
use crate::grade::feedback::Feedback;
use crate::grade::isolation::{Launcher, WORKER_BINARY};
use crate::grade::report::redact::redact;
use crate::grade::runner::{DEFAULT_SEED, GradeOptions, grade};
use crate::grade::student_build::{BuildFailure, StudentBuild};
use crate::grade::variant::Variant;
use crate::grade::verdict::{GradeReport, TaskStatus, format_points};
use crate::implementation::ImplChoice;
use crate::worksheet::TaskId;
use anyhow::{Context, bail};
use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The class-wide files a run writes from all results (a regrade keeps the old ones in
/// `history/<time>/`).
const TABLES: [&str; 6] = [
    "class.csv",
    "canvas.csv",
    "moodle.csv",
    "summary.md",
    "summary.html",
    "junit.xml",
];

/// A class to grade.
pub struct ClassRun<'a> {
    /// The instructor repository (the framework built, the reference in).
    pub root: &'a Path,
    /// The folder of submissions.
    pub submissions: &'a Path,
    /// Where the results go.
    pub out: &'a Path,
    /// Hidden cases, with this seed.
    pub hidden_seed: Option<u64>,
    /// Students graded at once.
    pub parallel: usize,
    /// Time limit per task.
    pub task_timeout: Duration,
    /// Memory limit per worker, in bytes.
    pub memory_limit: u64,
    /// How partly right checks are credited.
    pub credit: Credit,
    /// Show a progress bar.
    pub progress: bool,
    /// Grade every submission again, not only those without a grade: the results replaced
    /// go to `history/<UTC date and time>/` (`2026-12-07T13-30-05Z`), and `changes.md` (and `changes.json`) say
    /// what changed ([`super::regrade`]). A new result that is not a grade keeps the saved
    /// one.
    pub regrade: bool,
    /// How much of a failing case the feedback handed back shows (`students/<name>.txt`
    /// and `students/<name>/index.html`); the saved results stay in full.
    pub feedback: Feedback,
    /// The course secret of per-student variants: each student's hidden cases and seeds
    /// come from it and the student's name ([`Variant`]), in place of `hidden_seed`.
    pub variant_key: Option<String>,
    /// The class list that maps submission names to the gradebooks' students
    /// ([`super::gradebook::Roster`]).
    pub roster: Option<PathBuf>,
}

/// The submissions in `dir`: each subfolder and zip file, by student name.
pub fn submissions(dir: &Path) -> anyhow::Result<Vec<(String, PathBuf)>> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).with_context(|| format!("reading {}", dir.display()))? {
        let path = entry?.path();
        let Some(name) = path.file_name().and_then(|n| n.to_str()) else {
            continue;
        };
        if name.starts_with('.') {
            continue;
        }
        let meta = std::fs::symlink_metadata(&path)?;
        if meta.is_dir() {
            found.push((name.to_string(), path));
        } else if let Some(stem) = name.strip_suffix(".zip").filter(|_| meta.is_file()) {
            found.push((stem.to_string(), path));
        }
    }
    found.sort();
    let mut names: Vec<&str> = found.iter().map(|(n, _)| n.as_str()).collect();
    names.dedup();
    if names.len() != found.len() {
        bail!(
            "two submissions in {} have the same student name",
            dir.display()
        );
    }
    Ok(found)
}

/// A student's name as a file name, one to one: a name of letters, digits, `-` and `_` is
/// its own file name; any other has each other character as `_`, then `~` and a hash of the
/// whole name (no plain name has a `~`), so that `eve x`, `eve_x` and `eve.json` each get
/// files of their own, and no name reaches another's feedback (`<name>.txt`, `<name>/`).
fn file_name(student: &str) -> String {
    let plain = |c: char| c.is_alphanumeric() || c == '-' || c == '_';
    if !student.is_empty() && student.chars().all(plain) {
        return student.to_string();
    }
    let readable: String = student
        .chars()
        .map(|c| if plain(c) { c } else { '_' })
        .collect();
    let mut hasher = siphasher::sip::SipHasher24::new();
    std::hash::Hasher::write(&mut hasher, student.as_bytes());
    format!("{readable}~{:016x}", std::hash::Hasher::finish(&hasher))
}

/// True when `result` met a wall deadline: its build did not finish in time, or a task's
/// worker was stopped at the task's time limit.
fn ran_out_of_time(result: &StudentResult) -> bool {
    let build = result.status == SubmissionStatus::BuildError
        && result.message.contains("did not finish within");
    let task = result.report.as_ref().is_some_and(|report| {
        report.tasks.iter().any(|t| {
            matches!(&t.status, TaskStatus::Crashed { reason } if reason.starts_with("timed out"))
        })
    });
    build || task
}

/// A submission built and ready to grade.
struct Built {
    student: String,
    /// Where the submission is (to build it again).
    path: PathBuf,
    intake: Intake,
    scratch: tempfile::TempDir,
    compile_errors: BTreeMap<TaskId, String>,
    start: Instant,
}

impl ClassRun<'_> {
    fn result_file(&self, student: &str) -> PathBuf {
        self.out
            .join("students")
            .join(format!("{}.json", file_name(student)))
    }

    /// Grades every submission without a result yet, then writes the class table and
    /// summary. Returns the seconds per graded submission.
    pub fn run(&self) -> anyhow::Result<f64> {
        let all = submissions(self.submissions)?;
        for (student, _) in &all {
            let file = file_name(student);
            if file != *student {
                eprintln!(
                    "{student:?}: results in students/{file}.json (the name has characters a \
                     file name does not keep)"
                );
            }
        }
        std::fs::create_dir_all(self.out.join("students"))
            .with_context(|| format!("making {}", self.out.display()))?;
        // A result that is not a grade (the grading machinery failed) is tried again.
        let retried = all
            .iter()
            .filter(|(student, _)| self.saved_status(student) == Some(SubmissionStatus::NotGraded))
            .count();
        let todo: Vec<_> = all
            .iter()
            .filter(|(student, _)| {
                self.regrade
                    || self
                        .saved_status(student)
                        .is_none_or(|status| status == SubmissionStatus::NotGraded)
            })
            .cloned()
            .collect();
        eprintln!(
            "{} submissions, {} graded already, {} to grade{}",
            all.len(),
            all.len() - todo.len(),
            todo.len(),
            if retried > 0 {
                format!(" ({retried} of them again: not graded last time)")
            } else {
                String::new()
            }
        );
        // The shipped stubs, read once from git.
        let mut stubs = BTreeMap::new();
        for task in TaskId::ALL {
            stubs.insert(task, crate::handout::stubs::shipped(self.root, task)?);
        }
        let stub = |task: TaskId| {
            stubs
                .get(&task)
                .cloned()
                .context("no shipped stub for the task")
        };
        if !todo.is_empty() {
            self.build_framework(&stub)?;
        }
        let bar = indicatif::ProgressBar::new(todo.len() as u64);
        if !self.progress {
            bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
        }
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{bar:30} {pos}/{len} submissions, {elapsed} (ETA {eta}) {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        let start = Instant::now();
        let (tx, rx) = std::sync::mpsc::sync_channel::<Built>(self.parallel.max(1));
        let rx = std::sync::Mutex::new(rx);
        let failures = std::sync::Mutex::new(Vec::<String>::new());
        let changes = std::sync::Mutex::new(Vec::<StudentChange>::new());
        let history = self.history_folder();
        let record = |result: &StudentResult| self.record(result, &history, &failures, &changes);
        let contended = std::sync::Mutex::new(Vec::<(String, PathBuf)>::new());
        std::thread::scope(|scope| {
            for _ in 0..self.parallel.max(1) {
                scope.spawn(|| {
                    loop {
                        let next = rx.lock().ok().and_then(|rx| rx.recv().ok());
                        let Some(built) = next else { break };
                        let student = built.student.clone();
                        let path = built.path.clone();
                        let result = self.grade_built(built);
                        if ran_out_of_time(&result) {
                            if let Ok(mut contended) = contended.lock() {
                                contended.push((student, path));
                            }
                            continue;
                        }
                        record(&result);
                        bar.set_message(student);
                        bar.inc(1);
                    }
                });
            }
            for (student, path) in &todo {
                match self.build(student, path, &stub) {
                    Ok(built) => {
                        if tx.send(built).is_err() {
                            break;
                        }
                    }
                    Err(result) if ran_out_of_time(&result) => {
                        if let Ok(mut contended) = contended.lock() {
                            contended.push((student.clone(), path.clone()));
                        }
                    }
                    Err(result) => {
                        record(&result);
                        bar.inc(1);
                    }
                }
            }
            drop(tx);
        });
        // A wall deadline met while other submissions ran may be another student's doing
        // (a CPU hog): each such submission is graded again with nothing else running,
        // and only that grade counts.
        let contended = contended.into_inner().unwrap_or_default();
        if !contended.is_empty() {
            eprintln!(
                "{} submission(s) ran out of time while others ran: graded again alone",
                contended.len()
            );
        }
        for (student, path) in &contended {
            let result = match self.build(student, path, &stub) {
                Ok(built) => self.grade_built(built),
                Err(result) => *result,
            };
            record(&result);
            bar.inc(1);
        }
        bar.finish_and_clear();
        let per_submission = start.elapsed().as_secs_f64() / todo.len().max(1) as f64;
        let failures = failures.into_inner().unwrap_or_default();
        if !failures.is_empty() {
            bail!("results could not be saved:\n{}", failures.join("\n"));
        }
        if self.regrade {
            let mut changes = changes.into_inner().unwrap_or_default();
            changes.sort_by(|a, b| a.student.cmp(&b.student));
            crate::atomic_file::write(
                &self.out.join("changes.md"),
                super::regrade::report(&changes).as_bytes(),
            )?;
            crate::atomic_file::write(
                &self.out.join("changes.json"),
                serde_json::to_string_pretty(&changes)?.as_bytes(),
            )?;
            for table in TABLES {
                let from = self.out.join(table);
                if from.is_file() {
                    std::fs::create_dir_all(&history)?;
                    std::fs::copy(&from, history.join(table))
                        .with_context(|| format!("keeping {}", from.display()))?;
                }
            }
        }
        self.write_tables(&all)?;
        Ok(per_submission)
    }

    /// Saves a new result. In a regrade, a saved result is first compared with it (the
    /// change noted in `changes`) and moved to `history`, unless the new result is not a
    /// grade: then the saved one stays.
    fn record(
        &self,
        result: &StudentResult,
        history: &Path,
        failures: &std::sync::Mutex<Vec<String>>,
        changes: &std::sync::Mutex<Vec<StudentChange>>,
    ) {
        if self.regrade
            && let Some(saved) = self.saved(&result.student)
        {
            let change = super::regrade::compare(&saved, result);
            let keep = change.kept.is_some();
            if let Ok(mut changes) = changes.lock() {
                changes.push(change);
            }
            if keep {
                return;
            }
            if let Err(e) = self.archive(&result.student, history)
                && let Ok(mut f) = failures.lock()
            {
                f.push(format!("{}: {e:#}", result.student));
                return;
            }
        }
        self.save_noting(result, failures);
    }

    /// Where this run keeps the results a regrade replaces: `history/<seconds since
    /// 1970>/`, with `-2`, `-3`, … added when that folder exists.
    fn history_folder(&self) -> PathBuf {
        crate::timestamp::unused(&self.out.join("history"), "", "")
    }

    /// The saved result of `student`, if there is one that reads.
    fn saved(&self, student: &str) -> Option<StudentResult> {
        let text = std::fs::read_to_string(self.result_file(student)).ok()?;
        serde_json::from_str(&text).ok()
    }

    /// Moves `student`'s saved result and feedback into `history/students/`.
    fn archive(&self, student: &str, history: &Path) -> anyhow::Result<()> {
        let file = self.result_file(student);
        let to = history.join("students");
        std::fs::create_dir_all(&to).with_context(|| format!("making {}", to.display()))?;
        for from in [
            file.clone(),
            file.with_extension("txt"),
            file.with_extension(""),
        ] {
            if from.exists()
                && let Some(name) = from.file_name()
            {
                std::fs::rename(&from, to.join(name))
                    .with_context(|| format!("moving {} to {}", from.display(), to.display()))?;
            }
        }
        Ok(())
    }

    /// The status a saved result has, if there is one.
    fn saved_status(&self, student: &str) -> Option<SubmissionStatus> {
        let text = std::fs::read_to_string(self.result_file(student)).ok()?;
        let value: serde_json::Value = serde_json::from_str(&text).ok()?;
        // A file that does not read as a result is not a grade either.
        Some(serde_json::from_value(value["status"].clone()).unwrap_or(SubmissionStatus::NotGraded))
    }

    /// Builds the framework and the worker once, from the shipped stubs, before any
    /// student's build: no student's time or bounds pay for it, and the students' builds
    /// compile only their own crate.
    fn build_framework(
        &self,
        stub: &dyn Fn(TaskId) -> anyhow::Result<String>,
    ) -> anyhow::Result<()> {
        eprintln!(
            "building the framework and the reference libraries once before the first \
             submission (no student's time)"
        );
        let scratch = tempfile::Builder::new()
            .prefix("pbrlab-class-stubs-")
            .tempdir()
            .context("making a scratch folder")?;
        let exercises = scratch.path().join("exercises");
        std::fs::create_dir_all(&exercises)?;
        for task in TaskId::ALL {
            std::fs::write(exercises.join(format!("{}.rs", task.name())), stub(task)?)?;
        }
        StudentBuild {
            root: self.root,
            exercises: &exercises,
            commands: false,
            handout: !cfg!(feature = "solutions"),
            stub,
            echo: self.progress,
            deadline: Duration::from_secs(3600),
            offline: false,
            output: None,
            bounded: false,
        }
        .run()
        .context("building the framework before grading (no submission was graded)")?;
        // The reference's one-task libraries, which the workers load.
        crate::grade::references::for_spec(&crate::grade::worker::ImplSpec::Reference)
            .context("building the reference libraries before grading")?;
        Ok(())
    }

    /// Takes and builds one submission; a submission that cannot be built is a result.
    fn build(
        &self,
        student: &str,
        path: &Path,
        stub: &dyn Fn(TaskId) -> anyhow::Result<String>,
    ) -> Result<Built, Box<StudentResult>> {
        let start = Instant::now();
        let not_graded = |message: String, intake: Option<&Intake>| {
            Box::new(StudentResult {
                student: student.to_string(),
                status: SubmissionStatus::NotGraded,
                message,
                taken: intake.map(taken).unwrap_or_default(),
                ignored: intake.map(|i| i.ignored.clone()).unwrap_or_default(),
                report: None,
                seconds: start.elapsed().as_secs_f64(),
            })
        };
        let intake = submission::take(path).map_err(|e| not_graded(format!("{e:#}"), None))?;
        let prepared = (|| -> anyhow::Result<(tempfile::TempDir, BTreeMap<TaskId, String>)> {
            let scratch = tempfile::Builder::new()
                .prefix("pbrlab-class-")
                .permissions(std::os::unix::fs::PermissionsExt::from_mode(0o711))
                .tempdir()
                .context("making a scratch folder")?;
            let exercises = scratch.path().join("exercises");
            intake.write(&exercises, stub)?;
            let record = StudentBuild {
                root: self.root,
                exercises: &exercises,
                commands: false,
                handout: !cfg!(feature = "solutions"),
                stub,
                echo: false,
                deadline: Duration::from_secs(600),
                offline: false,
                // This submission's own: the next build cannot replace it while it grades.
                // Its folder lets others through (not list it), so that a worker run as a
                // user of its own can start it.
                output: Some(scratch.path()),
                bounded: true,
            }
            .run()
            .context("the submission did not build")?;
            Ok((scratch, record.errors()))
        })();
        match prepared {
            Ok((scratch, compile_errors)) => Ok(Built {
                student: student.to_string(),
                path: path.to_path_buf(),
                intake,
                scratch,
                compile_errors,
                start,
            }),
            Err(e) => {
                let mut result = not_graded(format!("{e:#}"), Some(&intake));
                // A compile-time bomb is the submission's doing: a grade of 0, not a retry.
                if e.chain().any(|c| c.is::<BuildFailure>()) {
                    result.status = SubmissionStatus::BuildError;
                }
                Err(result)
            }
        }
    }

    fn grade_built(&self, built: Built) -> StudentResult {
        let launcher = Launcher {
            program: built.scratch.path().join(WORKER_BINARY),
            args: Vec::new(),
            env: Vec::new(),
        };
        let variant = self
            .variant_key
            .as_deref()
            .map(|key| Variant::of(key, &built.student));
        let options = GradeOptions {
            implementation: ImplChoice::Student,
            seed: variant.as_ref().map_or(DEFAULT_SEED, |v| v.seed),
            // The student's own variant; or per submission, from the course's seed and the
            // files: either way a leak serves no one else.
            hidden_seed: match &variant {
                Some(v) => Some(v.hidden_seed),
                None => self.hidden_seed.map(|seed| built.intake.hidden_seed(seed)),
            },
            timeout: self.task_timeout,
            memory_limit: self.memory_limit,
            jobs: 1,
            compile_errors: built.compile_errors,
            credit: self.credit,
            ..GradeOptions::default()
        };
        let (status, message, report) = match grade(&options, &launcher) {
            Ok(mut report) => {
                report.variant = variant.map(|v| v.id);
                (
                    SubmissionStatus::Graded,
                    empty_note(&built.intake),
                    Some(report),
                )
            }
            Err(e) => (SubmissionStatus::NotGraded, format!("{e:#}"), None),
        };
        StudentResult {
            student: built.student,
            status,
            message,
            taken: taken(&built.intake),
            ignored: built.intake.ignored.clone(),
            report,
            seconds: built.start.elapsed().as_secs_f64(),
        }
    }

    /// Saves `result`, noting in `failures` when it cannot be saved.
    fn save_noting(&self, result: &StudentResult, failures: &std::sync::Mutex<Vec<String>>) {
        if let Err(e) = self.save(result)
            && let Ok(mut f) = failures.lock()
        {
            f.push(format!("{}: {e:#}", result.student));
        }
    }

    /// Saves `result`, and the feedback to hand back beside it: the text report
    /// (`students/<name>.txt`) and the HTML page (`students/<name>/index.html`).
    fn save(&self, result: &StudentResult) -> anyhow::Result<()> {
        let file = self.result_file(&result.student);
        if let Some(report) = &result.report {
            let shown = redact(report, self.feedback);
            // Why a grade is what it is when the submission itself explains it (no exercise
            // file in it), then what was ignored, then the report.
            let mut text = result.message.clone();
            if !text.is_empty() {
                text += "\n";
            }
            for line in &result.ignored {
                text += &format!("ignored: {line}\n");
            }
            text += &crate::grade::report::text(&shown, crate::grade::report::Detail::Verbose);
            crate::atomic_file::write(&file.with_extension("txt"), text.as_bytes())?;
            crate::grade::report::write_html(&shown, &file.with_extension(""))?;
        }
        let json = serde_json::to_string_pretty(result)?;
        crate::atomic_file::write(&file, json.as_bytes())
    }

    /// Writes the class-wide files ([`TABLES`]) from the saved results of `all`.
    fn write_tables(&self, all: &[(String, PathBuf)]) -> anyhow::Result<()> {
        let mut results = Vec::new();
        for (student, _) in all {
            let file = self.result_file(student);
            let text = std::fs::read_to_string(&file)
                .with_context(|| format!("reading {}", file.display()))?;
            let result: StudentResult = serde_json::from_str(&text)
                .with_context(|| format!("reading {}", file.display()))?;
            results.push(result);
        }
        let entries = entry_names(&results);
        crate::atomic_file::write(
            &self.out.join("class.csv"),
            csv(&results, &entries)?.as_bytes(),
        )?;
        // summary.md and summary.html: the class's counts, then the item analysis per check.
        let head = entry_summary(&results, &entries);
        let rows = check_rows(&results, &entries);
        crate::atomic_file::write(
            &self.out.join("summary.md"),
            (head.clone() + &item_analysis::markdown(&rows)).as_bytes(),
        )?;
        crate::atomic_file::write(
            &self.out.join("summary.html"),
            item_analysis::html(&head, &rows).as_bytes(),
        )?;
        // junit.xml: a suite per student and task, for CI systems that read JUnit.
        let runs = results.iter().map(|r| {
            let run = r.report.as_ref().ok_or(r.message.as_str());
            (Some(r.student.as_str()), run)
        });
        crate::atomic_file::write(
            &self.out.join("junit.xml"),
            crate::grade::report::junit::junit(runs).as_bytes(),
        )?;
        let roster = match &self.roster {
            Some(path) => Roster::load(path)?,
            None => Roster::default(),
        };
        if self.roster.is_some() {
            let unmatched = roster.unmatched(results.iter().map(|r| r.student.as_str()));
            if !unmatched.is_empty() {
                eprintln!(
                    "warning: the class list names no student for {} submission(s): {} \
                     (exported under their submission names)",
                    unmatched.len(),
                    unmatched.join(", ")
                );
            }
        }
        crate::atomic_file::write(
            &self.out.join("canvas.csv"),
            gradebook::canvas(&results, &entries, &roster)?.as_bytes(),
        )?;
        crate::atomic_file::write(
            &self.out.join("moodle.csv"),
            gradebook::moodle(&results, &entries, &roster)?.as_bytes(),
        )?;
        Ok(())
    }
}

/// The note of a graded submission that holds no exercise file: every task was graded as
/// its shipped stub (empty otherwise).
fn empty_note(intake: &Intake) -> String {
    if intake.taken.is_empty() {
        "no exercise file (<task>.rs) in the submission: every task was graded as its \
         shipped stub"
            .into()
    } else {
        String::new()
    }
}

fn taken(intake: &Intake) -> Vec<String> {
    intake.taken.values().map(|(p, _)| p.clone()).collect()
}

/// The graded entries (tasks, then scene renders) in report order.
fn entry_names(results: &[StudentResult]) -> Vec<String> {
    let mut names: Vec<String> = TaskId::ALL.iter().map(|t| t.name().to_string()).collect();
    for report in results.iter().filter_map(|r| r.report.as_ref()) {
        for t in &report.tasks {
            if !names.contains(&t.task) {
                names.push(t.task.clone());
            }
        }
    }
    names
}

/// `class.csv`: one row per student, points per entry, total, max and status.
pub fn csv(results: &[StudentResult], entries: &[String]) -> anyhow::Result<String> {
    let mut header = vec!["student".to_string()];
    header.extend(entries.iter().cloned());
    header.extend(["total", "max", "status"].map(String::from));
    let mut rows = vec![header];
    for r in results {
        let mut row = vec![r.student.clone()];
        row.extend(entries.iter().map(|e| {
            let points = r
                .report
                .as_ref()
                .and_then(|rep| rep.task(e))
                .map(|t| t.points);
            format_points(points.unwrap_or(0.0))
        }));
        let (total, max) = r
            .report
            .as_ref()
            .map_or((0.0, 0.0), |rep| (rep.score, rep.max_score));
        row.extend([
            format_points(total),
            format_points(max),
            r.status.to_string(),
        ]);
        rows.push(row);
    }
    gradebook::write(rows)
}

/// The item analysis of the graded `results`.
fn check_rows(results: &[StudentResult], entries: &[String]) -> Vec<item_analysis::CheckRow> {
    let graded: Vec<&GradeReport> = results.iter().filter_map(|r| r.report.as_ref()).collect();
    item_analysis::rows(&graded, entries)
}

/// The class's counts, then per entry: mean points, how many passed, failed, did not
/// compile, crashed or were not attempted, and the check that failed most often in the
/// submissions that failed it.
pub fn entry_summary(results: &[StudentResult], entries: &[String]) -> String {
    let graded: Vec<&GradeReport> = results.iter().filter_map(|r| r.report.as_ref()).collect();
    let count_status =
        |status: SubmissionStatus| results.iter().filter(|r| r.status == status).count();
    let mut s = format!(
        "# Class summary\n\n{} submissions, {} graded, {} build errors (0 points), {} not \
         graded.\n\n",
        results.len(),
        graded.len(),
        count_status(SubmissionStatus::BuildError),
        count_status(SubmissionStatus::NotGraded)
    );
    if count_status(SubmissionStatus::NotGraded) > 0 {
        s += "Not graded means the grading machinery failed, not the submission: the same \
              command grades these again.\n\n";
    }
    for r in results
        .iter()
        .filter(|r| r.report.is_none() || !r.message.is_empty())
    {
        let _ = writeln!(
            s,
            "- {} {}: {}",
            r.student,
            r.status,
            r.message.lines().next().unwrap_or("")
        );
    }
    if graded.len() < results.len() {
        s += "\n";
    }
    s += "| entry | mean | max | passed | partly right | failed | compile error | crashed | not attempted | most common failing check |\n";
    s += "|---|---|---|---|---|---|---|---|---|---|\n";
    for e in entries {
        let outcomes: Vec<_> = graded.iter().filter_map(|g| g.task(e)).collect();
        if outcomes.is_empty() {
            continue;
        }
        let mean = outcomes.iter().map(|o| o.points).sum::<f64>() / outcomes.len() as f64;
        let count =
            |f: &dyn Fn(&TaskStatus) -> bool| outcomes.iter().filter(|o| f(&o.status)).count();
        let mut failing: BTreeMap<&str, usize> = BTreeMap::new();
        for o in outcomes
            .iter()
            .filter(|o| matches!(o.status, TaskStatus::Failed | TaskStatus::Partial))
        {
            for c in o.checks.iter().filter(|c| !c.passed) {
                *failing.entry(c.name.as_str()).or_default() += 1;
            }
        }
        let common = failing
            .iter()
            .max_by_key(|(name, n)| (**n, std::cmp::Reverse(*name)))
            .map_or_else(|| "-".to_string(), |(name, n)| format!("{name} ({n})"));
        let _ = writeln!(
            s,
            "| {e} | {mean:.2} | {} | {} | {} | {} | {} | {} | {} | {} |",
            outcomes[0].max_points,
            count(&|st| *st == TaskStatus::Passed),
            count(&|st| *st == TaskStatus::Partial),
            count(&|st| *st == TaskStatus::Failed),
            count(&|st| matches!(st, TaskStatus::CompileError { .. })),
            count(&|st| matches!(st, TaskStatus::Crashed { .. })),
            count(&|st| matches!(st, TaskStatus::NotAttempted | TaskStatus::NeedsTask { .. })),
            common.replace('|', "/")
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn submissions_are_folders_and_zips_by_name() {
        let dir = tempfile::tempdir().unwrap();
        std::fs::create_dir(dir.path().join("bob")).unwrap();
        std::fs::write(dir.path().join("alice.zip"), "").unwrap();
        std::fs::write(dir.path().join("notes.txt"), "").unwrap();
        std::fs::create_dir(dir.path().join(".hidden")).unwrap();
        let names: Vec<_> = submissions(dir.path())
            .unwrap()
            .into_iter()
            .map(|(n, _)| n)
            .collect();
        assert_eq!(names, ["alice", "bob"]);
        std::fs::create_dir(dir.path().join("alice")).unwrap();
        assert!(submissions(dir.path()).is_err(), "alice twice");
        assert_eq!(file_name("ada_lovelace-2"), "ada_lovelace-2");
        let names = [
            "eve x", "eve_x", "eve/x", "eve.x", "eve.json", "eve", "=cmd",
        ];
        let files: std::collections::BTreeSet<_> = names.iter().map(|n| file_name(n)).collect();
        assert_eq!(files.len(), names.len(), "one file per name: {files:?}");
        for file in &files {
            assert!(
                file.chars()
                    .all(|c| c.is_alphanumeric() || "-_~".contains(c)),
                "{file}"
            );
        }
        assert!(file_name("eve x").starts_with("eve_x~"));
    }

    #[test]
    fn the_class_table_has_a_row_per_student_and_a_column_per_task() {
        let outcome =
            |task: &str, status: TaskStatus, points: f64| crate::grade::verdict::TaskOutcome {
                task: task.into(),
                status,
                points,
                max_points: 5.0,
                checks: Vec::new(),
                output: String::new(),
                seconds: 0.0,
            };
        let report = GradeReport::new(
            "student",
            1,
            true,
            vec![
                outcome("reflect", TaskStatus::Passed, 5.0),
                outcome(
                    "mis",
                    TaskStatus::CompileError {
                        message: "e".into(),
                    },
                    0.0,
                ),
            ],
            1.0,
        );
        let results = vec![
            StudentResult {
                student: "ann, b".into(),
                status: SubmissionStatus::Graded,
                message: String::new(),
                taken: vec![],
                ignored: vec![],
                report: Some(report),
                seconds: 1.0,
            },
            StudentResult {
                student: "cy".into(),
                status: SubmissionStatus::NotGraded,
                message: "the submission did not build".into(),
                taken: vec![],
                ignored: vec![],
                report: None,
                seconds: 1.0,
            },
        ];
        let entries = entry_names(&results);
        let table = csv(&results, &entries).unwrap();
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines.len(), 3);
        assert!(
            lines[0].starts_with("student,reflect,refract_stack"),
            "{}",
            lines[0]
        );
        assert!(lines[1].starts_with("\"ann, b\",5,"), "{}", lines[1]);
        assert!(lines[1].ends_with(",5,10,graded"), "{}", lines[1]);
        assert!(lines[2].ends_with(",0,0,not graded"), "{}", lines[2]);
        let text = entry_summary(&results, &entries);
        assert!(
            text.contains("| reflect | 5.00 | 5 | 1 | 0 | 0 |"),
            "{text}"
        );
        assert!(
            text.contains("| mis | 0.00 | 5 | 0 | 0 | 0 | 1 |"),
            "{text}"
        );
        assert!(
            text.contains("cy not graded: the submission did not build"),
            "{text}"
        );
        assert!(text.contains("grades these again"), "{text}");
    }
}
