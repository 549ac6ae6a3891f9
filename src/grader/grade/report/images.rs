//! Pictures for the HTML report of a render check: the render, the reference, the
//! false-colour z-map, the map of failed pixel-channels (PNG), and the values behind them
//! (JSON), which the page reads for the value under the cursor.

use crate::grade::image_check::{ImageStats, Z_CRITICAL};
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

/// The map of failed pixel-channels: yellow where any channel's |z| exceeds the per-pixel
/// critical value (or is not finite), dark grey elsewhere.
pub fn failed_mask(z: &[f64]) -> Vec<u8> {
    z.chunks(3)
        .flat_map(|px| {
            if px.iter().any(|z| z.is_nan() || z.abs() > Z_CRITICAL) {
                [255, 210, 0]
            } else {
                [40, 40, 40]
            }
        })
        .collect()
}

/// The values of a render check's pictures, per pixel-channel (row-major, RGB): what the
/// page shows under the cursor. Non-finite values are written as null.
#[derive(serde::Serialize)]
struct Values<'a> {
    width: usize,
    height: usize,
    student: &'a [f32],
    reference: &'a [f32],
    z: &'a [f64],
}

/// Writes `<name>-student.png`, `<name>-reference.png`, `<name>-difference.png` (the
/// z-map), `<name>-failed.png` and `<name>-values.json` into `dir` and returns their file
/// names (relative to `dir`), in that order.
pub fn write_pictures(
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
        (format!("{stem}-failed.png"), failed_mask(z)),
    ];
    let mut names = Vec::new();
    for (file, rgb) in files {
        write_png(&dir.join(&file), student.width, student.height, rgb)?;
        names.push(file);
    }
    let values = Values {
        width: student.width,
        height: student.height,
        student: &student.mean,
        reference: &reference.mean,
        z,
    };
    let json = format!("{stem}-values.json");
    crate::atomic_file::write(&dir.join(&json), serde_json::to_string(&values)?.as_bytes())?;
    names.push(json);
    Ok(names)
}

/// A false-colour picture of per-pixel-channel z-scores (3 per pixel): for each pixel the
/// channel with the largest |z|, blue where the student is too dark, red where too bright,
/// white where they agree, saturating at |z| = 2 `Z_CRITICAL`; non-finite pixels are green.
/// Returns 8-bit RGB, row-major.
pub fn false_colour(z: &[f64]) -> Vec<u8> {
    z.chunks(3)
        .flat_map(|px| {
            let zi = px
                .iter()
                .copied()
                .max_by(|a, b| a.abs().total_cmp(&b.abs()))
                .unwrap_or(0.0);
            if !zi.is_finite() {
                return [0, 200, 0];
            }
            let t = (zi.abs() / (2.0 * Z_CRITICAL)).min(1.0);
            let fade = (255.0 * (1.0 - t)) as u8;
            if zi > 0.0 {
                [255, fade, fade]
            } else {
                [fade, fade, 255]
            }
        })
        .collect()
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
    fn the_pictures_and_values_are_written() {
        let dir = tempfile::tempdir().unwrap();
        let img = ImageStats {
            width: 2,
            height: 1,
            mean: vec![0.5; 6],
            variance: vec![0.01; 6],
        };
        let files = write_pictures(
            dir.path(),
            "cornell box",
            &img,
            &img,
            &[0.0, f64::NAN, 0.0, 0.0, 9.0, 0.0],
        )
        .unwrap();
        assert_eq!(files[0], "cornell_box-student.png");
        assert_eq!(files.len(), 5);
        let values = std::fs::read_to_string(dir.path().join(&files[4])).unwrap();
        assert!(
            values.contains("\"z\":[0.0,null,0.0,0.0,9.0,0.0]"),
            "{values}"
        );
        assert_eq!(
            failed_mask(&[0.0, 0.0, 0.0, 0.0, 9.0, 0.0])[..6],
            [40, 40, 40, 255, 210, 0]
        );
        for f in files {
            assert!(dir.path().join(f).exists());
        }
    }
}
