//! The one scripted viewer: seeded fixations joined by saccades (paper sections 1.2 and 4: the
//! fixation point of every frame).
//!
//! `foveal gaze saccades` samples it at the tracker rate; the study (`foveal-bench`) asks it for
//! the gaze at each frame's start. Both get the same timeline from the same seed, so a figure in
//! the docs can be reproduced through the product.
//!
//! The model: fixations of [`FIXATION_S`] (uniform; scene viewing and reading, 150-400 ms) at
//! uniformly random points of the central part of the screen (a [`MARGIN`] from each edge), joined
//! by saccades whose duration follows the main sequence (about 21 ms + 2.2 ms per degree of
//! amplitude, Carpenter 1988; here [`saccade_duration_s`], 20-60 ms by on-screen distance, a
//! normalised distance of 1 being about 40 degrees on a desktop display). During a saccade the
//! reported gaze moves linearly from one target to the next, as a tracker's samples do.

use crate::rng::SplitMix64;

/// Fixation durations, seconds: uniform in this range.
pub const FIXATION_S: (f64, f64) = (0.150, 0.400);
/// Fixation targets lie in [MARGIN, 1 - MARGIN] of both normalised screen axes.
pub const MARGIN: f64 = 0.15;
/// Mixed into the seed so that seed 0 does not start the generator at its own seed 0 state.
const SEED_SALT: u64 = 0x6A5E_5EED_0000_0001;

/// Duration of a saccade of `amplitude` (normalised screen distance), seconds: 20 ms plus 40 ms
/// per screen width, at most 60 ms.
#[must_use]
pub fn saccade_duration_s(amplitude: f64) -> f64 {
    (0.020 + 0.040 * amplitude.min(1.0)).min(0.060)
}

/// One segment: hold still at `to` (fixation) or move from `from` to `to` (saccade).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Segment {
    start_s: f64,
    end_s: f64,
    from: [f64; 2],
    to: [f64; 2],
}

impl Segment {
    fn is_fixation(&self) -> bool {
        self.from == self.to
    }
}

/// Where the scripted viewer looks at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ViewerGaze {
    /// Normalised x (0 = left edge).
    pub x: f64,
    /// Normalised y (0 = top edge).
    pub y: f64,
    /// In a fixation (true) or a saccade (false).
    pub fixation: bool,
}

/// The scripted viewer; its whole timeline is fixed by the seed.
#[derive(Debug, Clone)]
pub struct Viewer {
    rng: SplitMix64,
    segments: Vec<Segment>,
}

impl Viewer {
    /// A viewer fixed by `seed`; time 0 is the start of its first fixation.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        let mut rng = SplitMix64::new(seed ^ SEED_SALT);
        let p = [
            rng.range(MARGIN, 1.0 - MARGIN),
            rng.range(MARGIN, 1.0 - MARGIN),
        ];
        let d = rng.range(FIXATION_S.0, FIXATION_S.1);
        Self {
            rng,
            segments: vec![Segment {
                start_s: 0.0,
                end_s: d,
                from: p,
                to: p,
            }],
        }
    }

    fn extend_to(&mut self, t: f64) {
        while let Some(&last) = self.segments.last() {
            if last.end_s > t {
                break;
            }
            let from = last.to;
            let to = [
                self.rng.range(MARGIN, 1.0 - MARGIN),
                self.rng.range(MARGIN, 1.0 - MARGIN),
            ];
            let amplitude = (to[0] - from[0]).hypot(to[1] - from[1]);
            let saccade = saccade_duration_s(amplitude);
            let fix = self.rng.range(FIXATION_S.0, FIXATION_S.1);
            let s0 = last.end_s;
            self.segments.push(Segment {
                start_s: s0,
                end_s: s0 + saccade,
                from,
                to,
            });
            self.segments.push(Segment {
                start_s: s0 + saccade,
                end_s: s0 + saccade + fix,
                from: to,
                to,
            });
        }
    }

    /// The gaze at `t` seconds (any order of calls; non-decreasing is fastest). A `t` that is not
    /// finite gives the first fixation.
    pub fn at(&mut self, t: f64) -> ViewerGaze {
        let t = if t.is_finite() { t } else { 0.0 };
        self.extend_to(t);
        let i = self
            .segments
            .partition_point(|s| s.end_s <= t)
            .min(self.segments.len() - 1);
        let s = self.segments[i];
        let u = if s.end_s > s.start_s {
            ((t - s.start_s) / (s.end_s - s.start_s)).clamp(0.0, 1.0)
        } else {
            1.0
        };
        ViewerGaze {
            x: s.from[0] + (s.to[0] - s.from[0]) * u,
            y: s.from[1] + (s.to[1] - s.from[1]) * u,
            fixation: s.is_fixation(),
        }
    }

    /// Durations (seconds) of the fixations that end by `t`: for checking the model.
    pub fn fixation_durations(&mut self, t: f64) -> Vec<f64> {
        self.extend_to(t);
        self.segments
            .iter()
            .filter(|s| s.is_fixation() && s.end_s <= t)
            .map(|s| s.end_s - s.start_s)
            .collect()
    }

    /// The fixations that end by `t`, as `(start_s, end_s, x, y)`: the ground truth a detector
    /// run on this viewer's samples should find.
    pub fn fixations(&mut self, t: f64) -> Vec<(f64, f64, f64, f64)> {
        self.extend_to(t);
        self.segments
            .iter()
            .filter(|s| s.is_fixation() && s.end_s <= t)
            .map(|s| (s.start_s, s.end_s, s.to[0], s.to[1]))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeded_with_realistic_durations_and_bounds() {
        let ts: Vec<f64> = (0..600).map(|i| f64::from(i) / 60.0).collect();
        let run = |seed| {
            let mut v = Viewer::new(seed);
            ts.iter().map(|&t| v.at(t)).collect::<Vec<_>>()
        };
        assert_eq!(run(7), run(7));
        assert_ne!(run(7), run(8));
        let mut v = Viewer::new(7);
        let d = v.fixation_durations(10.0);
        assert!(d.len() > 15, "{}", d.len());
        assert!(d.iter().all(|&x| (0.15..=0.4).contains(&x)), "{d:?}");
        for g in run(7) {
            assert!((MARGIN..=1.0 - MARGIN).contains(&g.x), "{g:?}");
            assert!((MARGIN..=1.0 - MARGIN).contains(&g.y), "{g:?}");
        }
    }

    #[test]
    fn still_in_fixations_moving_in_saccades() {
        let mut v = Viewer::new(1);
        let fixations = v.fixations(5.0);
        assert!(fixations.len() > 10);
        for pair in fixations.windows(2) {
            let gap = pair[1].0 - pair[0].1;
            assert!((0.020..=0.060 + 1e-12).contains(&gap), "saccade of {gap} s");
            let mid = v.at(pair[0].1 + gap / 2.0);
            assert!(!mid.fixation);
            assert!(mid.x != pair[0].2 || mid.y != pair[0].3);
        }
        let (s, e, x, y) = fixations[3];
        let g = v.at((s + e) / 2.0);
        assert_eq!((g.x, g.y, g.fixation), (x, y, true));
        // Earlier times after later ones give the same answers.
        assert_eq!(v.at(f64::NAN), v.at(0.0));
    }
}
