//! The two results formats as their documentation specifies them, checked key by key before
//! a results file is written (and by the tests): Gradescope's results.json
//! (<https://gradescope-autograders.readthedocs.io/en/latest/specs/>) and PrairieLearn's
//! external-grader results (<https://prairielearn.readthedocs.io/en/latest/externalGrading/>).

use anyhow::{bail, ensure};
use serde_json::{Map, Value};

/// The results formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Service {
    /// Gradescope's autograder.
    Gradescope,
    /// PrairieLearn's external grader.
    Prairielearn,
}

const GRADESCOPE_TOP: &[&str] = &[
    "score",
    "execution_time",
    "output",
    "output_format",
    "visibility",
    "stdout_visibility",
    "extra_data",
    "tests",
    "leaderboard",
];
const GRADESCOPE_TEST: &[&str] = &[
    "score",
    "max_score",
    "status",
    "name",
    "name_format",
    "number",
    "output",
    "output_format",
    "tags",
    "visibility",
    "extra_data",
];
const GRADESCOPE_VISIBILITY: &[&str] = &["hidden", "after_due_date", "after_published", "visible"];
const PRAIRIELEARN_TOP: &[&str] = &["gradable", "score", "message", "output", "images", "tests"];
const PRAIRIELEARN_TEST: &[&str] = &[
    "name",
    "description",
    "points",
    "max_points",
    "message",
    "output",
];

fn object<'a>(value: &'a Value, what: &str) -> anyhow::Result<&'a Map<String, Value>> {
    value
        .as_object()
        .ok_or_else(|| anyhow::anyhow!("{what} is not an object"))
}

fn only(map: &Map<String, Value>, allowed: &[&str], what: &str) -> anyhow::Result<()> {
    for key in map.keys() {
        ensure!(
            allowed.contains(&key.as_str()),
            "{what} has the unknown key `{key}`"
        );
    }
    Ok(())
}

fn number(map: &Map<String, Value>, key: &str, what: &str) -> anyhow::Result<Option<f64>> {
    match map.get(key) {
        None => Ok(None),
        Some(v) => match v.as_f64() {
            Some(x) if x.is_finite() => Ok(Some(x)),
            _ => bail!("{what}.{key} is not a finite number"),
        },
    }
}

fn string(map: &Map<String, Value>, key: &str, what: &str) -> anyhow::Result<()> {
    ensure!(
        map.get(key).is_none_or(Value::is_string),
        "{what}.{key} is not a string"
    );
    Ok(())
}

/// Checks `json` against `service`'s results format.
pub fn validate(service: Service, json: &str) -> anyhow::Result<()> {
    let value: Value = serde_json::from_str(json)?;
    let top = object(&value, "the results")?;
    match service {
        Service::Gradescope => {
            only(top, GRADESCOPE_TOP, "the results")?;
            let tests = top.get("tests").and_then(Value::as_array);
            ensure!(
                top.contains_key("score") || tests.is_some_and(|t| !t.is_empty()),
                "the results have neither a score nor tests"
            );
            number(top, "score", "the results")?;
            number(top, "execution_time", "the results")?;
            string(top, "output", "the results")?;
            for key in ["visibility", "stdout_visibility"] {
                if let Some(v) = top.get(key) {
                    ensure!(
                        v.as_str()
                            .is_some_and(|v| GRADESCOPE_VISIBILITY.contains(&v)),
                        "the results' {key} is not one of {GRADESCOPE_VISIBILITY:?}"
                    );
                }
            }
            for (i, test) in tests.into_iter().flatten().enumerate() {
                let what = format!("tests[{i}]");
                let test = object(test, &what)?;
                only(test, GRADESCOPE_TEST, &what)?;
                let score = number(test, "score", &what)?;
                let max = number(test, "max_score", &what)?;
                ensure!(
                    score.is_some() || test.contains_key("status"),
                    "{what} has neither score nor status"
                );
                if let (Some(score), Some(max)) = (score, max) {
                    ensure!(score <= max + 1e-9, "{what} scores {score} of {max}");
                }
                if let Some(status) = test.get("status") {
                    ensure!(
                        matches!(status.as_str(), Some("passed" | "failed")),
                        "{what}.status is not passed or failed"
                    );
                }
                if let Some(v) = test.get("visibility") {
                    ensure!(
                        v.as_str()
                            .is_some_and(|v| GRADESCOPE_VISIBILITY.contains(&v)),
                        "{what}.visibility is not one of {GRADESCOPE_VISIBILITY:?}"
                    );
                }
                for key in ["name", "output", "number"] {
                    string(test, key, &what)?;
                }
            }
        }
        Service::Prairielearn => {
            only(top, PRAIRIELEARN_TOP, "the results")?;
            ensure!(
                top.get("gradable").is_some_and(Value::is_boolean),
                "the results' gradable is not a boolean"
            );
            let score = number(top, "score", "the results")?;
            if top["gradable"] == Value::Bool(true) {
                let score =
                    score.ok_or_else(|| anyhow::anyhow!("a gradable result has no score"))?;
                ensure!(
                    (0.0..=1.0).contains(&score),
                    "the score {score} is not in [0, 1]"
                );
            }
            string(top, "message", "the results")?;
            string(top, "output", "the results")?;
            if let Some(tests) = top.get("tests") {
                let tests = tests
                    .as_array()
                    .ok_or_else(|| anyhow::anyhow!("the results' tests is not a list"))?;
                for (i, test) in tests.iter().enumerate() {
                    let what = format!("tests[{i}]");
                    let test = object(test, &what)?;
                    only(test, PRAIRIELEARN_TEST, &what)?;
                    ensure!(
                        test.get("name").is_some_and(Value::is_string),
                        "{what} has no name"
                    );
                    let points = number(test, "points", &what)?;
                    let max = number(test, "max_points", &what)?;
                    if let (Some(points), Some(max)) = (points, max) {
                        ensure!(points <= max + 1e-9, "{what} scores {points} of {max}");
                    }
                }
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_format_accepts_its_own_shape_and_refuses_the_other() {
        let gradescope = r#"{"score": 3, "execution_time": 1.5, "output": "x", "visibility": "visible",
            "tests": [{"name": "a", "score": 3, "max_score": 5, "status": "failed",
                       "visibility": "after_published", "output": ""}]}"#;
        let prairielearn = r#"{"gradable": true, "score": 0.6, "message": "m",
            "tests": [{"name": "a", "points": 3, "max_points": 5, "output": ""}]}"#;
        validate(Service::Gradescope, gradescope).unwrap();
        validate(Service::Prairielearn, prairielearn).unwrap();
        assert!(validate(Service::Gradescope, prairielearn).is_err());
        assert!(validate(Service::Prairielearn, gradescope).is_err());
        for bad in [
            r#"{"score": 1, "max_score": 2}"#,
            r#"{"tests": [{"name": "a", "score": 6, "max_score": 5}]}"#,
            r#"{"score": 1, "tests": [{"score": 1, "visibility": "secret"}]}"#,
            r#"{"score": "1"}"#,
        ] {
            assert!(validate(Service::Gradescope, bad).is_err(), "{bad}");
        }
        for bad in [
            r#"{"gradable": true, "score": 1.5}"#,
            r#"{"gradable": true}"#,
            r#"{"score": 0.5}"#,
        ] {
            assert!(validate(Service::Prairielearn, bad).is_err(), "{bad}");
        }
    }
}
