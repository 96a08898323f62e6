//! foveal-client (under construction)

pub mod gaze;
