use crate::prelude::*;

pub fn kajiya_kay(wo: Vec3, wi: Vec3, tangent: Vec3, params: &KajiyaKayParams) -> Vec3 {
    let ti = tangent.dot(wi).min(1.0).max(-1.0);
    let to = tangent.dot(wo).min(1.0).max(-1.0);
    let si = (1.0 - ti * ti).sqrt();
    let so = (1.0 - to * to).sqrt();
    // cos of the angle between wo and the mirror cone: cos(pi - theta_i - theta_o)
    let mut spec_cos = si * so - ti * to;
    if spec_cos < 0.0 {
        spec_cos = 0.0;
    }
    let diffuse = params.kd * si;
    let specular = params.ks * spec_cos.powf(params.exponent);
    diffuse + specular
}
