//! One input moved within rounding ([`Jitter`]): by how much a correct f32 implementation
//! may lose to rounding in a quantity it derives from its inputs. [`Call::jitters`] moves
//! every input of a call this way, and turns its directions.
//!
//! [`Call::jitters`]: super::call::Call::jitters

use super::test_brdf::TestBrdf;
use crate::bsdf::{KajiyaKayParams, PhongParams};
use glam::{Vec2, Vec3};

/// How many f32 ulps [`Call::jitters`](super::call::Call::jitters) moves an input at most: the rounding a correct
/// implementation may introduce in the quantities it derives from its inputs.
pub const JITTER_ULPS: f64 = 4.0;

/// The smallest positive (subnormal) f32, 2^-149.
const SMALLEST_SUBNORMAL: f64 = 1.401_298_464_324_817e-45;

/// A uniform number in [0, 1) from `seed` and `salt`: the same pair, the same number.
pub fn hash_unit(seed: u64, salt: u64) -> f64 {
    let mut h = seed ^ salt.wrapping_mul(0x9e37_79b9_7f4a_7c15);
    h ^= h >> 29;
    h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h ^= h >> 32;
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^= h >> 31;
    (h >> 11) as f64 / (1u64 << 53) as f64
}

/// A value whose real numbers [`Call::jitters`](super::call::Call::jitters) moves, each by [`jitter_real`]; integers
/// (seeds, counts, exponents of a test BRDF) are kept.
pub trait Jitter {
    /// Moves every real number in `self` for `seed`.
    fn jitter(&mut self, seed: u64);
}

/// `x` moved by up to [`JITTER_ULPS`] f32 ulps, by a factor that depends only on `seed` and
/// `x`; a subnormal f32 by up to as many of the smallest subnormal, away from 0. A move
/// that leaves the finite numbers keeps `x`.
pub fn jitter_real(x: f64, seed: u64) -> f64 {
    let u = hash_unit(seed, x.to_bits());
    // A subnormal f32 has fewer digits than ulps can move: move it by up to `JITTER_ULPS`
    // of the smallest subnormal instead, keeping its sign.
    let moved = if x != 0.0 && x.abs() < f32::MIN_POSITIVE as f64 {
        x.signum() * (x.abs() + JITTER_ULPS * SMALLEST_SUBNORMAL * u)
    } else {
        x * (1.0 + (2.0 * u - 1.0) * JITTER_ULPS * f32::EPSILON as f64)
    };
    if moved.is_finite() { moved } else { x }
}

impl Jitter for f64 {
    fn jitter(&mut self, seed: u64) {
        *self = jitter_real(*self, seed);
    }
}

impl Jitter for f32 {
    fn jitter(&mut self, seed: u64) {
        *self = jitter_real(*self as f64, seed) as f32;
    }
}

impl Jitter for Vec3 {
    fn jitter(&mut self, seed: u64) {
        for x in self.as_mut() {
            x.jitter(seed);
        }
    }
}

impl Jitter for Vec2 {
    fn jitter(&mut self, seed: u64) {
        for x in self.as_mut() {
            x.jitter(seed);
        }
    }
}

impl Jitter for PhongParams {
    fn jitter(&mut self, seed: u64) {
        self.kd.jitter(seed);
        self.ks.jitter(seed);
        self.exponent.jitter(seed);
    }
}

impl Jitter for KajiyaKayParams {
    fn jitter(&mut self, seed: u64) {
        self.kd.jitter(seed);
        self.ks.jitter(seed);
        self.exponent.jitter(seed);
    }
}

impl Jitter for TestBrdf {
    fn jitter(&mut self, seed: u64) {
        match self {
            TestBrdf::Lambert { albedo: x }
            | TestBrdf::CosinePower { k: x, .. }
            | TestBrdf::ScaledIncidentOnly { scale: x } => x.jitter(seed),
            TestBrdf::IncidentOnly
            | TestBrdf::NanNearGrazing
            | TestBrdf::NanOneWayRound
            | TestBrdf::Lopsided
            | TestBrdf::NegativeLopsided
            | TestBrdf::InfiniteNearGrazing => {}
        }
    }
}
