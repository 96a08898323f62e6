//! The forwarding loop: source → pacer → sender, for scripts, replays and live trackers alike.
//!
//! A bridge must outlive bad input: a tracker that sends one garbled line should not end an
//! experiment. So a malformed line is logged (with its line number, to stderr through
//! `tracing`) and counted, and the loop goes on; only a source that fails as a whole (an
//! unreadable file, a tracker that stays unreachable) or the server refusing the stream ends it
//! early. Either way the caller gets a [`BridgeReport`] with the counts and the server's
//! summary, so what was sent is never lost to an error.

use std::fmt;
use std::future::Future;

use tokio::sync::mpsc;
use tracing::{error, warn};

use crate::ClientError;
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
                warn!(
                    line = err.line(),
                    field = err.field(),
                    "skipping malformed input: {err}"
                );
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
    let summary = sender.finish().await?;
    Ok(BridgeReport {
        counts,
        summary,
        stopped,
    })
}
