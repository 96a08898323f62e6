//! The 1€ filter (Casiez, Roussel, Vogel, CHI 2012): a low-pass filter whose cutoff rises with
//! speed, so a fixation is smoothed (jitter removed) while a saccade passes with little lag.
//!
//! Defaults and their source: `min_cutoff_hz` 1.0 and `d_cutoff_hz` 1.0 are the paper's
//! recommended starting points. The paper's `beta` of 0.007 is per pixel per second; positions
//! here are normalised, so the default is 10 per (screen width per second), about 0.005 per px/s
//! on a 1920 px screen: a saccade (several screen widths per second) opens the cutoff to tens of
//! hertz, a fixation's drift leaves it near 1 Hz. The filter is causal: an output depends only
//! on the samples before it.

/// Parameters of the 1€ filter.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OneEuroParams {
    /// Cutoff at rest, Hz (lower: smoother fixations, more lag).
    pub min_cutoff_hz: f64,
    /// How fast the cutoff rises with speed, Hz per (normalised unit per second).
    pub beta: f64,
    /// Cutoff of the speed estimate, Hz.
    pub d_cutoff_hz: f64,
}

impl Default for OneEuroParams {
    fn default() -> Self {
        Self {
            min_cutoff_hz: 1.0,
            beta: 10.0,
            d_cutoff_hz: 1.0,
        }
    }
}

impl OneEuroParams {
    /// Whether every parameter is finite, the cutoffs positive and beta non-negative; `Err`
    /// names the first that is not.
    ///
    /// # Errors
    /// The name of the offending parameter.
    pub fn validate(&self) -> Result<(), &'static str> {
        if !(self.min_cutoff_hz.is_finite() && self.min_cutoff_hz > 0.0) {
            return Err("min_cutoff_hz");
        }
        if !(self.beta.is_finite() && self.beta >= 0.0) {
            return Err("beta");
        }
        if !(self.d_cutoff_hz.is_finite() && self.d_cutoff_hz > 0.0) {
            return Err("d_cutoff_hz");
        }
        Ok(())
    }
}

/// Largest speed the filter's derivative takes, normalised units per second. The eye peaks near
/// 700 deg/s, about 15 screen widths per second; two samples microseconds apart (or a subnormal
/// time step) would otherwise give an infinite speed, and infinity minus infinity on the next
/// step a NaN.
const MAX_SPEED: f64 = 1e4;

/// Smoothing factor of an exponential filter with cutoff `cutoff_hz` at step `dt_s`.
fn alpha(cutoff_hz: f64, dt_s: f64) -> f64 {
    let tau = 1.0 / (std::f64::consts::TAU * cutoff_hz);
    1.0 / (1.0 + tau / dt_s)
}

/// State of one axis.
#[derive(Debug, Clone, Copy)]
struct Axis {
    value: f64,
    speed: f64,
}

/// A 1€ filter of 2D gaze positions.
#[derive(Debug, Clone)]
pub struct OneEuro {
    params: OneEuroParams,
    last: Option<(f64, [Axis; 2])>,
}

impl OneEuro {
    /// A filter with `params` (assumed valid: see [`OneEuroParams::validate`]).
    #[must_use]
    pub fn new(params: OneEuroParams) -> Self {
        Self { params, last: None }
    }

    /// Forgets the past: the next sample passes unfiltered (after track loss, the old position
    /// says nothing about the new one).
    pub fn reset(&mut self) {
        self.last = None;
    }

    /// Filters the position (x, y) at `t_s`; a time not after the previous one (or not finite)
    /// gives the previous output unchanged, so the output is always finite for finite input.
    pub fn filter(&mut self, t_s: f64, x: f64, y: f64) -> (f64, f64) {
        let Some((t0, axes)) = self.last else {
            self.last = Some((
                t_s,
                [
                    Axis {
                        value: x,
                        speed: 0.0,
                    },
                    Axis {
                        value: y,
                        speed: 0.0,
                    },
                ],
            ));
            return (x, y);
        };
        let dt = t_s - t0;
        if !(dt > 0.0 && dt.is_finite() && x.is_finite() && y.is_finite()) {
            return (axes[0].value, axes[1].value);
        }
        let p = self.params;
        let a_d = alpha(p.d_cutoff_hz, dt);
        let step = |axis: Axis, raw: f64| {
            let derivative = ((raw - axis.value) / dt).clamp(-MAX_SPEED, MAX_SPEED);
            let speed = axis.speed + a_d * (derivative - axis.speed);
            let cutoff = p.min_cutoff_hz + p.beta * speed.abs();
            let value = axis.value + alpha(cutoff, dt) * (raw - axis.value);
            Axis { value, speed }
        };
        let next = [step(axes[0], x), step(axes[1], y)];
        self.last = Some((t_s, next));
        (next[0].value, next[1].value)
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    #[test]
    fn smooths_jitter_and_follows_a_step() {
        let mut f = OneEuro::new(OneEuroParams::default());
        let mut out = (0.0, 0.0);
        for i in 0..1000 {
            let jitter = if i % 2 == 0 { 0.01 } else { -0.01 };
            out = f.filter(f64::from(i) * 0.001, 0.5 + jitter, 0.5);
        }
        assert!(
            (out.0 - 0.5).abs() < 0.001,
            "jitter of 0.01 smoothed: {out:?}"
        );
        // A saccade to 0.8: the output gets there (the cutoff rises with speed).
        for i in 1000..1300 {
            out = f.filter(f64::from(i) * 0.001, 0.8, 0.5);
        }
        assert!((out.0 - 0.8).abs() < 0.01, "{out:?}");
        // A repeated or earlier time changes nothing.
        assert_eq!(f.filter(1.299, 0.1, 0.1), out);
        f.reset();
        assert_eq!(f.filter(2.0, 0.1, 0.2), (0.1, 0.2));
    }

    #[test]
    fn subnormal_time_steps_stay_finite() {
        // Found by fuzzing: a step of 2.6e-314 s made the speed infinite, the next one NaN.
        let mut f = OneEuro::new(OneEuroParams::default());
        f.filter(0.0, 0.0, 0.0);
        let a = f.filter(2.6e-314, 0.000_476_8, 0.000_476_8);
        let b = f.filter(1.0, 0.5, 0.5);
        let c = f.filter(1.0 + 1e-300, -1.0, 2.0);
        for (x, y) in [a, b, c] {
            assert!(x.is_finite() && y.is_finite(), "{a:?} {b:?} {c:?}");
        }
    }

    #[test]
    fn bad_parameters_are_named() {
        let ok = OneEuroParams::default();
        assert!(ok.validate().is_ok());
        let bad = OneEuroParams { beta: -1.0, ..ok };
        assert_eq!(bad.validate(), Err("beta"));
        let bad = OneEuroParams {
            min_cutoff_hz: f64::NAN,
            ..ok
        };
        assert_eq!(bad.validate(), Err("min_cutoff_hz"));
    }

    proptest! {
        /// Finite in, finite out; and causal: the outputs for a prefix are the prefix of the outputs.
        #[test]
        fn finite_and_causal(
            steps in proptest::collection::vec((0.0f64..0.1, -1.0f64..2.0, -1.0f64..2.0), 1..200),
            cut in 0usize..200,
        ) {
            let mut t = 0.0;
            let samples: Vec<_> = steps.iter().map(|&(dt, x, y)| { t += dt; (t, x, y) }).collect();
            let run = |n: usize| {
                let mut f = OneEuro::new(OneEuroParams::default());
                samples[..n].iter().map(|&(t, x, y)| f.filter(t, x, y)).collect::<Vec<_>>()
            };
            let full = run(samples.len());
            for &(x, y) in &full {
                prop_assert!(x.is_finite() && y.is_finite());
            }
            let k = cut.min(samples.len());
            prop_assert_eq!(&run(k)[..], &full[..k]);
        }
    }
}
