use super::Image;
use glam::{DVec3, Vec3};

/// Running sums of one pixel's samples, in f64 so that millions of samples add up exactly
/// enough for the variance.
#[derive(Clone, Copy, Debug, Default)]
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
