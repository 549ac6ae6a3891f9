//! The estimators of `mis`: the errata's direct-light scene, where the answer is an exact
//! integral, with and without an occluder, for every weighting; and the configurations the
//! errata's scene never shows: a light seen at a grazing angle (the cosine at the light
//! differs from the one at the shading point) and brighter than 1, a sky next to the square
//! light (an environment sample needs its MIS weight too, and the square hides part of it),
//! and a point light (a light no BSDF sample can hit), once away from the shading point and
//! once lying on it.
//!
//! The floor is Lambertian in all of these, and also, under the square light alone and
//! under the sky, a coloured glossy Phong floor seen along its normal (its BSDF density is
//! not `cos θ / π`, so code that assumes a Lambertian surface shows; the exact answer is a
//! quadrature of the lobe over the square), and a coloured perfect mirror that reflects the
//! square (a delta BSDF: no light sample, and its BSDF sample has weight 1 under every
//! heuristic), and smooth glass in the mirror's place. Every estimate weighs the colour
//! channels apart ([`CHANNEL_WEIGHTS`]).
//!
//! Beside the means, two variance comparisons: the same estimator in two units of length,
//! and the balance heuristic against light sampling alone (weights that sum to one but are
//! not the balance heuristic's keep the mean and inflate the variance).

use crate::grade::catalogue::phong_floor::PhongSurface;
use crate::grade::catalogue::polygon::projected_solid_angle;
use crate::grade::catalogue::rough_conductor::{self, RoughConductor, StoredQuadrature};
use crate::grade::estimator::{CHANNEL_WEIGHTS, EstimatorSpec, yaml_rgb};
use crate::tasks::path_trace::cases as path_trace;
use crate::geometry::{Hit, Ray};
use crate::grade::declared::Declared;
use crate::grade::variance_pair::{VarianceBound, VariancePair};
use crate::integrator::Heuristic;
use crate::optics::fresnel_dielectric_f64;
use crate::sampling::{Sampler, uniform_sphere};
use crate::scene::{LoadOptions, Scene};
use crate::worksheet::Tasks;
use glam::{DVec3, Vec3};
use std::f64::consts::PI;
use std::path::Path;

/// What the estimator and sampling checks of this task catch in at least 90 % of
/// gradings, as measured by `pbrlab power` (asserted by tests/instructor/power.rs).
pub const POWER: Declared = Declared {
    estimator_bias: Some(0.005),
    sampler_distortion: None,
};

/// The errata's exact direct light without the occluder (scene A).
pub const OPEN: f64 = 0.067_482_93;
/// The errata's exact direct light with the occluder (scene B).
pub const OCCLUDED: f64 = 0.009_195_30;

/// Albedo of the floor.
const ALBEDO: f64 = 0.8;
/// Radiance of the sky in [`Lighting::Sky`].
const SKY: f64 = 0.5;
/// Position and intensity of the point light in [`Lighting::PointLight`].
const POINT: ([f32; 3], f64) = ([-0.4, 0.2, 0.8], 0.5);
/// Where [`Lighting::PointLight`] shades: away from the origin, so that `p − x` and `p + x`
/// differ.
const OFF_ORIGIN: Vec3 = Vec3::new(0.3, -0.25, 0.0);
/// Radiance of the upright square of [`Lighting::Upright`] (the others emit 1).
const UPRIGHT_RADIANCE: f64 = 3.0;

/// The errata's square light: a one-sided unit square of radiance 1 at z = 1 facing down.
const SQUARE: [Vec3; 4] = [
    Vec3::new(0.5, -0.5, 1.0),
    Vec3::new(1.5, -0.5, 1.0),
    Vec3::new(1.5, 0.5, 1.0),
    Vec3::new(0.5, 0.5, 1.0),
];
/// A unit square of radiance [`UPRIGHT_RADIANCE`] standing upright at x = 1 and facing the
/// origin: seen from the origin, its lower edge lies 3° above the horizon, and the cosine at
/// the light (`1/r`) is far from the cosine at the shading point (`z/r`).
const UPRIGHT: [Vec3; 4] = [
    Vec3::new(1.0, -0.5, 0.05),
    Vec3::new(1.0, 0.5, 0.05),
    Vec3::new(1.0, 0.5, 1.05),
    Vec3::new(1.0, -0.5, 1.05),
];

/// A 4 × 4 square of radiance 1 at z = 1 centred above the origin, facing down: over it the
/// light's solid-angle density `1/(16 cos³θ)` crosses the BSDF's `cos θ/π` (at θ ≈ 48°),
/// where weights that are not the balance heuristic's can explode.
const WIDE: [Vec3; 4] = [
    Vec3::new(-2.0, -2.0, 1.0),
    Vec3::new(2.0, -2.0, 1.0),
    Vec3::new(2.0, 2.0, 1.0),
    Vec3::new(-2.0, 2.0, 1.0),
];

/// What lights the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Lighting {
    /// The errata's square light alone (scene A).
    Open,
    /// The square light behind a black strip at z = 0.5 (scene B).
    Occluded,
    /// The upright square instead of the errata's.
    Upright,
    /// The wide square instead of the errata's.
    Wide,
    /// The square light under a sky of constant radiance [`SKY`], which the square hides
    /// where it stands.
    Sky,
    /// The square light and a point light, shading at [`OFF_ORIGIN`].
    PointLight,
    /// The square light and a point light lying on the floor at the shading point: at
    /// distance 0 it lights nothing (every other point of the floor sees it at cos θ = 0).
    PointOnShadingPoint,
    /// The errata's square turned to face up, away from the floor, under the sky: it emits
    /// nothing towards the floor (a one-sided light) and hides the sky behind it.
    FacingAway,
}

impl Lighting {
    /// Every lighting, for the tests.
    #[cfg(test)]
    const ALL: [Lighting; 8] = [
        Lighting::Open,
        Lighting::Occluded,
        Lighting::Upright,
        Lighting::Wide,
        Lighting::Sky,
        Lighting::PointLight,
        Lighting::PointOnShadingPoint,
        Lighting::FacingAway,
    ];

    /// What the check's name calls it.
    fn describe(self) -> &'static str {
        match self {
            Lighting::Open => "a square light, open",
            Lighting::Occluded => "a square light, occluded",
            Lighting::Upright => "an upright square light of radiance 3 seen at grazing angles",
            Lighting::Wide => "a wide square light close above",
            Lighting::Sky => "a square light under a constant sky",
            Lighting::PointLight => "a square light and a point light, off the origin",
            Lighting::PointOnShadingPoint => {
                "a square light and a point light at the shading point"
            }
            Lighting::FacingAway => "a square light facing away, under a constant sky",
        }
    }

    /// The emitting square, and its radiance.
    fn square(self) -> (&'static [Vec3; 4], f64) {
        match self {
            Lighting::Upright => (&UPRIGHT, UPRIGHT_RADIANCE),
            Lighting::Wide => (&WIDE, 1.0),
            _ => (&SQUARE, 1.0),
        }
    }

    /// The point light's position and intensity, if there is one.
    fn point_light(self) -> Option<([f32; 3], f64)> {
        match self {
            Lighting::PointLight => Some(POINT),
            Lighting::PointOnShadingPoint => Some(([0.0; 3], POINT.1)),
            _ => None,
        }
    }

    /// True when a sky of radiance [`SKY`] lights the floor too.
    fn has_sky(self) -> bool {
        matches!(self, Lighting::Sky | Lighting::FacingAway)
    }

    /// Where the estimate is made, on the floor (before scaling).
    fn shading_point(self) -> Vec3 {
        if self == Lighting::PointLight {
            OFF_ORIGIN
        } else {
            Vec3::ZERO
        }
    }

    /// The exact direct light leaving the floor at the shading point upwards: `ρ/π · E`,
    /// with the irradiance `E` from Lambert's polygon formula (the errata's values for
    /// scenes A and B).
    fn analytic(self) -> f64 {
        match self {
            Lighting::Open => return OPEN,
            Lighting::Occluded => return OCCLUDED,
            _ => {}
        }
        let x = self.shading_point();
        let (light, radiance) = self.square();
        let hidden = projected_solid_angle(&light.map(|v| v - x));
        let sky = if self.has_sky() {
            SKY * (PI - hidden)
        } else {
            0.0
        };
        // A square facing away emits nothing this way.
        let radiance = if self == Lighting::FacingAway {
            0.0
        } else {
            radiance
        };
        // A point light at distance 0 lights nothing (see `PointOnShadingPoint`).
        let point = self.point_light().map_or(0.0, |(p, intensity)| {
            let d = Vec3::from(p) - x;
            let d2 = d.length_squared() as f64;
            if d2 > 0.0 {
                intensity * d.z as f64 / d2.sqrt() / d2
            } else {
                0.0
            }
        });
        ALBEDO / PI * (radiance * hidden + sky + point)
    }
}

/// The surface of [`Floor::Phong`].
const PHONG: PhongSurface = PhongSurface {
    kd: DVec3::new(0.5, 0.3, 0.1),
    ks: DVec3::new(0.3, 0.5, 0.6),
    exponent: 12.0,
};
/// The surface of [`Floor::BroadPhong`].
const BROAD_PHONG: PhongSurface = PhongSurface {
    kd: DVec3::new(0.1, 0.25, 0.05),
    ks: DVec3::new(0.6, 0.5, 0.8),
    exponent: 2.0,
};
/// The surface of [`Floor::Rough`]: isotropic GGX, α = 0.3, a coloured `f0`.
const ROUGH: RoughConductor = RoughConductor {
    alpha_x: 0.3,
    alpha_y: 0.3,
    f0: DVec3::new(0.6, 0.8, 0.95),
};
/// `[over the errata's square, over the hemisphere]`: `∫ f cos θi dωi` per channel of
/// [`ROUGH`] towards [`Floor::wo`], by quadrature of the reference
/// ([`stored_quadratures`]).
const ROUGH_REFLECTED: [DVec3; 2] = [
    DVec3::new(0.171_355_603, 0.228_283_561, 0.270_979_526),
    DVec3::new(0.508_260_473, 0.676_346_419, 0.802_410_866),
];
/// The surface of [`Floor::RoughGrazing`]: anisotropic GGX, rough across the plane of
/// incidence and smoother along it.
const ROUGH_GRAZING: RoughConductor = RoughConductor {
    alpha_x: 0.5,
    alpha_y: 0.2,
    f0: DVec3::new(0.95, 0.9, 0.7),
};
/// [`ROUGH_REFLECTED`] of [`ROUGH_GRAZING`] towards its [`Floor::wo`].
const ROUGH_GRAZING_REFLECTED: [DVec3; 2] = [
    DVec3::new(0.200_067_022, 0.189_748_656, 0.148_475_202),
    DVec3::new(0.757_937_075, 0.719_126_039, 0.563_881_940),
];
/// Reflectance of [`Floor::Mirror`].
const MIRROR: DVec3 = DVec3::new(0.9, 0.6, 0.3);
/// Index of refraction of [`Floor::Glass`].
const GLASS_IOR: f64 = 1.5;

/// What the floor is made of.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Floor {
    /// Lambertian, albedo [`ALBEDO`].
    Diffuse,
    /// The energy-normalised Phong BRDF of [`PHONG`], shaded along the normal (`wo = z`,
    /// so the lobe is `cos^n θ` around the normal).
    Phong,
    /// The broad lobe of [`BROAD_PHONG`] shaded from 70° on the far side of the light:
    /// about half of its BSDF samples fall below the horizon and fail, while its light
    /// samples still count.
    BroadPhong,
    /// The rough conductor [`ROUGH`], shaded from the direction that reflects onto the
    /// centre of the errata's square (as [`Floor::Mirror`]).
    Rough,
    /// The anisotropic rough conductor [`ROUGH_GRAZING`] shaded from 70° on the far side
    /// of the light (as [`Floor::BroadPhong`]): many of its half-vector samples reflect
    /// below the horizon and fail.
    RoughGrazing,
    /// A perfect mirror of reflectance [`MIRROR`], shaded from the direction that
    /// reflects onto the centre of the errata's square.
    Mirror,
    /// Smooth glass of index [`GLASS_IOR`] (a delta BSDF that reflects or refracts at
    /// random), shaded from the mirror's direction: it reflects the square with the
    /// Fresnel reflectance, and what it refracts leaves below the floor into the dark.
    Glass,
}

impl Floor {
    /// The floor's material in YAML.
    fn yaml(self) -> String {
        match self {
            Floor::Diffuse => format!("{{diffuse: {{albedo: {ALBEDO}}}}}"),
            Floor::Phong => PHONG.yaml(),
            Floor::BroadPhong => BROAD_PHONG.yaml(),
            Floor::Rough => ROUGH.yaml(),
            Floor::RoughGrazing => ROUGH_GRAZING.yaml(),
            Floor::Mirror => format!("{{mirror: {{reflectance: {}}}}}", yaml_rgb(MIRROR)),
            Floor::Glass => format!("{{dielectric: {{ior: {GLASS_IOR}}}}}"),
        }
    }

    /// The direction `mis` is asked about (away from the floor).
    fn wo(self) -> Vec3 {
        match self {
            Floor::Mirror | Floor::Glass | Floor::Rough => Vec3::new(-1.0, 0.0, 1.0).normalize(),
            Floor::Diffuse | Floor::Phong => Vec3::Z,
            Floor::BroadPhong | Floor::RoughGrazing => Vec3::new(-0.939_692_6, 0.0, 0.342_020_14),
        }
    }

    /// What the check's name calls it.
    fn describe(self) -> &'static str {
        match self {
            Floor::Diffuse => "",
            Floor::Phong => " on a glossy phong floor",
            Floor::BroadPhong => " on a broad phong lobe seen at 70° (bsdf samples fail)",
            Floor::Rough => " on a rough conductor floor",
            Floor::RoughGrazing => {
                " on an anisotropic rough conductor seen at 70° (bsdf samples fail)"
            }
            Floor::Mirror => " on a mirror floor",
            Floor::Glass => " on a glass floor",
        }
    }

    /// The exact direct light at the shading point of `lighting` towards [`Floor::wo`],
    /// channels weighted by [`CHANNEL_WEIGHTS`]. Defined for the lightings each floor is
    /// graded under: every one for [`Floor::Diffuse`], the errata's open square and the
    /// sky for the Phong and rough floors, the open square for [`Floor::Mirror`] and
    /// [`Floor::Glass`].
    fn analytic(self, lighting: Lighting) -> f64 {
        // `∫ f cos θ dω` per channel over the errata's square and over the hemisphere.
        let [square, albedo] = match self {
            Floor::Diffuse => return lighting.analytic(),
            Floor::Phong | Floor::BroadPhong => {
                let surface = if self == Floor::Phong {
                    PHONG
                } else {
                    BROAD_PHONG
                };
                let wo = self.wo().as_dvec3();
                [surface.over(wo, lighting.square().0), surface.albedo(wo)]
            }
            Floor::Rough => ROUGH_REFLECTED,
            Floor::RoughGrazing => ROUGH_GRAZING_REFLECTED,
            Floor::Mirror => {
                assert_eq!(lighting, Lighting::Open);
                // The mirror direction of `wo` is (1, 0, 1)/√2: it meets the square at its
                // centre (1, 0, 1), from below, where it emits radiance 1.
                return CHANNEL_WEIGHTS.dot(MIRROR * lighting.square().1);
            }
            Floor::Glass => {
                assert_eq!(lighting, Lighting::Open);
                // The reflection at 45° sees the square as the mirror does; its probability
                // is the exact Fresnel reflectance, and its weight 1.
                return fresnel_dielectric_f64(0.5f64.sqrt(), 1.0, GLASS_IOR)
                    * lighting.square().1;
            }
        };
        // The sky lights all of the hemisphere but the square.
        assert!(matches!(lighting, Lighting::Open | Lighting::Sky));
        let radiance = lighting.square().1;
        let sky = if lighting.has_sky() { SKY } else { 0.0 };
        CHANNEL_WEIGHTS.dot(square * (radiance - sky) + albedo * sky)
    }
}

/// A floor at z = 0 under `lighting`. Every length is multiplied by `scale`, which must not
/// change any radiance.
fn scene(lighting: Lighting, scale: f32, floor: Floor) -> Scene {
    let s = |x: f32| x * scale;
    // A quad faces `edge1 × edge2`: down for the squares, unless it faces away.
    let faces_away = lighting == Lighting::FacingAway;
    let quad = |v: &[Vec3; 4], what: &str| {
        let (o, mut e1, mut e2) = (v[0] * scale, (v[3] - v[0]) * scale, (v[1] - v[0]) * scale);
        if faces_away {
            std::mem::swap(&mut e1, &mut e2);
        }
        format!(
            "  - quad: {{origin: [{}, {}, {}], edge1: [{}, {}, {}], edge2: [{}, {}, {}], {what}}}\n",
            o.x, o.y, o.z, e1.x, e1.y, e1.z, e2.x, e2.y, e2.z
        )
    };
    let mut text = format!(
        "camera: {{eye: [0, 0, {e}], target: [0, 0, 0], up: [0, 1, 0], fov: 60, width: 4, height: 4}}
render: {{spp: 1, max_depth: 2, strategy: mis, heuristic: power, seed: 0}}
materials:
  floor: {floor}
  black: {{diffuse: {{albedo: 0}}}}
shapes:
  - quad: {{origin: [{a}, {a}, 0], edge1: [{b}, 0, 0], edge2: [0, {b}, 0], material: floor}}
",
        e = s(3.0),
        a = s(-3.0),
        b = s(6.0),
        floor = floor.yaml(),
    );
    let (light, radiance) = lighting.square();
    text += &quad(light, &format!("emission: {radiance}"));
    match lighting {
        Lighting::Occluded => {
            text += &format!(
                "  - quad: {{origin: [{ox}, {oy}, {oz}], edge1: [{w}, 0, 0], edge2: [0, {h}, 0], material: black}}\n",
                ox = s(0.2),
                oy = s(-1.0),
                oz = s(0.5),
                w = s(0.4),
                h = s(2.0),
            )
        }
        Lighting::Sky | Lighting::FacingAway => {
            text += &format!("lights:\n  - environment: {{radiance: {SKY}}}\n")
        }
        _ => {}
    }
    if let Some(([x, y, z], intensity)) = lighting.point_light() {
        // Intensity scales with area, so that the irradiance at the floor does not change.
        text += &format!(
            "lights:\n  - point: {{position: [{}, {}, {}], intensity: {}}}\n",
            s(x),
            s(y),
            s(z),
            intensity * (scale as f64).powi(2)
        );
    }
    Scene::from_yaml(
        Path::new("<grader mis scene>"),
        &text,
        &LoadOptions::default(),
    )
    .expect("the grader's MIS scene is valid")
}

/// The floor's hit at `point` (on the floor, before scaling), found by a ray straight down.
fn shading_hit(scene: &Scene, point: Vec3) -> Hit {
    let down = Ray::new(
        (point + Vec3::new(0.0, 0.0, 0.3)) * scene_scale(scene),
        -Vec3::Z,
    );
    scene
        .intersect(&down)
        .expect("the probe ray hits the floor at the shading point")
}

/// One call of `mis` at `point` on the floor towards `wo`; the channels weighted by
/// [`CHANNEL_WEIGHTS`].
fn direct_light<'a, T: Tasks>(
    t: &'a T,
    scene: Scene,
    point: Vec3,
    wo: Vec3,
    heuristic: Heuristic,
) -> Box<crate::grade::estimator::Estimator<'a>> {
    let hit = shading_hit(&scene, point);
    Box::new(move |s: &mut Sampler| {
        let direct = t.mis(&scene, &hit, wo, heuristic, s);
        Ok(direct.radiance.as_dvec3().dot(CHANNEL_WEIGHTS))
    })
}

/// The scale of a scene built by [`scene`], read back from its camera height.
fn scene_scale(scene: &Scene) -> f32 {
    scene.camera().eye.z / 3.0
}

/// The estimator of direct light on the Lambertian floor under `lighting`, lengths times
/// `scale`, weighted by `heuristic`.
fn spec<T: Tasks>(
    t: &T,
    lighting: Lighting,
    scale: f32,
    heuristic: Heuristic,
) -> EstimatorSpec<'_> {
    spec_on(t, Floor::Diffuse, lighting, scale, heuristic)
}

/// [`spec`] on the floor `floor`, seen from [`Floor::wo`].
fn spec_on<T: Tasks>(
    t: &T,
    floor: Floor,
    lighting: Lighting,
    scale: f32,
    heuristic: Heuristic,
) -> EstimatorSpec<'_> {
    let units = if scale == 1.0 {
        String::new()
    } else {
        format!(", lengths × {scale}")
    };
    EstimatorSpec {
        name: format!(
            "direct light from {}{}, {heuristic:?} weights{units}",
            lighting.describe(),
            floor.describe()
        )
        .to_lowercase(),
        analytic: floor.analytic(lighting),
        // The errata's Lambertian floor carries the declared power; the other floors are
        // there for the classes of mistakes they show, which bias far more than 0.5 %.
        samples: if floor == Floor::Diffuse {
            100_000
        } else {
            40_000
        },
        estimate: direct_light(
            t,
            scene(lighting, scale, floor),
            lighting.shading_point(),
            floor.wo(),
            heuristic,
        ),
    }
}

pub fn estimators<T: Tasks>(t: &T) -> Vec<EstimatorSpec<'_>> {
    use Lighting::*;
    // The whole paths' scenes: a coloured furnace, and the Phong box along its normal.
    let coloured = DVec3::new(0.8, 0.4, 0.0);
    let phong_albedo = path_trace::PHONG.kd + path_trace::PHONG.ks;
    vec![
        spec(t, Open, 1.0, Heuristic::Power),
        spec(t, Open, 1.0, Heuristic::Balance),
        spec(t, Occluded, 1.0, Heuristic::Power),
        spec(t, Occluded, 1.0, Heuristic::Light),
        spec(t, Occluded, 1.0, Heuristic::Bsdf),
        spec(t, Upright, 1.0, Heuristic::Light),
        spec(t, Upright, 1.0, Heuristic::Power),
        spec(t, Sky, 1.0, Heuristic::Power),
        spec(t, Sky, 1.0, Heuristic::Light),
        spec(t, PointLight, 1.0, Heuristic::Power),
        spec(t, PointOnShadingPoint, 1.0, Heuristic::Power),
        EstimatorSpec {
            samples: 40_000,
            ..spec(t, PointLight, 1.0, Heuristic::Bsdf)
        },
        EstimatorSpec {
            samples: 40_000,
            ..spec(t, FacingAway, 1.0, Heuristic::Power)
        },
        spec_on(t, Floor::Phong, Open, 1.0, Heuristic::Power),
        spec_on(t, Floor::Phong, Open, 1.0, Heuristic::Bsdf),
        spec_on(t, Floor::Phong, Sky, 1.0, Heuristic::Balance),
        spec_on(t, Floor::Phong, Sky, 1.0, Heuristic::Light),
        spec_on(t, Floor::BroadPhong, Open, 1.0, Heuristic::Power),
        spec_on(t, Floor::BroadPhong, Sky, 1.0, Heuristic::Light),
        spec_on(t, Floor::Rough, Open, 1.0, Heuristic::Power),
        spec_on(t, Floor::Rough, Open, 1.0, Heuristic::Bsdf),
        spec_on(t, Floor::Rough, Sky, 1.0, Heuristic::Balance),
        spec_on(t, Floor::RoughGrazing, Open, 1.0, Heuristic::Light),
        spec_on(t, Floor::RoughGrazing, Sky, 1.0, Heuristic::Power),
        spec_on(t, Floor::Mirror, Open, 1.0, Heuristic::Power),
        spec_on(t, Floor::Mirror, Open, 1.0, Heuristic::Light),
        spec_on(t, Floor::Glass, Open, 1.0, Heuristic::Power),
        // Light weights alone in a furnace would have infinite variance: where two walls
        // meet, the geometry term of a light sample on the other wall grows without bound
        // and no BSDF sample shares the weight. Under emitters that reflect nothing the
        // path shades only the floor's centre, away from every edge.
        whole_path(
            t,
            "a phong floor under emitters that reflect nothing, light weights: Le (kd + ks)",
            path_trace::floor_box(&path_trace::PHONG.yaml(), &render("light")),
            |_| Vec3::NEG_Y,
            CHANNEL_WEIGHTS.dot(path_trace::EMISSION * phong_albedo),
        ),
        whole_path(
            t,
            "a furnace with ρ = (0.8, 0.4, 0), power weights: Le/(1 − ρ) per channel",
            path_trace::furnace_around(coloured, &render("mis, heuristic: power"), None),
            |s| uniform_sphere(s.next_2d()),
            CHANNEL_WEIGHTS.dot(path_trace::EMISSION / (DVec3::ONE - coloured)),
        ),
        whole_path(
            t,
            "a phong floor under emitters that reflect nothing, balance weights: Le (kd + ks)",
            path_trace::floor_box(&path_trace::PHONG.yaml(), &render("mis, heuristic: balance")),
            |_| Vec3::NEG_Y,
            CHANNEL_WEIGHTS.dot(path_trace::EMISSION * phong_albedo),
        ),
    ]
}

/// Render settings for [`whole_path`]: unbounded, roulette from the first bounce on, the
/// direct-light `strategy` as the scene format names it (`light`, `bsdf`, or `mis,
/// heuristic: power`).
fn render(strategy: &str) -> String {
    format!("{{spp: 1, max_depth: ~, rr_depth: 1, strategy: {strategy}, seed: 0}}")
}

/// A whole path from the origin in a direction drawn by `direction`, by the `path_trace` a
/// grade of `mis` runs beside it (the reference's, as `mis` is graded alone), which calls
/// the `mis` under test at every bounce and continues along the bounce it returns: what
/// `mis` returns beside its radiance (the bounce's weight, its traced segment and
/// `emission_counted`) decides the rest of the path.
fn whole_path<'a, T: Tasks>(
    t: &'a T,
    what: &str,
    scene: Scene,
    direction: fn(&mut Sampler) -> Vec3,
    analytic: f64,
) -> EstimatorSpec<'a> {
    EstimatorSpec {
        name: format!("a whole path through {what}"),
        analytic,
        samples: 40_000,
        estimate: path_trace::path_estimator(t, scene, Vec3::ZERO, direction),
    }
}

/// The same estimator in the same scene in two units of length: its variance must not
/// change (MIS weights that mix a pdf per unit area with one per solid angle do). And the
/// balance heuristic against light sampling alone under the wide light, within Veach's
/// bound: weights that sum to one but are not the balance heuristic's (say
/// `p_a / (p_a − p_b)`) keep every mean and inflate the variance where the densities cross.
pub fn variance_pairs<T: Tasks>(t: &T) -> Vec<VariancePair<'_>> {
    vec![
        VariancePair {
            first: spec(t, Lighting::Open, 1.0, Heuristic::Balance),
            second: spec(t, Lighting::Open, 1000.0, Heuristic::Balance),
            bound: VarianceBound::SameInAnyUnits,
        },
        VariancePair {
            first: spec(t, Lighting::Wide, 1.0, Heuristic::Balance),
            second: spec(t, Lighting::Wide, 1.0, Heuristic::Light),
            bound: VarianceBound::BalanceBelowOther,
        },
    ]
}

/// The stored light the rough floors reflect beside the same quadratures of `t`'s BSDF,
/// at the hit each estimator shades.
pub(crate) fn stored_quadratures<T: Tasks>(t: &T) -> Vec<StoredQuadrature> {
    let mut all = Vec::new();
    for (what, floor, stored) in [
        ("ROUGH_REFLECTED", Floor::Rough, ROUGH_REFLECTED),
        ("ROUGH_GRAZING_REFLECTED", Floor::RoughGrazing, ROUGH_GRAZING_REFLECTED),
    ] {
        let scene = scene(Lighting::Open, 1.0, floor);
        let hit = shading_hit(&scene, Lighting::Open.shading_point());
        let [square, albedo] = stored;
        all.push(StoredQuadrature {
            what: format!("mis {what}[0]"),
            stored: square,
            computed: rough_conductor::over(t, &scene, &hit, floor.wo(), &SQUARE),
        });
        all.push(StoredQuadrature {
            what: format!("mis {what}[1]"),
            stored: albedo,
            computed: rough_conductor::albedo(t, &scene, &hit, floor.wo()),
        });
    }
    all
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_lighting_is_a_valid_scene_at_both_scales() {
        for lighting in Lighting::ALL {
            for scale in [1.0, 1000.0] {
                let scene = scene(lighting, scale, Floor::Diffuse);
                assert!((scene_scale(&scene) - scale).abs() < 1e-3 * scale);
                let hit = shading_hit(&scene, lighting.shading_point());
                assert!((hit.p - lighting.shading_point() * scale).length() < 1e-3 * scale);
            }
        }
    }

    #[test]
    fn the_point_light_lies_exactly_on_its_shading_point() {
        let scene = scene(Lighting::PointOnShadingPoint, 1.0, Floor::Diffuse);
        let hit = shading_hit(&scene, Lighting::PointOnShadingPoint.shading_point());
        let mut sampler = Sampler::new(0, 0);
        let on_point = (0..64).any(|_| {
            matches!(scene.sample_light(hit.p, &mut sampler),
                Some(crate::light::LightSample::Point { p, .. }) if p == hit.p)
        });
        assert!(on_point, "the hit is at {}", hit.p);
    }
}
