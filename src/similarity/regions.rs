//! The matched regions of two files: their shared fingerprints, chained into runs that
//! stay on one diagonal (the same offset between A and B, as copied text does), then merged
//! into line ranges, each A range paired with the B range it matches.

use super::Region;
use super::winnow::Fingerprint;

/// How many occurrences of one hash in each file are paired up: repeated code (the same
/// guard five times) would otherwise pair every copy with every other.
const MAX_OCCURRENCES: usize = 4;

/// How many of the most recent runs a match may extend (they come in A's order, so an old
/// run is far behind in A; this bounds the work on long files with many runs).
const RECENT_CHAINS: usize = 16;

/// One shared fingerprint, placed in both files.
#[derive(Clone, Copy, Debug)]
struct Match {
    a_token: usize,
    b_token: usize,
    a_lines: (usize, usize),
    b_lines: (usize, usize),
}

/// A run of matches on (nearly) one diagonal.
#[derive(Clone, Copy, Debug)]
struct Chain {
    last_a: usize,
    last_b: usize,
    region: Region,
    /// How many matches it holds.
    matches: usize,
}

/// A region and the number of matches it holds.
type Counted = (Region, usize);

/// The regions A and B share, given the fingerprints of each that the comparison kept
/// (shared or not), each list sorted by hash, then position ([`by_hash`]), for k-grams of
/// `k` tokens winnowed with window `w`. Sorted by A's lines.
pub(crate) fn regions(a: &[Fingerprint], b: &[Fingerprint], k: usize, w: usize) -> Vec<Region> {
    // A merge join of the two sorted lists: no allocation per hash, linear in their sizes.
    let mut matches = Vec::new();
    let (mut i, mut j) = (0, 0);
    while let (Some(pa), Some(pb)) = (a.get(i), b.get(j)) {
        if pa.hash != pb.hash {
            if pa.hash < pb.hash {
                i += 1;
            } else {
                j += 1;
            }
            continue;
        }
        let hash = pa.hash;
        let a_end = i + a
            .get(i..)
            .map_or(0, |r| r.iter().take_while(|p| p.hash == hash).count());
        let b_end = j + b
            .get(j..)
            .map_or(0, |r| r.iter().take_while(|p| p.hash == hash).count());
        let a_group = a.get(i..a_end).unwrap_or(&[]);
        let b_group = b.get(j..b_end).unwrap_or(&[]);
        for pa in a_group.iter().take(MAX_OCCURRENCES) {
            matches.extend(b_group.iter().take(MAX_OCCURRENCES).map(|pb| Match {
                a_token: pa.first_token,
                b_token: pb.first_token,
                a_lines: pa.lines,
                b_lines: pb.lines,
            }));
        }
        (i, j) = (a_end, b_end);
    }
    matches.sort_by_key(|m| (m.a_token, m.b_token));

    // Within a shared run, consecutive fingerprints are at most `w` k-grams apart; a changed
    // token in a copy breaks `k` k-grams. A step of up to `k + w` tokens on both sides, with
    // the diagonal moving by at most `k` (a few inserted or removed tokens), stays in a run.
    let gap = k.saturating_add(w);
    let mut chains: Vec<Chain> = Vec::new();
    for m in matches {
        // Only recent chains can continue: matches come in A's order.
        let joins = chains.iter_mut().rev().take(RECENT_CHAINS).find(|c| {
            let da = m.a_token.abs_diff(c.last_a);
            let db = m.b_token.abs_diff(c.last_b);
            m.a_token >= c.last_a && m.b_token >= c.last_b && da <= gap && da.abs_diff(db) <= k
        });
        match joins {
            Some(chain) => {
                chain.last_a = m.a_token;
                chain.last_b = m.b_token;
                chain.region = union(chain.region, region_of(&m));
                chain.matches += 1;
            }
            None => chains.push(Chain {
                last_a: m.a_token,
                last_b: m.b_token,
                region: region_of(&m),
                matches: 1,
            }),
        }
    }
    let merged = merge_overlapping(chains.into_iter().map(|c| (c.region, c.matches)).collect());
    without_echoes(merged)
}

/// Drops the echoes of repeated code: a region of one or two matches whose lines in A lie
/// inside a larger region and whose lines in B lie inside another (a guard that occurs
/// twice in both files pairs each occurrence with both, and only the pairs on the copied
/// runs mean anything).
fn without_echoes(regions: Vec<Counted>) -> Vec<Region> {
    let inside = |x: (usize, usize), y: (usize, usize)| y.0 <= x.0 && x.1 <= y.1;
    regions
        .iter()
        .filter(|&&(r, n)| {
            let bigger = |pick: fn(&Region) -> (usize, usize)| {
                regions
                    .iter()
                    .any(|(o, m)| *m > n && *o != r && inside(pick(&r), pick(o)))
            };
            n > 2 || !(bigger(|r| r.a_lines) && bigger(|r| r.b_lines))
        })
        .map(|&(r, _)| r)
        .collect()
}

/// `prints` sorted as [`regions`] needs them: by hash, then position.
pub(crate) fn by_hash(mut prints: Vec<Fingerprint>) -> Vec<Fingerprint> {
    prints.sort_by_key(|p| (p.hash, p.first_token));
    prints
}

fn region_of(m: &Match) -> Region {
    Region {
        a_lines: m.a_lines,
        b_lines: m.b_lines,
    }
}

fn union(x: Region, y: Region) -> Region {
    Region {
        a_lines: (x.a_lines.0.min(y.a_lines.0), x.a_lines.1.max(y.a_lines.1)),
        b_lines: (x.b_lines.0.min(y.b_lines.0), x.b_lines.1.max(y.b_lines.1)),
    }
}

/// Whether two line ranges overlap or touch.
fn touch(x: (usize, usize), y: (usize, usize)) -> bool {
    x.0 <= y.1.saturating_add(1) && y.0 <= x.1.saturating_add(1)
}

/// Merges regions that overlap (or touch) in both files until none do, sorted by A's
/// lines, then B's.
fn merge_overlapping(mut regions: Vec<Counted>) -> Vec<Counted> {
    loop {
        regions.sort_by_key(|(r, _)| (r.a_lines, r.b_lines));
        let mut merged: Vec<Counted> = Vec::with_capacity(regions.len());
        let mut changed = false;
        for (r, n) in regions {
            match merged
                .iter_mut()
                .find(|(m, _)| touch(m.a_lines, r.a_lines) && touch(m.b_lines, r.b_lines))
            {
                Some((m, count)) => {
                    *m = union(*m, r);
                    *count += n;
                    changed = true;
                }
                None => merged.push((r, n)),
            }
        }
        regions = merged;
        if !changed {
            return regions;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn print(hash: u64, first_token: usize, line: usize) -> Fingerprint {
        Fingerprint {
            hash,
            first_token,
            lines: (line, line + 1),
        }
    }

    #[test]
    fn one_copied_run_is_one_region_and_a_moved_block_another() {
        // A: hashes 1..=6 at tokens 0, 4, 8, … on lines 1, 2, 3, …; B has 1..=3 shifted by
        // 10 lines and 4..=6 before them.
        let a: Vec<_> = (1..=6)
            .map(|h| print(h, (h as usize - 1) * 4, h as usize))
            .collect();
        let b: Vec<_> = (1..=6)
            .map(|h| {
                let i = h as usize - 1;
                if h <= 3 {
                    print(h, 100 + i * 4, 20 + i)
                } else {
                    print(h, (i - 3) * 4, 2 + i)
                }
            })
            .collect();
        let r = regions(&by_hash(a), &by_hash(b), 5, 4);
        assert_eq!(
            r,
            vec![
                Region {
                    a_lines: (1, 4),
                    b_lines: (20, 23)
                },
                Region {
                    a_lines: (4, 7),
                    b_lines: (5, 8)
                },
            ]
        );
    }
}
