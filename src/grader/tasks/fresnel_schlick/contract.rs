//! The contract of `schlick_r0` and `fresnel_schlick` in f64 (see
//! [`crate::grade::contract`]).

use crate::grade::call::Call;
use crate::grade::output::Output;

/// Reflectance at normal incidence between indices `eta_i` and `eta_t`,
/// `((eta_i − eta_t) / (eta_i + eta_t))²`.
pub fn schlick_r0(eta_i: f64, eta_t: f64) -> f64 {
    let r = (eta_i - eta_t) / (eta_i + eta_t);
    r * r
}

/// Schlick's weight `(1 − cos θ)⁵`, the cosine clamped to [0, 1].
pub fn schlick_weight(cos_theta: f64) -> f64 {
    (1.0 - cos_theta).clamp(0.0, 1.0).powi(5)
}

/// Schlick's Fresnel reflectance at incident cosine `cos_theta_i` (its magnitude, clamped
/// to 1) from `eta_i` into `eta_t`: with the transmitted cosine when light goes from the
/// denser medium, 1 under total internal reflection, 0 between equal indices.
pub fn fresnel_schlick(cos_theta_i: f64, eta_i: f64, eta_t: f64) -> f64 {
    if eta_i == eta_t {
        return 0.0;
    }
    let cos_i = cos_theta_i.abs().min(1.0);
    let cos = if eta_i > eta_t {
        let sin2_t = (eta_i / eta_t).powi(2) * (1.0 - cos_i * cos_i).max(0.0);
        if sin2_t >= 1.0 {
            return 1.0;
        }
        (1.0 - sin2_t).sqrt()
    } else {
        cos_i
    };
    let r0 = schlick_r0(eta_i, eta_t);
    r0 + (1.0 - r0) * schlick_weight(cos)
}

/// The contract's answer to a call of this task's functions; `None` for any other call.
pub fn expected(call: &Call) -> Option<Output> {
    match *call {
        Call::schlick_r0 { eta_i, eta_t } => {
            Some(Output::Number(schlick_r0(eta_i as f64, eta_t as f64)))
        }
        Call::fresnel_schlick {
            cos_theta_i,
            eta_i,
            eta_t,
        } => Some(Output::Number(fresnel_schlick(
            cos_theta_i as f64,
            eta_i as f64,
            eta_t as f64,
        ))),
        _ => None,
    }
}
