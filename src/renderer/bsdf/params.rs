use glam::Vec3;
use serde::{Deserialize, Serialize};

/// Parameters of the (modified, energy-normalised) Phong BRDF
/// `f = kd/π + ks (n+2)/(2π) max(0, r·wo)^n`, with `r` the mirror of `wi` about the normal.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PhongParams {
    /// Diffuse albedo `kd` per RGB channel (the worksheet's k_d·ρ), in [0, 1].
    pub kd: Vec3,
    /// Specular coefficient `ks` per RGB channel, in [0, 1]; `kd + ks ≤ 1` conserves energy.
    pub ks: Vec3,
    /// Phong exponent `n` (the worksheet's α), ≥ 0. Need not be an integer.
    pub exponent: f32,
}

/// Parameters of the Kajiya-Kay fibre shading model (Kajiya and Kay 1989):
/// diffuse `kd sin(t, wi)` plus specular `ks max(0, cos of the angle to the reflection cone)^p`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KajiyaKayParams {
    /// Diffuse coefficient per RGB channel.
    pub kd: Vec3,
    /// Specular coefficient per RGB channel.
    pub ks: Vec3,
    /// Specular exponent `p` (larger is a tighter highlight), ≥ 0.
    pub exponent: f32,
}
