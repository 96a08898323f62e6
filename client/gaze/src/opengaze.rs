//! The Gazepoint Open Gaze API: XML elements, one per `\r\n`-terminated line, over TCP
//! (port [`DEFAULT_PORT`]).
//!
//! The client enables what it wants with `<SET ID="..." STATE="1" />` commands
//! ([`handshake_commands`]); the tracker answers each with `<ACK ID="..." STATE="1" />` and then
//! streams records such as
//! `<REC TIME="12.345" FPOGX="0.48" FPOGY="0.5" FPOGS="12.1" FPOGD="0.24" FPOGID="57" FPOGV="1" />`.
//! The parser here is pure: it takes lines and gives [`GazeSample`]s; sockets are the
//! caller's business.
//!
//! Mapping to [`GazeSample`]: `TIME` (seconds since the tracker started) → `t_s`; `FPOGX`,
//! `FPOGY` (already normalised, origin top-left) → `x`, `y`; `FPOGV="1"` → validity 1 and
//! `fixation: Some(true)` (the tracker only reports a valid fixation point while a fixation is
//! detected); `FPOGV="0"` (blink, lost eyes or saccade) → a missing sample with no fixation flag.
//! The point is the tracker's combined estimate, so the eye is [`Eye::Binocular`].

use std::io::BufRead;

use super::{Eye, GazeSample, Lines, ParseError, excerpt, parse_finite};

/// TCP port the Open Gaze server listens on by default.
pub const DEFAULT_PORT: u16 = 4242;

/// The data the handshake enables, in the order it is enabled: time and fixation fields first,
/// the data stream last, so that the first record already carries every field.
pub const HANDSHAKE_IDS: [&str; 3] = [
    "ENABLE_SEND_TIME",
    "ENABLE_SEND_POG_FIX",
    "ENABLE_SEND_DATA",
];

/// A `SET` command line, `\r\n` included: `<SET ID="{id}" STATE="1" />`.
#[must_use]
pub fn set_command(id: &str, enable: bool) -> String {
    format!("<SET ID=\"{id}\" STATE=\"{}\" />\r\n", u8::from(enable))
}

/// The command lines to send after connecting, `\r\n` included, in order (see
/// [`HANDSHAKE_IDS`]).
#[must_use]
pub fn handshake_commands() -> Vec<String> {
    HANDSHAKE_IDS
        .iter()
        .map(|id| set_command(id, true))
        .collect()
}

/// One `REC` record's fixation point of gaze.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpenGazeRecord {
    /// `TIME`: seconds since the tracker started.
    pub time_s: f64,
    /// `FPOGX`: fixation point x, normalised, 0 = left edge.
    pub x: f64,
    /// `FPOGY`: fixation point y, normalised, 0 = top edge.
    pub y: f64,
    /// `FPOGV`: whether the point is valid.
    pub valid: bool,
    /// `FPOGS`: start of the current fixation, seconds on the `TIME` clock, if sent.
    pub fixation_start_s: Option<f64>,
    /// `FPOGD`: duration of the current fixation so far, seconds, if sent.
    pub fixation_duration_s: Option<f64>,
    /// `FPOGID`: number of the current fixation, if sent.
    pub fixation_id: Option<u64>,
}

impl OpenGazeRecord {
    /// The record as a gaze sample (see the module documentation for the mapping).
    #[must_use]
    pub fn to_sample(&self) -> GazeSample {
        if self.valid {
            GazeSample::valid(self.time_s, self.x, self.y, Eye::Binocular).with_fixation(Some(true))
        } else {
            GazeSample::missing(self.time_s, Eye::Binocular)
        }
    }
}

/// One line from the tracker.
#[derive(Debug, Clone, PartialEq)]
pub enum OpenGazeMessage {
    /// A `REC` data record.
    Record(OpenGazeRecord),
    /// An `ACK` of a command.
    Ack {
        /// `ID` attribute (empty if absent).
        id: String,
        /// `STATE` attribute, if present.
        state: Option<String>,
    },
    /// Any other element (`NACK`, `CAL`, ...), kept by name.
    Other {
        /// The element name.
        tag: String,
        /// `ID` attribute, if present.
        id: Option<String>,
    },
}

/// An element: name and attributes, in order.
#[derive(Debug)]
struct Element<'a> {
    tag: &'a str,
    attributes: Vec<(&'a str, &'a str)>,
}

impl<'a> Element<'a> {
    fn get(&self, name: &str) -> Option<&'a str> {
        self.attributes
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, v)| *v)
    }
}

fn malformed(line: usize, reason: impl Into<String>) -> ParseError {
    ParseError::Malformed {
        line,
        field: "record",
        reason: reason.into(),
    }
}

fn is_name_char(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_' || c == '-'
}

/// Parses `<TAG NAME="value" ... />`.
fn parse_element(line: usize, text: &str) -> Result<Element<'_>, ParseError> {
    let inner = text
        .strip_prefix('<')
        .ok_or_else(|| malformed(line, format!("{:?} does not start with '<'", excerpt(text))))?;
    let inner = inner.strip_suffix("/>").ok_or_else(|| {
        malformed(
            line,
            format!("{:?} does not end with \"/>\"", excerpt(text)),
        )
    })?;
    let tag_end = inner
        .find(|c: char| !is_name_char(c))
        .unwrap_or(inner.len());
    let (tag, mut rest) = inner.split_at(tag_end);
    if tag.is_empty() {
        return Err(malformed(line, "element has no name"));
    }
    let mut attributes: Vec<(&str, &str)> = Vec::new();
    loop {
        let trimmed = rest.trim_start();
        if trimmed.is_empty() {
            break;
        }
        if trimmed.len() == rest.len() {
            return Err(malformed(
                line,
                format!("expected a space before {:?}", excerpt(trimmed)),
            ));
        }
        let name_end = trimmed
            .find(|c: char| !is_name_char(c))
            .unwrap_or(trimmed.len());
        let (name, after) = trimmed.split_at(name_end);
        if name.is_empty() {
            return Err(malformed(
                line,
                format!("expected an attribute name at {:?}", excerpt(trimmed)),
            ));
        }
        let after = after
            .trim_start()
            .strip_prefix('=')
            .ok_or_else(|| malformed(line, format!("attribute {:?} has no '='", excerpt(name))))?
            .trim_start();
        let quote = after
            .chars()
            .next()
            .filter(|c| *c == '"' || *c == '\'')
            .ok_or_else(|| {
                malformed(line, format!("value of {:?} is not quoted", excerpt(name)))
            })?;
        let after = &after[1..];
        let close = after.find(quote).ok_or_else(|| {
            malformed(line, format!("value of {:?} is not closed", excerpt(name)))
        })?;
        if attributes.iter().any(|(n, _)| *n == name) {
            return Err(malformed(
                line,
                format!("attribute {:?} appears twice", excerpt(name)),
            ));
        }
        attributes.push((name, &after[..close]));
        rest = &after[close + 1..];
    }
    Ok(Element { tag, attributes })
}

/// Parses one line from the tracker (terminator optional). `Ok(None)` for a blank line.
///
/// # Errors
/// A line that is not a single `<... />` element, or a `REC` record whose `TIME`, `FPOGX`,
/// `FPOGY` or `FPOGV` is missing or malformed, or whose `FPOGS`, `FPOGD`, `FPOGID` is malformed.
pub fn parse_line(line: usize, text: &str) -> Result<Option<OpenGazeMessage>, ParseError> {
    let text = text.trim();
    if text.is_empty() {
        return Ok(None);
    }
    let element = parse_element(line, text)?;
    let message = match element.tag {
        "REC" => OpenGazeMessage::Record(parse_record(line, &element)?),
        "ACK" => OpenGazeMessage::Ack {
            id: element.get("ID").unwrap_or_default().to_owned(),
            state: element.get("STATE").map(str::to_owned),
        },
        tag => OpenGazeMessage::Other {
            tag: tag.to_owned(),
            id: element.get("ID").map(str::to_owned),
        },
    };
    Ok(Some(message))
}

fn parse_record(line: usize, element: &Element<'_>) -> Result<OpenGazeRecord, ParseError> {
    let required = |field: &'static str| {
        element
            .get(field)
            .ok_or(ParseError::MissingField { line, field })
    };
    let optional_number = |field: &'static str| {
        element
            .get(field)
            .map(|v| parse_finite(line, field, v))
            .transpose()
    };
    let time_s = parse_finite(line, "TIME", required("TIME")?)?;
    let x = parse_finite(line, "FPOGX", required("FPOGX")?)?;
    let y = parse_finite(line, "FPOGY", required("FPOGY")?)?;
    let valid = match required("FPOGV")?.trim() {
        "1" => true,
        "0" => false,
        other => {
            return Err(ParseError::InvalidValue {
                line,
                field: "FPOGV",
                value: excerpt(other),
                reason: "is not 0 or 1",
            });
        }
    };
    let fixation_id = element
        .get("FPOGID")
        .map(|v| {
            v.trim()
                .parse::<u64>()
                .map_err(|_| ParseError::InvalidNumber {
                    line,
                    field: "FPOGID",
                    value: excerpt(v),
                })
        })
        .transpose()?;
    Ok(OpenGazeRecord {
        time_s,
        x,
        y,
        valid,
        fixation_start_s: optional_number("FPOGS")?,
        fixation_duration_s: optional_number("FPOGD")?,
        fixation_id,
    })
}

/// Line-by-line parser that numbers the lines it is fed and keeps only gaze samples.
#[derive(Debug, Default)]
pub struct OpenGazeParser {
    line: usize,
}

impl OpenGazeParser {
    /// A parser at line 0.
    #[must_use]
    pub fn new() -> Self {
        Self::default()
    }

    /// Feeds the next line: `Some` sample for a `REC` record, `None` for acknowledgements, other
    /// elements and blank lines.
    ///
    /// # Errors
    /// As [`parse_line`], numbered with this line's position in the stream.
    pub fn push_line(&mut self, text: &str) -> Result<Option<GazeSample>, ParseError> {
        self.line += 1;
        match parse_line(self.line, text)? {
            Some(OpenGazeMessage::Record(record)) => Ok(Some(record.to_sample())),
            _ => Ok(None),
        }
    }

    /// Number of lines fed so far.
    #[must_use]
    pub fn lines(&self) -> usize {
        self.line
    }
}

/// Streaming reader of an Open Gaze line stream (a log, or a blocking socket): an iterator of
/// samples, skipping acknowledgements and other elements. A bad line gives one `Err` and reading
/// goes on; an I/O error ends the iteration.
#[derive(Debug)]
pub struct OpenGazeReader<R> {
    lines: Lines<R>,
}

impl<R: BufRead> OpenGazeReader<R> {
    /// A reader of `reader`.
    pub fn new(reader: R) -> Self {
        Self {
            lines: Lines::new(reader),
        }
    }
}

impl<R: BufRead> Iterator for OpenGazeReader<R> {
    type Item = Result<GazeSample, ParseError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            let (line, text) = match self.lines.next_line()? {
                Ok(numbered) => numbered,
                Err(err) => return Some(Err(err)),
            };
            match parse_line(line, text) {
                Ok(Some(OpenGazeMessage::Record(record))) => return Some(Ok(record.to_sample())),
                Ok(_) => {}
                Err(err) => return Some(Err(err)),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    #[test]
    fn handshake_enables_time_fixations_then_data() {
        assert_eq!(
            handshake_commands(),
            vec![
                "<SET ID=\"ENABLE_SEND_TIME\" STATE=\"1\" />\r\n",
                "<SET ID=\"ENABLE_SEND_POG_FIX\" STATE=\"1\" />\r\n",
                "<SET ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\r\n",
            ]
        );
        assert_eq!(
            set_command("ENABLE_SEND_DATA", false),
            "<SET ID=\"ENABLE_SEND_DATA\" STATE=\"0\" />\r\n"
        );
        // The tracker's acknowledgement of our own command parses.
        let ack = parse_line(1, &set_command("X", true).replace("SET", "ACK")).expect("parses");
        assert_eq!(
            ack,
            Some(OpenGazeMessage::Ack {
                id: "X".into(),
                state: Some("1".into())
            })
        );
    }

    #[test]
    fn record_parses_in_any_attribute_order() {
        let line = "<REC FPOGV=\"1\" FPOGID='57' TIME=\"12.345\" FPOGX=\"0.48\" FPOGY=\"0.5\" \
                    FPOGS=\"12.1\" FPOGD=\"0.245\" CNT=\"12\" />\r\n";
        let Some(OpenGazeMessage::Record(record)) = parse_line(1, line).expect("parses") else {
            panic!("a record");
        };
        assert_eq!(
            record,
            OpenGazeRecord {
                time_s: 12.345,
                x: 0.48,
                y: 0.5,
                valid: true,
                fixation_start_s: Some(12.1),
                fixation_duration_s: Some(0.245),
                fixation_id: Some(57),
            }
        );
        assert_eq!(
            record.to_sample(),
            GazeSample::valid(12.345, 0.48, 0.5, Eye::Binocular).with_fixation(Some(true))
        );
        let minimal = "<REC TIME=\"1.5\" FPOGX=\"0.1\" FPOGY=\"0.2\" FPOGV=\"0\"/>";
        let Some(OpenGazeMessage::Record(record)) = parse_line(1, minimal).expect("parses") else {
            panic!("a record");
        };
        assert_eq!(record.fixation_id, None);
        assert_eq!(record.to_sample(), GazeSample::missing(1.5, Eye::Binocular));
    }

    #[test]
    fn parser_skips_acks_and_other_elements() {
        let mut parser = OpenGazeParser::new();
        assert_eq!(
            parser
                .push_line("<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />")
                .expect("ack"),
            None
        );
        assert_eq!(parser.push_line("").expect("blank"), None);
        assert_eq!(
            parser.push_line("<NACK ID=\"NOPE\" />").expect("nack"),
            None
        );
        let sample = parser
            .push_line("<REC TIME=\"2\" FPOGX=\"0.25\" FPOGY=\"0.75\" FPOGV=\"1\" />")
            .expect("record")
            .expect("a sample");
        assert_eq!(sample.t_s, 2.0);
        let err = parser
            .push_line("<REC TIME=\"3\" FPOGX=\"0.25\" FPOGV=\"1\" />")
            .expect_err("no FPOGY");
        assert!(
            matches!(
                err,
                ParseError::MissingField {
                    line: 5,
                    field: "FPOGY"
                }
            ),
            "{err}"
        );
        assert_eq!(parser.lines(), 5);
        assert_eq!(
            parse_line(1, "<NACK ID=\"NOPE\" />").expect("parses"),
            Some(OpenGazeMessage::Other {
                tag: "NACK".into(),
                id: Some("NOPE".into())
            })
        );
    }

    #[test]
    fn malformed_records_name_line_and_field() {
        let cases = [
            ("REC TIME=\"1\" />", "record"),
            ("<REC TIME=\"1\"", "record"),
            ("< />", "record"),
            ("<REC TIME=1 />", "record"),
            ("<REC TIME=\"1 />", "record"),
            ("<REC TIME\"1\" />", "record"),
            ("<REC TIME=\"1\"FPOGX=\"1\" />", "record"),
            ("<REC TIME=\"1\" TIME=\"2\" />", "record"),
            ("<REC = \"1\" />", "record"),
            ("<REC FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"1\" />", "TIME"),
            (
                "<REC TIME=\"x\" FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"1\" />",
                "TIME",
            ),
            (
                "<REC TIME=\"1\" FPOGX=\"nan\" FPOGY=\"0\" FPOGV=\"1\" />",
                "FPOGX",
            ),
            (
                "<REC TIME=\"1\" FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"yes\" />",
                "FPOGV",
            ),
            (
                "<REC TIME=\"1\" FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"1\" FPOGID=\"-1\" />",
                "FPOGID",
            ),
            (
                "<REC TIME=\"1\" FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"1\" FPOGD=\"?\" />",
                "FPOGD",
            ),
        ];
        for (text, field) in cases {
            let err = parse_line(9, text).expect_err(text);
            assert_eq!((err.line(), err.field()), (9, Some(field)), "{text}: {err}");
        }
    }

    #[test]
    fn reader_streams_samples_and_goes_on_after_errors() {
        let input = "<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />\r\n\
                     <REC TIME=\"0.1\" FPOGX=\"0.5\" FPOGY=\"0.5\" FPOGV=\"1\" />\r\n\
                     garbage\r\n\
                     <REC TIME=\"0.2\" FPOGX=\"0.6\" FPOGY=\"0.5\" FPOGV=\"0\" />\r\n";
        let got: Vec<_> = OpenGazeReader::new(input.as_bytes()).collect();
        assert_eq!(got.len(), 3);
        assert!(matches!(got[0], Ok(s) if s.x == 0.5 && s.is_valid()));
        assert!(matches!(
            got[1],
            Err(ParseError::Malformed {
                line: 3,
                field: "record",
                ..
            })
        ));
        assert!(matches!(got[2], Ok(s) if s.t_s == 0.2 && !s.is_valid()));
    }

    proptest! {
        #[test]
        fn never_panics_on_arbitrary_lines(text in ".{0,80}") {
            let _ = parse_line(1, &text);
        }

        #[test]
        fn never_panics_on_element_like_lines(text in "<[A-Z]{0,4}( [A-Z]{0,6}=?[\"']?[0-9a-z.\"']{0,6}){0,6} ?/?>?") {
            if let Err(err) = parse_line(1, &text) {
                prop_assert_eq!(err.line(), 1);
                prop_assert!(err.field().is_some());
            }
        }

        #[test]
        fn records_round_trip(
            time_s in 0.0f64..1e6,
            x in -1.0f64..2.0,
            y in -1.0f64..2.0,
            valid in any::<bool>(),
            fix in proptest::option::of((0.0f64..1e6, 0.0f64..100.0, any::<u64>())),
            order in Just((0..7).collect::<Vec<usize>>()).prop_shuffle(),
        ) {
            let record = OpenGazeRecord {
                time_s,
                x,
                y,
                valid,
                fixation_start_s: fix.map(|f| f.0),
                fixation_duration_s: fix.map(|f| f.1),
                fixation_id: fix.map(|f| f.2),
            };
            let mut attributes = [
                Some(format!("TIME=\"{time_s}\"")),
                Some(format!("FPOGX=\"{x}\"")),
                Some(format!("FPOGY=\"{y}\"")),
                Some(format!("FPOGV=\"{}\"", u8::from(valid))),
                fix.map(|f| format!("FPOGS=\"{}\"", f.0)),
                fix.map(|f| format!("FPOGD=\"{}\"", f.1)),
                fix.map(|f| format!("FPOGID=\"{}\"", f.2)),
            ];
            let ordered: Vec<String> = order.iter().filter_map(|i| attributes[*i].take()).collect();
            let line = format!("<REC {} />\r\n", ordered.join(" "));
            prop_assert_eq!(parse_line(1, &line).expect("parses"), Some(OpenGazeMessage::Record(record)));
        }
    }
}
