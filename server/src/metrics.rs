//! Counters shared by the frame loop and the service, read by GetStatus and the summary log.
//!
//! Plain atomics: the loop and the gaze handlers only ever add, and readers tolerate a value that
//! is one frame old, so nothing here needs a lock on the loop's path but the last fixation.

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::{Mutex, PoisonError};

use foveal_proto::pb;

/// Server-wide counters.
#[derive(Debug, Default)]
pub struct Metrics {
    frames: AtomicU64,
    overruns: AtomicU64,
    gaze_accepted: AtomicU64,
    gaze_rejected: AtomicU64,
    fps_bits: AtomicU64,
    gaze_rate_bits: AtomicU64,
    last_fixation: Mutex<Option<pb::Fixation>>,
}

impl Metrics {
    /// Count a finished frame and remember the fixation it used.
    pub fn frame_done(&self, fixation: pb::Fixation) {
        self.frames.fetch_add(1, Ordering::Relaxed);
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

    /// Publish the rates measured over the last summary window.
    pub fn set_rates(&self, fps: f64, gaze_rate_hz: f64) {
        self.fps_bits.store(fps.to_bits(), Ordering::Relaxed);
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

    /// Frame rate over the last summary window.
    pub fn fps(&self) -> f64 {
        f64::from_bits(self.fps_bits.load(Ordering::Relaxed))
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
