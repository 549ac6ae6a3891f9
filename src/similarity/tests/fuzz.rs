//! Garbage in, no panic out: random bytes, random Rust-like token soup and mangled real
//! files through the tokenisers, the comparison, the ranking and the report.

use super::super::lexer::lex;
use super::super::tokens::raw_tokens;
use super::super::*;
use super::{SOLVED, STUB, source};
use std::collections::BTreeMap;

/// A small deterministic generator (xorshift64*), so a failure can be replayed.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

const PIECES: &[&str] = &[
    "fn",
    " ",
    "\n",
    "{",
    "}",
    "(",
    ")",
    "[",
    "]",
    "'",
    "\"",
    "r#\"",
    "\"#",
    "b'",
    "/*",
    "*/",
    "//",
    "///",
    "//!",
    "#[doc = ",
    "#![",
    "::",
    ".",
    "..",
    "0.5e-3",
    "1.",
    "0x",
    "let",
    "x",
    "θ",
    "·",
    "\\",
    "é",
    "\u{0}",
    "\r\n",
    "\t",
    "'a",
    "'\\''",
    "r",
    "b",
    "c\"",
    "</script>",
    "<",
    ">",
    "&",
    "!",
    "=>",
    "|",
    "_",
    "r#type",
    "\u{feff}",
    "\u{202e}",
];

fn garbage(rng: &mut Rng) -> String {
    match rng.below(3) {
        0 => {
            let bytes: Vec<u8> = (0..rng.below(300)).map(|_| rng.next() as u8).collect();
            String::from_utf8_lossy(&bytes).into_owned()
        }
        1 => (0..rng.below(200))
            .map(|_| PIECES[rng.below(PIECES.len())])
            .collect(),
        _ => {
            // A real file, cut and with pieces inserted.
            let mut text: Vec<char> = SOLVED.chars().collect();
            for _ in 0..rng.below(6) {
                let at = rng.below(text.len() + 1);
                if rng.below(2) == 0 && at < text.len() {
                    text.remove(at);
                } else {
                    let piece = PIECES[rng.below(PIECES.len())];
                    for (k, c) in piece.chars().enumerate() {
                        text.insert((at + k).min(text.len()), c);
                    }
                }
            }
            text.truncate(rng.below(text.len() + 1));
            text.into_iter().collect()
        }
    }
}

#[test]
fn garbage_never_panics() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let options = Options {
        k: 3,
        window: 2,
        min_shared: 1,
        aggregate_min_shared: 1,
        ..Options::default()
    };
    for round in 0..3000 {
        let texts: Vec<String> = (0..4).map(|_| garbage(&mut rng)).collect();
        for text in &texts {
            let lexemes = lex(text);
            assert!(
                lexemes
                    .iter()
                    .all(|l| l.start <= l.end && l.end <= text.len())
            );
            let _ = raw_tokens(text);
        }
        let files: Vec<Source> = texts
            .iter()
            .enumerate()
            .map(|(i, t)| source(&format!("s{}", i % 3), t))
            .chain([source("solved", SOLVED)])
            .collect();
        let exclude = [STUB, texts[0].as_str()];
        let task = compare_task("t", &files, &exclude, &options);
        for pair in &task.pairs {
            assert!((0.0..=1.0).contains(&pair.score), "round {round}: {pair:?}");
            for r in &pair.regions {
                assert!(r.a_lines.0 <= r.a_lines.1 && r.b_lines.0 <= r.b_lines.1);
            }
        }
        if round % 50 == 0 {
            let tasks = [task];
            let ranked = rank(&tasks, &options);
            let sources: BTreeMap<(String, String), String> = files
                .iter()
                .map(|f| (("t".to_string(), f.student.clone()), f.text.clone()))
                .collect();
            let page = html(&ranked, &tasks, &sources);
            assert!(!page.contains("</script>"));
        }
    }
}

#[test]
fn deep_nesting_and_odd_options_do_not_panic() {
    let deep = format!("{}{}", "(".repeat(200_000), ")".repeat(200_000));
    let unbalanced = "{[(".repeat(50_000);
    let files = [
        source("a", &deep),
        source("b", &unbalanced),
        source("c", ""),
    ];
    for options in [
        Options::default(),
        Options {
            k: 0,
            window: 0,
            common_share: f64::NAN,
            common_max_files: Some(0),
            min_score: f64::NAN,
            ..Options::default()
        },
        Options {
            k: usize::MAX,
            window: usize::MAX,
            common_share: -1.0,
            ..Options::default()
        },
    ] {
        let task = compare_task("t", &files, &[&deep], &options);
        let _ = rank(&[task], &options);
    }
}
