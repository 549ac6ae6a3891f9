use glam::Vec3;

/// Exact unpolarised Fresnel reflectance of a smooth dielectric interface, in f64.
///
/// `cos_theta_i` is the cosine between the incident direction and the normal on the incident
/// side (only its magnitude is used); light travels from index `eta_i` into `eta_t`.
/// Returns 1 under total internal reflection, including exactly at the critical angle, and 0
/// when `eta_i == eta_t`. The square root is clamped so that rounding past the critical angle
/// gives TIR rather than NaN.
pub fn fresnel_dielectric_f64(cos_theta_i: f64, eta_i: f64, eta_t: f64) -> f64 {
    let cos_i = cos_theta_i.abs().min(1.0);
    let sin2_i = (1.0 - cos_i * cos_i).max(0.0);
    let sin2_t = (eta_i / eta_t).powi(2) * sin2_i;
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).max(0.0).sqrt();
    let r_s = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
    let r_p = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
    0.5 * (r_s * r_s + r_p * r_p)
}

/// [`fresnel_dielectric_f64`] in the renderer's f32 (computed in f64, then rounded).
pub fn fresnel_dielectric(cos_theta_i: f32, eta_i: f32, eta_t: f32) -> f32 {
    fresnel_dielectric_f64(cos_theta_i as f64, eta_i as f64, eta_t as f64) as f32
}

/// Exact unpolarised Fresnel reflectance of a smooth conductor seen from a dielectric of
/// index 1, per RGB channel, with the complex index of refraction `eta + i k`.
///
/// `cos_theta_i` is the cosine between the incident direction and the normal (clamped to
/// [0, 1]). The closed form (pbrt, §8.2.2 in the third edition) stays in real arithmetic:
/// `a² + b² = |(η + ik)² − sin²θ|`, `Rs = (a² + b² + cos²θ − 2a cos θ) / (… + 2a cos θ)` and
/// `Rp = Rs (cos²θ (a² + b²) + sin⁴θ − 2a cos θ sin²θ) / (… + …)`. It gives
/// `((η − 1)² + k²) / ((η + 1)² + k²)` at normal incidence and 1 at grazing; with `k = 0` it
/// is the dielectric Fresnel reflectance. Schlick's curve through the same normal-incidence
/// value is off by up to 7 % for gold's blue channel, which is why the renderer uses this for
/// conductors given by `eta` and `k`.
pub fn fresnel_conductor(cos_theta_i: f32, eta: Vec3, k: Vec3) -> Vec3 {
    let cos = Vec3::splat(cos_theta_i.clamp(0.0, 1.0));
    let cos2 = cos * cos;
    let sin2 = Vec3::ONE - cos2;
    let eta2 = eta * eta;
    let k2 = k * k;
    let t0 = eta2 - k2 - sin2;
    let a2_plus_b2 = (t0 * t0 + 4.0 * eta2 * k2).max(Vec3::ZERO).powf(0.5);
    let a = (0.5 * (a2_plus_b2 + t0)).max(Vec3::ZERO).powf(0.5);
    let t1 = a2_plus_b2 + cos2;
    let t2 = 2.0 * cos * a;
    let rs = ratio(t1 - t2, t1 + t2);
    let t3 = cos2 * a2_plus_b2 + sin2 * sin2;
    let t4 = t2 * sin2;
    let rp = rs * ratio(t3 - t4, t3 + t4);
    (0.5 * (rs + rp)).clamp(Vec3::ZERO, Vec3::ONE)
}

/// `num / den` per channel, 1 where `den` is 0 (only at grazing with `eta = k = 0`, where
/// the interface reflects everything).
fn ratio(num: Vec3, den: Vec3) -> Vec3 {
    Vec3::select(den.cmpgt(Vec3::ZERO), num / den, Vec3::ONE)
}

/// Schlick's angular weight `(1 − cos θ)^5`, with `cos_theta` clamped to [0, 1] first so a
/// cosine that rounding pushed past 1 (or a slightly negative one) cannot leave [0, 1].
///
/// Schlick's approximation is `R0 + (1 − R0) · schlick_weight(cos θ)`; the `fresnel_schlick`
/// and `cook_torrance` tasks both build on it.
#[inline]
pub fn schlick_weight(cos_theta: f32) -> f32 {
    let m = (1.0 - cos_theta).clamp(0.0, 1.0);
    let m2 = m * m;
    m2 * m2 * m
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Fresnel equations in complex f64 arithmetic, for one channel.
    fn conductor_complex(cos: f64, eta: f64, k: f64) -> f64 {
        // (re, im) pairs.
        let mul = |a: (f64, f64), b: (f64, f64)| (a.0 * b.0 - a.1 * b.1, a.0 * b.1 + a.1 * b.0);
        let div = |a: (f64, f64), b: (f64, f64)| {
            let d = b.0 * b.0 + b.1 * b.1;
            ((a.0 * b.0 + a.1 * b.1) / d, (a.1 * b.0 - a.0 * b.1) / d)
        };
        let sqrt = |a: (f64, f64)| {
            let r = (a.0 * a.0 + a.1 * a.1).sqrt();
            let re = ((r + a.0) / 2.0).sqrt();
            let im = ((r - a.0) / 2.0).sqrt().copysign(a.1);
            (re, im)
        };
        let n = (eta, k);
        let sin2 = 1.0 - cos * cos;
        let n2 = mul(n, n);
        let cos_t = sqrt((1.0 - div((sin2, 0.0), n2).0, -div((sin2, 0.0), n2).1));
        let n_cos_t = mul(n, cos_t);
        let rs = div((cos - n_cos_t.0, -n_cos_t.1), (cos + n_cos_t.0, n_cos_t.1));
        let n_cos = (n.0 * cos, n.1 * cos);
        let rp = div(
            (n_cos.0 - cos_t.0, n_cos.1 - cos_t.1),
            (n_cos.0 + cos_t.0, n_cos.1 + cos_t.1),
        );
        let abs2 = |a: (f64, f64)| a.0 * a.0 + a.1 * a.1;
        0.5 * (abs2(rs) + abs2(rp))
    }

    #[test]
    fn conductor_fresnel_matches_the_complex_fresnel_equations() {
        let gold_eta = Vec3::new(0.143, 0.374, 1.442);
        let gold_k = Vec3::new(3.983, 2.385, 1.603);
        for cos in [1.0f32, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01, 1e-4] {
            let f = fresnel_conductor(cos, gold_eta, gold_k);
            for c in 0..3 {
                let exact = conductor_complex(cos as f64, gold_eta[c] as f64, gold_k[c] as f64);
                assert!(
                    (f[c] as f64 - exact).abs() < 2e-6,
                    "cos {cos} channel {c}: {} vs {exact}",
                    f[c]
                );
            }
        }
    }

    #[test]
    fn conductor_fresnel_limits() {
        let (eta, k) = (Vec3::new(0.2, 1.1, 2.5), Vec3::new(3.0, 0.5, 0.0));
        let normal = ((eta - 1.0) * (eta - 1.0) + k * k) / ((eta + 1.0) * (eta + 1.0) + k * k);
        assert!(
            (fresnel_conductor(1.0, eta, k) - normal)
                .abs()
                .max_element()
                < 1e-6
        );
        assert_eq!(fresnel_conductor(0.0, eta, k), Vec3::ONE);
        assert_eq!(fresnel_conductor(-0.5, eta, k), Vec3::ONE);
        // k = 0 is a dielectric seen from outside.
        for cos in [1.0f32, 0.6, 0.2] {
            let f = fresnel_conductor(cos, Vec3::splat(1.5), Vec3::ZERO);
            assert!((f.x - fresnel_dielectric(cos, 1.0, 1.5)).abs() < 1e-6);
        }
        // Nothing to reflect off: eta = k = 0 is total reflection, never NaN.
        assert!(fresnel_conductor(0.3, Vec3::ZERO, Vec3::ZERO).is_finite());
    }
}
