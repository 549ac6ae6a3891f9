//! Fingerprints of a token list: hashes of all k-grams, of which winnowing keeps a few
//! (Schleimer, Wilkerson and Aiken, "Winnowing: local algorithms for document
//! fingerprinting", SIGMOD 2003).
//!
//! Winnowing keeps, in every window of `w` consecutive k-gram hashes, the smallest. That
//! guarantees that any run of at least `w + k − 1` tokens two files share yields at least
//! one shared fingerprint, and no match shorter than `k` tokens yields any, while keeping
//! about `2 / (w + 1)` of the hashes. The *robust* variant breaks ties by keeping the hash
//! already chosen for the previous window, so long runs of equal hashes (repeated
//! statements) do not produce a fingerprint per window.

use super::normalise::{Symbol, Token};

/// One kept k-gram hash and where its k-gram is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Fingerprint {
    /// The k-gram's hash.
    pub hash: u64,
    /// Index of the k-gram's first token in the file's token list.
    pub first_token: usize,
    /// The 1-based lines of its first and last token.
    pub lines: (usize, usize),
}

/// The hash of every k-gram of `tokens` (none if there are fewer than `k` tokens).
///
/// With `number_locals`, each [`Symbol::Local`] is hashed as the index of its first
/// occurrence within the k-gram, so the hash does not depend on the names themselves and a
/// consistent renaming keeps it; otherwise every local is the same placeholder.
pub(crate) fn kgram_hashes(tokens: &[Token], k: usize, number_locals: bool) -> Vec<u64> {
    let k = k.max(1);
    if tokens.len() < k {
        return Vec::new();
    }
    let mut locals: Vec<u64> = Vec::with_capacity(k);
    tokens
        .windows(k)
        .map(|gram| {
            locals.clear();
            let mut h: u64 = 0x9e37_79b9_7f4a_7c15;
            for token in gram {
                let value = match token.symbol {
                    Symbol::Fixed(v) => v,
                    Symbol::Local(name) => {
                        let index = if number_locals {
                            locals.iter().position(|&n| n == name).unwrap_or_else(|| {
                                locals.push(name);
                                locals.len() - 1
                            })
                        } else {
                            0
                        };
                        0x4c6f_6361_6c00_0000 ^ index as u64
                    }
                };
                h = mix(h ^ value);
            }
            h
        })
        .collect()
}

/// Robust winnowing of `hashes` with window `w`: the indices of the kept hashes, ascending.
/// A list shorter than one window keeps its minimum.
pub(crate) fn winnow(hashes: &[u64], w: usize) -> Vec<usize> {
    let w = w.max(1);
    if hashes.is_empty() {
        return Vec::new();
    }
    let windows = hashes.len().saturating_sub(w) + 1;
    let mut kept = Vec::new();
    let mut last: Option<(usize, u64)> = None;
    for start in 0..windows {
        let window = hashes
            .get(start..start.saturating_add(w).min(hashes.len()))
            .unwrap_or(&[]);
        // The rightmost minimum of the window.
        let Some((offset, &min)) = window
            .iter()
            .enumerate()
            .min_by(|(i, a), (j, b)| a.cmp(b).then(j.cmp(i)))
        else {
            continue;
        };
        match last {
            Some((previous, hash)) if previous >= start && hash == min => {}
            _ => {
                kept.push(start + offset);
                last = Some((start + offset, min));
            }
        }
    }
    kept
}

/// The winnowed fingerprints of `tokens`, with their k-grams' lines.
pub(crate) fn fingerprints(
    tokens: &[Token],
    k: usize,
    w: usize,
    number_locals: bool,
) -> Vec<Fingerprint> {
    let k = k.max(1);
    let hashes = kgram_hashes(tokens, k, number_locals);
    winnow(&hashes, w)
        .into_iter()
        .filter_map(|i| {
            let first = tokens.get(i)?.line;
            let last = tokens.get(i.checked_add(k - 1)?)?.line;
            Some(Fingerprint {
                hash: *hashes.get(i)?,
                first_token: i,
                lines: (first.min(last), first.max(last)),
            })
        })
        .collect()
}

/// A 64-bit finaliser (SplitMix64): every input bit affects every output bit, so the
/// minimum of a window is a fair sample.
fn mix(mut x: u64) -> u64 {
    x = (x ^ (x >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    x = (x ^ (x >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    x ^ (x >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn winnowing_keeps_a_hash_in_every_window() {
        let hashes: Vec<u64> = (0..200u64).map(|i| mix(i % 37)).collect();
        for w in 1..8 {
            let kept = winnow(&hashes, w);
            for start in 0..=hashes.len() - w {
                assert!(kept.iter().any(|&i| (start..start + w).contains(&i)));
            }
        }
    }

    #[test]
    fn robust_winnowing_keeps_one_of_a_run_of_equal_hashes() {
        assert_eq!(winnow(&[5, 1, 1, 1, 1, 1, 1, 9], 3), vec![2, 5]);
        assert_eq!(winnow(&[3, 2], 4), vec![1]);
        assert!(winnow(&[], 4).is_empty());
    }

    #[test]
    fn local_numbering_ignores_names_but_not_their_pattern() {
        let t = |symbols: &[Symbol]| -> Vec<Token> {
            symbols
                .iter()
                .map(|&symbol| Token { symbol, line: 1 })
                .collect()
        };
        let (a, b, c, plus) = (
            Symbol::Local(1),
            Symbol::Local(2),
            Symbol::Local(3),
            Symbol::Fixed(9),
        );
        let aab = kgram_hashes(&t(&[a, plus, a, plus, b]), 5, true);
        let ccb = kgram_hashes(&t(&[c, plus, c, plus, a]), 5, true);
        let abc = kgram_hashes(&t(&[a, plus, b, plus, c]), 5, true);
        assert_eq!(aab, ccb);
        assert_ne!(aab, abc);
        assert_eq!(
            kgram_hashes(&t(&[a, plus, a, plus, b]), 5, false),
            kgram_hashes(&t(&[a, plus, b, plus, c]), 5, false)
        );
    }
}
