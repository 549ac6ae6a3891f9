//! A render's state saved between passes, so a killed render continues where its last
//! complete pass ended and gives the image an uninterrupted render gives, bit for bit.
//!
//! The file (`renders/cornell.checkpoint` beside `renders/cornell.exr`) is one JSON line,
//! the [`Origin`] of the render and how far it got, followed by one record per pixel,
//! little endian: the pixel's sums ([`PixelSums::to_le_bytes`]) and the number of 32-bit
//! words its random stream has drawn ([`Sampler::draws`]). It is written atomically after
//! every pass, so a kill at any moment leaves the previous pass's file whole.

use super::{Film, PixelSums, RenderState};
use crate::sampling::Sampler;
use anyhow::{Context, Result, bail};
use serde::{Deserialize, Serialize};
use std::io::{BufRead, Read, Write};
use std::path::{Path, PathBuf};

/// What must be the same for a render to continue another: the scene file's text, every
/// setting that changes the samples, and whose code rendered.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Origin {
    /// The scene file's text.
    pub scene: String,
    /// The seed of the pixels' random streams.
    pub seed: u64,
    /// The direct-light strategy and heuristic, as the render used them.
    pub settings: String,
    /// Whose code rendered (`reference`, `student`, `mixed`).
    pub implementation: String,
    /// Image width.
    pub width: u32,
    /// Image height.
    pub height: u32,
}

/// The first line of the file.
#[derive(Debug, Serialize, Deserialize)]
struct Header {
    /// The format's version.
    version: u32,
    origin: Origin,
    /// Samples per pixel done.
    spp_done: u32,
    /// Samples dropped so far (NaN, infinite or negative).
    rejected: u64,
}

/// The format's version.
const VERSION: u32 = 1;

/// Bytes of one pixel's record.
const RECORD: usize = PixelSums::BYTES + 8;

/// The checkpoint file of the render written to `output`: the same name with the
/// extension `.checkpoint`.
pub fn path_for(output: &Path) -> PathBuf {
    output.with_extension("checkpoint")
}

/// Saves `state` of the render from `origin` to `path`, atomically.
pub fn save(path: &Path, origin: &Origin, state: &RenderState) -> Result<()> {
    let header = Header {
        version: VERSION,
        origin: origin.clone(),
        spp_done: state.spp_done,
        rejected: state.rejected,
    };
    crate::atomic_file::write_with(path, |w| {
        serde_json::to_writer(&mut *w, &header)?;
        w.write_all(b"\n")?;
        for (sums, sampler) in state.film.pixels.iter().zip(&state.samplers) {
            w.write_all(&sums.to_le_bytes())?;
            w.write_all(&sampler.draws().to_le_bytes())?;
        }
        Ok(())
    })
}

/// The state saved in `path`, to continue a render from `origin`. Errors name the file and
/// say what differs when the checkpoint belongs to another render.
pub fn load(path: &Path, origin: &Origin) -> Result<RenderState> {
    let file = std::fs::File::open(path).with_context(|| format!("opening {}", path.display()))?;
    let mut reader = std::io::BufReader::new(file);
    let mut line = String::new();
    reader
        .read_line(&mut line)
        .with_context(|| format!("reading {}", path.display()))?;
    let header: Header = serde_json::from_str(&line)
        .with_context(|| format!("{}: not a pbrlab render checkpoint", path.display()))?;
    if header.version != VERSION {
        bail!(
            "{}: a checkpoint of format {} (this pbrlab reads {VERSION})",
            path.display(),
            header.version
        );
    }
    let saved = &header.origin;
    let differs = [
        (saved.scene != origin.scene, "the scene file changed"),
        (saved.seed != origin.seed, "the seed differs"),
        (
            saved.settings != origin.settings,
            "the render settings differ",
        ),
        (
            saved.implementation != origin.implementation,
            "another implementation rendered it",
        ),
        (
            (saved.width, saved.height) != (origin.width, origin.height),
            "the image size differs",
        ),
    ];
    let reasons: Vec<&str> = differs
        .iter()
        .filter(|(d, _)| *d)
        .map(|(_, r)| *r)
        .collect();
    if !reasons.is_empty() {
        bail!(
            "{} belongs to another render ({}): render without --resume to start afresh",
            path.display(),
            reasons.join(", ")
        );
    }
    let pixels = origin.width as usize * origin.height as usize;
    let mut bytes = Vec::with_capacity(pixels * RECORD);
    reader
        .read_to_end(&mut bytes)
        .with_context(|| format!("reading {}", path.display()))?;
    if bytes.len() != pixels * RECORD {
        bail!(
            "{}: {} bytes of pixels where {pixels} pixels take {} (a damaged file: render \
             without --resume to start afresh)",
            path.display(),
            bytes.len(),
            pixels * RECORD
        );
    }
    let mut film = Film::new(origin.width, origin.height);
    let mut samplers = Vec::with_capacity(pixels);
    for (i, record) in bytes.chunks_exact(RECORD).enumerate() {
        let (sums, draws) = record.split_at(PixelSums::BYTES);
        film.pixels[i] = PixelSums::from_le_bytes(sums.try_into().expect("record size"));
        let draws = u64::from_le_bytes(draws.try_into().expect("record size"));
        samplers.push(Sampler::resume(origin.seed, i as u64, draws));
    }
    Ok(RenderState {
        film,
        samplers,
        spp_done: header.spp_done,
        rejected: header.rejected,
    })
}
