//! One task: fingerprints of every file, the exclusions, and the score of every pair.

use super::normalise::normalise;
use super::regions::{by_hash, regions};
use super::tokens::raw_tokens_all;
use super::winnow::{Fingerprint, fingerprints, kgram_hashes};
use super::{Options, PairScore, Source, TaskComparison};
use std::collections::{BTreeMap, HashMap, HashSet};

/// One student's file, fingerprinted.
struct Fingerprinted<'a> {
    student: &'a str,
    /// The winnowed fingerprints left after the exclusions, by hash (as `regions` needs
    /// them).
    prints: Vec<Fingerprint>,
    /// The distinct hashes of `prints`.
    distinct: HashSet<u64>,
    fallback: bool,
}

/// Compares the files of one task, pair by pair.
///
/// `files` holds one file per student (a name that repeats keeps its first file only).
/// `exclude` holds texts whose code is not evidence: the task's shipped stub, and the
/// reference solution if the caller wants copies of it ignored; every k-gram of them is
/// excluded, wherever it occurs. Never panics, whatever the texts hold.
pub fn compare_task(
    task: &str,
    files: &[Source],
    exclude: &[&str],
    options: &Options,
) -> TaskComparison {
    let mode = options.normalisation;
    let k = options.k.max(1);
    let w = options.window.max(1);
    let mut by_student: BTreeMap<&str, &Source> = BTreeMap::new();
    for file in files {
        by_student.entry(file.student.as_str()).or_insert(file);
    }
    let texts: Vec<&str> = exclude
        .iter()
        .copied()
        .chain(by_student.values().map(|f| f.text.as_str()))
        .collect();
    let mut lexed = raw_tokens_all(&texts).into_iter();
    let excluded: HashSet<u64> = lexed
        .by_ref()
        .take(exclude.len())
        .flat_map(|(raw, _)| kgram_hashes(&normalise(&raw, mode), k, mode.number_locals))
        .collect();
    let mut files: Vec<Fingerprinted> = by_student
        .into_values()
        .zip(lexed)
        .map(|(file, (raw, fallback))| {
            let mut prints = fingerprints(&normalise(&raw, mode), k, w, mode.number_locals);
            prints.retain(|p| !excluded.contains(&p.hash));
            Fingerprinted {
                student: &file.student,
                distinct: prints.iter().map(|p| p.hash).collect(),
                prints: by_hash(prints),
                fallback,
            }
        })
        .collect();

    // Common code: fingerprints in more files than the limit.
    let common_limit = common_limit(files.len(), options);
    let mut files_with: HashMap<u64, Vec<usize>> = HashMap::new();
    for (i, file) in files.iter().enumerate() {
        for &hash in &file.distinct {
            files_with.entry(hash).or_default().push(i);
        }
    }
    files_with.retain(|_, holders| holders.len() <= common_limit);
    let common: HashSet<u64> = files
        .iter()
        .flat_map(|f| f.distinct.iter().copied())
        .filter(|h| !files_with.contains_key(h))
        .collect();
    for file in &mut files {
        file.prints.retain(|p| !common.contains(&p.hash));
        file.distinct.retain(|h| !common.contains(h));
    }

    let mut shared: HashMap<(usize, usize), usize> = HashMap::new();
    for holders in files_with.values() {
        for (n, &i) in holders.iter().enumerate() {
            for &j in holders.iter().skip(n + 1) {
                *shared.entry((i.min(j), i.max(j))).or_default() += 1;
            }
        }
    }
    let mut pairs: Vec<PairScore> = shared
        .into_iter()
        .filter_map(|((i, j), count)| {
            let (fa, fb) = (files.get(i)?, files.get(j)?);
            let smaller = fa.distinct.len().min(fb.distinct.len());
            let score = if smaller == 0 {
                0.0
            } else {
                count as f64 / smaller as f64
            };
            Some(PairScore {
                a: fa.student.to_string(),
                b: fb.student.to_string(),
                shared: count,
                score,
                flagged: score >= options.min_score && count >= options.min_shared,
                regions: regions(&fa.prints, &fb.prints, k, w),
            })
        })
        .collect();
    pairs.sort_by(|x, y| {
        y.score
            .total_cmp(&x.score)
            .then(y.shared.cmp(&x.shared))
            .then_with(|| (&x.a, &x.b).cmp(&(&y.a, &y.b)))
    });

    TaskComparison {
        task: task.to_string(),
        pairs,
        fingerprints: files
            .iter()
            .map(|f| (f.student.to_string(), f.distinct.len()))
            .collect(),
        common_limit,
        common_fingerprints: common.len(),
        fallback_lexed: files
            .iter()
            .filter(|f| f.fallback)
            .map(|f| f.student.to_string())
            .collect(),
    }
}

/// The most files a fingerprint may be in and still count: `common_share` of the class
/// (and at most `common_max_files`), but never fewer than 2.
fn common_limit(files: usize, options: &Options) -> usize {
    let share = if options.common_share.is_nan() {
        1.0
    } else {
        options.common_share.clamp(0.0, 1.0)
    };
    // In [0, files]: the cast cannot overflow.
    let mut limit = (share * files as f64).floor() as usize;
    if let Some(max) = options.common_max_files {
        limit = limit.min(max);
    }
    limit.max(2)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_common_limit_never_drops_a_pair() {
        let options = Options::default();
        assert_eq!(common_limit(0, &options), 2);
        assert_eq!(common_limit(3, &options), 2);
        assert_eq!(common_limit(30, &options), 15);
        let absolute = Options {
            common_max_files: Some(10),
            ..options
        };
        assert_eq!(common_limit(100, &absolute), 10);
    }
}
