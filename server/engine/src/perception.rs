//! The perceptual model (paper section 3): where a collision lands on screen, how far that is from
//! the fixation (eccentricity), how big its gap looks, and the functions F that turn the two into a
//! perceived inaccuracy.
//!
//! Eccentricity and gap are available in pixels and in degrees of visual angle. Pixels are what the
//! paper uses; degrees are what transfers between displays and viewing distances, computed from the
//! display geometry (resolution, physical diagonal, viewing distance) with the eye in front of the
//! screen centre. The camera is perspective, on the axis through the centre of the volume's front
//! face at a fixed distance from it, with the same viewport for every N (section 4).

use serde::{Deserialize, Serialize};

use crate::math::Vec3;
use crate::validate::{ConfigError, check_finite_positive, check_finite_range};

/// The physical display the viewer looks at.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Display {
    /// Horizontal resolution (pixels).
    pub width_px: u32,
    /// Vertical resolution (pixels).
    pub height_px: u32,
    /// Diagonal (inches).
    pub diagonal_in: f64,
    /// Eye-to-screen distance (centimetres).
    pub viewing_distance_cm: f64,
}

impl Default for Display {
    /// The paper's set-up: a 22-inch monitor viewed from 70 cm, here at 1680x1050.
    fn default() -> Self {
        Self {
            width_px: 1680,
            height_px: 1050,
            diagonal_in: 22.0,
            viewing_distance_cm: 70.0,
        }
    }
}

impl Display {
    /// Check every field.
    pub fn validate(&self) -> Result<(), ConfigError> {
        if !(1..=100_000).contains(&self.width_px) {
            return Err(ConfigError::new(
                "display.width_px",
                self.width_px,
                "must be in 1..=100000",
            ));
        }
        if !(1..=100_000).contains(&self.height_px) {
            return Err(ConfigError::new(
                "display.height_px",
                self.height_px,
                "must be in 1..=100000",
            ));
        }
        check_finite_range("display.diagonal_in", self.diagonal_in, 0.1, 10_000.0)?;
        check_finite_range(
            "display.viewing_distance_cm",
            self.viewing_distance_cm,
            0.1,
            100_000.0,
        )
    }

    /// Physical size of one (square) pixel, centimetres.
    pub fn pixel_pitch_cm(&self) -> f64 {
        self.diagonal_in * 2.54 / f64::from(self.width_px).hypot(f64::from(self.height_px))
    }

    /// Pixels per degree of visual angle at the screen centre, where a degree spans the fewest
    /// pixels of a flat screen: an angle expressed in the pixel unit this way is never larger than
    /// it is anywhere on the screen.
    pub fn pixels_per_degree(&self) -> f64 {
        self.viewing_distance_cm * 1f64.to_radians().tan() / self.pixel_pitch_cm()
    }

    /// Unit ray from the eye (in front of the screen centre) to a screen point given in pixels.
    /// The angle between two points is the angle between their rays; comparing the chord of two
    /// rays with 2 sin(threshold / 2) tests an angle against a threshold with no trigonometry.
    #[inline]
    pub fn eye_ray(&self, px: [f64; 2]) -> [f64; 3] {
        let pitch = self.pixel_pitch_cm();
        let v = [
            (px[0] - 0.5 * f64::from(self.width_px)) * pitch,
            (px[1] - 0.5 * f64::from(self.height_px)) * pitch,
            self.viewing_distance_cm,
        ];
        let inv = 1.0 / (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        [v[0] * inv, v[1] * inv, v[2] * inv]
    }

    /// Visual angle (degrees) between two screen points given in pixels.
    pub fn visual_angle_deg(&self, a: [f64; 2], b: [f64; 2]) -> f64 {
        let pitch = self.pixel_pitch_cm();
        let (cx, cy) = (
            0.5 * f64::from(self.width_px),
            0.5 * f64::from(self.height_px),
        );
        let to_eye = |p: [f64; 2]| {
            Vec3::new(
                (p[0] - cx) * pitch,
                (p[1] - cy) * pitch,
                self.viewing_distance_cm,
            )
        };
        let (u, v) = (to_eye(a), to_eye(b));
        u.cross(v).length().atan2(u.dot(v)).to_degrees()
    }
}

/// Camera placement relative to the volume.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct CameraConfig {
    /// Distance from the eye point to the volume's front face (scene units), the same for every N.
    pub distance: f64,
    /// Vertical field of view (degrees).
    pub fov_y_deg: f64,
}

impl Default for CameraConfig {
    fn default() -> Self {
        Self {
            distance: 2.0,
            fov_y_deg: 60.0,
        }
    }
}

impl CameraConfig {
    /// Check every field.
    pub fn validate(&self) -> Result<(), ConfigError> {
        check_finite_positive("camera.distance", self.distance)?;
        check_finite_range("camera.fov_y_deg", self.fov_y_deg, 1.0, 170.0)
    }
}

/// A perspective camera looking down -z at the front face (z = max) of the volume, plus the display.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Viewer {
    /// Eye position (world).
    pub eye: Vec3,
    /// Point looked at: the centre of the front face.
    pub target: Vec3,
    /// Vertical field of view (degrees).
    pub fov_y_deg: f64,
    /// Display geometry.
    pub display: Display,
    #[serde(skip)]
    focal_px: f64,
}

impl Viewer {
    /// Camera for the volume [origin, origin + side]^3.
    pub fn new(camera: &CameraConfig, display: &Display, origin: Vec3, side: f64) -> Self {
        let target = origin + Vec3::new(0.5 * side, 0.5 * side, side);
        let eye = target + Vec3::new(0.0, 0.0, camera.distance);
        let focal_px =
            0.5 * f64::from(display.height_px) / (0.5 * camera.fov_y_deg.to_radians()).tan();
        Self {
            eye,
            target,
            fov_y_deg: camera.fov_y_deg,
            display: *display,
            focal_px,
        }
    }

    /// Screen position (pixels, origin top-left, y down) of world point `p`. Points at or behind the
    /// eye plane are pushed to a tiny positive depth, which sends them far off screen.
    #[inline]
    pub fn project(&self, p: Vec3) -> [f64; 2] {
        let r = p - self.eye;
        let depth = (-r.z).max(1e-9 * (1.0 + r.x.abs() + r.y.abs()));
        let s = self.focal_px / depth;
        [
            0.5 * f64::from(self.display.width_px) + r.x * s,
            0.5 * f64::from(self.display.height_px) - r.y * s,
        ]
    }

    /// The camera's focal length in pixels: a unit length at depth z spans `focal_px / z` pixels.
    pub fn focal_px(&self) -> f64 {
        self.focal_px
    }

    /// Distance between two screen points in `unit`.
    #[inline]
    pub fn screen_distance(&self, a: [f64; 2], b: [f64; 2], unit: EccentricityUnit) -> f64 {
        match unit {
            EccentricityUnit::Pixels => (a[0] - b[0]).hypot(a[1] - b[1]),
            EccentricityUnit::Degrees => self.display.visual_angle_deg(a, b),
        }
    }

    /// Pixel position of a normalised screen point (0..1, origin top-left).
    pub fn to_pixels(&self, x: f64, y: f64) -> [f64; 2] {
        [
            x * f64::from(self.display.width_px),
            y * f64::from(self.display.height_px),
        ]
    }
}

/// Unit in which a model measures eccentricity and gap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum EccentricityUnit {
    /// Screen pixels, as in the paper.
    Pixels,
    /// Degrees of visual angle.
    Degrees,
}

/// The function F(g, e) of section 3.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PerceptualFunction {
    /// F1 = g / e, and g at e = 0: a steep, "tunnel vision" fall-off.
    F1,
    /// F2 = g / exp(e / C): gradual fall-off (the model the paper's experiment 4 supports).
    F2 {
        /// Fall-off constant, in the model's unit.
        c: f64,
    },
    /// F2 averaged over a range of fall-off constants: g times the mean of exp(-e / C) over C
    /// log-uniform in [`c_min`, `c_max`] (ours). For scheduling when the viewer's true C is not
    /// known: it weighs the near periphery like a small C and the far periphery like a large one, so
    /// no single wrong guess of C sends the budget to the wrong place.
    F2Range {
        /// Smallest fall-off constant, in the model's unit.
        c_min: f64,
        /// Largest fall-off constant, in the model's unit.
        c_max: f64,
    },
    /// F3 = F2 with C piecewise in e: C1 below `e1`, C2 below `e2`, C3 beyond.
    F3 {
        /// Constant for e < e1.
        c1: f64,
        /// Constant for e1 <= e < e2.
        c2: f64,
        /// Constant for e >= e2.
        c3: f64,
        /// First break (paper: 20).
        e1: f64,
        /// Second break (paper: 100).
        e2: f64,
    },
}

/// A perceptual model: F and the unit of its arguments.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct PerceptualModel {
    /// The function.
    pub function: PerceptualFunction,
    /// Unit of g and e.
    pub unit: EccentricityUnit,
}

impl Default for PerceptualModel {
    /// F2 with C = 5 degrees: weight halves about every 3.5 degrees from the fovea.
    fn default() -> Self {
        Self {
            function: PerceptualFunction::F2 { c: 5.0 },
            unit: EccentricityUnit::Degrees,
        }
    }
}

impl PerceptualModel {
    /// The scheduling default: F2 averaged over C log-uniform in [1, 10] degrees, robust to not
    /// knowing the viewer's C (see `SimConfig::schedule_model`).
    pub fn scheduling_default() -> Self {
        Self {
            function: PerceptualFunction::F2Range {
                c_min: 1.0,
                c_max: 10.0,
            },
            unit: EccentricityUnit::Degrees,
        }
    }

    /// The paper's F1 in pixels.
    pub fn f1_pixels() -> Self {
        Self {
            function: PerceptualFunction::F1,
            unit: EccentricityUnit::Pixels,
        }
    }

    /// Check the constants (all > 0, breaks ordered).
    pub fn validate(&self, field: &'static str) -> Result<(), ConfigError> {
        let c = |v: f64| check_finite_positive(field, v);
        match self.function {
            PerceptualFunction::F1 => Ok(()),
            PerceptualFunction::F2 { c: k } => c(k),
            PerceptualFunction::F2Range { c_min, c_max } => {
                c(c_min)?;
                c(c_max)?;
                if c_min <= c_max {
                    Ok(())
                } else {
                    Err(ConfigError::new(
                        field,
                        format!("c_min={c_min}, c_max={c_max}"),
                        "F2 range must satisfy c_min <= c_max",
                    ))
                }
            }
            PerceptualFunction::F3 { c1, c2, c3, e1, e2 } => {
                c(c1)?;
                c(c2)?;
                c(c3)?;
                c(e1)?;
                c(e2)?;
                if e1 < e2 {
                    Ok(())
                } else {
                    Err(ConfigError::new(
                        field,
                        format!("e1={e1}, e2={e2}"),
                        "F3 breaks must satisfy e1 < e2",
                    ))
                }
            }
        }
    }

    /// F(g, e) for gap `g` and eccentricity `e`, both in this model's unit.
    #[inline]
    pub fn evaluate(&self, g: f64, e: f64) -> f64 {
        match self.function {
            PerceptualFunction::F1 => {
                if e > 0.0 {
                    g / e
                } else {
                    g
                }
            }
            PerceptualFunction::F2 { c } => g / (e / c).exp(),
            PerceptualFunction::F2Range { c_min, c_max } => g * f2_range_falloff(e, c_min, c_max),
            PerceptualFunction::F3 { c1, c2, c3, e1, e2 } => {
                let c = if e < e1 {
                    c1
                } else if e < e2 {
                    c2
                } else {
                    c3
                };
                g / (e / c).exp()
            }
        }
    }
}

/// Points of the quadrature over log C in [`PerceptualFunction::F2Range`]: the integrand is smooth
/// in log C, and 16 midpoints agree with 1,024 to better than 0.1% for ranges up to 100x.
const F2_RANGE_POINTS: u32 = 16;

/// Mean of exp(-e / C) over C log-uniform in [c_min, c_max] (midpoint rule in log C).
fn f2_range_falloff(e: f64, c_min: f64, c_max: f64) -> f64 {
    if c_max <= c_min {
        return (-e / c_min).exp();
    }
    let (lo, span) = (c_min.ln(), (c_max / c_min).ln());
    let n = f64::from(F2_RANGE_POINTS);
    (0..F2_RANGE_POINTS)
        .map(|k| (-e / (lo + span * (f64::from(k) + 0.5) / n).exp()).exp())
        .sum::<f64>()
        / n
}

#[cfg(test)]
mod tests {
    use super::*;

    fn viewer() -> Viewer {
        Viewer::new(
            &CameraConfig::default(),
            &Display::default(),
            Vec3::ZERO,
            1.0,
        )
    }

    #[test]
    fn front_face_centre_projects_to_screen_centre_and_axes_point_right_and_down() {
        let v = viewer();
        let c = v.project(Vec3::new(0.5, 0.5, 1.0));
        assert!(
            (c[0] - 840.0).abs() < 1e-9 && (c[1] - 525.0).abs() < 1e-9,
            "{c:?}"
        );
        let right = v.project(Vec3::new(0.6, 0.5, 1.0));
        let up = v.project(Vec3::new(0.5, 0.6, 1.0));
        assert!(right[0] > c[0] && (right[1] - c[1]).abs() < 1e-9);
        assert!(up[1] < c[1], "world +y is screen up");
        let far = v.project(Vec3::new(0.6, 0.5, 0.0));
        assert!(
            far[0] - c[0] < right[0] - c[0],
            "perspective shrinks distant offsets"
        );
    }

    #[test]
    fn visual_angle_matches_geometry() {
        let d = Display::default();
        // One degree at 70 cm is 1.2218 cm; the pixel pitch of a 22" 1680x1050 display is 0.02821 cm.
        let px = 70.0 * 1f64.to_radians().tan() / d.pixel_pitch_cm();
        let a = d.visual_angle_deg([840.0, 525.0], [840.0 + px, 525.0]);
        assert!((a - 1.0).abs() < 1e-9, "{a}");
        assert_eq!(d.visual_angle_deg([10.0, 10.0], [10.0, 10.0]), 0.0);
    }

    #[test]
    fn models_fall_off_with_eccentricity_and_handle_zero() {
        let f1 = PerceptualModel::f1_pixels();
        assert_eq!(f1.evaluate(3.0, 0.0), 3.0);
        assert_eq!(f1.evaluate(3.0, 2.0), 1.5);
        let f2 = PerceptualModel::default();
        assert_eq!(f2.evaluate(2.0, 0.0), 2.0);
        assert!(f2.evaluate(2.0, 10.0) < f2.evaluate(2.0, 1.0));
        let f3 = PerceptualModel {
            function: PerceptualFunction::F3 {
                c1: 1.0,
                c2: 2.0,
                c3: 4.0,
                e1: 20.0,
                e2: 100.0,
            },
            unit: EccentricityUnit::Pixels,
        };
        assert!((f3.evaluate(1.0, 10.0) - (-10.0f64).exp()).abs() < 1e-15);
        assert!((f3.evaluate(1.0, 50.0) - (-25.0f64).exp()).abs() < 1e-15);
        assert!(f3.validate("m").is_ok());
        let range = PerceptualModel {
            function: PerceptualFunction::F2Range {
                c_min: 1.0,
                c_max: 10.0,
            },
            unit: EccentricityUnit::Degrees,
        };
        assert_eq!(range.evaluate(2.0, 0.0), 2.0);
        // Between the two extremes of its range, and decreasing.
        let (lo, hi) = ((-5.0f64).exp(), (-0.5f64).exp());
        let mid = range.evaluate(1.0, 5.0);
        assert!(lo < mid && mid < hi, "{mid}");
        assert!(range.evaluate(1.0, 6.0) < mid);
        let bad = PerceptualModel {
            function: PerceptualFunction::F2 { c: 0.0 },
            unit: EccentricityUnit::Pixels,
        };
        assert!(bad.validate("measure_model").is_err());
    }
}
