//! The projected solid angle of a polygon, for irradiance estimators with an exact answer.

use glam::{DVec3, Vec3};

/// `∫_P cos θ dω` of the polygon with `vertices` (local frame, z = normal, all above the
/// surface) seen from the origin: Lambert's formula `½ Σ θ_k (n · ĉ_k)`, where θ_k is the
/// angle subtended by edge k and ĉ_k the unit normal of the plane through it and the origin.
/// This is the irradiance at the origin from the polygon emitting unit radiance.
pub fn projected_solid_angle(vertices: &[Vec3]) -> f64 {
    let v: Vec<DVec3> = vertices.iter().map(|p| p.as_dvec3().normalize()).collect();
    let sum: f64 = (0..v.len())
        .map(|k| {
            let (a, b) = (v[k], v[(k + 1) % v.len()]);
            let c = a.cross(b);
            let angle = c.length().atan2(a.dot(b));
            angle * c.normalize().z
        })
        .sum();
    0.5 * sum.abs()
}

/// True when the ray from the origin along `w` hits the axis-aligned rectangle at height
/// `z` spanning `x` and `y`.
pub fn hits_rectangle(w: Vec3, z: f32, x: (f32, f32), y: (f32, f32)) -> bool {
    if w.z <= 0.0 {
        return false;
    }
    let t = z / w.z;
    let (px, py) = (w.x * t, w.y * t);
    (x.0..x.1).contains(&px) && (y.0..y.1).contains(&py)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sampling::{Sampler, uniform_hemisphere, uniform_hemisphere_pdf};

    #[test]
    fn lamberts_formula_matches_monte_carlo() {
        // The errata's MIS light: a unit square at z = 1, x ∈ [0.5, 1.5], y ∈ [−0.5, 0.5];
        // their exact direct light for a ρ = 0.8 Lambertian is 0.06748293 = ρ/π · E.
        let quad = [
            Vec3::new(0.5, -0.5, 1.0),
            Vec3::new(1.5, -0.5, 1.0),
            Vec3::new(1.5, 0.5, 1.0),
            Vec3::new(0.5, 0.5, 1.0),
        ];
        let e = projected_solid_angle(&quad);
        assert!(
            (0.8 / std::f64::consts::PI * e - 0.067_482_93).abs() < 1e-7,
            "{e}"
        );
        let mut s = Sampler::new(3, 0);
        let n = 400_000;
        let mc: f64 = (0..n)
            .map(|_| {
                let w = uniform_hemisphere(s.next_2d());
                if hits_rectangle(w, 1.0, (0.5, 1.5), (-0.5, 0.5)) {
                    (w.z / uniform_hemisphere_pdf()) as f64
                } else {
                    0.0
                }
            })
            .sum::<f64>()
            / n as f64;
        assert!((mc - e).abs() < 0.005, "{mc} vs {e}");
    }
}
