//! The latest gaze: per-source online processing written by the gaze handlers and read by the
//! frame loop.
//!
//! Writers push each sample through the online processing of `foveal-gaze` ([`GazeProcessor`]:
//! eyes combined, optional 1€ filter and fixation detector, track-loss handling); the loop reads
//! the resulting state once per frame. There is no queue to drain and nothing can back up. The
//! critical section is one sample's processing (well under a microsecond, see
//! docs/BENCHMARKS.md), so the mutex never holds the loop up measurably.
//!
//! # Several sources
//! Every source (a `StreamGaze` call; a `PushGaze` client, by peer address and its `source`
//! name) has its own processor, so two trackers never interleave in one filter, detector or
//! clock estimate. One source steers a frame: the newest *live* one (a sample received within
//! the gaze age limit), because a client that starts sending while another runs is someone
//! taking over (the browser viewer switched to the mouse, a second tracker brought up); when it
//! goes quiet the next newest live source steers again. With no live source, the source heard
//! from last reports its (stale or lost) state. A source silent for [`FORGET_AFTER`] is
//! forgotten, and at most [`MAX_SOURCES`] are kept (the longest silent goes first).

use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use foveal_engine::Fixation;
use foveal_gaze::GazeSample;
use foveal_gaze::geometry::ViewingGeometry;
use foveal_gaze::online::{GazeProcessor, GazeState, ProcessorConfig, Track};

/// Where the fixation goes when gaze is missing or stale: the screen centre.
pub const FALLBACK: (f64, f64) = (0.5, 0.5);

/// A source silent this long is forgotten (its state would only ever be stale again).
pub const FORGET_AFTER: Duration = Duration::from_secs(60);

/// Most sources kept at once: the server's gaze-stream limit plus room for push clients.
pub const MAX_SOURCES: usize = 64;

/// The gaze processing's view of the engine's display: its physical size from the diagonal
/// and aspect ratio, and the viewing distance (degrees are then the same on both sides).
pub fn viewing_geometry(display: &foveal_engine::Display) -> ViewingGeometry {
    let (w, h) = (f64::from(display.width_px), f64::from(display.height_px));
    let diagonal_cm = display.diagonal_in * 2.54;
    ViewingGeometry {
        width_cm: diagonal_cm * w / w.hypot(h),
        height_cm: diagonal_cm * h / w.hypot(h),
        distance_cm: display.viewing_distance_cm,
    }
}

/// Where a frame's fixation comes from: gaze, or which fallback and why. The protocol's
/// `FixationSource` is this, converted where a frame leaves the server (`convert`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FixationSource {
    /// A live source's gaze.
    Gaze,
    /// The screen centre: no gaze has arrived.
    FallbackNoGaze,
    /// The screen centre: the newest gaze is older than the age limit.
    FallbackStale,
    /// The screen centre: the tracker reports the eye lost for too long.
    FallbackTrackLost,
}

impl FixationSource {
    /// The name a recorded session writes (`fixation_source`): part of the file format.
    pub fn name(self) -> &'static str {
        match self {
            Self::Gaze => "gaze",
            Self::FallbackNoGaze => "fallback_no_gaze",
            Self::FallbackStale => "fallback_stale",
            Self::FallbackTrackLost => "fallback_track_lost",
        }
    }
}

/// Which client a sample came from.
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum SourceKey {
    /// One `StreamGaze` call, numbered by the server.
    Stream(u64),
    /// A `PushGaze` client: its peer address (IP, or none in-process) and `source` name.
    Push(Option<std::net::IpAddr>, String),
}

impl std::fmt::Display for SourceKey {
    /// `stream:<n>`, or `push:<source>` with `@<ip>` when the peer is known (the names a recorded
    /// session gives its gaze samples).
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Stream(n) => write!(f, "stream:{n}"),
            Self::Push(None, source) => write!(f, "push:{source}"),
            Self::Push(Some(ip), source) => write!(f, "push:{source}@{ip}"),
        }
    }
}

#[derive(Debug)]
struct Source {
    key: SourceKey,
    processor: GazeProcessor,
    first_received_s: f64,
    last_received_s: f64,
}

#[derive(Debug)]
struct Inner {
    config: ProcessorConfig,
    sources: Vec<Source>,
    /// The source that steered the last frame (to log a change of hands once).
    steering: Option<SourceKey>,
}

impl Inner {
    /// The source for `key`, created if new (forgetting silent ones to make room).
    fn source(&mut self, key: &SourceKey, now_s: f64) -> &mut Source {
        if let Some(i) = self.sources.iter().position(|s| &s.key == key) {
            return &mut self.sources[i];
        }
        let forget = FORGET_AFTER.as_secs_f64();
        self.sources.retain(|s| now_s - s.last_received_s <= forget);
        if self.sources.len() >= MAX_SOURCES
            && let Some(oldest) = self
                .sources
                .iter()
                .enumerate()
                .min_by(|a, b| a.1.last_received_s.total_cmp(&b.1.last_received_s))
                .map(|(i, _)| i)
        {
            self.sources.swap_remove(oldest);
        }
        self.sources.push(Source {
            key: key.clone(),
            processor: GazeProcessor::new(self.config),
            first_received_s: now_s,
            last_received_s: now_s,
        });
        let last = self.sources.len() - 1;
        &mut self.sources[last]
    }

    /// The source that steers at `now_s` and its state (see the module documentation): the
    /// newest live source with a point to steer by, else the newest live one, else the one heard
    /// from last.
    fn steering<'a>(&'a self, now_s: f64, max_age_s: f64) -> Option<(&'a Source, GazeState)> {
        // One scan, no allocation (this runs every frame): the state is asked only of a live
        // source newer than the best one with a point so far; among equally new sources the
        // first registered wins.
        let mut steering: Option<(&'a Source, GazeState)> = None;
        let mut newest: Option<&'a Source> = None;
        for s in self
            .sources
            .iter()
            .filter(|s| now_s - s.last_received_s <= max_age_s)
        {
            if newest.is_none_or(|n| s.first_received_s > n.first_received_s) {
                newest = Some(s);
            }
            if steering
                .as_ref()
                .is_none_or(|(n, _)| s.first_received_s > n.first_received_s)
            {
                let st = s.processor.state(now_s);
                if st.steer.is_some() {
                    steering = Some((s, st));
                }
            }
        }
        let with_state = |s: &'a Source| (s, s.processor.state(now_s));
        steering.or_else(|| newest.map(with_state)).or_else(|| {
            self.sources
                .iter()
                .max_by(|a, b| a.last_received_s.total_cmp(&b.last_received_s))
                .map(with_state)
        })
    }
}

/// The online gaze processing and the clock its receipt times are on.
#[derive(Debug)]
pub struct FixationCell {
    epoch: Instant,
    inner: Mutex<Inner>,
}

impl Default for FixationCell {
    fn default() -> Self {
        Self::new()
    }
}

/// The latest raw sample, for the frame record.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RawGaze {
    /// Normalised x.
    pub x: f64,
    /// Normalised y.
    pub y: f64,
    /// Age at frame start, seconds: since receipt (server clock) plus the sample's delay beyond
    /// the source's fastest recent transit.
    pub age_s: f64,
    /// The sample's tracker time, seconds.
    pub tracker_time_s: f64,
}

/// The fixation a frame uses and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolvedFixation {
    /// Handed to the engine (`age_s` is the sample's age at frame start, 0 with no gaze; while
    /// the track is lost and widened, `uncertainty_deg` is the widening, so the schedulers treat
    /// the widened region as foveal).
    pub fixation: Fixation,
    /// Gaze, or which fallback.
    pub source: FixationSource,
    /// The latest raw sample, if any.
    pub raw: Option<RawGaze>,
    /// What the processing steered by.
    pub track: Track,
    /// Extra foveal radius while the track is lost, degrees.
    pub widen_deg: f64,
}

impl FixationCell {
    /// A cell with the default processing (raw samples steer): frames fall back to the centre
    /// until gaze arrives.
    pub fn new() -> Self {
        Self::with_config(ProcessorConfig::default())
    }

    /// A cell with this processing (assumed valid) for every source.
    pub fn with_config(config: ProcessorConfig) -> Self {
        Self {
            epoch: Instant::now(),
            inner: Mutex::new(Inner {
                config,
                sources: Vec::new(),
                steering: None,
            }),
        }
    }

    /// `at` on the processing's clock (seconds since the cell was made): what receipt times
    /// are given to the processing as, and what a recorded session's times are on.
    pub(crate) fn seconds(&self, at: Instant) -> f64 {
        at.saturating_duration_since(self.epoch).as_secs_f64()
    }

    /// Degrees are measured on `geometry` from now on, for every source (the display changed).
    pub fn set_geometry(&self, geometry: ViewingGeometry) {
        let mut inner = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        inner.config.geometry = geometry;
        for s in &mut inner.sources {
            s.processor.set_geometry(geometry);
        }
    }

    /// The geometry degrees are measured on.
    #[cfg(test)]
    pub fn geometry(&self) -> ViewingGeometry {
        self.inner
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .config
            .geometry
    }

    /// Sources heard from within `max_age` of `now`.
    pub fn live_sources(&self, now: Instant, max_age: Duration) -> usize {
        let now_s = self.seconds(now);
        let inner = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        inner
            .sources
            .iter()
            .filter(|s| now_s - s.last_received_s <= max_age.as_secs_f64())
            .count()
    }

    /// Pushes samples of `source` received at `received`, in order: accepted ones, and missing
    /// ones (validity 0), which mark track loss.
    pub fn push<'a>(
        &self,
        source: &SourceKey,
        samples: impl IntoIterator<Item = &'a GazeSample>,
        received: Instant,
    ) {
        let received_s = self.seconds(received);
        let mut inner = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        let src = inner.source(source, received_s);
        src.last_received_s = src.last_received_s.max(received_s);
        for s in samples {
            src.processor.push(s, received_s);
        }
    }

    #[cfg(test)]
    /// Makes (x, y), received at `received`, the latest gaze of source `Stream(0)`: a valid
    /// sample of unknown eye, stamped with its receipt time (so it has no excess transit).
    pub fn store(&self, x: f64, y: f64, received: Instant) {
        let t_s = self.seconds(received);
        let s = GazeSample::valid(t_s, x, y, foveal_gaze::Eye::Unspecified);
        self.push(&SourceKey::Stream(0), [&s], received);
    }

    /// The fixation for a frame starting at `now`: the steering source's point if it is at most
    /// `max_age` old (while the track is held or widened: if the source sent anything within
    /// `max_age`), else the screen centre flagged as a fallback (stale gaze keeps its age for the
    /// record).
    pub fn resolve(&self, now: Instant, max_age: Duration) -> ResolvedFixation {
        let now_s = self.seconds(now);
        let mut inner = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        let steering = inner.steering(now_s, max_age.as_secs_f64());
        let key = steering.as_ref().map(|(s, _)| s.key.clone());
        let silent_s = steering
            .as_ref()
            .map_or(0.0, |(s, _)| now_s - s.last_received_s);
        let state = steering.map(|(_, st)| st);
        if key.is_some() && key != inner.steering {
            tracing::info!(source = ?key, "gaze source steering");
            inner.steering = key;
        }
        drop(inner);
        let Some(state) = state else {
            return ResolvedFixation {
                fixation: Fixation::at(FALLBACK.0, FALLBACK.1),
                source: FixationSource::FallbackNoGaze,
                raw: None,
                track: Track::NoGaze,
                widen_deg: 0.0,
            };
        };
        // Since receipt (a sample stored after `now` was taken has 0, not a negative age), plus
        // the delay beyond the source's fastest recent transit (`foveal_gaze::clock`).
        let raw = state.raw.map(|r| RawGaze {
            x: r.x,
            y: r.y,
            age_s: r.age_s(now_s),
            tracker_time_s: r.t_s,
        });
        let centre = |age_s, source| ResolvedFixation {
            fixation: Fixation {
                age_s,
                ..Fixation::at(FALLBACK.0, FALLBACK.1)
            },
            source,
            raw,
            track: state.track,
            widen_deg: state.widen_deg,
        };
        match (state.track, state.steer) {
            (Track::NoGaze, _) => centre(0.0, FixationSource::FallbackNoGaze),
            (_, None) => centre(
                raw.map_or(0.0, |r| r.age_s),
                FixationSource::FallbackTrackLost,
            ),
            (_, Some(p)) => {
                let age_s = p.age_s(now_s);
                // While the eye is lost and the tracker says so, the processing holds and widens
                // the last fixation however old it is; only a source gone silent is stale.
                let stale = match state.track {
                    Track::Holding | Track::Widened => silent_s > max_age.as_secs_f64(),
                    _ => age_s > max_age.as_secs_f64(),
                };
                if stale {
                    centre(age_s, FixationSource::FallbackStale)
                } else {
                    ResolvedFixation {
                        fixation: Fixation {
                            age_s,
                            ..Fixation::at(p.x, p.y)
                        }
                        .with_uncertainty(state.widen_deg),
                        source: FixationSource::Gaze,
                        raw,
                        track: state.track,
                        widen_deg: state.widen_deg,
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use foveal_gaze::Eye;
    use foveal_gaze::detect::DetectorParams;

    use super::*;

    #[test]
    fn no_gaze_then_gaze_then_stale() {
        let cell = FixationCell::new();
        let t0 = Instant::now();
        let max = Duration::from_millis(500);
        assert_eq!(cell.resolve(t0, max).source, FixationSource::FallbackNoGaze);
        cell.store(0.2, 0.7, t0);
        let r = cell.resolve(t0 + Duration::from_millis(100), max);
        assert_eq!(r.source, FixationSource::Gaze);
        assert_eq!((r.fixation.x, r.fixation.y), (0.2, 0.7));
        assert!((r.fixation.age_s - 0.1).abs() < 1e-6);
        assert_eq!(r.track, Track::Raw);
        assert_eq!(r.raw.map(|g| (g.x, g.y)), Some((0.2, 0.7)));
        let r = cell.resolve(t0 + Duration::from_millis(501), max);
        assert_eq!(r.source, FixationSource::FallbackStale);
        assert_eq!((r.fixation.x, r.fixation.y), FALLBACK);
        // Stored after the frame started: age 0.
        let r = cell.resolve(t0 - Duration::from_millis(1), max);
        assert_eq!(r.fixation.age_s, 0.0);
    }

    #[test]
    fn with_a_detector_a_saccade_keeps_the_fixation_and_the_raw_sample_is_reported() {
        let cell = FixationCell::with_config(ProcessorConfig {
            detector: Some(DetectorParams::default()),
            ..ProcessorConfig::default()
        });
        let t0 = Instant::now();
        let fixation: Vec<GazeSample> = (0..100)
            .map(|i| GazeSample::valid(f64::from(i) * 0.001, 0.25, 0.25, Eye::Left))
            .collect();
        cell.push(&SourceKey::Stream(0), &fixation, t0);
        let saccade = [GazeSample::valid(0.1, 0.75, 0.25, Eye::Left)];
        cell.push(
            &SourceKey::Stream(0),
            &saccade,
            t0 + Duration::from_millis(1),
        );
        let r = cell.resolve(t0 + Duration::from_millis(2), Duration::from_millis(500));
        assert_eq!((r.source, r.track), (FixationSource::Gaze, Track::Saccade));
        assert_eq!((r.fixation.x, r.fixation.y), (0.25, 0.25));
        assert_eq!(r.raw.map(|g| (g.x, g.tracker_time_s)), Some((0.75, 0.1)));
        // Then the eye is lost for good: fallback, flagged.
        cell.push(
            &SourceKey::Stream(0),
            &[GazeSample::missing(0.101, Eye::Left)],
            t0 + Duration::from_millis(3),
        );
        let r = cell.resolve(t0 + Duration::from_secs(2), Duration::from_secs(10));
        assert_eq!(
            (r.source, r.track),
            (FixationSource::FallbackTrackLost, Track::Lost)
        );
    }

    fn fixation_run(t0_s: f64, x: f64, y: f64) -> Vec<GazeSample> {
        (0..100)
            .map(|i| GazeSample::valid(t0_s + f64::from(i) * 0.001, x, y, Eye::Left))
            .collect()
    }

    #[test]
    fn each_source_has_its_own_processing_and_the_newest_live_one_steers() {
        let cell = FixationCell::with_config(ProcessorConfig {
            detector: Some(DetectorParams::default()),
            ..ProcessorConfig::default()
        });
        let (a, b) = (SourceKey::Stream(1), SourceKey::Stream(2));
        let t0 = Instant::now();
        let max = Duration::from_millis(500);
        // Two trackers at once, sample by sample interleaved, on clocks 100 s apart: in one
        // processor they would be a saccade every sample (and clock resets); apart, each holds a
        // fixation.
        let (sa, sb) = (fixation_run(100.0, 0.2, 0.2), fixation_run(0.0, 0.8, 0.8));
        for (i, (x, y)) in sa.iter().zip(&sb).enumerate() {
            let at = t0 + Duration::from_millis(i as u64);
            cell.push(&a, [x], at);
            cell.push(&b, [y], at + Duration::from_micros(500));
        }
        assert_eq!(cell.live_sources(t0 + Duration::from_millis(100), max), 2);
        let r = cell.resolve(t0 + Duration::from_millis(100), max);
        assert_eq!((r.source, r.track), (FixationSource::Gaze, Track::Fixation));
        // B started last (by a hair): it steers.
        assert!((r.fixation.x - 0.8).abs() < 1e-9 && (r.fixation.y - 0.8).abs() < 1e-9);
        // B goes quiet; A keeps sending: once B is stale, A steers with its own fixation.
        for (i, x) in fixation_run(100.1, 0.2, 0.2).iter().enumerate() {
            cell.push(&a, [x], t0 + Duration::from_millis(100 + 5 * i as u64));
        }
        let r = cell.resolve(t0 + Duration::from_millis(650), max);
        assert_eq!((r.source, r.track), (FixationSource::Gaze, Track::Fixation));
        assert!((r.fixation.x - 0.2).abs() < 1e-9 && (r.fixation.y - 0.2).abs() < 1e-9);
    }

    #[test]
    fn a_widened_track_makes_the_engine_treat_the_widened_region_as_foveal() {
        let cell = FixationCell::new();
        let key = SourceKey::Push(None, "tracker".into());
        let t0 = Instant::now();
        cell.push(&key, &[GazeSample::valid(1.0, 0.3, 0.4, Eye::Left)], t0);
        cell.push(&key, &[GazeSample::missing(1.001, Eye::Left)], t0);
        // The gaze age limit is shorter than the loss: a source that reports the loss is live.
        let max = Duration::from_millis(200);
        cell.push(
            &key,
            &[GazeSample::missing(1.4, Eye::Left)],
            t0 + Duration::from_millis(400),
        );
        let held = cell.resolve(t0 + Duration::from_millis(100), max);
        assert_eq!(held.track, Track::Holding);
        assert_eq!(held.fixation.uncertainty_deg, 0.0);
        // 300 ms hold, then 20 deg/s: 0.5 s into the loss the region is 4 degrees wider.
        let widened = cell.resolve(t0 + Duration::from_millis(500), max);
        assert_eq!(
            (widened.source, widened.track),
            (FixationSource::Gaze, Track::Widened)
        );
        assert_eq!((widened.fixation.x, widened.fixation.y), (0.3, 0.4));
        assert!(
            (widened.fixation.uncertainty_deg - 4.0).abs() < 0.05,
            "{widened:?}"
        );
        assert_eq!(widened.fixation.uncertainty_deg, widened.widen_deg);
        assert!(widened.fixation.is_usable());
        // Then the tracker goes silent too: stale.
        let silent = cell.resolve(t0 + Duration::from_millis(700), max);
        assert_eq!(silent.source, FixationSource::FallbackStale);
    }

    #[test]
    fn a_new_display_reaches_every_source_and_later_ones() {
        let cell = FixationCell::new();
        let t0 = Instant::now();
        cell.store(0.5, 0.5, t0);
        let wide = ViewingGeometry {
            width_cm: 120.0,
            height_cm: 68.0,
            distance_cm: 200.0,
        };
        cell.set_geometry(wide);
        assert_eq!(cell.geometry(), wide);
        let inner = cell.inner.lock().expect("not poisoned");
        assert!(
            inner
                .sources
                .iter()
                .all(|s| s.processor.config().geometry == wide)
        );
        assert_eq!(inner.config.geometry, wide);
    }

    #[test]
    fn sources_are_bounded_and_silent_ones_forgotten() {
        let cell = FixationCell::new();
        let t0 = Instant::now();
        let s = [GazeSample::valid(1.0, 0.5, 0.5, Eye::Left)];
        for i in 0..(MAX_SOURCES as u64 + 10) {
            cell.push(&SourceKey::Stream(i), &s, t0 + Duration::from_millis(i));
        }
        let n = cell.inner.lock().expect("not poisoned").sources.len();
        assert_eq!(n, MAX_SOURCES);
        cell.push(
            &SourceKey::Stream(999),
            &s,
            t0 + FORGET_AFTER + Duration::from_secs(1),
        );
        let inner = cell.inner.lock().expect("not poisoned");
        assert_eq!(inner.sources.len(), 1, "every silent source forgotten");
    }
}
