//! Triangle meshes from OBJ files (read by tobj; faces with more than three vertices are
//! split into fans here, so problems can be reported by the file's own face numbers).

use super::error::{SceneError, SceneWarning};
use crate::geometry::double_area;
use glam::{Mat4, Vec3};
use std::io::BufReader;
use std::path::Path;

/// The world-space triangles of one OBJ file.
pub struct ObjTriangles {
    /// The triangles, transformed.
    pub triangles: Vec<[Vec3; 3]>,
    /// A warning when degenerate triangles (no area) were skipped.
    pub warning: Option<SceneWarning>,
}

/// Checks every face line (`f …`) of an OBJ file's `text` before it is parsed, so that a
/// face with fewer than three vertices or a vertex index that is not a vertex defined
/// before it is reported at its line and column (the parser reports neither where).
fn check_faces(path: &Path, text: &str) -> Result<(), SceneError> {
    let mut vertices: i64 = 0;
    for (number, line) in text.lines().enumerate() {
        let line_number = number as u64 + 1;
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => vertices += 1,
            Some("f") => {
                let corners: Vec<&str> = words.collect();
                let column =
                    |word: &str| (word.as_ptr() as usize - line.as_ptr() as usize) as u64 + 1;
                let error = |col: u64, message: String| {
                    Err(SceneError::at(path, text, line_number, col, message))
                };
                if corners.len() < 3 {
                    return error(
                        1,
                        format!(
                            "a face needs at least 3 vertices, this one has {}",
                            corners.len()
                        ),
                    );
                }
                for corner in corners {
                    let index = corner.split('/').next().unwrap_or_default();
                    let valid = match index.parse::<i64>() {
                        Ok(i) if i > 0 => i <= vertices,
                        Ok(i) if i < 0 => -i <= vertices,
                        _ => false,
                    };
                    if !valid {
                        return error(
                            column(corner),
                            format!(
                                "vertex index `{index}` is not one of the {vertices} vertices \
                                 defined above this line (indices count from 1, or from -1 \
                                 backwards)"
                            ),
                        );
                    }
                }
            }
            _ => {}
        }
    }
    Ok(())
}

/// Reads the OBJ file at `path` and places it with `transform`. Degenerate triangles are
/// skipped and counted; a non-finite vertex or an empty result is an error.
pub fn load_obj(path: &Path, transform: &Mat4) -> Result<ObjTriangles, SceneError> {
    let bytes = std::fs::read(path)
        .map_err(|e| SceneError::file(path, format!("cannot open the mesh: {e}")))?;
    check_faces(path, &String::from_utf8_lossy(&bytes))?;
    let options = tobj::LoadOptions {
        single_index: true,
        triangulate: false,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _materials) =
        tobj::load_obj_buf(&mut BufReader::new(&bytes[..]), &options, |_| {
            // Materials come from the scene file; .mtl files are not read.
            Err(tobj::LoadError::GenericFailure)
        })
        .map_err(|e| SceneError::file(path, format!("not a valid OBJ file: {e}")))?;

    let mut triangles = Vec::new();
    let mut degenerate = 0usize;
    let mut first_degenerate = None;
    for model in &models {
        let mesh = &model.mesh;
        let vertex = |i: u32| -> Option<Vec3> {
            let i = i as usize * 3;
            let p = Vec3::new(
                *mesh.positions.get(i)?,
                *mesh.positions.get(i + 1)?,
                *mesh.positions.get(i + 2)?,
            );
            Some(transform.transform_point3(p))
        };
        let arities: Vec<u32> = if mesh.face_arities.is_empty() {
            vec![3; mesh.indices.len() / 3]
        } else {
            mesh.face_arities.clone()
        };
        let mut start = 0usize;
        for (face, &arity) in arities.iter().enumerate() {
            let face_number = face + 1;
            let indices = mesh
                .indices
                .get(start..start + arity as usize)
                .ok_or_else(|| {
                    SceneError::face(
                        path,
                        &model.name,
                        face_number,
                        "the face's vertex list is cut short",
                    )
                })?;
            start += arity as usize;
            let corners: Vec<Vec3> = indices
                .iter()
                .map(|&i| vertex(i))
                .collect::<Option<_>>()
                .ok_or_else(|| {
                    SceneError::face(
                        path,
                        &model.name,
                        face_number,
                        "a vertex index is out of range",
                    )
                })?;
            if corners.iter().any(|c| !c.is_finite()) {
                return Err(SceneError::face(
                    path,
                    &model.name,
                    face_number,
                    "a vertex position is not a finite number",
                ));
            }
            for k in 1..corners.len().saturating_sub(1) {
                let tri = [corners[0], corners[k], corners[k + 1]];
                let longest = (tri[1] - tri[0])
                    .length_squared()
                    .max((tri[2] - tri[1]).length_squared())
                    .max((tri[0] - tri[2]).length_squared()) as f64;
                if double_area(&tri) <= 1e-10 * longest || longest == 0.0 {
                    degenerate += 1;
                    first_degenerate.get_or_insert((model.name.clone(), face_number));
                } else {
                    triangles.push(tri);
                }
            }
        }
    }
    if triangles.is_empty() {
        return Err(SceneError::file(
            path,
            if degenerate > 0 {
                format!("every one of its {degenerate} triangles is degenerate (no area)")
            } else {
                "the mesh has no faces".to_string()
            },
        ));
    }
    let warning = first_degenerate.map(|(object, face)| {
        SceneError::face(
            path,
            &object,
            face,
            format!("skipped {degenerate} degenerate triangle(s) with no area (the first is here)"),
        )
    });
    Ok(ObjTriangles { triangles, warning })
}
