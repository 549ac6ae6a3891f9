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
    /// 32-bit words drawn so far (a saved render continues from here).
    draws: u64,
}

impl Sampler {
    /// A sampler for `stream` of the sequence chosen by `seed`.
    pub fn new(seed: u64, stream: u64) -> Self {
        Self {
            rng: Pcg32::new(seed ^ 0x853c_49e6_748f_ea9b, stream),
            draws: 0,
        }
    }

    /// The sampler [`Sampler::new`]`(seed, stream)` becomes after [`Sampler::draws`] =
    /// `draws`: the same numbers follow (PCG jumps ahead in O(log draws) steps).
    pub fn resume(seed: u64, stream: u64, draws: u64) -> Self {
        let mut s = Self::new(seed, stream);
        s.rng.advance(draws);
        s.draws = draws;
        s
    }

    /// How many 32-bit words this sampler has drawn since it was seeded.
    pub fn draws(&self) -> u64 {
        self.draws
    }

    /// The next uniform number in [0, 1) (24 random bits, so every value is exact in f32).
    pub fn next_1d(&mut self) -> f32 {
        self.draws += 1;
        (self.rng.next_u32() >> 8) as f32 * (1.0 / (1u32 << 24) as f32)
    }

    /// The next uniform number in [0, 1) with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        // Two 32-bit words (PCG32 builds its 64-bit output from two).
        self.draws += 2;
        (self.rng.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// The next point uniform in [0, 1)².
    pub fn next_2d(&mut self) -> Vec2 {
        let x = self.next_1d();
        Vec2::new(x, self.next_1d())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_resumed_sampler_draws_what_the_original_draws_next() {
        let mut original = Sampler::new(7, 42);
        for i in 0..1000 {
            if i % 3 == 0 {
                original.next_f64();
            } else {
                original.next_1d();
            }
        }
        let mut resumed = Sampler::resume(7, 42, original.draws());
        assert_eq!(resumed.draws(), original.draws());
        for _ in 0..100 {
            assert_eq!(resumed.next_1d(), original.next_1d());
            assert_eq!(resumed.next_f64(), original.next_f64());
        }
    }
}
