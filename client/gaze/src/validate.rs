//! The rules a gaze sample must pass before it can steer the scheduler; the server applies them
//! to every sample of StreamGaze and PushGaze.
//!
//! Trackers send garbage in ordinary operation (NaN during blinks, wild values on track loss), so
//! a bad sample is rejected on its own with a reason naming the field, counted by kind, and the
//! samples around it are kept.
//!
//! # Time
//! Timestamps must not decrease within one source (stream or batch), and a step forward of more
//! than [`MAX_TIME_JUMP_S`] is rejected too: a single wild timestamp (10 s, then 1e9, then 10.001)
//! is one rejected sample and nothing more, because the clock later samples are checked against
//! only moves with accepted times. A tracker whose clock really changed (restarted, or resumed
//! after a long pause) is followed after [`RESYNC_SAMPLES`] samples that agree with one another:
//! the first `RESYNC_SAMPLES - 1` of the new clock are rejected (and counted as such), the rest
//! are checked against it. So no timestamp, however wild, can lock a source out.

use std::fmt;

use crate::GazeSample;

/// Smallest accepted gaze coordinate (normalised screen units). Fixations slightly off screen are
/// real (a viewer glancing at the bezel) and legal; a whole screen beyond the edge is a broken
/// calibration or a unit mistake (pixels sent as normalised), so it is rejected.
pub const MIN_COORD: f64 = -1.0;
/// Largest accepted gaze coordinate (normalised screen units); see [`MIN_COORD`].
pub const MAX_COORD: f64 = 2.0;
/// Largest accepted step forward of the tracker clock between two samples of a source, seconds.
/// The slowest trackers in use sample at 30 Hz (33 ms); 5 s covers dropped samples, a paused
/// bridge and a slow reconnect, while a wild timestamp (a corrupted or uninitialised field) is
/// orders of magnitude beyond it.
pub const MAX_TIME_JUMP_S: f64 = 5.0;
/// Consecutive samples that must agree on a new clock (each non-decreasing and within
/// [`MAX_TIME_JUMP_S`] of the one before) before the source is followed onto it. Three: one wild
/// timestamp, or two, never agree with each other by chance; a real clock change costs 2 samples.
pub const RESYNC_SAMPLES: u32 = 3;

/// Why a sample was rejected: one counter each.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RejectKind {
    /// `tracker_time_s` is NaN or infinite.
    TimeNotFinite,
    /// `tracker_time_s` is earlier than the source's clock.
    TimeBackwards,
    /// `tracker_time_s` steps forward by more than [`MAX_TIME_JUMP_S`].
    TimeJump,
    /// `validity` is outside [0, 1] or NaN.
    ValidityOutOfRange,
    /// `validity` is 0: the tracker marks the sample missing (blink, track loss).
    Missing,
    /// `x` or `y` is NaN or infinite.
    CoordNotFinite,
    /// `x` or `y` is outside [[`MIN_COORD`], [`MAX_COORD`]].
    CoordOutOfRange,
}

impl RejectKind {
    /// Every kind, in a fixed order (for counters).
    pub const ALL: [Self; 7] = [
        Self::TimeNotFinite,
        Self::TimeBackwards,
        Self::TimeJump,
        Self::ValidityOutOfRange,
        Self::Missing,
        Self::CoordNotFinite,
        Self::CoordOutOfRange,
    ];

    /// Position in [`Self::ALL`].
    #[must_use]
    pub fn index(self) -> usize {
        self as usize
    }

    /// A short snake_case name, for metrics and logs.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::TimeNotFinite => "time_not_finite",
            Self::TimeBackwards => "time_backwards",
            Self::TimeJump => "time_jump",
            Self::ValidityOutOfRange => "validity_out_of_range",
            Self::Missing => "missing",
            Self::CoordNotFinite => "coord_not_finite",
            Self::CoordOutOfRange => "coord_out_of_range",
        }
    }
}

/// Why a sample was not used: the field at fault, the kind, and a message for a person.
#[derive(Debug, Clone, PartialEq)]
pub struct Rejection {
    /// The offending field of the sample (`tracker_time_s`, `x`, `y`, `validity`).
    pub field: &'static str,
    /// Which rule.
    pub kind: RejectKind,
    /// What was wrong with it, with the limit.
    pub reason: String,
}

impl fmt::Display for Rejection {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: {}", self.field, self.reason)
    }
}

impl Rejection {
    fn new(field: &'static str, kind: RejectKind, reason: impl Into<String>) -> Self {
        Self {
            field,
            kind,
            reason: reason.into(),
        }
    }
}

/// A new clock the source may be moving onto: the last of the agreeing samples and how many.
#[derive(Debug, Clone, Copy)]
struct Candidate {
    last_s: f64,
    count: u32,
}

/// Validates one source of samples (one stream or one batch) in order, and counts the outcome.
///
/// Each source keeps its own clock: a bridge reconnecting after the tracker restarted starts a new
/// stream and must not be locked out by the old one's times.
#[derive(Debug, Clone, Default)]
pub struct Validator {
    clock_s: Option<f64>,
    candidate: Option<Candidate>,
    accepted: u64,
    rejected: [u64; RejectKind::ALL.len()],
}

impl Validator {
    /// A validator for a new source.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Checks the next sample of the source: `Ok` if it may steer the scheduler, else why not.
    /// Either way it is counted.
    ///
    /// # Errors
    /// The [`Rejection`] naming the field, the rule and its limit.
    pub fn check(&mut self, sample: &GazeSample) -> Result<(), Rejection> {
        let verdict = self.verdict(sample);
        match &verdict {
            Ok(()) => self.accepted += 1,
            Err(r) => self.rejected[r.kind.index()] += 1,
        }
        verdict
    }

    fn verdict(&mut self, s: &GazeSample) -> Result<(), Rejection> {
        self.check_time(s.t_s)?;
        let v = s.validity;
        if !(0.0..=1.0).contains(&v) {
            return Err(Rejection::new(
                "validity",
                RejectKind::ValidityOutOfRange,
                format!("{v} is outside [0, 1] (or NaN)"),
            ));
        }
        if v == 0.0 {
            return Err(Rejection::new(
                "validity",
                RejectKind::Missing,
                "is 0: the tracker marks the sample invalid (blink or track loss); not used",
            ));
        }
        for (field, c) in [("x", s.x), ("y", s.y)] {
            if !c.is_finite() {
                return Err(Rejection::new(
                    field,
                    RejectKind::CoordNotFinite,
                    format!("{c} is not finite"),
                ));
            }
            if !(MIN_COORD..=MAX_COORD).contains(&c) {
                return Err(Rejection::new(
                    field,
                    RejectKind::CoordOutOfRange,
                    format!(
                        "{c} is outside [{MIN_COORD}, {MAX_COORD}] (normalised screen units; 0..1 is on screen)"
                    ),
                ));
            }
        }
        Ok(())
    }

    /// The time rules (see the module documentation). A time that passes moves the source's
    /// clock even if the sample fails a later rule: later samples are ordered against it.
    fn check_time(&mut self, t: f64) -> Result<(), Rejection> {
        if !t.is_finite() {
            return Err(Rejection::new(
                "tracker_time_s",
                RejectKind::TimeNotFinite,
                format!("{t} is not finite"),
            ));
        }
        let Some(clock) = self.clock_s else {
            self.clock_s = Some(t);
            return Ok(());
        };
        let fits = |from: f64| t >= from && t - from <= MAX_TIME_JUMP_S;
        if fits(clock) {
            self.clock_s = Some(t);
            self.candidate = None;
            return Ok(());
        }
        let count = match self.candidate {
            Some(c) if fits(c.last_s) => c.count + 1,
            _ => 1,
        };
        if count >= RESYNC_SAMPLES {
            self.clock_s = Some(t);
            self.candidate = None;
            return Ok(());
        }
        self.candidate = Some(Candidate { last_s: t, count });
        Err(if t < clock {
            Rejection::new(
                "tracker_time_s",
                RejectKind::TimeBackwards,
                format!(
                    "decreases from {clock} to {t}: timestamps must not go backwards within a stream or batch \
                     ({RESYNC_SAMPLES} consecutive samples on a new clock are followed)"
                ),
            )
        } else {
            Rejection::new(
                "tracker_time_s",
                RejectKind::TimeJump,
                format!(
                    "jumps forward from {clock} to {t}, more than the limit of {MAX_TIME_JUMP_S} s \
                     ({RESYNC_SAMPLES} consecutive samples on a new clock are followed)"
                ),
            )
        })
    }

    /// Samples accepted so far.
    #[must_use]
    pub fn accepted(&self) -> u64 {
        self.accepted
    }

    /// Samples rejected so far, all kinds.
    #[must_use]
    pub fn rejected(&self) -> u64 {
        self.rejected.iter().sum()
    }

    /// Samples rejected so far for `kind`.
    #[must_use]
    pub fn rejected_for(&self, kind: RejectKind) -> u64 {
        self.rejected[kind.index()]
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;
    use crate::Eye;

    fn s(t: f64, x: f64, y: f64, validity: f32) -> GazeSample {
        GazeSample {
            validity,
            ..GazeSample::valid(t, x, y, Eye::Unspecified)
        }
    }

    fn kind(r: Result<(), Rejection>) -> Option<RejectKind> {
        r.err().map(|r| r.kind)
    }

    #[test]
    fn each_rule_names_its_field_and_is_counted() {
        let mut v = Validator::new();
        assert!(v.check(&s(0.0, 0.5, 0.5, 1.0)).is_ok());
        let r = v.check(&s(f64::NAN, 0.5, 0.5, 1.0)).expect_err("nan time");
        assert_eq!(
            (r.field, r.kind),
            ("tracker_time_s", RejectKind::TimeNotFinite)
        );
        let r = v.check(&s(0.1, f64::NAN, 0.5, 1.0)).expect_err("nan x");
        assert_eq!((r.field, r.kind), ("x", RejectKind::CoordNotFinite));
        let r = v.check(&s(0.2, 0.5, 2.5, 1.0)).expect_err("y off");
        assert_eq!((r.field, r.kind), ("y", RejectKind::CoordOutOfRange));
        assert!(r.reason.contains("[-1, 2]"), "{r}");
        let r = v.check(&s(0.3, 0.5, 0.5, 1.5)).expect_err("validity");
        assert_eq!(
            (r.field, r.kind),
            ("validity", RejectKind::ValidityOutOfRange)
        );
        let r = v.check(&s(0.3, f64::NAN, 0.5, 0.0)).expect_err("blink");
        assert_eq!((r.field, r.kind), ("validity", RejectKind::Missing));
        let r = v.check(&s(0.25, 0.5, 0.5, 1.0)).expect_err("backwards");
        assert_eq!(
            (r.field, r.kind),
            ("tracker_time_s", RejectKind::TimeBackwards)
        );
        assert!(r.reason.contains("decreases from 0.3 to 0.25"), "{r}");
        // Slightly off screen is legal; equal timestamps are fine.
        assert!(v.check(&s(0.3, -0.2, 1.1, 0.5)).is_ok());
        assert!(v.check(&s(0.3, -1.0, 2.0, 1.0)).is_ok());
        assert_eq!((v.accepted(), v.rejected()), (3, 6));
        assert_eq!(v.rejected_for(RejectKind::Missing), 1);
        assert_eq!(v.rejected_for(RejectKind::TimeJump), 0);
    }

    #[test]
    fn one_wild_timestamp_is_rejected_alone() {
        let mut v = Validator::new();
        assert!(v.check(&s(10.0, 0.5, 0.5, 1.0)).is_ok());
        let r = v.check(&s(1e9, 0.5, 0.5, 1.0)).expect_err("wild");
        assert_eq!(r.kind, RejectKind::TimeJump);
        assert!(r.reason.contains("limit of 5 s"), "{r}");
        for i in 1..=100 {
            let t = 10.0 + f64::from(i) * 0.001;
            assert!(v.check(&s(t, 0.5, 0.5, 1.0)).is_ok(), "sample at {t}");
        }
        assert_eq!((v.accepted(), v.rejected()), (101, 1));
    }

    #[test]
    fn two_wild_timestamps_in_a_row_are_not_a_new_clock() {
        let mut v = Validator::new();
        assert!(v.check(&s(10.0, 0.5, 0.5, 1.0)).is_ok());
        assert_eq!(
            kind(v.check(&s(1e9, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeJump)
        );
        assert_eq!(
            kind(v.check(&s(1e9 + 0.001, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeJump)
        );
        assert!(v.check(&s(10.001, 0.5, 0.5, 1.0)).is_ok());
    }

    #[test]
    fn a_real_clock_change_is_followed_after_resync_samples() {
        let mut v = Validator::new();
        assert!(v.check(&s(100.0, 0.5, 0.5, 1.0)).is_ok());
        // The tracker restarted: its clock is back near 0.
        assert_eq!(
            kind(v.check(&s(0.0, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeBackwards)
        );
        assert_eq!(
            kind(v.check(&s(0.001, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeBackwards)
        );
        assert!(v.check(&s(0.002, 0.5, 0.5, 1.0)).is_ok());
        assert!(v.check(&s(0.003, 0.5, 0.5, 1.0)).is_ok());
        // And a pause of a minute likewise.
        assert_eq!(
            kind(v.check(&s(60.0, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeJump)
        );
        assert_eq!(
            kind(v.check(&s(60.1, 0.5, 0.5, 1.0))),
            Some(RejectKind::TimeJump)
        );
        assert!(v.check(&s(60.2, 0.5, 0.5, 1.0)).is_ok());
        assert_eq!(v.rejected(), 4);
    }

    proptest! {
        /// Whatever garbage precedes it, a run of good samples on one clock is accepted after at
        /// most `RESYNC_SAMPLES - 1` of them: no input locks a source out.
        #[test]
        fn no_timestamp_locks_a_source_out(
            garbage in proptest::collection::vec(prop_oneof![
                any::<f64>(),
                -1e12f64..1e12,
                Just(f64::NAN),
                Just(f64::INFINITY),
            ], 0..20),
            start in -1e6f64..1e6,
        ) {
            let mut v = Validator::new();
            for t in garbage {
                let _ = v.check(&s(t, 0.5, 0.5, 1.0));
            }
            let results: Vec<bool> = (0..20)
                .map(|i| v.check(&s(start + f64::from(i) * 0.01, 0.5, 0.5, 1.0)).is_ok())
                .collect();
            let skip = (RESYNC_SAMPLES - 1) as usize;
            prop_assert!(results[skip..].iter().all(|ok| *ok), "{results:?}");
        }
    }
}
