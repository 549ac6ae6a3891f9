//! Materials: lossless ones are invisible under a white sky (glass and a perfect mirror in
//! the furnace), and every material's BSDF sampling agrees with its evaluation (BSDF
//! sampling and light sampling estimate the same direct light).

use pbrlab::render::{RenderOptions, RenderOutput, render};
use pbrlab::scene::schema::Strategy;
use pbrlab::scene::{LoadOptions, Scene};
use pbrlab_solutions::TASKS as Reference;
use std::path::Path;

fn scene(text: &str, options: &LoadOptions) -> Scene {
    Scene::from_yaml(Path::new("materials-test.yaml"), text, options)
        .unwrap_or_else(|e| panic!("{e}"))
}

/// The mean over all pixels and its standard error (pixels are independent).
fn image_mean(out: &RenderOutput) -> (f64, f64) {
    let n = out.mean.pixels.len() as f64;
    let spp = out.stats.spp as f64;
    let sum: f64 = out
        .mean
        .pixels
        .iter()
        .map(|p| p.element_sum() as f64 / 3.0)
        .sum();
    let var: f64 = out
        .variance
        .pixels
        .iter()
        .map(|v| v.element_sum() as f64 / 3.0 / spp)
        .sum();
    (sum / n, var.sqrt() / n)
}

fn furnace(material: &str) -> String {
    format!(
        "camera: {{eye: [0, 0, 4], target: [0, 0, 0], fov: 30, width: 24, height: 24}}\n\
         render: {{spp: 64, rr_depth: 6}}\n\
         materials: {{m: {material}}}\n\
         shapes: [sphere: {{center: [0, 0, 0], radius: 0.9, material: m}}]\n\
         lights: [environment: {{radiance: 1}}]\n"
    )
}

#[test]
fn lossless_materials_are_invisible_in_the_furnace() {
    for material in [
        "{dielectric: {ior: 1.5}}",
        "{dielectric: {ior: 1.33, fresnel: schlick}}",
        "{mirror: {reflectance: 1}}",
    ] {
        let s = scene(&furnace(material), &LoadOptions::default());
        let out = render(&s, &Reference, &RenderOptions::from_scene(&s));
        let (mean, se) = image_mean(&out);
        let z = (mean - 1.0) / se.max(1e-7);
        assert!(
            z.abs() < 4.5,
            "{material}: mean {mean} ({z:.2} s.e. from 1)"
        );
        assert_eq!(out.stats.rejected_samples, 0);
    }
}

/// Direct light only, by BSDF sampling and by light sampling: the two must agree.
fn assert_strategies_agree(text: &str, what: &str) {
    let mut means = Vec::new();
    for strategy in [Strategy::Bsdf, Strategy::Light] {
        let options = LoadOptions {
            strategy: Some(strategy),
            max_depth: Some(2),
            ..Default::default()
        };
        let s = scene(text, &options);
        let out = render(&s, &Reference, &RenderOptions::from_scene(&s));
        means.push(image_mean(&out));
    }
    let ((a, sa), (b, sb)) = (means[0], means[1]);
    let z = (a - b) / (sa * sa + sb * sb).sqrt();
    assert!(z.abs() < 4.5, "{what}: bsdf {a} vs light {b} ({z:.2} s.e.)");
}

fn lit(material: &str, shape: &str) -> String {
    format!(
        "camera: {{eye: [0, 1.2, 3], target: [0, 0.2, 0], fov: 35, width: 24, height: 24}}\n\
         render: {{spp: 256}}\n\
         materials: {{m: {material}}}\n\
         shapes:\n  - {shape}\n\
         \x20 - sphere: {{center: [-1, 2, 1], radius: 0.5, emission: 3}}\n\
         lights: [environment: {{radiance: 0.3}}]\n"
    )
}

const SPHERE: &str = "sphere: {center: [0, 0.2, 0], radius: 0.6, material: m}";

#[test]
fn sampling_agrees_with_evaluation() {
    for material in [
        "{diffuse: {albedo: 0.7}}",
        "{diffuse: {albedo: 0.7, sampling: uniform}}",
        "{conductor: {roughness: 0.3, reflectance: [0.9, 0.6, 0.3]}}",
        "{conductor: {roughness: 0.8, eta: [0.2, 0.9, 1.1], k: [3.9, 2.4, 2.1]}}",
        "{conductor: {alpha_x: 0.1, alpha_y: 0.5, reflectance: 0.9}}",
        "{phong: {kd: 0.4, ks: 0.4, exponent: 20}}",
    ] {
        assert_strategies_agree(&lit(material, SPHERE), material);
    }
    let hair = "fibres: {strands: {ball: {center: [0, 0.2, 0], radius: 0.3, count: 300, length: 0.3, segments: 4, curl: 2}}, radius: 0.01, material: m}";
    assert_strategies_agree(
        &lit("{kajiya_kay: {kd: 0.2, ks: 0.3, exponent: 20}}", hair),
        "kajiya_kay",
    );
}
