//! The Lab Streaming Layer wire protocol (liblsl's protocol 1.10), the pure parts: resolve
//! queries and their replies, the stream feed handshake, the test pattern, sample decoding,
//! time-correction probes, and the mapping of channels to a [`GazeSample`]. Sockets are the
//! caller's business.
//!
//! How an inlet reaches an outlet (liblsl `resolve_attempt_udp.cpp`, `udp_server.cpp`,
//! `tcp_server.cpp`, `data_receiver.cpp`, `sample.cpp`, `time_receiver.cpp`):
//! 1. **Resolve.** A UDP datagram `LSL:shortinfo\r\n<query>\r\n<return port> <query id>\r\n` goes
//!    to port [`MULTICAST_PORT`] of the addresses of [`RESOLVE_ADDRESSES`] (loopback, broadcast,
//!    multicast). An outlet whose stream matches the XPath-like query replies to the return port
//!    with `<query id>\r\n` and its *shortinfo* XML ([`StreamInfo`]).
//! 2. **Feed.** A TCP connection to the outlet's `v4data_port` sends [`feed_request`]
//!    (`LSL:streamfeed/110 <uid>` and headers); the outlet answers `LSL/110 200 OK` and headers
//!    ([`FeedResponse`]), then two test-pattern samples ([`test_pattern`]), then samples.
//! 3. **Samples.** Each sample is a tag byte ([`TAG_DEDUCED_TIMESTAMP`]: time is the previous
//!    one plus `1 / nominal_srate`; [`TAG_TRANSMITTED_TIMESTAMP`]: an 8-byte double follows),
//!    then `channel_count` values in the channel format, in the byte order the handshake agreed.
//! 4. **Clock.** UDP `LSL:timedata\r\n<wave id> <t0>\r\n` to the outlet's `v4service_port` is
//!    answered ` <wave id> <t0> <t1> <t2>`; the probe with the smallest round trip gives the
//!    offset of the outlet's clock ([`TimeProbe`]), which is added to every time stamp so that
//!    all of them are on the inlet's clock (`lsl_local_clock`: the monotonic clock in seconds).

use std::fmt;

use thiserror::Error;

use super::{Eye, GazeSample, ScreenPx};

/// UDP port outlets listen on for resolve queries.
pub const MULTICAST_PORT: u16 = 16571;

/// Where resolve queries go, as liblsl's default `ResolveScope = site` does: the machine
/// (loopback), the link (broadcast and its two multicast groups) and the site group.
pub const RESOLVE_ADDRESSES: [&str; 5] = [
    "127.0.0.1",
    "255.255.255.255",
    "224.0.0.1",
    "224.0.0.183",
    "239.255.172.215",
];

/// The protocol version spoken here (liblsl writes 1.10 as 110).
pub const PROTOCOL_VERSION: u32 = 110;

/// Session every outlet is in unless the lab configured another (`lab.SessionID`).
pub const DEFAULT_SESSION: &str = "default";

/// Sample tag: the time stamp is the previous one plus the sampling interval.
pub const TAG_DEDUCED_TIMESTAMP: u8 = 1;
/// Sample tag: an 8-byte time stamp follows.
pub const TAG_TRANSMITTED_TIMESTAMP: u8 = 2;

/// Time stamp of the test-pattern samples.
pub const TEST_PATTERN_TIMESTAMP: f64 = 123_456.789;

/// Samples the outlet may queue for this inlet (liblsl's `max_buflen` for 360 s of a 1 kHz
/// stream is far more; a live bridge wants little queued, but enough to ride out a hiccup).
pub const MAX_BUFFER_SAMPLES: u32 = 60_000;

/// What went wrong with LSL input; each names the field at fault.
#[derive(Debug, Error, PartialEq)]
pub enum LslError {
    /// A request parameter cannot be sent.
    #[error("`{field}`: {reason}")]
    BadRequest {
        /// The parameter.
        field: &'static str,
        /// Why not.
        reason: String,
    },
    /// The outlet's stream info lacks or garbles a field.
    #[error("stream info field `{field}`: {reason}")]
    Info {
        /// The field.
        field: &'static str,
        /// What is wrong.
        reason: String,
    },
    /// The outlet refused or garbled the feed handshake.
    #[error("stream feed: {0}")]
    Feed(String),
    /// The outlet's test pattern is not what the protocol says: the formats do not agree.
    #[error("test-pattern sample {index} is {got:?}, expected {expected:?}")]
    TestPattern {
        /// 0 or 1.
        index: usize,
        /// What came.
        got: Vec<f64>,
        /// What should have.
        expected: Vec<f64>,
    },
    /// A sample's tag byte is neither of the two tags.
    #[error("sample tag {0} is neither 1 (deduced) nor 2 (transmitted time stamp)")]
    Tag(u8),
}

/// A numeric channel format (strings are refused: they carry no gaze).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ChannelFormat {
    /// `float32`.
    Float32,
    /// `double64`.
    Double64,
    /// `int32`.
    Int32,
    /// `int16`.
    Int16,
    /// `int8`.
    Int8,
    /// `int64`.
    Int64,
}

impl ChannelFormat {
    /// From the shortinfo's `channel_format` text.
    ///
    /// # Errors
    /// [`LslError::Info`] for `string` and anything unknown.
    pub fn parse(text: &str) -> Result<Self, LslError> {
        Ok(match text {
            "float32" => Self::Float32,
            "double64" => Self::Double64,
            "int32" => Self::Int32,
            "int16" => Self::Int16,
            "int8" => Self::Int8,
            "int64" => Self::Int64,
            other => {
                return Err(LslError::Info {
                    field: "channel_format",
                    reason: format!("{other:?} is not a numeric format (float32, double64, int*)"),
                });
            }
        })
    }

    /// Bytes per value.
    #[must_use]
    pub fn value_bytes(self) -> usize {
        match self {
            Self::Int8 => 1,
            Self::Int16 => 2,
            Self::Float32 | Self::Int32 => 4,
            Self::Double64 | Self::Int64 => 8,
        }
    }

    /// The base of the test pattern (liblsl `sample::assign_test_pattern`).
    fn pattern_base(self) -> i64 {
        match self {
            Self::Float32 => 0,
            Self::Double64 => 16_777_217,
            Self::Int32 => 65_537,
            Self::Int16 => 257,
            Self::Int8 => 1,
            Self::Int64 => 2_147_483_649,
        }
    }
}

impl fmt::Display for ChannelFormat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Float32 => "float32",
            Self::Double64 => "double64",
            Self::Int32 => "int32",
            Self::Int16 => "int16",
            Self::Int8 => "int8",
            Self::Int64 => "int64",
        })
    }
}

/// The outlet's description of its stream (the shortinfo XML), the fields an inlet needs.
#[derive(Debug, Clone, PartialEq)]
pub struct StreamInfo {
    /// `name`.
    pub name: String,
    /// `type` (content type, e.g. `Gaze`).
    pub type_: String,
    /// `channel_count`.
    pub channel_count: usize,
    /// `channel_format`.
    pub channel_format: ChannelFormat,
    /// `nominal_srate`, Hz; 0 for an irregular rate.
    pub nominal_srate: f64,
    /// `source_id`.
    pub source_id: String,
    /// `uid`: this outlet instance.
    pub uid: String,
    /// `session_id`.
    pub session_id: String,
    /// `hostname`.
    pub hostname: String,
    /// `v4address`; empty for "the address the reply came from".
    pub v4address: String,
    /// `v4data_port`: the TCP feed.
    pub v4data_port: u16,
    /// `v4service_port`: the UDP time service.
    pub v4service_port: u16,
}

/// The text of `<tag>...</tag>` (or empty for `<tag/>`), entities decoded; `None` if absent.
fn xml_child(xml: &str, tag: &str) -> Option<String> {
    let open = format!("<{tag}>");
    if let Some(start) = xml.find(&open) {
        let rest = &xml[start + open.len()..];
        let end = rest.find(&format!("</{tag}>"))?;
        return Some(unescape(&rest[..end]));
    }
    let empty = [format!("<{tag}/>"), format!("<{tag} />")];
    empty
        .iter()
        .any(|e| xml.contains(e.as_str()))
        .then(String::new)
}

fn unescape(text: &str) -> String {
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

impl StreamInfo {
    /// Parses a shortinfo XML message.
    ///
    /// # Errors
    /// [`LslError::Info`] naming the first field that is missing or does not parse.
    pub fn parse(xml: &str) -> Result<Self, LslError> {
        let text = |field: &'static str| {
            xml_child(xml, field).ok_or(LslError::Info {
                field,
                reason: "is missing".into(),
            })
        };
        let number = |field: &'static str| -> Result<f64, LslError> {
            let value = text(field)?;
            value
                .trim()
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite())
                .ok_or(LslError::Info {
                    field,
                    reason: format!("{value:?} is not a finite number"),
                })
        };
        let port = |field: &'static str| -> Result<u16, LslError> {
            let value = text(field)?;
            value.trim().parse::<u16>().map_err(|_| LslError::Info {
                field,
                reason: format!("{value:?} is not a port number"),
            })
        };
        let channel_count = number("channel_count")?;
        if !(channel_count >= 1.0 && channel_count.fract() == 0.0 && channel_count <= 65_536.0) {
            return Err(LslError::Info {
                field: "channel_count",
                reason: format!("{channel_count} is not a channel count in 1..=65536"),
            });
        }
        let nominal_srate = number("nominal_srate")?;
        if nominal_srate < 0.0 {
            return Err(LslError::Info {
                field: "nominal_srate",
                reason: format!("{nominal_srate} is negative"),
            });
        }
        Ok(Self {
            name: text("name")?,
            type_: text("type")?,
            channel_count: channel_count as usize,
            channel_format: ChannelFormat::parse(text("channel_format")?.trim())?,
            nominal_srate,
            source_id: text("source_id").unwrap_or_default(),
            uid: text("uid")?,
            session_id: text("session_id").unwrap_or_default(),
            hostname: text("hostname").unwrap_or_default(),
            v4address: text("v4address").unwrap_or_default(),
            v4data_port: port("v4data_port")?,
            v4service_port: port("v4service_port")?,
        })
    }
}

/// An XPath string literal: the value in single quotes (a value holding one cannot be quoted in
/// XPath 1.0, so it is refused).
fn literal(field: &'static str, value: &str) -> Result<String, LslError> {
    if value.contains('\'') {
        return Err(LslError::BadRequest {
            field,
            reason: format!("{value:?} contains a single quote, which a query cannot hold"),
        });
    }
    Ok(format!("'{value}'"))
}

/// The resolve query for streams of `type_` (and `name`, if given) in the default session, as
/// liblsl's `resolve_byprop` builds it.
///
/// # Errors
/// [`LslError::BadRequest`] when a value holds a single quote.
pub fn query(type_: &str, name: Option<&str>) -> Result<String, LslError> {
    let mut query = format!(
        "session_id={} and type={}",
        literal("session", DEFAULT_SESSION)?,
        literal("type", type_)?
    );
    if let Some(name) = name {
        query.push_str(&format!(" and name={}", literal("name", name)?));
    }
    Ok(query)
}

/// The resolve datagram.
#[must_use]
pub fn shortinfo_request(query: &str, return_port: u16, query_id: &str) -> String {
    format!("LSL:shortinfo\r\n{query}\r\n{return_port} {query_id}\r\n")
}

/// The query that finds `info`'s stream again after its outlet went away: the same name, type
/// and, when the outlet gave one, `source_id` (a restarted outlet keeps its source id but not its
/// `uid`), as liblsl's inlet recovery does; the type and name looked for first when a value
/// cannot be quoted.
///
/// # Errors
/// [`LslError::BadRequest`] when the fallback values hold a single quote.
pub fn recovery_query(
    info: &StreamInfo,
    type_: &str,
    name: Option<&str>,
) -> Result<String, LslError> {
    let mut query = format!(
        "session_id={} and type={}",
        literal("session", DEFAULT_SESSION)?,
        literal("type", &info.type_).or_else(|_| literal("type", type_))?
    );
    match literal("name", &info.name) {
        Ok(n) => query.push_str(&format!(" and name={n}")),
        Err(_) => {
            if let Some(name) = name {
                query.push_str(&format!(" and name={}", literal("name", name)?));
            }
        }
    }
    if !info.source_id.is_empty()
        && let Ok(id) = literal("source_id", &info.source_id)
    {
        query.push_str(&format!(" and source_id={id}"));
    }
    Ok(query)
}

/// The stream info of a resolve reply to `query_id`; `None` for a reply to another query.
///
/// # Errors
/// [`LslError::Info`] when the reply is ours but its stream info does not parse.
pub fn parse_resolve_reply(datagram: &str, query_id: &str) -> Result<Option<StreamInfo>, LslError> {
    let Some((id, xml)) = datagram.split_once('\n') else {
        return Ok(None);
    };
    if id.trim_end() != query_id {
        return Ok(None);
    }
    StreamInfo::parse(xml).map(Some)
}

/// The feed request for `info`'s stream: protocol 1.10, little-endian IEEE floats of the stream's
/// own value size (a different size would make the outlet fall back to protocol 1.00).
#[must_use]
pub fn feed_request(info: &StreamInfo) -> String {
    format!(
        "LSL:streamfeed/{PROTOCOL_VERSION} {uid}\r\n\
         Native-Byte-Order: 1234\r\n\
         Endian-Performance: 0\r\n\
         Has-IEEE754-Floats: 1\r\n\
         Supports-Subnormals: 1\r\n\
         Value-Size: {size}\r\n\
         Data-Protocol-Version: {PROTOCOL_VERSION}\r\n\
         Max-Buffer-Length: {MAX_BUFFER_SAMPLES}\r\n\
         Max-Chunk-Length: 0\r\n\
         Hostname: {host}\r\n\
         Source-Id: {source}\r\n\
         Session-Id: {session}\r\n\
         \r\n",
        uid = info.uid,
        size = info.channel_format.value_bytes(),
        host = info.hostname,
        source = info.source_id,
        session = info.session_id,
    )
}

/// What the outlet answered to [`feed_request`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FeedResponse {
    /// Whether values arrive big-endian (`Byte-Order: 4321`).
    pub big_endian: bool,
    /// Whether subnormal floats must be flushed to zero.
    pub suppress_subnormals: bool,
}

/// Parses the status line and headers (up to, not including, the empty line).
///
/// # Errors
/// [`LslError::Feed`] for an error status, another protocol than 1.10, a mismatched `UID` or
/// a byte order other than 1234 and 4321.
pub fn parse_feed_response(head: &str, uid: &str) -> Result<FeedResponse, LslError> {
    let mut lines = head.lines();
    let status = lines.next().unwrap_or_default().trim();
    let mut parts = status.split_whitespace();
    let (version, code) = (parts.next(), parts.next());
    let Some(version) = version.and_then(|v| v.strip_prefix("LSL/")) else {
        return Err(LslError::Feed(format!("malformed status line {status:?}")));
    };
    if code != Some("200") {
        return Err(LslError::Feed(format!("the outlet refused: {status:?}")));
    }
    if version.parse::<u32>().map_or(true, |v| v / 100 != 1) {
        return Err(LslError::Feed(format!(
            "protocol {version} in {status:?} is not 1.x"
        )));
    }
    let mut response = FeedResponse {
        big_endian: false,
        suppress_subnormals: false,
    };
    let mut protocol = None;
    for line in lines {
        let line = line.split(';').next().unwrap_or_default();
        let Some((key, value)) = line.split_once(':') else {
            continue;
        };
        let (key, value) = (key.trim().to_ascii_lowercase(), value.trim());
        match key.as_str() {
            "byte-order" => {
                response.big_endian = match value {
                    "1234" | "0" => false,
                    "4321" => true,
                    other => return Err(LslError::Feed(format!("byte order {other} unsupported"))),
                }
            }
            "suppress-subnormals" => response.suppress_subnormals = value == "1" || value == "true",
            "uid" if value != uid => {
                return Err(LslError::Feed(format!(
                    "the outlet serves stream {value}, not {uid} (it restarted)"
                )));
            }
            "data-protocol-version" => protocol = value.parse::<u32>().ok(),
            _ => {}
        }
    }
    if protocol != Some(PROTOCOL_VERSION) {
        return Err(LslError::Feed(format!(
            "data protocol {protocol:?} offered; only {PROTOCOL_VERSION} is spoken here"
        )));
    }
    Ok(response)
}

/// The values of test-pattern sample `offset` (4, then 2): channel `k` is `k + base + offset`,
/// negated for odd `k`.
#[must_use]
pub fn test_pattern(format: ChannelFormat, channels: usize, offset: i64) -> Vec<f64> {
    (0..channels)
        .map(|k| {
            let value = (k as i64 + format.pattern_base() + offset) as f64;
            let value = match format {
                // The value is first converted to the channel type, as liblsl does.
                ChannelFormat::Float32 => f64::from(value as f32),
                _ => value,
            };
            if k % 2 == 0 { value } else { -value }
        })
        .collect()
}

/// Decodes one sample's channel bytes (`channels * value_bytes` of them).
#[must_use]
pub fn decode_values(format: ChannelFormat, bytes: &[u8], response: FeedResponse) -> Vec<f64> {
    let size = format.value_bytes();
    bytes
        .chunks_exact(size)
        .map(|chunk| {
            let mut raw = [0u8; 8];
            raw[..size].copy_from_slice(chunk);
            if response.big_endian {
                raw[..size].reverse();
            }
            let value = match format {
                ChannelFormat::Float32 => {
                    let v = f32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]);
                    f64::from(v)
                }
                ChannelFormat::Double64 => f64::from_le_bytes(raw),
                ChannelFormat::Int8 => f64::from(raw[0] as i8),
                ChannelFormat::Int16 => f64::from(i16::from_le_bytes([raw[0], raw[1]])),
                ChannelFormat::Int32 => {
                    f64::from(i32::from_le_bytes([raw[0], raw[1], raw[2], raw[3]]))
                }
                ChannelFormat::Int64 => i64::from_le_bytes(raw) as f64,
            };
            if response.suppress_subnormals && value.is_subnormal() {
                0.0_f64.copysign(value)
            } else {
                value
            }
        })
        .collect()
}

/// The time stamp of a sample with a deduced time: the previous one plus the sampling interval
/// (the previous one itself for an irregular rate).
#[must_use]
pub fn deduced_timestamp(previous: f64, nominal_srate: f64) -> f64 {
    if nominal_srate > 0.0 {
        previous + 1.0 / nominal_srate
    } else {
        previous
    }
}

/// The time of each sample of one outlet's feed, on the outlet's clock.
///
/// An outlet that pushes a chunk with one time stamp (that of its newest sample, as LSL's
/// `push_chunk` documents) sends the chunk's first sample with that stamp less the chunk's length
/// at the nominal rate and the others as deduced (previous plus one sampling interval). When
/// chunks are stamped when they are pushed, a chunk pushed late followed by one pushed on time
/// overlap: the second begins before the first ends, and its first samples would reach the
/// server as time going backwards and be lost. The samples of a stream with a nominal rate are
/// one interval apart, so such a chunk is placed right after the previous sample, one nominal
/// interval later, and its deduced samples follow from there. The shift is bounded
/// ([`Self::MAX_SHIFT_S`]): an outlet whose clock really stepped back is passed on as it is.
#[derive(Debug, Clone)]
pub struct SampleClock {
    nominal_srate: f64,
    previous: Option<f64>,
    shifted: u64,
}

impl SampleClock {
    /// Largest step a transmitted time stamp is moved forward, seconds: more than any chunk's
    /// push jitter, far less than a clock that went back.
    pub const MAX_SHIFT_S: f64 = 1.0;

    /// The clock of a stream with this nominal rate (0: irregular, never re-timed).
    #[must_use]
    pub fn new(nominal_srate: f64) -> Self {
        Self {
            nominal_srate,
            previous: None,
            shifted: 0,
        }
    }

    /// The time of a sample that came with time stamp `t`.
    pub fn transmitted(&mut self, t: f64) -> f64 {
        let t = match self.previous {
            Some(previous) if self.nominal_srate > 0.0 && t < previous => {
                let next = previous + 1.0 / self.nominal_srate;
                if next - t <= Self::MAX_SHIFT_S {
                    self.shifted += 1;
                    next
                } else {
                    t
                }
            }
            _ => t,
        };
        self.previous = Some(t);
        t
    }

    /// The time of a sample sent with a deduced time stamp.
    pub fn deduced(&mut self) -> f64 {
        let t = deduced_timestamp(self.previous.unwrap_or(0.0), self.nominal_srate);
        self.previous = Some(t);
        t
    }

    /// Transmitted time stamps moved forward so far (count).
    #[must_use]
    pub fn shifted(&self) -> u64 {
        self.shifted
    }
}

/// The time-service request of probe `wave_id` sent at `t0` (inlet clock). liblsl reads the id
/// as a C `int`, so it must be below 2^31.
#[must_use]
pub fn timedata_request(wave_id: u32, t0: f64) -> String {
    format!("LSL:timedata\r\n{wave_id} {t0:.9}\r\n")
}

/// One answered time probe: sent at `t0` and received at `t3` (inlet clock), received at `t1`
/// and answered at `t2` (outlet clock).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TimeProbe {
    /// Inlet clock, request sent.
    pub t0: f64,
    /// Outlet clock, request received.
    pub t1: f64,
    /// Outlet clock, reply sent.
    pub t2: f64,
    /// Inlet clock, reply received.
    pub t3: f64,
}

impl TimeProbe {
    /// Parses the reply ` <wave id> <t0> <t1> <t2>` to probe `wave_id`, received at `t3`;
    /// `None` for a reply to another probe or a garbled one.
    #[must_use]
    pub fn from_reply(reply: &str, wave_id: u32, t3: f64) -> Option<Self> {
        let mut fields = reply.split_whitespace();
        if fields.next()?.parse::<u32>().ok()? != wave_id {
            return None;
        }
        let mut next = || fields.next()?.parse::<f64>().ok().filter(|v| v.is_finite());
        let (t0, t1, t2) = (next()?, next()?, next()?);
        Some(Self { t0, t1, t2, t3 })
    }

    /// Round trip, less the time the outlet held the request: the bound on the offset's error.
    #[must_use]
    pub fn rtt(&self) -> f64 {
        (self.t3 - self.t0) - (self.t2 - self.t1)
    }

    /// The correction to add to an outlet time stamp to put it on the inlet's clock (liblsl's
    /// `time_correction()`: minus the offset of the outlet's clock from the inlet's).
    #[must_use]
    pub fn correction(&self) -> f64 {
        -((self.t1 - self.t0) + (self.t2 - self.t3)) / 2.0
    }
}

/// The probe to trust: the one with the smallest round trip, as NTP (and liblsl) do.
#[must_use]
pub fn best_probe(probes: &[TimeProbe]) -> Option<TimeProbe> {
    probes
        .iter()
        .copied()
        .filter(|p| p.rtt().is_finite())
        .min_by(|a, b| a.rtt().total_cmp(&b.rtt()))
}

/// How channel values become screen positions.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Units {
    /// Already normalised: 0..1, origin top-left.
    Normalised,
    /// Pixels of this screen, origin top-left.
    Pixels(ScreenPx),
}

/// Which channels hold the gaze and in which units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ChannelMap {
    /// Index of the x channel.
    pub x: usize,
    /// Index of the y channel.
    pub y: usize,
    /// Units of both.
    pub units: Units,
}

impl Default for ChannelMap {
    fn default() -> Self {
        Self {
            x: 0,
            y: 1,
            units: Units::Normalised,
        }
    }
}

impl ChannelMap {
    /// Checks the channel indices against the stream's channel count.
    ///
    /// # Errors
    /// [`LslError::BadRequest`] naming `x-channel` or `y-channel` and the limit.
    pub fn check(&self, channel_count: usize) -> Result<(), LslError> {
        for (field, index) in [("x-channel", self.x), ("y-channel", self.y)] {
            if index >= channel_count {
                return Err(LslError::BadRequest {
                    field,
                    reason: format!(
                        "channel {index} does not exist: the stream has {channel_count} \
                         channels (0..={})",
                        channel_count - 1
                    ),
                });
            }
        }
        Ok(())
    }

    /// The sample of one LSL sample at `t_s`: a missing sample when either channel is NaN or
    /// infinite (trackers send NaN during blinks), else the position in normalised units.
    #[must_use]
    pub fn sample(&self, t_s: f64, values: &[f64]) -> GazeSample {
        let (Some(&x), Some(&y)) = (values.get(self.x), values.get(self.y)) else {
            return GazeSample::missing(t_s, Eye::Unspecified);
        };
        if !(x.is_finite() && y.is_finite()) {
            return GazeSample::missing(t_s, Eye::Unspecified);
        }
        let (x, y) = match self.units {
            Units::Normalised => (x, y),
            Units::Pixels(screen) => screen.normalise(x, y),
        };
        GazeSample::valid(t_s, x, y, Eye::Unspecified)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A shortinfo message as liblsl 1.16 (pugixml) writes it.
    const SHORTINFO: &str = "<?xml version=\"1.0\"?>\n<info>\n\t<name>Tobii &amp; co</name>\n\
        \t<type>Gaze</type>\n\t<channel_count>3</channel_count>\n\
        \t<channel_format>float32</channel_format>\n\t<source_id>tracker-1</source_id>\n\
        \t<nominal_srate>120.0000000000000</nominal_srate>\n\t<version>1.100000000000000</version>\n\
        \t<created_at>51.30000000000000</created_at>\n\t<uid>6a1e-42</uid>\n\
        \t<session_id>default</session_id>\n\t<hostname>lab-pc</hostname>\n\
        \t<v4address />\n\t<v4data_port>16573</v4data_port>\n\t<v4service_port>16574</v4service_port>\n\
        \t<v6address />\n\t<v6data_port>0</v6data_port>\n\t<v6service_port>0</v6service_port>\n\
        \t<desc />\n</info>\n";

    #[test]
    fn shortinfo_parses_with_entities_and_empty_elements() {
        let info = StreamInfo::parse(SHORTINFO).expect("parses");
        assert_eq!(info.name, "Tobii & co");
        assert_eq!(
            (info.channel_count, info.channel_format),
            (3, ChannelFormat::Float32)
        );
        assert_eq!((info.v4data_port, info.v4service_port), (16573, 16574));
        assert_eq!(info.v4address, "");
        assert_eq!(info.nominal_srate, 120.0);
        let reply = format!("q7\r\n{SHORTINFO}");
        assert!(parse_resolve_reply(&reply, "q7").expect("ours").is_some());
        assert_eq!(parse_resolve_reply(&reply, "q8"), Ok(None));
        let strings = SHORTINFO.replace(">float32<", ">string<");
        assert!(matches!(
            StreamInfo::parse(&strings),
            Err(LslError::Info {
                field: "channel_format",
                ..
            })
        ));
    }

    #[test]
    fn query_quotes_and_refuses_quotes() {
        assert_eq!(
            query("Gaze", Some("Pupil")).expect("fine"),
            "session_id='default' and type='Gaze' and name='Pupil'"
        );
        assert!(matches!(
            query("Ga'ze", None),
            Err(LslError::BadRequest { field: "type", .. })
        ));
    }

    #[test]
    fn a_chunk_overlapping_the_previous_one_follows_it_at_the_nominal_rate() {
        // 100 Hz, chunks of 5 stamped when pushed: the second pushed 30 ms early.
        let mut clock = SampleClock::new(100.0);
        let mut times = Vec::new();
        for stamp in [1000.04, 1000.06] {
            times.push(clock.transmitted(stamp - 0.04));
            for _ in 0..4 {
                times.push(clock.deduced());
            }
        }
        for (k, t) in times.iter().enumerate() {
            let expected = 1000.0 + 0.01 * k as f64;
            assert!(
                (t - expected).abs() < 1e-9,
                "sample {k}: {t} for {expected}"
            );
        }
        assert_eq!(clock.shifted(), 1);
        // A later chunk is taken as stamped; a clock that went far back is not re-timed.
        assert_eq!(clock.transmitted(1001.0), 1001.0);
        assert_eq!(clock.transmitted(10.0), 10.0);
        // Without a nominal rate nothing is re-timed.
        let mut irregular = SampleClock::new(0.0);
        assert_eq!(irregular.transmitted(5.0), 5.0);
        assert_eq!(irregular.transmitted(4.0), 4.0);
        assert_eq!(irregular.deduced(), 4.0);
    }

    #[test]
    fn recovery_finds_the_same_source_again() {
        let info = StreamInfo::parse(SHORTINFO).expect("parses");
        assert_eq!(
            recovery_query(&info, "Gaze", None).expect("quotable"),
            "session_id='default' and type='Gaze' and name='Tobii & co' and source_id='tracker-1'"
        );
        let odd = StreamInfo {
            name: "it's".into(),
            source_id: String::new(),
            ..info
        };
        assert_eq!(
            recovery_query(&odd, "Gaze", Some("x")).expect("falls back"),
            "session_id='default' and type='Gaze' and name='x'"
        );
    }

    #[test]
    fn feed_response_is_checked() {
        let ok = "LSL/110 200 OK\r\nUID: u1\r\nByte-Order: 1234\r\nSuppress-Subnormals: 0\r\nData-Protocol-Version: 110\r\n";
        assert_eq!(
            parse_feed_response(ok, "u1"),
            Ok(FeedResponse {
                big_endian: false,
                suppress_subnormals: false
            })
        );
        assert!(parse_feed_response(ok, "u2").is_err());
        assert!(parse_feed_response("LSL/110 404 Not found\r\n", "u1").is_err());
        let v100 = ok.replace("Data-Protocol-Version: 110", "Data-Protocol-Version: 100");
        assert!(parse_feed_response(&v100, "u1").is_err());
    }

    #[test]
    fn test_pattern_matches_liblsl() {
        // float32, 3 channels, offset 4: 4, -5, 6; double64 adds 16777217.
        assert_eq!(test_pattern(ChannelFormat::Float32, 3, 4), [4.0, -5.0, 6.0]);
        assert_eq!(
            test_pattern(ChannelFormat::Double64, 2, 2),
            [16_777_219.0, -16_777_220.0]
        );
    }

    #[test]
    fn values_decode_in_either_byte_order() {
        let little = FeedResponse {
            big_endian: false,
            suppress_subnormals: false,
        };
        let mut bytes = 0.25f32.to_le_bytes().to_vec();
        bytes.extend(f32::NAN.to_le_bytes());
        let values = decode_values(ChannelFormat::Float32, &bytes, little);
        assert_eq!(values[0], 0.25);
        assert!(values[1].is_nan());
        let big = FeedResponse {
            big_endian: true,
            ..little
        };
        let bytes = 1920.5f64.to_be_bytes();
        assert_eq!(
            decode_values(ChannelFormat::Double64, &bytes, big),
            [1920.5]
        );
    }

    #[test]
    fn the_fastest_probe_sets_the_correction() {
        // Outlet clock 100 s ahead; the second probe waited 40 ms on the way back.
        let fast = TimeProbe {
            t0: 1.0,
            t1: 101.001,
            t2: 101.0015,
            t3: 1.0025,
        };
        let slow = TimeProbe {
            t0: 2.0,
            t1: 102.001,
            t2: 102.0015,
            t3: 2.0425,
        };
        let best = best_probe(&[slow, fast]).expect("a probe");
        assert_eq!(best, fast);
        assert!(
            (best.correction() + 100.0).abs() < 1e-3,
            "{}",
            best.correction()
        );
        let reply = " 7 1.000000000 101.001 101.0015";
        assert_eq!(TimeProbe::from_reply(reply, 7, 1.0025), Some(fast));
        assert_eq!(TimeProbe::from_reply(reply, 8, 1.0025), None);
    }

    #[test]
    fn nan_channels_are_missing_and_pixels_are_normalised() {
        let map = ChannelMap::default();
        assert!(!map.sample(5.0, &[f64::NAN, 0.5]).is_valid());
        let s = map.sample(5.0, &[0.25, 0.5]);
        assert_eq!((s.x, s.y, s.t_s), (0.25, 0.5, 5.0));
        let screen = ScreenPx::new(1920.0, 1080.0).expect("screen");
        let pixels = ChannelMap {
            x: 2,
            y: 0,
            units: Units::Pixels(screen),
        };
        let s = pixels.sample(0.0, &[540.0, 0.0, 960.0]);
        assert!(
            (s.x - 0.5).abs() < 0.01 && (s.y - 0.5).abs() < 0.01,
            "{s:?}"
        );
        assert!(pixels.check(3).is_ok());
        assert!(matches!(
            pixels.check(2),
            Err(LslError::BadRequest {
                field: "x-channel",
                ..
            })
        ));
    }
}
