//! JUnit XML, the test report GitLab CI, Jenkins, GitHub's test reporters and CodeGrade
//! read: a `<testsuite>` per graded task and a `<testcase>` per check, in the elements and
//! attributes of the JUnit schema those tools share (Jenkins' `junit-10.xsd`). A failing
//! check is a `<failure>` whose text is its failing cases, each with the input it was
//! given; a task that is not written yet is `<skipped>`; a task whose file does not
//! compile or whose code brought the worker down is a failing `build` or `run` case; a
//! grader error is an `<error>`. The points are the suite's properties.

use super::text::details;
use crate::grade::verdict::{CheckResult, GradeReport, TaskOutcome, TaskStatus, Visibility};
use crate::html_escape::escape;
use std::fmt::Write;

/// The JUnit XML of one or more grading runs: one suite per task of each, named
/// `student: task` when the run is named (a class), else `task`. A run that could not grade
/// (`Err` with the reason: a submission that did not build) is one suite with one failing
/// case, `submission`.
pub fn junit<'a>(
    runs: impl IntoIterator<Item = (Option<&'a str>, Result<&'a GradeReport, &'a str>)>,
) -> String {
    let mut suites = String::new();
    let (mut tests, mut failures, mut errors, mut seconds) = (0, 0, 0, 0.0);
    let mut add = |suite: &Suite| {
        tests += suite.cases.len();
        failures += suite.failures;
        errors += suite.errors;
        seconds += suite.seconds;
        suite.write(&mut suites);
    };
    for (student, run) in runs {
        match run {
            Ok(report) => {
                for task in report.tasks.iter().filter(|t| t.max_points > 0.0) {
                    add(&Suite::of(student, task));
                }
            }
            Err(reason) => add(&Suite::not_graded(student, reason)),
        }
    }
    format!(
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n\
         <testsuites name=\"pbrlab\" tests=\"{tests}\" failures=\"{failures}\" \
         errors=\"{errors}\" time=\"{seconds:.3}\">\n{suites}</testsuites>\n"
    )
}

/// One task's suite, its cases already written.
struct Suite<'a> {
    /// `student: task`, or `task`.
    name: String,
    /// `pbrlab.student.task`, or `pbrlab.task`: the class name of every case.
    classname: String,
    /// Points scored and available, and the status label: the suite's properties.
    points: (f64, f64, String),
    /// Wall time, in seconds.
    seconds: f64,
    /// What the code printed.
    output: &'a str,
    /// Each `<testcase>` element, whole.
    cases: Vec<String>,
    /// How many of them failed, erred and were skipped.
    failures: usize,
    errors: usize,
    skipped: usize,
}

impl<'a> Suite<'a> {
    /// The suite of a submission that could not be graded.
    fn not_graded(student: Option<&str>, reason: &str) -> Suite<'a> {
        let name = student.unwrap_or("submission").to_string();
        let mut suite = Suite {
            classname: format!("pbrlab.{name}"),
            name,
            points: (0.0, 0.0, "not graded".into()),
            seconds: 0.0,
            output: "",
            cases: Vec::new(),
            failures: 0,
            errors: 0,
            skipped: 0,
        };
        suite.case(
            "submission",
            0.0,
            &Verdict::Failure(format!("not graded: {reason}"), reason.to_string()),
        );
        suite
    }

    /// The suite of one graded task.
    fn of(student: Option<&str>, task: &'a TaskOutcome) -> Suite<'a> {
        let (name, classname) = match student {
            Some(s) => (
                format!("{s}: {}", task.task),
                format!("pbrlab.{s}.{}", task.task),
            ),
            None => (task.task.clone(), format!("pbrlab.{}", task.task)),
        };
        let mut suite = Suite {
            name,
            classname,
            points: (task.points, task.max_points, task.status.label()),
            seconds: task.seconds,
            output: &task.output,
            cases: Vec::new(),
            failures: 0,
            errors: 0,
            skipped: 0,
        };
        let status = match &task.status {
            TaskStatus::NotAttempted => Some(Verdict::Skipped(
                "not attempted: the functions still stop at todo!()".into(),
            )),
            TaskStatus::NeedsTask { task: first } => Some(Verdict::Skipped(format!(
                "waits for {first}, which does not pass yet"
            ))),
            _ => None,
        };
        match &task.status {
            TaskStatus::CompileError { .. } => suite.case(
                "build",
                0.0,
                &Verdict::Failure("does not compile".into(), details(task)),
            ),
            TaskStatus::Crashed { reason } => suite.case(
                "run",
                0.0,
                &Verdict::Failure(format!("the code {reason}"), details(task)),
            ),
            TaskStatus::GraderError { message } => suite.case(
                "grader",
                0.0,
                &Verdict::Error(format!("the grader failed here, not the code: {message}")),
            ),
            _ => {}
        }
        for check in &task.checks {
            let verdict = match &status {
                Some(skipped) => skipped.clone(),
                None => Verdict::of(check),
            };
            suite.case(
                &check.name,
                task.seconds / task.checks.len() as f64,
                &verdict,
            );
        }
        if suite.cases.is_empty() {
            let verdict =
                status.unwrap_or_else(|| Verdict::Failure(task.status.label(), details(task)));
            suite.case("task", task.seconds, &verdict);
        }
        suite
    }

    /// Adds a `<testcase>` named `name`.
    fn case(&mut self, name: &str, seconds: f64, verdict: &Verdict) {
        let mut case = format!(
            "    <testcase name=\"{}\" classname=\"{}\" time=\"{seconds:.3}\"",
            escape(name),
            escape(&self.classname)
        );
        match verdict {
            Verdict::Passed => case += "/>\n",
            Verdict::Skipped(message) => {
                self.skipped += 1;
                let _ = write!(
                    case,
                    ">\n      <skipped message=\"{}\"/>\n    </testcase>\n",
                    escape(message)
                );
            }
            Verdict::Failure(message, text) => {
                self.failures += 1;
                let _ = write!(
                    case,
                    ">\n      <failure message=\"{}\" type=\"failure\">{}</failure>\n    </testcase>\n",
                    escape(message),
                    body(text)
                );
            }
            Verdict::Error(message) => {
                self.errors += 1;
                let _ = write!(
                    case,
                    ">\n      <error message=\"{}\" type=\"error\"/>\n    </testcase>\n",
                    escape(message)
                );
            }
        }
        self.cases.push(case);
    }

    fn write(&self, out: &mut String) {
        let _ = write!(
            out,
            "  <testsuite name=\"{}\" tests=\"{}\" failures=\"{}\" errors=\"{}\" skipped=\"{}\" \
             time=\"{:.3}\">\n    <properties>\n      \
             <property name=\"points\" value=\"{}\"/>\n      \
             <property name=\"max_points\" value=\"{}\"/>\n      \
             <property name=\"status\" value=\"{}\"/>\n    </properties>\n",
            escape(&self.name),
            self.cases.len(),
            self.failures,
            self.errors,
            self.skipped,
            self.seconds,
            self.points.0,
            self.points.1,
            escape(&self.points.2),
        );
        for case in &self.cases {
            out.push_str(case);
        }
        if !self.output.trim().is_empty() {
            let _ = writeln!(out, "    <system-out>{}</system-out>", body(self.output));
        }
        out.push_str("  </testsuite>\n");
    }
}

/// What a `<testcase>` says.
#[derive(Clone)]
enum Verdict {
    Passed,
    /// Not run, and why.
    Skipped(String),
    /// The message (one line) and the failing cases (lines).
    Failure(String, String),
    /// The grader's own failure.
    Error(String),
}

impl Verdict {
    /// The verdict of a check that ran: its failing cases each once (the shrunk one first),
    /// a hidden check's as a count only.
    fn of(check: &CheckResult) -> Verdict {
        if check.passed {
            return Verdict::Passed;
        }
        if check.visibility == Visibility::Hidden {
            let message = format!("{} of {} hidden cases fail", check.failed, check.total);
            return Verdict::Failure(message.clone(), message);
        }
        let mut text: Vec<&str> = Vec::new();
        for case in check
            .shrunk
            .iter()
            .map(|(full, _)| full)
            .chain(&check.failures)
        {
            if !text.contains(&case.as_str()) {
                text.push(case);
            }
        }
        let more = check.failed.saturating_sub(check.failures.len());
        let more = (more > 0).then(|| format!("… and {more} more"));
        text.extend(more.as_deref());
        Verdict::Failure(check.summary.clone(), text.join("\n"))
    }
}

/// Element text: each line escaped, the line breaks kept.
fn body(text: &str) -> String {
    text.lines().map(escape).collect::<Vec<_>>().join("\n")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::verdict::CheckKind;

    fn outcome(task: &str, status: TaskStatus, checks: Vec<CheckResult>) -> TaskOutcome {
        TaskOutcome {
            task: task.into(),
            status,
            points: 1.0,
            max_points: 4.0,
            checks,
            output: String::new(),
            seconds: 0.5,
        }
    }

    #[test]
    fn each_check_is_a_case_and_each_failing_input_is_written_once_and_escaped() {
        let mut failing = CheckResult::new("values", CheckKind::Values);
        failing.fail(
            "reflect(wo=(0, 0, 1), n=(0, 0, 1)): got <NaN> & \u{7}".into(),
            String::new(),
        );
        failing.shrunk = Some((failing.failures[0].clone(), String::new()));
        failing.summary = "1 of 30 cases fail".into();
        failing.total = 30;
        failing.finish();
        let mut passing = CheckResult::new("stability", CheckKind::Stability);
        passing.total = 4;
        passing.finish();
        let mut hidden = CheckResult::new("values (hidden cases)", CheckKind::Values);
        (hidden.visibility, hidden.total) = (Visibility::Hidden, 10);
        hidden.fail("secret input".into(), String::new());
        hidden.finish();
        let report = GradeReport {
            tasks: vec![
                outcome(
                    "reflect",
                    TaskStatus::Failed,
                    vec![failing, passing, hidden],
                ),
                outcome(
                    "smith_g1",
                    TaskStatus::NotAttempted,
                    vec![CheckResult::new("values", CheckKind::Values)],
                ),
                outcome(
                    "phong",
                    TaskStatus::CompileError {
                        message: "error[E0308]".into(),
                    },
                    vec![],
                ),
            ],
            implementation: "student".into(),
            seed: 1,
            hidden: true,
            score: 1.0,
            max_score: 12.0,
            seconds: 1.5,
            sandbox: Vec::new(),
            feedback: crate::grade::feedback::Feedback::Full,
            variant: None,
        };
        let xml = junit([
            (Some("eve <x>"), Ok(&report)),
            (Some("bob"), Err("the build ran out of time")),
        ]);
        assert!(
            xml.contains("<testsuite name=\"bob\" tests=\"1\" failures=\"1\""),
            "{xml}"
        );
        assert!(
            xml.contains("<testsuite name=\"eve &lt;x&gt;: reflect\" tests=\"3\" failures=\"2\""),
            "{xml}"
        );
        assert_eq!(
            xml.matches("got &lt;NaN&gt; &amp; \u{FFFD}").count(),
            1,
            "{xml}"
        );
        assert!(!xml.contains("secret input"), "{xml}");
        assert!(xml.contains("1 of 10 hidden cases fail"), "{xml}");
        assert!(xml.contains("<skipped message=\"not attempted"), "{xml}");
        assert!(xml.contains("<testcase name=\"build\""), "{xml}");
        assert!(
            xml.contains("<testsuites name=\"pbrlab\" tests=\"6\" failures=\"4\" errors=\"0\""),
            "{xml}"
        );
    }
}
