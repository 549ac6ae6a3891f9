use super::{Coefficients, Medium};
use glam::Vec3;

/// Densities on a regular grid of `res[0] × res[1] × res[2]` points (each at least 2),
/// x varying fastest, then y, then z. Values are ≥ 0; between grid points the density is
/// interpolated trilinearly.
#[derive(Clone, Debug, PartialEq)]
pub struct DensityGrid {
    res: [usize; 3],
    data: Vec<f32>,
    max: f32,
}

impl DensityGrid {
    /// A grid from its resolution and values; `None` unless every resolution is ≥ 2, the
    /// value count matches and every value is finite and ≥ 0.
    pub fn new(res: [usize; 3], data: Vec<f32>) -> Option<Self> {
        let count = res.iter().try_fold(1usize, |acc, &r| acc.checked_mul(r))?;
        if res.iter().any(|&r| r < 2)
            || data.len() != count
            || data.iter().any(|v| !(v.is_finite() && *v >= 0.0))
        {
            return None;
        }
        let max = data.iter().copied().fold(0.0f32, f32::max);
        Some(Self { res, data, max })
    }

    /// Grid resolution per axis.
    pub fn resolution(&self) -> [usize; 3] {
        self.res
    }

    /// The largest value.
    pub fn max(&self) -> f32 {
        self.max
    }

    fn at(&self, x: usize, y: usize, z: usize) -> f32 {
        self.data[x + self.res[0] * (y + self.res[1] * z)]
    }

    /// The trilinear interpolation at grid coordinates `u ∈ [0, 1]³` (0 outside).
    pub fn lookup(&self, u: Vec3) -> f32 {
        if !(u.cmpge(Vec3::ZERO).all() && u.cmple(Vec3::ONE).all()) {
            return 0.0;
        }
        let g = u * Vec3::new(
            (self.res[0] - 1) as f32,
            (self.res[1] - 1) as f32,
            (self.res[2] - 1) as f32,
        );
        let i = [
            (g.x as usize).min(self.res[0] - 2),
            (g.y as usize).min(self.res[1] - 2),
            (g.z as usize).min(self.res[2] - 2),
        ];
        let f = g - Vec3::new(i[0] as f32, i[1] as f32, i[2] as f32);
        let lerp = |a: f32, b: f32, t: f32| a + (b - a) * t;
        let c = |dx, dy, dz| self.at(i[0] + dx, i[1] + dy, i[2] + dz);
        let x00 = lerp(c(0, 0, 0), c(1, 0, 0), f.x);
        let x10 = lerp(c(0, 1, 0), c(1, 1, 0), f.x);
        let x01 = lerp(c(0, 0, 1), c(1, 0, 1), f.x);
        let x11 = lerp(c(0, 1, 1), c(1, 1, 1), f.x);
        lerp(lerp(x00, x10, f.y), lerp(x01, x11, f.y), f.z)
    }
}

/// A heterogeneous medium: a density grid stretched over the box `[min, max]`, with
/// coefficients `density × (σa, σs)`. Its majorant is the largest density times σt.
#[derive(Clone, Debug, PartialEq)]
pub struct GridMedium {
    /// The densities.
    pub grid: DensityGrid,
    /// Lower corner of the box the grid spans.
    pub min: Vec3,
    /// Upper corner of the box the grid spans.
    pub max: Vec3,
    /// Coefficients at density 1.
    pub per_density: Coefficients,
}

impl Medium for GridMedium {
    fn coefficients(&self, p: Vec3) -> Coefficients {
        let d = self.grid.lookup((p - self.min) / (self.max - self.min));
        Coefficients {
            sigma_a: d * self.per_density.sigma_a,
            sigma_s: d * self.per_density.sigma_s,
        }
    }

    fn majorant(&self) -> f32 {
        self.grid.max() * self.per_density.sigma_t()
    }
}
