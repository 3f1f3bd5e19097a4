//! Mapping of 2D patterns onto the unit sphere.
use glam::{DVec2, DVec3};
pub fn square_to_sphere(p: DVec2) -> DVec3 {
    let _ = p;
    unimplemented!()
}
