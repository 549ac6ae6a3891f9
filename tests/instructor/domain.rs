//! Instructor test: the value cases cover each task's declared domain, measured the way
//! the hidden rounds of student bugs are, by a *boundary-mutation score*.
//!
//! For every task, every declared boundary (each side inside the range), every special
//! value and every output field, a variant of the reference is wrong only there: by 1 %
//! (at least 1e-3) inside a band of relative width 1e-3 at the boundary, exactly at the
//! special value or within 1e-3 of it, between a boundary and that boundary moved by
//! ±10 % (a threshold mutant), or in that one field of every output. The grader must fail each variant,
//! both with the stored public cases alone (the handout) and with a hidden seed's cases
//! added (a class). Verdict-judged outputs (reciprocity gaps, plausibility reports) are
//! judged by their verdicts, not their digits, and are left out of the field variants.

use pbrlab::grade::call::Call;
use pbrlab::grade::case::{Rule, ValueCase};
use pbrlab::grade::catalogue::{contract, domain};
use pbrlab::grade::domain::Param;
use pbrlab::grade::output::Output;
use pbrlab::grade::value_cases::{evaluate, hidden_inputs, public_inputs};
use pbrlab::grade::values::judge;
use pbrlab::grade::verdict::Visibility;
use pbrlab::grade::wire::ValueOutputs;
use pbrlab::worksheet::{TaskId, Tasks};
use pbrlab_solutions::TASKS as Reference;
use std::collections::{BTreeMap, BTreeSet};

/// The relative width of a mutant's band at a boundary.
const BAND: f64 = 1e-3;
/// How far a threshold mutant moves a compared constant, relative to it.
const THRESHOLD: f64 = 0.1;
/// Below this share of caught variants a task fails the score.
const REQUIRED: f64 = 0.98;

/// Every leaf path of a call's stored form (`w`, `params.exponent`, `stack.slabs`),
/// without its `fn` tag.
fn input_paths(call: &Call) -> (String, Vec<String>) {
    fn walk(prefix: &str, v: &serde_json::Value, out: &mut Vec<String>) {
        match v {
            serde_json::Value::Object(fields) => {
                for (k, f) in fields {
                    let path = if prefix.is_empty() {
                        k.clone()
                    } else {
                        format!("{prefix}.{k}")
                    };
                    walk(&path, f, out);
                }
            }
            _ => out.push(prefix.to_string()),
        }
    }
    let mut v = serde_json::to_value(call).expect("a call serialises");
    let function = v["fn"].as_str().expect("tagged by fn").to_string();
    v.as_object_mut().expect("an object").remove("fn");
    let mut paths = Vec::new();
    walk("", &v, &mut paths);
    (function, paths)
}

/// A path is covered by a declared path that is it or one of its parents.
fn covers(declared: &str, path: &str) -> bool {
    path == declared || path.starts_with(&format!("{declared}."))
}

#[test]
fn every_input_of_every_task_function_is_declared_and_drawn_inside_its_domain() {
    let mut problems = Vec::new();
    for task in TaskId::ALL {
        let params = domain(task);
        let inputs: Vec<_> = public_inputs(task)
            .into_iter()
            .chain(hidden_inputs(task, 1))
            .collect();
        let mut functions = BTreeSet::new();
        for input in &inputs {
            let (function, paths) = input_paths(&input.call);
            for path in paths {
                let declared = params
                    .iter()
                    .any(|p| p.function == function && p.covers.iter().any(|d| covers(d, &path)));
                if !declared {
                    problems.push(format!(
                        "{task}: `{function}` input `{path}` has no declaration"
                    ));
                }
            }
            if input.drawn {
                for p in params.iter().filter(|p| p.function == function) {
                    if let Some(v) = (p.value)(&input.call)
                        && !(p.lo..=p.hi).contains(&v)
                    {
                        problems.push(format!(
                            "{task}: `{}` of {} is {v}, outside [{}, {}]",
                            p.name, input.call, p.lo, p.hi
                        ));
                    }
                }
            }
            functions.insert(function);
        }
        for p in params {
            if !functions.contains(p.function) {
                problems.push(format!(
                    "{task}: `{}` declares an ungraded function",
                    p.function
                ));
            }
        }
    }
    problems.dedup();
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}

/// `x` made wrong: 1 % off, and at least 1e-3 (beyond every tolerance of a value check).
fn off(x: f64) -> f64 {
    x + 0.01 * x.abs().max(0.1)
}

/// Every number of `out` made wrong; `None` becomes a value.
fn wrong(out: &Output) -> Output {
    match out {
        Output::Nothing => Output::Number(0.0),
        Output::Number(x) => Output::Number(off(*x)),
        Output::Numbers(v) => Output::Numbers(v.iter().map(|x| off(*x)).collect()),
        Output::Record(m) => Output::Record(m.iter().map(|(k, v)| (k.clone(), wrong(v))).collect()),
    }
}

/// `out` with only the field at `path` made wrong (the whole output for the empty path).
fn wrong_at(out: &Output, path: &[&str]) -> Output {
    match (out, path) {
        (_, []) => wrong(out),
        (Output::Record(m), [first, rest @ ..]) => Output::Record(
            m.iter()
                .map(|(k, v)| {
                    let v = if k == first {
                        wrong_at(v, rest)
                    } else {
                        v.clone()
                    };
                    (k.clone(), v)
                })
                .collect(),
        ),
        _ => out.clone(),
    }
}

/// The field paths of a record output (nested with `.`); empty for a plain value.
fn field_paths(out: &Output, prefix: &str, into: &mut BTreeSet<String>) {
    if let Output::Record(m) = out {
        for (k, v) in m {
            let path = if prefix.is_empty() {
                k.clone()
            } else {
                format!("{prefix}.{k}")
            };
            into.insert(path.clone());
            field_paths(v, &path, into);
        }
    }
}

/// One wrong variant of the reference: its name and which outputs it changes.
struct Mutant {
    name: String,
    answer: Box<dyn Fn(&ValueCase) -> Output>,
}

fn mutants(task: TaskId, cases: &[ValueCase]) -> Vec<Mutant> {
    let mut out = Vec::new();
    let judged_by_value: BTreeSet<String> = cases
        .iter()
        .filter(|c| matches!(c.rule, Rule::Close(_)))
        .map(|c| input_paths(&c.call).0)
        .collect();
    for p in domain(task).iter().copied() {
        if !judged_by_value.contains(p.function) {
            continue;
        }
        let band = |p: Param, lo: f64, hi: f64, name: String| Mutant {
            name,
            answer: Box::new(move |c: &ValueCase| match (p.value)(&c.call) {
                Some(v) if (lo..=hi).contains(&v) => wrong(&c.expected),
                _ => c.expected.clone(),
            }),
        };
        let tiny = |at: f64| 1e-7 * p.scale(at);
        for b in p.boundaries {
            // Open bands: a variant wrong only near the boundary, right on it.
            let width = BAND * p.scale(b.at);
            if b.at > p.lo {
                out.push(band(
                    p,
                    b.at - width,
                    b.at - tiny(b.at),
                    format!(
                        "`{}` {}: just below {} ({})",
                        p.function, p.name, b.at, b.what
                    ),
                ));
            }
            if b.at < p.hi {
                out.push(band(
                    p,
                    b.at + tiny(b.at),
                    b.at + width,
                    format!(
                        "`{}` {}: just above {} ({})",
                        p.function, p.name, b.at, b.what
                    ),
                ));
            }
            if p.on_boundaries {
                out.push(band(
                    p,
                    b.at - tiny(b.at),
                    b.at + tiny(b.at),
                    format!("`{}` {}: on {} ({})", p.function, p.name, b.at, b.what),
                ));
            }
        }
        for &s in p.special {
            out.push(band(
                p,
                s - tiny(s),
                s + tiny(s),
                format!("`{}` {} = {s}", p.function, p.name),
            ));
            // Wrong within 1e-3 of a special point (code that skips a normalisation when
            // a length is within 1e-3 of 1, or cuts off a cosine below 1e-3).
            let width = BAND * p.scale(s);
            out.push(band(
                p,
                s - width,
                s + width,
                format!("`{}` {}: within {BAND} of {s}", p.function, p.name),
            ));
        }
        // Threshold mutants: every value the reference compares against, moved by ±10 %
        // (a floor of 1e-4 written 1.1e-4, a `<` that should be `<=` a little off).
        let thresholds = p.boundaries.iter().map(|b| b.at).filter(|v| *v != 0.0);
        for t in thresholds {
            for moved in [t * (1.0 - THRESHOLD), t * (1.0 + THRESHOLD)] {
                let (lo, hi) = if moved < t {
                    (moved, t - tiny(t) * t.abs().min(1.0))
                } else {
                    (t + tiny(t) * t.abs().min(1.0), moved)
                };
                let (lo, hi) = (lo.max(p.lo), hi.min(p.hi));
                if lo < hi {
                    out.push(band(
                        p,
                        lo,
                        hi,
                        format!(
                            "`{}` {}: threshold {t} moved to {moved}",
                            p.function, p.name
                        ),
                    ));
                }
            }
        }
    }
    // One variant per output field of every function, wrong in that field alone.
    let mut fields: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for c in cases.iter().filter(|c| matches!(c.rule, Rule::Close(_))) {
        let (function, _) = input_paths(&c.call);
        let entry = fields.entry(function).or_default();
        entry.insert(String::new());
        field_paths(&c.expected, "", entry);
    }
    for (function, paths) in fields {
        for path in paths {
            let f = function.clone();
            let parts: Vec<String> = path
                .split('.')
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect();
            out.push(Mutant {
                name: format!(
                    "`{function}` output {}",
                    if path.is_empty() { "(whole)" } else { &path }
                ),
                answer: Box::new(move |c: &ValueCase| {
                    if input_paths(&c.call).0 == f && matches!(c.rule, Rule::Close(_)) {
                        let parts: Vec<&str> = parts.iter().map(String::as_str).collect();
                        wrong_at(&c.expected, &parts)
                    } else {
                        c.expected.clone()
                    }
                }),
            });
        }
    }
    out
}

/// Whether the values check fails `mutant` on `cases`.
fn caught(mutant: &Mutant, cases: &[ValueCase]) -> bool {
    let outputs = ValueOutputs {
        check: "values".into(),
        outputs: cases.iter().map(|c| Ok((mutant.answer)(c))).collect(),
        seconds: 0.0,
    };
    judge(cases, &outputs, Visibility::Visible).failed > 0
}

#[test]
fn the_value_cases_catch_every_boundary_mutant() {
    let mut report = String::from("task | variants | caught (public) | caught (public + hidden)\n");
    let mut failures = Vec::new();
    let mut missed = Vec::new();
    for task in TaskId::ALL {
        let public = evaluate(&public_inputs(task), &Reference).expect("reference outputs");
        let mut class = public.clone();
        class.extend(evaluate(&hidden_inputs(task, 2026), &Reference).expect("reference outputs"));
        // The reference itself passes its own cases.
        let exact = Mutant {
            name: "the reference".into(),
            answer: Box::new(|c: &ValueCase| c.expected.clone()),
        };
        assert!(
            !caught(&exact, &class),
            "{task}: the reference fails its own cases"
        );
        let all = mutants(task, &class);
        let mut on_public = 0;
        let mut on_class = 0;
        for m in &all {
            on_public += usize::from(caught(m, &public));
            if caught(m, &class) {
                on_class += 1;
            } else {
                missed.push(format!("{task}: {}", m.name));
            }
        }
        if all.is_empty() {
            continue;
        }
        report += &format!("{task} | {} | {on_public} | {on_class}\n", all.len());
        if (on_class as f64) < REQUIRED * all.len() as f64 {
            failures.push(format!("{task}: {on_class}/{} caught", all.len()));
        }
    }
    println!("{report}\nmissed:\n{}", missed.join("\n"));
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Every correct alternative passes the value cases (public and hidden) of `seeds`, the
/// seeds split over the machine's cores.
fn alternatives_pass(seeds: std::ops::Range<u64>) {
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get()) as u64;
    let failures: Vec<String> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads)
            .map(|k| {
                let seeds = seeds.clone().filter(move |s| s % threads == k);
                scope.spawn(move || alternatives_fail(seeds))
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|w| {
                w.join()
                    .expect("a worker of the alternatives check panicked")
            })
            .collect()
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The failures of every correct alternative on the value cases (public and hidden) of
/// `seeds`.
fn alternatives_fail(seeds: impl Iterator<Item = u64> + Clone) -> Vec<String> {
    use crate::support::variants;
    use pbrlab::grade::values::run;
    let mut failures = Vec::new();
    for task in TaskId::ALL {
        if domain(task).is_empty() {
            continue;
        }
        let public = evaluate(&public_inputs(task), &Reference).expect("reference outputs");
        // Where the task has a contract in f64, the expected outputs are the contract's,
        // and the f32 reference is one more correct implementation to try.
        let has_contract = public.iter().any(|c| contract(&c.call).is_some());
        let reference = has_contract.then(|| crate::support::patch::Variant {
            name: "the f32 reference",
            task,
            patch: crate::support::patch::Patch::new(task),
        });
        let variants: Vec<_> = variants::different()
            .into_iter()
            .filter(|d| d.task == task)
            .chain(reference)
            .collect();
        for seed in seeds.clone() {
            let mut cases = public.clone();
            cases.extend(evaluate(&hidden_inputs(task, seed), &Reference).expect("reference"));
            for d in &variants {
                let result = run("values", &cases, Visibility::Hidden, &d.patch);
                if result.failed > 0 {
                    failures.push(format!(
                        "{task}, seed {seed}: `{}` fails {}/{}: {:?}",
                        d.name, result.failed, result.total, result.failures
                    ));
                }
            }
        }
    }
    failures
}

#[test]
fn every_correct_alternative_passes_the_hidden_cases_of_a_few_seeds() {
    alternatives_pass(0..3);
}

/// Every correct alternative (f64 throughout, other algebraic forms) over many hidden
/// seeds, no failing case: the value checks have no false-failure rate to spend, their
/// tolerances come from the contract's conditioning at each input. CI runs 200 seeds (a
/// minute on two cores); `PBRLAB_ALTERNATIVE_SEEDS=1000` runs the 1,000 (four
/// minutes, 0 failing cases at this commit).
#[test]
#[ignore = "slow: 200 seeds of every closed-form task (run in CI with --ignored)"]
fn every_correct_alternative_passes_the_hidden_cases_of_many_seeds() {
    let seeds = std::env::var("PBRLAB_ALTERNATIVE_SEEDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(200);
    alternatives_pass(0..seeds);
}

#[test]
fn a_failing_value_check_names_its_simplest_and_its_shrunk_failing_input_in_every_report() {
    use crate::support::patch::Patch;
    use pbrlab::grade::report::{Detail, gradescope, text, write_html};
    use pbrlab::grade::verdict::{GradeReport, TaskStatus};
    let task = TaskId::SmithG1;
    let mut patch = Patch::new(task);
    // Wrong only just above the horizon.
    patch.smith_g1 = Some(|w, alpha| {
        if w.z > 0.0 && w.z < 1e-3 {
            0.5
        } else {
            pbrlab_solutions::smith_g1::smith_g1(w, alpha)
        }
    });
    let inputs = crate::support::inputs(1);
    let (status, points, mut checks) = crate::support::grade(&patch, task, &inputs[&task]);
    assert_eq!(status, TaskStatus::Failed);
    // Shrunk as the grader shrinks it, with the student's outputs computed here.
    let cases = &inputs[&task].data.as_ref().expect("stored cases").values;
    let calls: Vec<Call> = cases.iter().map(|c| c.call.clone()).collect();
    let outputs = pbrlab::grade::measure::evaluate_values("values", &calls, &patch);
    let values = checks.iter_mut().find(|c| c.name == "values").unwrap();
    let before = values.summary.clone();
    pbrlab::grade::shrink::attach(
        cases,
        &outputs,
        values,
        &Reference,
        |calls: &[Call]| pbrlab::grade::measure::evaluate_values("values", calls, &patch).outputs,
        std::time::Duration::from_secs(60),
    );
    let (shrunk, _) = values.shrunk.clone().expect("a simpler failing input");
    assert!(
        shrunk.starts_with("shrunk to smith_g1("),
        "{before}\n{shrunk}"
    );
    // Still in the band next to the horizon, and still failing there.
    assert!(shrunk.contains("from the horizon"), "{shrunk}");
    let values = checks
        .iter()
        .find(|c| c.name == "values")
        .expect("values ran");
    let simplest = &values.failures[0];
    assert!(
        simplest.starts_with("simplest failing input: smith_g1(")
            && simplest.contains("from the horizon: cos θ of w"),
        "{simplest}"
    );
    // Each failing case is printed once: the summary counts, the list names.
    assert!(!values.summary.contains("smith_g1("), "{}", values.summary);
    let report = GradeReport::new(
        "student",
        1,
        false,
        vec![crate::support::outcome(task, (status, points, checks))],
        1.0,
    );
    let dir = tempfile::tempdir().unwrap();
    let html = std::fs::read_to_string(write_html(&report, dir.path()).unwrap()).unwrap();
    let results = serde_json::to_string(&gradescope(&report)).unwrap();
    for (name, shown) in [
        ("HTML", html),
        ("Gradescope", results),
        // The terminal's table as a student sees it, its long lines wrapped.
        (
            "text",
            text(&report, Detail::Compact)
                .split_whitespace()
                .collect::<Vec<_>>()
                .join(" "),
        ),
    ] {
        assert!(
            shown.contains("simplest failing input: smith_g1(")
                && shown.contains("shrunk to smith_g1(")
                && shown.contains("from the horizon"),
            "the {name} report does not name the simplest failing input:\n{shown}"
        );
    }
}

/// `w` with its polar angle scaled by 1.01 (clamped at the horizon): a sampler 1 % off.
fn one_percent_off(w: glam::Vec3) -> glam::Vec3 {
    let theta = (w.z.clamp(-1.0, 1.0).acos() * 1.01).min(std::f32::consts::FRAC_PI_2);
    let phi = w.y.atan2(w.x);
    glam::Vec3::new(
        theta.sin() * phi.cos(),
        theta.sin() * phi.sin(),
        theta.cos(),
    )
}

#[test]
fn a_sampler_one_percent_off_its_pdf_fails_its_values() {
    use crate::support::patch::Patch;
    let inputs = crate::support::inputs(1);
    let mut cosine = Patch::new(TaskId::CosineSample);
    cosine.cosine_sample = Some(|u| one_percent_off(pbrlab_solutions::TASKS.cosine_sample(u)));
    let mut ndf = Patch::new(TaskId::NdfSample);
    ndf.ndf_sample = Some(|_, wo, ax, ay, u| {
        pbrlab_solutions::TASKS
            .ndf_sample(wo, ax, ay, u)
            .map(one_percent_off)
    });
    for (task, patch) in [(TaskId::CosineSample, cosine), (TaskId::NdfSample, ndf)] {
        let (_, _, checks) = crate::support::grade(&patch, task, &inputs[&task]);
        let values = checks
            .iter()
            .find(|c| c.name == "values")
            .expect("values ran");
        let said = format!("{}\n{}", values.summary, values.failures.join("\n"));
        assert!(
            !values.passed && said.contains("the directions do not follow the pdf"),
            "{task}: {said}"
        );
    }
}

/// Credit by region: a bug confined to the tiniest cosines (Λ from tan²θ = (1 − c²)/c², NaN
/// once c² underflows below 1e-19 or so) fails those special points' regions alone, the
/// values checks lose exactly their share, and the task keeps more than its pass
/// threshold: partly right, not failed.
#[test]
fn a_bug_confined_to_one_region_costs_that_region_s_share_and_is_not_a_failed_task() {
    use crate::support::patch::Patch;
    use pbrlab::grade::checks::{PASS_SHARE, grade_task, score};
    use pbrlab::grade::credit::Credit;
    use pbrlab::grade::runner::{GradeOptions, prepare};
    use pbrlab::grade::verdict::TaskStatus;
    crate::support::install();
    let task = TaskId::SmithG1;
    let mut patch = Patch::new(task);
    patch.smith_g1 = Some(|w, alpha| {
        if w.z <= 0.0 {
            return 0.0;
        }
        let c2 = (w.z * w.z).min(1.0);
        let a = alpha * alpha * (1.0 - c2) / c2;
        1.0 / (1.0 + a / (2.0 * (1.0 + (1.0 + a).sqrt())))
    });
    let inputs = prepare(&GradeOptions {
        hidden_seed: Some(3),
        ..GradeOptions::default()
    })
    .expect("inputs");
    let mut checks = grade_task(&patch, task, &inputs[&task]);
    Credit::PerRegion.apply(&mut checks);
    let values: Vec<_> = checks.iter().filter(|c| !c.regions.is_empty()).collect();
    assert!(!values.is_empty(), "{checks:?}");
    let mut failing_somewhere = false;
    for c in &values {
        let failing: Vec<_> = c.regions.iter().filter(|r| r.failed > 0).collect();
        assert!(
            failing.iter().all(|r| r.name.starts_with("cos θ of w = ")),
            "{}: {failing:?}",
            c.name
        );
        let share = 1.0 - failing.len() as f64 / c.regions.len() as f64;
        assert!((c.credit - share).abs() < 1e-12, "{}: {}", c.name, c.credit);
        failing_somewhere |= !failing.is_empty();
    }
    assert!(failing_somewhere, "the cut-off is caught");
    let (status, points) = score(task, &checks);
    let max = task.info().points as f64;
    assert_eq!(status, TaskStatus::Partial, "{points} of {max}");
    assert!(
        points < max && points >= PASS_SHARE * max,
        "{points} of {max}"
    );
}
