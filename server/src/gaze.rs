//! Validation of incoming gaze samples, shared by StreamGaze and PushGaze.
//!
//! Trackers send garbage in ordinary operation (NaN during blinks, wild values on track loss), so a
//! bad sample is rejected on its own with a reason naming the field, counted, and the samples
//! around it are kept. Only samples that pass every check can become the fixation.

use foveal_proto::pb;

/// Largest PushGaze batch (samples). A 1 kHz tracker produces this in 10 s; anything larger is a
/// client that should be streaming, and it keeps one call's decoding and locking bounded.
pub const MAX_BATCH_SAMPLES: usize = 10_000;
/// Smallest accepted gaze coordinate (normalised screen units). Fixations slightly off screen are
/// real (a viewer glancing at the bezel) and legal; a whole screen beyond the edge is a broken
/// calibration or a unit mistake (pixels sent as normalised), so it is rejected.
pub const MIN_COORD: f64 = -1.0;
/// Largest accepted gaze coordinate (normalised screen units); see [`MIN_COORD`].
pub const MAX_COORD: f64 = 2.0;
/// How many rejections a response lists; the counts stay exact past it.
pub const MAX_LISTED_REJECTIONS: usize = 32;

/// A sample that passed validation and can become the fixation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GazePoint {
    /// Normalised horizontal position.
    pub x: f64,
    /// Normalised vertical position.
    pub y: f64,
    /// Tracker time (seconds, the tracker's clock).
    pub tracker_time_s: f64,
}

/// Why a sample was not used.
#[derive(Debug, Clone, PartialEq)]
pub struct Rejection {
    /// The offending field of `GazeSample`.
    pub field: &'static str,
    /// What was wrong with it.
    pub reason: String,
}

impl Rejection {
    fn new(field: &'static str, reason: impl Into<String>) -> Self {
        Self {
            field,
            reason: reason.into(),
        }
    }
}

/// Validates one source of samples (one stream or one batch) in order, and tallies the outcome.
///
/// Timestamps must not decrease *within* the source: each stream or batch may start its own tracker
/// clock (a bridge reconnecting after the tracker restarted must not be locked out).
#[derive(Debug, Default)]
pub struct GazeValidator {
    next_index: u64,
    last_time_s: Option<f64>,
    accepted: u64,
    rejected: u64,
    rejections: Vec<pb::SampleRejection>,
    last_accepted_time_s: f64,
}

impl GazeValidator {
    /// A validator for a new stream or batch.
    pub fn new() -> Self {
        Self::default()
    }

    /// Check the next sample of the source: `Ok` with the point to use, or the rejection (already
    /// counted and, for the first [`MAX_LISTED_REJECTIONS`], listed).
    pub fn check(&mut self, sample: &pb::GazeSample) -> Result<GazePoint, Rejection> {
        let index = self.next_index;
        self.next_index += 1;
        match self.verdict(sample) {
            Ok(point) => {
                self.accepted += 1;
                self.last_accepted_time_s = point.tracker_time_s;
                Ok(point)
            }
            Err(rejection) => {
                self.rejected += 1;
                if self.rejections.len() < MAX_LISTED_REJECTIONS {
                    self.rejections.push(pb::SampleRejection {
                        index,
                        field: rejection.field.to_owned(),
                        reason: rejection.reason.clone(),
                    });
                }
                Err(rejection)
            }
        }
    }

    fn verdict(&mut self, s: &pb::GazeSample) -> Result<GazePoint, Rejection> {
        let t = s.tracker_time_s;
        if !t.is_finite() {
            return Err(Rejection::new(
                "tracker_time_s",
                format!("{t} is not finite"),
            ));
        }
        if let Some(last) = self.last_time_s.filter(|&last| t < last) {
            return Err(Rejection::new(
                "tracker_time_s",
                format!(
                    "decreases from {last} to {t}: timestamps must not go backwards within a stream or batch"
                ),
            ));
        }
        // The time is good: later samples are ordered against it even if this one fails below.
        self.last_time_s = Some(t);
        let v = s.validity;
        if !(0.0..=1.0).contains(&v) {
            return Err(Rejection::new(
                "validity",
                format!("{v} is outside [0, 1] (or NaN)"),
            ));
        }
        if v == 0.0 {
            return Err(Rejection::new(
                "validity",
                "is 0: the tracker marks the sample invalid (blink or track loss); not used",
            ));
        }
        for (field, c) in [("x", s.x), ("y", s.y)] {
            if !c.is_finite() {
                return Err(Rejection::new(field, format!("{c} is not finite")));
            }
            if !(MIN_COORD..=MAX_COORD).contains(&c) {
                return Err(Rejection::new(
                    field,
                    format!(
                        "{c} is outside [{MIN_COORD}, {MAX_COORD}] (normalised screen units; 0..1 is on screen)"
                    ),
                ));
            }
        }
        Ok(GazePoint {
            x: s.x,
            y: s.y,
            tracker_time_s: t,
        })
    }

    /// Pass over the next sample without looking at it (dropped by the rate limit), so that later
    /// rejections keep their index in the stream.
    pub fn skip(&mut self) {
        self.next_index += 1;
    }

    /// Samples accepted so far.
    pub fn accepted(&self) -> u64 {
        self.accepted
    }

    /// Samples rejected so far.
    pub fn rejected(&self) -> u64 {
        self.rejected
    }

    /// The summary StreamGaze answers with.
    pub fn into_summary(self) -> pb::StreamGazeSummary {
        pb::StreamGazeSummary {
            accepted: self.accepted,
            rejected: self.rejected,
            rejections: self.rejections,
            last_accepted_time_s: self.last_accepted_time_s,
            rate_limited: 0,
        }
    }

    /// The response PushGaze answers with.
    pub fn into_push_response(self) -> pb::PushGazeResponse {
        pb::PushGazeResponse {
            accepted: self.accepted,
            rejected: self.rejected,
            rejections: self.rejections,
            last_accepted_time_s: self.last_accepted_time_s,
            rate_limited: 0,
        }
    }
}

/// Check a PushGaze batch's size before any sample is looked at: nothing of a refused batch is
/// applied. The message names the field and the limit.
pub fn check_batch_size(len: usize) -> Result<(), String> {
    if len == 0 {
        Err(format!(
            "`samples` is empty: send 1..={MAX_BATCH_SAMPLES} samples per PushGaze call"
        ))
    } else if len > MAX_BATCH_SAMPLES {
        Err(format!(
            "`samples` has {len} samples, more than the limit of {MAX_BATCH_SAMPLES} per PushGaze call: split the batch or use StreamGaze"
        ))
    } else {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(t: f64, x: f64, y: f64, validity: f32) -> pb::GazeSample {
        pb::GazeSample {
            tracker_time_s: t,
            x,
            y,
            validity,
            ..Default::default()
        }
    }

    fn field(r: Result<GazePoint, Rejection>) -> Option<&'static str> {
        r.err().map(|r| r.field)
    }

    #[test]
    fn good_samples_around_bad_ones_are_kept_and_fields_named() {
        let mut v = GazeValidator::new();
        assert!(v.check(&s(0.0, 0.5, 0.5, 1.0)).is_ok());
        assert_eq!(
            field(v.check(&s(f64::NAN, 0.5, 0.5, 1.0))),
            Some("tracker_time_s")
        );
        assert_eq!(field(v.check(&s(0.1, f64::NAN, 0.5, 1.0))), Some("x"));
        assert_eq!(field(v.check(&s(0.2, 0.5, 2.5, 1.0))), Some("y"));
        assert_eq!(
            field(v.check(&s(0.3, 0.5, 0.5, f32::NAN))),
            Some("validity")
        );
        assert_eq!(field(v.check(&s(0.3, 0.5, 0.5, 1.5))), Some("validity"));
        assert_eq!(
            field(v.check(&s(0.3, f64::NAN, 0.5, 0.0))),
            Some("validity")
        );
        assert_eq!(
            field(v.check(&s(0.25, 0.5, 0.5, 1.0))),
            Some("tracker_time_s")
        );
        // Slightly off screen is legal; equal timestamps are fine.
        assert!(v.check(&s(0.3, -0.2, 1.1, 0.5)).is_ok());
        assert!(v.check(&s(0.3, -1.0, 2.0, 1.0)).is_ok());
        let sum = v.into_summary();
        assert_eq!((sum.accepted, sum.rejected), (3, 7));
        assert_eq!(sum.rejections.len(), 7);
        assert_eq!(sum.rejections[0].index, 1);
        assert_eq!(sum.rejections[6].field, "tracker_time_s");
        assert!(
            sum.rejections[6].reason.contains("decreases"),
            "{:?}",
            sum.rejections[6]
        );
        assert_eq!(sum.last_accepted_time_s, 0.3);
    }

    #[test]
    fn listed_rejections_are_capped_but_counts_exact() {
        let mut v = GazeValidator::new();
        for i in 0..100 {
            let _ = v.check(&s(f64::from(i), 9.0, 0.5, 1.0));
        }
        let sum = v.into_push_response();
        assert_eq!(sum.rejected, 100);
        assert_eq!(sum.rejections.len(), MAX_LISTED_REJECTIONS);
    }

    #[test]
    fn batch_size_limits_name_the_field_and_limit() {
        assert!(check_batch_size(1).is_ok());
        assert!(check_batch_size(MAX_BATCH_SAMPLES).is_ok());
        let e = check_batch_size(MAX_BATCH_SAMPLES + 1).expect_err("oversize");
        assert!(e.contains("`samples`") && e.contains("10000"), "{e}");
        assert!(
            check_batch_size(0)
                .expect_err("empty")
                .contains("`samples`")
        );
    }
}
