//! Pacing: when to send a sample, given its timestamp on the source's clock.
//!
//! A recording or a script carries its own timeline; replaying it means sending each sample
//! when as much wall-clock time has passed since the first one as tracker time has (divided by
//! the speed). The first sample anchors the two clocks. Two things keep replay sane:
//! - timestamps that go backwards or are not finite wait for nothing (the server will judge
//!   them; the pacer never holds the stream back for them);
//! - after a stall longer than [`Pacer::max_lag`] (a suspended laptop, a slow server) the pacer
//!   re-anchors instead of sending the whole backlog in one burst, which would make the server
//!   see a gaze "jump" through every missed position at once.
//!
//! The arithmetic ([`Pacer::deadline`]) takes `now` as an argument so that it is tested without
//! sleeping; [`Pacer::wait`] is the async wrapper that sleeps.

use std::time::Duration;

use tokio::time::Instant;

/// How fast to replay.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pace {
    /// No waiting at all: send as fast as the server takes samples.
    AsFastAsPossible,
    /// Real time scaled by `speed`: 2.0 sends a 10 s recording in 5 s.
    Scaled {
        /// Speed-up factor (finite, > 0).
        speed: f64,
    },
}

impl Pace {
    /// Real time, speed 1.
    pub const REAL_TIME: Self = Self::Scaled { speed: 1.0 };

    /// `speed`× real time.
    ///
    /// # Errors
    /// A speed that is not finite and positive, with the reason.
    pub fn scaled(speed: f64) -> Result<Self, String> {
        if speed.is_finite() && speed > 0.0 {
            Ok(Self::Scaled { speed })
        } else {
            Err(format!("speed must be finite and > 0, not {speed}"))
        }
    }
}

/// Wall-clock time after the anchor at which a sample `t_s - t0_s` tracker-seconds after the
/// anchor sample is due at `speed`; zero for samples at or before the anchor, saturated at
/// [`Duration::MAX`] for absurd gaps.
#[must_use]
pub fn wall_offset(t0_s: f64, t_s: f64, speed: f64) -> Duration {
    let seconds = (t_s - t0_s) / speed;
    if seconds.is_nan() || seconds <= 0.0 {
        Duration::ZERO
    } else {
        Duration::try_from_secs_f64(seconds).unwrap_or(Duration::MAX)
    }
}

/// Turns sample timestamps into send deadlines (see the module documentation).
#[derive(Debug, Clone)]
pub struct Pacer {
    pace: Pace,
    max_lag: Duration,
    /// Tracker time and wall-clock instant of the anchor sample.
    anchor: Option<(f64, Instant)>,
    /// Latest finite timestamp seen, so that a step back waits for nothing.
    latest_s: f64,
    reanchors: u64,
}

impl Pacer {
    /// Default for [`Self::max_lag`]: well above scheduler jitter, well below anything a viewer
    /// would call a stall.
    pub const DEFAULT_MAX_LAG: Duration = Duration::from_millis(250);

    /// A pacer that has seen no sample yet.
    #[must_use]
    pub fn new(pace: Pace) -> Self {
        Self {
            pace,
            max_lag: Self::DEFAULT_MAX_LAG,
            anchor: None,
            latest_s: f64::NEG_INFINITY,
            reanchors: 0,
        }
    }

    /// The same pacer with another lag after which it re-anchors.
    #[must_use]
    pub fn with_max_lag(mut self, max_lag: Duration) -> Self {
        self.max_lag = max_lag;
        self
    }

    /// Lag behind schedule after which the pacer re-anchors rather than catching up.
    #[must_use]
    pub fn max_lag(&self) -> Duration {
        self.max_lag
    }

    /// How many times the pacer fell more than [`Self::max_lag`] behind and re-anchored.
    #[must_use]
    pub fn reanchors(&self) -> u64 {
        self.reanchors
    }

    /// When the sample stamped `t_s` is due, given that it is `now`: `None` means "send now".
    pub fn deadline(&mut self, t_s: f64, now: Instant) -> Option<Instant> {
        let Pace::Scaled { speed } = self.pace else {
            return None;
        };
        if !t_s.is_finite() || t_s <= self.latest_s {
            return None;
        }
        self.latest_s = t_s;
        let Some((t0_s, start)) = self.anchor else {
            self.anchor = Some((t_s, now));
            return None;
        };
        let due = start.checked_add(wall_offset(t0_s, t_s, speed));
        match due {
            Some(due) if due > now => Some(due),
            Some(due) if now.duration_since(due) <= self.max_lag => None,
            // Too far behind (or a gap too large to represent): start a new timeline here.
            _ => {
                self.anchor = Some((t_s, now));
                self.reanchors += 1;
                None
            }
        }
    }

    /// Sleeps until the sample stamped `t_s` is due.
    pub async fn wait(&mut self, t_s: f64) {
        if let Some(due) = self.deadline(t_s, Instant::now()) {
            tokio::time::sleep_until(due).await;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ms(n: u64) -> Duration {
        Duration::from_millis(n)
    }

    #[test]
    fn offsets_scale_with_speed_and_never_go_negative() {
        assert_eq!(wall_offset(10.0, 11.0, 1.0), ms(1000));
        assert_eq!(wall_offset(10.0, 11.0, 2.0), ms(500));
        assert_eq!(wall_offset(10.0, 11.0, 0.5), ms(2000));
        assert_eq!(wall_offset(10.0, 9.0, 1.0), Duration::ZERO);
        assert_eq!(wall_offset(0.0, f64::NAN, 1.0), Duration::ZERO);
        assert_eq!(wall_offset(0.0, 1e300, 1e-300), Duration::MAX);
    }

    #[test]
    fn speeds_must_be_finite_and_positive() {
        assert_eq!(Pace::scaled(2.0), Ok(Pace::Scaled { speed: 2.0 }));
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(Pace::scaled(bad).is_err(), "{bad}");
        }
    }

    #[test]
    fn first_sample_anchors_and_later_ones_follow_their_timestamps() {
        let start = Instant::now();
        let mut pacer = Pacer::new(Pace::Scaled { speed: 2.0 });
        assert_eq!(pacer.deadline(100.0, start), None, "first sample: send now");
        assert_eq!(pacer.deadline(100.5, start), Some(start + ms(250)));
        // Called late but within the lag: send now, keep the timeline.
        assert_eq!(pacer.deadline(101.0, start + ms(600)), None);
        assert_eq!(
            pacer.deadline(102.0, start + ms(600)),
            Some(start + ms(1000))
        );
        assert_eq!(pacer.reanchors(), 0);
    }

    #[test]
    fn steps_back_and_bad_timestamps_wait_for_nothing() {
        let start = Instant::now();
        let mut pacer = Pacer::new(Pace::REAL_TIME);
        assert_eq!(pacer.deadline(5.0, start), None);
        assert_eq!(pacer.deadline(6.0, start), Some(start + ms(1000)));
        assert_eq!(pacer.deadline(5.5, start), None, "backwards");
        assert_eq!(pacer.deadline(f64::NAN, start), None);
        assert_eq!(pacer.deadline(f64::INFINITY, start), None);
        assert_eq!(
            pacer.deadline(7.0, start),
            Some(start + ms(2000)),
            "timeline kept"
        );
    }

    #[test]
    fn a_long_stall_re_anchors_instead_of_bursting() {
        let start = Instant::now();
        let mut pacer = Pacer::new(Pace::REAL_TIME).with_max_lag(ms(100));
        assert_eq!(pacer.deadline(0.0, start), None);
        // Due at +10 ms, called at +1 s: far behind, so re-anchor at (0.01, +1 s).
        let late = start + ms(1000);
        assert_eq!(pacer.deadline(0.01, late), None);
        assert_eq!(pacer.reanchors(), 1);
        assert_eq!(pacer.deadline(0.02, late), Some(late + ms(10)));
        // A gap too large to represent also re-anchors rather than sleeping for ever.
        assert_eq!(pacer.deadline(1e300, late), None);
        assert_eq!(pacer.reanchors(), 2);
    }

    #[test]
    fn as_fast_as_possible_never_waits() {
        let now = Instant::now();
        let mut pacer = Pacer::new(Pace::AsFastAsPossible);
        for t in [0.0, 10.0, 1000.0] {
            assert_eq!(pacer.deadline(t, now), None);
        }
    }

    #[tokio::test(start_paused = true)]
    async fn wait_sleeps_until_the_deadline() {
        let mut pacer = Pacer::new(Pace::Scaled { speed: 4.0 });
        let start = Instant::now();
        pacer.wait(0.0).await;
        pacer.wait(1.0).await;
        assert_eq!(Instant::now().duration_since(start), ms(250));
    }
}
