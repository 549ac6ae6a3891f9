//! The image check: a student's render against the reference, pixel-channel by
//! pixel-channel, by a z-test on the difference of the two Monte Carlo means (the scheme of
//! Mitsuba's test suite). A render passes when at least [`PASS_FRACTION`] of its
//! pixel-channels pass; a false-colour image shows where and in which direction it differs.

use serde::{Deserialize, Serialize};

/// A Monte Carlo render: the per-pixel mean and the variance of that mean, linear RGB,
/// row-major, 3 floats per pixel.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImageStats {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Mean radiance per pixel-channel.
    #[serde(with = "super::lenient_f64::seq_f32")]
    pub mean: Vec<f32>,
    /// Variance of each mean (sample variance / sample count).
    #[serde(with = "super::lenient_f64::seq_f32")]
    pub variance: Vec<f32>,
}

/// Share of pixel-channels that must pass for the render to pass.
pub const PASS_FRACTION: f64 = 0.995;

/// |z| above which a pixel-channel fails: two-sided α = 1e-4 per pixel-channel. A pixel's
/// Monte Carlo mean is only roughly normal at a few hundred samples (a glossy highlight's
/// samples are skewed, and their sample variance is then too small), so a correct render
/// fails more pixel-channels than α says; this margin keeps that well under the 0.5 %
/// allowed.
pub const Z_CRITICAL: f64 = 3.890_591_886;

/// |z| above which the whole image fails: the z-score, per colour channel, of the summed
/// difference over every pixel, which catches a small bias everywhere (10 % too bright) that
/// no single noisy pixel shows. Pixels are independent, so a sum of thousands of them is
/// close to normal even where single pixels are not (channels of one pixel share their
/// paths, hence one sum per channel); two-sided α ≈ 6e-5 per channel.
pub const Z_AGGREGATE: f64 = 4.0;

/// The declared false-failure rate of one image check on a correct render: the three
/// aggregate tests take 3 · 6.3e-5 ≈ 1.9e-4, and the rest bounds the pass-fraction test,
/// whose per-pixel normality is only approximate (see [`Z_CRITICAL`]).
pub const ALPHA: f64 = 1e-3;

/// Variance floor, so pixels where both renders are exactly constant (black background)
/// compare by value instead of dividing by zero.
const VARIANCE_FLOOR: f64 = 1e-12;

/// The outcome of comparing two renders (drawn by the HTML report).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ImageDetail {
    /// The scene or image name.
    pub name: String,
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// Share of pixel-channels whose |z| ≤ [`Z_CRITICAL`].
    pub pass_fraction: f64,
    /// Largest |z| (infinite at a NaN or infinite pixel).
    #[serde(with = "super::lenient_f64")]
    pub worst_z: f64,
    /// The pixel (x, y) where it occurs.
    pub worst_pixel: (usize, usize),
    /// The largest (in magnitude) per-channel z-score of the summed difference over all
    /// pixels.
    #[serde(with = "super::lenient_f64")]
    pub total_z: f64,
    /// Pixel-channels that are NaN or infinite in the student's render.
    pub non_finite: usize,
    /// Files written for the report (student, reference, difference PNGs), if any.
    pub files: Vec<String>,
}

/// Compares `student` with `reference`; `Err` when the sizes differ.
pub fn compare(
    name: &str,
    student: &ImageStats,
    reference: &ImageStats,
) -> Result<(ImageDetail, Vec<f64>), String> {
    if (student.width, student.height) != (reference.width, reference.height)
        || student.mean.len() != reference.mean.len()
        || student.variance.len() != student.mean.len()
        || reference.variance.len() != reference.mean.len()
    {
        return Err(format!(
            "{name}: the render is {}×{}, the reference {}×{}",
            student.width, student.height, reference.width, reference.height
        ));
    }
    let mut z = Vec::with_capacity(student.mean.len());
    let (mut passed, mut non_finite, mut worst) = (0usize, 0usize, (0.0f64, 0, 0));
    let (mut sum_diff, mut sum_var) = ([0.0f64; 3], [0.0f64; 3]);
    for (i, (((&s, &r), &vs), &vr)) in student
        .mean
        .iter()
        .zip(&reference.mean)
        .zip(&student.variance)
        .zip(&reference.variance)
        .enumerate()
    {
        let zi = if !s.is_finite() || !vs.is_finite() {
            non_finite += 1;
            f64::INFINITY
        } else {
            sum_diff[i % 3] += s as f64 - r as f64;
            sum_var[i % 3] += vs as f64 + vr as f64;
            (s as f64 - r as f64) / (vs as f64 + vr as f64).max(VARIANCE_FLOOR).sqrt()
        };
        if zi.abs() <= Z_CRITICAL {
            passed += 1;
        }
        let pixel = i / 3;
        if zi.abs() > worst.0 {
            worst = (zi.abs(), pixel % student.width, pixel / student.width);
        }
        z.push(zi);
    }
    let detail = ImageDetail {
        name: name.into(),
        width: student.width,
        height: student.height,
        pass_fraction: passed as f64 / z.len().max(1) as f64,
        worst_z: worst.0,
        total_z: (0..3)
            .map(|c| sum_diff[c] / sum_var[c].max(VARIANCE_FLOOR).sqrt())
            .max_by(|a, b| a.abs().total_cmp(&b.abs()))
            .unwrap_or(0.0),
        worst_pixel: (worst.1, worst.2),
        non_finite,
        files: Vec::new(),
    };
    Ok((detail, z))
}

impl ImageDetail {
    /// True when enough pixel-channels pass.
    pub fn passed(&self) -> bool {
        self.pass_fraction >= PASS_FRACTION
            && self.total_z.abs() <= Z_AGGREGATE
            && self.non_finite == 0
    }

    /// What fails, in words (empty when the check passes): the property each failing
    /// criterion states, for the failure list (the numbers are in [`ImageDetail::describe`]).
    pub fn violations(&self) -> Vec<String> {
        let mut v = Vec::new();
        if self.non_finite > 0 {
            v.push(format!(
                "{} pixel-channels are NaN or infinite: every pixel must be finite",
                self.non_finite
            ));
        }
        if self.pass_fraction < PASS_FRACTION {
            v.push(format!(
                "only {:.2} % of pixel-channels agree with the reference within noise (need \
                 {:.1} %): the picture differs somewhere (see the z-map)",
                100.0 * self.pass_fraction,
                100.0 * PASS_FRACTION
            ));
        }
        if self.total_z.abs() > Z_AGGREGATE {
            v.push(format!(
                "the whole image is {} than the reference by z = {:.1} (need |z| ≤ {}): a \
                 bias shared by many pixels",
                if self.total_z > 0.0 {
                    "brighter"
                } else {
                    "darker"
                },
                self.total_z,
                Z_AGGREGATE
            ));
        }
        v
    }

    /// One line for reports.
    pub fn describe(&self) -> String {
        format!(
            "{}: {:.2} % of pixel-channels within |z| ≤ {:.2} (need {:.1} %); whole image z = {:.1} (need |z| ≤ {}); worst |z| = {:.1} at pixel ({}, {}){}",
            self.name,
            100.0 * self.pass_fraction,
            Z_CRITICAL,
            100.0 * PASS_FRACTION,
            self.total_z,
            Z_AGGREGATE,
            self.worst_z,
            self.worst_pixel.0,
            self.worst_pixel.1,
            if self.non_finite > 0 {
                format!("; {} pixel-channels are NaN or infinite", self.non_finite)
            } else {
                String::new()
            }
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grade::render_check::image_result as run;
    use crate::grade::report::images::false_colour;
    use crate::grade::verdict::Detail;
    use crate::sampling::Sampler;

    fn render(width: usize, height: usize, value: f32, sigma: f32, seed: u64) -> ImageStats {
        let mut s = Sampler::new(seed, 0);
        let n = width * height * 3;
        // A Box-Muller normal deviate per pixel-channel around `value`.
        let mean = (0..n)
            .map(|_| {
                let u = s.next_2d();
                let g = (-2.0 * (1.0 - u.x).ln()).sqrt() * (std::f32::consts::TAU * u.y).cos();
                value + sigma * g
            })
            .collect();
        ImageStats {
            width,
            height,
            mean,
            variance: vec![sigma * sigma; n],
        }
    }

    #[test]
    fn renders_of_the_same_scene_agree_and_a_darker_one_does_not() {
        let reference = render(64, 48, 0.5, 0.01, 1);
        let (detail, _) = compare("same", &render(64, 48, 0.5, 0.01, 2), &reference).unwrap();
        assert!(detail.passed(), "{}", detail.describe());
        let (detail, z) = compare("dark", &render(64, 48, 0.45, 0.01, 3), &reference).unwrap();
        assert!(!detail.passed());
        let picture = false_colour(&z);
        assert_eq!(picture.len(), 64 * 48 * 3);
        assert_eq!(picture[2], 255, "too dark shows blue");
    }

    #[test]
    fn the_check_writes_its_images_and_fails_a_biased_render() {
        let dir = tempfile::tempdir().unwrap();
        let reference = render(16, 8, 0.5, 0.01, 1);
        let ok = run(
            "same",
            &render(16, 8, 0.5, 0.01, 2),
            &reference,
            Some(dir.path()),
        );
        assert!(ok.passed, "{}", ok.summary);
        let Some(Detail::Image(detail)) = &ok.detail else {
            panic!("no detail")
        };
        assert_eq!(detail.files.len(), 5);
        let bright = run("bright", &render(16, 8, 0.6, 0.01, 3), &reference, None);
        assert!(!bright.passed);
        assert!(
            bright.failures[0].contains("of pixel-channels"),
            "{:?}",
            bright.failures
        );
        // Each failing criterion once, as a property; the numbers only in the summary.
        assert_eq!(bright.failures.len(), 2, "{:?}", bright.failures);
        assert!(
            bright.failures[1].contains("brighter"),
            "{:?}",
            bright.failures
        );
        assert!(
            !bright
                .failures
                .iter()
                .any(|f| bright.summary.contains(f.as_str()))
        );
    }

    #[test]
    fn nan_pixels_and_size_mismatches_are_named() {
        let reference = render(8, 8, 0.5, 0.01, 1);
        let mut student = render(8, 8, 0.5, 0.01, 2);
        student.mean[5] = f32::NAN;
        let (detail, _) = compare("nan", &student, &reference).unwrap();
        assert_eq!(detail.non_finite, 1);
        assert!(detail.describe().contains("NaN"));
        assert!(detail.violations()[0].contains("NaN or infinite"));
        assert!(compare("size", &render(4, 8, 0.5, 0.01, 2), &reference).is_err());
    }
}
