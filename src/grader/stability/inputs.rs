//! Extreme inputs that several tasks share, built the way the errata built them.

use glam::Vec3;

/// The largest value the framework's [`crate::sampling::Sampler`] returns: 1 − 2⁻²⁴.
pub const U_MAX: f32 = 1.0 - 1.0 / (1u32 << 24) as f32;

/// The errata's f32 vector v = (0.34558418, 0.82161814, 0.33043706) normalised in f32 as
/// `v / sqrt(v·v)`. Its dot product with itself rounds to 1.0000001, so `1 − c²` is
/// negative and an unclamped `sqrt(1 − c²)` is NaN (about 19 % of random f32 unit vectors
/// behave like this).
pub fn errata_unit_vector() -> Vec3 {
    let v = Vec3::new(0.345_584_18, 0.821_618_14, 0.330_437_06);
    v / v.dot(v).sqrt()
}

/// A local direction along the normal whose cosine rounds to one ulp above 1.
pub fn cos_above_one() -> Vec3 {
    Vec3::new(0.0, 0.0, 1.0f32.next_up())
}

/// The critical angle in radians from `eta_i` into `eta_t` (< `eta_i`), computed in f64
/// and rounded to f32 as an f32 renderer would store it. For glass → air (1.5 → 1) the
/// rounded angle lies 6.5e-8 past the true one, where `1 − sin²θt` computed in f32 is 0
/// or −1.2e-7 depending on the order of operations.
pub fn critical_angle_f32(eta_i: f32, eta_t: f32) -> f32 {
    ((eta_t / eta_i) as f64).asin() as f32
}

/// The same angle in degrees in f64 (what the layer-stack task takes).
pub fn critical_angle_deg_f64(eta_i: f64, eta_t: f64) -> f64 {
    (eta_t / eta_i).asin().to_degrees()
}

/// `x` moved `ulps` representable f32 values upwards.
pub fn ulps_above_f32(x: f32, ulps: u32) -> f32 {
    (0..ulps).fold(x, |x, _| x.next_up())
}

/// `x` moved `ulps` representable f64 values upwards.
pub fn ulps_above_f64(x: f64, ulps: u32) -> f64 {
    (0..ulps).fold(x, |x, _| x.next_up())
}

/// The unit direction in the x-z plane at `theta` radians from +z (towards +x), in f32.
pub fn direction_xz(theta: f32) -> Vec3 {
    let (s, c) = theta.sin_cos();
    Vec3::new(s, 0.0, c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_errata_vector_has_a_cosine_above_one() {
        let w = errata_unit_vector();
        assert!(w.dot(w) > 1.0, "w·w = {}", w.dot(w));
        assert!(1.0 - w.dot(w) * w.dot(w) < 0.0);
    }

    #[test]
    fn the_f32_critical_angle_is_just_past_the_true_one() {
        let theta = critical_angle_f32(1.5, 1.0) as f64;
        assert!(1.5 * theta.sin() > 1.0);
        assert!(1.5 * theta.sin() < 1.0 + 1e-7);
        assert!(U_MAX < 1.0 && U_MAX + 1.0 / (1u32 << 24) as f32 == 1.0);
    }
}
