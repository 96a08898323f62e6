//! Per-source clock offset between a tracker and the receiver, estimated online from one-way
//! arrivals, so that a sample's age can include the delay it spent on the way.
//!
//! Every sample carries the tracker's time `t_s` and arrives at the receiver's `received_s`. Their
//! difference is the clocks' offset plus the sample's transit delay. The smallest difference over
//! a recent window ([`WINDOW_S`], 10 s) estimates offset plus the *fastest* transit (as NTP's and
//! LSL's time correction take the least-delayed exchange as the most trustworthy); a sample's
//! *excess transit* is how much later than that it arrived: bridge buffering, batching, network
//! queueing. A frame adds it to the age since receipt. What one-way timing cannot see is the
//! constant part (the fastest transit itself, and the tracker's own processing before stamping);
//! it stays out of the age, so the age is a lower bound of the true one.
//!
//! The window slides, so a tracker clock that drifts against the receiver's is followed; a clock
//! that jumps (a new stream) must be [`ClockSync::reset`].

use std::collections::VecDeque;

/// Span of arrivals the minimum is taken over, seconds of receiver time.
pub const WINDOW_S: f64 = 10.0;

/// The online offset estimate of one source.
#[derive(Debug, Clone, Default)]
pub struct ClockSync {
    /// (received_s, received_s - t_s), increasing in the difference: a monotonic deque whose
    /// front is the window's minimum.
    minima: VecDeque<(f64, f64)>,
}

impl ClockSync {
    /// No estimate yet.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Forgets the past (the tracker clock changed).
    pub fn reset(&mut self) {
        self.minima.clear();
    }

    /// Takes a sample stamped `t_s` that arrived at `received_s` and gives its excess transit,
    /// seconds (>= 0; 0 for the first sample or non-finite times).
    pub fn observe(&mut self, t_s: f64, received_s: f64) -> f64 {
        let d = received_s - t_s;
        if !d.is_finite() {
            return 0.0;
        }
        while self.minima.back().is_some_and(|&(_, back)| back >= d) {
            self.minima.pop_back();
        }
        self.minima.push_back((received_s, d));
        while self
            .minima
            .front()
            .is_some_and(|&(at, _)| received_s - at > WINDOW_S)
        {
            self.minima.pop_front();
        }
        let min = self.minima.front().map_or(d, |&(_, m)| m);
        (d - min).max(0.0)
    }

    /// The current estimate of offset plus fastest transit, seconds (`received - t`), if any.
    #[must_use]
    pub fn offset_s(&self) -> Option<f64> {
        self.minima.front().map(|&(_, m)| m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn excess_transit_is_the_delay_beyond_the_fastest() {
        let mut c = ClockSync::new();
        // Tracker clock 1000 s behind; transit 2 ms, except one sample held 30 ms by a bridge.
        assert_eq!(c.observe(0.000, 1000.002), 0.0);
        assert!(c.observe(0.001, 1000.003).abs() < 1e-9);
        assert!((c.observe(0.002, 1000.034) - 0.030).abs() < 1e-9);
        assert!(c.observe(0.003, 1000.005).abs() < 1e-9);
        assert!((c.offset_s().expect("estimate") - 1000.002).abs() < 1e-9);
        // A batch: four samples arriving at once; the oldest waited longest.
        let batch: Vec<f64> = (4..8)
            .map(|i| c.observe(f64::from(i) * 0.001, 1000.009))
            .collect();
        assert!(
            (batch[0] - 0.003).abs() < 1e-9 && batch[3].abs() < 1e-9,
            "{batch:?}"
        );
        assert_eq!(c.observe(f64::NAN, 1.0), 0.0);
        c.reset();
        assert_eq!(c.offset_s(), None);
    }

    #[test]
    fn a_drifting_clock_is_followed_by_the_window() {
        let mut c = ClockSync::new();
        // The tracker clock runs 1% slow: received - t grows by 10 ms per second.
        let mut last = 0.0;
        for i in 0..30_000 {
            let r = f64::from(i) * 0.001;
            last = c.observe(r * 0.99, r + 0.002);
        }
        // Against a fixed minimum the excess would be ~0.3 s; the window keeps it near 0.1 s.
        assert!(last < 0.101, "{last}");
    }
}
