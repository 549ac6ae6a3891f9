//! Panics of student code: caught with their message and source location, and kept quiet.
//!
//! One process-wide panic hook, installed on first use, serves every caller, so no caller
//! ever swaps the hook (which would lose another thread's setting):
//! - [`catch`] runs a closure and turns a panic on the calling thread into a [`Panic`]
//!   record, printing nothing;
//! - while a [`QuietPanics`] guard lives, panics raised by student code (in `exercises/`,
//!   or any `todo!()`) print nothing on any thread, and the first one is kept, so code that
//!   sees a panic re-raised from a rayon thread can still say where it happened;
//! - every other panic goes to the hook that was installed before, so test harnesses and
//!   the CLI keep their usual output.

use crate::worksheet::TaskId;
use serde::{Deserialize, Serialize};
use std::cell::{Cell, RefCell};
use std::panic::{AssertUnwindSafe, PanicHookInfo, catch_unwind};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::{Mutex, Once};

/// A caught panic.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Panic {
    /// The panic message (`"not yet implemented"` for `todo!()`).
    pub message: String,
    /// `file:line` where it was raised, when known.
    pub location: Option<String>,
    /// When the panic is a `todo!()`/`unimplemented!()` in `exercises/<task>.rs`: that task.
    pub todo_in: Option<String>,
}

impl Panic {
    /// True when the panic is the stub of `task` itself (the student has not written it).
    pub fn is_todo_of(&self, task: TaskId) -> bool {
        self.todo_in.as_deref() == Some(task.name())
    }

    /// One line for messages: `panicked at exercises/reflect.rs:7: index out of bounds`.
    pub fn describe(&self) -> String {
        if let Some(task) = &self.todo_in {
            return format!("not implemented yet (todo!() in exercises/{task}.rs)");
        }
        match &self.location {
            Some(loc) => format!("panicked at {loc}: {}", self.message),
            None => format!("panicked: {}", self.message),
        }
    }
}

thread_local! {
    static CAPTURING: Cell<bool> = const { Cell::new(false) };
    static LAST: RefCell<Option<Panic>> = const { RefCell::new(None) };
}

static INSTALL: Once = Once::new();

/// Live [`QuietPanics`] guards.
static QUIET: AtomicUsize = AtomicUsize::new(0);

/// The first student panic silenced by a [`QuietPanics`] guard and not yet taken.
static FIRST_QUIET: Mutex<Option<Panic>> = Mutex::new(None);

/// The name of `file` when it is an exercise file: in `exercises/`, or in the copy a build
/// compiles when another exercise file does not (`.pbrlab/stubbed/`,
/// [`crate::grade::student_build`]).
fn exercise_file_name(file: &str) -> Option<String> {
    let file = file.replace('\\', "/");
    let (folder, name) = file.rsplit_once('/')?;
    let mut up = folder.rsplit('/');
    match (up.next(), up.next()) {
        (Some("exercises"), _) | (Some("stubbed"), Some(".pbrlab")) => Some(name.into()),
        _ => None,
    }
}

/// The task whose stub raised a `todo!()` at `file`, if the file is an exercise.
fn exercise_task(file: &str) -> Option<String> {
    let file = exercise_file_name(file)?;
    let name = file.strip_suffix(".rs")?;
    TaskId::parse(name)
        .ok()
        .filter(|t| t.name() == name)
        .map(|t| t.name().to_string())
}

impl Panic {
    fn from_hook(info: &PanicHookInfo<'_>) -> Self {
        let todo = crate::implementation::is_todo_panic(info.payload());
        Self {
            message: crate::implementation::panic_message(info.payload())
                .unwrap_or("panic with a non-string payload")
                .to_string(),
            location: info
                .location()
                .map(|l| format!("{}:{}", public_path(l.file()), l.line())),
            todo_in: info
                .location()
                .filter(|_| todo)
                .and_then(|l| exercise_task(l.file())),
        }
    }
}

/// A source path as a report may show it: no path of the grading machine. A crate from
/// the registry is named from its folder (`glam-0.34.2/src/f32/vec3.rs`), the standard
/// library from `library/`, an exercise file from `exercises/`, a file of the framework
/// from the repository's root; any other absolute path by its file name.
pub fn public_path(file: &str) -> String {
    let after = |marker: &str| file.split_once(marker).map(|(_, rest)| rest.to_string());
    if let Some(rest) = after("/registry/src/") {
        // `index.crates.io-<hash>/glam-0.34.2/…`: from the crate's folder on.
        return rest
            .split_once('/')
            .map_or(rest.clone(), |(_, r)| r.to_string());
    }
    if file.starts_with("/rustc/")
        && let Some(rest) = after("/library/")
    {
        return format!("library/{rest}");
    }
    if let Some(name) = exercise_file_name(file) {
        return format!("exercises/{name}");
    }
    let path = std::path::Path::new(file);
    if !path.is_absolute() {
        return file.to_string();
    }
    path.strip_prefix(crate::repository_root())
        .map(|p| p.display().to_string())
        .unwrap_or_else(|_| {
            path.file_name()
                .map_or_else(String::new, |n| n.to_string_lossy().into_owned())
        })
}

/// True for a panic raised by student code: a `todo!()` anywhere, or any panic in an
/// exercise file.
fn from_student(info: &PanicHookInfo<'_>) -> bool {
    crate::implementation::is_todo_panic(info.payload())
        || info
            .location()
            .is_some_and(|l| exercise_file_name(l.file()).is_some())
}

fn install() {
    INSTALL.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if CAPTURING.with(Cell::get) {
                LAST.with(|last| *last.borrow_mut() = Some(Panic::from_hook(info)));
            } else if QUIET.load(Ordering::SeqCst) > 0 && from_student(info) {
                let mut first = FIRST_QUIET.lock().unwrap_or_else(|e| e.into_inner());
                first.get_or_insert_with(|| Panic::from_hook(info));
            } else {
                previous(info);
            }
        }));
    });
}

/// While alive, panics raised by student code print nothing, on every thread; other panics
/// print as usual. Guards may overlap (in several threads); the quiet lasts until the last
/// one is dropped. The guard belongs to the code that waits for the student's code, not to
/// that code: a call that never returns cannot leave the process quiet for good.
pub struct QuietPanics(());

impl QuietPanics {
    /// Starts the quiet.
    pub fn new() -> Self {
        install();
        QUIET.fetch_add(1, Ordering::SeqCst);
        Self(())
    }

    /// The first student panic silenced since the last call (by this guard or any other),
    /// with its location.
    pub fn take_first(&self) -> Option<Panic> {
        FIRST_QUIET.lock().unwrap_or_else(|e| e.into_inner()).take()
    }
}

impl Default for QuietPanics {
    fn default() -> Self {
        Self::new()
    }
}

impl Drop for QuietPanics {
    fn drop(&mut self) {
        QUIET.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Runs `f`, turning a panic into a [`Panic`] record without printing anything.
pub fn catch<R>(f: impl FnOnce() -> R) -> Result<R, Panic> {
    install();
    let was = CAPTURING.with(|c| c.replace(true));
    let out = catch_unwind(AssertUnwindSafe(f));
    CAPTURING.with(|c| c.set(was));
    out.map_err(|payload| {
        LAST.with(|last| last.borrow_mut().take())
            .unwrap_or_else(|| Panic {
                message: crate::implementation::panic_message(payload.as_ref())
                    .unwrap_or("panic with a non-string payload")
                    .to_string(),
                location: None,
                todo_in: None,
            })
    })
}

#[cfg(test)]
mod tests {

    #[test]
    fn a_reported_location_holds_no_path_of_the_grading_machine() {
        let public = |f: &str| public_path(f);
        assert_eq!(
            public(
                "/root/.cargo/registry/src/index.crates.io-1949cf8c6b5b557f/glam-0.34.2/src/f32/vec3.rs"
            ),
            "glam-0.34.2/src/f32/vec3.rs"
        );
        assert_eq!(
            public("/rustc/59807616e1c2b3e9/library/core/src/num/mod.rs"),
            "library/core/src/num/mod.rs"
        );
        assert_eq!(
            public("/tmp/pbrlab-class-x/exercises/reflect.rs"),
            "exercises/reflect.rs"
        );
        let framework = crate::repository_root().join("src/renderer/bsdf.rs");
        assert_eq!(public(&framework.to_string_lossy()), "src/renderer/bsdf.rs");
        assert_eq!(public("/home/ta/secret/place/x.rs"), "x.rs");
        assert_eq!(public("src/grader/lib.rs"), "src/grader/lib.rs");
    }
    use super::*;

    #[test]
    fn a_todo_outside_the_exercises_is_an_ordinary_panic() {
        let p = catch(|| -> u32 { todo!() }).expect_err("todo!() panics");
        assert_eq!(p.message, "not yet implemented");
        assert_eq!(p.todo_in, None, "only exercises/ files name a task");
        assert!(!p.is_todo_of(TaskId::Reflect));
    }

    #[test]
    fn other_panics_keep_message_and_location() {
        let p = catch(|| {
            let v: Vec<i32> = Vec::new();
            v[std::hint::black_box(3)]
        })
        .unwrap_err();
        assert_eq!(p.todo_in, None);
        assert!(p.message.contains("index out of bounds"), "{p:?}");
        assert!(p.location.unwrap().contains("panics.rs"));
        assert_eq!(catch(|| 7), Ok(7));
    }

    #[test]
    fn exercise_files_map_to_tasks() {
        assert_eq!(
            exercise_task("exercises/smith_g1.rs").as_deref(),
            Some("smith_g1")
        );
        assert_eq!(exercise_task("/x/exercises/smith.rs"), None);
        assert_eq!(
            exercise_task("/x/.pbrlab/stubbed/mis.rs").as_deref(),
            Some("mis"),
            "the copy built when another file does not compile"
        );
        assert_eq!(exercise_task("/x/exercises/sub/mis.rs"), None);
        assert_eq!(exercise_task("/x/my_exercises/mis.rs"), None);
        assert_eq!(exercise_task("solutions/smith_g1.rs"), None);
    }

    #[test]
    fn quiet_panics_keeps_the_first_student_panic_of_any_thread() {
        let quiet = QuietPanics::new();
        quiet.take_first();
        let joined = std::thread::spawn(|| -> u32 { todo!() }).join();
        assert!(joined.is_err());
        let first = quiet.take_first().expect("recorded");
        assert_eq!(first.message, "not yet implemented");
        assert!(first.location.is_some_and(|l| l.contains("panics.rs")));
        // A panic that is not the student's is not silenced, so nothing is recorded.
        let other = std::thread::spawn(|| panic!("a framework bug")).join();
        assert!(other.is_err());
        assert_eq!(quiet.take_first(), None);
    }
}
