//! The fixation a frame is scheduled and measured around, and the per-frame view that turns a pair's
//! evidence into eccentricity, on-screen gap and perceptual weight (paper section 3).

use serde::{Deserialize, Serialize};

use crate::math::Vec3;
use crate::narrow_phase::Evidence;
use crate::perception::{EccentricityUnit, PerceptualModel, Viewer};

/// Where the viewer looks: normalised screen coordinates (0..1, origin top-left, y down).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Fixation {
    /// Horizontal position, 0 = left edge, 1 = right edge. Values outside 0..1 are off screen (legal).
    pub x: f64,
    /// Vertical position, 0 = top edge, 1 = bottom edge.
    pub y: f64,
    /// Age of the sample the fixation came from when the frame started (seconds).
    pub age_s: f64,
}

impl Fixation {
    /// A fixation with age 0.
    pub fn at(x: f64, y: f64) -> Self {
        Self { x, y, age_s: 0.0 }
    }

    /// Usable: finite coordinates and a finite, non-negative age. A fixation failing this is never used.
    pub fn is_usable(&self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.age_s.is_finite() && self.age_s >= 0.0
    }

    /// Largest |x| or |y| the perceptual computations use: a fixation a thousand screens away is
    /// already infinitely eccentric for every model, and clamping keeps the visual-angle arithmetic
    /// away from overflow for any finite input.
    pub const MAX_OFFSET: f64 = 1e3;

    /// The fixation with coordinates clamped to [-MAX_OFFSET, MAX_OFFSET].
    pub fn clamped(self) -> Self {
        let c = |v: f64| v.clamp(-Self::MAX_OFFSET, Self::MAX_OFFSET);
        Self {
            x: c(self.x),
            y: c(self.y),
            ..self
        }
    }
}

/// Screen, fixation and model for one frame.
#[derive(Debug, Clone, Copy)]
pub struct FrameView<'a> {
    /// Camera and display.
    pub viewer: &'a Viewer,
    /// Fixation in pixels.
    pub fixation_px: [f64; 2],
    /// The model weights are computed with.
    pub model: PerceptualModel,
}

impl FrameView<'_> {
    /// Eccentricity of a world point from the fixation, in `unit`.
    pub fn eccentricity(&self, p: Vec3, unit: EccentricityUnit) -> f64 {
        self.viewer
            .screen_distance(self.viewer.project(p), self.fixation_px, unit)
    }

    /// On-screen gap between two world points (their projected distance), in `unit`.
    pub fn screen_gap(&self, a: Vec3, b: Vec3, unit: EccentricityUnit) -> f64 {
        self.viewer
            .screen_distance(self.viewer.project(a), self.viewer.project(b), unit)
    }

    /// F(g', e) of the model for a pair's evidence: g' the projected distance of the two sphere
    /// centres, e the eccentricity of the centre of collision.
    pub fn weight(&self, ev: &Evidence) -> f64 {
        self.weight_points(ev.center_a, ev.center_b, ev.centre_of_collision)
    }

    /// F(g', e) for a gap between world points `a` and `b` around centre `c`.
    pub fn weight_points(&self, a: Vec3, b: Vec3, c: Vec3) -> f64 {
        let unit = self.model.unit;
        self.model
            .evaluate(self.screen_gap(a, b, unit), self.eccentricity(c, unit))
    }

    /// The same view measured with another model.
    pub fn with_model(&self, model: PerceptualModel) -> Self {
        Self { model, ..*self }
    }
}
