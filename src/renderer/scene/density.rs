//! Density grids for heterogeneous media: read from a text file or made procedurally.
//!
//! The file format: after optional `#` comments, three integers `nx ny nz` (each 2 to 256),
//! then `nx·ny·nz` numbers ≥ 0, x varying fastest, then y, then z, separated by any
//! whitespace. Grid points sit on the corners and faces of the shape's bounding box.

use super::error::SceneError;
use super::text_file::{self, Token};
use crate::medium::DensityGrid;
use crate::sampling::Sampler;
use glam::Vec3;
use std::path::Path;

/// Largest grid resolution per axis.
pub const MAX_RESOLUTION: usize = 256;

/// Reads a density grid file.
pub fn load_grid(path: &Path) -> Result<DensityGrid, SceneError> {
    let source = text_file::read(path, "density grid")?;
    let tokens: Vec<Token<'_>> = text_file::tokenize(&source).into_iter().flatten().collect();
    let Some(header) = tokens.get(..3) else {
        return Err(SceneError::file(
            path,
            "expected the resolution `nx ny nz` first",
        ));
    };
    let mut res = [0usize; 3];
    for (r, tok) in res.iter_mut().zip(header) {
        *r = match tok.text.parse::<usize>() {
            Ok(v) if (2..=MAX_RESOLUTION).contains(&v) => v,
            _ => {
                return Err(SceneError::at(
                    path,
                    &source,
                    tok.line,
                    tok.column,
                    format!(
                        "a grid resolution must be an integer from 2 to {MAX_RESOLUTION}, found `{}`",
                        tok.text
                    ),
                ));
            }
        };
    }
    let count = res[0] * res[1] * res[2];
    let values = &tokens[3..];
    if values.len() != count {
        let (line, column) = values
            .get(count)
            .or(values.last())
            .map_or((header[2].line, header[2].column), |t| (t.line, t.column));
        return Err(SceneError::at(
            path,
            &source,
            line,
            column,
            format!(
                "a {}×{}×{} grid has {count} values, the file has {}",
                res[0],
                res[1],
                res[2],
                values.len()
            ),
        ));
    }
    let mut data = Vec::with_capacity(count);
    for tok in values {
        let v = text_file::number(path, &source, tok)?;
        if v < 0.0 {
            return Err(SceneError::at(
                path,
                &source,
                tok.line,
                tok.column,
                format!("a density must be ≥ 0, found {v}"),
            ));
        }
        data.push(v);
    }
    DensityGrid::new(res, data).ok_or_else(|| SceneError::file(path, "invalid density grid"))
}

/// A procedural cloud: fractal value noise under a spherical falloff from the box centre,
/// values in [0, 1]. The same parameters always give the same grid; `None` when
/// `resolution < 2`.
pub fn cloud(resolution: usize, seed: u64, frequency: f32, octaves: u32) -> Option<DensityGrid> {
    let noise = ValueNoise::new(seed);
    let n = resolution;
    let mut data = Vec::with_capacity(n * n * n);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let u = Vec3::new(x as f32, y as f32, z as f32) / (n - 1) as f32;
                let r = ((u - 0.5) * 2.0).length();
                let mut amplitude = 0.5;
                let mut f = frequency;
                let mut value = 0.0;
                for _ in 0..octaves {
                    value += amplitude * noise.at(u * f);
                    amplitude *= 0.5;
                    f *= 2.0;
                }
                let total = 1.0 - 0.5f32.powi(octaves as i32);
                let v = value / total;
                data.push((2.0 * (1.0 - r) - 0.6 + 1.2 * (v - 0.5)).clamp(0.0, 1.0));
            }
        }
    }
    DensityGrid::new([n; 3], data)
}

/// Value noise: random values on the integer lattice, smoothly interpolated.
struct ValueNoise {
    table: Vec<f32>,
    perm: Vec<usize>,
}

impl ValueNoise {
    const SIZE: usize = 256;

    fn new(seed: u64) -> Self {
        let mut sampler = Sampler::new(seed, 0x6e_6f69_7365);
        let table = (0..Self::SIZE).map(|_| sampler.next_1d()).collect();
        let mut perm: Vec<usize> = (0..Self::SIZE).collect();
        for i in (1..Self::SIZE).rev() {
            let j = ((sampler.next_1d() * (i + 1) as f32) as usize).min(i);
            perm.swap(i, j);
        }
        Self { table, perm }
    }

    fn lattice(&self, x: i64, y: i64, z: i64) -> f32 {
        let m = Self::SIZE as i64;
        let h = self.perm[x.rem_euclid(m) as usize];
        let h = self.perm[(h as i64 + y).rem_euclid(m) as usize];
        let h = self.perm[(h as i64 + z).rem_euclid(m) as usize];
        self.table[h]
    }

    fn at(&self, p: Vec3) -> f32 {
        let base = p.floor();
        let f = p - base;
        let s = f * f * (Vec3::splat(3.0) - 2.0 * f);
        let (x, y, z) = (base.x as i64, base.y as i64, base.z as i64);
        let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
        let c = |dx, dy, dz| self.lattice(x + dx, y + dy, z + dz);
        lerp(
            lerp(
                lerp(c(0, 0, 0), c(1, 0, 0), s.x),
                lerp(c(0, 1, 0), c(1, 1, 0), s.x),
                s.y,
            ),
            lerp(
                lerp(c(0, 0, 1), c(1, 0, 1), s.x),
                lerp(c(0, 1, 1), c(1, 1, 1), s.x),
                s.y,
            ),
            s.z,
        )
    }
}
