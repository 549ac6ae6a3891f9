//! Instructor test: the stored reference renders of the graded scenes
//! (src/grader/renders/<scene>.{mean,variance}.exr) agree with fresh reference renders
//! by the grader's own image check, and a biased render (or a wrong path tracer) does not.
//!
//! Missing files are written; after a deliberate change to a scene or the reference,
//! rewrite them with `PBRLAB_UPDATE_RENDERS=1 cargo test --release --test instructor renders::`
//! and commit them: `build.rs` embeds them in the grader. Not part of the student handout.

use pbrlab::grade::image_check;
use pbrlab::grade::render_check::{from_exr, write_reference};
use pbrlab::grade::renders::{
    REFERENCE_SEED, REFERENCE_SPP, RENDER_CHECKS, STUDENT_SPP, load, render_stats,
};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

#[test]
fn stored_reference_renders_agree_with_fresh_ones() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/grader/renders");
    let update = std::env::var_os("PBRLAB_UPDATE_RENDERS").is_some();
    for check in RENDER_CHECKS {
        let scene = load(check.scene).expect("a graded scene loads");
        let mean = dir.join(format!("{}.mean.exr", check.scene));
        if update || !mean.exists() {
            let (stats, rejected) = render_stats(&scene, &Reference, REFERENCE_SPP, REFERENCE_SEED);
            assert_eq!(
                rejected, 0,
                "{}: the reference dropped samples",
                check.scene
            );
            write_reference(&dir, check.scene, &stats).expect("reference render written");
        }
        let read =
            |kind: &str| std::fs::read(dir.join(format!("{}.{kind}.exr", check.scene))).unwrap();
        let stored = from_exr(&read("mean"), &read("variance")).expect("stored render reads");
        let (fresh, _) = render_stats(&scene, &Reference, STUDENT_SPP, 12345);
        let (detail, _) = image_check::compare(check.scene, &fresh, &stored).unwrap();
        assert!(detail.passed(), "{}", detail.describe());
        // Ten percent too bright is caught.
        let mut bright = fresh.clone();
        bright.mean.iter_mut().for_each(|m| *m *= 1.1);
        let (detail, _) = image_check::compare(check.scene, &bright, &stored).unwrap();
        assert!(
            !detail.passed(),
            "{}: a 10 % brighter render passes: {}",
            check.scene,
            detail.describe()
        );
    }
}

#[test]
fn a_wrong_path_tracer_fails_the_render_check() {
    let wrong = crate::support::variants::wrong()
        .into_iter()
        .find(|w| w.name == "emission counted twice")
        .expect("the double-counting slip");
    let result = pbrlab::grade::render_check::check(&wrong.patch, "cornell", 7, None);
    assert!(!result.passed, "{}", result.summary);
    let right = pbrlab::grade::render_check::check(&Reference, "cornell", 7, None);
    assert!(right.passed, "{}", right.summary);
}
