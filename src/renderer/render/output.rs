//! Image files: EXR (linear f32, the truth) and PNG (sRGB, clamped, for looking), each
//! written atomically: into a temporary file in the same directory, then renamed, so an
//! interrupted write never leaves a truncated image.

use super::Image;
use anyhow::{Context, Result};
use image::{ImageFormat, Rgb32FImage, RgbImage};
use std::io::Seek;
use std::path::{Path, PathBuf};

/// The sRGB encoding of a linear value in [0, 1].
pub fn linear_to_srgb(c: f32) -> f32 {
    let c = c.clamp(0.0, 1.0);
    if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    }
}

/// Writes `image` as a linear RGB f32 OpenEXR file.
pub fn write_exr(path: &Path, image: &Image) -> Result<()> {
    let data: Vec<f32> = image.pixels.iter().flat_map(|p| p.to_array()).collect();
    let buffer = Rgb32FImage::from_raw(image.width, image.height, data)
        .context("image size does not match its pixels")?;
    crate::atomic_file::write_with(path, |w| {
        w.rewind()?;
        buffer
            .write_to(w, ImageFormat::OpenExr)
            .with_context(|| format!("cannot encode {}", path.display()))
    })
}

/// Writes `image` as an 8-bit sRGB PNG, values clamped to [0, 1].
pub fn write_png(path: &Path, image: &Image) -> Result<()> {
    let data: Vec<u8> = image
        .pixels
        .iter()
        .flat_map(|p| p.to_array())
        .map(|c| (linear_to_srgb(c) * 255.0 + 0.5) as u8)
        .collect();
    let buffer = RgbImage::from_raw(image.width, image.height, data)
        .context("image size does not match its pixels")?;
    crate::atomic_file::write_with(path, |w| {
        buffer
            .write_to(w, ImageFormat::Png)
            .with_context(|| format!("cannot encode {}", path.display()))
    })
}

/// Writes the EXR at `path` (its extension replaced by `.exr`) and the PNG preview beside
/// it; returns both paths.
pub fn write_both(path: &Path, image: &Image) -> Result<(PathBuf, PathBuf)> {
    let exr = path.with_extension("exr");
    let png = path.with_extension("png");
    write_exr(&exr, image)?;
    write_png(&png, image)?;
    Ok((exr, png))
}
