//! The latest fixation: a single-value cell written by the gaze handlers and read by the frame loop.
//!
//! Only the newest sample matters to a frame, so there is no queue to drain and nothing can back
//! up: writers overwrite, the loop reads once per frame. The critical section is a copy of three
//! words, so a mutex never holds the loop up measurably.

use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use foveal_engine::Fixation;
use foveal_proto::pb::FixationSource;

/// Where the fixation goes when gaze is missing or stale: the screen centre.
pub const FALLBACK: (f64, f64) = (0.5, 0.5);

#[derive(Debug, Clone, Copy)]
struct Latest {
    x: f64,
    y: f64,
    received: Instant,
}

/// The latest accepted gaze point and when the server received it.
#[derive(Debug, Default)]
pub struct FixationCell {
    latest: Mutex<Option<Latest>>,
}

/// The fixation a frame uses and why.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResolvedFixation {
    /// Handed to the engine (`age_s` is the sample's age at frame start, 0 with no gaze).
    pub fixation: Fixation,
    /// Gaze, or which fallback.
    pub source: FixationSource,
}

impl FixationCell {
    /// An empty cell: frames fall back to the centre until gaze arrives.
    pub fn new() -> Self {
        Self::default()
    }

    /// Make (x, y), received at `received`, the latest gaze. Age is measured on the server clock
    /// from receipt because tracker clocks have arbitrary origins.
    pub fn store(&self, x: f64, y: f64, received: Instant) {
        *self.latest.lock().unwrap_or_else(PoisonError::into_inner) =
            Some(Latest { x, y, received });
    }

    /// The fixation for a frame starting at `now`: the latest gaze if it is at most `max_age` old,
    /// else the screen centre flagged as a fallback (stale gaze keeps its age for the record).
    pub fn resolve(&self, now: Instant, max_age: Duration) -> ResolvedFixation {
        let latest = *self.latest.lock().unwrap_or_else(PoisonError::into_inner);
        let centre = |age_s, source| ResolvedFixation {
            fixation: Fixation {
                x: FALLBACK.0,
                y: FALLBACK.1,
                age_s,
            },
            source,
        };
        match latest {
            None => centre(0.0, FixationSource::FallbackNoGaze),
            Some(l) => {
                // A sample stored after `now` was taken has age 0, not a negative one.
                let age = now.saturating_duration_since(l.received);
                if age > max_age {
                    centre(age.as_secs_f64(), FixationSource::FallbackStale)
                } else {
                    ResolvedFixation {
                        fixation: Fixation {
                            x: l.x,
                            y: l.y,
                            age_s: age.as_secs_f64(),
                        },
                        source: FixationSource::Gaze,
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
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
        assert!((r.fixation.age_s - 0.1).abs() < 1e-9);
        let r = cell.resolve(t0 + Duration::from_millis(501), max);
        assert_eq!(r.source, FixationSource::FallbackStale);
        assert_eq!((r.fixation.x, r.fixation.y), FALLBACK);
        // Stored after the frame started: age 0.
        let r = cell.resolve(t0 - Duration::from_millis(1), max);
        assert_eq!(r.fixation.age_s, 0.0);
    }
}
