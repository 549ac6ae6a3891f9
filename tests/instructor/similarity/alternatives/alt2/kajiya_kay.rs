use crate::prelude::*;
use std::f32::consts::PI;

pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    // work with the angles themselves
    let theta_i = tangent.dot(wi).clamp(-1.0, 1.0).acos();
    let theta_o = tangent.dot(wo).clamp(-1.0, 1.0).acos();
    let cone = (PI - theta_i - theta_o).cos().max(0.0);
    let sin_theta_i = theta_i.sin().max(0.0);
    params.kd * sin_theta_i + params.ks * cone.powf(params.exponent)
}
