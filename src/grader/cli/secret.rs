//! The course's secrets on the command line (`--hidden-seed`, `--variant-key`) or, better, in
//! a file (`--hidden-seed-file`, `--variant-key-file`): a command line is every local user's
//! to read (`ps`, `/proc/<pid>/cmdline`) for as long as the run lasts; a file is its owner's.

use anyhow::Context;
use std::path::Path;

/// The text of a secret's file, without surrounding white space.
fn read(file: &Path) -> anyhow::Result<String> {
    let text = std::fs::read_to_string(file)
        .with_context(|| format!("reading the secret in {}", file.display()))?;
    let text = text.trim();
    anyhow::ensure!(!text.is_empty(), "{} is empty", file.display());
    Ok(text.to_string())
}

/// Says that a secret given on the command line is readable by every user of the machine.
fn warn(flag: &str) {
    eprintln!(
        "pbrlab: --{flag} on the command line is readable by every user of this machine while \
         the run lasts (ps, /proc): put it in a file of yours and pass --{flag}-file instead"
    );
}

/// The hidden seed, from `--{flag}` or the file of `--{flag}-file` (at most one is given).
pub fn seed(flag: &str, given: Option<u64>, file: Option<&Path>) -> anyhow::Result<Option<u64>> {
    if given.is_some() {
        warn(flag);
    }
    match file {
        Some(file) => {
            let text = read(file)?;
            let seed = text.parse().with_context(|| {
                format!("{} does not hold a seed (a whole number)", file.display())
            })?;
            Ok(Some(seed))
        }
        None => Ok(given),
    }
}

/// The course's variant key, from `--{flag}` or the file of `--{flag}-file`.
pub fn key(
    flag: &str,
    given: Option<String>,
    file: Option<&Path>,
) -> anyhow::Result<Option<String>> {
    if given.is_some() {
        warn(flag);
    }
    match file {
        Some(file) => Ok(Some(read(file)?)),
        None => Ok(given),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_secret_comes_from_its_file_trimmed() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("seed");
        std::fs::write(&file, "4242\n").unwrap();
        assert_eq!(seed("hidden-seed", None, Some(&file)).unwrap(), Some(4242));
        assert_eq!(seed("hidden-seed", Some(7), None).unwrap(), Some(7));
        assert_eq!(seed("hidden-seed", None, None).unwrap(), None);
        std::fs::write(&file, "  course key \n").unwrap();
        assert_eq!(
            key("variant-key", None, Some(&file)).unwrap().as_deref(),
            Some("course key")
        );
        std::fs::write(&file, "x").unwrap();
        assert!(
            seed("hidden-seed", None, Some(&file)).is_err(),
            "not a number"
        );
        std::fs::write(&file, "\n").unwrap();
        assert!(key("variant-key", None, Some(&file)).is_err(), "empty");
        assert!(key("variant-key", None, Some(&dir.path().join("none"))).is_err());
    }
}
