//! Image files: EXR (linear f32, the truth) and PNG (sRGB, clamped, for looking), each
//! written atomically: into a temporary file in the same directory, then renamed, so an
//! interrupted write never leaves a truncated image.

use super::Image;
use anyhow::{Context, Result};
use image::{ImageFormat, Rgb32FImage, RgbImage};
use std::io::{BufWriter, Seek, Write};
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

fn write_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<std::fs::File>) -> Result<()>,
) -> Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    std::fs::create_dir_all(&dir).with_context(|| format!("cannot create {}", dir.display()))?;
    let tmp = tempfile::NamedTempFile::new_in(&dir)
        .with_context(|| format!("cannot create a temporary file in {}", dir.display()))?;
    let mut writer = BufWriter::new(tmp.reopen()?);
    write(&mut writer)?;
    writer.flush()?;
    writer.get_ref().sync_all()?;
    // Temporary files are private (0600); an image is not.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(tmp.path(), std::fs::Permissions::from_mode(0o644))?;
    }
    tmp.persist(path)
        .with_context(|| format!("cannot write {}", path.display()))?;
    Ok(())
}

/// Writes `image` as a linear RGB f32 OpenEXR file.
pub fn write_exr(path: &Path, image: &Image) -> Result<()> {
    let data: Vec<f32> = image.pixels.iter().flat_map(|p| p.to_array()).collect();
    let buffer = Rgb32FImage::from_raw(image.width, image.height, data)
        .context("image size does not match its pixels")?;
    write_atomically(path, |w| {
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
    write_atomically(path, |w| {
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
