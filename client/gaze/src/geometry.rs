//! Screen positions as directions of gaze: the display geometry that turns normalised screen
//! coordinates into degrees of visual angle, the unit every fixation threshold is stated in.

use thiserror::Error;

/// A display geometry field that cannot work.
#[derive(Debug, Error, PartialEq)]
#[error("display geometry: `{field}` = {value} must be finite and > 0")]
pub struct GeometryError {
    /// The field.
    pub field: &'static str,
    /// Its value.
    pub value: f64,
}

/// Where the viewer's eye is relative to the screen: its physical size and the viewing distance,
/// the eye facing the screen centre. Resolution does not enter: positions are normalised.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewingGeometry {
    /// Width of the visible screen area, cm.
    pub width_cm: f64,
    /// Height of the visible screen area, cm.
    pub height_cm: f64,
    /// Eye to screen centre, cm.
    pub distance_cm: f64,
}

impl Default for ViewingGeometry {
    /// A 24-inch 16:9 monitor (53.1 x 29.9 cm) viewed from 60 cm: a common eye-tracking desk
    /// set-up, about 48 x 28 degrees (37 px per degree at 1920x1080).
    fn default() -> Self {
        Self {
            width_cm: 53.1,
            height_cm: 29.9,
            distance_cm: 60.0,
        }
    }
}

impl ViewingGeometry {
    /// Checks every field.
    ///
    /// # Errors
    /// The first field that is not finite and positive.
    pub fn validate(&self) -> Result<(), GeometryError> {
        for (field, value) in [
            ("width_cm", self.width_cm),
            ("height_cm", self.height_cm),
            ("distance_cm", self.distance_cm),
        ] {
            if !(value.is_finite() && value > 0.0) {
                return Err(GeometryError { field, value });
            }
        }
        Ok(())
    }

    /// The gaze direction of normalised screen point (x, y) as (azimuth, elevation) in degrees
    /// from the screen centre (elevation positive downwards, as y). Distances between these
    /// coordinates are within 2% of the true angle between the rays over a desktop screen (the
    /// horizontal scale shrinks with the cosine of the elevation), and
    /// exact along the axes through the centre.
    #[must_use]
    pub fn degrees(&self, x: f64, y: f64) -> (f64, f64) {
        let xc = (x - 0.5) * self.width_cm;
        let yc = (y - 0.5) * self.height_cm;
        let az = xc.atan2(self.distance_cm);
        let el = yc.atan2(xc.hypot(self.distance_cm));
        (az.to_degrees(), el.to_degrees())
    }

    /// The angle in degrees between the gaze rays to normalised points `a` and `b`.
    #[must_use]
    pub fn angle_between(&self, a: (f64, f64), b: (f64, f64)) -> f64 {
        let ray = |(x, y): (f64, f64)| {
            [
                (x - 0.5) * self.width_cm,
                (y - 0.5) * self.height_cm,
                self.distance_cm,
            ]
        };
        let (u, v) = (ray(a), ray(b));
        let cross = [
            u[1] * v[2] - u[2] * v[1],
            u[2] * v[0] - u[0] * v[2],
            u[0] * v[1] - u[1] * v[0],
        ];
        let dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
        let cross_len = (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]).sqrt();
        cross_len.atan2(dot).to_degrees()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn degrees_follow_the_geometry() {
        let g = ViewingGeometry {
            width_cm: 100.0,
            height_cm: 50.0,
            distance_cm: 50.0,
        };
        assert_eq!(g.degrees(0.5, 0.5), (0.0, 0.0));
        let (az, el) = g.degrees(1.0, 0.5);
        assert!((az - 45.0).abs() < 1e-12 && el == 0.0);
        assert!((g.angle_between((0.5, 0.5), (1.0, 0.5)) - 45.0).abs() < 1e-12);
        assert!((g.angle_between((0.0, 0.5), (1.0, 0.5)) - 90.0).abs() < 1e-12);
        // Small steps anywhere on a desktop screen: the coordinate distance is close to the angle.
        let d = ViewingGeometry::default();
        for (x, y) in [(0.1, 0.1), (0.9, 0.2), (0.5, 0.95)] {
            let (a, b) = (d.degrees(x, y), d.degrees(x + 0.01, y + 0.01));
            let approx = (a.0 - b.0).hypot(a.1 - b.1);
            let exact = d.angle_between((x, y), (x + 0.01, y + 0.01));
            assert!((approx / exact - 1.0).abs() < 0.02, "{approx} vs {exact}");
        }
        assert_eq!(
            ViewingGeometry {
                distance_cm: 0.0,
                ..d
            }
            .validate()
            .map_err(|e| e.field),
            Err("distance_cm")
        );
        assert!(d.validate().is_ok());
    }
}
