//! Vector helpers and shading frames shared by every part of pbrlab.
//!
//! Convention (used everywhere): directions point *away* from the surface, and in the local
//! shading frame the surface normal is +z, so `cos_theta(w) = w.z`.

mod frame;
mod spherical;

pub use frame::Frame;
pub use spherical::{
    abs_cos_theta, cos_phi, cos_theta, cos2_theta, same_hemisphere, sin_phi, sin_theta, sin2_theta,
    spherical_direction, tan2_theta,
};
