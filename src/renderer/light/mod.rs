//! Lights: emitting shapes (area lights), point lights and a constant environment, and the
//! light sampler that picks one of them uniformly and a point on it.

mod area;
mod sample;

pub use area::Patch;
pub use sample::LightSample;

use crate::geometry::ShapeId;
use crate::sampling::{Sampler, uniform_sphere, uniform_sphere_pdf};
use glam::Vec3;

/// One light of the scene.
#[derive(Clone, Debug)]
pub enum Light {
    /// An emitting shape: uniform radiance on the front side of its surface.
    Area {
        /// The shape that emits.
        shape: ShapeId,
        /// Emitted radiance per RGB channel.
        radiance: Vec3,
        /// The shape's surface, in pieces.
        patches: Vec<Patch>,
        /// Cumulative areas of `patches` (the last entry is the total area).
        cumulative_area: Vec<f32>,
    },
    /// A point light.
    Point {
        /// Position.
        position: Vec3,
        /// Radiant intensity per RGB channel (W/sr).
        intensity: Vec3,
    },
    /// Constant radiance arriving from every direction at infinity.
    Environment {
        /// Radiance per RGB channel.
        radiance: Vec3,
    },
}

impl Light {
    /// An area light over `patches` (at least one, with positive total area).
    pub fn area(shape: ShapeId, radiance: Vec3, patches: Vec<Patch>) -> Self {
        let cumulative_area = patches
            .iter()
            .scan(0.0f32, |acc, p| {
                *acc += p.area();
                Some(*acc)
            })
            .collect();
        Light::Area {
            shape,
            radiance,
            patches,
            cumulative_area,
        }
    }

    /// Total emitting area (0 for point and environment lights).
    pub fn total_area(&self) -> f32 {
        match self {
            Light::Area {
                cumulative_area, ..
            } => cumulative_area.last().copied().unwrap_or(0.0),
            _ => 0.0,
        }
    }
}

/// Every light of a scene, with the lookups the integrators need. Lights are picked with
/// equal probability.
#[derive(Clone, Debug)]
pub struct Lights {
    lights: Vec<Light>,
    /// For each shape, the index of its area light (`u32::MAX` when it does not emit).
    light_of_shape: Vec<u32>,
    environment: Option<Vec3>,
}

impl Lights {
    /// The sampler over `lights` (at least one); `shapes` is the number of shapes of the
    /// scene.
    pub fn new(lights: Vec<Light>, shapes: usize) -> Self {
        let mut light_of_shape = vec![u32::MAX; shapes];
        let mut environment = None;
        for (i, light) in lights.iter().enumerate() {
            match light {
                Light::Area { shape, .. } => light_of_shape[*shape as usize] = i as u32,
                Light::Environment { radiance } => environment = Some(*radiance),
                Light::Point { .. } => {}
            }
        }
        Self {
            lights,
            light_of_shape,
            environment,
        }
    }

    /// Number of lights.
    pub fn len(&self) -> usize {
        self.lights.len()
    }

    /// True when there are no lights.
    pub fn is_empty(&self) -> bool {
        self.lights.is_empty()
    }

    /// The lights.
    pub fn lights(&self) -> &[Light] {
        &self.lights
    }

    fn pick_probability(&self) -> f32 {
        1.0 / self.lights.len() as f32
    }

    /// Picks a light uniformly, then a point (or direction) on it.
    #[inline]
    pub fn sample(&self, sampler: &mut Sampler) -> Option<LightSample> {
        let n = self.lights.len();
        if n == 0 {
            return None;
        }
        let index = ((sampler.next_1d() * n as f32) as usize).min(n - 1);
        let prob = self.pick_probability();
        match &self.lights[index] {
            Light::Area {
                radiance,
                patches,
                cumulative_area,
                ..
            } => {
                let total = *cumulative_area.last()?;
                let target = sampler.next_1d() * total;
                let k = cumulative_area
                    .partition_point(|&c| c <= target)
                    .min(patches.len() - 1);
                let (p, normal) = patches[k].sample(sampler.next_2d());
                Some(LightSample::Area {
                    p,
                    n: normal,
                    radiance: *radiance,
                    pdf_area: prob / total,
                })
            }
            Light::Point {
                position,
                intensity,
            } => Some(LightSample::Point {
                p: *position,
                intensity: *intensity,
                prob,
            }),
            Light::Environment { radiance } => Some(LightSample::Environment {
                wi: uniform_sphere(sampler.next_2d()),
                radiance: *radiance,
                pdf: prob * uniform_sphere_pdf(),
            }),
        }
    }

    /// The area density with which [`Lights::sample`] picks a given point of `shape`
    /// (0 when the shape does not emit).
    #[inline]
    pub fn pdf_area(&self, shape: ShapeId) -> f32 {
        match self.light_of_shape.get(shape as usize) {
            Some(&i) if i != u32::MAX => {
                self.pick_probability() / self.lights[i as usize].total_area()
            }
            _ => 0.0,
        }
    }

    /// The radiance the environment sends along `-dir` (seen looking along `dir`).
    #[inline]
    pub fn environment(&self) -> Vec3 {
        self.environment.unwrap_or(Vec3::ZERO)
    }

    /// The solid-angle density with which [`Lights::sample`] picks an environment direction.
    #[inline]
    pub fn environment_pdf(&self) -> f32 {
        if self.environment.is_some() {
            self.pick_probability() * uniform_sphere_pdf()
        } else {
            0.0
        }
    }
}
