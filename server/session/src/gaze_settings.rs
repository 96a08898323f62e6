//! The online gaze processing's configuration as the session header states it.
//!
//! `foveal-gaze` has no serde dependency (it is used by small bridges too), so the header
//! carries this mirror, converted from [`ProcessorConfig`]. It documents the session; a replay
//! does not need it, since every frame's fixation is recorded.

use foveal_gaze::Binocular;
use foveal_gaze::detect::DetectorParams;
use foveal_gaze::online::ProcessorConfig;
use serde::{Deserialize, Serialize};

/// [`ProcessorConfig`], field for field.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GazeSettings {
    /// `mean`, `left`, `right` or `both`.
    pub eyes: String,
    /// Left and right samples this close in tracker time are one instant, seconds.
    pub pair_window_s: f64,
    /// The 1€ filter, if any.
    pub filter: Option<OneEuroSettings>,
    /// The fixation detector, if any.
    pub detector: Option<DetectorSettings>,
    /// Visible screen width, cm (the detector's degrees).
    pub width_cm: f64,
    /// Visible screen height, cm.
    pub height_cm: f64,
    /// Eye to screen centre, cm.
    pub distance_cm: f64,
    /// The last fixation is held this long into track loss, seconds.
    pub hold_s: f64,
    /// Then the foveal region widens by this much per second, deg/s.
    pub widen_deg_per_s: f64,
    /// After this long in track loss the state is lost, seconds.
    pub fallback_s: f64,
}

/// 1€ filter parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct OneEuroSettings {
    /// Cutoff at rest, Hz.
    pub min_cutoff_hz: f64,
    /// Cutoff slope with speed.
    pub beta: f64,
    /// Cutoff of the speed estimate, Hz.
    pub d_cutoff_hz: f64,
}

/// Fixation detector parameters.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum DetectorSettings {
    /// Velocity threshold.
    Ivt {
        /// deg/s.
        velocity_threshold_deg_s: f64,
        /// Seconds.
        velocity_window_s: f64,
        /// Seconds.
        merge_gap_s: f64,
        /// Degrees.
        merge_angle_deg: f64,
        /// Seconds.
        min_duration_s: f64,
        /// Seconds.
        max_gap_s: f64,
    },
    /// Dispersion threshold.
    Idt {
        /// Degrees.
        max_dispersion_deg: f64,
        /// Seconds.
        min_duration_s: f64,
        /// Seconds.
        max_gap_s: f64,
    },
}

impl From<&ProcessorConfig> for GazeSettings {
    fn from(c: &ProcessorConfig) -> Self {
        let eyes = match c.eyes {
            Binocular::Mean => "mean",
            Binocular::Left => "left",
            Binocular::Right => "right",
            Binocular::Both => "both",
        };
        Self {
            eyes: eyes.to_owned(),
            pair_window_s: c.pair_window_s,
            filter: c.filter.map(|f| OneEuroSettings {
                min_cutoff_hz: f.min_cutoff_hz,
                beta: f.beta,
                d_cutoff_hz: f.d_cutoff_hz,
            }),
            detector: c.detector.map(|d| match d {
                DetectorParams::Ivt(p) => DetectorSettings::Ivt {
                    velocity_threshold_deg_s: p.velocity_threshold_deg_s,
                    velocity_window_s: p.velocity_window_s,
                    merge_gap_s: p.merge_gap_s,
                    merge_angle_deg: p.merge_angle_deg,
                    min_duration_s: p.min_duration_s,
                    max_gap_s: p.max_gap_s,
                },
                DetectorParams::Idt(p) => DetectorSettings::Idt {
                    max_dispersion_deg: p.max_dispersion_deg,
                    min_duration_s: p.min_duration_s,
                    max_gap_s: p.max_gap_s,
                },
            }),
            width_cm: c.geometry.width_cm,
            height_cm: c.geometry.height_cm,
            distance_cm: c.geometry.distance_cm,
            hold_s: c.hold_s,
            widen_deg_per_s: c.widen_deg_per_s,
            fallback_s: c.fallback_s,
        }
    }
}
