//! Deterministic scripted gaze: the same script, rate and seed give the same samples, bit for
//! bit, on every machine.
//!
//! A [`ScriptedGaze`] is an endless iterator of samples at a fixed rate; sample `i` is at
//! `start_s + i / rate_hz`. Scripts:
//! - [`GazeScript::Fixed`]: one point, flagged as a fixation.
//! - [`GazeScript::Circle`]: a point going round a circle (clockwise on screen, since y points
//!   down), like smooth pursuit: no fixation flag.
//! - [`GazeScript::Saccades`]: the scripted [`Viewer`] (the same one the study uses): fixations
//!   at random points joined by brief saccades whose samples are flagged `fixation: Some(false)`.

use std::f64::consts::TAU;

use thiserror::Error;

use crate::viewer::Viewer;
use crate::{Eye, GazeSample};

/// What the scripted eye does.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GazeScript {
    /// Look at one point (normalised) the whole time.
    Fixed {
        /// x, normalised.
        x: f64,
        /// y, normalised.
        y: f64,
    },
    /// Go round a circle, starting at angle 0 (rightmost point).
    Circle {
        /// Centre x, normalised.
        cx: f64,
        /// Centre y, normalised.
        cy: f64,
        /// Radius, in normalised units (of width for x, of height for y).
        radius: f64,
        /// Time for one turn, seconds (> 0).
        period_s: f64,
    },
    /// Random fixations and saccades.
    Saccades {
        /// Seed of the random sequence.
        seed: u64,
    },
}

/// A script parameter that cannot work.
#[derive(Debug, Error, PartialEq)]
#[error("gaze script: `{name}` = {value} {reason}")]
pub struct ScriptError {
    /// Parameter name.
    pub name: &'static str,
    /// Its value.
    pub value: f64,
    /// What is wrong with it.
    pub reason: &'static str,
}

fn check(
    name: &'static str,
    value: f64,
    ok: bool,
    reason: &'static str,
) -> Result<(), ScriptError> {
    if ok {
        Ok(())
    } else {
        Err(ScriptError {
            name,
            value,
            reason,
        })
    }
}

/// An endless, deterministic stream of scripted gaze samples at a fixed rate.
#[derive(Debug, Clone)]
pub struct ScriptedGaze {
    script: GazeScript,
    rate_hz: f64,
    start_s: f64,
    index: u64,
    /// Running state of a saccade script, made on its first sample (fixed and circle scripts are
    /// stateless).
    timeline: Option<Viewer>,
}

impl ScriptedGaze {
    /// Samples of `script` at `rate_hz`, the first at time 0.
    ///
    /// # Errors
    /// A rate that is not finite and positive, a non-finite coordinate, a negative or non-finite
    /// radius, or a period that is not finite and positive.
    pub fn new(script: GazeScript, rate_hz: f64) -> Result<Self, ScriptError> {
        check(
            "rate_hz",
            rate_hz,
            rate_hz.is_finite() && rate_hz > 0.0,
            "must be finite and > 0",
        )?;
        let finite = "must be finite";
        match script {
            GazeScript::Fixed { x, y } => {
                check("x", x, x.is_finite(), finite)?;
                check("y", y, y.is_finite(), finite)?;
            }
            GazeScript::Circle {
                cx,
                cy,
                radius,
                period_s,
            } => {
                check("cx", cx, cx.is_finite(), finite)?;
                check("cy", cy, cy.is_finite(), finite)?;
                check(
                    "radius",
                    radius,
                    radius.is_finite() && radius >= 0.0,
                    "must be finite and >= 0",
                )?;
                check(
                    "period_s",
                    period_s,
                    period_s.is_finite() && period_s > 0.0,
                    "must be finite and > 0",
                )?;
            }
            GazeScript::Saccades { .. } => {}
        }
        Ok(Self {
            script,
            rate_hz,
            start_s: 0.0,
            index: 0,
            timeline: None,
        })
    }

    /// The same stream with the first sample at `start_s` instead of 0 (the script's own
    /// timeline is unchanged, only shifted).
    ///
    /// # Errors
    /// A `start_s` that is not finite.
    pub fn starting_at(mut self, start_s: f64) -> Result<Self, ScriptError> {
        check("start_s", start_s, start_s.is_finite(), "must be finite")?;
        self.start_s = start_s;
        Ok(self)
    }

    /// The script.
    #[must_use]
    pub fn script(&self) -> GazeScript {
        self.script
    }

    /// Samples per second.
    #[must_use]
    pub fn rate_hz(&self) -> f64 {
        self.rate_hz
    }

    /// Just the samples of the next `duration_s` seconds: `round(duration_s * rate_hz)` of
    /// them (none for a negative or non-finite duration).
    pub fn for_duration(self, duration_s: f64) -> std::iter::Take<Self> {
        let count = duration_s * self.rate_hz;
        let count = if count.is_finite() && count > 0.0 {
            // Saturating float-to-int conversion of a positive, rounded value.
            #[allow(clippy::cast_possible_truncation, clippy::cast_sign_loss)]
            let n = count.round() as usize;
            n
        } else {
            0
        };
        self.take(count)
    }
}

impl Iterator for ScriptedGaze {
    type Item = GazeSample;

    fn next(&mut self) -> Option<GazeSample> {
        // Index to time without accumulating rounding: exact for any index below 2^53.
        #[allow(clippy::cast_precision_loss)]
        let elapsed_s = self.index as f64 / self.rate_hz;
        self.index += 1;
        let t_s = self.start_s + elapsed_s;
        let sample = match self.script {
            GazeScript::Fixed { x, y } => {
                GazeSample::valid(t_s, x, y, Eye::Unspecified).with_fixation(Some(true))
            }
            GazeScript::Circle {
                cx,
                cy,
                radius,
                period_s,
            } => {
                let angle = TAU * (elapsed_s / period_s).fract();
                GazeSample::valid(
                    t_s,
                    cx + radius * angle.cos(),
                    cy + radius * angle.sin(),
                    Eye::Unspecified,
                )
            }
            GazeScript::Saccades { seed } => {
                let timeline = self.timeline.get_or_insert_with(|| Viewer::new(seed));
                let g = timeline.at(elapsed_s);
                GazeSample::valid(t_s, g.x, g.y, Eye::Unspecified).with_fixation(Some(g.fixation))
            }
        };
        Some(sample)
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::viewer::MARGIN as TARGET_MARGIN;

    fn saccades(seed: u64, rate_hz: f64, n: usize) -> Vec<GazeSample> {
        ScriptedGaze::new(GazeScript::Saccades { seed }, rate_hz)
            .expect("valid script")
            .take(n)
            .collect()
    }

    #[test]
    fn fixed_point_is_a_fixation_at_the_rate() {
        let samples: Vec<_> = ScriptedGaze::new(GazeScript::Fixed { x: 0.3, y: 0.6 }, 250.0)
            .expect("valid")
            .starting_at(10.0)
            .expect("valid start")
            .for_duration(1.0)
            .collect();
        assert_eq!(samples.len(), 250);
        assert_eq!(
            samples[0],
            GazeSample::valid(10.0, 0.3, 0.6, Eye::Unspecified).with_fixation(Some(true))
        );
        assert_eq!(samples[249].t_s, 10.0 + 249.0 / 250.0);
    }

    #[test]
    fn circle_goes_round_clockwise_once_per_period() {
        let script = GazeScript::Circle {
            cx: 0.5,
            cy: 0.5,
            radius: 0.25,
            period_s: 2.0,
        };
        let samples: Vec<_> = ScriptedGaze::new(script, 100.0)
            .expect("valid")
            .take(201)
            .collect();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(samples[0].x, 0.75) && close(samples[0].y, 0.5));
        // A quarter turn later the point is below the centre (y down).
        assert!(
            close(samples[50].x, 0.5) && close(samples[50].y, 0.75),
            "{:?}",
            samples[50]
        );
        assert!(close(samples[200].x, 0.75) && close(samples[200].y, 0.5));
        assert!(samples.iter().all(|s| s.fixation.is_none() && s.is_valid()));
        for s in &samples {
            assert!(close((s.x - 0.5).hypot(s.y - 0.5), 0.25));
        }
    }

    #[test]
    fn bad_parameters_are_refused() {
        let fixed = GazeScript::Fixed { x: 0.5, y: 0.5 };
        assert_eq!(
            ScriptedGaze::new(fixed, 0.0).expect_err("zero rate").name,
            "rate_hz"
        );
        assert_eq!(
            ScriptedGaze::new(fixed, f64::NAN)
                .expect_err("nan rate")
                .name,
            "rate_hz"
        );
        let nan_x = GazeScript::Fixed {
            x: f64::NAN,
            y: 0.5,
        };
        assert_eq!(ScriptedGaze::new(nan_x, 60.0).expect_err("nan x").name, "x");
        let circle = |radius, period_s| GazeScript::Circle {
            cx: 0.5,
            cy: 0.5,
            radius,
            period_s,
        };
        assert_eq!(
            ScriptedGaze::new(circle(-0.1, 1.0), 60.0)
                .expect_err("radius")
                .name,
            "radius"
        );
        assert_eq!(
            ScriptedGaze::new(circle(0.1, 0.0), 60.0)
                .expect_err("period")
                .name,
            "period_s"
        );
        let err = ScriptedGaze::new(fixed, 60.0)
            .expect("valid")
            .starting_at(f64::INFINITY)
            .expect_err("start");
        assert_eq!(
            err.to_string(),
            "gaze script: `start_s` = inf must be finite"
        );
        assert_eq!(
            ScriptedGaze::new(fixed, 60.0)
                .expect("valid")
                .for_duration(-1.0)
                .count(),
            0
        );
    }

    #[test]
    fn saccades_alternate_fixations_of_the_right_length_with_brief_saccades() {
        let rate = 1000.0;
        let samples = saccades(42, rate, 60_000);
        // Runs of equal fixation flags: (flag, length in samples).
        let mut runs: Vec<(bool, usize)> = Vec::new();
        for s in &samples {
            let flag = s.fixation.expect("scripted samples carry a flag");
            match runs.last_mut() {
                Some((f, n)) if *f == flag => *n += 1,
                _ => runs.push((flag, 1)),
            }
        }
        assert!(
            runs.len() > 200,
            "many fixations in a minute: {}",
            runs.len()
        );
        // Skip the last, cut-off run.
        for (flag, n) in &runs[..runs.len() - 1] {
            let duration_ms = *n as f64;
            if *flag {
                assert!(
                    (149.0..=401.0).contains(&duration_ms),
                    "fixation of {duration_ms} ms"
                );
            } else {
                assert!(
                    (19.0..=61.0).contains(&duration_ms),
                    "saccade of {duration_ms} ms"
                );
            }
        }
        assert!(runs[0].0, "starts with a fixation");
        // Fixation durations cover the range, not one value.
        let fix: Vec<usize> = runs.iter().filter(|r| r.0).map(|r| r.1).collect();
        assert!(fix.iter().min() < Some(&200) && fix.iter().max() > Some(&350));
        // Within a fixation the point stays put; during a saccade it moves.
        for pair in samples.windows(2) {
            let same_point = (pair[0].x, pair[0].y) == (pair[1].x, pair[1].y);
            match (pair[0].fixation, pair[1].fixation) {
                (Some(true), Some(true)) => assert!(same_point, "{pair:?}"),
                (Some(false), Some(false)) => assert!(!same_point, "{pair:?}"),
                _ => {}
            }
        }
        for s in &samples {
            assert!((TARGET_MARGIN..=1.0 - TARGET_MARGIN).contains(&s.x));
            assert!((TARGET_MARGIN..=1.0 - TARGET_MARGIN).contains(&s.y));
        }
    }

    #[test]
    fn saccades_are_deterministic_per_seed() {
        assert_eq!(saccades(7, 120.0, 5_000), saccades(7, 120.0, 5_000));
        assert_ne!(saccades(7, 120.0, 5_000), saccades(8, 120.0, 5_000));
        // The timeline does not depend on the rate: at a rate 10x lower, every sample equals
        // the one at the same time at the higher rate.
        let fast = saccades(3, 1000.0, 20_000);
        let slow = saccades(3, 100.0, 2_000);
        for (i, s) in slow.iter().enumerate() {
            let f = &fast[i * 10];
            assert_eq!((s.x, s.y, s.fixation), (f.x, f.y, f.fixation), "sample {i}");
        }
    }

    proptest! {
        #[test]
        fn saccade_samples_are_valid_and_in_bounds(seed in any::<u64>(), rate in 1.0f64..2000.0) {
            let samples = saccades(seed, rate, 500);
            for pair in samples.windows(2) {
                prop_assert!(pair[1].t_s > pair[0].t_s);
            }
            for s in &samples {
                prop_assert!(s.is_valid() && s.fixation.is_some());
                prop_assert!((TARGET_MARGIN..=1.0 - TARGET_MARGIN).contains(&s.x));
                prop_assert!((TARGET_MARGIN..=1.0 - TARGET_MARGIN).contains(&s.y));
            }
        }
    }
}
