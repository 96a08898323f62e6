//! Online gaze processing for the scheduler, one sample at a time, causal: binocular combination,
//! an optional 1€ filter, an optional fixation detector, and what to do while the tracker has lost
//! the eye. The server keeps one [`GazeProcessor`] and asks it, once per frame, for the
//! [`GazeState`] to schedule by.
//!
//! Times are two clocks: a sample's `t_s` is the tracker's (used for velocities and durations);
//! `received_s` is the caller's clock when the sample arrived (used for ages and track loss), so
//! a tracker clock with any origin works.
//!
//! # Track loss (blinks, the eye out of range)
//! While the latest sample is missing, the last fixation is *held* for [`ProcessorConfig::hold_s`]
//! (300 ms: most blinks last 100-300 ms, Stern et al. 1984); after that it is kept but *widened*:
//! the region to treat as foveal grows by [`ProcessorConfig::widen_deg_per_s`] (an eye can have
//! moved anywhere by then); after [`ProcessorConfig::fallback_s`] (1 s) the state is *lost* and
//! the caller falls back (the server: the screen centre).
//!
//! # Binocular streams
//! Samples tagged [`Eye::Left`] and [`Eye::Right`] are combined as [`Binocular`] says: the mean of
//! the valid eyes of one instant (a left and a right sample whose tracker times are within
//! [`ProcessorConfig::pair_window_s`]), or one chosen eye (the other's samples are counted as
//! unused). Samples of any other eye tag pass through as they are.

use crate::clock::ClockSync;
use crate::detect::{Detector, DetectorParams, FixationEvent};
use crate::filter::{OneEuro, OneEuroParams};
use crate::geometry::ViewingGeometry;
use crate::validate::MAX_TIME_JUMP_S;
use crate::{Binocular, Eye, GazeSample};

/// Configuration of the online processing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProcessorConfig {
    /// How left and right samples combine ([`Binocular::Both`] is taken as the mean).
    pub eyes: Binocular,
    /// A left and a right sample this close in tracker time are one instant, seconds (5 ms: a
    /// binocular tracker stamps both eyes with one time; 5 ms tolerates rounding at 200 Hz).
    pub pair_window_s: f64,
    /// 1€ filter of the positions, if any.
    pub filter: Option<OneEuroParams>,
    /// Fixation detector, if any; without one every valid sample steers (lowest latency).
    pub detector: Option<DetectorParams>,
    /// The display geometry the detector measures degrees in.
    pub geometry: ViewingGeometry,
    /// Hold the last fixation this long into track loss, seconds.
    pub hold_s: f64,
    /// After the hold, widen the foveal region by this much per second of loss, deg/s.
    pub widen_deg_per_s: f64,
    /// After this long in track loss the state is lost, seconds.
    pub fallback_s: f64,
}

impl Default for ProcessorConfig {
    /// Mean of the eyes, no filter, no detector (raw samples steer), hold 300 ms, widen 20 deg/s,
    /// fall back after 1 s.
    fn default() -> Self {
        Self {
            eyes: Binocular::Mean,
            pair_window_s: 0.005,
            filter: None,
            detector: None,
            geometry: ViewingGeometry::default(),
            hold_s: 0.3,
            widen_deg_per_s: 20.0,
            fallback_s: 1.0,
        }
    }
}

impl ProcessorConfig {
    /// Checks every field.
    ///
    /// # Errors
    /// The name of the first field that cannot work.
    pub fn validate(&self) -> Result<(), &'static str> {
        let non_negative = |v: f64| v.is_finite() && v >= 0.0;
        if !non_negative(self.pair_window_s) {
            return Err("pair_window_s");
        }
        if let Some(f) = &self.filter {
            f.validate()?;
        }
        if let Some(d) = &self.detector {
            d.validate()?;
        }
        self.geometry.validate().map_err(|e| e.field)?;
        if !non_negative(self.hold_s) {
            return Err("hold_s");
        }
        if !non_negative(self.widen_deg_per_s) {
            return Err("widen_deg_per_s");
        }
        if !(non_negative(self.fallback_s) && self.fallback_s >= self.hold_s) {
            return Err("fallback_s");
        }
        Ok(())
    }
}

/// A position and when the sample behind it arrived.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimedPoint {
    /// Normalised x.
    pub x: f64,
    /// Normalised y.
    pub y: f64,
    /// Tracker time of the sample, seconds.
    pub t_s: f64,
    /// Arrival time of the sample, seconds on the caller's clock.
    pub received_s: f64,
    /// How much later than the fastest recent sample of the source this one arrived, seconds
    /// (see [`crate::clock`]): add it to the age since receipt.
    pub transit_excess_s: f64,
}

impl TimedPoint {
    /// Age at `now_s` (the caller's clock): since receipt, plus the excess transit.
    #[must_use]
    pub fn age_s(&self, now_s: f64) -> f64 {
        (now_s - self.received_s).max(0.0) + self.transit_excess_s
    }
}

/// What the steering point is and why.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Track {
    /// No sample yet.
    NoGaze,
    /// No detector: the latest (filtered) sample steers.
    Raw,
    /// In a detected fixation: it steers.
    Fixation,
    /// Between fixations (a saccade, or a fixation not yet long enough): the last fixation is held
    /// (the latest sample, before any fixation was seen).
    Saccade,
    /// Track lost for less than the hold: the last fixation is held.
    Holding,
    /// Track lost longer: the last fixation is kept with a widened foveal region.
    Widened,
    /// Track lost past the fallback: the caller falls back.
    Lost,
}

/// The state to schedule a frame by.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GazeState {
    /// The latest valid (combined, unfiltered) sample.
    pub raw: Option<TimedPoint>,
    /// The point to steer by (absent when there is no gaze or it is lost).
    pub steer: Option<TimedPoint>,
    /// Why.
    pub track: Track,
    /// Extra radius to treat as foveal around `steer`, degrees (0 unless widened).
    pub widen_deg: f64,
}

/// Counters of the processing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct ProcessorCounts {
    /// Samples pushed.
    pub samples: u64,
    /// Of them, missing (validity 0).
    pub missing: u64,
    /// Samples of the eye not chosen ([`Binocular::Left`] or [`Binocular::Right`]): not used.
    pub other_eye: u64,
    /// Fixations finished.
    pub fixations: u64,
    /// Times the tracker clock went back or jumped ahead (beyond [`MAX_TIME_JUMP_S`]) and the
    /// filter and detector started afresh.
    pub clock_resets: u64,
}

/// The online processor of one gaze source.
#[derive(Debug, Clone)]
pub struct GazeProcessor {
    config: ProcessorConfig,
    filter: Option<OneEuro>,
    detector: Option<Detector>,
    /// A left or right sample waiting for its other eye.
    pending_eye: Option<GazeSample>,
    binocular_seen: [bool; 2],
    raw: Option<TimedPoint>,
    filtered: Option<TimedPoint>,
    current: Option<FixationEvent>,
    /// The last fixation, with the arrival time and excess transit of its latest sample.
    last_fixation: Option<(FixationEvent, f64, f64)>,
    /// Arrival time of the first missing sample since the last valid one.
    lost_since_s: Option<f64>,
    /// Tracker time of the last sample processed.
    last_t_s: Option<f64>,
    clock: ClockSync,
    counts: ProcessorCounts,
}

impl GazeProcessor {
    /// A processor with `config` (assumed valid: see [`ProcessorConfig::validate`]).
    #[must_use]
    pub fn new(config: ProcessorConfig) -> Self {
        Self {
            config,
            filter: config.filter.map(OneEuro::new),
            detector: config.detector.map(|d| Detector::new(d, config.geometry)),
            pending_eye: None,
            binocular_seen: [false; 2],
            raw: None,
            filtered: None,
            current: None,
            last_fixation: None,
            lost_since_s: None,
            last_t_s: None,
            clock: ClockSync::new(),
            counts: ProcessorCounts::default(),
        }
    }

    /// The configuration.
    #[must_use]
    pub fn config(&self) -> &ProcessorConfig {
        &self.config
    }

    /// Measures degrees on `geometry` from now on (the display changed). The detector's window
    /// was in degrees of the old display, so it starts afresh; the last fixation is kept (it is a
    /// screen position, which the new display shows at the same normalised place) and the
    /// filter, which works in screen units, keeps its state.
    pub fn set_geometry(&mut self, geometry: ViewingGeometry) {
        if geometry == self.config.geometry {
            return;
        }
        self.config.geometry = geometry;
        self.detector = self.config.detector.map(|d| Detector::new(d, geometry));
        self.current = None;
    }

    /// Counters so far.
    #[must_use]
    pub fn counts(&self) -> ProcessorCounts {
        self.counts
    }

    /// Takes the next sample of the source (validated, or missing with validity 0), which
    /// arrived at `received_s`.
    pub fn push(&mut self, s: &GazeSample, received_s: f64) {
        self.counts.samples += 1;
        let side = match s.eye {
            Eye::Left => Some(0),
            Eye::Right => Some(1),
            Eye::Binocular | Eye::Unspecified => None,
        };
        let Some(side) = side else {
            self.process(s, received_s);
            return;
        };
        match self.config.eyes {
            Binocular::Left | Binocular::Right => {
                let chosen = usize::from(self.config.eyes == Binocular::Right);
                if side == chosen {
                    self.process(s, received_s);
                } else {
                    self.counts.other_eye += 1;
                }
            }
            Binocular::Mean | Binocular::Both => {
                self.binocular_seen[side] = true;
                if !(self.binocular_seen[0] && self.binocular_seen[1]) {
                    // One eye only so far: a monocular stream, not delayed.
                    self.process(s, received_s);
                    return;
                }
                match self.pending_eye.take() {
                    Some(p)
                        if p.eye != s.eye && (p.t_s - s.t_s).abs() <= self.config.pair_window_s =>
                    {
                        let (left, right) = if side == 0 { (s, &p) } else { (&p, s) };
                        let reading =
                            |e: &GazeSample| e.is_valid().then_some((e.x, e.y, e.validity));
                        let (mean, _) = Binocular::Mean.samples(
                            s.t_s.max(p.t_s),
                            reading(left),
                            reading(right),
                            s.fixation.or(p.fixation),
                        );
                        self.process(&mean, received_s);
                    }
                    Some(p) => {
                        // Its other eye never came: it stands alone.
                        self.process(&p, received_s);
                        self.pending_eye = Some(*s);
                    }
                    None => self.pending_eye = Some(*s),
                }
            }
        }
    }

    fn process(&mut self, s: &GazeSample, received_s: f64) {
        // A new tracker clock (a new stream after a restart, or a long pause): the filter's and
        // the detector's past say nothing about it. The last fixation is kept for holding.
        if let Some(last) = self.last_t_s
            && s.t_s.is_finite()
            && (s.t_s < last || s.t_s - last > MAX_TIME_JUMP_S)
        {
            self.filter = self.config.filter.map(OneEuro::new);
            self.detector = self
                .config
                .detector
                .map(|d| Detector::new(d, self.config.geometry));
            self.current = None;
            self.clock.reset();
            self.counts.clock_resets += 1;
        }
        if s.t_s.is_finite() {
            self.last_t_s = Some(s.t_s);
        }
        if !s.is_valid() {
            self.counts.missing += 1;
            self.lost_since_s.get_or_insert(received_s);
        } else {
            self.lost_since_s = None;
            let transit_excess_s = self.clock.observe(s.t_s, received_s);
            self.raw = Some(TimedPoint {
                x: s.x,
                y: s.y,
                t_s: s.t_s,
                received_s,
                transit_excess_s,
            });
            let (x, y) = match &mut self.filter {
                Some(f) => f.filter(s.t_s, s.x, s.y),
                None => (s.x, s.y),
            };
            self.filtered = Some(TimedPoint {
                x,
                y,
                t_s: s.t_s,
                received_s,
                transit_excess_s,
            });
        }
        if let Some(d) = &mut self.detector {
            let out = d.push(s);
            let excess = self.raw.map_or(0.0, |r| r.transit_excess_s);
            if let Some(done) = out.finished {
                self.counts.fixations += 1;
                self.last_fixation = Some((done, received_s, excess));
            }
            if let Some(c) = out.current {
                self.current = Some(c);
                self.last_fixation = Some((c, received_s, excess));
            } else {
                self.current = None;
            }
        }
    }

    /// The state to schedule by at `now_s` (the caller's clock).
    #[must_use]
    pub fn state(&self, now_s: f64) -> GazeState {
        let c = &self.config;
        let raw = self.raw;
        let Some(latest) = self.filtered else {
            return GazeState {
                raw,
                steer: None,
                track: Track::NoGaze,
                widen_deg: 0.0,
            };
        };
        let held = match (self.detector.is_some(), self.last_fixation) {
            (true, Some((f, received_s, transit_excess_s))) => TimedPoint {
                x: f.x,
                y: f.y,
                t_s: f.end_s,
                received_s,
                transit_excess_s,
            },
            _ => latest,
        };
        if let Some(since) = self.lost_since_s {
            let lost = (now_s - since).max(0.0);
            let (track, steer, widen_deg) = if lost < c.hold_s {
                (Track::Holding, Some(held), 0.0)
            } else if lost < c.fallback_s {
                (
                    Track::Widened,
                    Some(held),
                    c.widen_deg_per_s * (lost - c.hold_s),
                )
            } else {
                (Track::Lost, None, 0.0)
            };
            return GazeState {
                raw,
                steer,
                track,
                widen_deg,
            };
        }
        let (track, steer) = match (&self.detector, self.current) {
            (None, _) => (Track::Raw, latest),
            (Some(_), Some(f)) => (
                Track::Fixation,
                TimedPoint {
                    x: f.x,
                    y: f.y,
                    t_s: f.end_s,
                    received_s: latest.received_s,
                    transit_excess_s: latest.transit_excess_s,
                },
            ),
            (Some(_), None) => (Track::Saccade, held),
        };
        GazeState {
            raw,
            steer: Some(steer),
            track,
            widen_deg: 0.0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::detect::IvtParams;

    fn at(t: f64, x: f64, y: f64, eye: Eye) -> GazeSample {
        GazeSample::valid(t, x, y, eye)
    }

    #[test]
    fn raw_samples_steer_without_a_detector() {
        let mut p = GazeProcessor::new(ProcessorConfig::default());
        assert_eq!(p.state(0.0).track, Track::NoGaze);
        p.push(&at(5.0, 0.25, 0.75, Eye::Unspecified), 100.0);
        let s = p.state(100.01);
        assert_eq!(s.track, Track::Raw);
        let steer = s.steer.expect("a point");
        assert_eq!(
            (steer.x, steer.y, steer.t_s, steer.received_s),
            (0.25, 0.75, 5.0, 100.0)
        );
        assert_eq!(s.raw, s.steer);
    }

    #[test]
    fn a_fixation_steers_and_is_held_through_a_saccade_and_a_blink() {
        let config = ProcessorConfig {
            detector: Some(DetectorParams::Ivt(IvtParams::default())),
            ..ProcessorConfig::default()
        };
        let mut p = GazeProcessor::new(config);
        for i in 0..100 {
            let t = f64::from(i) * 0.001;
            p.push(&at(t, 0.25, 0.25, Eye::Left), t);
        }
        let s = p.state(0.1);
        assert_eq!(s.track, Track::Fixation);
        assert_eq!(s.steer.map(|f| (f.x, f.y)), Some((0.25, 0.25)));
        // A saccade: raw moves, the fixation is held.
        p.push(&at(0.100, 0.5, 0.25, Eye::Left), 0.100);
        p.push(&at(0.101, 0.75, 0.25, Eye::Left), 0.101);
        let s = p.state(0.101);
        assert_eq!(s.track, Track::Saccade);
        assert_eq!(s.steer.map(|f| (f.x, f.y)), Some((0.25, 0.25)));
        assert_eq!(s.raw.map(|r| r.x), Some(0.75));
        // Track loss: hold, widen, then lost.
        p.push(&GazeSample::missing(0.102, Eye::Left), 0.102);
        assert_eq!(p.state(0.2).track, Track::Holding);
        let widened = p.state(0.502);
        assert_eq!(widened.track, Track::Widened);
        assert!((widened.widen_deg - 2.0).abs() < 1e-9, "{widened:?}");
        assert_eq!(widened.steer.map(|f| f.x), Some(0.25));
        let lost = p.state(1.2);
        assert_eq!((lost.track, lost.steer), (Track::Lost, None));
        assert_eq!(p.counts().missing, 1);
    }

    #[test]
    fn binocular_streams_are_combined_or_one_eye_chosen() {
        let mut mean = GazeProcessor::new(ProcessorConfig::default());
        mean.push(&at(1.0, 0.25, 0.5, Eye::Left), 10.0);
        // One eye so far: used at once.
        assert_eq!(mean.state(10.0).steer.map(|f| f.x), Some(0.25));
        mean.push(&at(1.0, 0.75, 0.5, Eye::Right), 10.0);
        mean.push(&at(1.001, 0.25, 0.5, Eye::Left), 10.001);
        mean.push(&at(1.001, 0.75, 0.5, Eye::Right), 10.001);
        assert_eq!(
            mean.state(10.001).steer.map(|f| (f.x, f.t_s)),
            Some((0.5, 1.001))
        );
        // A blink of one eye: the other alone.
        mean.push(&GazeSample::missing(1.002, Eye::Left), 10.002);
        mean.push(&at(1.002, 0.75, 0.5, Eye::Right), 10.002);
        assert_eq!(mean.state(10.002).steer.map(|f| f.x), Some(0.75));

        let mut right = GazeProcessor::new(ProcessorConfig {
            eyes: Binocular::Right,
            ..ProcessorConfig::default()
        });
        right.push(&at(1.0, 0.25, 0.5, Eye::Left), 10.0);
        right.push(&at(1.0, 0.75, 0.5, Eye::Right), 10.0);
        assert_eq!(right.state(10.0).steer.map(|f| f.x), Some(0.75));
        assert_eq!(right.counts().other_eye, 1);
    }

    #[test]
    fn a_new_display_measures_degrees_on_it_and_keeps_the_held_fixation() {
        let config = ProcessorConfig {
            detector: Some(DetectorParams::Ivt(IvtParams::default())),
            ..ProcessorConfig::default()
        };
        // A drift of 1e-4 of the screen width per ms from the centre: 5 deg/s on the default desk
        // monitor (a fixation for I-VT), but 500 deg/s (a saccade) on a screen 100 times wider.
        let run = |p: &mut GazeProcessor, t0: f64| {
            for i in 0..100 {
                let t = t0 + f64::from(i) * 0.001;
                p.push(&at(t, 0.5 + f64::from(i) * 1e-4, 0.5, Eye::Left), t);
            }
        };
        let mut p = GazeProcessor::new(config);
        run(&mut p, 0.0);
        assert_eq!(p.state(0.1).track, Track::Fixation);
        let wall = ViewingGeometry {
            width_cm: 5310.0,
            height_cm: 2990.0,
            distance_cm: 60.0,
        };
        p.set_geometry(wall);
        assert_eq!(p.config().geometry, wall);
        // The held fixation survives the change; the new samples are a saccade in the new degrees.
        run(&mut p, 0.1);
        let s = p.state(0.2);
        assert_eq!(s.track, Track::Saccade, "{s:?}");
        assert!(s.steer.is_some_and(|f| (f.x - 0.505).abs() < 0.01), "{s:?}");
    }

    #[test]
    fn a_new_tracker_clock_starts_the_detector_afresh() {
        let config = ProcessorConfig {
            detector: Some(DetectorParams::Ivt(IvtParams::default())),
            ..ProcessorConfig::default()
        };
        let mut p = GazeProcessor::new(config);
        for i in 0..100 {
            let t = 50.0 + f64::from(i) * 0.001;
            p.push(&at(t, 0.25, 0.25, Eye::Left), f64::from(i) * 0.001);
        }
        // The tracker restarted: its clock is back at 0, the eye elsewhere.
        for i in 0..100 {
            let t = f64::from(i) * 0.001;
            p.push(&at(t, 0.75, 0.75, Eye::Left), 0.1 + t);
        }
        let s = p.state(0.2);
        assert_eq!(s.track, Track::Fixation);
        assert_eq!(s.steer.map(|f| f.x), Some(0.75));
        assert_eq!(p.counts().clock_resets, 1);
    }

    #[test]
    fn bad_configs_are_named() {
        assert!(ProcessorConfig::default().validate().is_ok());
        let bad = ProcessorConfig {
            fallback_s: 0.1,
            ..ProcessorConfig::default()
        };
        assert_eq!(bad.validate(), Err("fallback_s"));
    }
}
