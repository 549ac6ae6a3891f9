//! # pbrlab-course
//!
//! The course as pbrlab hands it out, with nothing of the renderer or the grader: the
//! worksheet's tasks and their points and hints ([`task`]), the scenes graded by rendering
//! ([`scenes`]), the student's progress as the grader records it ([`history`], [`status`]),
//! the shipped stubs ([`stubs`]), and the commands that need nothing more ([`cli`]:
//! `tasks`, `hint`, `reset`), with three small pieces every layer above shares ([`atomic_file`],
//! [`timestamp`], [`html_escape`]). The `pbrlab` binary links only this crate, so a student's
//! first command builds in seconds and the rest (renderer, grader) is built on first use.
//! Every other crate of the workspace builds on it; the renderer re-exports [`task`] and
//! [`task_set`] under its `worksheet` and `task_set`.

pub mod atomic_file;
pub mod cli;
pub mod commands_binary;
pub mod history;
pub mod html_escape;
pub mod scenes;
pub mod selection;
pub mod status;
pub mod stubs;
pub mod task;
pub mod task_set;
pub mod timestamp;

/// The repository this crate was built from (the workspace root, two folders above
/// `src/course/`): where `exercises/` and `.pbrlab/` are found.
pub fn repository_root() -> &'static std::path::Path {
    let course = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    course
        .parent()
        .and_then(std::path::Path::parent)
        .unwrap_or(course)
}
