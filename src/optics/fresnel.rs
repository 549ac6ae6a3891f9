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
