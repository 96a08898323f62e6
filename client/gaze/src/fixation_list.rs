//! Fixation lists as CSV: `eye,start_s,end_s,x_px,y_px`, one fixation a line, `#` comments. The
//! format the tracker's own parser output is shared in (eye 0 = left, 1 = right, 2 = both or
//! unknown) and the one `foveal fixations` prints.

use std::io::BufRead;

use crate::detect::FixationEvent;
use crate::{Eye, Lines, ParseError, ScreenPx, excerpt, parse_finite};

/// The header line.
pub const HEADER: &str = "eye,start_s,end_s,x_px,y_px";

/// One fixation of a list.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ListedFixation {
    /// 0 left, 1 right, 2 both or unknown.
    pub eye: u8,
    /// Start, seconds.
    pub start_s: f64,
    /// End, seconds.
    pub end_s: f64,
    /// Horizontal position, screen pixels.
    pub x_px: f64,
    /// Vertical position, screen pixels.
    pub y_px: f64,
}

/// The list code of an eye.
#[must_use]
pub fn eye_code(eye: Eye) -> u8 {
    match eye {
        Eye::Left => 0,
        Eye::Right => 1,
        Eye::Binocular | Eye::Unspecified => 2,
    }
}

impl ListedFixation {
    /// A detected fixation in pixels of `screen`, its times shifted by `-origin_s`.
    #[must_use]
    pub fn from_event(e: &FixationEvent, screen: ScreenPx, origin_s: f64) -> Self {
        Self {
            eye: eye_code(e.eye),
            start_s: e.start_s - origin_s,
            end_s: e.end_s - origin_s,
            x_px: screen.origin_x + e.x * screen.width,
            y_px: screen.origin_y + e.y * screen.height,
        }
    }

    /// The line, without terminator: times to the millisecond's tenth, positions to 0.1 px.
    #[must_use]
    pub fn to_line(&self) -> String {
        format!(
            "{},{:.4},{:.4},{:.1},{:.1}",
            self.eye, self.start_s, self.end_s, self.x_px, self.y_px
        )
    }
}

/// Reads a fixation list. The first line that is neither blank nor a comment must be
/// [`HEADER`].
///
/// # Errors
/// The first line that does not parse, with its number and field; an end before start.
pub fn read<R: BufRead>(reader: R) -> Result<Vec<ListedFixation>, ParseError> {
    let mut lines = Lines::new(reader);
    let mut header_seen = false;
    let mut out = Vec::new();
    while let Some(item) = lines.next_line() {
        let (line, text) = item?;
        let text = text.trim();
        if text.is_empty() || text.starts_with('#') {
            continue;
        }
        if !header_seen {
            let names: Vec<&str> = text.split(',').map(str::trim).collect();
            if names.join(",") != HEADER {
                return Err(ParseError::Malformed {
                    line,
                    field: "header",
                    reason: format!("expected `{HEADER}`, found {:?}", excerpt(text)),
                });
            }
            header_seen = true;
            continue;
        }
        let fields: Vec<&str> = text.split(',').map(str::trim).collect();
        let get = |i: usize, field: &'static str| {
            fields
                .get(i)
                .copied()
                .ok_or(ParseError::MissingField { line, field })
        };
        let eye = match get(0, "eye")? {
            "0" => 0,
            "1" => 1,
            "2" => 2,
            other => {
                return Err(ParseError::InvalidValue {
                    line,
                    field: "eye",
                    value: excerpt(other),
                    reason: "is not 0 (left), 1 (right) or 2 (both)",
                });
            }
        };
        let start_s = parse_finite(line, "start_s", get(1, "start_s")?)?;
        let end_s = parse_finite(line, "end_s", get(2, "end_s")?)?;
        if end_s < start_s {
            return Err(ParseError::InvalidValue {
                line,
                field: "end_s",
                value: excerpt(fields[2]),
                reason: "is before start_s",
            });
        }
        out.push(ListedFixation {
            eye,
            start_s,
            end_s,
            x_px: parse_finite(line, "x_px", get(3, "x_px")?)?,
            y_px: parse_finite(line, "y_px", get(4, "y_px")?)?,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_what_it_writes_and_names_bad_fields() {
        let f = ListedFixation {
            eye: 0,
            start_s: 0.007,
            end_s: 0.043,
            x_px: 742.0,
            y_px: 550.7,
        };
        let text = format!("# a comment\n{HEADER}\n{}\n", f.to_line());
        assert_eq!(read(text.as_bytes()).expect("parses"), vec![f]);
        let err = read("x,y\n".as_bytes()).expect_err("bad header");
        assert_eq!((err.line(), err.field()), (1, Some("header")));
        let err = read(format!("{HEADER}\n0,1,0.5,1,1\n").as_bytes()).expect_err("end first");
        assert_eq!((err.line(), err.field()), (2, Some("end_s")));
        let err = read(format!("{HEADER}\n3,0,1,1,1\n").as_bytes()).expect_err("eye");
        assert_eq!(err.field(), Some("eye"));
        let err = read(format!("{HEADER}\n0,0,1,1\n").as_bytes()).expect_err("short");
        assert_eq!(err.field(), Some("y_px"));
    }
}
