//! Pupil Core gaze datums (Pupil Capture and Pupil Service network API) as [`GazeSample`]s.
//!
//! Pupil publishes gaze on topics such as `gaze.3d.0.` (eye 0 only), `gaze.3d.1.` (eye 1 only)
//! and `gaze.3d.01.` (both eyes mapped together; `gaze.2d.*` for the 2D pipeline). Pupil numbers
//! its eye cameras from the wearer's point of view: eye 0 is the **right** eye, eye 1 the
//! **left**. A datum is a msgpack dict, decoded here ([`decode_payload`]) from the bytes the
//! caller received, so the network side only moves bytes.
//!
//! Mapping to [`GazeSample`]:
//! - `norm_pos` `[x, y]` is normalised with the origin at the **bottom**-left; foveal's origin is
//!   the top-left, so `y` becomes `1 - y`. Unless the datum was mapped onto a surface
//!   (`surfaces.NAME` topics, `gaze_on_surfaces`), `norm_pos` is in the *world camera's* image,
//!   which is the display only if the camera sees nothing but the display; use a surface marked
//!   on the display's corners for display coordinates.
//! - `confidence` below the threshold ([`DEFAULT_MIN_CONFIDENCE`] unless the caller says) makes
//!   a missing sample (validity 0), kept in the stream so that the gap stays visible; at or above
//!   it, the confidence is the validity.
//! - `timestamp` (seconds on the Pupil clock, see Pupil Remote's `t` command) is the tracker
//!   time, unchanged.
//! - the eye comes from the topic; a topic that does not say (older versions publish plain
//!   `gaze`) falls back to the eyes of `base_data`.

use rmpv::Value;

use super::{Eye, GazeSample};

/// A field of a datum that did not decode, and why.
pub type DecodeError = (&'static str, String);

/// The gaze datums of one message's msgpack `payload` on `topic`: one for a gaze datum, one per
/// `gaze_on_surfaces` entry when `surface` is set, each decoded or naming its bad field.
///
/// # Errors
/// The payload is not msgpack, or (with `surface`) has no `gaze_on_surfaces` list.
pub fn decode_payload(
    payload: &[u8],
    topic: &str,
    surface: bool,
) -> Result<Vec<Result<PupilGaze, DecodeError>>, DecodeError> {
    let value = rmpv::decode::read_value(&mut &payload[..])
        .map_err(|err| ("payload", format!("is not msgpack: {err}")))?;
    if surface {
        match field(&value, "gaze_on_surfaces") {
            Some(Value::Array(entries)) => Ok(entries
                .iter()
                .map(|entry| decode_gaze(entry, topic))
                .collect()),
            _ => Err((
                "gaze_on_surfaces",
                "is missing or not a list (is the surface tracker running?)".into(),
            )),
        }
    } else {
        Ok(vec![decode_gaze(&value, topic)])
    }
}

/// Confidence below which Pupil Labs advise discarding a datum (their documentation: "data with
/// confidence below 0.6 should be discarded").
pub const DEFAULT_MIN_CONFIDENCE: f64 = 0.6;

/// Port Pupil Remote listens on by default.
pub const DEFAULT_REMOTE_PORT: u16 = 50020;

/// The fields of one Pupil gaze datum that make a sample.
#[derive(Debug, Clone, PartialEq)]
pub struct PupilGaze {
    /// The datum's `topic`, e.g. `gaze.3d.01.` or `gaze.3d.1._on_surface`.
    pub topic: String,
    /// `norm_pos`: normalised position, origin bottom-left.
    pub norm_pos: [f64; 2],
    /// `confidence`, 0..1.
    pub confidence: f64,
    /// `timestamp`: seconds on the Pupil clock.
    pub timestamp: f64,
    /// Eye ids (`id`: 0 or 1) of the pupil datums in `base_data`, when present.
    pub base_eyes: Vec<u8>,
}

/// Which eye a Pupil eye id is: 0 is the right eye, 1 the left.
#[must_use]
pub fn eye_of_id(id: u8) -> Eye {
    match id {
        0 => Eye::Right,
        1 => Eye::Left,
        _ => Eye::Unspecified,
    }
}

/// The eye a gaze topic names: the `0`, `1` or `01` segment after `2d`/`3d` (`gaze.3d.0.`,
/// `gaze.2d.01.`, `gaze.3d.1._on_surface`); `None` when the topic does not say.
#[must_use]
pub fn eye_of_topic(topic: &str) -> Option<Eye> {
    let mut segments = topic.split('.');
    if segments.next() != Some("gaze") {
        return None;
    }
    let mut segments = segments.skip_while(|s| *s == "2d" || *s == "3d");
    match segments.next()? {
        "0" => Some(Eye::Right),
        "1" => Some(Eye::Left),
        "01" | "10" => Some(Eye::Binocular),
        _ => None,
    }
}

impl PupilGaze {
    /// The datum's eye: from the topic, else from `base_data` (one datum of one eye, or two).
    #[must_use]
    pub fn eye(&self) -> Eye {
        if let Some(eye) = eye_of_topic(&self.topic) {
            return eye;
        }
        match self.base_eyes.as_slice() {
            [id] => eye_of_id(*id),
            [a, b] if a != b => Eye::Binocular,
            _ => Eye::Unspecified,
        }
    }

    /// Whether the confidence is below `min_confidence` (the datum becomes a missing sample).
    #[must_use]
    pub fn is_low_confidence(&self, min_confidence: f64) -> bool {
        // NaN confidence is no confidence.
        self.confidence.is_nan() || self.confidence < min_confidence
    }

    /// The sample: y flipped to the top-left origin, validity = confidence, or a missing sample
    /// when the confidence is below `min_confidence`.
    #[must_use]
    pub fn to_sample(&self, min_confidence: f64) -> GazeSample {
        let eye = self.eye();
        if self.is_low_confidence(min_confidence) || self.confidence <= 0.0 {
            return GazeSample::missing(self.timestamp, eye);
        }
        let [x, y] = self.norm_pos;
        GazeSample {
            t_s: self.timestamp,
            x,
            y: 1.0 - y,
            validity: self.confidence.min(1.0) as f32,
            eye,
            fixation: None,
        }
    }
}

/// The value of `key` in a msgpack map.
fn field<'a>(map: &'a Value, key: &str) -> Option<&'a Value> {
    map.as_map()?
        .iter()
        .find(|(k, _)| k.as_str() == Some(key))
        .map(|(_, v)| v)
}

fn number(value: &Value) -> Option<f64> {
    value
        .as_f64()
        .or_else(|| value.as_i64().map(|v| v as f64))
        .or_else(|| value.as_u64().map(|v| v as f64))
}

/// One gaze datum (a gaze message or a `gaze_on_surfaces` entry); `topic` is the message's,
/// used when the datum has none of its own.
fn decode_gaze(datum: &Value, topic: &str) -> Result<PupilGaze, DecodeError> {
    if datum.as_map().is_none() {
        return Err(("datum", "is not a map".into()));
    }
    let num = |key: &'static str| {
        let value = field(datum, key).ok_or((key, "is missing".to_owned()))?;
        number(value).ok_or((key, format!("{value} is not a number")))
    };
    let norm_pos = match field(datum, "norm_pos").and_then(Value::as_array) {
        Some(pair) if pair.len() == 2 => match (number(&pair[0]), number(&pair[1])) {
            (Some(x), Some(y)) => [x, y],
            _ => return Err(("norm_pos", "holds a value that is not a number".into())),
        },
        _ => return Err(("norm_pos", "is missing or not an [x, y] pair".into())),
    };
    let topic = field(datum, "topic")
        .and_then(Value::as_str)
        .unwrap_or(topic)
        .to_owned();
    // Pupil datums in base_data carry their eye as `id`; surface entries hold [topic, time]
    // pairs there instead, which say nothing more than the topic.
    let base_eyes = field(datum, "base_data")
        .and_then(Value::as_array)
        .map(|base| {
            base.iter()
                .filter_map(|b| field(b, "id").and_then(Value::as_u64))
                .filter_map(|id| u8::try_from(id).ok())
                .collect()
        })
        .unwrap_or_default();
    Ok(PupilGaze {
        topic,
        norm_pos,
        confidence: num("confidence")?,
        timestamp: num("timestamp")?,
        base_eyes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn datum(topic: &str, confidence: f64) -> PupilGaze {
        PupilGaze {
            topic: topic.into(),
            norm_pos: [0.25, 0.2],
            confidence,
            timestamp: 1234.5,
            base_eyes: Vec::new(),
        }
    }

    #[test]
    fn topics_name_the_eye_with_eye0_the_right_one() {
        assert_eq!(eye_of_topic("gaze.3d.0."), Some(Eye::Right));
        assert_eq!(eye_of_topic("gaze.3d.1."), Some(Eye::Left));
        assert_eq!(eye_of_topic("gaze.2d.01."), Some(Eye::Binocular));
        assert_eq!(eye_of_topic("gaze.3d.1._on_surface"), Some(Eye::Left));
        assert_eq!(eye_of_topic("gaze"), None);
        assert_eq!(eye_of_topic("pupil.0.3d"), None);
    }

    #[test]
    fn base_data_decides_when_the_topic_does_not() {
        let mut d = datum("gaze", 0.9);
        d.base_eyes = vec![0, 1];
        assert_eq!(d.eye(), Eye::Binocular);
        d.base_eyes = vec![1];
        assert_eq!(d.eye(), Eye::Left);
        d.base_eyes.clear();
        assert_eq!(d.eye(), Eye::Unspecified);
    }

    #[test]
    fn y_is_flipped_and_confidence_is_the_validity() {
        let s = datum("gaze.3d.01.", 0.95).to_sample(DEFAULT_MIN_CONFIDENCE);
        assert_eq!((s.x, s.y, s.t_s), (0.25, 0.8, 1234.5));
        assert!((f64::from(s.validity) - 0.95).abs() < 1e-6);
        assert_eq!(s.eye, Eye::Binocular);
    }

    #[test]
    fn low_confidence_is_a_missing_sample_at_its_time() {
        let d = datum("gaze.3d.0.", 0.59);
        assert!(d.is_low_confidence(DEFAULT_MIN_CONFIDENCE));
        let s = d.to_sample(DEFAULT_MIN_CONFIDENCE);
        assert!(!s.is_valid());
        assert_eq!((s.t_s, s.eye), (1234.5, Eye::Right));
        assert!(datum("gaze", f64::NAN).is_low_confidence(0.0));
        assert!(datum("gaze", 0.6).to_sample(0.6).is_valid());
    }
}
