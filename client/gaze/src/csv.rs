//! CSV gaze recordings.
//!
//! Two layouts, told apart by the header line (the first line that is neither blank nor a
//! comment); columns are found by name, in any order, and unknown columns are ignored:
//! - **pixels**: `t_s,xpos,ypos[,ps]`: seconds, gaze in screen pixels (origin top-left), pupil
//!   (ignored). Needs the screen size: give it with [`CsvGazeReader::with_screen`] or declare it
//!   in a comment such as `# screen 1920x1080 px`.
//! - **normalised** (this crate's own): `t_s,x,y[,validity][,fixation]`: seconds, gaze
//!   normalised 0..1, confidence 0..1 (default 1), fixation flag `1`/`0`/`true`/`false`/empty.
//!
//! - **binocular**: either layout with one column per eye, `_left` and `_right` appended:
//!   `t_s,xpos_left,xpos_right,ypos_left,ypos_right[,ps_left,ps_right]` (an EyeLink binocular
//!   export) or `t_s,x_left,y_left,x_right,y_right[,validity_left,validity_right][,fixation]`.
//!   How the eyes become samples is [`CsvGazeReader::with_binocular`] (default: the mean of the
//!   valid eyes). A file with one side only (`xpos_left,ypos_left`) is monocular, tagged with
//!   that eye.
//!
//! Lines starting with `#` are comments. An empty `x`/`y` (or `xpos`/`ypos`) field is a
//! missing sample: it is kept, with validity 0 (see [`GazeSample`]).

use std::io::{self, BufRead, Write};

use super::{
    Binocular, Eye, EyeReading, GazeSample, Lines, ParseError, ScreenPx, excerpt, parse_finite,
    parse_validity,
};

/// Which of the two CSV layouts an input uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CsvFormat {
    /// `t_s,xpos,ypos[,ps]`, gaze in screen pixels.
    Pixels,
    /// `t_s,x,y[,validity][,fixation]`, gaze normalised 0..1.
    Normalised,
}

/// The header [`write_normalised`] writes.
pub const NORMALISED_HEADER: &str = "t_s,x,y,validity,fixation";

/// Columns of one eye: position and optional validity, with the names errors use.
#[derive(Debug, Clone, Copy)]
struct EyeColumns {
    x: usize,
    y: usize,
    validity: Option<usize>,
    names: [&'static str; 3],
}

/// Column positions found in a header.
#[derive(Debug, Clone)]
struct Columns {
    format: CsvFormat,
    count: usize,
    t: usize,
    /// One eye (monocular), or left and right.
    eyes: Vec<EyeColumns>,
    /// The eye a monocular file names by its column suffix, if it does.
    named_eye: Option<Eye>,
    fixation: Option<usize>,
}

impl Columns {
    fn from_header(line: usize, header: &str) -> Result<Self, ParseError> {
        let names: Vec<&str> = header.split(',').map(str::trim).collect();
        for (i, name) in names.iter().enumerate() {
            if !name.is_empty() && names[..i].contains(name) {
                return Err(ParseError::Malformed {
                    line,
                    field: "header",
                    reason: format!("column {:?} appears twice", excerpt(name)),
                });
            }
        }
        let find = |name: &str| names.iter().position(|n| *n == name);
        let Some(t) = find("t_s") else {
            return Err(ParseError::Malformed {
                line,
                field: "header",
                reason: format!(
                    "no `t_s` column in {:?}; expected `t_s,xpos,ypos[,ps]`, \
                     `t_s,x,y[,validity][,fixation]` or their `_left`/`_right` forms",
                    excerpt(header)
                ),
            });
        };
        let eye = |format: CsvFormat, names: [&'static str; 3]| {
            let (x, y) = (find(names[0])?, find(names[1])?);
            let validity = match format {
                CsvFormat::Pixels => None,
                CsvFormat::Normalised => find(names[2]),
            };
            Some(EyeColumns {
                x,
                y,
                validity,
                names,
            })
        };
        let layouts = [
            (
                CsvFormat::Pixels,
                ["xpos", "ypos", ""],
                ["xpos_left", "ypos_left", ""],
                ["xpos_right", "ypos_right", ""],
            ),
            (
                CsvFormat::Normalised,
                ["x", "y", "validity"],
                ["x_left", "y_left", "validity_left"],
                ["x_right", "y_right", "validity_right"],
            ),
        ];
        let found = layouts.iter().find_map(|&(format, mono, left, right)| {
            if let Some(mono) = eye(format, mono) {
                return Some((format, vec![mono], None));
            }
            match (eye(format, left), eye(format, right)) {
                (Some(l), Some(r)) => Some((format, vec![l, r], None)),
                (Some(l), None) => Some((format, vec![l], Some(Eye::Left))),
                (None, Some(r)) => Some((format, vec![r], Some(Eye::Right))),
                (None, None) => None,
            }
        });
        let Some((format, eyes, named_eye)) = found else {
            return Err(ParseError::Malformed {
                line,
                field: "header",
                reason: format!(
                    "no `xpos,ypos` nor `x,y` columns (nor their `_left`/`_right` forms) in {:?}",
                    excerpt(header)
                ),
            });
        };
        let fixation = match format {
            CsvFormat::Pixels => None,
            CsvFormat::Normalised => find("fixation"),
        };
        Ok(Self {
            format,
            count: names.len(),
            t,
            eyes,
            named_eye,
            fixation,
        })
    }
}

/// Finds a screen size declared in a comment as `WIDTHxHEIGHT px` (or `WIDTHxHEIGHTpx`).
#[must_use]
pub fn screen_from_comment(comment: &str) -> Option<ScreenPx> {
    let words: Vec<&str> = comment
        .split(|c: char| c.is_whitespace() || c == ',' || c == ';' || c == '(' || c == ')')
        .filter(|w| !w.is_empty())
        .collect();
    words.iter().enumerate().find_map(|(i, word)| {
        let (dims, px_follows) = match word.strip_suffix("px") {
            Some(dims) => (dims, true),
            None => (*word, words.get(i + 1).is_some_and(|next| *next == "px")),
        };
        let (w, h) = dims.split_once('x')?;
        let all_digits =
            |s: &str| !s.is_empty() && s.len() <= 6 && s.bytes().all(|b| b.is_ascii_digit());
        if !px_follows || !all_digits(w) || !all_digits(h) {
            return None;
        }
        ScreenPx::new(w.parse().ok()?, h.parse().ok()?)
    })
}

/// Streaming reader of a CSV gaze recording: an iterator of samples, one per data line.
///
/// A bad data line gives one `Err` and reading goes on with the next line; a bad header or an
/// I/O error ends the iteration after its `Err`.
#[derive(Debug)]
pub struct CsvGazeReader<R> {
    lines: Lines<R>,
    screen_given: Option<ScreenPx>,
    screen_found: Option<ScreenPx>,
    eye: Option<Eye>,
    binocular: Binocular,
    columns: Option<Columns>,
    /// The right eye's sample of a [`Binocular::Both`] line, given on the next call.
    pending: Option<GazeSample>,
    stopped: bool,
}

impl<R: BufRead> CsvGazeReader<R> {
    /// A reader of `reader`. Samples of a monocular file get [`Eye::Unspecified`] (or the eye
    /// its column names say) unless [`Self::with_eye`] says; a binocular file gives what
    /// [`Self::with_binocular`] says.
    pub fn new(reader: R) -> Self {
        Self {
            lines: Lines::new(reader),
            screen_given: None,
            screen_found: None,
            eye: None,
            binocular: Binocular::default(),
            columns: None,
            pending: None,
            stopped: false,
        }
    }

    /// How a binocular file's eyes become samples (default [`Binocular::Mean`]).
    #[must_use]
    pub fn with_binocular(mut self, binocular: Binocular) -> Self {
        self.binocular = binocular;
        self
    }

    /// Whether the file is binocular, once the header has been read.
    pub fn is_binocular(&self) -> Option<bool> {
        self.columns.as_ref().map(|c| c.eyes.len() == 2)
    }

    /// Use this screen size for pixel gaze; it wins over any size declared in the input.
    #[must_use]
    pub fn with_screen(mut self, screen: ScreenPx) -> Self {
        self.screen_given = Some(screen);
        self
    }

    /// Tag every sample of a monocular file with this eye.
    #[must_use]
    pub fn with_eye(mut self, eye: Eye) -> Self {
        self.eye = Some(eye);
        self
    }

    /// The layout, once the header has been read.
    pub fn format(&self) -> Option<CsvFormat> {
        self.columns.as_ref().map(|c| c.format)
    }

    /// The screen size in use: the one given, else the last one declared so far in the input.
    pub fn screen(&self) -> Option<ScreenPx> {
        self.screen_given.or(self.screen_found)
    }

    /// The 1-based number of the line read last (that of the last sample or error given).
    pub fn line(&self) -> usize {
        self.lines.line
    }
}

/// What a reader needs besides the columns to turn a line into samples.
#[derive(Debug, Clone, Copy)]
struct RecordContext {
    screen: Option<ScreenPx>,
    eye: Option<Eye>,
    binocular: Binocular,
}

/// One eye's reading on a line: `None` for a missing sample (empty position or validity 0).
fn parse_eye(
    columns: &Columns,
    eye: &EyeColumns,
    screen: Option<ScreenPx>,
    line: usize,
    fields: &[&str],
) -> Result<EyeReading, ParseError> {
    let get = |index: usize, field: &'static str| {
        fields
            .get(index)
            .copied()
            .ok_or(ParseError::MissingField { line, field })
    };
    let [x_name, y_name, validity_name] = eye.names;
    let x_text = get(eye.x, x_name)?;
    let y_text = get(eye.y, y_name)?;
    let validity_text = match eye.validity {
        Some(i) => get(i, validity_name)?,
        None => "",
    };
    if x_text.is_empty() || y_text.is_empty() {
        if !validity_text.is_empty() {
            parse_validity(line, validity_name, validity_text)?;
        }
        return Ok(None);
    }
    let x = parse_finite(line, x_name, x_text)?;
    let y = parse_finite(line, y_name, y_text)?;
    let validity = if validity_text.is_empty() {
        1.0
    } else {
        parse_validity(line, validity_name, validity_text)?
    };
    if validity == 0.0 {
        return Ok(None);
    }
    let (x, y) = match columns.format {
        CsvFormat::Normalised => (x, y),
        CsvFormat::Pixels => {
            let screen = screen.ok_or(ParseError::UnknownScreen {
                line,
                field: x_name,
            })?;
            screen.normalise(x, y)
        }
    };
    Ok(Some((x, y, validity)))
}

/// Parses one data line under `columns`: one sample, or two for [`Binocular::Both`].
fn parse_record(
    columns: &Columns,
    context: RecordContext,
    line: usize,
    text: &str,
) -> Result<(GazeSample, Option<GazeSample>), ParseError> {
    let fields: Vec<&str> = text.split(',').map(str::trim).collect();
    if fields.len() > columns.count {
        return Err(ParseError::Malformed {
            line,
            field: "line",
            reason: format!(
                "{} fields but the header has {}",
                fields.len(),
                columns.count
            ),
        });
    }
    let t_text = fields
        .get(columns.t)
        .copied()
        .ok_or(ParseError::MissingField { line, field: "t_s" })?;
    if t_text.is_empty() {
        return Err(ParseError::MissingField { line, field: "t_s" });
    }
    let t_s = parse_finite(line, "t_s", t_text)?;
    let fixation = match columns.fixation {
        Some(i) => {
            let text = fields.get(i).copied().ok_or(ParseError::MissingField {
                line,
                field: "fixation",
            })?;
            parse_flag(line, "fixation", text)?
        }
        None => None,
    };
    let mut readings = [None, None];
    for (reading, eye) in readings.iter_mut().zip(&columns.eyes) {
        *reading = parse_eye(columns, eye, context.screen, line, &fields)?;
    }
    if let [left, right] = readings
        && columns.eyes.len() == 2
    {
        return Ok(context.binocular.samples(t_s, left, right, fixation));
    }
    let eye = context
        .eye
        .or(columns.named_eye)
        .unwrap_or(Eye::Unspecified);
    let sample = GazeSample::from_reading(t_s, readings[0], eye, fixation);
    Ok((sample, None))
}

impl<R: BufRead> Iterator for CsvGazeReader<R> {
    type Item = Result<GazeSample, ParseError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(sample) = self.pending.take() {
                return Some(Ok(sample));
            }
            if self.stopped {
                return None;
            }
            let (line, text) = match self.lines.next_line()? {
                Ok(numbered) => numbered,
                Err(err) => return Some(Err(err)),
            };
            let text = text.trim();
            if text.is_empty() {
                continue;
            }
            if let Some(comment) = text.strip_prefix('#') {
                if let Some(screen) = screen_from_comment(comment) {
                    self.screen_found = Some(screen);
                }
                continue;
            }
            match &self.columns {
                Some(columns) => {
                    let context = RecordContext {
                        screen: self.screen_given.or(self.screen_found),
                        eye: self.eye,
                        binocular: self.binocular,
                    };
                    return Some(parse_record(columns, context, line, text).map(
                        |(first, second)| {
                            self.pending = second;
                            first
                        },
                    ));
                }
                None => match Columns::from_header(line, text) {
                    Ok(columns) => self.columns = Some(columns),
                    Err(err) => {
                        self.stopped = true;
                        return Some(Err(err));
                    }
                },
            }
        }
    }
}

/// Parses a fixation flag: `1`/`true` → true, `0`/`false` → false, empty → none.
fn parse_flag(line: usize, field: &'static str, text: &str) -> Result<Option<bool>, ParseError> {
    match text {
        "" => Ok(None),
        "1" | "true" => Ok(Some(true)),
        "0" | "false" => Ok(Some(false)),
        other => Err(ParseError::InvalidValue {
            line,
            field,
            value: excerpt(other),
            reason: "is not one of 1, 0, true, false or empty",
        }),
    }
}

/// One data line of the normalised layout ([`NORMALISED_HEADER`]), without terminator. A missing
/// sample (validity 0) is written with empty `x` and `y`. Numbers are written so that they
/// parse back to the same value.
#[must_use]
pub fn format_normalised(sample: &GazeSample) -> String {
    let fixation = match sample.fixation {
        Some(true) => "1",
        Some(false) => "0",
        None => "",
    };
    if sample.is_valid() {
        format!(
            "{},{},{},{},{fixation}",
            sample.t_s, sample.x, sample.y, sample.validity
        )
    } else {
        format!("{},,,0,{fixation}", sample.t_s)
    }
}

/// Writes `samples` in the normalised layout, header first, one `\n`-terminated line each.
///
/// # Errors
/// The first error of `writer`.
pub fn write_normalised<W: Write>(
    mut writer: W,
    samples: impl IntoIterator<Item = GazeSample>,
) -> io::Result<()> {
    writeln!(writer, "{NORMALISED_HEADER}")?;
    for sample in samples {
        writeln!(writer, "{}", format_normalised(&sample))?;
    }
    writer.flush()
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    fn read_all(input: &str) -> Vec<Result<GazeSample, ParseError>> {
        CsvGazeReader::new(input.as_bytes()).collect()
    }

    fn read_ok(reader: CsvGazeReader<&[u8]>) -> Vec<GazeSample> {
        reader.collect::<Result<_, _>>().expect("parses")
    }

    #[test]
    fn pixel_layout_uses_the_screen_declared_in_a_comment() {
        let input = "# source: test; screen 1920x1080 px, origin top-left\n\
                     t_s,xpos,ypos,ps\n\
                     0.0000,960.0,540.0,1103.0\n\
                     0.0010,,,0.0\n\
                     \n\
                     0.0020,0,1080,12\n";
        let mut reader = CsvGazeReader::new(input.as_bytes()).with_eye(Eye::Left);
        let samples: Vec<_> = reader.by_ref().collect::<Result<_, _>>().expect("parses");
        assert_eq!(reader.format(), Some(CsvFormat::Pixels));
        assert_eq!(reader.screen(), ScreenPx::new(1920.0, 1080.0));
        assert_eq!(
            samples,
            vec![
                GazeSample::valid(0.0, 0.5, 0.5, Eye::Left),
                GazeSample::missing(0.001, Eye::Left),
                GazeSample::valid(0.002, 0.0, 1.0, Eye::Left),
            ]
        );
    }

    #[test]
    fn pixel_layout_needs_a_screen() {
        let input = "t_s,xpos,ypos,ps\n0.0,10,20,1\n0.1,,,0\n";
        let got = read_all(input);
        assert!(
            matches!(
                got[0],
                Err(ParseError::UnknownScreen {
                    line: 2,
                    field: "xpos"
                })
            ),
            "{got:?}"
        );
        // A missing sample needs no screen.
        assert!(matches!(got[1], Ok(s) if !s.is_valid()));
        let screen = ScreenPx::new(100.0, 200.0).expect("screen");
        let samples = read_ok(CsvGazeReader::new(input.as_bytes()).with_screen(screen));
        assert_eq!(
            samples[0],
            GazeSample::valid(0.0, 0.1, 0.1, Eye::Unspecified)
        );
    }

    #[test]
    fn given_screen_wins_over_declared_one() {
        let input = "# screen 1000x1000 px\nt_s,xpos,ypos\n1.5,50,50\n";
        let screen = ScreenPx::new(100.0, 100.0).expect("screen");
        let samples = read_ok(CsvGazeReader::new(input.as_bytes()).with_screen(screen));
        assert_eq!((samples[0].x, samples[0].y), (0.5, 0.5));
    }

    #[test]
    fn screen_comments_are_recognised() {
        let hd = ScreenPx::new(1920.0, 1080.0);
        assert_eq!(screen_from_comment(" screen 1920x1080 px"), hd);
        assert_eq!(screen_from_comment("1920x1080px"), hd);
        assert_eq!(screen_from_comment("eye 0=left; screen 1920x1080 px"), hd);
        assert_eq!(screen_from_comment("screen 1920x1080"), None);
        assert_eq!(screen_from_comment("screen 0x1080 px"), None);
        assert_eq!(screen_from_comment("axb px"), None);
        assert_eq!(screen_from_comment("x px"), None);
        assert_eq!(screen_from_comment(""), None);
    }

    #[test]
    fn normalised_layout_with_optional_columns_in_any_order() {
        let input = "fixation,validity,y,x,t_s,extra\n\
                     1,0.5,0.25,0.75,10.0,zzz\n\
                     ,,0.1,0.2,10.5,\n\
                     0,0,0.1,0.2,11,\n\
                     false,,,,12,\n";
        let mut reader = CsvGazeReader::new(input.as_bytes());
        let samples: Vec<_> = reader.by_ref().collect::<Result<_, _>>().expect("parses");
        assert_eq!(reader.format(), Some(CsvFormat::Normalised));
        assert_eq!(
            samples,
            vec![
                GazeSample {
                    validity: 0.5,
                    ..GazeSample::valid(10.0, 0.75, 0.25, Eye::Unspecified)
                }
                .with_fixation(Some(true)),
                GazeSample::valid(10.5, 0.2, 0.1, Eye::Unspecified),
                GazeSample::missing(11.0, Eye::Unspecified).with_fixation(Some(false)),
                GazeSample::missing(12.0, Eye::Unspecified).with_fixation(Some(false)),
            ]
        );
    }

    #[test]
    fn binocular_eyelink_export_gives_every_sample() {
        // The column order of an EyeLink binocular export.
        let input = "# screen 100x100 px\n\
                     t_s,xpos_left,xpos_right,ypos_left,ypos_right,ps_left,ps_right\n\
                     0.000,10,30,20,40,900,910\n\
                     0.001,,30,,40,0,910\n\
                     0.002,,,,,0,0\n";
        let mut reader = CsvGazeReader::new(input.as_bytes());
        let mean: Vec<_> = reader.by_ref().collect::<Result<_, _>>().expect("parses");
        assert_eq!(reader.is_binocular(), Some(true));
        assert_eq!(
            mean,
            vec![
                GazeSample::valid(0.0, (0.1 + 0.3) / 2.0, (0.2 + 0.4) / 2.0, Eye::Binocular),
                GazeSample::valid(0.001, 0.3, 0.4, Eye::Binocular),
                GazeSample::missing(0.002, Eye::Binocular),
            ]
        );
        let both = read_ok(CsvGazeReader::new(input.as_bytes()).with_binocular(Binocular::Both));
        assert_eq!(
            both,
            vec![
                GazeSample::valid(0.0, 0.1, 0.2, Eye::Left),
                GazeSample::valid(0.0, 0.3, 0.4, Eye::Right),
                GazeSample::missing(0.001, Eye::Left),
                GazeSample::valid(0.001, 0.3, 0.4, Eye::Right),
                GazeSample::missing(0.002, Eye::Left),
                GazeSample::missing(0.002, Eye::Right),
            ]
        );
        let left = read_ok(CsvGazeReader::new(input.as_bytes()).with_binocular(Binocular::Left));
        assert_eq!(left[0], GazeSample::valid(0.0, 0.1, 0.2, Eye::Left));
        assert!(!left[1].is_valid());
    }

    #[test]
    fn binocular_normalised_with_validity_and_one_sided_files() {
        let input = "t_s,x_left,y_left,validity_left,x_right,y_right,validity_right,fixation\n\
                     1.0,0.25,0.5,0.5,0.75,0.5,1,1\n\
                     1.1,0.25,0.5,0,0.75,0.5,1,0\n\
                     1.2,0.25,0.5,2,0.75,0.5,1,0\n";
        let got = read_all(input);
        assert_eq!(
            got[0].as_ref().ok(),
            Some(
                &GazeSample {
                    validity: 0.75,
                    ..GazeSample::valid(1.0, 0.5, 0.5, Eye::Binocular)
                }
                .with_fixation(Some(true))
            )
        );
        assert_eq!(
            got[1].as_ref().ok(),
            Some(&GazeSample::valid(1.1, 0.75, 0.5, Eye::Binocular).with_fixation(Some(false)))
        );
        let err = got[2].as_ref().expect_err("bad validity");
        assert_eq!((err.line(), err.field()), (4, Some("validity_left")));
        // One side only: monocular, tagged with that eye.
        let right = read_ok(CsvGazeReader::new(
            "t_s,x_right,y_right\n0,0.5,0.5\n".as_bytes(),
        ));
        assert_eq!(right, vec![GazeSample::valid(0.0, 0.5, 0.5, Eye::Right)]);
    }

    #[test]
    fn bad_lines_name_line_and_field_and_reading_goes_on() {
        let input = "t_s,x,y,validity\n\
                     0.0,0.5,0.5,1\n\
                     abc,0.5,0.5,1\n\
                     0.2,0.5,NaN,1\n\
                     0.3,0.5,0.5,2\n\
                     0.4,0.5\n\
                     ,0.5,0.5,1\n\
                     0.5,0.5,0.5,1,9\n\
                     0.6,0.5,0.5,1\n";
        let got = read_all(input);
        assert_eq!(got.len(), 8);
        let errors: Vec<_> = got
            .iter()
            .filter_map(|r| r.as_ref().err())
            .map(|e| (e.line(), e.field()))
            .collect();
        assert_eq!(
            errors,
            vec![
                (3, Some("t_s")),
                (4, Some("y")),
                (5, Some("validity")),
                (6, Some("y")),
                (7, Some("t_s")),
                (8, Some("line")),
            ]
        );
        assert!(matches!(got[7], Ok(s) if s.t_s == 0.6));
        let message = got[1].as_ref().expect_err("bad time").to_string();
        assert_eq!(message, "line 3: field `t_s`: \"abc\" is not a number");
    }

    #[test]
    fn bad_headers_stop_reading() {
        for header in ["time,x,y", "t_s,x,z", "t_s,x,y,x", "t_s,ypos"] {
            let input = format!("# comment\n{header}\n0,0,0\n");
            let got = read_all(&input);
            assert_eq!(got.len(), 1, "{header}");
            let err = got[0].as_ref().expect_err("bad header");
            assert_eq!((err.line(), err.field()), (2, Some("header")), "{header}");
        }
        assert!(read_all("").is_empty());
        assert!(read_all("# only a comment\n\n").is_empty());
        assert!(read_all("t_s,x,y\n").is_empty());
    }

    #[test]
    fn bad_fixation_flag_is_an_error() {
        let got = read_all("t_s,x,y,fixation\n0,0.5,0.5,yes\n");
        let err = got[0].as_ref().expect_err("bad flag");
        assert_eq!((err.line(), err.field()), (2, Some("fixation")));
    }

    #[test]
    fn crlf_input_parses() {
        let samples = read_ok(CsvGazeReader::new("t_s,x,y\r\n1,0.5,0.5\r\n".as_bytes()));
        assert_eq!(
            samples,
            vec![GazeSample::valid(1.0, 0.5, 0.5, Eye::Unspecified)]
        );
    }

    #[test]
    fn writer_output_reads_back() {
        let samples = vec![
            GazeSample::valid(0.1, 0.3, 0.7, Eye::Right).with_fixation(Some(true)),
            GazeSample::missing(0.2, Eye::Right),
            GazeSample {
                validity: 0.25,
                ..GazeSample::valid(0.3, -0.1, 1.2, Eye::Right)
            },
        ];
        let mut out = Vec::new();
        write_normalised(&mut out, samples.clone()).expect("writes");
        let text = String::from_utf8(out).expect("utf-8");
        assert!(
            text.starts_with("t_s,x,y,validity,fixation\n0.1,0.3,0.7,1,1\n0.2,,,0,\n"),
            "{text}"
        );
        let back = read_ok(CsvGazeReader::new(text.as_bytes()).with_eye(Eye::Right));
        assert_eq!(back, samples);
    }

    fn arb_sample() -> impl Strategy<Value = GazeSample> {
        (
            -1e6f64..1e6,
            proptest::num::f64::NORMAL | proptest::num::f64::ZERO | proptest::num::f64::SUBNORMAL,
            -2.0f64..3.0,
            prop_oneof![Just(0.0f32), Just(1.0f32), 0.0f32..=1.0],
            proptest::option::of(any::<bool>()),
        )
            .prop_map(|(t_s, x, y, validity, fixation)| {
                if validity == 0.0 {
                    GazeSample::missing(t_s, Eye::Left).with_fixation(fixation)
                } else {
                    GazeSample {
                        t_s,
                        x,
                        y,
                        validity,
                        eye: Eye::Left,
                        fixation,
                    }
                }
            })
    }

    proptest! {
        #[test]
        fn never_panics_on_arbitrary_lines(lines in proptest::collection::vec(".{0,40}", 0..12)) {
            let input = lines.join("\n");
            for s in CsvGazeReader::new(input.as_bytes()).flatten() {
                prop_assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite());
                prop_assert!((0.0..=1.0).contains(&s.validity));
            }
        }

        #[test]
        fn never_panics_on_arbitrary_data_after_a_header(
            header in prop_oneof![Just("t_s,xpos,ypos,ps"), Just("t_s,x,y,validity,fixation"), Just("x,t_s,y")],
            lines in proptest::collection::vec("[-0-9.,eE naif]{0,30}", 0..12),
        ) {
            let input = format!("# screen 640x480 px\n{header}\n{}", lines.join("\n"));
            let mut count = 0;
            for result in CsvGazeReader::new(input.as_bytes()) {
                count += 1;
                if let Err(err) = result {
                    prop_assert!(err.line() >= 3);
                    prop_assert!(err.field().is_some());
                }
            }
            prop_assert!(count <= lines.len());
        }

        #[test]
        fn normalised_layout_round_trips(samples in proptest::collection::vec(arb_sample(), 0..20)) {
            let mut out = Vec::new();
            write_normalised(&mut out, samples.clone()).expect("writes to memory");
            let back: Vec<_> = CsvGazeReader::new(out.as_slice())
                .with_eye(Eye::Left)
                .collect::<Result<_, _>>()
                .expect("reads back");
            prop_assert_eq!(back, samples);
        }
    }
}
