use glam::Vec2;
use rand_pcg::Pcg32;
use rand_pcg::rand_core::RngCore;

/// The renderer's and grader's source of uniform random numbers: PCG32 (O'Neill 2014).
///
/// Every value is in [0, 1): 1.0 is never returned, so `1 - u` is never 0. A sampler is
/// seeded from a `(seed, stream)` pair; the renderer uses the pixel index as the stream, so
/// an image depends on the seed and never on the thread count.
#[derive(Clone, Debug)]
pub struct Sampler {
    rng: Pcg32,
}

impl Sampler {
    /// A sampler for `stream` of the sequence chosen by `seed`.
    pub fn new(seed: u64, stream: u64) -> Self {
        Self {
            rng: Pcg32::new(seed ^ 0x853c_49e6_748f_ea9b, stream),
        }
    }

    /// The next uniform number in [0, 1) (24 random bits, so every value is exact in f32).
    pub fn next_1d(&mut self) -> f32 {
        (self.rng.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }

    /// The next uniform number in [0, 1) with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        (self.rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// The next point uniform in [0, 1)².
    pub fn next_2d(&mut self) -> Vec2 {
        let x = self.next_1d();
        Vec2::new(x, self.next_1d())
    }
}
