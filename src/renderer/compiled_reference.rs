//! The reference in compiled form: shared libraries built from `tools/reference-library/`.
//! The whole reference goes into the student handout (`tools/reference/`, written by
//! `pbrlab handout`), whose binaries load it, so `render --impl mixed` takes the reference for
//! the tasks a student has not written, without the reference's source. One library per task
//! is what the grader's workers load (the grader's `grade::references`).
//!
//! The library holds its own copy of this framework, and the handout's binaries hand it
//! their scenes, samplers and task tables by reference, in Rust's own calling convention.
//! That is sound only when both copies were compiled from the same sources, by the same
//! compiler, for the same target, with the same features and dependency versions: the
//! library says what it was built from ([`abi_signature`]: `PBRLAB_ABI_BUILD`, set by the
//! build script, plus the sizes of the types that cross), and [`load`] refuses a library
//! whose signature is not this build's, saying what differs. Two C functions cross before
//! the check: [`ABI_SYMBOL`] and [`TASKS_SYMBOL`].
//!
//! The library counts the rays its code casts in its own counter, which it exports
//! ([`RAYS_SYMBOL`]) and this build adds to its own. A limit of the shared copy, harmless to
//! a render: a panic inside the library's code cannot be caught by this build's (another copy of
//! the standard library), so it ends the process. The reference does not panic on a scene
//! that loaded.

use crate::worksheet::TaskFns;
use anyhow::{Context, bail};
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The exported C function that returns the library's [`abi_signature`]: it writes the
/// length through its argument and returns a pointer to UTF-8 bytes that live as long as
/// the library.
pub const ABI_SYMBOL: &[u8] = b"pbrlab_reference_abi";

/// The exported C function that returns a pointer to the library's [`TaskFns`] (the
/// reference's table); read only after the signatures agree.
pub const TASKS_SYMBOL: &[u8] = b"pbrlab_reference_tasks";

/// The exported C function that returns the rays the calling thread cast in the library's
/// code since the last call: the library's copy of the framework counts them in its own
/// counter, which [`take_library_rays`] adds to this build's.
pub const RAYS_SYMBOL: &[u8] = b"pbrlab_reference_take_rays";

/// The ray counters of the libraries loaded in this process.
static RAY_COUNTERS: std::sync::Mutex<Vec<extern "C" fn() -> u64>> =
    std::sync::Mutex::new(Vec::new());

/// The rays the calling thread cast in loaded libraries' code since the last call (see
/// [`crate::scene::take_ray_count`], which adds them).
pub fn take_library_rays() -> u64 {
    RAY_COUNTERS
        .lock()
        .map(|counters| counters.iter().map(|take| take()).sum())
        .unwrap_or(0)
}

/// The library's file name on this platform (`libpbrlab_reference.so` on Linux).
pub fn file_name() -> String {
    format!(
        "{}pbrlab_reference{}",
        std::env::consts::DLL_PREFIX,
        std::env::consts::DLL_SUFFIX
    )
}

/// The start of the name of each one-task library, followed by the task's id
/// (`pbrlab_reference_smith_g1`): the examples of `tools/reference-library/`, which the
/// grader's workers load (the grader's `grade::references`).
pub const TASK_LIBRARY_PREFIX: &str = "pbrlab_reference_";

/// Defines the two C functions of a reference library ([`ABI_SYMBOL`], [`TASKS_SYMBOL`]),
/// the table being `$table`, a constant expression of type
/// [`TaskFns`](crate::worksheet::TaskFns). Built with [`TaskFns::ABSENT`] and
/// [`TaskFns::with_task`](crate::worksheet::TaskFns::with_task), the table refers to one
/// task's functions only, so the linker leaves every other task's reference out of the
/// library.
///
/// [`TaskFns::ABSENT`]: crate::worksheet::TaskFns::ABSENT
#[macro_export]
macro_rules! reference_library {
    ($table:expr) => {
        /// [`pbrlab::compiled_reference::ABI_SYMBOL`]: writes the signature's length to
        /// `len` and returns its bytes, which live as long as the library.
        ///
        /// # Safety
        /// `len` must be valid for a write.
        #[unsafe(no_mangle)]
        pub unsafe extern "C" fn pbrlab_reference_abi(len: *mut usize) -> *const u8 {
            static SIGNATURE: std::sync::OnceLock<String> = std::sync::OnceLock::new();
            let signature = SIGNATURE.get_or_init($crate::compiled_reference::abi_signature);
            // SAFETY: the caller passes a writable `usize`.
            unsafe { len.write(signature.len()) };
            signature.as_ptr()
        }

        /// [`pbrlab::compiled_reference::TASKS_SYMBOL`]: the library's task table, to be
        /// read only by a build whose signature is this library's.
        #[unsafe(no_mangle)]
        pub extern "C" fn pbrlab_reference_tasks() -> *const std::ffi::c_void {
            static TABLE: $crate::worksheet::TaskFns = $table;
            (&raw const TABLE).cast()
        }

        /// [`pbrlab::compiled_reference::RAYS_SYMBOL`]: the rays the calling thread cast
        /// in the library's code since the last call (its own copy of the counter).
        #[unsafe(no_mangle)]
        pub extern "C" fn pbrlab_reference_take_rays() -> u64 {
            $crate::scene::take_ray_count()
        }
    };
}

/// Where a repository keeps its compiled reference: `tools/reference/` in it.
pub fn path_in(repository: &Path) -> PathBuf {
    repository.join("tools").join("reference").join(file_name())
}

/// Why [`load_in`] found no usable library, for messages.
static UNAVAILABLE: OnceLock<String> = OnceLock::new();

/// The compiled reference of the repository at `repository` ([`path_in`]), or `None`, with
/// the reason kept for [`unavailable`] (no file, or a file this build cannot use).
pub fn load_in(repository: &Path) -> Option<TaskFns> {
    let path = path_in(repository);
    let reason = match load(&path) {
        Ok(Some(table)) => return Some(table),
        Ok(None) => format!("no compiled reference at {}", path.display()),
        Err(e) => format!("{e:#}"),
    };
    let _ = UNAVAILABLE.set(reason);
    None
}

/// Why the last [`load_in`] returned `None`, when it was called.
pub fn unavailable() -> Option<&'static str> {
    UNAVAILABLE.get().map(String::as_str)
}

/// What this copy of the framework was built from and with, and the sizes of the types a
/// call into the library passes: equal in the library and in the binary that loads it, or
/// the library is not loaded.
pub fn abi_signature() -> String {
    use std::mem::{align_of, size_of};
    macro_rules! layouts {
        ($($t:ty),+) => {
            [$(format!("{} {}/{}", stringify!($t), size_of::<$t>(), align_of::<$t>())),+].join(", ")
        };
    }
    let layouts = layouts!(
        TaskFns,
        crate::scene::Scene,
        crate::geometry::Hit,
        crate::geometry::Ray,
        crate::integrator::Segment,
        crate::integrator::DirectLight,
        crate::sampling::Sampler,
        crate::optics::LayerStack,
        crate::bsdf::PhongParams,
        crate::bsdf::KajiyaKayParams,
        crate::medium::FreeFlight,
        glam::Vec3
    );
    format!("{}; layouts {layouts}", env!("PBRLAB_ABI_BUILD"))
}

/// Loads the compiled reference at `path` and returns its task table, or `None` when there
/// is no file there. An error says why a library that is there cannot be used (built by
/// another compiler, from other sources, …).
///
/// The library stays loaded for the rest of the process: its functions are in the table.
pub fn load(path: &Path) -> anyhow::Result<Option<TaskFns>> {
    if !path.exists() {
        return Ok(None);
    }
    // SAFETY: loading runs the library's initialisers, which are those of Rust code built
    // by `pbrlab handout` from this repository (no life-before-main of its own).
    let library = unsafe { libloading::Library::new(path) }
        .with_context(|| format!("loading {}", path.display()))?;
    let theirs = {
        // SAFETY: the symbol is `extern "C" fn(*mut usize) -> *const u8` in every library
        // `tools/reference-library/` builds, which is the only kind `handout` writes here.
        let abi: libloading::Symbol<unsafe extern "C" fn(*mut usize) -> *const u8> =
            unsafe { library.get(ABI_SYMBOL) }.with_context(|| {
                format!(
                    "{} is not a pbrlab reference library (no ABI signature)",
                    path.display()
                )
            })?;
        let mut len = 0usize;
        // SAFETY: the function returns `len` bytes that live as long as the library.
        let bytes = unsafe { std::slice::from_raw_parts(abi(&mut len), len) };
        String::from_utf8_lossy(bytes).into_owned()
    };
    let ours = abi_signature();
    if theirs != ours {
        bail!(
            "{} was built for another build of this framework: {}. Rebuild it with the \
             instructor's `pbrlab handout`, or build this repository as it was handed out \
             (same Rust version: `{}`)",
            path.display(),
            differences(&theirs, &ours),
            env!("PBRLAB_ABI_BUILD")
                .split(';')
                .next()
                .unwrap_or_default()
        );
    }
    // SAFETY: the signatures agree, so the library's `TaskFns` is this build's type; the
    // function returns a pointer to a static of it.
    let table = unsafe {
        let tasks: libloading::Symbol<unsafe extern "C" fn() -> *const std::ffi::c_void> = library
            .get(TASKS_SYMBOL)
            .with_context(|| format!("{} has no task table", path.display()))?;
        *tasks().cast::<TaskFns>()
    };
    // SAFETY: the signatures agree, so the symbol is the macro's `extern "C" fn() -> u64`;
    // the library stays loaded, so the pointer stays valid.
    if let Ok(take) = unsafe { library.get::<extern "C" fn() -> u64>(RAYS_SYMBOL) }
        && let Ok(mut counters) = RAY_COUNTERS.lock()
    {
        let take = *take;
        if !counters
            .iter()
            .any(|known| std::ptr::fn_addr_eq(*known, take))
        {
            counters.push(take);
        }
    }
    std::mem::forget(library);
    Ok(Some(table))
}

/// The parts of two [`abi_signature`]s that differ, as "library: …, this build: …".
fn differences(library: &str, ours: &str) -> String {
    let parts =
        |s: &str| -> Vec<String> { s.split([';', ',']).map(|p| p.trim().to_string()).collect() };
    let (theirs, mine) = (parts(library), parts(ours));
    let only_theirs: Vec<&String> = theirs.iter().filter(|p| !mine.contains(p)).collect();
    let only_mine: Vec<&String> = mine.iter().filter(|p| !theirs.contains(p)).collect();
    let list = |v: &[&String]| v.iter().map(|s| s.as_str()).collect::<Vec<_>>().join(", ");
    format!(
        "the library has {}; this build has {}",
        list(&only_theirs),
        list(&only_mine)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_difference_names_the_parts_that_differ() {
        let a = "rustc 1.95.0; target x; sources 01; layouts Scene 10/8, Hit 4/4";
        let b = "rustc 1.96.0; target x; sources 01; layouts Scene 12/8, Hit 4/4";
        assert_eq!(
            differences(a, b),
            "the library has rustc 1.95.0, layouts Scene 10/8; this build has rustc 1.96.0, layouts Scene 12/8"
        );
    }

    #[test]
    fn the_signature_says_what_the_build_is_made_of() {
        let s = abi_signature();
        for part in [
            "rustc ",
            "target ",
            "features [",
            "sources ",
            "dependencies ",
            "TaskFns ",
        ] {
            assert!(s.contains(part), "{part} missing from {s}");
        }
    }

    #[test]
    fn a_missing_library_is_none_and_another_file_is_refused() {
        let dir = tempfile::tempdir().unwrap();
        assert!(load(&path_in(dir.path())).unwrap().is_none());
        let path = dir.path().join(file_name());
        std::fs::write(&path, b"not a library").unwrap();
        let err = format!("{:#}", load(&path).unwrap_err());
        assert!(err.contains(&path.display().to_string()), "{err}");
    }
}
