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
    /// Radius around (x, y) within which the eye may really be, degrees of visual angle. The
    /// schedulers treat everything inside it as foveal (eccentricity e is scheduled as
    /// max(0, e - radius)), so while a tracker has lost the eye the budget covers where the eye may
    /// have gone; measurement (Δ, P) is always about (x, y) itself. 0 (the default) is a fixation
    /// known exactly, the paper's assumption (section 3).
    #[serde(default)]
    pub uncertainty_deg: f64,
}

impl Fixation {
    /// A fixation with age 0.
    pub fn at(x: f64, y: f64) -> Self {
        Self {
            x,
            y,
            age_s: 0.0,
            uncertainty_deg: 0.0,
        }
    }

    /// The same fixation, uncertain by `radius_deg` (see [`Self::uncertainty_deg`]).
    #[must_use]
    pub fn with_uncertainty(self, radius_deg: f64) -> Self {
        Self {
            uncertainty_deg: radius_deg,
            ..self
        }
    }

    /// Usable: finite coordinates, a finite, non-negative age and a finite, non-negative
    /// uncertainty. A fixation failing this is never used.
    pub fn is_usable(&self) -> bool {
        self.x.is_finite()
            && self.y.is_finite()
            && self.age_s.is_finite()
            && self.age_s >= 0.0
            && self.uncertainty_deg.is_finite()
            && self.uncertainty_deg >= 0.0
    }

    /// Largest |x| or |y| the perceptual computations use: a fixation a thousand screens away is
    /// already infinitely eccentric for every model, and clamping keeps the visual-angle arithmetic
    /// away from overflow for any finite input.
    pub const MAX_OFFSET: f64 = 1e3;

    /// The fixation with coordinates clamped to [-MAX_OFFSET, MAX_OFFSET] and the uncertainty to
    /// [0, 180] degrees (a radius of 180 degrees already covers every direction).
    pub fn clamped(self) -> Self {
        let c = |v: f64| v.clamp(-Self::MAX_OFFSET, Self::MAX_OFFSET);
        Self {
            x: c(self.x),
            y: c(self.y),
            uncertainty_deg: self.uncertainty_deg.clamp(0.0, 180.0),
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
    /// The fixation's uncertainty, degrees ([`Fixation::uncertainty_deg`]): schedulers' views
    /// reduce eccentricity by it; measurement views have 0.
    pub uncertainty_deg: f64,
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
        let mut e = self.eccentricity(c, unit);
        if self.uncertainty_deg > 0.0 {
            e = (e - self.uncertainty_in(unit)).max(0.0);
        }
        self.model.evaluate(self.screen_gap(a, b, unit), e)
    }

    /// The uncertainty radius in `unit` (pixels: at the screen centre).
    pub fn uncertainty_in(&self, unit: EccentricityUnit) -> f64 {
        match unit {
            EccentricityUnit::Degrees => self.uncertainty_deg,
            EccentricityUnit::Pixels => {
                self.uncertainty_deg * self.viewer.display.pixels_per_degree()
            }
        }
    }

    /// The same view measured with another model.
    pub fn with_model(&self, model: PerceptualModel) -> Self {
        Self { model, ..*self }
    }
}
