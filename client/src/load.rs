//! `foveal load`: load a server the way a lab full of clients would, and measure what the loop
//! keeps up.
//!
//! M gaze streams send samples at a fixed rate (tracker time advancing with the wall clock), K
//! watchers subscribe to frames, of which S never read a single frame (a stalled viewer), for T
//! seconds. Reported: the loop's frame rate (frames completed over the run, from GetStatus, and the
//! lowest one-second rate seen), the step-time p99 (sum of the frame's phases, read by a watcher
//! that keeps up), samples sent against accepted / rejected / rate-limited by the server's own
//! summaries, and the server's resident memory over time (Linux `/proc`, on loopback).
//!
//! With [`LoadOptions::chaos`] (`foveal load --chaos`), the same load runs while the server is
//! treated as a hostile network would: clients killed mid-call, connections left idle by the
//! hundred (silent, half an HTTP/1.1 head, an HTTP/2 preface and nothing more), request bodies
//! stalled mid-message, and Configure called every second. A fresh client's call (connect and
//! GetStatus) is timed throughout: what a new user would wait at the worst moment.

use std::fmt;
use std::time::{Duration, Instant};

use foveal_proto::pb;
use tokio::io::AsyncWriteExt;
use tokio::net::TcpStream;
use tokio::sync::mpsc;
use tokio_stream::wrappers::ReceiverStream;

use crate::{ClientError, ConnectOptions, connect_with};

/// What to run.
#[derive(Debug, Clone)]
pub struct LoadOptions {
    /// Server address.
    pub addr: String,
    /// Token and CA of gaze streams (role `gaze` or `admin`).
    pub gaze: ConnectOptions,
    /// Token and CA of watchers and status calls (role `viewer` or `admin`).
    pub viewer: ConnectOptions,
    /// Gaze streams (M).
    pub streams: usize,
    /// Samples per second per stream.
    pub rate_hz: f64,
    /// Watchers (K), stalled ones included.
    pub watchers: usize,
    /// Watchers that never read (S <= K).
    pub stalled: usize,
    /// Whether watchers ask for poses.
    pub poses: bool,
    /// How long to load the server.
    pub duration: Duration,
    /// The server's process id for its RSS; `None` finds the process listening on the port.
    pub server_pid: Option<u32>,
    /// How often RSS and the frame rate are sampled.
    pub sample_every: Duration,
    /// The disorder to add, if any (a chaos run).
    pub chaos: Option<ChaosOptions>,
}

/// The disorder of a chaos run, added to the load.
#[derive(Debug, Clone)]
pub struct ChaosOptions {
    /// Token and CA for Configure (role `admin`).
    pub admin: ConnectOptions,
    /// A client (gaze stream or watcher, in turn) is started and killed mid-call this often.
    pub kill_every: Duration,
    /// Connections kept open doing nothing useful (a third silent, a third half an HTTP/1.1
    /// head, a third an HTTP/2 preface only), renewed every [`Self::renew_every`].
    pub idle_connections: usize,
    /// Requests whose body stops mid-message, renewed with the idle connections.
    pub stalled_bodies: usize,
    /// How often the idle connections and stalled bodies are dropped and opened anew.
    pub renew_every: Duration,
    /// How often Configure is called.
    pub configure_every: Duration,
    /// How often a fresh client connects and calls GetStatus, timed.
    pub probe_every: Duration,
    /// How long a fresh client's call may take before it counts as failed.
    pub probe_timeout: Duration,
}

impl Default for ChaosOptions {
    fn default() -> Self {
        Self {
            admin: ConnectOptions::default(),
            kill_every: Duration::from_secs(1),
            idle_connections: 200,
            stalled_bodies: 16,
            renew_every: Duration::from_secs(10),
            configure_every: Duration::from_secs(1),
            probe_every: Duration::from_millis(250),
            probe_timeout: Duration::from_secs(5),
        }
    }
}

/// What the disorder did and how a fresh client fared through it.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct ChaosReport {
    /// Clients killed mid-call.
    pub killed: u64,
    /// Idle connections opened (all rounds).
    pub idle_opened: u64,
    /// Idle connections the server did not accept (connect failed).
    pub idle_refused: u64,
    /// Requests left with a body stalled mid-message.
    pub stalled_bodies: u64,
    /// Configure calls answered OK, and failed.
    pub configures: (u64, u64),
    /// Fresh clients' calls made, and failed (or over the timeout).
    pub probes: (u64, u64),
    /// Their latency (connect and GetStatus), milliseconds: median, 99th percentile, worst.
    pub probe_ms: (f64, f64, f64),
    /// When the worst one started, seconds into the run.
    pub worst_at_s: f64,
}

impl fmt::Display for ChaosReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "chaos: {} clients killed mid-call, {} idle connections opened ({} refused), {} \
             bodies stalled mid-message, Configure {} ok / {} failed",
            self.killed,
            self.idle_opened,
            self.idle_refused,
            self.stalled_bodies,
            self.configures.0,
            self.configures.1
        )?;
        write!(
            f,
            "fresh client (connect + GetStatus): {} calls, {} failed; p50 {:.1} ms, p99 {:.1} ms, \
             worst {:.1} ms at {:.0} s",
            self.probes.0,
            self.probes.1,
            self.probe_ms.0,
            self.probe_ms.1,
            self.probe_ms.2,
            self.worst_at_s
        )
    }
}

impl Default for LoadOptions {
    fn default() -> Self {
        Self {
            addr: crate::DEFAULT_ADDR.to_owned(),
            gaze: ConnectOptions::default(),
            viewer: ConnectOptions::default(),
            streams: 8,
            rate_hz: 2000.0,
            watchers: 64,
            stalled: 16,
            poses: false,
            duration: Duration::from_secs(60),
            server_pid: None,
            sample_every: Duration::from_secs(1),
            chaos: None,
        }
    }
}

/// One sample of the server over time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadSample {
    /// Seconds since the load started.
    pub t_s: f64,
    /// Frames completed in the last second, as GetStatus reports it.
    pub fps: f64,
    /// Server resident memory, MiB (`None` when it cannot be read).
    pub rss_mib: Option<f64>,
}

/// What a load run measured.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LoadReport {
    /// Seconds the load ran.
    pub seconds: f64,
    /// Frames completed over the run divided by its length.
    pub loop_fps: f64,
    /// Lowest one-second frame rate sampled during the run (after the first second).
    pub min_fps: f64,
    /// 99th percentile of the step time (sum of the frame's phases), milliseconds.
    pub step_p99_ms: f64,
    /// Frames the reading watchers received, all together.
    pub frames_received: u64,
    /// Frames the reading watchers were told they missed (`dropped_before`), all together.
    pub frames_dropped: u64,
    /// Samples handed to the gaze streams.
    pub samples_sent: u64,
    /// Samples the server accepted, from its summaries.
    pub samples_accepted: u64,
    /// Samples the server rejected.
    pub samples_rejected: u64,
    /// Samples the server dropped by its rate limit.
    pub samples_rate_limited: u64,
    /// Gaze streams that ended in an error.
    pub stream_errors: u64,
    /// The server over time.
    pub samples: Vec<LoadSample>,
    /// What a chaos run did, if it was one.
    pub chaos: Option<ChaosReport>,
}

impl LoadReport {
    /// RSS growth from the first to the last sample that has one, percent.
    #[must_use]
    pub fn rss_growth_percent(&self) -> Option<f64> {
        let rss: Vec<f64> = self.samples.iter().filter_map(|s| s.rss_mib).collect();
        let (first, last) = (*rss.first()?, *rss.last()?);
        Some((last - first) / first * 100.0)
    }
}

impl fmt::Display for LoadReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "t_s,fps,rss_mib")?;
        for s in &self.samples {
            let rss = s.rss_mib.map_or_else(String::new, |r| format!("{r:.1}"));
            writeln!(f, "{:.0},{:.1},{rss}", s.t_s, s.fps)?;
        }
        writeln!(
            f,
            "loop fps {:.2} over {:.0} s (lowest one-second rate {:.1}); step p99 {:.2} ms",
            self.loop_fps, self.seconds, self.min_fps, self.step_p99_ms
        )?;
        writeln!(
            f,
            "samples sent {} accepted {} rejected {} rate-limited {} (unaccounted {}); stream \
             errors {}",
            self.samples_sent,
            self.samples_accepted,
            self.samples_rejected,
            self.samples_rate_limited,
            self.samples_sent
                - (self.samples_accepted + self.samples_rejected + self.samples_rate_limited)
                    .min(self.samples_sent),
            self.stream_errors
        )?;
        if let Some(chaos) = &self.chaos {
            writeln!(f, "{chaos}")?;
        }
        writeln!(
            f,
            "frames received {} (dropped for slowness {}) by the reading watchers",
            self.frames_received, self.frames_dropped
        )?;
        match self.rss_growth_percent() {
            Some(g) => write!(f, "server RSS growth {g:+.2}% first to last sample"),
            None => write!(f, "server RSS not readable (give --server-pid)"),
        }
    }
}

/// Resident memory of process `pid`, MiB (Linux; `None` elsewhere or when unreadable).
#[must_use]
pub fn rss_mib(pid: u32) -> Option<f64> {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
    let kb: f64 = status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))?
        .trim()
        .trim_end_matches("kB")
        .trim()
        .parse()
        .ok()?;
    Some(kb / 1024.0)
}

/// The process listening on TCP `port` (Linux, same user or root), from `/proc/net/tcp*` and the
/// processes' open sockets.
#[must_use]
pub fn listener_pid(port: u16) -> Option<u32> {
    let mut inodes = Vec::new();
    for table in ["/proc/net/tcp", "/proc/net/tcp6"] {
        let Ok(text) = std::fs::read_to_string(table) else {
            continue;
        };
        for line in text.lines().skip(1) {
            let cols: Vec<&str> = line.split_whitespace().collect();
            let (Some(local), Some(state), Some(inode)) = (cols.get(1), cols.get(3), cols.get(9))
            else {
                continue;
            };
            let listening = *state == "0A";
            let on_port = local
                .rsplit(':')
                .next()
                .and_then(|p| u16::from_str_radix(p, 16).ok())
                == Some(port);
            if listening && on_port {
                inodes.push(format!("socket:[{inode}]"));
            }
        }
    }
    if inodes.is_empty() {
        return None;
    }
    for entry in std::fs::read_dir("/proc").ok()?.flatten() {
        let Some(pid) = entry
            .file_name()
            .to_str()
            .and_then(|s| s.parse::<u32>().ok())
        else {
            continue;
        };
        let Ok(fds) = std::fs::read_dir(entry.path().join("fd")) else {
            continue;
        };
        for fd in fds.flatten() {
            if let Ok(target) = std::fs::read_link(fd.path())
                && inodes.iter().any(|i| target.as_os_str() == i.as_str())
            {
                return Some(pid);
            }
        }
    }
    None
}

fn port_of(addr: &str) -> Option<u16> {
    crate::normalise_addr(addr)
        .rsplit(':')
        .next()?
        .trim_end_matches('/')
        .parse()
        .ok()
}

/// Tally of one gaze stream.
#[derive(Debug, Default, Clone, Copy)]
struct StreamTally {
    sent: u64,
    accepted: u64,
    rejected: u64,
    rate_limited: u64,
    failed: bool,
}

async fn gaze_stream(
    addr: String,
    options: ConnectOptions,
    index: usize,
    rate_hz: f64,
    until: Instant,
) -> Result<StreamTally, ClientError> {
    let mut client = connect_with(&addr, &options).await?;
    let (tx, rx) = mpsc::channel::<pb::GazeSample>(4096);
    let call = tokio::spawn(async move { client.stream_gaze(ReceiverStream::new(rx)).await });
    let mut tally = StreamTally::default();
    let start = Instant::now();
    let mut tick = tokio::time::interval(Duration::from_millis(1));
    tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Skip);
    let phase = index as f64 * 0.7;
    'send: loop {
        tick.tick().await;
        let now = Instant::now();
        if now >= until {
            break;
        }
        // Every sample that is due by now, so that the rate holds whatever the timer does.
        let due = (now.duration_since(start).as_secs_f64() * rate_hz) as u64;
        while tally.sent < due {
            let t = tally.sent as f64 / rate_hz;
            let angle = phase + t * std::f64::consts::TAU / 4.0;
            let sample = pb::GazeSample {
                tracker_time_s: t,
                x: 0.5 + 0.3 * angle.cos(),
                y: 0.5 + 0.3 * angle.sin(),
                validity: 1.0,
                eye: pb::Eye::Binocular as i32,
                fixation: Some(true),
            };
            if tx.send(sample).await.is_err() {
                tally.failed = true;
                break 'send;
            }
            tally.sent += 1;
        }
    }
    drop(tx);
    match call.await {
        Ok(Ok(summary)) => {
            let s = summary.into_inner();
            tally.accepted = s.accepted;
            tally.rejected = s.rejected;
            tally.rate_limited = s.rate_limited;
        }
        Ok(Err(status)) => {
            tracing::warn!(stream = index, %status, "gaze stream failed");
            tally.failed = true;
        }
        Err(e) => {
            tracing::warn!(stream = index, error = %e, "gaze stream task failed");
            tally.failed = true;
        }
    }
    Ok(tally)
}

/// What a reading watcher saw: frames, drops, step times (ms).
type WatchTally = (u64, u64, Vec<f64>);

async fn watcher(
    addr: String,
    options: ConnectOptions,
    stalled: bool,
    poses: bool,
    until: Instant,
) -> Result<WatchTally, ClientError> {
    let mut client = connect_with(&addr, &options).await?;
    let mut frames = client
        .watch_frames(pb::WatchFramesRequest {
            every_k: 1,
            include_poses: poses,
            ..Default::default()
        })
        .await
        .map_err(|status| ClientError::Rpc {
            rpc: "WatchFrames",
            status,
        })?
        .into_inner();
    let deadline = tokio::time::Instant::from_std(until);
    if stalled {
        // Holds the stream open without reading a single frame.
        tokio::time::sleep_until(deadline).await;
        drop(frames);
        return Ok((0, 0, Vec::new()));
    }
    let (mut received, mut dropped, mut steps) = (0u64, 0u64, Vec::new());
    loop {
        let next = tokio::select! {
            () = tokio::time::sleep_until(deadline) => break,
            next = frames.message() => next,
        };
        match next {
            Ok(Some(frame)) => {
                received += 1;
                dropped += frame.dropped_before;
                if let Some(p) = frame.profile {
                    steps.push(
                        (p.integrate_s
                            + p.broad_s
                            + p.narrow_s
                            + p.response_s
                            + p.prioritise_s
                            + p.measure_s)
                            * 1e3,
                    );
                }
            }
            Ok(None) => break,
            Err(status) => {
                return Err(ClientError::Rpc {
                    rpc: "WatchFrames",
                    status,
                });
            }
        }
    }
    Ok((received, dropped, steps))
}

/// A gaze stream or a watcher (in turn) on its own connection, killed mid-call: the task holding
/// its connection is aborted, so the server sees the connection vanish with the call open.
async fn doomed_client(addr: String, gaze: ConnectOptions, viewer: ConnectOptions, index: u64) {
    let work = async move {
        if index.is_multiple_of(2) {
            let mut client = connect_with(&addr, &gaze).await.ok()?;
            let (tx, rx) = mpsc::channel::<pb::GazeSample>(64);
            let call =
                tokio::spawn(async move { client.stream_gaze(ReceiverStream::new(rx)).await });
            for i in 0u32.. {
                let sample = pb::GazeSample {
                    tracker_time_s: f64::from(i) * 1e-3,
                    x: 0.5,
                    y: 0.5,
                    validity: 1.0,
                    eye: pb::Eye::Binocular as i32,
                    fixation: None,
                };
                if tx.send(sample).await.is_err() {
                    break;
                }
                tokio::time::sleep(Duration::from_millis(1)).await;
            }
            call.abort();
        } else {
            let mut client = connect_with(&addr, &viewer).await.ok()?;
            let mut frames = client
                .watch_frames(pb::WatchFramesRequest {
                    every_k: 1,
                    ..Default::default()
                })
                .await
                .ok()?
                .into_inner();
            while let Ok(Some(_)) = frames.message().await {}
        }
        Some(())
    };
    // Killed after a while mid-call: dropping the future drops its connection.
    let _ = tokio::time::timeout(Duration::from_millis(700), work).await;
}

/// `host:port` of a server address, for raw connections.
fn authority(addr: &str) -> String {
    let url = crate::normalise_addr(addr);
    let rest = url.split_once("://").map_or(url.as_str(), |(_, r)| r);
    rest.trim_end_matches('/').to_owned()
}

/// One round of connections that do nothing useful: silent, half an HTTP/1.1 head, an HTTP/2
/// preface only, and grpc-web PushGaze requests whose body stops after a few bytes.
async fn idle_round(
    authority: &str,
    idle: usize,
    stalled: usize,
    report: &mut ChaosReport,
) -> Vec<TcpStream> {
    let mut held = Vec::with_capacity(idle + stalled);
    for i in 0..idle + stalled {
        let Ok(mut stream) = TcpStream::connect(authority).await else {
            report.idle_refused += 1;
            continue;
        };
        let bytes: Vec<u8> = if i >= idle {
            report.stalled_bodies += 1;
            // A grpc-web message announced as 995 bytes of which 10 arrive.
            let mut head = format!(
                "POST /foveal.v1.Foveal/PushGaze HTTP/1.1\r\nHost: {authority}\r\n\
                 Content-Type: application/grpc-web+proto\r\nX-Grpc-Web: 1\r\n\
                 Content-Length: 1000\r\n\r\n"
            )
            .into_bytes();
            head.extend_from_slice(&[0, 0, 0, 0x03, 0xe3]);
            head.extend_from_slice(&[0x0a; 10]);
            head
        } else {
            report.idle_opened += 1;
            match i % 3 {
                0 => Vec::new(),
                1 => format!("GET / HTTP/1.1\r\nHost: {authority}\r\n").into_bytes(),
                _ => b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n".to_vec(),
            }
        };
        if !bytes.is_empty() {
            let _ = stream.write_all(&bytes).await;
        }
        held.push(stream);
    }
    held
}

/// A fresh client: connect and GetStatus, timed; `None` when it failed or took too long.
async fn probe(addr: &str, options: &ConnectOptions, timeout: Duration) -> (f64, bool) {
    let started = Instant::now();
    let call = async {
        let mut client = connect_with(addr, options).await.ok()?;
        client.get_status(pb::GetStatusRequest {}).await.ok()
    };
    let ok = matches!(tokio::time::timeout(timeout, call).await, Ok(Some(_)));
    (started.elapsed().as_secs_f64() * 1e3, ok)
}

/// Runs the disorder until `until` and reports it.
async fn chaos(
    options: LoadOptions,
    chaos: ChaosOptions,
    start: Instant,
    until: Instant,
) -> ChaosReport {
    let mut report = ChaosReport::default();
    let deadline = tokio::time::Instant::from_std(until);
    let authority = authority(&options.addr);
    let mut kill = tokio::time::interval(chaos.kill_every);
    let mut renew = tokio::time::interval(chaos.renew_every);
    let mut configure = tokio::time::interval(chaos.configure_every);
    let mut probe_tick = tokio::time::interval(chaos.probe_every);
    for tick in [&mut kill, &mut renew, &mut configure, &mut probe_tick] {
        tick.set_missed_tick_behavior(tokio::time::MissedTickBehavior::Skip);
    }
    let mut admin = connect_with(&options.addr, &chaos.admin).await.ok();
    let mut held: Vec<TcpStream> = Vec::new();
    let mut doomed = tokio::task::JoinSet::new();
    let mut probes = tokio::task::JoinSet::new();
    let mut latencies: Vec<(f64, f64)> = Vec::new();
    let mut killed = 0u64;
    let mut threshold = false;
    loop {
        tokio::select! {
            () = tokio::time::sleep_until(deadline) => break,
            _ = kill.tick() => {
                doomed.spawn(doomed_client(
                    options.addr.clone(),
                    options.gaze.clone(),
                    options.viewer.clone(),
                    killed,
                ));
                killed += 1;
            }
            _ = renew.tick() => {
                held.clear();
                held = idle_round(&authority, chaos.idle_connections, chaos.stalled_bodies, &mut report).await;
            }
            _ = configure.tick() => {
                threshold = !threshold;
                let request = pb::ConfigureRequest {
                    config: Some(pb::SceneConfig {
                        eccentricity_threshold_deg: if threshold { 5.5 } else { 5.0 },
                        ..Default::default()
                    }),
                    update_mask: None,
                };
                let ok = match admin.as_mut() {
                    Some(client) => client.configure(request).await.is_ok(),
                    None => false,
                };
                if ok {
                    report.configures.0 += 1;
                } else {
                    report.configures.1 += 1;
                    admin = connect_with(&options.addr, &chaos.admin).await.ok();
                }
            }
            _ = probe_tick.tick() => {
                let (addr, viewer, timeout) = (options.addr.clone(), options.viewer.clone(), chaos.probe_timeout);
                let at = start.elapsed().as_secs_f64();
                probes.spawn(async move { (at, probe(&addr, &viewer, timeout).await) });
            }
            Some(done) = probes.join_next() => {
                if let Ok((at, (ms, ok))) = done {
                    report.probes.0 += 1;
                    report.probes.1 += u64::from(!ok);
                    latencies.push((ms, at));
                }
            }
            Some(_) = doomed.join_next() => {}
        }
    }
    drop(held);
    doomed.shutdown().await;
    while let Some(done) = probes.join_next().await {
        if let Ok((at, (ms, ok))) = done {
            report.probes.0 += 1;
            report.probes.1 += u64::from(!ok);
            latencies.push((ms, at));
        }
    }
    report.killed = killed;
    let mut ms: Vec<f64> = latencies.iter().map(|(ms, _)| *ms).collect();
    ms.sort_by(f64::total_cmp);
    let p = |q| crate::watch::percentile(&ms, q).unwrap_or(0.0);
    if let Some(&(worst, at)) = latencies.iter().max_by(|a, b| a.0.total_cmp(&b.0)) {
        report.probe_ms = (p(0.5), p(0.99), worst);
        report.worst_at_s = at;
    }
    report
}

/// Run the load and measure.
///
/// # Errors
/// [`ClientError::InvalidOption`] for impossible options, or the first connection or rpc
/// failure of the status poller.
pub async fn run(options: &LoadOptions) -> Result<LoadReport, ClientError> {
    if options.stalled > options.watchers {
        return Err(ClientError::InvalidOption {
            name: "stalled",
            reason: format!(
                "{} stalled watchers but only {} watchers",
                options.stalled, options.watchers
            ),
        });
    }
    if !(options.rate_hz.is_finite() && options.rate_hz > 0.0) {
        return Err(ClientError::InvalidOption {
            name: "rate",
            reason: format!(
                "must be a positive number of samples per second, not {}",
                options.rate_hz
            ),
        });
    }
    let pid = options
        .server_pid
        .or_else(|| port_of(&options.addr).and_then(listener_pid));
    let mut status_client = connect_with(&options.addr, &options.viewer).await?;
    let status = |s: Result<tonic::Response<pb::Status>, tonic::Status>| {
        s.map(tonic::Response::into_inner)
            .map_err(|status| ClientError::Rpc {
                rpc: "GetStatus",
                status,
            })
    };
    let start = Instant::now();
    let until = start + options.duration;
    let first = status(status_client.get_status(pb::GetStatusRequest {}).await)?;

    let streams: Vec<_> = (0..options.streams)
        .map(|i| {
            tokio::spawn(gaze_stream(
                options.addr.clone(),
                options.gaze.clone(),
                i,
                options.rate_hz,
                until,
            ))
        })
        .collect();
    let watchers: Vec<_> = (0..options.watchers)
        .map(|i| {
            tokio::spawn(watcher(
                options.addr.clone(),
                options.viewer.clone(),
                i < options.stalled,
                options.poses,
                until,
            ))
        })
        .collect();

    let chaos_task = options
        .chaos
        .clone()
        .map(|c| tokio::spawn(chaos(options.clone(), c, start, until)));

    let mut samples = Vec::new();
    let mut next = start + options.sample_every;
    while next <= until {
        tokio::time::sleep_until(tokio::time::Instant::from_std(next)).await;
        let s = status(status_client.get_status(pb::GetStatusRequest {}).await)?;
        let sample = LoadSample {
            t_s: next.duration_since(start).as_secs_f64(),
            fps: s.fps,
            rss_mib: pid.and_then(rss_mib),
        };
        tracing::info!(t_s = sample.t_s, fps = sample.fps, rss_mib = ?sample.rss_mib, "load");
        samples.push(sample);
        next += options.sample_every;
    }
    let last = status(status_client.get_status(pb::GetStatusRequest {}).await)?;
    let seconds = start.elapsed().as_secs_f64();

    let mut report = LoadReport {
        seconds,
        loop_fps: (last.frames - first.frames) as f64 / seconds,
        min_fps: samples
            .iter()
            .filter(|s| s.t_s > 1.5)
            .map(|s| s.fps)
            .fold(f64::INFINITY, f64::min),
        ..LoadReport::default()
    };
    if !report.min_fps.is_finite() {
        report.min_fps = last.fps;
    }
    for s in streams {
        match s.await {
            Ok(Ok(t)) => {
                report.samples_sent += t.sent;
                report.samples_accepted += t.accepted;
                report.samples_rejected += t.rejected;
                report.samples_rate_limited += t.rate_limited;
                report.stream_errors += u64::from(t.failed);
            }
            Ok(Err(e)) => {
                tracing::warn!(error = %e, "gaze stream could not start");
                report.stream_errors += 1;
            }
            Err(e) => {
                tracing::warn!(error = %e, "gaze stream task failed");
                report.stream_errors += 1;
            }
        }
    }
    let mut steps = Vec::new();
    for w in watchers {
        match w.await {
            Ok(Ok((received, dropped, s))) => {
                report.frames_received += received;
                report.frames_dropped += dropped;
                steps.extend(s);
            }
            Ok(Err(e)) => tracing::warn!(error = %e, "watcher failed"),
            Err(e) => tracing::warn!(error = %e, "watcher task failed"),
        }
    }
    steps.sort_by(f64::total_cmp);
    report.step_p99_ms = crate::watch::percentile(&steps, 0.99).unwrap_or(0.0);
    report.samples = samples;
    if let Some(task) = chaos_task {
        match task.await {
            Ok(chaos) => report.chaos = Some(chaos),
            Err(e) => tracing::warn!(error = %e, "the chaos task failed"),
        }
    }
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn own_rss_is_readable_on_linux() {
        if cfg!(target_os = "linux") {
            let rss = rss_mib(std::process::id()).expect("VmRSS");
            assert!(rss > 0.1, "{rss}");
        }
        assert_eq!(port_of("http://127.0.0.1:50051"), Some(50051));
        assert_eq!(authority("127.0.0.1:50051"), "127.0.0.1:50051");
        assert_eq!(authority("https://localhost:7000/"), "localhost:7000");
    }
}
