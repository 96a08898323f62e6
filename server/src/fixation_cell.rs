//! The latest gaze: a single-value cell written by the gaze handlers and read by the frame loop.
//!
//! Writers push each sample through the online processing of `foveal-gaze` ([`GazeProcessor`]:
//! eyes combined, optional 1€ filter and fixation detector, track-loss handling); the loop reads
//! the resulting state once per frame. There is no queue to drain and nothing can back up. The
//! critical section is one sample's processing (well under a microsecond, see
//! docs/BENCHMARKS.md), so the mutex never holds the loop up measurably.
//!
//! One processor serves every gaze source: samples from two streams at once interleave (the
//! processor starts afresh when the tracker clock jumps, so a new stream after a restart works).

use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use foveal_engine::Fixation;
use foveal_gaze::GazeSample;
use foveal_gaze::online::{GazeProcessor, ProcessorConfig, Track};
use foveal_proto::pb::FixationSource;

/// Where the fixation goes when gaze is missing or stale: the screen centre.
pub const FALLBACK: (f64, f64) = (0.5, 0.5);

#[derive(Debug)]
struct Inner {
    processor: GazeProcessor,
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
    /// Handed to the engine (`age_s` is the sample's age at frame start, 0 with no gaze).
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

    /// A cell with this processing (assumed valid).
    pub fn with_config(config: ProcessorConfig) -> Self {
        Self {
            epoch: Instant::now(),
            inner: Mutex::new(Inner {
                processor: GazeProcessor::new(config),
            }),
        }
    }

    /// `at` on the processing's clock (seconds since the cell was made): what receipt times
    /// are given to the processing as, and what a recorded session's times are on.
    pub(crate) fn seconds(&self, at: Instant) -> f64 {
        at.saturating_duration_since(self.epoch).as_secs_f64()
    }

    /// Pushes samples received at `received`, in order: accepted ones, and missing ones
    /// (validity 0), which mark track loss.
    pub fn push<'a>(&self, samples: impl IntoIterator<Item = &'a GazeSample>, received: Instant) {
        let received_s = self.seconds(received);
        let mut inner = self.inner.lock().unwrap_or_else(PoisonError::into_inner);
        for s in samples {
            inner.processor.push(s, received_s);
        }
    }

    #[cfg(test)]
    /// Makes (x, y), received at `received`, the latest gaze: a valid sample of unknown eye,
    /// stamped with its receipt time (so it has no excess transit).
    pub fn store(&self, x: f64, y: f64, received: Instant) {
        let t_s = self.seconds(received);
        let s = GazeSample::valid(t_s, x, y, foveal_gaze::Eye::Unspecified);
        self.push([&s], received);
    }

    /// The fixation for a frame starting at `now`: the processing's steering point if it is at
    /// most `max_age` old, else the screen centre flagged as a fallback (stale gaze keeps its age
    /// for the record).
    pub fn resolve(&self, now: Instant, max_age: Duration) -> ResolvedFixation {
        let now_s = self.seconds(now);
        let state = self
            .inner
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .processor
            .state(now_s);
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
                x: FALLBACK.0,
                y: FALLBACK.1,
                age_s,
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
                if age_s > max_age.as_secs_f64() {
                    centre(age_s, FixationSource::FallbackStale)
                } else {
                    ResolvedFixation {
                        fixation: Fixation {
                            x: p.x,
                            y: p.y,
                            age_s,
                        },
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
        cell.push(&fixation, t0);
        let saccade = [GazeSample::valid(0.1, 0.75, 0.25, Eye::Left)];
        cell.push(&saccade, t0 + Duration::from_millis(1));
        let r = cell.resolve(t0 + Duration::from_millis(2), Duration::from_millis(500));
        assert_eq!((r.source, r.track), (FixationSource::Gaze, Track::Saccade));
        assert_eq!((r.fixation.x, r.fixation.y), (0.25, 0.25));
        assert_eq!(r.raw.map(|g| (g.x, g.tracker_time_s)), Some((0.75, 0.1)));
        // Then the eye is lost for good: fallback, flagged.
        cell.push(
            &[GazeSample::missing(0.101, Eye::Left)],
            t0 + Duration::from_millis(3),
        );
        let r = cell.resolve(t0 + Duration::from_secs(2), Duration::from_secs(10));
        assert_eq!(
            (r.source, r.track),
            (FixationSource::FallbackTrackLost, Track::Lost)
        );
    }
}
