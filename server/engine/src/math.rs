//! One place for the numeric types the engine uses.
//!
//! World state (positions, velocities, orientations) is `f64` so that a scene far from the origin
//! keeps its precision. Sphere-tree geometry and the pair-relative kernels are `f32`: every sphere test
//! is done in the frame of one body of the pair, where coordinates are of the order of the shape
//! radius, so single precision loses nothing and halves the memory traffic of the hot loop.

/// World-space vector (scene units).
pub type Vec3 = glam::DVec3;
/// World-space orientation (unit quaternion).
pub type Quat = glam::DQuat;
/// Body-frame or pair-relative vector (scene units, relative to a body centre).
pub type LVec3 = glam::Vec3A;
/// Body-frame or pair-relative rotation.
pub type LMat3 = glam::Mat3A;
