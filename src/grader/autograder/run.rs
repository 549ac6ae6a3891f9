//! Grading one submission inside an autograder (`pbrlab autograder run`, called by the
//! package's `run_autograder` or entrypoint): take the exercise files, build them into a
//! worker of their own, grade with the hidden cases, and write the service's results file.
//! The file is written exactly once and atomically, whatever happens: a build that fails
//! outside the exercise files, an error of the grader, or the deadline passing all give a
//! valid file with score 0 and the reason.

use super::config::Config;
use super::schema::{Service, validate};
use super::submission::{self, Intake};
use crate::grade::isolation::Launcher;
use crate::grade::report::redact::redact;
use crate::grade::report::{self, gradescope, prairielearn};
use crate::grade::runner::{GradeOptions, grade};
use crate::grade::student_build::StudentBuild;
use crate::grade::variant::Variant;
use crate::grade::verdict::GradeReport;
use crate::implementation::ImplChoice;
use anyhow::Context;
use std::path::Path;
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// Time kept back from the deadline for writing the results.
const MARGIN: Duration = Duration::from_secs(5);

/// One submission to grade.
pub struct Submission<'a> {
    /// The package's source tree (the framework built, `exercises/` the shipped stubs).
    pub root: &'a Path,
    /// The package's settings.
    pub config: &'a Config,
    /// The results format.
    pub service: Service,
    /// The submission: a folder or a zip file.
    pub files: &'a Path,
    /// Where the results file goes.
    pub results: &'a Path,
    /// The service's description of the submission (Gradescope's
    /// `submission_metadata.json`, PrairieLearn's `data.json`): the student's id, for a
    /// package that grades per-student variants.
    pub metadata: Option<&'a Path>,
}

/// A graded submission, before it is written in a service's format.
struct Graded {
    /// What was taken from the submission and what was ignored.
    intake: Intake,
    /// The grade.
    report: GradeReport,
}

impl Submission<'_> {
    /// Grades and writes the results file. Fails only when the results file itself cannot
    /// be written.
    pub fn run(&self) -> anyhow::Result<()> {
        let start = Instant::now();
        let deadline = Duration::from_secs_f64(self.config.deadline.max(10.0));
        let written = Arc::new(Mutex::new(false));
        {
            let written = Arc::clone(&written);
            let results = self.results.to_path_buf();
            let service = self.service;
            std::thread::spawn(move || {
                std::thread::sleep(deadline.saturating_sub(MARGIN));
                let reason = format!(
                    "grading did not finish within {} s (an infinite loop at build time, or \
                     a very slow submission)",
                    deadline.as_secs()
                );
                if write_once(&written, &results, &failed(service, &reason, start)).is_ok() {
                    eprintln!("pbrlab: {reason}");
                    std::process::exit(0);
                }
            });
        }
        let graded = self.grade(deadline.saturating_sub(MARGIN * 2));
        let json = match &graded {
            Ok(graded) => self.results_json(graded, start),
            Err(e) => failed(self.service, &format!("{e:#}"), start),
        };
        write_once(&written, self.results, &json)
    }

    fn grade(&self, time: Duration) -> anyhow::Result<Graded> {
        let start = Instant::now();
        let intake = submission::take(self.files)?;
        print!("{}", intake.ignored_text());
        let scratch = tempfile::Builder::new()
            .prefix("pbrlab-submission-")
            .tempdir()
            .context("making the scratch folder")?;
        let exercises = scratch.path().join("exercises");
        let stub = |task| super::stub_in(self.root, task);
        intake.write(&exercises, &stub)?;
        let record = StudentBuild {
            root: self.root,
            exercises: &exercises,
            commands: false,
            handout: !cfg!(feature = "solutions"),
            stub: &stub,
            echo: false,
            deadline: time,
            offline: true,
            output: Some(scratch.path()),
            bounded: true,
        }
        .run()
        .context("the submission did not build")?;
        let launcher = Launcher {
            program: record.worker.clone(),
            args: Vec::new(),
            env: Vec::new(),
        };
        let variant = match &self.config.variant_key {
            Some(key) => Some(Variant::of(key, &self.student()?)),
            None => None,
        };
        let options = GradeOptions {
            implementation: ImplChoice::Student,
            seed: variant.as_ref().map_or(self.config.seed, |v| v.seed),
            // The student's own variant; or per submission: either way a leak of hidden
            // inputs serves one student only.
            hidden_seed: Some(match &variant {
                Some(v) => v.hidden_seed,
                None => intake.hidden_seed(self.config.hidden_seed),
            }),
            timeout: Duration::from_secs_f64(self.config.task_timeout.max(1.0)),
            memory_limit: self.config.memory_limit_mb << 20,
            jobs: self.config.jobs.max(1),
            compile_errors: record.errors(),
            credit: self.config.credit,
            ..GradeOptions::default()
        };
        let mut report = grade(&options, &launcher)?;
        report.seconds = start.elapsed().as_secs_f64();
        report.variant = variant.map(|v| v.id);
        // The grader's log (hidden from students) in full; the results as the course shows
        // them.
        println!("{}", report::text(&report, report::Detail::Verbose));
        let report = redact(&report, self.config.feedback);
        Ok(Graded { intake, report })
    }

    /// The student's id in the service's description of the submission: Gradescope's
    /// `users[0].id` (with the other users of a group submission), PrairieLearn's
    /// `variant_seed` (PrairieLearn gives a grader no user; its variant is per student
    /// when the question sets `singleVariant`, else each new variant draws anew).
    fn student(&self) -> anyhow::Result<String> {
        let path = self.metadata.context(
            "the package grades per-student variants, and the service gave no description \
             of the submission (--metadata)",
        )?;
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("reading {} (the student's id)", path.display()))?;
        student_id(self.service, &text).with_context(|| format!("reading {}", path.display()))
    }

    fn results_json(&self, graded: &Graded, start: Instant) -> String {
        let mut header = graded.intake.ignored_text();
        let taken: Vec<&str> = graded
            .intake
            .taken
            .values()
            .map(|(p, _)| p.as_str())
            .collect();
        header += &if taken.is_empty() {
            "No exercise file was found in the submission: every task is its stub.\n".into()
        } else {
            format!("Graded files: {}\n", taken.join(", "))
        };
        for protections in &graded.report.sandbox {
            header += &format!("Sandbox of the workers: {protections}\n");
        }
        let json = match self.service {
            Service::Gradescope => {
                let mut results = gradescope(&graded.report);
                results.output = format!("{header}{}", results.output);
                results.execution_time = start.elapsed().as_secs_f64();
                serde_json::to_string_pretty(&results)
            }
            Service::Prairielearn => {
                serde_json::to_string_pretty(&prairielearn::prairielearn(&graded.report, &header))
            }
        };
        match json {
            Ok(json) => match validate(self.service, &json) {
                Ok(()) => json,
                Err(e) => failed(
                    self.service,
                    &format!("the grader built an invalid results file ({e:#})"),
                    start,
                ),
            },
            Err(e) => failed(self.service, &format!("{e}"), start),
        }
    }
}

/// The student's id in `service`'s description of a submission (`text`, JSON):
/// Gradescope's `users[].id` (or email), the ids of a group joined in sorted order, so a
/// group has one variant whoever of it submits; PrairieLearn's `variant_seed`.
fn student_id(service: Service, text: &str) -> anyhow::Result<String> {
    let value: serde_json::Value = serde_json::from_str(text).context("not JSON")?;
    let id = |v: &serde_json::Value| match v {
        serde_json::Value::String(s) if !s.is_empty() => Some(s.clone()),
        serde_json::Value::Number(n) => Some(n.to_string()),
        _ => None,
    };
    let found = match service {
        Service::Gradescope => {
            let mut ids: Vec<String> = value["users"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(|u| id(&u["id"]).or_else(|| id(&u["email"])))
                .collect();
            ids.sort();
            (!ids.is_empty()).then(|| ids.join("+"))
        }
        Service::Prairielearn => id(&value["variant_seed"]),
    };
    found.with_context(|| {
        format!(
            "no student's id in it ({})",
            match service {
                Service::Gradescope => "users[].id",
                Service::Prairielearn => "variant_seed",
            }
        )
    })
}

/// The results of a submission that could not be graded, in `service`'s format.
pub fn failed(service: Service, reason: &str, start: Instant) -> String {
    let json = match service {
        Service::Gradescope => {
            serde_json::to_string_pretty(&gradescope::failed(reason, start.elapsed().as_secs_f64()))
        }
        Service::Prairielearn => serde_json::to_string_pretty(&prairielearn::failed(reason)),
    };
    json.unwrap_or_else(|_| r#"{"score": 0, "gradable": true}"#.into())
}

/// Writes `json` to `results` atomically, unless it has been written already.
fn write_once(written: &Mutex<bool>, results: &Path, json: &str) -> anyhow::Result<()> {
    let mut done = written
        .lock()
        .map_err(|_| anyhow::anyhow!("the results lock is poisoned"))?;
    if *done {
        anyhow::bail!("the results were written already");
    }
    if let Some(dir) = results.parent() {
        std::fs::create_dir_all(dir).with_context(|| format!("making {}", dir.display()))?;
    }
    crate::atomic_file::write(results, json.as_bytes())
        .with_context(|| format!("writing {}", results.display()))?;
    *done = true;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_student_of_a_submission_is_the_service_s_user_or_variant() {
        let gradescope = r#"{"id": 123, "users": [{"email": "b@x.edu", "id": 72}, {"email": "a@x.edu", "id": 9}]}"#;
        assert_eq!(student_id(Service::Gradescope, gradescope).unwrap(), "72+9");
        let one = r#"{"users": [{"email": "a@x.edu", "id": null}]}"#;
        assert_eq!(student_id(Service::Gradescope, one).unwrap(), "a@x.edu");
        let pl = r#"{"params": {}, "variant_seed": 418803}"#;
        assert_eq!(student_id(Service::Prairielearn, pl).unwrap(), "418803");
        for (service, text) in [
            (Service::Gradescope, r#"{"users": []}"#),
            (Service::Prairielearn, r#"{"params": {}}"#),
            (Service::Gradescope, "not json"),
        ] {
            assert!(student_id(service, text).is_err(), "{text}");
        }
    }
}
