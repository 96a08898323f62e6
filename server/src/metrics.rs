//! Counters shared by the frame loop and the service, read by GetStatus and the summary log.
//!
//! Plain atomics: the loop and the gaze handlers only ever add, and readers tolerate a value that
//! is one frame old, so nothing here needs a lock on the loop's path but the last fixation.

use std::collections::VecDeque;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, PoisonError};
use std::time::{Duration, Instant};

use foveal_proto::pb;

/// Server-wide counters.
#[derive(Debug, Default)]
pub struct Metrics {
    frames: AtomicU64,
    overruns: AtomicU64,
    gaze_accepted: AtomicU64,
    gaze_rejected: AtomicU64,
    gaze_rate_limited: AtomicU64,
    /// When each of the frames of the last second completed (oldest first): fps is their count,
    /// so a loop that stops shows 0 within a second instead of its last good rate.
    recent: Mutex<VecDeque<Instant>>,
    gaze_rate_bits: AtomicU64,
    last_fixation: Mutex<Option<pb::Fixation>>,
}

/// The window fps counts frames over.
const FPS_WINDOW: Duration = Duration::from_secs(1);

fn forget_before(recent: &mut VecDeque<Instant>, now: Instant) {
    while recent
        .front()
        .is_some_and(|&t| now.saturating_duration_since(t) > FPS_WINDOW)
    {
        recent.pop_front();
    }
}

impl Metrics {
    /// Count a frame finished at `now` and remember the fixation it used.
    pub fn frame_done(&self, fixation: pb::Fixation, now: Instant) {
        self.frames.fetch_add(1, Ordering::Relaxed);
        {
            let mut recent = self.recent.lock().unwrap_or_else(PoisonError::into_inner);
            forget_before(&mut recent, now);
            recent.push_back(now);
        }
        *self
            .last_fixation
            .lock()
            .unwrap_or_else(PoisonError::into_inner) = Some(fixation);
    }

    /// Count a frame that ended after its deadline.
    pub fn overrun(&self) {
        self.overruns.fetch_add(1, Ordering::Relaxed);
    }

    /// Count validated gaze samples.
    pub fn gaze(&self, accepted: u64, rejected: u64) {
        self.gaze_accepted.fetch_add(accepted, Ordering::Relaxed);
        self.gaze_rejected.fetch_add(rejected, Ordering::Relaxed);
    }

    /// Count gaze samples dropped by the rate limit.
    pub fn gaze_limited(&self, dropped: u64) {
        self.gaze_rate_limited.fetch_add(dropped, Ordering::Relaxed);
    }

    /// Gaze samples dropped by the rate limit since start.
    pub fn gaze_rate_limited(&self) -> u64 {
        self.gaze_rate_limited.load(Ordering::Relaxed)
    }

    /// Publish the gaze rate measured over the last summary window.
    pub fn set_gaze_rate(&self, gaze_rate_hz: f64) {
        self.gaze_rate_bits
            .store(gaze_rate_hz.to_bits(), Ordering::Relaxed);
    }

    /// Frames simulated since start.
    pub fn frames(&self) -> u64 {
        self.frames.load(Ordering::Relaxed)
    }

    /// Frames that overran their period since start.
    pub fn overruns(&self) -> u64 {
        self.overruns.load(Ordering::Relaxed)
    }

    /// Gaze samples accepted since start.
    pub fn gaze_accepted(&self) -> u64 {
        self.gaze_accepted.load(Ordering::Relaxed)
    }

    /// Gaze samples rejected since start.
    pub fn gaze_rejected(&self) -> u64 {
        self.gaze_rejected.load(Ordering::Relaxed)
    }

    /// Frames completed in the second before `now` (frames per second).
    pub fn fps(&self, now: Instant) -> f64 {
        let mut recent = self.recent.lock().unwrap_or_else(PoisonError::into_inner);
        forget_before(&mut recent, now);
        recent.len() as f64
    }

    /// When the latest frame completed, if any has.
    pub fn last_frame_at(&self) -> Option<Instant> {
        self.recent
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
            .back()
            .copied()
    }

    /// Accepted gaze samples per second over the last summary window.
    pub fn gaze_rate_hz(&self) -> f64 {
        f64::from_bits(self.gaze_rate_bits.load(Ordering::Relaxed))
    }

    /// The fixation of the latest frame, if any frame has run.
    pub fn last_fixation(&self) -> Option<pb::Fixation> {
        *self
            .last_fixation
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fps_counts_the_last_second_and_falls_to_zero_when_frames_stop() {
        let m = Metrics::default();
        let t0 = Instant::now();
        for i in 0..60 {
            m.frame_done(pb::Fixation::default(), t0 + Duration::from_millis(i * 16));
        }
        let end = t0 + Duration::from_millis(59 * 16);
        assert_eq!(m.fps(end), 60.0);
        // Frames at 28 * 16 ms = 448 ms and later are within a second of 1,444 ms.
        assert_eq!(m.fps(end + Duration::from_millis(500)), 32.0);
        assert_eq!(m.fps(end + Duration::from_secs(2)), 0.0);
        assert_eq!(m.frames(), 60);
    }
}
