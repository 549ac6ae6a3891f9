//! The renderer's tests that need no reference solutions: bad scene input, what a scene
//! needs, watertight meshes, and the scene-loader fuzz. One test binary with a module per
//! subject. The framework's own, so not in the student handout (which has only the
//! student's tests, `tests/exercises.rs`).

mod bad_input;
mod needs;
mod scene_fuzz;
mod watertight;

/// The worker binary that runs the student's code, beside the `pbrlab` these tests run
/// (built by the first test that asks, as `pbrlab` builds it before running student code).
fn worker() -> std::path::PathBuf {
    let pbrlab = std::path::Path::new(env!("CARGO_BIN_EXE_pbrlab"));
    let built = pbrlab::cli::rebuild::ensure_student_binaries_beside(pbrlab)
        .expect("building pbrlab-worker");
    built.worker
}
