//! Tests of the whole comparison: robustness on garbage (`fuzz`) and the report. The
//! measurement on a generated class of planted copies and independent solutions is an
//! instructor test (`tests/instructor/similarity/`): its fixtures are solutions.

mod fuzz;

use super::*;

fn source(student: &str, text: &str) -> Source {
    Source {
        student: student.to_string(),
        text: text.to_string(),
    }
}

const STUB: &str = "//! Task docs.\nuse crate::prelude::*;\n\n/// Docs.\n\
                    pub fn area(w: f32, h: f32) -> f32 {\n    todo!()\n}\n";

const SOLVED: &str = "use crate::prelude::*;\n\npub fn area(w: f32, h: f32) -> f32 {\n    \
                      let mut total = 0.0;\n    for row in 0..(h as usize) {\n        \
                      let width = w * scale(row);\n        total += width.max(0.0);\n        \
                      if total > LIMIT { return LIMIT; }\n    }\n    total.min(w * h)\n}\n\n\
                      const LIMIT: f32 = 1e6;\n\nfn scale(row: usize) -> f32 {\n    \
                      (row as f32 * 0.5).sin().abs() + 1.0\n}\n";

#[test]
fn a_renamed_reformatted_copy_matches_and_the_stub_does_not() {
    let copy = "use crate::prelude::*;\npub fn area(breadth: f32, height: f32) -> f32\n{\n\
                let mut acc = 0.0;\n// loop\nfor r in 0..(height as usize) { let b = breadth * \
                factor(r); acc += b.max(0.0); if acc > CAP { return CAP; } }\nacc.min(breadth * \
                height)\n}\nconst CAP: f32 = 2e6;\nfn factor(i: usize) -> f32 { (i as f32 * 0.5)\
                .sin().abs() + 1.0 }\n";
    let files = [
        source("alice", SOLVED),
        source("bob", copy),
        source("carol", STUB),
    ];
    let options = Options {
        min_shared: 1,
        ..Options::default()
    };
    let result = compare_task("area", &files, &[STUB], &options);
    assert_eq!(result.fingerprints.get("carol"), Some(&0));
    let pair = result.pairs.first().expect("a pair");
    assert_eq!((pair.a.as_str(), pair.b.as_str()), ("alice", "bob"));
    assert!(pair.score > 0.9, "{pair:?}");
    assert!(pair.flagged);
    assert_eq!(result.pairs.len(), 1, "the stub shares nothing");
    // Regions lie inside the files.
    for r in &pair.regions {
        assert!(1 <= r.a_lines.0 && r.a_lines.0 <= r.a_lines.1 && r.a_lines.1 <= 17);
        assert!(1 <= r.b_lines.0 && r.b_lines.0 <= r.b_lines.1 && r.b_lines.1 <= 11);
    }
}

#[test]
fn code_every_file_shares_is_not_evidence() {
    let files: Vec<Source> = ["a", "b", "c", "d", "e"]
        .iter()
        .map(|s| source(s, SOLVED))
        .collect();
    let result = compare_task("area", &files, &[], &Options::default());
    assert!(result.pairs.is_empty());
    assert!(result.common_fingerprints > 0);
    assert_eq!(result.common_limit, 2);
    assert!(result.fingerprints.values().all(|&n| n == 0));
}

#[test]
fn rank_sums_over_tasks_and_html_escapes_everything() {
    let evil_name = "<script>alert(1)</script>";
    let evil_code = format!("{SOLVED}\n// </pre></script><img src=x onerror=alert(1)>\n");
    let files = [
        source(evil_name, &evil_code),
        source("bob\"'&", SOLVED),
        source("carol", STUB),
    ];
    let options = Options {
        min_shared: 1,
        aggregate_min_shared: 1,
        ..Options::default()
    };
    let tasks = vec![
        compare_task("area", &files, &[STUB], &options),
        compare_task("<b>task</b>", &files, &[STUB], &options),
    ];
    let ranked = rank(&tasks, &options);
    let top = ranked.first().expect("a pair");
    assert_eq!(top.tasks.len(), 2);
    assert!(top.flagged && top.flagged_tasks == 2);
    assert_eq!(
        top.shared,
        tasks.iter().map(|t| t.pairs[0].shared).sum::<usize>()
    );
    let mut sources = BTreeMap::new();
    for task in ["area", "<b>task</b>"] {
        for f in &files {
            sources.insert((task.to_string(), f.student.clone()), f.text.clone());
        }
    }
    let page = html(&ranked, &tasks, &sources);
    assert!(!page.contains("<script"), "no script element");
    assert!(!page.contains("<img"));
    assert!(!page.contains("<b>task"));
    assert!(!page.contains("bob\"'&"));
    assert!(page.contains("&lt;script&gt;alert(1)&lt;/script&gt;"));
    assert!(page.contains("class=\"l m0\""), "highlighted lines");
    // The page is well nested: every section closed.
    assert_eq!(
        page.matches("<section").count(),
        page.matches("</section>").count()
    );
    // JSON for the command line.
    let json = serde_json::to_string(&(&tasks, &ranked)).expect("serialisable");
    assert!(json.contains("\"a_lines\""));
}
