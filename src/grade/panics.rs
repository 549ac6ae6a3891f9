//! Catching panics of student code with their message and source location, silently.
//!
//! A process-wide panic hook records the panic of a thread that is inside [`catch`] and stays
//! quiet; panics elsewhere go to the hook that was installed before, so test harnesses and
//! the CLI keep their usual output.

use crate::worksheet::TaskId;
use serde::{Deserialize, Serialize};
use std::cell::{Cell, RefCell};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::Once;

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

/// The task whose stub raised a `todo!()` at `file`, if the file is an exercise.
fn exercise_task(file: &str) -> Option<String> {
    let file = file.replace('\\', "/");
    let name = file.rsplit_once("exercises/")?.1.strip_suffix(".rs")?;
    TaskId::parse(name)
        .ok()
        .filter(|t| t.name() == name)
        .map(|t| t.name().to_string())
}

fn install() {
    INSTALL.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !CAPTURING.with(Cell::get) {
                previous(info);
                return;
            }
            let message = crate::implementation::panic_message(info.payload())
                .unwrap_or("panic with a non-string payload")
                .to_string();
            let todo = crate::implementation::is_todo_panic(info.payload());
            let location = info
                .location()
                .map(|l| format!("{}:{}", l.file(), l.line()));
            let todo_in = info
                .location()
                .filter(|_| todo)
                .and_then(|l| exercise_task(l.file()));
            LAST.with(|last| {
                *last.borrow_mut() = Some(Panic {
                    message,
                    location,
                    todo_in,
                })
            });
        }));
    });
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
        assert_eq!(exercise_task("solutions/smith_g1.rs"), None);
    }
}
