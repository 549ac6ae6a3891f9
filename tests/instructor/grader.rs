//! The grader grades itself: the reference scores full marks, the shipped stubs score zero,
//! every known-wrong implementation fails its own task and only that task, and every correct
//! but different implementation passes. In-process (isolation is tested in
//! instructor_isolation.rs). Not part of the student handout: it contains correct code.

use crate::support::{grade, graded_tasks, inputs, messages, variants};
use pbrlab::grade::runner::student_tasks_for;
use pbrlab::grade::verdict::TaskStatus;
use pbrlab::grade::wire::WorkerInput;
use pbrlab::implementation::ImplChoice;
use pbrlab::worksheet::TaskId;
use pbrlab_exercises::TASKS as Student;
use pbrlab_solutions::TASKS as Reference;

#[test]
fn every_task_in_the_trait_has_checks() {
    let inputs = inputs(1);
    let graded = graded_tasks(&inputs);
    for task in TaskId::ALL {
        let in_trait = !pbrlab::worksheet::task_functions(task).is_empty();
        assert_eq!(graded.contains(&task), in_trait, "{task}");
    }
}

#[test]
fn the_reference_scores_full_marks() {
    let inputs = inputs(1);
    for task in graded_tasks(&inputs) {
        let (status, points, checks) = grade(&Reference, task, &inputs[&task]);
        assert_eq!(status, TaskStatus::Passed, "{task}:\n{}", messages(&checks));
        assert_eq!(points, task.info().points as f64);
    }
}

#[test]
fn the_shipped_stubs_score_zero_as_not_attempted() {
    let inputs = inputs(1);
    let untouched = crate::shipped_stubs::untouched();
    for task in graded_tasks(&inputs)
        .into_iter()
        .filter(|t| untouched.contains(t))
    {
        let (status, points, checks) = grade(&Student, task, &inputs[&task]);
        assert_eq!(
            status,
            TaskStatus::NotAttempted,
            "{task}:\n{}",
            messages(&checks)
        );
        assert_eq!(points, 0.0);
    }
}

/// The tasks that call `task` through the implementation (directly or through others).
fn dependents(task: TaskId) -> Vec<TaskId> {
    TaskId::ALL
        .into_iter()
        .filter(|t| *t != task && depends_on(*t, task))
        .collect()
}

fn depends_on(t: TaskId, on: TaskId) -> bool {
    t.info()
        .needs
        .iter()
        .any(|n| *n == on || depends_on(*n, on))
}

/// Each wrong implementation fails its task, and the tasks built on it still pass when
/// graded the way the grader grades them (`student_tasks_for`): the mistake is charged once.
/// Tasks that do not call it run the reference only, which `the_reference_scores_full_marks`
/// covers.
#[test]
fn every_wrong_implementation_fails_its_own_task_and_only_it() {
    let inputs = inputs(1);
    let mut report = Vec::new();
    for w in variants::wrong() {
        for task in std::iter::once(w.task).chain(dependents(w.task)) {
            let student = student_tasks_for(task, ImplChoice::Student, &[]);
            let (status, points, checks) = grade(&w.patch.only(student), task, &inputs[&task]);
            if task == w.task {
                if status == TaskStatus::Passed || points >= task.info().points as f64 {
                    report.push(format!("{task}: `{}` was not caught", w.name));
                }
                let text = messages(&checks);
                assert!(
                    !text.is_empty() && !text.contains("todo!()"),
                    "{}: {text}",
                    w.name
                );
            } else if status != TaskStatus::Passed {
                report.push(format!(
                    "{task}: `{}` (of {}) failed it:\n{}",
                    w.name,
                    w.task,
                    messages(&checks)
                ));
            }
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

/// The integrator bugs that only show in one configuration (a light not parallel to the
/// surface or brighter than 1, a sky, a point light off the origin or on the shading point,
/// MIS weights that only the variance tells apart, bounce weights above 1, a survival
/// probability other than 1/2, a path that escapes after a bounce, a depth below 1,
/// coloured albedos, surfaces without a bounce, glossy and rough surfaces, a light facing
/// away, the bounce `mis` hands on, rays off the origin, small step bounds) fail the estimator of
/// that configuration, and the message names it.
#[test]
fn integrator_bugs_fail_the_estimator_of_the_configuration_they_hide_in() {
    let inputs = inputs(1);
    let cases = [
        (
            "the sky added again after an escape",
            "a floor (ρ = 0.5) under a sky",
        ),
        ("a survival probability not capped at 1", "ρ = 1.25"),
        ("the roulette test inverted", "ρ = 0.8"),
        (
            "the light's pdf converted with the cosine at the shading point",
            "an upright square light of radiance 3 seen at grazing angles",
        ),
        (
            "an environment sample without its MIS weight",
            "a square light under a constant sky",
        ),
        (
            "point-light samples dropped",
            "a square light and a point light",
        ),
        (
            "weights p_a / (p_a − p_b): they sum to one, but are not the balance heuristic",
            "variance of the balance heuristic within Veach's bound",
        ),
        ("the light sample's radiance left out", "radiance 3"),
        (
            "the point light's direction taken from the origin",
            "a point light, off the origin",
        ),
        (
            "a point light at distance 0 divides 0 by 0",
            "a point light at the shading point",
        ),
        (
            "an environment sample never tested for occlusion",
            "a square light under a constant sky, light weights",
        ),
        ("`depth == 0` as the only stop", "called with depth -1"),
        ("survival from the smallest channel", "ρ = (0.8, 0.4, 0)"),
        ("a scalar throughput", "ρ = (0.8, 0.4, 0)"),
        ("black where mis gives no bounce", "seen directly"),
        (
            "the Lambertian density in the light sample's weight",
            "phong",
        ),
        (
            "point lights skipped under BSDF weights",
            "a point light, off the origin, bsdf weights",
        ),
        ("area lights taken as two-sided", "facing away"),
        (
            "the bounce returned with its emission not counted",
            "a whole path through",
        ),
        (
            "the medium looked up as if the ray started at the origin",
            "crossed downwards",
        ),
        (
            "one tentative collision fewer than allowed",
            "at most 1 step",
        ),
        (
            "one tentative collision more than allowed",
            "at most 2 steps",
        ),
        (
            "a walk out of steps reported as an absorption",
            "at most 5 steps",
        ),
        (
            "the Lambertian density in the BSDF sample's weight",
            "rough conductor",
        ),
    ];
    let catalogue = variants::wrong();
    for (name, configuration) in cases {
        let w = catalogue
            .iter()
            .find(|w| w.name == name)
            .unwrap_or_else(|| panic!("`{name}` is in the wrong catalogue"));
        let student = student_tasks_for(w.task, ImplChoice::Student, &[]);
        let (_, _, checks) = grade(&w.patch.only(student), w.task, &inputs[&w.task]);
        let failed = messages(&checks);
        assert!(
            failed
                .lines()
                .any(|l| l.starts_with("estimator: ") && l.contains(configuration)),
            "`{name}` should fail the estimator of {configuration}:\n{failed}"
        );
    }
}

#[test]
fn every_correct_but_different_implementation_passes() {
    let inputs = inputs(1);
    let mut report = Vec::new();
    for d in variants::different() {
        let (status, _, checks) = grade(&d.patch, d.task, &inputs[&d.task]);
        if status != TaskStatus::Passed {
            report.push(format!(
                "{}: `{}` failed:\n{}",
                d.task,
                d.name,
                messages(&checks)
            ));
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
fn a_wrong_dependency_is_blamed_on_its_own_task() {
    let inputs = inputs(1);
    let wrong_g1 = variants::wrong()
        .into_iter()
        .find(|w| w.name == "Λ without the 1/2")
        .expect("a wrong smith_g1");
    let ct = TaskId::CookTorrance;
    // Graded alone, cook_torrance runs on the reference smith_g1 and passes.
    let alone = wrong_g1
        .patch
        .only(student_tasks_for(ct, ImplChoice::Student, &[]));
    assert_eq!(grade(&alone, ct, &inputs[&ct]).0, TaskStatus::Passed);
    // With the student's smith_g1 behind it (`--impl mixed`), it fails too.
    let both = student_tasks_for(ct, ImplChoice::Mixed, &[ct, TaskId::SmithG1]);
    assert_eq!(
        grade(&wrong_g1.patch.only(both), ct, &inputs[&ct]).0,
        TaskStatus::Failed
    );
}

#[test]
fn failure_messages_name_the_case_input_and_cause() {
    let inputs = inputs(1);
    let task = TaskId::FresnelSchlick;
    let w = variants::wrong()
        .into_iter()
        .find(|w| w.name.contains("cos θi from dense"))
        .expect("the wrong-cosine Schlick");
    let (_, _, checks) = grade(&w.patch, task, &inputs[&task]);
    let text = messages(&checks);
    assert!(
        text.contains(
            "fresnel_schlick(cos_theta_i=0.76604444, eta_i=1.5, eta_t=1.0): got 0.04067, expected 0.2456 (dense→less dense: use cos θt)"
        ),
        "{text}"
    );
    let factor_4 = variants::wrong()
        .into_iter()
        .find(|w| w.name == "missing factor 4")
        .expect("factor 4")
        .patch;
    let (_, _, checks) = grade(
        &factor_4,
        TaskId::CookTorrance,
        &inputs[&TaskId::CookTorrance],
    );
    assert!(
        messages(&checks).contains(" 4 × the expected one — a constant factor"),
        "{}",
        messages(&checks)
    );
}

#[test]
fn hidden_cases_are_new_inputs_that_the_reference_passes_and_wrong_code_fails() {
    use pbrlab::grade::value_cases::{evaluate, hidden_inputs, public_inputs};
    let task = TaskId::FresnelSchlick;
    let public = public_inputs(task);
    let hidden = hidden_inputs(task, 1234);
    assert_eq!(
        hidden,
        hidden_inputs(task, 1234),
        "a seed gives the same cases"
    );
    assert_ne!(hidden, hidden_inputs(task, 1235));
    assert!(
        hidden
            .iter()
            .all(|h| public.iter().all(|p| p.call != h.call))
    );
    let mut input = inputs(1).remove(&task).unwrap();
    input.hidden = evaluate(&hidden, &Reference).unwrap();
    let (status, _, checks) = grade(&Reference, task, &input);
    assert_eq!(status, TaskStatus::Passed);
    assert!(
        checks
            .iter()
            .any(|c| c.visibility == pbrlab::grade::verdict::Visibility::Hidden)
    );
    let w = variants::wrong()
        .into_iter()
        .find(|w| w.task == task)
        .unwrap();
    let (_, _, checks) = grade(&w.patch, task, &input);
    let hidden_check = checks
        .iter()
        .find(|c| c.visibility == pbrlab::grade::verdict::Visibility::Hidden)
        .unwrap();
    assert!(!hidden_check.passed);
}

#[test]
fn a_worker_receives_every_call_and_sampler_but_no_expected_value_or_density() {
    use pbrlab::grade::value_cases::{evaluate, hidden_inputs};
    for (task, mut input) in inputs(1) {
        input.hidden = evaluate(&hidden_inputs(task, 77), &Reference).unwrap();
        let workers = input.for_workers();
        assert_eq!(workers.len(), 1 + usize::from(!input.hidden.is_empty()));
        assert!(!workers[0].values_only, "{task}");
        if let [_, hidden] = workers.as_slice() {
            assert!(hidden.values_only && hidden.sampling.is_empty(), "{task}");
            assert_eq!(
                hidden.values.len(),
                1,
                "{task}: the hidden worker's one check"
            );
        }
        let worker = WorkerInput {
            values: workers.iter().flat_map(|w| w.values.clone()).collect(),
            ..workers[0].clone()
        };
        let calls: usize = worker.values.iter().map(|v| v.calls.len()).sum();
        let cases = input.data.as_ref().map_or(0, |d| d.values.len()) + input.hidden.len();
        assert_eq!(calls, cases, "{task}: every case's call goes to the worker");
        let json = serde_json::to_string(&worker).unwrap();
        assert!(!json.contains("\"expected\""), "{task}: {json}");
        assert!(!json.contains("\"probabilities\""), "{task}: {json}");
        assert_eq!(
            worker.sampling.len(),
            input.data.as_ref().map_or(0, |d| d.sampling.len()),
            "{task}: every sampler goes to the worker"
        );
        for case in &input.hidden {
            assert!(
                worker
                    .values
                    .iter()
                    .flat_map(|v| &v.calls)
                    .any(|c| *c == case.call),
                "{task}: hidden case {} missing",
                case.name
            );
            assert!(
                !workers[0]
                    .values
                    .iter()
                    .flat_map(|v| &v.calls)
                    .any(|c| *c == case.call),
                "{task}: hidden case {} reached the visible checks' worker",
                case.name
            );
        }
    }
}
