//! A bounded mutation fuzz of the scene loader: every shipped scene, mutated many times
//! (numbers replaced by extreme values, text or quotes; lines deleted, duplicated or
//! swapped; the file cut short), must load or fail with an error naming the file: no
//! panic, no hang. The mutations come from a fixed seed, so a failure reproduces; the
//! message prints the mutated scene.

use pbrlab::sampling::Sampler;
use pbrlab::scene::{LoadOptions, Scene};
use std::path::{Path, PathBuf};
use std::sync::mpsc;
use std::time::Duration;

/// Values a number in a scene is replaced by: zeros, signs, f32 limits and beyond, NaN,
/// infinities, text, quoted numbers, huge counts.
const EXTREMES: &[&str] = &[
    "0",
    "-0",
    "-1",
    "1e-38",
    "1e8",
    "3e38",
    "-3e38",
    "1e39",
    ".nan",
    ".inf",
    "-.inf",
    "\"0.5\"",
    "x",
    "[]",
    "{}",
    "65536",
    "4294967296",
    "-7",
    "0.0000001",
    "1e6",
];

/// The byte ranges of the numbers in `text`.
fn numbers(text: &str) -> Vec<(usize, usize)> {
    let bytes = text.as_bytes();
    let mut spans = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let starts = bytes[i].is_ascii_digit()
            && (i == 0 || !(bytes[i - 1].is_ascii_alphanumeric() || bytes[i - 1] == b'_'));
        if starts {
            let start = if i > 0 && bytes[i - 1] == b'-' {
                i - 1
            } else {
                i
            };
            let mut end = i;
            while end < bytes.len()
                && (bytes[end].is_ascii_digit() || b".eE-".contains(&bytes[end]))
            {
                end += 1;
            }
            spans.push((start, end));
            i = end;
        } else {
            i += 1;
        }
    }
    spans
}

/// One mutant of `text`, chosen by `sampler`.
fn mutate(text: &str, sampler: &mut Sampler) -> String {
    let pick =
        |sampler: &mut Sampler, n: usize| ((sampler.next_1d() * n as f32) as usize).min(n - 1);
    let lines: Vec<&str> = text.lines().collect();
    if lines.is_empty() {
        return text.to_string();
    }
    match pick(sampler, 5) {
        0 | 1 => {
            let spans = numbers(text);
            if spans.is_empty() {
                return text.to_string();
            }
            let (start, end) = spans[pick(sampler, spans.len())];
            let value = EXTREMES[pick(sampler, EXTREMES.len())];
            format!("{}{value}{}", &text[..start], &text[end..])
        }
        2 => {
            let mut kept = lines.clone();
            kept.remove(pick(sampler, lines.len()));
            kept.join("\n")
        }
        3 => {
            let mut more = lines.clone();
            let i = pick(sampler, lines.len());
            more.insert(i, lines[i]);
            let (a, b) = (pick(sampler, more.len()), pick(sampler, more.len()));
            more.swap(a, b);
            more.join("\n")
        }
        _ => {
            let mut cut = pick(sampler, text.len());
            while !text.is_char_boundary(cut) {
                cut -= 1;
            }
            text[..cut].to_string()
        }
    }
}

/// The shipped scenes, with their text.
fn scenes() -> Vec<(PathBuf, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut scenes: Vec<(PathBuf, String)> = std::fs::read_dir(&dir)
        .expect("scenes/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .map(|p| {
            let text = std::fs::read_to_string(&p).expect("readable");
            (p, text)
        })
        .collect();
    scenes.sort();
    scenes
}

/// What the fuzzing thread reports.
enum Report {
    /// About to load this mutant.
    Loading(String),
    /// A mutant broke the loader.
    Broken(String),
    /// All done; this many mutants loaded.
    Done(usize),
}

/// Loads `mutants` mutants of every shipped scene, each applied to the previous one with
/// probability ½ (so mutations pile up), on a thread; each load may take at most `limit`.
fn fuzz(mutants: usize, limit: Duration) {
    let (tx, rx) = mpsc::channel::<Report>();
    std::thread::spawn(move || {
        let options = LoadOptions {
            width: Some(8),
            height: Some(8),
            ..LoadOptions::default()
        };
        let mut sampler = Sampler::new(0xf022, 0);
        let mut loaded = 0;
        for (path, original) in scenes() {
            let mut text = original.clone();
            for _ in 0..mutants {
                if sampler.next_1d() < 0.5 {
                    text = original.clone();
                }
                text = mutate(&text, &mut sampler);
                let _ = tx.send(Report::Loading(text.clone()));
                let outcome = std::panic::catch_unwind(|| Scene::from_yaml(&path, &text, &options));
                match outcome {
                    Ok(Ok(_)) => loaded += 1,
                    Ok(Err(e)) => {
                        if e.file.as_os_str().is_empty() || e.message.trim().is_empty() {
                            let message =
                                format!("an error without file or message: {e:?}\n{text}");
                            let _ = tx.send(Report::Broken(message));
                            return;
                        }
                    }
                    Err(_) => {
                        let message = format!(
                            "the loader panicked on this mutant of {}:\n{text}",
                            path.display()
                        );
                        let _ = tx.send(Report::Broken(message));
                        return;
                    }
                }
            }
        }
        let _ = tx.send(Report::Done(loaded));
    });
    let mut last = String::new();
    loop {
        match rx.recv_timeout(limit) {
            Ok(Report::Loading(text)) => last = text,
            Ok(Report::Done(loaded)) => {
                // The mutations must leave some scenes loadable, or they test only the parser.
                assert!(loaded > mutants / 10, "only {loaded} mutants loaded");
                return;
            }
            Ok(Report::Broken(message)) => panic!("{message}"),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                panic!("this mutant did not load within {limit:?} (a hang?):\n{last}")
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                panic!("the fuzzing thread died (see its panic above) at:\n{last}")
            }
        }
    }
}

#[test]
fn mutated_scenes_load_or_fail_with_an_error_and_never_crash() {
    fuzz(300, Duration::from_secs(60));
}

#[test]
#[ignore = "slow: the fuzz at its CI budget"]
fn mutated_scenes_load_or_fail_with_an_error_and_never_crash_at_scale() {
    fuzz(1500, Duration::from_secs(60));
}
