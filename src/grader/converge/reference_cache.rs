//! The high-sample reference image of a scene study, rendered once and kept beside the
//! study's output (`reference.exr` and `reference.json`), reused while the scene file and
//! the reference settings are unchanged.

use crate::render::Image;
use crate::render::output::write_exr;
use anyhow::{Context, Result};
use glam::Vec3;
use serde::{Deserialize, Serialize};
use std::hash::{DefaultHasher, Hash, Hasher};
use std::path::Path;

/// What a cached reference was rendered from; a cache whose key differs is re-rendered.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct ReferenceKey {
    /// Hash of the scene file's text.
    pub scene_hash: String,
    /// Image size.
    pub width: u32,
    /// Image size.
    pub height: u32,
    /// Samples per pixel of the reference.
    pub spp: u32,
    /// Seed of the reference render.
    pub seed: u64,
    /// Which implementation rendered it, and with which settings.
    pub renderer: String,
    /// The pbrlab version that rendered it.
    pub version: String,
}

/// What `reference.json` holds: the key, and the relMSE the reference's own noise adds
/// to every measurement against it.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct CacheRecord {
    key: ReferenceKey,
    rel_mse_floor: f64,
}

/// A cached or freshly rendered reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// The image.
    pub image: Image,
    /// Expected relMSE the reference's own noise adds to a measurement against it (see
    /// [`rel_mse_floor`]).
    pub rel_mse_floor: f64,
    /// True when it came from the cache.
    pub cached: bool,
}

/// The expected relMSE that the noise of a reference adds to any estimate measured against
/// it: the mean over channels of `Var(r) / (r² + ε)`, with `variance` the per-sample
/// variance of each channel and `spp` the samples averaged.
pub fn rel_mse_floor(mean: &Image, variance: &Image, spp: u32) -> f64 {
    let n = (mean.pixels.len() * 3).max(1) as f64;
    let sum: f64 = mean
        .pixels
        .iter()
        .zip(&variance.pixels)
        .flat_map(|(m, v)| (0..3).map(move |c| (m[c] as f64, v[c] as f64)))
        .map(|(m, v)| v / spp.max(1) as f64 / (m * m + super::metrics::REL_MSE_EPSILON))
        .sum();
    sum / n
}

/// A hash of `text` for [`ReferenceKey::scene_hash`]. Not stable across Rust releases,
/// which only costs a re-render.
pub fn text_hash(text: &str) -> String {
    let mut h = DefaultHasher::new();
    text.hash(&mut h);
    format!("{:016x}", h.finish())
}

/// Reads an RGB EXR into an [`Image`].
pub fn read_exr(path: &Path) -> Result<Image> {
    let img = image::open(path)
        .with_context(|| format!("cannot read the reference image {}", path.display()))?
        .into_rgb32f();
    let (width, height) = img.dimensions();
    let pixels = img.pixels().map(|p| Vec3::from_array(p.0)).collect();
    Ok(Image {
        width,
        height,
        pixels,
    })
}

/// The reference for `key`: read from `dir` when `reference.json` there holds the same key,
/// otherwise rendered by `render` (which returns the image and its [`rel_mse_floor`]) and
/// written to `dir`.
pub fn cached_reference(
    dir: &Path,
    key: &ReferenceKey,
    render: impl FnOnce() -> Result<(Image, f64)>,
) -> Result<Reference> {
    let (exr, json) = (dir.join("reference.exr"), dir.join("reference.json"));
    let stored: Option<CacheRecord> = std::fs::read_to_string(&json)
        .ok()
        .and_then(|text| serde_json::from_str(&text).ok());
    if let Some(record) = stored
        && record.key == *key
        && let Ok(image) = read_exr(&exr)
        && (image.width, image.height) == (key.width, key.height)
    {
        return Ok(Reference {
            image,
            rel_mse_floor: record.rel_mse_floor,
            cached: true,
        });
    }
    let (image, rel_mse_floor) = render()?;
    write_exr(&exr, &image)?;
    let record = CacheRecord {
        key: key.clone(),
        rel_mse_floor,
    };
    std::fs::write(&json, serde_json::to_string_pretty(&record)?)
        .with_context(|| format!("cannot write {}", json.display()))?;
    Ok(Reference {
        image,
        rel_mse_floor,
        cached: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_reference_is_rendered_once_then_read_back() {
        let dir = tempfile::tempdir().unwrap();
        let key = ReferenceKey {
            scene_hash: text_hash("scene"),
            width: 2,
            height: 1,
            spp: 8,
            seed: 1,
            renderer: "test".into(),
            version: "0".into(),
        };
        let image = Image {
            width: 2,
            height: 1,
            pixels: vec![Vec3::new(0.25, 1.5, 3.0), Vec3::splat(0.125)],
        };
        let first = cached_reference(dir.path(), &key, || Ok((image.clone(), 0.5))).unwrap();
        assert!(!first.cached);
        assert_eq!(
            (first.image.clone(), first.rel_mse_floor),
            (image.clone(), 0.5)
        );
        let second = cached_reference(dir.path(), &key, || panic!("rendered twice")).unwrap();
        assert!(second.cached);
        assert_eq!((second.image, second.rel_mse_floor), (image.clone(), 0.5));
        let other = ReferenceKey { spp: 16, ..key };
        let cached = cached_reference(dir.path(), &other, || Ok((image.clone(), 0.5)))
            .unwrap()
            .cached;
        assert!(!cached, "a different key renders again");
    }

    #[test]
    fn the_floor_is_the_variance_of_the_mean_relative_to_the_value() {
        let mean = Image {
            width: 1,
            height: 1,
            pixels: vec![Vec3::new(1.0, 0.0, 2.0)],
        };
        let variance = Image {
            width: 1,
            height: 1,
            pixels: vec![Vec3::new(0.8, 0.0, 0.8)],
        };
        let eps = crate::converge::metrics::REL_MSE_EPSILON;
        let expected = (0.1 / (1.0 + eps) + 0.1 / (4.0 + eps)) / 3.0;
        assert!((rel_mse_floor(&mean, &variance, 8) / expected - 1.0).abs() < 1e-6);
    }
}
