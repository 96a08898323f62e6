//! A Pupil Core tracker (Pupil Capture or Pupil Service) as a source, over its network API.
//!
//! Pupil Remote is a ZeroMQ REP socket (port 50020 by default). The source connects a REQ
//! socket to it, asks `SUB_PORT` for the port of the IPC backbone's PUB socket, connects a SUB
//! socket there and subscribes to a topic prefix (`gaze.` unless told otherwise, or
//! `surfaces.NAME` for gaze mapped onto a surface). Each message is a multipart one: the topic,
//! then a msgpack dict, decoded here into a [`PupilGaze`] and mapped by [`crate::gaze::pupil`].
//!
//! A PUB socket never says when its peer has gone, so the source asks Pupil Remote for its
//! clock (`t`) every heartbeat: a Pupil Remote that does not answer within the connect timeout
//! ends the source with an error naming its address, instead of a bridge waiting forever.

use std::io;
use std::time::Duration;

use tokio::sync::mpsc;
use tracing::{debug, info};
use zeromq::{ReqSocket, Socket, SocketOptions, SocketRecv, SocketSend, SubSocket, ZmqMessage};

use crate::gaze::pupil;
use crate::gaze::{Eye, ParseError};
use crate::source::{CHANNEL_CAPACITY, SourceError, SourceItem};

/// Where Pupil Remote is and what to take from it.
#[derive(Debug, Clone)]
pub struct PupilOptions {
    /// Host name or address of Pupil Remote.
    pub host: String,
    /// Pupil Remote's port.
    pub port: u16,
    /// Topic prefix of the gaze to subscribe to (`gaze.`, `gaze.3d.01.`, ...); ignored with a
    /// surface.
    pub topic: String,
    /// Subscribe to `surfaces.NAME` and use its `gaze_on_surfaces` instead of raw gaze.
    pub surface: Option<String>,
    /// Keep only gaze of this eye (Pupil's eye 0 is the right eye); `None` for all.
    pub eye: Option<Eye>,
    /// Confidence below which a datum becomes a missing sample.
    pub min_confidence: f64,
    /// Time allowed to connect and for each answer of Pupil Remote.
    pub connect_timeout: Duration,
    /// How often Pupil Remote is asked whether it is still there.
    pub heartbeat: Duration,
}

impl Default for PupilOptions {
    fn default() -> Self {
        Self {
            host: "127.0.0.1".into(),
            port: pupil::DEFAULT_REMOTE_PORT,
            topic: "gaze.".into(),
            surface: None,
            eye: None,
            min_confidence: pupil::DEFAULT_MIN_CONFIDENCE,
            connect_timeout: Duration::from_secs(3),
            heartbeat: Duration::from_secs(1),
        }
    }
}

impl PupilOptions {
    /// `host:port` of Pupil Remote, as errors name it.
    #[must_use]
    pub fn remote(&self) -> String {
        format!("{}:{}", self.host, self.port)
    }

    /// The subscription: `surfaces.NAME` with a surface, else the gaze topic.
    #[must_use]
    pub fn subscription(&self) -> String {
        match &self.surface {
            Some(name) => format!("surfaces.{name}"),
            None => self.topic.clone(),
        }
    }

    /// Checks the options a user gives.
    ///
    /// # Errors
    /// A message naming the option and its limit.
    pub fn check(&self) -> Result<(), String> {
        if !(0.0..=1.0).contains(&self.min_confidence) {
            return Err(format!(
                "--min-confidence must be in 0..=1, not {}",
                self.min_confidence
            ));
        }
        if self.connect_timeout.is_zero() {
            return Err("--connect-timeout must be more than 0 s".into());
        }
        if self.surface.is_none() && !self.topic.starts_with("gaze") {
            return Err(format!(
                "--topic must be a gaze topic (start with `gaze`), not {:?}",
                self.topic
            ));
        }
        if let Some(name) = &self.surface
            && name.is_empty()
        {
            return Err("--surface needs the surface's name".into());
        }
        Ok(())
    }
}

/// A Pupil Core tracker as a source (see the module docs). Connection failures end the source
/// with one [`SourceError::Io`] naming Pupil Remote's `host:port`.
///
/// # Panics
/// When called outside a tokio runtime.
#[must_use]
pub fn pupil(options: PupilOptions) -> mpsc::Receiver<SourceItem> {
    let (tx, rx) = mpsc::channel(CHANNEL_CAPACITY);
    tokio::spawn(run(options, tx));
    rx
}

fn io_error(kind: io::ErrorKind, what: impl std::fmt::Display) -> io::Error {
    io::Error::new(kind, what.to_string())
}

/// One request to Pupil Remote and its answer as text, within `timeout`.
async fn ask(req: &mut ReqSocket, command: &str, timeout: Duration) -> io::Result<String> {
    let exchange = async {
        req.send(ZmqMessage::from(command))
            .await
            .map_err(|e| io_error(io::ErrorKind::BrokenPipe, e))?;
        let reply = req
            .recv()
            .await
            .map_err(|e| io_error(io::ErrorKind::BrokenPipe, e))?;
        let bytes: Vec<u8> = reply.into_vec().into_iter().flatten().collect();
        String::from_utf8(bytes).map_err(|_| io_error(io::ErrorKind::InvalidData, "not UTF-8"))
    };
    tokio::time::timeout(timeout, exchange).await.map_err(|_| {
        io_error(
            io::ErrorKind::TimedOut,
            format!("no answer to `{command}` within {timeout:?}"),
        )
    })?
}

/// Connects a socket of type `S` to `endpoint` within `timeout`.
async fn connect<S: Socket>(endpoint: &str, timeout: Duration) -> io::Result<S> {
    let mut options = SocketOptions::default();
    options.connect_timeout(timeout);
    let mut socket = S::with_options(options);
    match tokio::time::timeout(timeout, socket.connect(endpoint)).await {
        Ok(Ok(())) => Ok(socket),
        Ok(Err(err)) => Err(io_error(io::ErrorKind::ConnectionRefused, err)),
        Err(_) => Err(io_error(
            io::ErrorKind::TimedOut,
            format!("cannot connect within {timeout:?}"),
        )),
    }
}

/// Connects to Pupil Remote, finds the SUB port and subscribes.
async fn open(options: &PupilOptions) -> io::Result<(ReqSocket, SubSocket)> {
    let timeout = options.connect_timeout;
    let mut req: ReqSocket =
        connect(&format!("tcp://{}:{}", options.host, options.port), timeout).await?;
    let answer = ask(&mut req, "SUB_PORT", timeout).await?;
    let sub_port: u16 = answer.trim().parse().map_err(|_| {
        io_error(
            io::ErrorKind::InvalidData,
            format!("answered SUB_PORT with {answer:?}, not a port"),
        )
    })?;
    let clock = ask(&mut req, "t", timeout).await?;
    info!(sub_port, pupil_time_s = %clock.trim(), "connected to Pupil Remote");
    let mut sub: SubSocket = connect(&format!("tcp://{}:{sub_port}", options.host), timeout)
        .await
        .map_err(|e| io_error(e.kind(), format!("SUB port {sub_port}: {e}")))?;
    sub.subscribe(&options.subscription())
        .await
        .map_err(|e| io_error(io::ErrorKind::BrokenPipe, e))?;
    Ok((req, sub))
}

async fn run(options: PupilOptions, tx: mpsc::Sender<SourceItem>) {
    let remote = options.remote();
    let (mut req, mut sub) = match open(&options).await {
        Ok(sockets) => sockets,
        Err(source) => {
            let what = format!("Pupil Remote at {remote}");
            let _ = tx.send(Err(SourceError::Io { what, source })).await;
            return;
        }
    };
    let mut heartbeat = tokio::time::interval(options.heartbeat);
    heartbeat.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Delay);
    heartbeat.tick().await;
    let mut message = 0usize;
    let mut low_confidence = 0u64;
    loop {
        tokio::select! {
            biased;
            () = tx.closed() => return,
            received = sub.recv() => {
                let frames = match received {
                    Ok(frames) => frames,
                    Err(err) => {
                        // A dropped PUB connection; the heartbeat decides whether Pupil is gone.
                        debug!(%remote, error = %err, "SUB socket");
                        tokio::time::sleep(Duration::from_millis(50)).await;
                        continue;
                    }
                };
                message += 1;
                for item in datums(message, &frames, &options) {
                    if let Ok(sample) = &item
                        && !sample.is_valid()
                    {
                        low_confidence += 1;
                    }
                    if tx.send(item).await.is_err() {
                        return;
                    }
                }
            }
            _ = heartbeat.tick() => {
                if let Err(source) = ask(&mut req, "t", options.connect_timeout).await {
                    info!(%remote, messages = message, low_confidence, "Pupil Remote is gone");
                    let what = format!("Pupil Remote at {remote} stopped answering");
                    let _ = tx.send(Err(SourceError::Io { what, source })).await;
                    return;
                }
            }
        }
    }
}

/// The samples of one multipart message (topic frame, msgpack payload, maybe more frames):
/// one for a gaze datum, one per `gaze_on_surfaces` entry for a surface datum, none for gaze of
/// an eye that was not asked for; a payload that does not decode is one [`SourceError::Parse`].
fn datums(message: usize, frames: &ZmqMessage, options: &PupilOptions) -> Vec<SourceItem> {
    let malformed = |field: &'static str, reason: String| {
        vec![Err(SourceError::Parse(ParseError::Malformed {
            line: message,
            field,
            reason,
        }))]
    };
    let Some(payload) = frames.get(1) else {
        return malformed("payload", "the message has no payload frame".into());
    };
    let topic = frames
        .get(0)
        .map(|t| String::from_utf8_lossy(t).into_owned())
        .unwrap_or_default();
    let gazes = match pupil::decode_payload(payload, &topic, options.surface.is_some()) {
        Ok(gazes) => gazes,
        Err((field, reason)) => return malformed(field, reason),
    };
    gazes
        .into_iter()
        .filter_map(|gaze| match gaze {
            Ok(gaze) => {
                let sample = gaze.to_sample(options.min_confidence);
                if options.eye.is_some_and(|eye| eye != sample.eye) {
                    return None;
                }
                if gaze.is_low_confidence(options.min_confidence) {
                    debug!(
                        message,
                        confidence = gaze.confidence,
                        "low confidence: missing"
                    );
                }
                Some(Ok(sample))
            }
            Err((field, reason)) => Some(Err(SourceError::Parse(ParseError::Malformed {
                line: message,
                field,
                reason,
            }))),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use rmpv::Value;

    use super::*;

    fn message(topic: &str, payload: &Value) -> ZmqMessage {
        let mut bytes = Vec::new();
        rmpv::encode::write_value(&mut bytes, payload).expect("encodes");
        let mut m = ZmqMessage::from(topic);
        m.push_back(bytes.into());
        m
    }

    fn map(pairs: Vec<(&str, Value)>) -> Value {
        Value::Map(pairs.into_iter().map(|(k, v)| (k.into(), v)).collect())
    }

    fn gaze(topic: &str, x: f64, y: f64, confidence: f64, t: f64) -> Value {
        map(vec![
            ("topic", topic.into()),
            ("norm_pos", Value::Array(vec![x.into(), y.into()])),
            ("confidence", confidence.into()),
            ("timestamp", t.into()),
        ])
    }

    #[test]
    fn a_gaze_message_is_one_flipped_sample() {
        let m = message("gaze.3d.01.", &gaze("gaze.3d.01.", 0.5, 0.25, 0.9, 10.0));
        let items = datums(1, &m, &PupilOptions::default());
        let s = items[0].as_ref().expect("a sample");
        assert_eq!((s.x, s.y, s.t_s, s.eye), (0.5, 0.75, 10.0, Eye::Binocular));
    }

    #[test]
    fn surface_entries_are_one_sample_each_and_the_eye_filter_applies() {
        let payload = map(vec![(
            "gaze_on_surfaces",
            Value::Array(vec![
                gaze("gaze.3d.0._on_surface", 0.1, 0.1, 0.95, 1.0),
                gaze("gaze.3d.1._on_surface", 0.2, 0.2, 0.95, 1.01),
            ]),
        )]);
        let m = message("surfaces.screen", &payload);
        let options = PupilOptions {
            surface: Some("screen".into()),
            ..PupilOptions::default()
        };
        assert_eq!(datums(1, &m, &options).len(), 2);
        let left = PupilOptions {
            eye: Some(Eye::Left),
            ..options
        };
        let items = datums(1, &m, &left);
        assert_eq!(items.len(), 1);
        assert_eq!(items[0].as_ref().expect("sample").t_s, 1.01);
    }

    #[test]
    fn garbage_is_one_malformed_item_naming_the_field() {
        let m = message("gaze.3d.0.", &map(vec![("confidence", 1.0.into())]));
        let items = datums(7, &m, &PupilOptions::default());
        let err = items[0].as_ref().expect_err("malformed");
        assert!(
            err.to_string().contains("line 7: field `norm_pos`"),
            "{err}"
        );
        let mut raw = ZmqMessage::from("gaze.3d.0.");
        raw.push_back(vec![0xc1].into());
        assert!(datums(8, &raw, &PupilOptions::default())[0].is_err());
    }

    #[test]
    fn options_are_checked() {
        let bad = PupilOptions {
            min_confidence: 1.5,
            ..PupilOptions::default()
        };
        assert!(bad.check().expect_err("bad").contains("--min-confidence"));
        let topic = PupilOptions {
            topic: "pupil.".into(),
            ..PupilOptions::default()
        };
        assert!(topic.check().expect_err("bad").contains("--topic"));
        assert!(PupilOptions::default().check().is_ok());
    }
}
