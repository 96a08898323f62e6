//! The forwarding loop: source → pacer → sender, for scripts, replays and live trackers alike.
//!
//! A bridge must outlive bad input: a tracker that sends one garbled line should not end an
//! experiment. So a malformed line is logged (with its line number, to stderr through
//! `tracing`) and counted, and the loop goes on; only a source that fails as a whole (an
//! unreadable file, a tracker that stays unreachable) or the server refusing the stream ends it
//! early. Either way the caller gets a [`BridgeReport`] with the counts and the server's
//! summary, so what was sent is never lost to an error.
//!
//! A file whose every line has the same fault (pixels without a screen size: thousands of
//! lines) must not bury the terminal: only the first line of each kind of fault is logged, and
//! the report counts each kind ([`MalformedKind`]).

use std::fmt;
use std::future::Future;

use tokio::sync::mpsc;
use tracing::{error, warn};

use crate::ClientError;
use crate::gaze::ParseError;
use crate::pacer::{Pace, Pacer};
use crate::sender::{GazeSender, SendSummary};
use crate::source::{SourceError, SourceItem};

/// How [`forward`] paces and limits what it sends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForwardOptions {
    /// Pacing by sample timestamps.
    pub pace: Pace,
    /// Stop before the first sample this many tracker-seconds after the first one; `None` for
    /// the whole source.
    pub duration_s: Option<f64>,
}

impl Default for ForwardOptions {
    /// Whole source, sent as samples arrive (no pacing): right for live sources.
    fn default() -> Self {
        Self {
            pace: Pace::AsFastAsPossible,
            duration_s: None,
        }
    }
}

/// What the source gave.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct BridgeCounts {
    /// Samples with a position (validity > 0) forwarded (count).
    pub valid: u64,
    /// Samples without a position (blink, track loss; validity 0) forwarded (count).
    pub invalid: u64,
    /// Lines that could not be parsed, logged and skipped (count).
    pub malformed: u64,
    /// Times the pacer fell far behind and restarted its timeline (count).
    pub reanchors: u64,
}

impl BridgeCounts {
    /// Samples forwarded, valid or not.
    #[must_use]
    pub fn samples(&self) -> u64 {
        self.valid + self.invalid
    }
}

/// The gaze rate limit of a server left at its defaults, samples per second per stream
/// (`foveal-server --max-gaze-rate`): what a replay is warned about before it starts, since the
/// protocol does not say a server's own limit.
pub const SERVER_DEFAULT_GAZE_RATE_HZ: f64 = 4000.0;
/// The burst that limit lets through at once, samples (a quarter second of the rate).
pub const SERVER_DEFAULT_GAZE_BURST: f64 = 1000.0;

/// What a server at its default gaze rate limit will do to a recording sent at `pace`, said
/// before sending so that a replay does not quietly lose most of its samples: `None` when the
/// pace stays under the limit (or the recording's rate is unknown and it is paced).
#[must_use]
pub fn pace_warning(
    pace: Pace,
    rate_hz: Option<f64>,
    samples: u64,
    complete: bool,
) -> Option<String> {
    let limit = SERVER_DEFAULT_GAZE_RATE_HZ;
    let of_file = match (rate_hz, complete) {
        (Some(r), true) => format!("its {samples} samples at {r:.0} Hz"),
        (Some(r), false) => format!("its samples at {r:.0} Hz"),
        (None, _) => "its samples".to_owned(),
    };
    match pace {
        Pace::AsFastAsPossible => {
            if complete && samples as f64 <= SERVER_DEFAULT_GAZE_BURST {
                return None;
            }
            let paced = match rate_hz {
                Some(r) => format!(
                    "; paced (the default, or --speed up to {:.1}) it stays under the limit",
                    limit / r
                ),
                None => String::new(),
            };
            Some(format!(
                "sending without pacing: a server keeps at most its gaze rate limit per stream \
                 (by default {limit:.0} samples/s after a first burst of {SERVER_DEFAULT_GAZE_BURST:.0}; \
                 foveal-server --max-gaze-rate) and drops the rest unread, counted as \
                 rate-limited, so {of_file} will mostly be dropped unless the server's limit is \
                 raised{paced}"
            ))
        }
        Pace::Scaled { speed } => {
            let r = rate_hz?;
            (r * speed > limit).then(|| {
                format!(
                    "at --speed {speed} this recording sends {:.0} samples/s ({of_file}), over \
                     a server's default gaze rate limit of {limit:.0} per stream: the excess will \
                     be dropped unread, counted as rate-limited; use --speed {:.1} or less, or \
                     raise the server's --max-gaze-rate",
                    r * speed,
                    limit / r
                )
            })
        }
    }
}

/// One kind of malformed input (the parser's fault and its field) and how often it came.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct MalformedKind {
    /// The field at fault, or `line` when the whole line is.
    pub field: &'static str,
    /// Lines skipped for it (count).
    pub count: u64,
    /// The first such error, as logged (it names its line).
    pub first: String,
}

/// The kinds of malformed input seen, in order of first appearance.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MalformedTally {
    kinds: Vec<(ParseKind, MalformedKind)>,
}

/// The variant of a parse error, so that lines differing only in number and value count as one.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum ParseKind {
    MissingField,
    InvalidNumber,
    InvalidValue,
    UnknownScreen,
    Malformed,
    Io,
}

impl MalformedTally {
    /// Counts `err`; true when it is the first of its kind (so the caller logs it).
    pub fn add(&mut self, err: &ParseError) -> bool {
        let kind = match err {
            ParseError::MissingField { .. } => ParseKind::MissingField,
            ParseError::InvalidNumber { .. } => ParseKind::InvalidNumber,
            ParseError::InvalidValue { .. } => ParseKind::InvalidValue,
            ParseError::UnknownScreen { .. } => ParseKind::UnknownScreen,
            ParseError::Malformed { .. } => ParseKind::Malformed,
            ParseError::Io { .. } => ParseKind::Io,
        };
        let field = err.field().unwrap_or("line");
        if let Some((_, seen)) = self
            .kinds
            .iter_mut()
            .find(|(k, m)| *k == kind && m.field == field)
        {
            seen.count += 1;
            return false;
        }
        self.kinds.push((
            kind,
            MalformedKind {
                field,
                count: 1,
                first: err.to_string(),
            },
        ));
        true
    }

    /// The kinds, in order of first appearance.
    pub fn kinds(&self) -> impl Iterator<Item = &MalformedKind> {
        self.kinds.iter().map(|(_, m)| m)
    }
}

/// Why forwarding stopped.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum StopReason {
    /// The source ended (end of file, tracker closed the connection).
    EndOfInput,
    /// `duration_s` was reached.
    Duration,
    /// The shutdown future completed (Ctrl-C).
    Shutdown,
    /// The source failed as a whole; the message says how.
    SourceFailed(String),
}

impl fmt::Display for StopReason {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::EndOfInput => f.write_str("end of input"),
            Self::Duration => f.write_str("duration reached"),
            Self::Shutdown => f.write_str("interrupted"),
            Self::SourceFailed(why) => write!(f, "source failed: {why}"),
        }
    }
}

/// The outcome of [`forward`].
#[derive(Debug, Clone, PartialEq)]
pub struct BridgeReport {
    /// What the source gave.
    pub counts: BridgeCounts,
    /// What the server made of it.
    pub summary: SendSummary,
    /// Why forwarding stopped.
    pub stopped: StopReason,
    /// The malformed lines by kind.
    pub malformed: MalformedTally,
}

impl BridgeReport {
    /// Why the source sent nothing, when it sent nothing although it ended normally: a file or
    /// stream with no usable line is a failure to say, not a quiet success.
    #[must_use]
    pub fn nothing_sent(&self) -> Option<String> {
        if self.counts.samples() > 0 || self.stopped != StopReason::EndOfInput {
            return None;
        }
        Some(match self.malformed.kinds().next() {
            None => "the input ended without a gaze sample (no data line)".to_owned(),
            Some(first) => format!(
                "the input ended without a gaze sample: all {} of its data lines were skipped; \
                 the first: {}",
                self.counts.malformed, first.first
            ),
        })
    }
}

impl fmt::Display for BridgeReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let c = &self.counts;
        write!(
            f,
            "stopped: {}\nsource: {} samples ({} valid, {} invalid), {} malformed lines skipped",
            self.stopped,
            c.samples(),
            c.valid,
            c.invalid,
            c.malformed
        )?;
        if c.reanchors > 0 {
            write!(f, ", fell behind real time {} times", c.reanchors)?;
        }
        for kind in self.malformed.kinds() {
            write!(f, "\n  {} skipped like {}", kind.count, kind.first)?;
        }
        write!(f, "\nserver: {}", self.summary)
    }
}

/// Forwards `source` into `sender`, paced and limited by `options`, until the source ends, the
/// duration is reached or `shutdown` completes; then closes the sender and reports.
///
/// # Errors
/// [`ClientError::Rpc`] when the server broke the stream or refused a push (what was counted
/// until then is logged).
pub async fn forward(
    mut source: mpsc::Receiver<SourceItem>,
    mut sender: GazeSender,
    options: ForwardOptions,
    shutdown: impl Future<Output = ()>,
) -> Result<BridgeReport, ClientError> {
    let mut pacer = Pacer::new(options.pace);
    let mut counts = BridgeCounts::default();
    let mut malformed = MalformedTally::default();
    let mut first_t_s: Option<f64> = None;
    tokio::pin!(shutdown);
    let stopped = loop {
        let item = tokio::select! {
            biased;
            () = &mut shutdown => break StopReason::Shutdown,
            item = source.recv() => item,
        };
        let sample = match item {
            None => break StopReason::EndOfInput,
            Some(Ok(sample)) => sample,
            Some(Err(SourceError::Parse(err))) => {
                counts.malformed += 1;
                if malformed.add(&err) {
                    warn!(
                        line = err.line(),
                        field = err.field(),
                        "skipping malformed input: {err} (further lines with this fault are \
                         counted, not logged)"
                    );
                }
                continue;
            }
            Some(Err(err @ SourceError::Io { .. })) => {
                error!("{err}");
                break StopReason::SourceFailed(err.to_string());
            }
        };
        if let Some(limit) = options.duration_s {
            let t0 = *first_t_s.get_or_insert(sample.t_s);
            if sample.t_s - t0 >= limit {
                break StopReason::Duration;
            }
        }
        tokio::select! {
            biased;
            () = &mut shutdown => break StopReason::Shutdown,
            () = pacer.wait(sample.t_s) => {}
        }
        if let Err(err) = sender.send(sample).await {
            error!(
                valid = counts.valid,
                invalid = counts.invalid,
                malformed = counts.malformed,
                "sending stopped: {err}"
            );
            return Err(err);
        }
        if sample.is_valid() {
            counts.valid += 1;
        } else {
            counts.invalid += 1;
        }
    };
    counts.reanchors = pacer.reanchors();
    for kind in malformed.kinds().filter(|k| k.count > 1) {
        warn!(
            count = kind.count,
            field = kind.field,
            "skipped {} lines like {}",
            kind.count,
            kind.first
        );
    }
    let summary = sender.finish().await?;
    Ok(BridgeReport {
        counts,
        summary,
        stopped,
        malformed,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn malformed_lines_are_counted_by_kind_and_logged_once_each() {
        let mut tally = MalformedTally::default();
        let screen = |line| ParseError::UnknownScreen {
            line,
            field: "xpos",
        };
        assert!(tally.add(&screen(2)), "the first is logged");
        for line in 3..2001 {
            assert!(!tally.add(&screen(line)), "repeats are counted, not logged");
        }
        let number = ParseError::InvalidNumber {
            line: 7,
            field: "x",
            value: "oops".into(),
        };
        assert!(tally.add(&number));
        let kinds: Vec<_> = tally.kinds().map(|k| (k.field, k.count)).collect();
        assert_eq!(kinds, vec![("xpos", 1999), ("x", 1)]);
        assert!(
            tally
                .kinds()
                .next()
                .is_some_and(|k| k.first.starts_with("line 2:"))
        );
    }

    #[test]
    fn pacing_over_the_default_rate_limit_is_said_up_front() {
        let unpaced =
            pace_warning(Pace::AsFastAsPossible, Some(1000.0), 66_800, true).expect("a warning");
        assert!(unpaced.contains("66800 samples at 1000 Hz"), "{unpaced}");
        assert!(unpaced.contains("--speed up to 4.0"), "{unpaced}");
        assert_eq!(
            pace_warning(Pace::AsFastAsPossible, Some(1000.0), 500, true),
            None
        );
        assert_eq!(
            pace_warning(Pace::REAL_TIME, Some(1000.0), 66_800, true),
            None
        );
        let fast = pace_warning(Pace::Scaled { speed: 8.0 }, Some(1000.0), 66_800, true)
            .expect("over the limit");
        assert!(fast.contains("8000 samples/s"), "{fast}");
    }
}
