//! What the grader takes from a submission: the exercise files (`<task>.rs`, found anywhere
//! in the upload, as a folder or a zip), nothing else. Every other entry is listed as
//! ignored, and so are a second copy of a task file, a symbolic link, a file over
//! [`MAX_FILE`] and a file that is not UTF-8. The files taken are written over the shipped
//! stubs in a scratch `exercises/` folder, so a task the student did not submit is its stub.

use crate::worksheet::TaskId;
use anyhow::{Context, bail};
use std::collections::BTreeMap;
use std::io::Read;
use std::path::{Component, Path};

/// The largest exercise file taken, in bytes.
pub const MAX_FILE: u64 = 1 << 20;

/// The most entries of a submission looked at (a zip bomb of empty entries stops here).
const MAX_ENTRIES: usize = 10_000;

/// The files taken from a submission and what was left.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Intake {
    /// Per task, the file's path in the submission and its text.
    pub taken: BTreeMap<TaskId, (String, String)>,
    /// Entries not taken, each with the reason.
    pub ignored: Vec<String>,
}

impl Intake {
    /// One line per ignored entry, for the report.
    pub fn ignored_text(&self) -> String {
        if self.ignored.is_empty() {
            return String::new();
        }
        let mut s = format!(
            "Ignored ({} entries; only exercise files <task>.rs are graded):\n",
            self.ignored.len()
        );
        for line in &self.ignored {
            s += &format!("  {line}\n");
        }
        s
    }

    /// The hidden seed of this submission under the course's secret `secret`: a keyed hash
    /// (SipHash-2-4) of the files taken. Hidden inputs that leak from one submission tell
    /// nothing of another's, while a regrade of the same files draws the same cases.
    pub fn hidden_seed(&self, secret: u64) -> u64 {
        use std::hash::Hasher;
        /// Separates this use of the secret from any other.
        const DOMAIN: u64 = 0x7062_726c_6162_6873; // "pbrlabhs"
        let mut hasher = siphasher::sip::SipHasher24::new_with_keys(secret, DOMAIN);
        for (task, (_, text)) in &self.taken {
            hasher.write(task.name().as_bytes());
            hasher.write_u8(0xff);
            hasher.write_usize(text.len());
            hasher.write(text.as_bytes());
        }
        hasher.finish()
    }

    /// Offers one entry, at `path` in the submission, of `size` bytes.
    fn offer(&mut self, path: &str, size: u64, read: impl FnOnce() -> std::io::Result<Vec<u8>>) {
        let name = path.rsplit('/').next().unwrap_or(path);
        let Some(task) = name
            .strip_suffix(".rs")
            .and_then(|stem| TaskId::ALL.into_iter().find(|t| t.name() == stem))
        else {
            self.ignored.push(format!("{path}: not an exercise file"));
            return;
        };
        if size > MAX_FILE {
            self.ignored
                .push(format!("{path}: larger than {} KiB", MAX_FILE >> 10));
            return;
        }
        let text = match read().map(String::from_utf8) {
            Ok(Ok(text)) => text,
            Ok(Err(_)) => {
                self.ignored.push(format!("{path}: not UTF-8 text"));
                return;
            }
            Err(e) => {
                self.ignored.push(format!("{path}: unreadable ({e})"));
                return;
            }
        };
        match self.taken.get(&task) {
            // The copy in an `exercises/` folder wins, then the shallower one.
            Some((kept, _)) if rank(kept) <= rank(path) => {
                self.ignored
                    .push(format!("{path}: another copy, {kept}, was taken"));
            }
            Some((kept, _)) => {
                self.ignored
                    .push(format!("{kept}: another copy, {path}, was taken"));
                self.taken.insert(task, (path.to_string(), text));
            }
            None => {
                self.taken.insert(task, (path.to_string(), text));
            }
        }
    }

    /// Writes the shipped stubs (from `stub`) and over them the files taken into the folder
    /// `exercises`, which is created.
    pub fn write(
        &self,
        exercises: &Path,
        stub: &dyn Fn(TaskId) -> anyhow::Result<String>,
    ) -> anyhow::Result<()> {
        std::fs::create_dir_all(exercises)
            .with_context(|| format!("making {}", exercises.display()))?;
        for task in TaskId::ALL {
            let text = match self.taken.get(&task) {
                Some((_, text)) => text.clone(),
                None => stub(task)?,
            };
            let file = exercises.join(format!("{}.rs", task.name()));
            std::fs::write(&file, text).with_context(|| format!("writing {}", file.display()))?;
        }
        Ok(())
    }
}

/// Which of two copies of a task file is taken: the lower rank.
fn rank(path: &str) -> (bool, usize) {
    let in_exercises = path.split('/').rev().nth(1) == Some("exercises");
    (!in_exercises, path.matches('/').count())
}

/// Takes the exercise files from `submission`, a folder or a `.zip` file.
pub fn take(submission: &Path) -> anyhow::Result<Intake> {
    let mut intake = Intake::default();
    let meta = std::fs::symlink_metadata(submission)
        .with_context(|| format!("reading the submission {}", submission.display()))?;
    if meta.is_dir() {
        walk(submission, "", &mut intake, &mut 0)?;
    } else if submission
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("zip"))
    {
        take_zip(submission, &mut intake)?;
    } else {
        bail!(
            "the submission {} is neither a folder nor a .zip file",
            submission.display()
        );
    }
    Ok(intake)
}

fn walk(dir: &Path, prefix: &str, intake: &mut Intake, seen: &mut usize) -> anyhow::Result<()> {
    let mut entries: Vec<_> = std::fs::read_dir(dir)
        .with_context(|| format!("reading {}", dir.display()))?
        .flatten()
        .collect();
    entries.sort_by_key(|e| e.file_name());
    for entry in entries {
        *seen += 1;
        if *seen > MAX_ENTRIES {
            intake
                .ignored
                .push(format!("(more than {MAX_ENTRIES} entries: the rest)"));
            return Ok(());
        }
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = format!("{prefix}{name}");
        let Ok(meta) = std::fs::symlink_metadata(entry.path()) else {
            intake.ignored.push(format!("{path}: unreadable"));
            continue;
        };
        if meta.file_type().is_symlink() {
            intake.ignored.push(format!("{path}: a symbolic link"));
        } else if meta.is_dir() {
            walk(&entry.path(), &format!("{path}/"), intake, seen)?;
        } else if meta.is_file() && name.to_ascii_lowercase().ends_with(".zip") {
            // A zip uploaded beside (or instead of) the files: its entries are offered in
            // turn, one level deep (a zip inside it is not opened).
            if let Err(e) = take_zip(&entry.path(), intake) {
                intake.ignored.push(format!("{path}: {e:#}"));
            }
        } else if meta.is_file() {
            intake.offer(&path, meta.len(), || {
                let mut bytes = Vec::new();
                std::fs::File::open(entry.path())?
                    .take(MAX_FILE + 1)
                    .read_to_end(&mut bytes)?;
                Ok(bytes)
            });
        } else {
            intake.ignored.push(format!("{path}: not a regular file"));
        }
    }
    Ok(())
}

fn take_zip(file: &Path, intake: &mut Intake) -> anyhow::Result<()> {
    let reader =
        std::fs::File::open(file).with_context(|| format!("opening {}", file.display()))?;
    let mut zip = zip::ZipArchive::new(reader)
        .with_context(|| format!("{} is not a readable zip file", file.display()))?;
    for i in 0..zip.len().min(MAX_ENTRIES) {
        let mut entry = match zip.by_index(i) {
            Ok(entry) => entry,
            Err(e) => {
                intake.ignored.push(format!("entry {i}: unreadable ({e})"));
                continue;
            }
        };
        let raw = match entry.name() {
            Ok(name) => name.into_owned(),
            Err(e) => {
                intake
                    .ignored
                    .push(format!("entry {i}: an unreadable name ({e})"));
                continue;
            }
        };
        if entry.is_dir() {
            continue;
        }
        // A name that climbs out of the archive, or is absolute, is never a path here.
        let Some(path) = entry
            .enclosed_name()
            .filter(|p| p.components().all(|c| matches!(c, Component::Normal(_))))
        else {
            intake
                .ignored
                .push(format!("{raw}: a path outside the archive"));
            continue;
        };
        if entry.is_symlink() {
            intake.ignored.push(format!("{raw}: a symbolic link"));
            continue;
        }
        let path = slash_path(&path);
        let size = entry.size();
        intake.offer(&path, size, || {
            let mut bytes = Vec::new();
            (&mut entry).take(MAX_FILE + 1).read_to_end(&mut bytes)?;
            Ok(bytes)
        });
    }
    if zip.len() > MAX_ENTRIES {
        intake
            .ignored
            .push(format!("(more than {MAX_ENTRIES} entries: the rest)"));
    }
    Ok(())
}

fn slash_path(path: &Path) -> String {
    path.components()
        .map(|c| c.as_os_str().to_string_lossy())
        .collect::<Vec<_>>()
        .join("/")
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_hidden_seed_depends_on_the_secret_and_every_file() {
        let intake = |text: &str| Intake {
            taken: [
                (
                    TaskId::Reflect,
                    ("reflect.rs".to_string(), text.to_string()),
                ),
                (
                    TaskId::Mis,
                    ("mis.rs".to_string(), "fn mis() {}".to_string()),
                ),
            ]
            .into(),
            ignored: Vec::new(),
        };
        let a = intake("fn reflect() {}");
        assert_eq!(a.hidden_seed(7), intake("fn reflect() {}").hidden_seed(7));
        assert_ne!(a.hidden_seed(7), a.hidden_seed(8), "another course secret");
        assert_ne!(a.hidden_seed(7), intake("fn reflect() { }").hidden_seed(7));
        let mut moved = a.clone();
        moved.taken.remove(&TaskId::Mis);
        assert_ne!(a.hidden_seed(7), moved.hidden_seed(7));
    }

    use super::*;
    use std::io::Write;

    #[test]
    fn only_exercise_files_are_taken_and_the_rest_is_listed() {
        let dir = tempfile::tempdir().unwrap();
        let root = dir.path();
        std::fs::create_dir_all(root.join("exercises")).unwrap();
        std::fs::write(root.join("exercises/smith_g1.rs"), "// mine").unwrap();
        std::fs::write(root.join("smith_g1.rs"), "// stray copy").unwrap();
        std::fs::write(root.join("mis.rs"), "// mis").unwrap();
        std::fs::write(root.join("notes.txt"), "hi").unwrap();
        std::fs::write(root.join("build.rs"), "fn main() {}").unwrap();
        std::fs::write(root.join("reflect.rs"), [0xff, 0xfe]).unwrap();
        std::os::unix::fs::symlink("/etc/passwd", root.join("phong.rs")).unwrap();
        let intake = take(root).unwrap();
        let taken: Vec<_> = intake
            .taken
            .iter()
            .map(|(t, (p, _))| (*t, p.as_str()))
            .collect();
        assert_eq!(
            taken,
            [
                (TaskId::SmithG1, "exercises/smith_g1.rs"),
                (TaskId::Mis, "mis.rs")
            ]
        );
        let ignored = intake.ignored.join("\n");
        for expected in [
            "smith_g1.rs: another copy, exercises/smith_g1.rs, was taken",
            "notes.txt: not an exercise file",
            "build.rs: not an exercise file",
            "reflect.rs: not UTF-8 text",
            "phong.rs: a symbolic link",
        ] {
            assert!(
                ignored.contains(expected),
                "{expected:?} missing in\n{ignored}"
            );
        }
        let scratch = root.join("scratch/exercises");
        intake
            .write(&scratch, &|t| Ok(format!("// stub of {}", t.name())))
            .unwrap();
        assert_eq!(
            std::fs::read_to_string(scratch.join("smith_g1.rs")).unwrap(),
            "// mine"
        );
        assert_eq!(
            std::fs::read_to_string(scratch.join("reflect.rs")).unwrap(),
            "// stub of reflect",
            "a task not taken is its stub"
        );
    }

    #[test]
    fn a_zip_inside_a_submission_folder_is_read() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("exercises.zip");
        let mut zip = zip::ZipWriter::new(std::fs::File::create(&file).unwrap());
        zip.start_file("exercises/mis.rs", zip::write::SimpleFileOptions::default())
            .unwrap();
        zip.write_all(b"// mis").unwrap();
        zip.finish().unwrap();
        std::fs::write(dir.path().join("reflect.rs"), "// reflect").unwrap();
        std::fs::write(dir.path().join("broken.zip"), "not a zip").unwrap();
        let intake = take(dir.path()).unwrap();
        assert_eq!(
            intake.taken.keys().copied().collect::<Vec<_>>(),
            [TaskId::Reflect, TaskId::Mis]
        );
        assert!(
            intake.ignored.iter().any(|i| i.starts_with("broken.zip: ")),
            "{:?}",
            intake.ignored
        );
    }

    #[test]
    fn a_zip_submission_is_read_without_extracting_escaping_paths() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("alice.zip");
        let mut zip = zip::ZipWriter::new(std::fs::File::create(&file).unwrap());
        let options = zip::write::SimpleFileOptions::default();
        zip.start_file("alice/exercises/reflect.rs", options)
            .unwrap();
        zip.write_all(b"// reflect").unwrap();
        zip.start_file("../../solutions/mis.rs", options).unwrap();
        zip.write_all(b"// escape").unwrap();
        zip.start_file("alice/readme.md", options).unwrap();
        zip.write_all(b"# hi").unwrap();
        zip.finish().unwrap();
        let intake = take(&file).unwrap();
        assert_eq!(intake.taken.len(), 1);
        assert_eq!(
            intake.taken[&TaskId::Reflect],
            (
                "alice/exercises/reflect.rs".to_string(),
                "// reflect".to_string()
            )
        );
        let ignored = intake.ignored.join("\n");
        assert!(
            ignored.contains("../../solutions/mis.rs: a path outside the archive"),
            "{ignored}"
        );
        assert!(
            ignored.contains("alice/readme.md: not an exercise file"),
            "{ignored}"
        );
    }
}
