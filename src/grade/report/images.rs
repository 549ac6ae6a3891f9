//! PNG files for the HTML report: a render, the reference, and the false-colour difference.

use crate::grade::image_check::{ImageStats, false_colour};
use anyhow::Context;
use std::path::Path;

/// Linear RGB to 8-bit sRGB, clamped (for looking only: EXR is the truth).
pub fn to_srgb8(linear: &[f32]) -> Vec<u8> {
    linear
        .iter()
        .map(|&x| {
            let x = if x.is_finite() {
                x.clamp(0.0, 1.0)
            } else {
                0.0
            };
            let s = if x <= 0.003_130_8 {
                12.92 * x
            } else {
                1.055 * x.powf(1.0 / 2.4) - 0.055
            };
            (255.0 * s + 0.5) as u8
        })
        .collect()
}

fn write_png(path: &Path, width: usize, height: usize, rgb: Vec<u8>) -> anyhow::Result<()> {
    let image = image::RgbImage::from_raw(width as u32, height as u32, rgb)
        .context("image size does not match its pixels")?;
    image
        .save(path)
        .with_context(|| format!("writing {}", path.display()))
}

/// Writes `<name>-student.png`, `<name>-reference.png` and `<name>-difference.png` into
/// `dir` and returns their file names (relative to `dir`, as the HTML page links them).
pub fn write_triple(
    dir: &Path,
    name: &str,
    student: &ImageStats,
    reference: &ImageStats,
    z: &[f64],
) -> anyhow::Result<Vec<String>> {
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let stem: String = name
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    let files = [
        (format!("{stem}-student.png"), to_srgb8(&student.mean)),
        (format!("{stem}-reference.png"), to_srgb8(&reference.mean)),
        (format!("{stem}-difference.png"), false_colour(z)),
    ];
    let mut names = Vec::new();
    for (file, rgb) in files {
        write_png(&dir.join(&file), student.width, student.height, rgb)?;
        names.push(file);
    }
    Ok(names)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn srgb_encoding_endpoints() {
        assert_eq!(to_srgb8(&[0.0, 1.0, 2.0, f32::NAN]), vec![0, 255, 255, 0]);
        assert_eq!(to_srgb8(&[0.2159])[0], 128);
    }

    #[test]
    fn a_triple_is_written() {
        let dir = tempfile::tempdir().unwrap();
        let img = ImageStats {
            width: 2,
            height: 1,
            mean: vec![0.5; 6],
            variance: vec![0.01; 6],
        };
        let files = write_triple(dir.path(), "cornell box", &img, &img, &[0.0; 6]).unwrap();
        assert_eq!(files[0], "cornell_box-student.png");
        for f in files {
            assert!(dir.path().join(f).exists());
        }
    }
}
