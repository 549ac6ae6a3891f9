//! A moment as a file or folder name: the UTC date and time to the second,
//! `2026-12-07T13-30-05Z` (RFC 3339 with `-` for `:`, which some file systems refuse), so
//! that names sort in time order and read as dates.

use std::path::{Path, PathBuf};
use std::time::SystemTime;

/// `now` as a name: `2026-12-07T13-30-05Z`.
pub fn name(now: SystemTime) -> String {
    humantime::format_rfc3339_seconds(now)
        .to_string()
        .replace(':', "-")
}

/// `dir/<prefix><now><suffix>`, or, when that exists already (two in one second),
/// `dir/<prefix><now>-2<suffix>`, `-3` and so on: a name nothing else has.
pub fn unused(dir: &Path, prefix: &str, suffix: &str) -> PathBuf {
    let stamp = name(SystemTime::now());
    (1..)
        .map(|k| match k {
            1 => dir.join(format!("{prefix}{stamp}{suffix}")),
            k => dir.join(format!("{prefix}{stamp}-{k}{suffix}")),
        })
        .find(|p| !p.exists())
        .unwrap_or_else(|| dir.join(format!("{prefix}{stamp}{suffix}")))
}

#[cfg(test)]
mod tests {
    use std::time::{Duration, UNIX_EPOCH};

    #[test]
    fn names_read_as_utc_dates_and_never_repeat_in_one_folder() {
        let moment = UNIX_EPOCH + Duration::from_secs(1_796_650_205);
        assert_eq!(super::name(moment), "2026-12-07T13-30-05Z");
        let dir = tempfile::tempdir().unwrap();
        let first = super::unused(dir.path(), "reflect-", ".rs");
        std::fs::write(&first, "").unwrap();
        let second = super::unused(dir.path(), "reflect-", ".rs");
        assert_ne!(first, second);
        assert!(second.to_string_lossy().ends_with("-2.rs"), "{second:?}");
    }
}
