/// Absorption and scattering coefficients at a point, per unit length.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Coefficients {
    /// Absorption coefficient σa ≥ 0.
    pub sigma_a: f32,
    /// Scattering coefficient σs ≥ 0.
    pub sigma_s: f32,
}

impl Coefficients {
    /// The extinction coefficient σt = σa + σs.
    #[inline]
    pub fn sigma_t(&self) -> f32 {
        self.sigma_a + self.sigma_s
    }
}
