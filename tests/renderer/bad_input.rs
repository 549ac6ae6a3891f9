//! Every kind of bad scene input gets an error that names the file and the line and column
//! (or, for an OBJ model, the face), and says what is wrong. Nothing panics.

use pbrlab::scene::{LoadOptions, Position, Scene, SceneError};
use std::path::{Path, PathBuf};

const CAMERA: &str = "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 8, height: 8}\n";

fn load_text(text: &str) -> Result<Scene, SceneError> {
    Scene::from_yaml(Path::new("bad.yaml"), text, &LoadOptions::default())
}

fn error_of(text: &str) -> SceneError {
    match load_text(text) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e,
    }
}

/// Asserts the error is at `line:column` of bad.yaml and mentions `words`.
fn assert_error_at(text: &str, line: u64, column: u64, words: &str) {
    let e = error_of(text);
    assert_eq!(e.file, PathBuf::from("bad.yaml"));
    assert_eq!(e.position, Position::LineColumn { line, column }, "{e}");
    assert!(e.message.contains(words), "`{words}` not in: {e}");
    let shown = e.to_string();
    assert!(
        shown.starts_with(&format!("bad.yaml:{line}:{column}: ")),
        "{shown}"
    );
    assert!(shown.contains(" | "), "no excerpt in: {shown}");
}

#[test]
fn unknown_key() {
    let text =
        format!("{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, colour: red}}\n");
    assert_error_at(&text, 3, 44, "unknown field `colour`");
}

#[test]
fn unknown_shape_kind() {
    let text = format!("{CAMERA}shapes:\n  - cylinder: {{radius: 1}}\n");
    assert_error_at(&text, 3, 5, "unknown variant `cylinder`");
}

#[test]
fn negative_radius() {
    let text = format!(
        "{CAMERA}materials: {{m: {{diffuse: {{albedo: 0.5}}}}}}\nshapes:\n  - sphere:\n      center: [0, 0, 0]\n      radius: -1\n      material: m\n"
    );
    assert_error_at(&text, 6, 15, "> 0");
}

#[test]
fn nan_and_infinity() {
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, .nan, 0], radius: 1}}\n");
    let e = error_of(&text);
    assert!(
        matches!(e.position, Position::LineColumn { line: 3, .. }),
        "{e}"
    );
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: .inf}}\n");
    assert_error_at(&text, 3, 41, "finite");
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1e60}}\n");
    assert_error_at(&text, 3, 41, "finite");
}

#[test]
fn ior_not_positive() {
    let text = format!("{CAMERA}materials:\n  glass: {{dielectric: {{ior: 0}}}}\n");
    assert_error_at(&text, 3, 29, "index of refraction");
    let text = format!("{CAMERA}materials:\n  glass: {{dielectric: {{ior: 1.5, ext_ior: -1}}}}\n");
    assert_error_at(&text, 3, 43, "index of refraction");
}

#[test]
fn albedo_above_one_is_a_warning() {
    let text = format!(
        "{CAMERA}materials:\n  hot: {{diffuse: {{albedo: [1.2, 0.5, 0.5]}}}}\nshapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, material: hot}}\nlights:\n  - environment: {{radiance: 1}}\n"
    );
    let scene = load_text(&text).expect("an albedo above 1 loads");
    let w = &scene.warnings()[0];
    assert_eq!(
        w.position,
        Position::LineColumn {
            line: 3,
            column: 27
        },
        "{w}"
    );
    assert!(w.message.contains("albedo above 1"), "{w}");
}

#[test]
fn unknown_material_name() {
    let text = format!(
        "{CAMERA}materials:\n  white: {{diffuse: {{albedo: 0.5}}}}\nshapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, material: whte}}\n"
    );
    assert_error_at(
        &text,
        5,
        54,
        "no material is named `whte`; the materials are: white",
    );
}

#[test]
fn unknown_medium_name() {
    let text = format!(
        "{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, medium: fog}}\nlights:\n  - point: {{position: [0, 3, 0], intensity: 1}}\n"
    );
    assert_error_at(
        &text,
        3,
        52,
        "no medium is named `fog`; the media are: (none)",
    );
}

#[test]
fn shape_without_surface() {
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1}}\n");
    assert_error_at(&text, 3, 5, "no material");
}

#[test]
fn degenerate_quad_and_box() {
    let text = format!(
        "{CAMERA}lights: [environment: {{radiance: 1}}]\nshapes:\n  - quad: {{origin: [0, 0, 0], edge1: [1, 0, 0], edge2: [2, 0, 0], emission: 1}}\n"
    );
    assert_error_at(&text, 4, 5, "no area");
    let text =
        format!("{CAMERA}shapes:\n  - box: {{min: [0, 0, 0], max: [1, 0, 1], emission: 1}}\n");
    assert_error_at(&text, 3, 5, "min < max");
}

#[test]
fn empty_scene_and_empty_file() {
    let e = error_of(CAMERA);
    assert_eq!(e.position, Position::File);
    assert!(
        e.to_string().starts_with("bad.yaml: the scene is empty"),
        "{e}"
    );
    let e = error_of("  \n");
    assert!(e.to_string().contains("empty"), "{e}");
}

#[test]
fn camera_problems() {
    let e = error_of(
        "camera: {eye: [0, 0, 0], target: [0, 0, 0], fov: 40, width: 8, height: 8}\nlights: [environment: {radiance: 1}]\n",
    );
    assert_eq!(
        e.position,
        Position::LineColumn {
            line: 1,
            column: 15
        },
        "{e}"
    );
    let e = error_of(
        "camera: {eye: [0, 5, 0], target: [0, 0, 0], up: [0, 1, 0], fov: 40, width: 8, height: 8}\nlights: [environment: {radiance: 1}]\n",
    );
    assert!(e.message.contains("parallel"), "{e}");
    let e =
        error_of("camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 180, width: 8, height: 8}\n");
    assert!(e.message.contains("field of view"), "{e}");
    let e = error_of(
        "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 0, height: 8}\nlights: [environment: {radiance: 1}]\n",
    );
    assert!(e.message.contains("width"), "{e}");
}

#[test]
fn yaml_syntax_error() {
    let e = error_of("camera: {eye: [0, 0, 5]\n");
    assert!(matches!(e.position, Position::LineColumn { .. }), "{e}");
}

fn scene_dir() -> tempfile::TempDir {
    tempfile::tempdir().expect("temporary directory")
}

#[test]
fn missing_mesh_file_names_the_scene_line() {
    let dir = scene_dir();
    let scene = dir.path().join("s.yaml");
    let text = format!(
        "{CAMERA}materials: {{m: {{diffuse: {{albedo: 0.5}}}}}}\nshapes:\n  - mesh: {{file: nowhere.obj, material: m}}\n"
    );
    std::fs::write(&scene, &text).unwrap();
    let e = Scene::load(&scene, &LoadOptions::default())
        .err()
        .expect("missing mesh");
    assert_eq!(e.file, scene);
    assert_eq!(
        e.position,
        Position::LineColumn {
            line: 4,
            column: 18
        },
        "{e}"
    );
    assert!(e.message.contains("nowhere.obj"), "{e}");
}

#[test]
fn missing_scene_file() {
    let e = Scene::load(Path::new("/no/such/scene.yaml"), &LoadOptions::default())
        .err()
        .expect("missing scene");
    assert_eq!(e.position, Position::File);
    assert!(
        e.to_string()
            .starts_with("/no/such/scene.yaml: cannot read"),
        "{e}"
    );
}

fn mesh_scene(obj: &str) -> Result<Scene, SceneError> {
    let dir = scene_dir();
    std::fs::write(dir.path().join("m.obj"), obj).unwrap();
    let scene = dir.path().join("s.yaml");
    let text = format!(
        "{CAMERA}materials: {{m: {{diffuse: {{albedo: 0.5}}}}}}\nshapes:\n  - mesh: {{file: m.obj, material: m}}\nlights: [environment: {{radiance: 1}}]\n"
    );
    std::fs::write(&scene, text).unwrap();
    Scene::load(&scene, &LoadOptions::default())
}

#[test]
fn degenerate_triangles_are_skipped_and_counted() {
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 1 2 4\nf 1 4 2\n";
    let scene = mesh_scene(obj).expect("one good triangle loads");
    assert_eq!(scene.needs().triangles, 1);
    let w = &scene.warnings()[0];
    assert!(w.file.ends_with("m.obj"), "{w}");
    assert!(matches!(w.position, Position::Face { face: 2, .. }), "{w}");
    assert!(w.message.contains("skipped 2 degenerate"), "{w}");
}

#[test]
fn bad_obj_files() {
    let e = mesh_scene("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 1 2 4\n")
        .err()
        .expect("all degenerate");
    assert!(
        e.file.ends_with("m.obj") && e.message.contains("degenerate"),
        "{e}"
    );
    let e = mesh_scene("v 0 0 0\nv 1 nan 0\nv 0 1 0\nf 1 2 3\n")
        .err()
        .expect("NaN vertex");
    assert!(matches!(e.position, Position::Face { face: 1, .. }), "{e}");
    assert!(e.message.contains("finite"), "{e}");
    let e = mesh_scene("v 0 0 0\nf 1 2 3\n")
        .err()
        .expect("index out of range");
    assert!(e.file.ends_with("m.obj"), "{e}");
    let e = mesh_scene("").err().expect("no faces");
    assert!(e.file.ends_with("m.obj"), "{e}");
}

#[test]
fn bad_grid_file() {
    let dir = scene_dir();
    std::fs::write(dir.path().join("g.grid"), "2 2 2\n0 0 0 0\n0 0 -1 0\n").unwrap();
    let scene = dir.path().join("s.yaml");
    let text = format!(
        "{CAMERA}media:\n  smoke: {{grid: {{density: {{file: g.grid}}, sigma_a: 1, sigma_s: 1}}}}\nshapes:\n  - box: {{min: [-1, -1, -1], max: [1, 1, 1], medium: smoke}}\nlights: [environment: {{radiance: 1}}]\n"
    );
    std::fs::write(&scene, text).unwrap();
    let e = Scene::load(&scene, &LoadOptions::default())
        .err()
        .expect("negative density");
    assert!(e.file.ends_with("g.grid"), "{e}");
    assert_eq!(
        e.position,
        Position::LineColumn { line: 3, column: 5 },
        "{e}"
    );
}

#[test]
fn bad_strand_file() {
    let dir = scene_dir();
    std::fs::write(dir.path().join("h.txt"), "0 0 0\n0 1 0\n\n1 1 1\n\n0 0 x\n").unwrap();
    let scene = dir.path().join("s.yaml");
    let text = format!(
        "{CAMERA}materials: {{hair: {{kajiya_kay: {{kd: 0.1, ks: 0.5, exponent: 40}}}}}}\nshapes:\n  - fibres: {{strands: {{file: h.txt}}, radius: 0.01, material: hair}}\nlights: [environment: {{radiance: 1}}]\n"
    );
    std::fs::write(&scene, text).unwrap();
    let e = Scene::load(&scene, &LoadOptions::default())
        .err()
        .expect("one-vertex strand");
    assert!(e.file.ends_with("h.txt"), "{e}");
    assert_eq!(
        e.position,
        Position::LineColumn { line: 4, column: 1 },
        "{e}"
    );
}

#[test]
fn media_need_light_sampling_and_boundaries_take_no_material() {
    let media = "media:\n  fog: {homogeneous: {sigma_a: 0.1, sigma_s: 0.1}}\nmaterials: {m: {diffuse: {albedo: 0.5}}}\n";
    let text = format!(
        "{CAMERA}render: {{strategy: mis}}\n{media}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, medium: fog}}\nlights: [environment: {{radiance: 1}}]\n"
    );
    assert_error_at(&text, 2, 20, "strategy: light");
    let text = format!(
        "{CAMERA}{media}shapes:\n  - sphere: {{center: [0, 0, 0], radius: 1, medium: fog, material: m}}\n"
    );
    assert_error_at(&text, 6, 67, "no material");
}

#[test]
fn camera_inside_a_medium() {
    let text = "camera: {eye: [0, 0, 0.5], target: [0, 0, 0], fov: 40, width: 8, height: 8}\nmedia: {fog: {homogeneous: {sigma_a: 0.1, sigma_s: 0.1}}}\nshapes:\n  - sphere: {center: [0, 0, 0], radius: 1, medium: fog}\nlights: [environment: {radiance: 1}]\n";
    assert_error_at(text, 4, 5, "camera is inside");
}

#[test]
fn conductor_needs_one_roughness_and_one_colour() {
    let text = format!("{CAMERA}materials:\n  metal: {{conductor: {{roughness: 0.3}}}}\n");
    assert_error_at(&text, 3, 10, "`reflectance` or both `eta` and `k`");
    let text =
        format!("{CAMERA}materials:\n  metal: {{conductor: {{roughness: 0, reflectance: 0.9}}}}\n");
    assert_error_at(&text, 3, 34, "roughness");
}

#[test]
fn arbitrary_bytes_never_panic() {
    let samples = [
        "\u{0}\u{1}\u{2}",
        "camera: 5",
        "[1, 2, 3]",
        "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 8, height: 8}\nshapes: {a: 1}",
        "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 99999999999, height: 8}",
        "camera: &a {eye: *a}",
        "render: {spp: -3}",
    ];
    for s in samples {
        assert!(load_text(s).is_err(), "{s:?} loaded");
    }
}

#[test]
fn shapes_beyond_single_precision_are_refused_before_any_bvh() {
    let materials = "materials: {m: {diffuse: {albedo: 0.5}}}\n";
    // A hair ball centred at 3e38 crashed the BVH builder; a fibre radius of 1e8 hung it.
    for (strands, column) in [
        (
            "{ball: {center: [3e38, 0, 0], radius: 0.3, count: 4, length: 0.2, segments: 2}}, radius: 0.01",
            5,
        ),
        (
            "{ball: {center: [0, 0, 0], radius: 0.3, count: 4, length: 0.2, segments: 2}}, radius: 1e8",
            5,
        ),
    ] {
        let text = format!(
            "{CAMERA}{materials}shapes:\n  - fibres: {{strands: {strands}, material: m}}\n"
        );
        assert_error_at(&text, 4, column, "must stay within");
    }
    let text = format!(
        "{CAMERA}{materials}shapes:\n  - sphere: {{center: [0, 2e6, 0], radius: 1, material: m}}\n"
    );
    assert_error_at(&text, 4, 5, "must stay within");
    let text = format!(
        "{CAMERA}{materials}shapes:\n  - box: {{min: [0, 0, 0], max: [1, 1, 1e30], material: m}}\n"
    );
    assert_error_at(&text, 4, 5, "must stay within");
}

#[test]
fn a_mesh_moved_or_scaled_beyond_single_precision_is_refused() {
    let dir = scene_dir();
    std::fs::write(
        dir.path().join("m.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    )
    .unwrap();
    let scene = dir.path().join("s.yaml");
    for transform in ["translate: [3e38, 0, 0]", "scale: 1e38"] {
        let text = format!(
            "{CAMERA}materials: {{m: {{diffuse: {{albedo: 0.5}}}}}}\nshapes:\n  - mesh: {{file: m.obj, material: m, transform: {{{transform}}}}}\n"
        );
        std::fs::write(&scene, text).unwrap();
        let e = Scene::load(&scene, &LoadOptions::default())
            .err()
            .expect("refused");
        assert_eq!(e.file, scene);
        assert!(
            matches!(e.position, Position::LineColumn { line: 4, .. }),
            "{e}"
        );
        assert!(e.message.contains("must stay within"), "{transform}: {e}");
    }
}

#[test]
fn an_image_too_large_to_render_in_memory_is_refused() {
    let text = "camera: {eye: [0, 0, 5], target: [0, 0, 0], fov: 40, width: 8192, height: 8192}\nshapes:\n  - sphere: {center: [0, 0, 0], radius: 1}\n";
    assert_error_at(text, 1, 61, "at most 16777216");
}

#[test]
fn obj_face_errors_name_the_line_and_column() {
    for (obj, line, column, words) in [
        (
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n",
            4,
            7,
            "not one of the 3 vertices",
        ),
        ("v 0 0 0\nv 1 0 0\nf 1 2\n", 3, 1, "at least 3 vertices"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 0/2 3\n", 4, 7, "`0`"),
        ("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", 4, 9, "`-4`"),
    ] {
        let e = mesh_scene(obj).err().expect("refused");
        assert!(e.file.ends_with("m.obj"), "{e}");
        assert_eq!(
            e.position,
            Position::LineColumn { line, column },
            "{obj}: {e}"
        );
        assert!(e.message.contains(words), "{obj}: {e}");
    }
    // Relative indices that do name a vertex load.
    assert!(mesh_scene("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n").is_ok());
}

#[test]
fn a_scene_too_large_for_the_yaml_loader_says_so() {
    let sphere = "  - sphere: {center: [0, 0, 0], radius: 1}\n";
    let text = format!("{CAMERA}shapes:\n{}", sphere.repeat(60_000));
    let e = error_of(&text);
    assert!(e.message.contains("too large for the loader"), "{e}");
    assert!(e.message.contains("OBJ"), "{e}");
}

#[test]
fn a_quoted_number_is_text_not_a_number() {
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, 0, 0], radius: \"0.5\"}}\n");
    assert_error_at(&text, 3, 41, "without quotes");
    let text = format!("{CAMERA}shapes:\n  - sphere: {{center: [0, '1', 0], radius: 1}}\n");
    assert_error_at(&text, 3, 26, "found the text `1`");
}

#[test]
fn a_megabyte_key_is_named_and_its_line_is_not_printed_whole() {
    let key = "k".repeat(1 << 20);
    let text = format!("camera:\n  fov: 40\n{key}: 1\n");
    let e = error_of(&text);
    let shown = e.to_string();
    assert!(
        shown.contains(&format!("line 3 is {} characters long", (1 << 20) + 3)),
        "{}",
        &shown[..shown.len().min(400)]
    );
    assert!(
        shown.len() < 1000,
        "the excerpt is a window, not the line: {} bytes",
        shown.len()
    );
}
