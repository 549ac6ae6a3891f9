use super::Image;
use glam::{DVec3, Vec3};

/// Running sums of one pixel's samples, in f64 so that millions of samples add up exactly
/// enough for the variance.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PixelSums {
    sum: DVec3,
    sum_sq: DVec3,
    count: u32,
}

impl PixelSums {
    /// Adds one sample; returns false (and ignores it) when it is not finite or negative.
    #[inline]
    pub fn add(&mut self, v: Vec3) -> bool {
        if !v.is_finite() || v.min_element() < 0.0 {
            return false;
        }
        let v = v.as_dvec3();
        self.sum += v;
        self.sum_sq += v * v;
        self.count += 1;
        true
    }

    /// Bytes of [`PixelSums::to_le_bytes`].
    pub const BYTES: usize = 6 * 8 + 4;

    /// The sums as little-endian bytes (sum, sum of squares, count), for a checkpoint.
    pub fn to_le_bytes(&self) -> [u8; Self::BYTES] {
        let mut bytes = [0u8; Self::BYTES];
        let values = self
            .sum
            .to_array()
            .into_iter()
            .chain(self.sum_sq.to_array());
        for (chunk, v) in bytes.chunks_exact_mut(8).zip(values) {
            chunk.copy_from_slice(&v.to_le_bytes());
        }
        bytes[48..].copy_from_slice(&self.count.to_le_bytes());
        bytes
    }

    /// The sums written by [`PixelSums::to_le_bytes`].
    pub fn from_le_bytes(bytes: &[u8; Self::BYTES]) -> Self {
        let f =
            |i: usize| f64::from_le_bytes(bytes[8 * i..8 * i + 8].try_into().expect("eight bytes"));
        Self {
            sum: DVec3::new(f(0), f(1), f(2)),
            sum_sq: DVec3::new(f(3), f(4), f(5)),
            count: u32::from_le_bytes(bytes[48..].try_into().expect("four bytes")),
        }
    }

    /// Number of samples added.
    pub fn count(&self) -> u32 {
        self.count
    }

    /// The mean of the samples (0 without samples).
    pub fn mean(&self) -> Vec3 {
        if self.count == 0 {
            Vec3::ZERO
        } else {
            (self.sum / self.count as f64).as_vec3()
        }
    }

    /// The unbiased sample variance of one sample, per channel (0 with fewer than two).
    pub fn variance(&self) -> Vec3 {
        if self.count < 2 {
            return Vec3::ZERO;
        }
        let n = self.count as f64;
        ((self.sum_sq - self.sum * self.sum / n) / (n - 1.0))
            .max(DVec3::ZERO)
            .as_vec3()
    }
}

/// The accumulated samples of every pixel.
#[derive(Clone, Debug)]
pub struct Film {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// Per-pixel sums, row-major from the top.
    pub pixels: Vec<PixelSums>,
}

impl Film {
    /// An empty film.
    pub fn new(width: u32, height: u32) -> Self {
        Self {
            width,
            height,
            pixels: vec![PixelSums::default(); width as usize * height as usize],
        }
    }

    /// The current estimate: every pixel's mean.
    pub fn mean(&self) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self.pixels.iter().map(PixelSums::mean).collect(),
        }
    }

    /// Every pixel's sample variance (of one sample; divide by the sample count for the
    /// variance of the mean).
    pub fn variance(&self) -> Image {
        Image {
            width: self.width,
            height: self.height,
            pixels: self.pixels.iter().map(PixelSums::variance).collect(),
        }
    }
}
