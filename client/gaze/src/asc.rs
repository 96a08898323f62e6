//! EyeLink ASC files (the text form `edf2asc` writes).
//!
//! Lines used:
//! - `MSG <t> DISPLAY_COORDS x0 y0 x1 y1` (or `GAZE_COORDS`): the screen, first and last pixel.
//! - `SAMPLES GAZE LEFT|RIGHT|LEFT RIGHT ...`: which eyes the sample lines carry.
//! - sample lines `time_ms x y pupil ...` (monocular) or `time_ms xl yl pl xr yr pr ...`
//!   (binocular), `.` for a missing value; a missing sample is kept with validity 0. Binocular
//!   samples become what [`AscReader::with_binocular`] says (default: the mean of the valid eyes).
//! - `SFIX <eye> <start_ms>` and `EFIX <eye> <start_ms> <end_ms> ...`: the tracker's fixations.
//!   Once any fixation event of the recorded eye has been seen, samples carry
//!   `fixation: Some(true)` between a fixation's start and end (inclusive) and `Some(false)`
//!   elsewhere; before that, `None`.
//!
//! Every other line (`START`, `END`, `EVENTS`, other `MSG`s, saccade and blink events, `**`
//! comments, blank lines) is ignored. Timestamps are converted from milliseconds to seconds
//! without changing their origin.

use std::io::BufRead;

use super::{Binocular, Eye, GazeSample, Lines, ParseError, ScreenPx, excerpt, parse_finite};

/// Which eyes the sample lines carry.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Recorded {
    /// No `SAMPLES` line seen: monocular, eye unknown.
    Unknown,
    Left,
    Right,
    Both,
}

/// Fixation state of one eye, in tracker milliseconds.
#[derive(Debug, Clone, Copy, Default)]
struct FixationEvents {
    /// Start of the fixation in progress (after `SFIX`, before its `EFIX`).
    open_since_ms: Option<f64>,
    /// End of the last finished fixation (inclusive).
    last_end_ms: Option<f64>,
}

impl FixationEvents {
    fn contains(&self, t_ms: f64) -> bool {
        self.open_since_ms.is_some_and(|start| t_ms >= start)
            || self.last_end_ms.is_some_and(|end| t_ms <= end)
    }
}

/// Streaming reader of an EyeLink ASC file: an iterator of samples, one per sample line.
///
/// A bad line gives one `Err` and reading goes on; an I/O error ends the iteration.
#[derive(Debug)]
pub struct AscReader<R> {
    lines: Lines<R>,
    screen_given: Option<ScreenPx>,
    screen_found: Option<ScreenPx>,
    recorded: Recorded,
    /// Fixation events of the left and the right eye.
    events: [FixationEvents; 2],
    events_seen: bool,
    binocular: Binocular,
    /// The right eye's sample of a [`Binocular::Both`] line, given on the next call.
    pending: Option<GazeSample>,
}

impl<R: BufRead> AscReader<R> {
    /// A reader of `reader`.
    pub fn new(reader: R) -> Self {
        Self {
            lines: Lines::new(reader),
            screen_given: None,
            screen_found: None,
            recorded: Recorded::Unknown,
            events: [FixationEvents::default(); 2],
            events_seen: false,
            binocular: Binocular::default(),
            pending: None,
        }
    }

    /// How a binocular recording's eyes become samples (default [`Binocular::Mean`]).
    #[must_use]
    pub fn with_binocular(mut self, binocular: Binocular) -> Self {
        self.binocular = binocular;
        self
    }

    /// Use this screen; it wins over any `DISPLAY_COORDS` in the file.
    #[must_use]
    pub fn with_screen(mut self, screen: ScreenPx) -> Self {
        self.screen_given = Some(screen);
        self
    }

    /// The screen in use: the one given, else the last one the file declared so far.
    pub fn screen(&self) -> Option<ScreenPx> {
        self.screen_given.or(self.screen_found)
    }

    /// The eye samples are tagged with, from the last `SAMPLES` line so far.
    pub fn eye(&self) -> Eye {
        match self.recorded {
            Recorded::Unknown => Eye::Unspecified,
            Recorded::Left => Eye::Left,
            Recorded::Right => Eye::Right,
            Recorded::Both => Eye::Binocular,
        }
    }

    /// Handles one line: `Some` for a sample line, `None` for anything else.
    fn parse_line(&mut self, line: usize, text: &str) -> Result<Option<GazeSample>, ParseError> {
        let tokens: Vec<&str> = text.split_whitespace().collect();
        let Some(first) = tokens.first() else {
            return Ok(None);
        };
        if first.starts_with(|c: char| c.is_ascii_digit()) {
            let (sample, second) = self.parse_sample(line, &tokens)?;
            self.pending = second;
            return Ok(Some(sample));
        }
        match *first {
            "MSG" => self.parse_msg(line, &tokens)?,
            "SAMPLES" => self.parse_samples_header(line, &tokens)?,
            "SFIX" => {
                let eye = event_eye(line, &tokens)?;
                let start = parse_finite(line, "start_ms", token(line, &tokens, 2, "start_ms")?)?;
                if self.tracks(eye) {
                    self.events_seen = true;
                    self.events[eye].open_since_ms = Some(start);
                }
            }
            "EFIX" => {
                let eye = event_eye(line, &tokens)?;
                let end = parse_finite(line, "end_ms", token(line, &tokens, 3, "end_ms")?)?;
                if self.tracks(eye) {
                    self.events_seen = true;
                    self.events[eye].open_since_ms = None;
                    self.events[eye].last_end_ms = Some(end);
                }
            }
            _ => {}
        }
        Ok(None)
    }

    /// Whether events of eye index `eye` (0 left, 1 right) describe the recorded samples.
    fn tracks(&self, eye: usize) -> bool {
        match self.recorded {
            Recorded::Unknown | Recorded::Both => true,
            Recorded::Left => eye == 0,
            Recorded::Right => eye == 1,
        }
    }

    fn parse_msg(&mut self, line: usize, tokens: &[&str]) -> Result<(), ParseError> {
        let Some(at) = tokens
            .iter()
            .position(|t| *t == "DISPLAY_COORDS" || *t == "GAZE_COORDS")
        else {
            return Ok(());
        };
        let field = "DISPLAY_COORDS";
        let mut corners = [0.0; 4];
        for (i, corner) in corners.iter_mut().enumerate() {
            *corner = parse_finite(line, field, token(line, tokens, at + 1 + i, field)?)?;
        }
        let [left, top, right, bottom] = corners;
        let screen = ScreenPx::from_corners(left, top, right, bottom).ok_or_else(|| {
            ParseError::InvalidValue {
                line,
                field,
                value: excerpt(&tokens[at + 1..at + 5].join(" ")),
                reason: "is not a screen of positive size",
            }
        })?;
        self.screen_found = Some(screen);
        Ok(())
    }

    fn parse_samples_header(&mut self, line: usize, tokens: &[&str]) -> Result<(), ParseError> {
        let has = |word: &str| tokens.contains(&word);
        if !has("GAZE") {
            return Err(ParseError::InvalidValue {
                line,
                field: "SAMPLES",
                value: excerpt(&tokens.join(" ")),
                reason: "does not carry GAZE (screen) samples; HREF and raw samples are not supported",
            });
        }
        self.recorded = match (has("LEFT"), has("RIGHT")) {
            (true, true) => Recorded::Both,
            (true, false) => Recorded::Left,
            (false, true) => Recorded::Right,
            (false, false) => {
                return Err(ParseError::MissingField {
                    line,
                    field: "SAMPLES eye",
                });
            }
        };
        Ok(())
    }

    /// Whether eye index `eye` (0 left, 1 right; `None` either) is in a fixation at `t_ms`, once
    /// any fixation event has been seen.
    fn in_fixation(&self, eye: Option<usize>, t_ms: f64) -> Option<bool> {
        self.events_seen.then(|| match eye {
            Some(i) => self.events[i].contains(t_ms),
            None => self.events.iter().any(|e| e.contains(t_ms)),
        })
    }

    fn parse_sample(
        &self,
        line: usize,
        tokens: &[&str],
    ) -> Result<(GazeSample, Option<GazeSample>), ParseError> {
        let t_ms = parse_finite(line, "time_ms", tokens[0])?;
        let t_s = t_ms / 1000.0;
        let normalise = |position: Option<(f64, f64)>| -> Result<_, ParseError> {
            let Some((x_px, y_px)) = position else {
                return Ok(None);
            };
            let screen = self
                .screen()
                .ok_or(ParseError::UnknownScreen { line, field: "x" })?;
            let (x, y) = screen.normalise(x_px, y_px);
            Ok(Some((x, y, 1.0)))
        };
        if self.recorded == Recorded::Both {
            let left = normalise(position(line, tokens, 1, ("x_left", "y_left"))?)?;
            let right = normalise(position(line, tokens, 4, ("x_right", "y_right"))?)?;
            let eye = match self.binocular {
                Binocular::Left => Some(0),
                Binocular::Right => Some(1),
                Binocular::Mean | Binocular::Both => None,
            };
            let (first, second) =
                self.binocular
                    .samples(t_s, left, right, self.in_fixation(eye, t_ms));
            // With both eyes given apart, each carries its own eye's fixation flag.
            let second = second.map(|s| s.with_fixation(self.in_fixation(Some(1), t_ms)));
            let first = match second {
                Some(_) => first.with_fixation(self.in_fixation(Some(0), t_ms)),
                None => first,
            };
            return Ok((first, second));
        }
        let eye = self.eye();
        let fixation = self.in_fixation(
            match self.recorded {
                Recorded::Left => Some(0),
                Recorded::Right => Some(1),
                Recorded::Unknown | Recorded::Both => None,
            },
            t_ms,
        );
        let reading = normalise(position(line, tokens, 1, ("x", "y"))?)?;
        let sample = GazeSample::from_reading(t_s, reading, eye, fixation);
        Ok((sample, None))
    }
}

impl<R: BufRead> Iterator for AscReader<R> {
    type Item = Result<GazeSample, ParseError>;

    fn next(&mut self) -> Option<Self::Item> {
        loop {
            if let Some(sample) = self.pending.take() {
                return Some(Ok(sample));
            }
            let (line, text) = match self.lines.next_line()? {
                Ok((line, text)) => (line, text.to_owned()),
                Err(err) => return Some(Err(err)),
            };
            match self.parse_line(line, &text) {
                Ok(None) => {}
                Ok(Some(sample)) => return Some(Ok(sample)),
                Err(err) => return Some(Err(err)),
            }
        }
    }
}

/// Token `index`, or a [`ParseError::MissingField`] naming `field`.
fn token<'a>(
    line: usize,
    tokens: &[&'a str],
    index: usize,
    field: &'static str,
) -> Result<&'a str, ParseError> {
    tokens
        .get(index)
        .copied()
        .ok_or(ParseError::MissingField { line, field })
}

/// Eye index (0 left, 1 right) of an `SFIX`/`EFIX` line.
fn event_eye(line: usize, tokens: &[&str]) -> Result<usize, ParseError> {
    match token(line, tokens, 1, "eye")? {
        "L" => Ok(0),
        "R" => Ok(1),
        other => Err(ParseError::InvalidValue {
            line,
            field: "eye",
            value: excerpt(other),
            reason: "is not L or R",
        }),
    }
}

/// Pixel position at tokens `index`, `index + 1`; `None` if either is `.` (missing).
fn position(
    line: usize,
    tokens: &[&str],
    index: usize,
    (x_field, y_field): (&'static str, &'static str),
) -> Result<Option<(f64, f64)>, ParseError> {
    let x = token(line, tokens, index, x_field)?;
    let y = token(line, tokens, index + 1, y_field)?;
    if x == "." || y == "." {
        return Ok(None);
    }
    Ok(Some((
        parse_finite(line, x_field, x)?,
        parse_finite(line, y_field, y)?,
    )))
}

#[cfg(test)]
mod tests {
    use proptest::prelude::*;

    use super::*;

    const HEAD: &str = "** CONVERTED FROM test.edf\n\
                        MSG\t1000 DISPLAY_COORDS 0 0 1919 1079\n\
                        SAMPLES\tGAZE\tLEFT\tRATE\t1000.00\n";

    fn read(input: &str) -> Vec<Result<GazeSample, ParseError>> {
        AscReader::new(input.as_bytes()).collect()
    }

    fn read_ok(input: &str) -> Vec<GazeSample> {
        AscReader::new(input.as_bytes())
            .collect::<Result<_, _>>()
            .expect("parses")
    }

    #[test]
    fn samples_are_normalised_with_missing_ones_kept() {
        let input = format!(
            "{HEAD}1000\t  960.0\t  540.0\t 1103.0\t...\n\
             1001\t   .\t   .\t    0.0\t...\n\
             START\t1002 \tLEFT\tSAMPLES\tEVENTS\n\
             1002\t0.0\t1079\t1.0\t...\n"
        );
        let samples = read_ok(&input);
        assert_eq!(
            samples,
            vec![
                GazeSample::valid(1.0, 0.5, 0.5, Eye::Left),
                GazeSample::missing(1.001, Eye::Left),
                GazeSample::valid(1.002, 0.0, 1079.0 / 1080.0, Eye::Left),
            ]
        );
    }

    #[test]
    fn fixation_flag_follows_sfix_and_efix() {
        let input = format!(
            "{HEAD}1000 1 1 1 ...\n\
             SFIX L   1001\n\
             1001 1 1 1 ...\n\
             1002 1 1 1 ...\n\
             EFIX L   1001\t1003\t3\t  1.0\t  1.0\t0\n\
             1003 1 1 1 ...\n\
             1004 1 1 1 ...\n\
             SSACC L 1004\n\
             ESACC L 1004 1005 2 1 1 1 1 0.1 10\n\
             SBLINK L 1005\n\
             1005 . . 0 ...\n\
             EBLINK L 1005 1005 1\n\
             SFIX R 1006\n\
             1006 1 1 1 ...\n"
        );
        let flags: Vec<_> = read_ok(&input).iter().map(|s| s.fixation).collect();
        assert_eq!(
            flags,
            vec![
                None,
                Some(true),
                Some(true),
                Some(true),
                Some(false),
                Some(false),
                Some(false)
            ],
            "right-eye events do not count for a left-eye recording"
        );
    }

    #[test]
    fn binocular_samples_average_valid_eyes() {
        let input = "MSG 5 DISPLAY_COORDS 0 0 99 99\n\
                     SAMPLES GAZE LEFT RIGHT RATE 500.00\n\
                     10 10 20 1 30 40 1 .....\n\
                     12 . . 0 30 40 1 .....\n\
                     14 . . 0 . . 0 .....\n\
                     SFIX R 16\n\
                     16 10 10 1 10 10 1 .....\n";
        let samples = read_ok(input);
        // Each eye is normalised, then the valid ones averaged.
        let mean = |a: f64, b: f64| (a / 100.0 + b / 100.0) / 2.0;
        assert_eq!(
            samples[0],
            GazeSample::valid(0.01, mean(10.0, 30.0), mean(20.0, 40.0), Eye::Binocular)
        );
        assert_eq!(
            samples[1],
            GazeSample::valid(0.012, 0.3, 0.4, Eye::Binocular)
        );
        assert_eq!(samples[2], GazeSample::missing(0.014, Eye::Binocular));
        assert_eq!(samples[3].fixation, Some(true));
        assert_eq!(samples.len(), 4);

        // Both eyes apart: two samples per line, each with its own eye's fixation flag.
        let both: Vec<_> = AscReader::new(input.as_bytes())
            .with_binocular(Binocular::Both)
            .collect::<Result<_, _>>()
            .expect("parses");
        assert_eq!(both.len(), 8);
        assert_eq!(both[0], GazeSample::valid(0.01, 0.1, 0.2, Eye::Left));
        assert_eq!(both[1], GazeSample::valid(0.01, 0.3, 0.4, Eye::Right));
        assert_eq!(both[2], GazeSample::missing(0.012, Eye::Left));
        assert_eq!((both[6].eye, both[6].fixation), (Eye::Left, Some(false)));
        assert_eq!((both[7].eye, both[7].fixation), (Eye::Right, Some(true)));

        // One chosen eye.
        let right: Vec<_> = AscReader::new(input.as_bytes())
            .with_binocular(Binocular::Right)
            .collect::<Result<_, _>>()
            .expect("parses");
        assert_eq!(right[1], GazeSample::valid(0.012, 0.3, 0.4, Eye::Right));
        assert_eq!(right[3].fixation, Some(true));
    }

    #[test]
    fn given_screen_wins_and_unknown_screen_is_an_error() {
        let input = "SAMPLES GAZE RIGHT\n1000 50 50 1\n1001 . . 0\n";
        let got = read(input);
        assert!(
            matches!(
                got[0],
                Err(ParseError::UnknownScreen {
                    line: 2,
                    field: "x"
                })
            ),
            "{got:?}"
        );
        assert!(matches!(got[1], Ok(s) if !s.is_valid() && s.eye == Eye::Right));
        let screen = ScreenPx::new(100.0, 200.0).expect("screen");
        let with_coords = format!("MSG 1 DISPLAY_COORDS 0 0 9 9\n{input}");
        let samples: Vec<_> = AscReader::new(with_coords.as_bytes())
            .with_screen(screen)
            .collect::<Result<_, _>>()
            .expect("parses");
        assert_eq!((samples[0].x, samples[0].y), (0.5, 0.25));
    }

    #[test]
    fn bad_lines_name_line_and_field() {
        let input = format!(
            "{HEAD}1000 abc 1 1\n\
             1001 1\n\
             1e999 1 1 1\n\
             SFIX X 1000\n\
             EFIX L 1000\n\
             MSG 1 DISPLAY_COORDS 0 0 -5 10\n\
             MSG 1 DISPLAY_COORDS 0 0\n\
             SAMPLES HREF LEFT\n\
             SAMPLES GAZE\n\
             1002 1 1 1\n"
        );
        let got = read(&input);
        let errors: Vec<_> = got
            .iter()
            .filter_map(|r| r.as_ref().err())
            .map(|e| (e.line(), e.field()))
            .collect();
        assert_eq!(
            errors,
            vec![
                (4, Some("x")),
                (5, Some("y")),
                (6, Some("time_ms")),
                (7, Some("eye")),
                (8, Some("end_ms")),
                (9, Some("DISPLAY_COORDS")),
                (10, Some("DISPLAY_COORDS")),
                (11, Some("SAMPLES")),
                (12, Some("SAMPLES eye")),
            ]
        );
        assert!(
            matches!(got.last(), Some(Ok(s)) if s.t_s == 1.002),
            "reading goes on after errors"
        );
    }

    proptest! {
        #[test]
        fn never_panics_on_arbitrary_lines(lines in proptest::collection::vec(".{0,40}", 0..12)) {
            let input = lines.join("\n");
            for s in AscReader::new(input.as_bytes()).flatten() {
                prop_assert!(s.t_s.is_finite() && s.x.is_finite() && s.y.is_finite());
            }
        }

        #[test]
        fn never_panics_on_asc_like_lines(
            lines in proptest::collection::vec(
                prop_oneof![
                    "[0-9]{1,5}( +[-0-9.e]{1,6}){0,8}",
                    "(SFIX|EFIX|MSG|SAMPLES) ?[LR]?( [-0-9.A-Z_]{1,8}){0,7}",
                ],
                0..16,
            )
        ) {
            let input = format!("{HEAD}{}", lines.join("\n"));
            for result in AscReader::new(input.as_bytes()) {
                if let Err(err) = result {
                    prop_assert!(err.field().is_some() && err.line() > 3);
                }
            }
        }

        #[test]
        fn pixel_samples_round_trip(
            samples in proptest::collection::vec((0u32..100_000, proptest::option::of((0u32..19_200, 0u32..10_800))), 1..30)
        ) {
            let mut text = String::from(HEAD);
            let mut t_ms = 1000;
            let mut expected = Vec::new();
            for (dt, position) in &samples {
                t_ms += dt;
                let t_s = f64::from(t_ms) / 1000.0;
                match position {
                    Some((x10, y10)) => {
                        let (x_px, y_px) = (f64::from(*x10) / 10.0, f64::from(*y10) / 10.0);
                        text.push_str(&format!("{t_ms}\t{x_px:7.1}\t{y_px:7.1}\t 1000.0\t...\n"));
                        expected.push(GazeSample::valid(t_s, x_px / 1920.0, y_px / 1080.0, Eye::Left));
                    }
                    None => {
                        text.push_str(&format!("{t_ms}\t   .\t   .\t    0.0\t...\n"));
                        expected.push(GazeSample::missing(t_s, Eye::Left));
                    }
                }
            }
            prop_assert_eq!(read_ok(&text), expected);
        }
    }
}
