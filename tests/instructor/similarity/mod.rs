//! The measurement behind the defaults: a generated class, planted copies, and how many of
//! each the comparison flags.
//!
//! Independent code: the reference solutions (`solutions/<task>.rs`) and the alternatives
//! in `alternatives/alt1`, `alt2` (every task) and `alt3` (the long tasks), written independently in other styles. A student without a file for a task
//! submits the shipped stub (`exercises/<task>.rs`), which is also the exclusion.
//!
//! For every independent student and every [`Disguise`], a class of the independent
//! students plus one disguised copy of that student is compared: the copy must be flagged,
//! per task for the tasks long enough to judge and over all tasks; independent pairs must
//! not be.
//!
mod transform;

use pbrlab::similarity::*;
use pbrlab::worksheet::TaskId;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use transform::{Disguise, disguise};

/// Tasks whose solutions are long enough to be judged on their own (at least about
/// 20 lines of code): a planted copy of these must be flagged per task.
const LONG_TASKS: [&str; 8] = [
    "refract_stack",
    "cook_torrance",
    "phong",
    "ndf_sample",
    "brdf_check",
    "path_trace",
    "mis",
    "delta_tracking",
];

/// The class: per student, per task, the file's text; and the stubs.
struct Corpus {
    stubs: BTreeMap<&'static str, String>,
    students: BTreeMap<String, BTreeMap<&'static str, String>>,
}

/// The tasks, in worksheet order.
fn task_names() -> Vec<&'static str> {
    TaskId::ALL.iter().map(|t| t.name()).collect()
}

/// The independent students' files (the reference and the alternatives) and the stubs.
fn corpus() -> Corpus {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let read = |dir: &Path, task: &str| {
        let file = dir.join(format!("{task}.rs"));
        std::fs::read_to_string(&file).ok()
    };
    let stubs = task_names()
        .into_iter()
        .map(|task| {
            let stub = read(&root.join("exercises"), task).expect("the shipped stub");
            (task, stub)
        })
        .collect();
    let alternatives = root.join("tests/instructor/similarity/alternatives");
    let mut folders: Vec<(String, PathBuf)> = vec![("reference".into(), root.join("solutions"))];
    for alt in ["alt1", "alt2", "alt3"] {
        folders.push((alt.to_string(), alternatives.join(alt)));
    }
    let mut students = BTreeMap::new();
    for (name, dir) in folders {
        let files: BTreeMap<&'static str, String> = task_names()
            .into_iter()
            .filter_map(|task| Some((task, read(&dir, task)?)))
            .collect();
        assert!(!files.is_empty(), "no files in {}", dir.display());
        students.insert(name, files);
    }
    Corpus { stubs, students }
}

/// A student's file for a task, or the stub if they have none.
fn file_of<'a>(corpus: &'a Corpus, student: &str, task: &str) -> Option<&'a String> {
    corpus
        .students
        .get(student)
        .and_then(|files| files.get(task))
        .or_else(|| corpus.stubs.get(task))
}

/// What one configuration achieves.
#[derive(Default, Debug)]
struct Outcome {
    /// Per disguise: (task flags found, task copies planted) over the long tasks.
    long_task_found: BTreeMap<Disguise, (usize, usize)>,
    /// Per disguise: (found, planted) over all tasks with a solution.
    any_task_found: BTreeMap<Disguise, (usize, usize)>,
    /// Per task: (found, planted) over all disguises.
    per_task_found: BTreeMap<&'static str, (usize, usize)>,
    /// Per disguise: (whole copied submissions flagged over all tasks, planted).
    aggregate_found: BTreeMap<Disguise, (usize, usize)>,
    /// Lowest aggregate score of a planted copy.
    aggregate_copy_min: f64,
    /// Lowest score and shared count of a planted copy of a long task.
    long_task_copy_min: (f64, usize),
    /// Highest shared count of an independent task pair.
    independent_task_max_shared: usize,
    /// Sum and count of the scores of planted copies of long tasks, and of independent
    /// pairs of long tasks: their means.
    long_task_copy_mean: (f64, usize),
    long_task_independent_mean: (f64, usize),
    /// Independent task pairs (both solved): flagged, compared, highest score.
    independent_task: (usize, usize, f64),
    /// Per task: the highest independent score.
    independent_task_max: BTreeMap<&'static str, f64>,
    /// Independent submission pairs over all tasks: flagged, compared, highest score.
    independent_aggregate: (usize, usize, f64),
}

fn compare_class(
    corpus: &Corpus,
    class: &BTreeMap<String, BTreeMap<&'static str, String>>,
    options: &Options,
) -> Vec<TaskComparison> {
    task_names()
        .into_iter()
        .map(|task| {
            let files: Vec<Source> = class
                .iter()
                .filter_map(|(student, files)| {
                    Some(Source {
                        student: student.clone(),
                        text: files.get(task)?.clone(),
                    })
                })
                .collect();
            let stub = corpus.stubs.get(task).map_or("", String::as_str);
            compare_task(task, &files, &[stub], options)
        })
        .collect()
}

/// Every independent student's files, stubs where they have none.
fn independent_class(corpus: &Corpus) -> BTreeMap<String, BTreeMap<&'static str, String>> {
    corpus
        .students
        .keys()
        .map(|student| {
            let files = task_names()
                .into_iter()
                .filter_map(|task| Some((task, file_of(corpus, student, task)?.clone())))
                .collect();
            (student.clone(), files)
        })
        .collect()
}

fn measure(corpus: &Corpus, options: &Options) -> Outcome {
    let mut outcome = Outcome {
        aggregate_copy_min: f64::INFINITY,
        long_task_copy_min: (f64::INFINITY, usize::MAX),
        ..Outcome::default()
    };
    let solved = |student: &str, task: &str| {
        corpus
            .students
            .get(student)
            .is_some_and(|files| files.contains_key(task))
    };
    let independent = independent_class(corpus);

    // False flags: the independent students alone.
    let tasks = compare_class(corpus, &independent, options);
    let names: Vec<&String> = independent.keys().collect();
    for t in &tasks {
        let task = task_names()
            .into_iter()
            .find(|&n| n == t.task)
            .unwrap_or("");
        for (n, a) in names.iter().enumerate() {
            for b in names.iter().skip(n + 1) {
                if !(solved(a, task) && solved(b, task)) {
                    continue;
                }
                let pair = t.pairs.iter().find(|p| &p.a == *a && &p.b == *b);
                let (flagged, score) = pair.map_or((false, 0.0), |p| (p.flagged, p.score));
                outcome.independent_task.0 += usize::from(flagged);
                outcome.independent_task.1 += 1;
                outcome.independent_task.2 = outcome.independent_task.2.max(score);
                outcome.independent_task_max_shared = outcome
                    .independent_task_max_shared
                    .max(pair.map_or(0, |p| p.shared));
                if LONG_TASKS.contains(&task) {
                    outcome.long_task_independent_mean.0 += score;
                    outcome.long_task_independent_mean.1 += 1;
                }
                let max = outcome.independent_task_max.entry(task).or_insert(0.0);
                *max = max.max(score);
            }
        }
    }
    let ranked = rank(&tasks, options);
    for (n, a) in names.iter().enumerate() {
        for b in names.iter().skip(n + 1) {
            let pair = ranked.iter().find(|p| &p.a == *a && &p.b == *b);
            outcome.independent_aggregate.0 += usize::from(pair.is_some_and(|p| p.flagged));
            outcome.independent_aggregate.1 += 1;
            let score = pair.map_or(0.0, |p| p.score);
            outcome.independent_aggregate.2 = outcome.independent_aggregate.2.max(score);
        }
    }

    // Planted copies, one per class.
    for (seed, how) in Disguise::ALL.into_iter().enumerate() {
        for original in corpus.students.keys() {
            let copy_name = format!("{original}~copy");
            let mut class = independent.clone();
            let copied: BTreeMap<&'static str, String> = task_names()
                .into_iter()
                .filter_map(|task| {
                    let text = file_of(corpus, original, task)?;
                    let text = if solved(original, task) {
                        disguise(text, how, seed as u64 + task.len() as u64)
                    } else {
                        text.clone()
                    };
                    Some((task, text))
                })
                .collect();
            class.insert(copy_name.clone(), copied);
            let tasks = compare_class(corpus, &class, options);
            let (a, b) = if *original < copy_name {
                (original.clone(), copy_name.clone())
            } else {
                (copy_name.clone(), original.clone())
            };
            for t in &tasks {
                let task = task_names()
                    .into_iter()
                    .find(|&n| n == t.task)
                    .unwrap_or("");
                if !solved(original, task) {
                    continue;
                }
                let pair = t.pairs.iter().find(|p| p.a == a && p.b == b);
                let found = pair.is_some_and(|p| p.flagged);
                if LONG_TASKS.contains(&task) {
                    let (score, shared) = pair.map_or((0.0, 0), |p| (p.score, p.shared));
                    if std::env::var("SHOW_LOW").is_ok() && score < 0.6 {
                        println!("low: {how:?} {original} {task} {score:.2} {shared}");
                    }
                    outcome.long_task_copy_mean.0 += score;
                    outcome.long_task_copy_mean.1 += 1;
                    let min = &mut outcome.long_task_copy_min;
                    *min = (min.0.min(score), min.1.min(shared));
                }
                let count = |entry: &mut (usize, usize)| {
                    entry.0 += usize::from(found);
                    entry.1 += 1;
                };
                count(outcome.any_task_found.entry(how).or_default());
                count(outcome.per_task_found.entry(task).or_default());
                if LONG_TASKS.contains(&task) {
                    count(outcome.long_task_found.entry(how).or_default());
                }
            }
            let ranked = rank(&tasks, options);
            let pair = ranked.iter().find(|p| p.a == a && p.b == b);
            let entry = outcome.aggregate_found.entry(how).or_default();
            entry.0 += usize::from(pair.is_some_and(|p| p.flagged));
            entry.1 += 1;
            let score = pair.map_or(0.0, |p| p.score);
            outcome.aggregate_copy_min = outcome.aggregate_copy_min.min(score);
        }
    }
    outcome
}

fn share((found, of): (usize, usize)) -> f64 {
    if of == 0 {
        1.0
    } else {
        found as f64 / of as f64
    }
}

fn print_outcome(outcome: &Outcome) {
    println!("planted copies flagged (long tasks / all tasks / whole submission):");
    for how in Disguise::ALL {
        let get = |m: &BTreeMap<Disguise, (usize, usize)>| m.get(&how).copied().unwrap_or_default();
        let (l, t, a) = (
            get(&outcome.long_task_found),
            get(&outcome.any_task_found),
            get(&outcome.aggregate_found),
        );
        println!("  {how:?}: {}/{} {}/{} {}/{}", l.0, l.1, t.0, t.1, a.0, a.1);
    }
    println!("per task (all disguises), highest independent score:");
    for task in task_names() {
        let (f, n) = outcome
            .per_task_found
            .get(task)
            .copied()
            .unwrap_or_default();
        let max = outcome
            .independent_task_max
            .get(task)
            .copied()
            .unwrap_or(0.0);
        println!("  {task}: {f}/{n}, independent max {max:.2}");
    }
    println!(
        "long-task copies: lowest score {:.2}, fewest shared {}; independent task pairs: most \
         shared {}",
        outcome.long_task_copy_min.0,
        outcome.long_task_copy_min.1,
        outcome.independent_task_max_shared
    );
    println!(
        "independent: tasks {}/{} flagged (max {:.2}), submissions {}/{} (max {:.2}); \
         lowest copied submission {:.2}",
        outcome.independent_task.0,
        outcome.independent_task.1,
        outcome.independent_task.2,
        outcome.independent_aggregate.0,
        outcome.independent_aggregate.1,
        outcome.independent_aggregate.2,
        outcome.aggregate_copy_min
    );
}

#[test]
fn the_defaults_find_planted_copies_and_leave_independent_code_alone() {
    let corpus = corpus();
    // The class here has five students, so the common-code filter drops whatever three of
    // them share; in a large class, code that a few independent students share survives
    // it. Without the filter is the worst case for independent pairs.
    let without_filter = Options {
        common_share: 1.0,
        ..Options::default()
    };
    for (name, options) in [
        ("defaults", Options::default()),
        ("no common filter", without_filter),
    ] {
        println!("== {name}");
        let outcome = measure(&corpus, &options);
        print_outcome(&outcome);
        for how in Disguise::ALL {
            let aggregate = outcome
                .aggregate_found
                .get(&how)
                .copied()
                .unwrap_or_default();
            assert!(
                share(aggregate) >= 0.95,
                "{name}, {how:?}: whole copies {aggregate:?}"
            );
            let long = outcome
                .long_task_found
                .get(&how)
                .copied()
                .unwrap_or_default();
            assert!(share(long) >= 0.95, "{name}, {how:?}: long tasks {long:?}");
        }
        assert_eq!(
            outcome.independent_aggregate.0, 0,
            "{name}: independent submissions"
        );
        assert_eq!(
            outcome.independent_task.0, 0,
            "{name}: independent task pairs"
        );
    }
}

/// `pbrlab similarity` on a class folder: the disguised copy of a whole submission is
/// flagged and ranked first, the independent students are not, and the page shows the
/// matched files side by side with the students' code escaped.
#[test]
fn the_command_flags_a_disguised_copy_and_writes_the_page() {
    let corpus = corpus();
    let dir = tempfile::tempdir().unwrap();
    let class = dir.path().join("submissions");
    let write = |student: &str, files: &BTreeMap<&'static str, String>| {
        let folder = class.join(student).join("exercises");
        std::fs::create_dir_all(&folder).unwrap();
        for (task, text) in files {
            std::fs::write(folder.join(format!("{task}.rs")), text).unwrap();
        }
    };
    for (student, files) in &corpus.students {
        write(student, files);
    }
    let copied: BTreeMap<&'static str, String> = corpus.students["alt2"]
        .iter()
        .map(|(task, text)| {
            let text = disguise(text, Disguise::ALL[Disguise::ALL.len() - 1], 7);
            (
                *task,
                format!("{text}\n// </pre><script>alert(1)</script>\n"),
            )
        })
        .collect();
    write("zed", &copied);
    let out = dir.path().join("report");
    let output = std::process::Command::new(env!("CARGO_BIN_EXE_pbrlab"))
        .arg("similarity")
        .arg(&class)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(
        output.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let pairs: Vec<&str> = stdout.lines().filter(|l| l.contains(" ~ ")).collect();
    assert!(
        pairs[0].contains("alt2 ~ zed") && pairs[0].contains("FLAGGED"),
        "{stdout}"
    );
    assert!(
        pairs[1..].iter().all(|l| !l.contains("FLAGGED")),
        "only the copy: {stdout}"
    );
    assert!(
        stdout.contains("1 pairs flagged over all tasks"),
        "{stdout}"
    );
    let page = std::fs::read_to_string(out.join("similarity.html")).unwrap();
    assert!(
        page.contains("zed") && page.contains("alt2"),
        "the pair is on the page"
    );
    assert!(!page.contains("<script>alert"), "student code is escaped");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("similarity.json")).unwrap())
            .unwrap();
    assert_eq!(json["flagged"][0]["b"], "zed", "{json}");
}
