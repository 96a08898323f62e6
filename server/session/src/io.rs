//! Writing and reading session files over writers and readers handed in (no files opened here).
//!
//! Reading is strict: a session that replays must be complete, so a line that does not parse, a
//! header of another format or version, frames out of order, a scene change that is not at the
//! next frame, records after the trailer or a missing trailer are errors naming the line.

use std::io::{BufRead, Write};

use crate::format::{
    FORMAT, FrameRecord, GazeRecord, Header, Record, SceneRecord, Trailer, VERSION,
};

/// Why a session could not be written or read.
#[derive(Debug, thiserror::Error)]
pub enum SessionError {
    /// The writer or reader failed.
    #[error("session I/O: {0}")]
    Io(#[from] std::io::Error),
    /// A record could not be encoded (a float that JSON cannot hold, for instance).
    #[error("encoding a session record: {0}")]
    Encode(#[source] serde_json::Error),
    /// [`SessionWriter::write`] was handed a trailer: the counts it holds are the writer's.
    #[error("the trailer is written by SessionWriter::finish, not write")]
    TrailerByWrite,
    /// A line is not a record of this format (or is cut short).
    #[error("session line {line}: {reason}")]
    Line {
        /// 1-based line number.
        line: u64,
        /// What is wrong with it.
        reason: String,
    },
}

fn at(line: u64, reason: impl Into<String>) -> SessionError {
    SessionError::Line {
        line,
        reason: reason.into(),
    }
}

/// Writes a session: the header at once, then records, then the trailer.
#[derive(Debug)]
pub struct SessionWriter<W: Write> {
    out: W,
    counts: Trailer,
}

impl<W: Write> SessionWriter<W> {
    /// Write `header` to `out` and flush it, so that a file that cannot take even that fails
    /// before anything else happens.
    pub fn new(mut out: W, header: &Header) -> Result<Self, SessionError> {
        serde_json::to_writer(&mut out, header).map_err(SessionError::Encode)?;
        out.write_all(b"\n")?;
        out.flush()?;
        Ok(Self {
            out,
            counts: Trailer {
                frames: 0,
                gaze_samples: 0,
                scenes: 0,
                dropped: 0,
            },
        })
    }

    /// Append one record (a trailer given here is refused: use [`Self::finish`]).
    pub fn write(&mut self, record: &Record) -> Result<(), SessionError> {
        match record {
            Record::Gaze(_) => self.counts.gaze_samples += 1,
            Record::Frame(_) => self.counts.frames += 1,
            Record::Scene(_) => self.counts.scenes += 1,
            Record::End(_) => return Err(SessionError::TrailerByWrite),
        }
        serde_json::to_writer(&mut self.out, record).map_err(SessionError::Encode)?;
        self.out.write_all(b"\n")?;
        Ok(())
    }

    /// Write the trailer with `dropped` records lost before the writer, flush, and hand the
    /// writer back with what was written.
    pub fn finish(mut self, dropped: u64) -> Result<(W, Trailer), SessionError> {
        self.counts.dropped = dropped;
        let end = Record::End(self.counts);
        serde_json::to_writer(&mut self.out, &end).map_err(SessionError::Encode)?;
        self.out.write_all(b"\n")?;
        self.out.flush()?;
        Ok((self.out, self.counts))
    }
}

/// A whole session, read back.
#[derive(Debug, Clone, PartialEq)]
pub struct Session {
    /// The first line.
    pub header: Header,
    /// Gaze samples, in order.
    pub gaze: Vec<GazeRecord>,
    /// Frames, in order.
    pub frames: Vec<FrameRecord>,
    /// Scene changes, in order.
    pub scenes: Vec<SceneRecord>,
    /// The last line.
    pub trailer: Trailer,
}

impl Session {
    /// Read a session, checking it line by line (see the module documentation).
    pub fn read(input: impl BufRead) -> Result<Self, SessionError> {
        let mut lines = input.lines();
        let first = lines
            .next()
            .ok_or_else(|| at(1, "the file is empty: expected the session header"))??;
        let header: Header = serde_json::from_str(&first)
            .map_err(|e| at(1, format!("not a session header: {e}")))?;
        if header.format != FORMAT {
            return Err(at(
                1,
                format!("format `{}` is not `{FORMAT}`", header.format),
            ));
        }
        if header.version != VERSION {
            return Err(at(
                1,
                format!(
                    "version {} is not supported (this build reads version {VERSION})",
                    header.version
                ),
            ));
        }
        let mut session = Self {
            header,
            gaze: Vec::new(),
            frames: Vec::new(),
            scenes: Vec::new(),
            trailer: Trailer {
                frames: 0,
                gaze_samples: 0,
                scenes: 0,
                dropped: 0,
            },
        };
        let mut trailer: Option<(u64, Trailer)> = None;
        for (i, line) in lines.enumerate() {
            let n = i as u64 + 2;
            let line = line?;
            if let Some((end_line, _)) = trailer {
                return Err(at(
                    n,
                    format!("a record after the trailer on line {end_line}"),
                ));
            }
            let record: Record = serde_json::from_str(&line)
                .map_err(|e| at(n, format!("not a session record: {e}")))?;
            match record {
                Record::Gaze(g) => session.gaze.push(g),
                Record::Frame(f) => {
                    if let Some(last) = session.frames.last()
                        && f.index <= last.index
                    {
                        return Err(at(
                            n,
                            format!(
                                "frame {} does not follow frame {}: frames must increase",
                                f.index, last.index
                            ),
                        ));
                    }
                    session.frames.push(*f);
                }
                Record::Scene(s) => {
                    let next = session.frames.last().map_or(0, |f| f.index + 1);
                    if s.first_frame < next {
                        return Err(at(
                            n,
                            format!(
                                "scene change at frame {} after frame {} was recorded",
                                s.first_frame,
                                next.saturating_sub(1)
                            ),
                        ));
                    }
                    session.scenes.push(*s);
                }
                Record::End(t) => trailer = Some((n, t)),
            }
        }
        let Some((end_line, t)) = trailer else {
            let last = session.gaze.len() + session.frames.len() + session.scenes.len() + 1;
            return Err(at(
                last as u64,
                "the session ends here without its trailer (an `end` record): the recording was cut short",
            ));
        };
        let found = (
            session.frames.len() as u64,
            session.gaze.len() as u64,
            session.scenes.len() as u64,
        );
        if found != (t.frames, t.gaze_samples, t.scenes) {
            return Err(at(
                end_line,
                format!(
                    "the trailer counts {} frames, {} gaze samples and {} scenes but the file holds {}, {} and {}",
                    t.frames, t.gaze_samples, t.scenes, found.0, found.1, found.2
                ),
            ));
        }
        session.trailer = t;
        Ok(session)
    }
}
