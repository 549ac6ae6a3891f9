//! The reference solutions.

pub mod aniso_ndf;
pub mod beckmann_ndf;
pub mod brdf_check;
pub mod cook_torrance;
pub mod cosine_sample;
pub mod delta_tracking;
pub mod fresnel_schlick;
pub mod kajiya_kay;
pub mod mis;
pub mod ndf_sample;
pub mod path_trace;
pub mod phong;
pub mod reflect;
pub mod refract_stack;
pub mod smith_g1;
