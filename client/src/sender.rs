//! Sending gaze: one interface over the two gaze rpcs.
//!
//! - [`Transport::Stream`] (`StreamGaze`, client streaming) is the default: one long-lived call,
//!   one message per sample, lowest latency; the server answers once when the stream closes.
//! - [`Transport::Push`] (`PushGaze`, unary) sends batches, for settings that cannot hold a
//!   stream open (scripts behind proxies, browser-like clients). A batch goes out when it is
//!   full or when its oldest sample has waited [`GazeSender::MAX_BATCH_DELAY`], so a slow
//!   tracker does not sit in a half-full batch.
//!
//! Both give one [`SendSummary`]; for batches the server's per-batch rejection indices are
//! turned into indices over everything this sender sent, so the two transports read the same.
//!
//! The server answers with a total of rejections and the first few of them only. So that a
//! summary says why *every* rejected sample was refused, the sender checks each sample it sends
//! with the server's own rules (foveal-gaze's [`Validator`], per stream or per batch as the
//! server applies it) and counts the rejections by reason.

use std::fmt;
use std::time::Duration;

use foveal_proto::pb;
use tokio::sync::mpsc;
use tokio::task::JoinHandle;
use tokio::time::Instant;
use tokio_stream::wrappers::ReceiverStream;

use crate::ClientError;
use crate::gaze::validate::{RejectKind, Validator};
use crate::gaze::{Eye, GazeSample};

/// Which rpc carries the samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Transport {
    /// `StreamGaze`: one client stream for the whole run.
    Stream,
    /// `PushGaze`: unary calls of at most `batch` samples each.
    Push {
        /// Samples per call (>= 1).
        batch: usize,
    },
}

/// One rejected sample.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Rejection {
    /// 0-based index of the sample among all this sender sent.
    pub index: u64,
    /// Offending field of the sample.
    pub field: String,
    /// Why the server refused it.
    pub reason: String,
}

/// What the server made of everything one sender sent.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SendSummary {
    /// Samples handed to the transport (count).
    pub sent: u64,
    /// Samples the server accepted (count).
    pub accepted: u64,
    /// Samples the server rejected (count).
    pub rejected: u64,
    /// Samples the server dropped unread by its gaze rate limit (count).
    pub rate_limited: u64,
    /// The first rejections, in order (capped; `rejected` is exact).
    pub rejections: Vec<Rejection>,
    /// Tracker time of the last accepted sample, seconds; `None` if none was accepted.
    pub last_accepted_time_s: Option<f64>,
    /// Rejections by reason ([`RejectKind::ALL`] order), as this sender counted them by checking
    /// every sample it sent with the server's rules. Equal to the server's counts unless the
    /// server dropped samples by its rate limit (those it never checks).
    pub rejected_by_reason: [u64; RejectKind::ALL.len()],
}

impl SendSummary {
    /// At most this many rejections are kept: enough to see a pattern, bounded for long runs.
    pub const MAX_REJECTIONS: usize = 100;

    /// Adds the server's answer for `sent` samples whose first had global index `offset`.
    fn absorb(
        &mut self,
        offset: u64,
        accepted: u64,
        rejected: u64,
        rejections: Vec<pb::SampleRejection>,
        last_accepted_time_s: f64,
    ) {
        self.accepted += accepted;
        self.rejected += rejected;
        let room = Self::MAX_REJECTIONS.saturating_sub(self.rejections.len());
        self.rejections
            .extend(rejections.into_iter().take(room).map(|r| Rejection {
                index: offset + r.index,
                field: r.field,
                reason: r.reason,
            }));
        if accepted > 0 {
            self.last_accepted_time_s = Some(last_accepted_time_s);
        }
    }
}

impl fmt::Display for SendSummary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "sent {}, accepted {}, rejected {}",
            self.sent, self.accepted, self.rejected
        )?;
        let reasons: Vec<String> = RejectKind::ALL
            .iter()
            .zip(self.rejected_by_reason)
            .filter(|(_, n)| *n > 0)
            .map(|(kind, n)| format!("{} {n}", kind.name()))
            .collect();
        if !reasons.is_empty() {
            write!(f, " ({}", reasons.join(", "))?;
            let counted: u64 = self.rejected_by_reason.iter().sum();
            if counted != self.rejected {
                write!(
                    f,
                    "; counted by this client over all {} samples it sent, the server checked \
                     only those within its rate limit",
                    self.sent
                )?;
            }
            f.write_str(")")?;
        }
        if self.rate_limited > 0 {
            write!(
                f,
                ", rate-limited {} (over the server's gaze rate limit)",
                self.rate_limited
            )?;
        }
        if let Some(t) = self.last_accepted_time_s {
            write!(f, ", last accepted t={t:.3} s")?;
        }
        for r in &self.rejections {
            write!(f, "\n  rejected #{}: {}: {}", r.index, r.field, r.reason)?;
        }
        let unlisted = self.rejected.saturating_sub(self.rejections.len() as u64);
        if unlisted > 0 {
            write!(f, "\n  ... and {unlisted} more rejections")?;
        }
        Ok(())
    }
}

type StreamCall = JoinHandle<Result<tonic::Response<pb::StreamGazeSummary>, tonic::Status>>;

#[derive(Debug)]
enum Inner {
    Stream {
        /// `None` once closed.
        tx: Option<mpsc::Sender<pb::GazeSample>>,
        call: StreamCall,
    },
    Push {
        /// Boxed: a client is large next to the stream's two handles.
        client: Box<crate::Client>,
        source: String,
        batch: usize,
        buf: Vec<pb::GazeSample>,
        /// When the oldest sample in `buf` was queued.
        oldest: Option<Instant>,
    },
}

/// Sends gaze samples over the chosen [`Transport`]; [`GazeSender::finish`] gives the summary.
#[derive(Debug)]
pub struct GazeSender {
    inner: Inner,
    summary: SendSummary,
    /// Samples already answered for (pushed batches).
    answered: u64,
    /// The server's rules, applied here to count rejections by reason: one for the stream, a
    /// new one for each batch (the server checks each batch on its own).
    check: Validator,
}

impl GazeSender {
    /// Longest a sample waits in a partial batch under [`Transport::Push`].
    pub const MAX_BATCH_DELAY: Duration = Duration::from_millis(50);

    /// Largest batch: the server refuses larger `PushGaze` batches (a client that needs more
    /// should stream).
    pub const MAX_BATCH: usize = 10_000;

    /// Samples queued towards the stream before `send` waits for the network: about a second
    /// of a 120 Hz tracker, enough to ride out a hiccup without unbounded memory.
    const STREAM_QUEUE: usize = 256;

    /// Opens a sender. Under [`Transport::Stream`] the call starts now; `source` names the
    /// sender in `PushGaze` requests (the stream has no such field).
    ///
    /// # Errors
    /// [`ClientError::InvalidOption`] for a batch outside 1..=[`Self::MAX_BATCH`].
    ///
    /// # Panics
    /// Under [`Transport::Stream`], when called outside a tokio runtime.
    pub fn open(
        client: crate::Client,
        transport: Transport,
        source: &str,
    ) -> Result<Self, ClientError> {
        let inner = match transport {
            Transport::Stream => {
                let (tx, rx) = mpsc::channel(Self::STREAM_QUEUE);
                let mut client = client;
                let call =
                    tokio::spawn(async move { client.stream_gaze(ReceiverStream::new(rx)).await });
                Inner::Stream { tx: Some(tx), call }
            }
            Transport::Push { batch } if !(1..=Self::MAX_BATCH).contains(&batch) => {
                return Err(ClientError::InvalidOption {
                    name: "batch",
                    reason: format!("must be in 1..={}, not {batch}", Self::MAX_BATCH),
                });
            }
            Transport::Push { batch } => Inner::Push {
                client: Box::new(client),
                source: source.to_owned(),
                batch,
                buf: Vec::with_capacity(batch),
                oldest: None,
            },
        };
        Ok(Self {
            inner,
            summary: SendSummary::default(),
            answered: 0,
            check: Validator::new(),
        })
    }

    /// Samples handed over so far.
    #[must_use]
    pub fn sent(&self) -> u64 {
        self.summary.sent
    }

    /// Sends one sample (queues it, under [`Transport::Push`], until its batch goes out).
    ///
    /// # Errors
    /// [`ClientError::Rpc`] when the stream broke or a push failed.
    pub async fn send(&mut self, sample: GazeSample) -> Result<(), ClientError> {
        let message = to_pb(&sample);
        if let Err(rejection) = self.check.check(&sample) {
            self.summary.rejected_by_reason[rejection.kind.index()] += 1;
        }
        match &mut self.inner {
            Inner::Stream { tx, .. } => {
                let closed = match tx {
                    Some(tx) => tx.send(message).await.is_err(),
                    None => true,
                };
                if closed {
                    // The call ended early; its status says why.
                    *tx = None;
                    return Err(self.stream_failure().await);
                }
                self.summary.sent += 1;
            }
            Inner::Push {
                buf, oldest, batch, ..
            } => {
                buf.push(message);
                self.summary.sent += 1;
                let first_queued = *oldest.get_or_insert_with(Instant::now);
                if buf.len() >= *batch || first_queued.elapsed() >= Self::MAX_BATCH_DELAY {
                    self.flush().await?;
                }
            }
        }
        Ok(())
    }

    /// Pushes the partial batch now (a no-op for the stream, which has no batches).
    ///
    /// # Errors
    /// [`ClientError::Rpc`] when the push failed.
    pub async fn flush(&mut self) -> Result<(), ClientError> {
        let Inner::Push {
            client,
            source,
            buf,
            oldest,
            batch,
        } = &mut self.inner
        else {
            return Ok(());
        };
        *oldest = None;
        if buf.is_empty() {
            return Ok(());
        }
        self.check = Validator::new();
        let samples = std::mem::replace(buf, Vec::with_capacity(*batch));
        let count = samples.len() as u64;
        let request = pb::PushGazeRequest {
            samples,
            source: source.clone(),
        };
        let response = client
            .push_gaze(request)
            .await
            .map_err(|status| ClientError::Rpc {
                rpc: "PushGaze",
                status,
            })?
            .into_inner();
        self.summary.rate_limited += response.rate_limited;
        self.summary.absorb(
            self.answered,
            response.accepted,
            response.rejected,
            response.rejections,
            response.last_accepted_time_s,
        );
        self.answered += count;
        Ok(())
    }

    /// Closes the stream (or pushes the last batch) and returns what the server made of it all.
    ///
    /// # Errors
    /// [`ClientError::Rpc`] when the call failed.
    pub async fn finish(mut self) -> Result<SendSummary, ClientError> {
        self.flush().await?;
        if let Inner::Stream { tx, call } = &mut self.inner {
            tx.take();
            let response = await_call(call).await?;
            let sent = self.summary.sent;
            self.summary.rate_limited += response.rate_limited;
            self.summary.absorb(
                0,
                response.accepted,
                response.rejected,
                response.rejections,
                response.last_accepted_time_s,
            );
            self.answered = sent;
        }
        Ok(self.summary)
    }

    /// The error that ended the stream call early.
    async fn stream_failure(&mut self) -> ClientError {
        let Inner::Stream { call, .. } = &mut self.inner else {
            return ClientError::Rpc {
                rpc: "StreamGaze",
                status: tonic::Status::internal("not a stream"),
            };
        };
        match await_call(call).await {
            Err(err) => err,
            Ok(_) => ClientError::Rpc {
                rpc: "StreamGaze",
                status: tonic::Status::aborted("the server closed the gaze stream early"),
            },
        }
    }
}

async fn await_call(call: &mut StreamCall) -> Result<pb::StreamGazeSummary, ClientError> {
    match call.await {
        Ok(Ok(response)) => Ok(response.into_inner()),
        Ok(Err(status)) => Err(ClientError::Rpc {
            rpc: "StreamGaze",
            status,
        }),
        Err(join) => Err(ClientError::Rpc {
            rpc: "StreamGaze",
            status: tonic::Status::internal(format!("stream task failed: {join}")),
        }),
    }
}

/// A sample as the protocol carries it (`tracker_time_s` is the sample's own time).
#[must_use]
pub fn to_pb(s: &GazeSample) -> pb::GazeSample {
    let eye = match s.eye {
        Eye::Unspecified => pb::Eye::Unspecified,
        Eye::Left => pb::Eye::Left,
        Eye::Right => pb::Eye::Right,
        Eye::Binocular => pb::Eye::Binocular,
    };
    pb::GazeSample {
        tracker_time_s: s.t_s,
        x: s.x,
        y: s.y,
        validity: s.validity,
        eye: eye as i32,
        fixation: s.fixation,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_rejections_get_global_indices_and_are_capped() {
        let mut summary = SendSummary::default();
        let rejection = |index| pb::SampleRejection {
            index,
            field: "x".into(),
            reason: "not finite".into(),
        };
        summary.absorb(0, 9, 1, vec![rejection(3)], 1.5);
        summary.absorb(10, 0, 2, vec![rejection(0), rejection(7)], 0.0);
        assert_eq!((summary.accepted, summary.rejected), (9, 3));
        let indices: Vec<u64> = summary.rejections.iter().map(|r| r.index).collect();
        assert_eq!(indices, vec![3, 10, 17]);
        assert_eq!(
            summary.last_accepted_time_s,
            Some(1.5),
            "a batch with nothing accepted keeps the previous time"
        );
        let many = (0..500).map(rejection).collect();
        summary.absorb(20, 0, 500, many, 0.0);
        assert_eq!(summary.rejections.len(), SendSummary::MAX_REJECTIONS);
        assert_eq!(summary.rejected, 503);
        summary.rejected_by_reason[RejectKind::Missing.index()] = 500;
        summary.rejected_by_reason[RejectKind::CoordNotFinite.index()] = 3;
        let text = summary.to_string();
        assert!(
            text.contains("rejected 503 (missing 500, coord_not_finite 3), last accepted"),
            "{text}"
        );
        assert!(text.contains("rejected #10: x: not finite"), "{text}");
        assert!(text.contains("403 more rejections"), "{text}");
    }
}
