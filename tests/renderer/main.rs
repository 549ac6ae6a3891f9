//! The renderer's tests that need no reference solutions, so the student handout keeps
//! them: bad scene input, what a scene needs, watertight meshes, and the scene-loader fuzz.
//! One test binary with a module per subject.

mod bad_input;
mod needs;
mod scene_fuzz;
mod watertight;
