//! Widgets shared by the panels and the controls: the image view (GPU or CPU textures), the
//! editors of the scene's parameters, and a result's status line.

pub mod image;
pub mod params;
pub mod status;
