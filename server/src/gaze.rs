//! Validation of incoming gaze samples, shared by StreamGaze and PushGaze.
//!
//! The rules themselves (fields, ranges, the timestamp-jump limit) live in
//! [`foveal_gaze::validate`], so that a bridge, a test and the server agree on them; this module
//! maps the protocol's samples onto them and keeps the per-call tally the rpcs answer with. A bad
//! sample is rejected on its own with a reason naming the field, counted, and the samples around
//! it are kept. Only samples that pass every check can become the fixation.

#[cfg(test)]
use foveal_gaze::validate::RejectKind;
use foveal_gaze::validate::Validator;
use foveal_gaze::{Eye, GazeSample};
use foveal_proto::pb;

/// Largest PushGaze batch (samples). A 1 kHz tracker produces this in 10 s; anything larger is a
/// client that should be streaming, and it keeps one call's decoding and locking bounded.
pub const MAX_BATCH_SAMPLES: usize = 10_000;
/// Longest `PushGazeRequest.source` (bytes of UTF-8): a name for logs, the status and a
/// recorded session, which copy it with every sample.
pub const MAX_SOURCE_BYTES: usize = 64;
/// How many rejections a response lists; the counts stay exact past it.
pub const MAX_LISTED_REJECTIONS: usize = 32;

/// Why a sample was not used (the field, the rule, the message).
pub type Rejection = foveal_gaze::validate::Rejection;

/// A protocol sample as the gaze crate's sample; an unknown eye value is [`Eye::Unspecified`].
#[must_use]
pub fn from_pb(s: &pb::GazeSample) -> GazeSample {
    let eye = match pb::Eye::try_from(s.eye) {
        Ok(pb::Eye::Left) => Eye::Left,
        Ok(pb::Eye::Right) => Eye::Right,
        Ok(pb::Eye::Binocular) => Eye::Binocular,
        Ok(pb::Eye::Unspecified) | Err(_) => Eye::Unspecified,
    };
    GazeSample {
        t_s: s.tracker_time_s,
        x: s.x,
        y: s.y,
        validity: s.validity,
        eye,
        fixation: s.fixation,
    }
}

/// Validates one source of samples (one stream or one batch) in order, and tallies the outcome
/// for the rpc's answer (see [`foveal_gaze::validate`] for the rules, the time ones included).
#[derive(Debug, Default)]
pub struct GazeValidator {
    next_index: u64,
    rules: Validator,
    rejections: Vec<pb::SampleRejection>,
    last_accepted_time_s: f64,
}

impl GazeValidator {
    /// A validator for a new stream or batch.
    pub fn new() -> Self {
        Self::default()
    }

    /// Check the next sample of the source (converted once, at the rpc, by [`from_pb`]): `Ok`
    /// when it can become the fixation, or the rejection (already counted and, for the first
    /// [`MAX_LISTED_REJECTIONS`], listed).
    pub fn check(&mut self, sample: &GazeSample) -> Result<(), Rejection> {
        let index = self.next_index;
        self.next_index += 1;
        match self.rules.check(sample) {
            Ok(()) => {
                self.last_accepted_time_s = sample.t_s;
                Ok(())
            }
            Err(rejection) => {
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

    #[cfg(test)]
    /// Samples rejected so far for one rule.
    pub fn rejected_for(&self, kind: RejectKind) -> u64 {
        self.rules.rejected_for(kind)
    }

    /// Pass over the next sample without looking at it (dropped by the rate limit), so that later
    /// rejections keep their index in the stream.
    pub fn skip(&mut self) {
        self.next_index += 1;
    }

    /// Samples accepted so far.
    pub fn accepted(&self) -> u64 {
        self.rules.accepted()
    }

    /// Samples rejected so far.
    pub fn rejected(&self) -> u64 {
        self.rules.rejected()
    }

    /// The summary StreamGaze answers with.
    pub fn into_summary(self) -> pb::StreamGazeSummary {
        pb::StreamGazeSummary {
            accepted: self.rules.accepted(),
            rejected: self.rules.rejected(),
            rejections: self.rejections,
            last_accepted_time_s: self.last_accepted_time_s,
            rate_limited: 0,
        }
    }

    /// The response PushGaze answers with.
    pub fn into_push_response(self) -> pb::PushGazeResponse {
        pb::PushGazeResponse {
            accepted: self.rules.accepted(),
            rejected: self.rules.rejected(),
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

/// Check a PushGaze `source` before anything of its batch is used: at most
/// [`MAX_SOURCE_BYTES`] bytes of printable text (a name is logged, kept per source and written
/// with every recorded sample, so an unbounded one would be copied a thousand times a batch).
/// The message names the field and the limit, and never quotes the string.
pub fn check_source(source: &str) -> Result<(), String> {
    if source.len() > MAX_SOURCE_BYTES {
        return Err(format!(
            "`source` is {} bytes long, more than the limit of {MAX_SOURCE_BYTES}: send a short printable name of the sender (e.g. \"eyelink-bridge\")",
            source.len()
        ));
    }
    if let Some((at, _)) = source.char_indices().find(|(_, c)| c.is_control()) {
        return Err(format!(
            "`source` has a control character at byte {at}: send at most {MAX_SOURCE_BYTES} bytes of printable text"
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(t: f64, x: f64, y: f64, validity: f32) -> GazeSample {
        from_pb(&pb::GazeSample {
            tracker_time_s: t,
            x,
            y,
            validity,
            ..Default::default()
        })
    }

    fn field(r: Result<(), Rejection>) -> Option<&'static str> {
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
    fn a_wild_timestamp_does_not_block_the_stream() {
        let mut v = GazeValidator::new();
        assert!(v.check(&s(10.0, 0.5, 0.5, 1.0)).is_ok());
        assert_eq!(
            field(v.check(&s(1e9, 0.5, 0.5, 1.0))),
            Some("tracker_time_s")
        );
        assert!(v.check(&s(10.001, 0.5, 0.5, 1.0)).is_ok());
        assert_eq!(v.rejected_for(RejectKind::TimeJump), 1);
        let sum = v.into_summary();
        assert_eq!((sum.accepted, sum.rejected), (2, 1));
        assert_eq!(sum.rejections[0].index, 1);
        assert_eq!(sum.last_accepted_time_s, 10.001);
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
    fn sources_are_short_printable_names() {
        assert!(check_source("").is_ok());
        assert!(check_source("viewer:mouse").is_ok());
        assert!(check_source("Blickverfolgung-äöü").is_ok());
        assert!(check_source(&"x".repeat(MAX_SOURCE_BYTES)).is_ok());
        let e = check_source(&"x".repeat(256 << 10)).expect_err("long");
        assert!(
            e.contains("`source`") && e.contains("64") && e.contains("262144"),
            "{e}"
        );
        assert!(!e.contains("xxxx"), "the string is not quoted: {e}");
        let e = check_source("a\nb").expect_err("control");
        assert!(e.contains("`source`") && e.contains("byte 1"), "{e}");
        assert!(check_source("\u{1b}[31mred").is_err());
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
