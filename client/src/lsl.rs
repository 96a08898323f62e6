//! A Lab Streaming Layer outlet as a source, over LSL's own wire protocol (no liblsl needed).
//!
//! The steps are those of a liblsl inlet (see [`crate::gaze::lsl`] for the formats): resolve the
//! stream by UDP query, estimate the outlet's clock offset with time probes to its UDP service
//! port, open the TCP stream feed, check the two test-pattern samples, then read samples until
//! the outlet closes the feed. Every time stamp has the latest clock correction added, so it is
//! on this machine's LSL clock (the monotonic clock, as liblsl's `local_clock()`), whichever
//! machine the outlet runs on; the probes are repeated every [`TIME_PROBE_INTERVAL`] in the
//! background so that drift is followed. Chunks stamped once are timed per sample by
//! [`SampleClock`].
//!
//! An outlet that goes away (its program closed or crashed, its feed reset) is waited for, as a
//! liblsl inlet with recovery does: the stream is looked for again by name, type and source id,
//! and the bridge says when it is back. With [`LslOptions::reconnect`] off, the outlet going away
//! ends the source with an error instead, so that a script sees a failure rather than success.

use std::io;
use std::net::{IpAddr, SocketAddr};
use std::time::Duration;

use tokio::io::{AsyncBufReadExt, AsyncRead, AsyncReadExt, AsyncWriteExt, BufReader};
use tokio::net::{TcpStream, UdpSocket};
use tokio::sync::{mpsc, watch};
use tracing::{debug, info, warn};

use crate::gaze::lsl::{
    self, ChannelMap, FeedResponse, LslError, SampleClock, StreamInfo, TAG_DEDUCED_TIMESTAMP,
    TAG_TRANSMITTED_TIMESTAMP, TEST_PATTERN_TIMESTAMP, TimeProbe,
};
use crate::source::{CHANNEL_CAPACITY, SourceError, SourceItem};

/// Time between two rounds of clock probes.
pub const TIME_PROBE_INTERVAL: Duration = Duration::from_secs(5);
/// Probes per round, and the wait between two (liblsl's `TimeProbeCount`, `TimeProbeInterval`).
const PROBES: u32 = 8;
const PROBE_GAP: Duration = Duration::from_millis(64);
/// How long the last probe of a round may take to come back (liblsl's `TimeProbeMaxRTT`).
const PROBE_MAX_RTT: Duration = Duration::from_millis(128);
/// Longest feed response header accepted.
const MAX_HEADER_BYTES: usize = 16 * 1024;

/// Which stream to take and how to read it.
#[derive(Debug, Clone)]
pub struct LslOptions {
    /// Content type of the stream (`type`).
    pub type_: String,
    /// Stream name, if the type alone is ambiguous.
    pub name: Option<String>,
    /// Channels holding x and y, and their units.
    pub channels: ChannelMap,
    /// How long to look for the stream, and to connect to it.
    pub resolve_timeout: Duration,
    /// Where resolve queries go (port [`lsl::MULTICAST_PORT`]).
    pub resolve_addresses: Vec<IpAddr>,
    /// Add the outlet's clock correction to its time stamps.
    pub time_correction: bool,
    /// When the outlet goes away, wait for it to come back (true) or end with an error (false).
    pub reconnect: bool,
}

impl Default for LslOptions {
    fn default() -> Self {
        Self {
            type_: "Gaze".into(),
            name: None,
            channels: ChannelMap::default(),
            resolve_timeout: Duration::from_secs(5),
            resolve_addresses: lsl::RESOLVE_ADDRESSES
                .iter()
                .filter_map(|a| a.parse().ok())
                .collect(),
            time_correction: true,
            reconnect: true,
        }
    }
}

impl LslOptions {
    /// What is being looked for, as errors name it: `type='Gaze'` (and `name='...'`).
    #[must_use]
    pub fn describe(&self) -> String {
        match &self.name {
            Some(name) => format!("LSL stream type={:?} name={name:?}", self.type_),
            None => format!("LSL stream type={:?}", self.type_),
        }
    }
}

/// Seconds on this machine's LSL clock: `CLOCK_MONOTONIC`, as liblsl's `local_clock()`.
#[must_use]
pub fn local_clock() -> f64 {
    let now = rustix::time::clock_gettime(rustix::time::ClockId::Monotonic);
    now.tv_sec as f64 + now.tv_nsec as f64 * 1e-9
}

/// An LSL outlet as a source. A stream that cannot be found, reached or understood ends the
/// source with one [`SourceError::Io`] that says which. The outlet closing its feed is waited
/// out until it comes back ([`LslOptions::reconnect`]), or ends the source with an error. NaN or
/// infinite gaze channels are forwarded as missing samples.
///
/// # Panics
/// When called outside a tokio runtime.
#[must_use]
pub fn lsl(options: LslOptions) -> mpsc::Receiver<SourceItem> {
    let (tx, rx) = mpsc::channel(CHANNEL_CAPACITY);
    tokio::spawn(async move {
        let what = options.describe();
        if let Err(source) = run(&options, &tx).await {
            let _ = tx.send(Err(SourceError::Io { what, source })).await;
        }
    });
    rx
}

fn invalid(err: impl std::fmt::Display) -> io::Error {
    io::Error::new(io::ErrorKind::InvalidData, err.to_string())
}

/// A query id unlikely to be another inlet's: the clock's nanoseconds and the process id.
fn query_id() -> String {
    let now = rustix::time::clock_gettime(rustix::time::ClockId::Realtime);
    format!("{}{}", now.tv_nsec, std::process::id())
}

/// Sends the resolve query every half second until a matching outlet answers or the resolve
/// timeout passes; gives its stream info and the address to reach it at.
///
/// # Errors
/// No outlet answered in time, a value cannot be put in a query, or the socket failed.
pub async fn resolve(options: &LslOptions) -> io::Result<(StreamInfo, IpAddr)> {
    let query = lsl::query(&options.type_, options.name.as_deref()).map_err(invalid)?;
    resolve_query(options, &query).await
}

/// [`resolve`] with a query of the caller's.
async fn resolve_query(options: &LslOptions, query: &str) -> io::Result<(StreamInfo, IpAddr)> {
    let socket = UdpSocket::bind("0.0.0.0:0").await?;
    socket.set_broadcast(true)?;
    let id = query_id();
    let request = lsl::shortinfo_request(query, socket.local_addr()?.port(), &id);
    let deadline = tokio::time::Instant::now() + options.resolve_timeout;
    let mut buf = vec![0u8; 65_536];
    loop {
        for addr in &options.resolve_addresses {
            let target = SocketAddr::new(*addr, lsl::MULTICAST_PORT);
            if let Err(err) = socket.send_to(request.as_bytes(), target).await {
                debug!(%target, error = %err, "resolve query not sent");
            }
        }
        let wave_end = (tokio::time::Instant::now() + Duration::from_millis(500)).min(deadline);
        while let Ok(received) = tokio::time::timeout_at(wave_end, socket.recv_from(&mut buf)).await
        {
            let (n, from) = received?;
            let text = String::from_utf8_lossy(&buf[..n]);
            match lsl::parse_resolve_reply(&text, &id) {
                Ok(Some(info)) => {
                    let addr = info.v4address.parse().unwrap_or(from.ip());
                    return Ok((info, addr));
                }
                Ok(None) => {}
                Err(err) => warn!(%from, "ignoring an outlet's reply: {err}"),
            }
        }
        if tokio::time::Instant::now() >= deadline {
            return Err(io::Error::new(
                io::ErrorKind::NotFound,
                format!(
                    "no outlet answered within {:?} (query {query:?} to port {})",
                    options.resolve_timeout,
                    lsl::MULTICAST_PORT
                ),
            ));
        }
    }
}

/// One round of clock probes to the outlet's time service (`v4service_port`): the best probe's
/// correction, to add to the outlet's time stamps, or `None` when no probe came back.
///
/// # Errors
/// The UDP socket cannot be opened or used.
pub async fn probe_clock(service: SocketAddr) -> io::Result<Option<f64>> {
    let socket = UdpSocket::bind("0.0.0.0:0").await?;
    socket.connect(service).await?;
    // liblsl reads the wave id as a C `int`: larger ids would come back garbled.
    let wave =
        (std::process::id().wrapping_mul(7919) ^ local_clock().to_bits() as u32) & 0x3fff_ffff;
    let mut probes = Vec::new();
    let mut buf = [0u8; 512];
    for k in 0..PROBES {
        let wave_id = wave.wrapping_add(k);
        socket
            .send(lsl::timedata_request(wave_id, local_clock()).as_bytes())
            .await?;
        let wait = if k + 1 == PROBES {
            PROBE_MAX_RTT
        } else {
            PROBE_GAP
        };
        let until = tokio::time::Instant::now() + wait;
        while let Ok(Ok(n)) = tokio::time::timeout_at(until, socket.recv(&mut buf)).await {
            let t3 = local_clock();
            let reply = String::from_utf8_lossy(&buf[..n]);
            // Late replies to earlier probes of this round count too.
            if let Some(probe) =
                (0..=k).find_map(|j| TimeProbe::from_reply(&reply, wave.wrapping_add(j), t3))
            {
                probes.push(probe);
            }
        }
    }
    Ok(lsl::best_probe(&probes).map(|p| p.correction()))
}

/// Probes the clock every [`TIME_PROBE_INTERVAL`] and publishes the correction, until nobody
/// reads it.
async fn follow_clock(service: SocketAddr, tx: watch::Sender<f64>) {
    loop {
        tokio::select! {
            () = tx.closed() => return,
            () = tokio::time::sleep(TIME_PROBE_INTERVAL) => {}
        }
        match probe_clock(service).await {
            Ok(Some(correction)) => {
                debug!(correction_s = correction, "LSL clock correction");
                let _ = tx.send(correction);
            }
            Ok(None) => debug!(%service, "no clock probe answered; keeping the last correction"),
            Err(err) => debug!(%service, error = %err, "clock probe failed"),
        }
    }
}

/// Reads one sample: its time (on the outlet's clock, before correction, from `clock`) and
/// channel values.
async fn read_sample<R: AsyncRead + Unpin>(
    reader: &mut R,
    info: &StreamInfo,
    response: FeedResponse,
    clock: &mut SampleClock,
    values: &mut Vec<u8>,
) -> io::Result<(f64, Vec<f64>)> {
    let timestamp = match reader.read_u8().await? {
        TAG_DEDUCED_TIMESTAMP => clock.deduced(),
        TAG_TRANSMITTED_TIMESTAMP => {
            let mut raw = [0u8; 8];
            reader.read_exact(&mut raw).await?;
            clock.transmitted(if response.big_endian {
                f64::from_be_bytes(raw)
            } else {
                f64::from_le_bytes(raw)
            })
        }
        other => return Err(invalid(LslError::Tag(other))),
    };
    values.resize(info.channel_count * info.channel_format.value_bytes(), 0);
    reader.read_exact(values).await?;
    Ok((
        timestamp,
        lsl::decode_values(info.channel_format, values, response),
    ))
}

/// How one connection to an outlet ended, other than by an error.
enum SessionEnd {
    /// The outlet closed its feed.
    Closed,
    /// Nobody reads the source any more.
    ReceiverGone,
}

/// Whether an error of a session means the outlet went away (and may come back), rather than a
/// stream this bridge cannot read.
fn outlet_gone(err: &io::Error) -> bool {
    use io::ErrorKind::{
        BrokenPipe, ConnectionAborted, ConnectionRefused, ConnectionReset, TimedOut, UnexpectedEof,
    };
    matches!(
        err.kind(),
        UnexpectedEof
            | ConnectionReset
            | ConnectionAborted
            | BrokenPipe
            | ConnectionRefused
            | TimedOut
    )
}

async fn run(options: &LslOptions, tx: &mpsc::Sender<SourceItem>) -> io::Result<()> {
    let (mut info, mut addr) = resolve(options).await?;
    // When the outlet went away, if it did: the next session says when it is back.
    let mut lost: Option<tokio::time::Instant> = None;
    loop {
        options
            .channels
            .check(info.channel_count)
            .map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e.to_string()))?;
        info!(
            name = %info.name, source_id = %info.source_id, %addr, port = info.v4data_port,
            channels = info.channel_count, format = %info.channel_format, srate = info.nominal_srate,
            "found the LSL stream"
        );
        let why = match session(options, &info, addr, tx, lost.take()).await {
            Ok(SessionEnd::ReceiverGone) => return Ok(()),
            Ok(SessionEnd::Closed) => "the outlet closed the stream".to_owned(),
            Err(err) if outlet_gone(&err) => format!("the outlet went away ({err})"),
            Err(err) => return Err(err),
        };
        let data = SocketAddr::new(addr, info.v4data_port);
        if !options.reconnect {
            return Err(io::Error::new(
                io::ErrorKind::ConnectionAborted,
                format!("{why} at {data}; not waiting for it to come back (--no-reconnect)"),
            ));
        }
        let query =
            lsl::recovery_query(&info, &options.type_, options.name.as_deref()).map_err(invalid)?;
        warn!(%data, "{why}; waiting for it to come back ({query})");
        let since = lost.unwrap_or_else(tokio::time::Instant::now);
        lost = Some(since);
        (info, addr) = loop {
            let found = tokio::select! {
                () = tx.closed() => return Ok(()),
                found = resolve_query(options, &query) => found,
            };
            match found {
                Ok(found) => break found,
                Err(err) if err.kind() == io::ErrorKind::NotFound => {}
                Err(err) => return Err(err),
            }
        };
    }
}

/// One connection to an outlet: clock probes, the feed handshake, then samples until the outlet
/// closes the feed or nobody reads the source.
async fn session(
    options: &LslOptions,
    info: &StreamInfo,
    addr: IpAddr,
    tx: &mpsc::Sender<SourceItem>,
    lost: Option<tokio::time::Instant>,
) -> io::Result<SessionEnd> {
    let (correction_tx, correction) = watch::channel(0.0);
    if options.time_correction {
        let service = SocketAddr::new(addr, info.v4service_port);
        match probe_clock(service).await {
            Ok(Some(c)) => {
                info!(correction_s = c, "LSL clock correction");
                correction_tx.send_replace(c);
            }
            Ok(None) => warn!(
                %service,
                "the outlet's time service did not answer; time stamps stay on its clock until it does"
            ),
            Err(err) => warn!(%service, error = %err, "cannot probe the outlet's clock"),
        }
        tokio::spawn(follow_clock(service, correction_tx));
    }

    let data = SocketAddr::new(addr, info.v4data_port);
    let stream = tokio::time::timeout(options.resolve_timeout, TcpStream::connect(data))
        .await
        .map_err(|_| io::Error::new(io::ErrorKind::TimedOut, format!("connect to {data}")))?
        .map_err(|e| io::Error::new(e.kind(), format!("connect to {data}: {e}")))?;
    stream.set_nodelay(true)?;
    let mut reader = BufReader::new(stream);
    reader
        .get_mut()
        .write_all(lsl::feed_request(info).as_bytes())
        .await?;
    let response = read_feed_response(&mut reader, info).await?;

    let mut values = Vec::new();
    for (index, offset) in [4, 2].into_iter().enumerate() {
        let mut pattern_clock = SampleClock::new(0.0);
        let (t, got) =
            read_sample(&mut reader, info, response, &mut pattern_clock, &mut values).await?;
        let expected = lsl::test_pattern(info.channel_format, info.channel_count, offset);
        if t != TEST_PATTERN_TIMESTAMP || got != expected {
            return Err(invalid(LslError::TestPattern {
                index,
                got,
                expected,
            }));
        }
    }
    match lost {
        Some(since) => info!(
            %data,
            after_s = format!("{:.1}", since.elapsed().as_secs_f64()),
            "the LSL outlet is back: reconnected, receiving the stream again"
        ),
        None => info!(%data, "receiving the LSL stream"),
    }

    let mut clock = SampleClock::new(info.nominal_srate);
    let mut shift_said = false;
    loop {
        let (t, values) = tokio::select! {
            biased;
            () = tx.closed() => return Ok(SessionEnd::ReceiverGone),
            read = read_sample(&mut reader, info, response, &mut clock, &mut values) => match read {
                Ok(sample) => sample,
                Err(err) if err.kind() == io::ErrorKind::UnexpectedEof => {
                    return Ok(SessionEnd::Closed);
                }
                Err(err) => return Err(err),
            },
        };
        if clock.shifted() > 0 && !shift_said {
            shift_said = true;
            info!(
                srate = info.nominal_srate,
                "a chunk's time stamps overlap the previous chunk's: its samples follow the \
                 previous one at the nominal rate (and so do later such chunks)"
            );
        }
        let sample = options.channels.sample(t + *correction.borrow(), &values);
        if tx.send(Ok(sample)).await.is_err() {
            return Ok(SessionEnd::ReceiverGone);
        }
    }
}

/// Reads the feed response's status line and headers, up to the empty line.
async fn read_feed_response<R: AsyncRead + Unpin>(
    reader: &mut BufReader<R>,
    info: &StreamInfo,
) -> io::Result<FeedResponse> {
    let mut head = String::new();
    loop {
        let mut line = String::new();
        let n = (&mut *reader)
            .take(MAX_HEADER_BYTES as u64)
            .read_line(&mut line)
            .await?;
        if n == 0 {
            return Err(invalid(LslError::Feed(
                "the outlet closed the connection during the handshake".into(),
            )));
        }
        if line.trim().is_empty() {
            break;
        }
        head.push_str(&line);
        if head.len() > MAX_HEADER_BYTES {
            return Err(invalid(LslError::Feed(format!(
                "response header longer than {MAX_HEADER_BYTES} bytes"
            ))));
        }
    }
    lsl::parse_feed_response(&head, &info.uid).map_err(invalid)
}
