//! Hair strands: generated (a ball of curly hair) or read from a text file.
//!
//! The file format: one vertex `x y z` per line; a blank line ends a strand; `#` starts a
//! comment. Every strand needs at least two vertices. Consecutive vertices are joined by
//! straight fibre segments.

use super::error::SceneError;
use super::text_file;
use crate::sampling::{Sampler, uniform_sphere};
use glam::Vec3;
use std::path::Path;

/// Most fibre segments a scene may have in all.
pub const MAX_SEGMENTS: usize = 2_000_000;

/// Reads a strand file into polylines.
pub fn load_strands(path: &Path) -> Result<Vec<Vec<Vec3>>, SceneError> {
    let source = text_file::read(path, "strand file")?;
    let mut strands = Vec::new();
    let mut current: Vec<Vec3> = Vec::new();
    let mut current_start = (1u64, 1u64);
    let finish =
        |strand: Vec<Vec3>, at: (u64, u64), strands: &mut Vec<Vec<Vec3>>| match strand.len() {
            0 => Ok(()),
            1 => Err(SceneError::at(
                path,
                &source,
                at.0,
                at.1,
                "a strand needs at least two vertices",
            )),
            _ => {
                strands.push(strand);
                Ok(())
            }
        };
    for line in text_file::tokenize(&source) {
        if line.is_empty() {
            finish(std::mem::take(&mut current), current_start, &mut strands)?;
            continue;
        }
        if line.len() != 3 {
            return Err(SceneError::at(
                path,
                &source,
                line[0].line,
                line[0].column,
                format!("expected a vertex `x y z`, found {} number(s)", line.len()),
            ));
        }
        if current.is_empty() {
            current_start = (line[0].line, line[0].column);
        }
        let mut v = [0.0f32; 3];
        for (slot, tok) in v.iter_mut().zip(&line) {
            *slot = text_file::number(path, &source, tok)?;
        }
        current.push(Vec3::from(v));
    }
    finish(current, current_start, &mut strands)?;
    if strands.is_empty() {
        return Err(SceneError::file(path, "the file has no strands"));
    }
    Ok(strands)
}

/// A ball of hair: `count` strands rooted uniformly on the sphere (`center`, `radius`),
/// each of `segments` straight pieces of total length `length`, growing outwards and
/// turning randomly by up to `curl` radians per unit length.
pub fn ball(
    center: Vec3,
    radius: f32,
    count: usize,
    length: f32,
    segments: usize,
    curl: f32,
    seed: u64,
) -> Vec<Vec<Vec3>> {
    let mut sampler = Sampler::new(seed, 0x6861_6972);
    let step = length / segments as f32;
    (0..count)
        .map(|_| {
            let normal = uniform_sphere(sampler.next_2d());
            let mut p = center + radius * normal;
            let mut dir = normal;
            let mut strand = Vec::with_capacity(segments + 1);
            strand.push(p);
            for _ in 0..segments {
                let kick = uniform_sphere(sampler.next_2d());
                dir = (dir + curl * step * kick).normalize_or(dir);
                p += step * dir;
                strand.push(p);
            }
            strand
        })
        .collect()
}
