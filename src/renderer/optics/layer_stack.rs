use serde::Serialize;

/// One slab of a [`LayerStack`]: a medium of refractive index `eta` and finite `thickness`
/// (any length unit; shifts come out in the same unit).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Slab {
    /// Refractive index of the slab.
    pub eta: f64,
    /// Thickness of the slab, measured along the normal.
    pub thickness: f64,
}

/// Plane-parallel media that a ray crosses in order: it starts in the half-space of index
/// `eta_incident`, crosses every slab of `slabs` in turn, and ends in the half-space of index
/// `eta_exit`. All interfaces share one normal. Light of intensity `intensity` enters.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct LayerStack {
    /// Index of the medium the ray starts in (for example air, 1.0).
    pub eta_incident: f64,
    /// The finite slabs between the two half-spaces, in the order the ray meets them.
    pub slabs: Vec<Slab>,
    /// Index of the medium the ray ends in.
    pub eta_exit: f64,
    /// Incident intensity (any unit; transmitted intensities come out in the same unit).
    pub intensity: f64,
}

impl LayerStack {
    /// Refractive indices of every medium in ray order: incident, each slab, exit.
    pub fn etas(&self) -> Vec<f64> {
        std::iter::once(self.eta_incident)
            .chain(self.slabs.iter().map(|s| s.eta))
            .chain(std::iter::once(self.eta_exit))
            .collect()
    }

    /// Number of interfaces the ray crosses (slabs + 1).
    pub fn interfaces(&self) -> usize {
        self.slabs.len() + 1
    }
}

/// What happens to a ray crossing a [`LayerStack`]; the output of the `refract_stack` task.
///
/// Angles are measured from the common normal, in degrees. Vectors are indexed by medium
/// (`theta`), by slab (`perpendicular_shift`, `interface_offset`) or by interface
/// (`reflectance_*`), and hold entries only for what the ray reached. When total internal
/// reflection stops the ray at interface `k` (decided on `sin²θt ≥ 1`, so exactly at the
/// critical angle too), `tir_at = Some(k)`, `theta` holds the `k + 1` media reached, the
/// per-slab vectors the `k` slabs entered (the last one up to the point of reflection), the
/// reflectance vectors `k + 1` entries of which the last is 1, and both transmitted
/// intensities are 0.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct StackReport {
    /// Angle from the normal in each medium reached, in degrees (`theta[0]` is the input).
    pub theta: Vec<f64>,
    /// Interface at which total internal reflection stopped the ray, if any.
    pub tir_at: Option<usize>,
    /// Per slab: the ray's lateral shift, measured perpendicular to the ray, between the
    /// exit point and the undeviated incident ray: `d sin(θ_in − θ_slab) / cos θ_slab`.
    pub perpendicular_shift: Vec<f64>,
    /// Per slab: distance along the interface between the entry and exit points,
    /// `d tan θ_slab` (what the worksheet wrongly calls the lateral displacement).
    pub interface_offset: Vec<f64>,
    /// Per interface: reflectance by Schlick's approximation (the student's `fresnel_schlick`).
    pub reflectance_schlick: Vec<f64>,
    /// Per interface: reflectance by the exact unpolarised Fresnel equations.
    pub reflectance_exact: Vec<f64>,
    /// Intensity leaving the last interface, losses by Schlick reflectance (no absorption,
    /// no multiple reflections).
    pub transmitted_schlick: f64,
    /// Intensity leaving the last interface, losses by exact Fresnel reflectance.
    pub transmitted_exact: f64,
}
