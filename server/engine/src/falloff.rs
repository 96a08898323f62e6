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
    inv_step: f32,
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
        Self {
            unit,
            factor,
            angle,
            inv_step: (1.0 / step) as f32,
            reciprocal: matches!(model.function, PerceptualFunction::F1),
        }
    }

    /// The unit the lookup's argument is in: chord of unit eye rays (degrees) or pixels.
    pub fn unit(&self) -> EccentricityUnit {
        self.unit
    }

    #[inline]
    fn lerp(&self, table: &[f32], x: f32) -> f32 {
        let t = (x.max(0.0) * self.inv_step).min((KNOTS - 1) as f32);
        let k = (t as usize).min(KNOTS - 2);
        let f = t - k as f32;
        table[k] + (table[k + 1] - table[k]) * f
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
        assert_eq!(f1.factor(0.0), 1.0);
        assert_eq!(f1.factor(4.0), 0.25);
        assert!(f1.factor(1e9).is_finite() && f1.factor(-3.0) == 1.0);
    }
}
