//! # foveal-gaze
//!
//! The one home of gaze in foveal: the sample type, every parser of recordings and tracker
//! protocols, the validation the server applies, online filtering and fixation detection, the
//! seeded generator and the scripted viewer. The client, the server, the study and the fuzz
//! targets all use this crate, so a rule (or a threshold) lives in one place.
//!
//! Everything here is pure and synchronous: parsers take lines (or any [`BufRead`]) and give
//! [`GazeSample`]s; networking and timing live with the callers.
//!
//! # Layout
//! - [`GazeSample`], [`Eye`], [`ScreenPx`]: the common sample type (screen coordinates normalised
//!   to 0..1, origin top-left, x right, y down; times in seconds) and pixel-to-normalised
//!   conversion.
//! - [`ParseError`]: the one error type of every parser; each error names its 1-based line
//!   number and, where there is one, the field.
//! - [`csv`]: CSV recordings, in screen pixels (`t_s,xpos,ypos,ps`, or binocular
//!   `xpos_left,xpos_right,...`) or normalised (`t_s,x,y[,validity][,fixation]`), and a writer.
//! - [`asc`]: EyeLink ASC files, monocular and binocular (samples, `SFIX`/`EFIX` events,
//!   display coordinates).
//! - [`opengaze`]: the Gazepoint Open Gaze API (XML lines over TCP): handshake commands and a
//!   record parser.
//! - [`pupil`]: Pupil Core gaze datums (network API): topics, eyes, confidence, the y flip.
//! - [`lsl`]: the Lab Streaming Layer wire protocol (resolve, stream feed, samples, clock
//!   probes) and the mapping of channels to gaze.
//! - [`validate`]: the rules a sample must pass before it can steer the scheduler, including
//!   the limit on timestamp jumps.
//! - [`geometry`]: normalised screen points as gaze directions in degrees of visual angle.
//! - [`filter`]: the 1€ filter. [`detect`]: online I-VT and I-DT fixation detection.
//! - [`clock`]: per-source clock offset, so a sample's age includes its delay on the way.
//! - [`online`]: the server's per-source processing: eyes combined, filter, detector, track loss.
//! - [`fixation_list`]: fixation lists as CSV (`eye,start_s,end_s,x_px,y_px`).
//! - [`agreement`]: event-level agreement of two fixation lists (Hooge et al. 2018).
//! - [`rng`], [`viewer`]: the one seeded generator and the one scripted viewer.
//! - [`script`]: deterministic scripted gaze at a rate: fixed point, circle, the viewer's saccades.

use std::io::{self, BufRead};

use thiserror::Error;

pub mod agreement;
pub mod asc;
pub mod clock;
pub mod csv;
pub mod detect;
pub mod filter;
pub mod fixation_list;
pub mod geometry;
pub mod lsl;
pub mod online;
pub mod opengaze;
pub mod pupil;
pub mod quantile;
pub mod rng;
pub mod script;
pub mod validate;
pub mod viewer;

#[cfg(test)]
mod recording_tests;

/// Which eye a sample is for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Eye {
    /// Not said by the source.
    #[default]
    Unspecified,
    /// Left eye only.
    Left,
    /// Right eye only.
    Right,
    /// Both eyes combined (average or the tracker's cyclopean estimate).
    Binocular,
}

/// One gaze sample.
///
/// `x` and `y` are normalised to the screen: 0..1, origin at the top-left, x right, y down;
/// values outside 0..1 are off-screen gaze and kept as they are. A sample with `validity == 0`
/// is a missing sample (blink, track loss): it is kept in the stream so that gaps stay visible,
/// and its `x` and `y` are 0 and mean nothing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GazeSample {
    /// Seconds on the source's clock (any origin).
    pub t_s: f64,
    /// Horizontal position, fraction of the screen width from the left edge.
    pub x: f64,
    /// Vertical position, fraction of the screen height from the top edge.
    pub y: f64,
    /// Confidence 0..1; 0 = invalid.
    pub validity: f32,
    /// Which eye.
    pub eye: Eye,
    /// The source's own fixation flag (true in a fixation, false in a saccade), if it has one.
    pub fixation: Option<bool>,
}

impl GazeSample {
    /// A fully valid sample with no fixation flag.
    #[must_use]
    pub fn valid(t_s: f64, x: f64, y: f64, eye: Eye) -> Self {
        Self {
            t_s,
            x,
            y,
            validity: 1.0,
            eye,
            fixation: None,
        }
    }

    /// A missing sample (blink, track loss): validity 0, position 0, no fixation flag.
    #[must_use]
    pub fn missing(t_s: f64, eye: Eye) -> Self {
        Self {
            t_s,
            x: 0.0,
            y: 0.0,
            validity: 0.0,
            eye,
            fixation: None,
        }
    }

    /// The sample of one eye's reading at `t_s`: its position, or a missing sample when the eye
    /// gave none; the tracker's fixation flag either way.
    #[must_use]
    pub fn from_reading(t_s: f64, reading: EyeReading, eye: Eye, fixation: Option<bool>) -> Self {
        match reading {
            Some((x, y, validity)) => Self {
                t_s,
                x,
                y,
                validity,
                eye,
                fixation,
            },
            None => Self::missing(t_s, eye).with_fixation(fixation),
        }
    }

    /// Whether the sample carries a position (`validity > 0`).
    #[must_use]
    pub fn is_valid(&self) -> bool {
        self.validity > 0.0
    }

    /// The same sample with its fixation flag replaced.
    #[must_use]
    pub fn with_fixation(self, fixation: Option<bool>) -> Self {
        Self { fixation, ..self }
    }
}

/// One eye's reading at one instant: normalised (x, y) and validity, or `None` when the eye was
/// not tracked (blink, track loss).
pub type EyeReading = Option<(f64, f64, f32)>;

/// How a binocular recording becomes samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Binocular {
    /// One [`Eye::Binocular`] sample: the mean of the valid eyes (the one valid eye alone when the
    /// other is missing), missing when neither is valid. The usual choice: averaging halves the
    /// variance of uncorrelated noise, and a one-eyed blink does not lose the sample.
    #[default]
    Mean,
    /// One [`Eye::Left`] sample: the left eye only.
    Left,
    /// One [`Eye::Right`] sample: the right eye only.
    Right,
    /// Two samples per instant, left then right, each tagged with its eye: the receiver combines
    /// them (the server does, online).
    Both,
}

impl Binocular {
    /// The sample(s) of one binocular instant: the first always, the second only for
    /// [`Binocular::Both`]. `fixation` is the source's flag, copied to each.
    #[must_use]
    pub fn samples(
        self,
        t_s: f64,
        left: EyeReading,
        right: EyeReading,
        fixation: Option<bool>,
    ) -> (GazeSample, Option<GazeSample>) {
        let one = |reading: EyeReading, eye| GazeSample::from_reading(t_s, reading, eye, fixation);
        match self {
            Self::Mean => {
                let mean = match (left, right) {
                    (Some((xl, yl, vl)), Some((xr, yr, vr))) => {
                        Some(((xl + xr) / 2.0, (yl + yr) / 2.0, f32::midpoint(vl, vr)))
                    }
                    (one, None) | (None, one) => one,
                };
                (one(mean, Eye::Binocular), None)
            }
            Self::Left => (one(left, Eye::Left), None),
            Self::Right => (one(right, Eye::Right), None),
            Self::Both => (one(left, Eye::Left), Some(one(right, Eye::Right))),
        }
    }
}

/// Screen size in pixels, for converting pixel gaze to normalised coordinates.
///
/// `origin_x`/`origin_y` is the pixel coordinate of the top-left corner (EyeLink's
/// `DISPLAY_COORDS` may start elsewhere than 0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ScreenPx {
    /// Width, pixels (> 0).
    pub width: f64,
    /// Height, pixels (> 0).
    pub height: f64,
    /// Pixel x of the left edge.
    pub origin_x: f64,
    /// Pixel y of the top edge.
    pub origin_y: f64,
}

impl ScreenPx {
    /// A screen `width` x `height` pixels with its origin at pixel (0, 0); `None` unless both
    /// sides are finite and positive.
    #[must_use]
    pub fn new(width: f64, height: f64) -> Option<Self> {
        let ok = width.is_finite() && height.is_finite() && width > 0.0 && height > 0.0;
        ok.then_some(Self {
            width,
            height,
            origin_x: 0.0,
            origin_y: 0.0,
        })
    }

    /// A screen from the pixel coordinates of its first and last pixel, inclusive, as in
    /// EyeLink's `DISPLAY_COORDS 0 0 1919 1079`; `None` unless the result has positive size.
    #[must_use]
    pub fn from_corners(left: f64, top: f64, right: f64, bottom: f64) -> Option<Self> {
        let width = right - left + 1.0;
        let height = bottom - top + 1.0;
        let ok =
            [left, top, width, height].iter().all(|v| v.is_finite()) && width > 0.0 && height > 0.0;
        ok.then_some(Self {
            width,
            height,
            origin_x: left,
            origin_y: top,
        })
    }

    /// Normalised (x, y) of a pixel position.
    #[must_use]
    pub fn normalise(&self, x_px: f64, y_px: f64) -> (f64, f64) {
        (
            (x_px - self.origin_x) / self.width,
            (y_px - self.origin_y) / self.height,
        )
    }
}

/// An error from one of the gaze parsers. Every variant names the 1-based line number of the
/// input, and all but [`ParseError::Io`] the field at fault.
#[derive(Debug, Error)]
pub enum ParseError {
    /// Reading the input failed; parsing stops.
    #[error("line {line}: cannot read input: {source}")]
    Io {
        /// Line being read.
        line: usize,
        /// The I/O error.
        #[source]
        source: io::Error,
    },
    /// A required field is absent.
    #[error("line {line}: field `{field}` is missing")]
    MissingField {
        /// Line number.
        line: usize,
        /// Field name.
        field: &'static str,
    },
    /// A field that must be a number is not one.
    #[error("line {line}: field `{field}`: {value:?} is not a number")]
    InvalidNumber {
        /// Line number.
        line: usize,
        /// Field name.
        field: &'static str,
        /// The offending text (shortened if long).
        value: String,
    },
    /// A field parses but its value is not allowed.
    #[error("line {line}: field `{field}`: {value:?} {reason}")]
    InvalidValue {
        /// Line number.
        line: usize,
        /// Field name.
        field: &'static str,
        /// The offending text (shortened if long).
        value: String,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// Gaze is in pixels but no screen size was given or found in the input.
    #[error(
        "line {line}: field `{field}`: gaze is in pixels but the screen size is unknown \
         (give one, or declare it in the input)"
    )]
    UnknownScreen {
        /// Line number.
        line: usize,
        /// Field name.
        field: &'static str,
    },
    /// The line does not have the expected structure.
    #[error("line {line}: field `{field}`: {reason}")]
    Malformed {
        /// Line number.
        line: usize,
        /// Field name (or `line`, `header`, `record` when no single field is at fault).
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
}

impl ParseError {
    /// 1-based line number of the error.
    #[must_use]
    pub fn line(&self) -> usize {
        match self {
            Self::Io { line, .. }
            | Self::MissingField { line, .. }
            | Self::InvalidNumber { line, .. }
            | Self::InvalidValue { line, .. }
            | Self::UnknownScreen { line, .. }
            | Self::Malformed { line, .. } => *line,
        }
    }

    /// The field at fault, if any.
    #[must_use]
    pub fn field(&self) -> Option<&'static str> {
        match self {
            Self::Io { .. } => None,
            Self::MissingField { field, .. }
            | Self::InvalidNumber { field, .. }
            | Self::InvalidValue { field, .. }
            | Self::UnknownScreen { field, .. }
            | Self::Malformed { field, .. } => Some(field),
        }
    }
}

/// At most this many characters of an offending value are kept in an error.
const MAX_VALUE_CHARS: usize = 64;

/// `value`, shortened for an error message.
fn excerpt(value: &str) -> String {
    match value.char_indices().nth(MAX_VALUE_CHARS) {
        Some((cut, _)) => format!("{}...", &value[..cut]),
        None => value.to_owned(),
    }
}

/// Parses a finite `f64`.
fn parse_finite(line: usize, field: &'static str, text: &str) -> Result<f64, ParseError> {
    let text = text.trim();
    let value: f64 = text.parse().map_err(|_| ParseError::InvalidNumber {
        line,
        field,
        value: excerpt(text),
    })?;
    if value.is_finite() {
        Ok(value)
    } else {
        Err(ParseError::InvalidValue {
            line,
            field,
            value: excerpt(text),
            reason: "is not finite",
        })
    }
}

/// Parses a validity in 0..1 (directly as `f32`, so a value written from an `f32` reads back
/// exactly).
fn parse_validity(line: usize, field: &'static str, text: &str) -> Result<f32, ParseError> {
    let text = text.trim();
    let value: f32 = text.parse().map_err(|_| ParseError::InvalidNumber {
        line,
        field,
        value: excerpt(text),
    })?;
    if (0.0..=1.0).contains(&value) {
        Ok(value)
    } else {
        Err(ParseError::InvalidValue {
            line,
            field,
            value: excerpt(text),
            reason: "is not in 0..1",
        })
    }
}

/// Lines of a [`BufRead`], numbered from 1, without their `\n` / `\r\n` terminator. Bytes that
/// are not UTF-8 give a [`ParseError::Malformed`] for that line only; an I/O error ends the
/// lines.
#[derive(Debug)]
struct Lines<R> {
    reader: R,
    buf: Vec<u8>,
    line: usize,
    done: bool,
}

impl<R: BufRead> Lines<R> {
    fn new(reader: R) -> Self {
        Self {
            reader,
            buf: Vec::new(),
            line: 0,
            done: false,
        }
    }

    /// The next line and its number, `None` at the end of input (or after an I/O error).
    fn next_line(&mut self) -> Option<Result<(usize, &str), ParseError>> {
        if self.done {
            return None;
        }
        self.buf.clear();
        self.line += 1;
        let line = self.line;
        match self.reader.read_until(b'\n', &mut self.buf) {
            Ok(0) => {
                self.done = true;
                None
            }
            Ok(_) => {
                let mut bytes = self.buf.as_slice();
                if let Some(rest) = bytes.strip_suffix(b"\n") {
                    bytes = rest;
                }
                if let Some(rest) = bytes.strip_suffix(b"\r") {
                    bytes = rest;
                }
                Some(
                    std::str::from_utf8(bytes)
                        .map(|text| (line, text))
                        .map_err(|_| ParseError::Malformed {
                            line,
                            field: "line",
                            reason: "is not valid UTF-8".into(),
                        }),
                )
            }
            Err(source) => {
                self.done = true;
                Some(Err(ParseError::Io { line, source }))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn screen_normalises_pixels_from_its_origin() {
        let screen = ScreenPx::new(1920.0, 1080.0).expect("valid screen");
        assert_eq!(screen.normalise(960.0, 540.0), (0.5, 0.5));
        assert_eq!(screen.normalise(0.0, 0.0), (0.0, 0.0));
        let corners = ScreenPx::from_corners(0.0, 0.0, 1919.0, 1079.0).expect("valid screen");
        assert_eq!(corners, screen);
        let offset = ScreenPx::from_corners(100.0, 50.0, 199.0, 149.0).expect("valid screen");
        assert_eq!(offset.normalise(150.0, 100.0), (0.5, 0.5));
    }

    #[test]
    fn degenerate_screens_are_refused() {
        assert!(ScreenPx::new(0.0, 1080.0).is_none());
        assert!(ScreenPx::new(1920.0, -1.0).is_none());
        assert!(ScreenPx::new(f64::NAN, 1080.0).is_none());
        assert!(ScreenPx::new(f64::INFINITY, 1080.0).is_none());
        assert!(ScreenPx::from_corners(10.0, 0.0, 5.0, 100.0).is_none());
    }

    #[test]
    fn errors_name_line_and_field() {
        let err = parse_finite(7, "x", "abc").expect_err("not a number");
        assert_eq!((err.line(), err.field()), (7, Some("x")));
        assert_eq!(
            err.to_string(),
            "line 7: field `x`: \"abc\" is not a number"
        );
        let err = parse_finite(3, "t_s", "inf").expect_err("not finite");
        assert!(matches!(
            err,
            ParseError::InvalidValue {
                line: 3,
                field: "t_s",
                ..
            }
        ));
        let err = parse_validity(4, "validity", "1.5").expect_err("out of range");
        assert!(err.to_string().contains("not in 0..1"), "{err}");
        let long = "9".repeat(1000) + "x";
        let err = parse_finite(1, "x", &long).expect_err("not a number");
        assert!(err.to_string().len() < 200);
    }

    #[test]
    fn lines_strip_terminators_and_flag_bad_utf8() {
        let input: &[u8] = b"a\r\nb\n\xff\xfe\nlast";
        let mut lines = Lines::new(input);
        let mut got = Vec::new();
        while let Some(item) = lines.next_line() {
            got.push(
                item.map(|(n, s)| (n, s.to_owned()))
                    .map_err(|e| (e.line(), e.field())),
            );
        }
        assert_eq!(
            got,
            vec![
                Ok((1, "a".to_owned())),
                Ok((2, "b".to_owned())),
                Err((3, Some("line"))),
                Ok((4, "last".to_owned())),
            ]
        );
    }
}
