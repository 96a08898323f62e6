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
//!
//! Where the fixations land is the viewer's [`Placement`]: uniform over the central part (the
//! default), a central bias measured on scene viewing, or chosen by the caller at each saccade
//! (the study's scene-driven viewer, which looks where the scene's collisions and motion are).

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

/// Where the scripted viewer's fixations land. The timeline (fixation durations, saccades) is the
/// same for every placement; only the targets differ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Placement {
    /// Uniformly random points of the central part of the screen ([`MARGIN`] from each edge).
    Uniform,
    /// The central bias of scene viewing: an axis-aligned Gaussian about the screen centre with
    /// these standard deviations (normalised screen units per axis), truncated to the screen
    /// (redrawn until inside). Clarke and Tatler (2014, Vision Research 102: 41-51) fit such an
    /// anisotropic Gaussian across ten eye-movement datasets as a baseline for image-independent
    /// fixation placement.
    CentralBias {
        /// Horizontal standard deviation, fraction of the screen width.
        sd_x: f64,
        /// Vertical standard deviation, fraction of the screen height.
        sd_y: f64,
    },
    /// The first fixation at the screen centre; every later target from the caller
    /// ([`Viewer::at_choosing`]).
    Chosen,
}

impl Placement {
    /// A target under this placement, or `None` when the caller chooses.
    fn draw(self, rng: &mut SplitMix64) -> Option<[f64; 2]> {
        match self {
            Self::Uniform => Some([
                rng.range(MARGIN, 1.0 - MARGIN),
                rng.range(MARGIN, 1.0 - MARGIN),
            ]),
            Self::CentralBias { sd_x, sd_y } => {
                // Rejection keeps the truncated Gaussian's shape; with the measured spreads
                // (about a quarter of the screen) nearly every draw lands on screen, and the
                // cap only guards against absurd spreads.
                for _ in 0..64 {
                    let (gx, gy) = gaussian_pair(rng);
                    let p = [0.5 + sd_x * gx, 0.5 + sd_y * gy];
                    if (0.0..=1.0).contains(&p[0]) && (0.0..=1.0).contains(&p[1]) {
                        return Some(p);
                    }
                }
                Some([0.5, 0.5])
            }
            Self::Chosen => None,
        }
    }
}

/// Two independent standard normal deviates (Box-Muller).
pub fn gaussian_pair(rng: &mut SplitMix64) -> (f64, f64) {
    let u1 = rng.next_f64().max(f64::MIN_POSITIVE);
    let u2 = rng.next_f64();
    let r = (-2.0 * u1.ln()).sqrt();
    let a = std::f64::consts::TAU * u2;
    (r * a.cos(), r * a.sin())
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
    placement: Placement,
    segments: Vec<Segment>,
}

impl Viewer {
    /// A viewer fixed by `seed`, fixating uniformly; time 0 is the start of its first fixation.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self::with_placement(seed, Placement::Uniform)
    }

    /// A viewer fixed by `seed` whose fixations land by `placement`.
    #[must_use]
    pub fn with_placement(seed: u64, placement: Placement) -> Self {
        let mut rng = SplitMix64::new(seed ^ SEED_SALT);
        let p = placement.draw(&mut rng).unwrap_or([0.5, 0.5]);
        let d = rng.range(FIXATION_S.0, FIXATION_S.1);
        Self {
            rng,
            placement,
            segments: vec![Segment {
                start_s: 0.0,
                end_s: d,
                from: p,
                to: p,
            }],
        }
    }

    fn extend_to(&mut self, t: f64, choose: &mut dyn FnMut(&mut SplitMix64, [f64; 2]) -> [f64; 2]) {
        while let Some(&last) = self.segments.last() {
            if last.end_s > t {
                break;
            }
            let from = last.to;
            let to = match self.placement.draw(&mut self.rng) {
                Some(p) => p,
                None => {
                    let p = choose(&mut self.rng, from);
                    [p[0].clamp(0.0, 1.0), p[1].clamp(0.0, 1.0)]
                }
            };
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
        self.at_choosing(t, &mut |_, from| from)
    }

    /// [`Self::at`], with `choose` giving each new target of a [`Placement::Chosen`] viewer from
    /// the generator and the last target (clamped to the screen). It is called when a fixation
    /// that ends by `t` is followed, so a caller that asks frame by frame chooses from the frame
    /// at which the saccade starts. Other placements never call it.
    pub fn at_choosing(
        &mut self,
        t: f64,
        choose: &mut dyn FnMut(&mut SplitMix64, [f64; 2]) -> [f64; 2],
    ) -> ViewerGaze {
        let t = if t.is_finite() { t } else { 0.0 };
        self.extend_to(t, choose);
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
        self.extend_to(t, &mut |_, from| from);
        self.segments
            .iter()
            .filter(|s| s.is_fixation() && s.end_s <= t)
            .map(|s| s.end_s - s.start_s)
            .collect()
    }

    /// The fixations that end by `t`, as `(start_s, end_s, x, y)`: the ground truth a detector
    /// run on this viewer's samples should find.
    pub fn fixations(&mut self, t: f64) -> Vec<(f64, f64, f64, f64)> {
        self.extend_to(t, &mut |_, from| from);
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

    /// The central bias places fixations about the centre with the spreads asked for, all on
    /// screen; the timeline is the uniform viewer's.
    #[test]
    fn central_bias_is_centred_with_its_spread_and_on_screen() {
        let mut v = Viewer::with_placement(
            3,
            Placement::CentralBias {
                sd_x: 0.23,
                sd_y: 0.28,
            },
        );
        let f = v.fixations(2_000.0);
        assert!(f.len() > 5_000, "{}", f.len());
        let n = f.len() as f64;
        let (mx, my) = (
            f.iter().map(|x| x.2).sum::<f64>() / n,
            f.iter().map(|x| x.3).sum::<f64>() / n,
        );
        assert!(
            (mx - 0.5).abs() < 0.01 && (my - 0.5).abs() < 0.01,
            "{mx} {my}"
        );
        // Truncation at the edges narrows the spread a little (to about 0.21 and 0.24 here).
        let sd = |m: f64, k: fn(&(f64, f64, f64, f64)) -> f64| {
            (f.iter().map(|x| (k(x) - m).powi(2)).sum::<f64>() / n).sqrt()
        };
        let (sx, sy) = (sd(mx, |x| x.2), sd(my, |x| x.3));
        assert!(
            (0.19..0.23).contains(&sx) && (0.21..0.28).contains(&sy),
            "{sx} {sy}"
        );
        assert!(
            f.iter()
                .all(|x| (0.0..=1.0).contains(&x.2) && (0.0..=1.0).contains(&x.3))
        );
        let d = v.fixation_durations(100.0);
        assert!(d.iter().all(|&x| (0.15..=0.4).contains(&x)));
    }

    /// A chosen placement starts at the centre and takes each later target from the caller,
    /// clamped to the screen, once per saccade.
    #[test]
    fn chosen_targets_come_from_the_caller() {
        let mut v = Viewer::with_placement(5, Placement::Chosen);
        assert_eq!((v.at(0.0).x, v.at(0.0).y), (0.5, 0.5));
        let mut calls = 0;
        let mut choose = |_: &mut SplitMix64, from: [f64; 2]| {
            calls += 1;
            [from[0] + 0.3, -1.0]
        };
        for i in 0..600 {
            v.at_choosing(f64::from(i) / 60.0, &mut choose);
        }
        let f = v.fixations(10.0);
        assert!(calls >= 20, "{calls}");
        assert_eq!((f[1].2, f[1].3), (0.8, 0.0));
        assert_eq!((f[2].2, f[2].3), (1.0, 0.0));
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
