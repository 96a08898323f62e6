//! The perceptual fall-off of section 3 looked up instead of computed, so that prioritising every
//! candidate pair costs a few arithmetic operations and no libm call.
//!
//! The models F(g, e) of section 3 are all a gap times a fall-off in eccentricity: F1 = g / e,
//! F2 = g exp(-e / C), F3 = F2 with C piecewise. The fall-off depends on the display only through
//! the unit of e. In pixels it is a function of one distance; in degrees of visual angle, e between
//! two screen points is the angle between the two rays from the eye, which a flat screen makes
//! position-dependent. Both are tabulated once per model:
//!
//! - **degrees**: the argument is the *chord* |u - v| between the unit eye rays u and v of the two
//!   points, which needs one square root and one division per point and no trigonometry. The angle is
//!   e = 2 asin(chord / 2), so a table over the chord in [0, 2] holds the fall-off exactly at its
//!   knots, and the table is well conditioned at small angles, where e is proportional to the chord.
//! - **pixels**: the argument is the pixel distance, tabulated up to [`PIXEL_RANGE`].
//!
//! Values between knots are interpolated linearly. F1's fall-off 1/e is singular at 0 and is
//! computed by one division instead (from the tabulated angle in degrees).

use crate::perception::{EccentricityUnit, PerceptualFunction, PerceptualModel};

/// Knots of every table: at 4,096 knots over the chord range a knot is 0.028 degrees apart, well
/// below any tracker's accuracy (about 0.5 degrees), and the table is 16 KiB.
const KNOTS: usize = 4096;
/// Largest angle of the degrees unit's angle-indexed table (used only with an uncertain
/// fixation): two eye rays are never further apart.
const ANGLE_RANGE: f64 = 180.0;

/// Largest pixel distance tabulated; beyond it the last value holds (F2 has decayed to nothing
/// there for any C below 1,000 px).
pub const PIXEL_RANGE: f32 = 16_384.0;

/// A perceptual fall-off ready for per-pair lookup.
#[derive(Debug, Clone)]
pub struct Falloff {
    unit: EccentricityUnit,
    /// Fall-off at each knot (for F1: unused).
    factor: Vec<f32>,
    /// Eccentricity in the model's unit at each knot (degrees unit only; for F1 and gaps).
    angle: Vec<f32>,
    /// Degrees unit: the fall-off over the angle itself, [0, 180] degrees, for an eccentricity
    /// reduced by the fixation's uncertainty (which no longer maps to a chord).
    factor_by_angle: Vec<f32>,
    inv_step: f32,
    inv_angle_step: f32,
    reciprocal: bool,
}

impl Falloff {
    /// Tabulate `model`'s fall-off.
    pub fn new(model: &PerceptualModel) -> Self {
        let unit = model.unit;
        let range = match unit {
            EccentricityUnit::Degrees => 2.0,
            EccentricityUnit::Pixels => f64::from(PIXEL_RANGE),
        };
        let step = range / (KNOTS - 1) as f64;
        let ecc = |k: usize| {
            let x = (k as f64 * step).min(range);
            match unit {
                EccentricityUnit::Degrees => (2.0 * (0.5 * x).min(1.0).asin()).to_degrees(),
                EccentricityUnit::Pixels => x,
            }
        };
        let angle: Vec<f32> = (0..KNOTS).map(|k| ecc(k) as f32).collect();
        let factor = (0..KNOTS)
            .map(|k| model.evaluate(1.0, ecc(k)) as f32)
            .collect();
        let angle_step = ANGLE_RANGE / (KNOTS - 1) as f64;
        let factor_by_angle = match unit {
            EccentricityUnit::Degrees => (0..KNOTS)
                .map(|k| model.evaluate(1.0, (k as f64 * angle_step).min(ANGLE_RANGE)) as f32)
                .collect(),
            EccentricityUnit::Pixels => Vec::new(),
        };
        Self {
            unit,
            factor,
            angle,
            factor_by_angle,
            inv_step: (1.0 / step) as f32,
            inv_angle_step: (1.0 / angle_step) as f32,
            reciprocal: matches!(model.function, PerceptualFunction::F1),
        }
    }

    /// The unit the lookup's argument is in: chord of unit eye rays (degrees) or pixels.
    pub fn unit(&self) -> EccentricityUnit {
        self.unit
    }

    #[inline]
    fn lerp(&self, table: &[f32], x: f32) -> f32 {
        lerp(table, x, self.inv_step)
    }

    /// Eccentricity in the model's unit for argument `x` (a chord in the degrees unit, pixels in the
    /// pixel unit).
    #[inline]
    pub fn eccentricity(&self, x: f32) -> f32 {
        match self.unit {
            EccentricityUnit::Degrees => self.lerp(&self.angle, x),
            EccentricityUnit::Pixels => x,
        }
    }

    /// The fall-off F(1, e) for argument `x`.
    #[inline]
    pub fn factor(&self, x: f32) -> f32 {
        if self.reciprocal {
            let e = self.eccentricity(x);
            if e > 0.0 { 1.0 / e } else { 1.0 }
        } else {
            self.lerp(&self.factor, x)
        }
    }

    /// The fall-off at argument `x` with the eccentricity reduced by `widen` (in the model's
    /// unit: degrees or pixels), never below 0: the fixation is uncertain by that radius, and
    /// everything inside it is scheduled as foveal. `widen` 0 is [`Self::factor`] up to the
    /// tables' interpolation.
    #[inline]
    pub fn factor_widened(&self, x: f32, widen: f32) -> f32 {
        let e = (self.eccentricity(x) - widen).max(0.0);
        if self.reciprocal {
            if e > 0.0 { 1.0 / e } else { 1.0 }
        } else {
            match self.unit {
                EccentricityUnit::Degrees => lerp(&self.factor_by_angle, e, self.inv_angle_step),
                EccentricityUnit::Pixels => self.lerp(&self.factor, e),
            }
        }
    }
}

/// Linear interpolation in a table of [`KNOTS`] values spaced `1 / inv_step` apart from 0; the
/// last value holds beyond the range.
#[inline]
fn lerp(table: &[f32], x: f32, inv_step: f32) -> f32 {
    let t = (x.max(0.0) * inv_step).min((KNOTS - 1) as f32);
    // t is in [0, KNOTS - 1]: converting through i32 is exact and cheaper than to usize.
    let k = (t as i32 as usize).min(KNOTS - 2);
    let f = t - k as f32;
    table[k] + (table[k + 1] - table[k]) * f
}

#[cfg(test)]
mod tests {
    use super::*;

    fn chord(deg: f64) -> f32 {
        (2.0 * (0.5 * deg.to_radians()).sin()) as f32
    }

    #[test]
    fn tabulated_falloff_matches_the_model_in_degrees_and_pixels() {
        for model in [
            PerceptualModel::default(),
            PerceptualModel {
                function: PerceptualFunction::F2 { c: 1.0 },
                unit: EccentricityUnit::Degrees,
            },
            PerceptualModel {
                function: PerceptualFunction::F2Range {
                    c_min: 1.0,
                    c_max: 10.0,
                },
                unit: EccentricityUnit::Degrees,
            },
        ] {
            let f = Falloff::new(&model);
            for deg in [0.0, 0.3, 1.0, 2.5, 5.0, 10.0, 30.0, 90.0] {
                let want = model.evaluate(1.0, deg);
                let got = f64::from(f.factor(chord(deg)));
                assert!(
                    (got - want).abs() <= 2e-3 * want.max(1e-3),
                    "{model:?} at {deg} deg: {got} vs {want}"
                );
                assert!((f64::from(f.eccentricity(chord(deg))) - deg).abs() < 1e-3);
            }
        }
        let px = PerceptualModel {
            function: PerceptualFunction::F2 { c: 200.0 },
            unit: EccentricityUnit::Pixels,
        };
        let f = Falloff::new(&px);
        for e in [0.0f32, 17.0, 400.0, 1500.0] {
            let want = px.evaluate(1.0, f64::from(e));
            assert!((f64::from(f.factor(e)) - want).abs() < 1e-3 * want.max(1e-3));
        }
        let f1 = Falloff::new(&PerceptualModel::f1_pixels());
        assert_eq!(f1.factor_widened(4.0, 2.0), 0.5);
        assert_eq!(f1.factor_widened(4.0, 9.0), 1.0);
        assert_eq!(f1.factor(0.0), 1.0);
        assert_eq!(f1.factor(4.0), 0.25);
        assert!(f1.factor(1e9).is_finite() && f1.factor(-3.0) == 1.0);
    }

    #[test]
    fn an_uncertain_fixation_schedules_its_radius_as_foveal_and_beyond_it_shifted() {
        for model in [
            PerceptualModel::default(),
            PerceptualModel {
                function: PerceptualFunction::F2 { c: 1.0 },
                unit: EccentricityUnit::Degrees,
            },
            PerceptualModel {
                function: PerceptualFunction::F2 { c: 200.0 },
                unit: EccentricityUnit::Pixels,
            },
        ] {
            let f = Falloff::new(&model);
            let arg = |e: f64| match model.unit {
                EccentricityUnit::Degrees => chord(e),
                EccentricityUnit::Pixels => e as f32,
            };
            let (widen, scale) = match model.unit {
                EccentricityUnit::Degrees => (3.0, 1.0),
                EccentricityUnit::Pixels => (120.0, 40.0),
            };
            // Inside the radius: foveal, the fall-off's value at 0.
            let at0 = model.evaluate(1.0, 0.0);
            for e in [0.0, 0.5 * widen, widen] {
                let got = f64::from(f.factor_widened(arg(e), widen as f32));
                assert!((got - at0).abs() < 2e-3, "{model:?} e {e}: {got} vs {at0}");
            }
            // Beyond it: the fall-off of the eccentricity less the radius.
            for extra in [0.5, 2.0, 7.0] {
                let e = widen + extra * scale;
                let want = model.evaluate(1.0, extra * scale);
                let got = f64::from(f.factor_widened(arg(e), widen as f32));
                assert!(
                    (got - want).abs() <= 3e-3 * want.max(1e-3),
                    "{model:?} e {e}: {got} vs {want}"
                );
                // Never below the unwidened fall-off.
                assert!(got >= f64::from(f.factor(arg(e))) - 1e-6);
            }
            // No uncertainty: the same as the plain lookup.
            for e in [0.0, 1.0, 4.0, 20.0] {
                let (a, b) = (f.factor_widened(arg(e), 0.0), f.factor(arg(e)));
                assert!(
                    (a - b).abs() <= 2e-3 * b.max(1e-3),
                    "{model:?} e {e}: {a} vs {b}"
                );
            }
        }
    }
}
