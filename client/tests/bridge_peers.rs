//! The Pupil and LSL bridges against real peers on loopback: a fake Pupil Capture written with
//! pyzmq and an LSL outlet written with pylsl (which bundles liblsl), each bridged into an
//! in-process server.
//!
//! The peers need a Python with pyzmq, msgpack and pylsl: its path goes in FOVEAL_PEER_PYTHON
//! (CI makes a venv). Without it these tests print why and pass; with FOVEAL_REQUIRE_PEERS=1 a
//! missing interpreter is a failure.

// The gaze recording (`common::gaze_data`) is not needed here.
#[allow(dead_code)]
mod common;

use std::io::{BufRead, BufReader};
use std::path::PathBuf;
use std::process::{Child, Command, Stdio};
use std::sync::mpsc as std_mpsc;
use std::time::Duration;

use common::TestServer;
use foveal_client::bridge::{self, BridgeReport, ForwardOptions, StopReason};
use foveal_client::gaze::lsl::{ChannelMap, Units};
use foveal_client::gaze::{Eye, GazeSample, ScreenPx};
use foveal_client::lsl::{self, LslOptions};
use foveal_client::pupil::{self, PupilOptions};
use foveal_client::sender::{GazeSender, Transport};
use foveal_client::source::{SourceError, SourceItem};
use tokio::net::TcpListener;
use tokio::sync::mpsc;

/// The interpreter for the peers, or `None` (after saying why) when the test is to be skipped.
fn peer_python() -> Option<PathBuf> {
    let required = std::env::var("FOVEAL_REQUIRE_PEERS").is_ok_and(|v| v == "1");
    match std::env::var_os("FOVEAL_PEER_PYTHON") {
        Some(path) if !path.is_empty() => Some(PathBuf::from(path)),
        _ => {
            assert!(
                !required,
                "FOVEAL_REQUIRE_PEERS=1 but FOVEAL_PEER_PYTHON (a Python with pyzmq, msgpack \
                 and pylsl) is not set"
            );
            eprintln!(
                "skipped: set FOVEAL_PEER_PYTHON to a Python with pyzmq, msgpack and pylsl to \
                 run the Pupil and LSL peer tests"
            );
            None
        }
    }
}

/// A peer process, killed when dropped (a failed test must not leave it running).
struct Peer {
    child: Child,
    /// The first line the peer printed (`READY ...`).
    ready: String,
}

impl Drop for Peer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Starts `script` (in `tests/peers/`) and waits for its `READY` line.
fn start_peer(python: &PathBuf, script: &str, args: &[&str]) -> Peer {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/peers")
        .join(script);
    let mut child = Command::new(python)
        .arg(&path)
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .unwrap_or_else(|e| panic!("start {} {}: {e}", python.display(), path.display()));
    let stdout = child.stdout.take().expect("piped stdout");
    let (tx, rx) = std_mpsc::channel();
    std::thread::spawn(move || {
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let _ = tx.send(line);
    });
    let ready = rx
        .recv_timeout(Duration::from_secs(30))
        .unwrap_or_else(|_| panic!("{script} did not print READY within 30 s"));
    assert!(ready.starts_with("READY"), "{script} printed {ready:?}");
    Peer {
        child,
        ready: ready.trim().to_owned(),
    }
}

/// Copies a source's items into a list while passing them on, so that a test sees what the
/// bridge forwarded.
fn tap(
    mut source: mpsc::Receiver<SourceItem>,
) -> (
    mpsc::Receiver<SourceItem>,
    tokio::task::JoinHandle<Vec<Result<GazeSample, String>>>,
) {
    let (tx, rx) = mpsc::channel(64);
    let seen = tokio::spawn(async move {
        let mut seen = Vec::new();
        while let Some(item) = source.recv().await {
            seen.push(item.as_ref().map(|s| *s).map_err(ToString::to_string));
            if tx.send(item).await.is_err() {
                break;
            }
        }
        seen
    });
    (rx, seen)
}

/// Bridges `source` into `server` and gives the report and every item the source gave.
async fn bridge_into(
    server: &TestServer,
    source: mpsc::Receiver<SourceItem>,
) -> (BridgeReport, Vec<Result<GazeSample, String>>) {
    let (source, seen) = tap(source);
    let client = foveal_client::connect(&server.addr).await.expect("connect");
    let sender = GazeSender::open(client, Transport::Stream, "test:peer").expect("sender");
    let report = tokio::time::timeout(
        Duration::from_secs(60),
        bridge::forward(
            source,
            sender,
            ForwardOptions::default(),
            std::future::pending(),
        ),
    )
    .await
    .expect("the bridge ends within 60 s")
    .expect("bridge");
    (report, seen.await.expect("tap"))
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pupil_gaze_is_flipped_low_confidence_is_missing_and_a_closed_pupil_ends_it() {
    let Some(python) = peer_python() else { return };
    let peer = start_peer(&python, "fake_pupil.py", &[]);
    let port: u16 = peer.ready["READY ".len()..].parse().expect("port");
    let server = TestServer::start().await;
    let source = pupil::pupil(PupilOptions {
        port,
        connect_timeout: Duration::from_secs(1),
        ..PupilOptions::default()
    });
    let (report, seen) = bridge_into(&server, source).await;

    let samples: Vec<GazeSample> = seen.iter().filter_map(|i| i.clone().ok()).collect();
    assert_eq!(samples.len(), 4, "{seen:?}");
    // norm_pos has its origin bottom-left: y = 1 - norm_pos[1].
    let expected = [
        (100.00, 0.25, 0.25, Eye::Binocular, true),
        (100.01, 0.50, 0.80, Eye::Right, true),
        (100.02, 0.00, 0.00, Eye::Left, false),
        (100.03, 0.40, 0.10, Eye::Binocular, true),
    ];
    for (s, (t, x, y, eye, valid)) in samples.iter().zip(expected) {
        assert_eq!((s.t_s, s.eye, s.is_valid()), (t, eye, valid), "{s:?}");
        assert!(close(s.x, x) && close(s.y, y), "{s:?}");
    }
    // The peer closed: the heartbeat notices, and the error names Pupil Remote.
    let StopReason::SourceFailed(why) = &report.stopped else {
        panic!("{report}");
    };
    assert!(
        why.contains(&format!(
            "Pupil Remote at 127.0.0.1:{port} stopped answering"
        )),
        "{why}"
    );
    assert_eq!((report.counts.valid, report.counts.invalid), (3, 1));
    assert_eq!(
        (report.summary.accepted, report.summary.rejected),
        (3, 1),
        "{report}"
    );
    assert_eq!(report.summary.last_accepted_time_s, Some(100.03));
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pupil_surface_gaze_is_used_and_the_eye_filter_keeps_one_eye() {
    let Some(python) = peer_python() else { return };
    let peer = start_peer(&python, "fake_pupil.py", &[]);
    let port: u16 = peer.ready["READY ".len()..].parse().expect("port");
    let server = TestServer::start().await;
    let source = pupil::pupil(PupilOptions {
        port,
        surface: Some("screen".into()),
        eye: Some(Eye::Binocular),
        connect_timeout: Duration::from_secs(1),
        ..PupilOptions::default()
    });
    let (report, seen) = bridge_into(&server, source).await;
    let samples: Vec<GazeSample> = seen.iter().filter_map(|i| i.clone().ok()).collect();
    // The two binocular entries of gaze_on_surfaces, at half the raw norm_pos, y flipped.
    assert_eq!(samples.len(), 2, "{seen:?}");
    assert!(close(samples[0].x, 0.125) && close(samples[0].y, 1.0 - 0.375));
    assert!(close(samples[1].x, 0.2) && close(samples[1].y, 1.0 - 0.45));
    assert_eq!(report.summary.accepted, 2, "{report}");
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn no_pupil_remote_is_an_error_naming_host_and_port_in_bounded_time() {
    let port = {
        let l = TcpListener::bind("127.0.0.1:0").await.expect("bind");
        l.local_addr().expect("addr").port()
    };
    let mut rx = pupil::pupil(PupilOptions {
        port,
        connect_timeout: Duration::from_millis(500),
        ..PupilOptions::default()
    });
    let item = tokio::time::timeout(Duration::from_secs(5), rx.recv())
        .await
        .expect("gives up within 5 s")
        .expect("an item");
    let err = item.expect_err("nobody there, no sample");
    assert!(matches!(err, SourceError::Io { .. }), "{err}");
    assert!(
        err.to_string()
            .contains(&format!("Pupil Remote at 127.0.0.1:{port}")),
        "{err}"
    );
    assert!(rx.recv().await.is_none(), "the source ends");
}

/// One LSL outlet at a time: every outlet listens on UDP port 16571, and a query sent to
/// 127.0.0.1 reaches only one of the sockets bound there, which may be the other test's.
static LSL_OUTLET: tokio::sync::Mutex<()> = tokio::sync::Mutex::const_new(());

/// Runs the LSL outlet peer with `peer_args` and bridges it with `channels`.
async fn lsl_run(
    name: &str,
    peer_args: &[&str],
    channels: ChannelMap,
) -> Option<(BridgeReport, Vec<GazeSample>)> {
    let python = peer_python()?;
    let _one_outlet = LSL_OUTLET.lock().await;
    let mut args = vec!["--name", name];
    args.extend_from_slice(peer_args);
    let _peer = start_peer(&python, "lsl_outlet.py", &args);
    let server = TestServer::start().await;
    let options = LslOptions {
        name: Some(name.into()),
        channels,
        resolve_timeout: Duration::from_secs(10),
        resolve_addresses: vec!["127.0.0.1".parse().expect("address")],
        // The outlet closing ends the source (with an error) instead of being waited for.
        reconnect: false,
        ..LslOptions::default()
    };
    // The outlet's time service answers, and on one machine its clock is the inlet's.
    let (info, addr) = lsl::resolve(&options).await.expect("the outlet is found");
    let service = std::net::SocketAddr::new(addr, info.v4service_port);
    let correction = lsl::probe_clock(service)
        .await
        .expect("probe")
        .expect("the outlet answers time probes");
    assert!(correction.abs() < 1e-3, "correction {correction} s");
    let source = lsl::lsl(options);
    let (report, seen) = bridge_into(&server, source).await;
    server.stop().await;
    // The last item is the error that ends the source (the outlet closed); none before it.
    let samples: Vec<GazeSample> = seen.iter().filter_map(|i| i.clone().ok()).collect();
    assert_eq!(samples.len() + 1, seen.len(), "{seen:?}");
    Some((report, samples))
}

/// What the outlet sends: (x, y) or None for its NaN sample, at its LSL times.
const LSL_EXPECTED: [(f64, Option<(f64, f64)>); 5] = [
    (1000.00, Some((0.10, 0.20))),
    (1000.01, Some((0.30, 0.40))),
    (1000.02, None),
    (1000.03, Some((0.50, 0.60))),
    // Sent with a deduced time stamp: the previous one plus 1 / 100 Hz.
    (1000.04, Some((0.70, 0.80))),
];

/// The outlet closed, and the bridge was told not to wait for it: an error, not a success.
fn assert_closed_without_waiting(report: &BridgeReport) {
    let StopReason::SourceFailed(why) = &report.stopped else {
        panic!("the closed outlet is a failure: {report}");
    };
    assert!(
        why.contains("the outlet closed the stream") && why.contains("--no-reconnect"),
        "{why}"
    );
}

fn check_lsl(report: &BridgeReport, samples: &[GazeSample], scale: (f64, f64)) {
    assert_closed_without_waiting(report);
    assert_eq!(samples.len(), LSL_EXPECTED.len(), "{samples:?}");
    for (s, (t, position)) in samples.iter().zip(LSL_EXPECTED) {
        // Outlet and inlet share this machine's clock: the correction is well under 1 ms.
        assert!((s.t_s - t).abs() < 1e-3, "time {} for {t}", s.t_s);
        match position {
            Some((x, y)) => {
                assert!(s.is_valid(), "{s:?}");
                let (x, y) = (x * scale.0, y * scale.1);
                assert!((s.x - x).abs() < 1e-6 && (s.y - y).abs() < 1e-6, "{s:?}");
            }
            None => assert!(!s.is_valid(), "the NaN sample is missing: {s:?}"),
        }
    }
    assert_eq!((report.counts.valid, report.counts.invalid), (4, 1));
    assert_eq!(
        (report.summary.accepted, report.summary.rejected),
        (4, 1),
        "{report}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsl_float32_outlet_is_bridged_with_nan_as_missing() {
    let name = format!("foveal-f32-{}", std::process::id());
    let Some((report, samples)) = lsl_run(&name, &[], ChannelMap::default()).await else {
        return;
    };
    check_lsl(&report, &samples, (1.0, 1.0));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsl_double_outlet_with_other_channels_in_pixels() {
    // Layout y, pupil, x, read as pixels of a 2x4 px screen: x is halved, y quartered.
    let name = format!("foveal-f64-{}", std::process::id());
    let channels = ChannelMap {
        x: 2,
        y: 0,
        units: Units::Pixels(ScreenPx::new(2.0, 4.0).expect("screen")),
    };
    let Some((report, samples)) =
        lsl_run(&name, &["--format", "double64", "--swap"], channels).await
    else {
        return;
    };
    check_lsl(&report, &samples, (0.5, 0.25));
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsl_chunks_stamped_when_pushed_lose_no_sample() {
    // Two chunks of five at 100 Hz, the second stamped 30 ms early: by their stamps it would
    // begin 30 ms before the first ends.
    let name = format!("foveal-chunks-{}", std::process::id());
    let Some((report, samples)) = lsl_run(&name, &["--chunks"], ChannelMap::default()).await else {
        return;
    };
    assert_closed_without_waiting(&report);
    assert_eq!(samples.len(), 10, "{samples:?}");
    for (k, s) in samples.iter().enumerate() {
        let t = 1000.0 + 0.01 * k as f64;
        assert!((s.t_s - t).abs() < 1e-3, "sample {k} at {} for {t}", s.t_s);
    }
    assert_eq!(
        (report.summary.accepted, report.summary.rejected),
        (10, 0),
        "{report}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn lsl_bridge_waits_for_a_restarted_outlet_and_says_so() {
    let Some(python) = peer_python() else { return };
    let _one_outlet = LSL_OUTLET.lock().await;
    let name = format!("foveal-restart-{}", std::process::id());
    let _peer = start_peer(&python, "lsl_outlet.py", &["--name", &name, "--restart"]);
    let server = TestServer::start().await;
    let addr = server.addr.clone();
    let (stdout, stderr) = tokio::task::spawn_blocking(move || {
        let mut child = Command::new(env!("CARGO_BIN_EXE_foveal"))
            .env("RUST_LOG", "info")
            .args(["bridge", "--addr", &addr, "lsl", "--name", &name])
            .args(["--resolve-timeout", "10"])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("start foveal");
        let stderr = child.stderr.take().expect("piped stderr");
        let (tx, rx) = std_mpsc::channel();
        std::thread::spawn(move || {
            for line in BufReader::new(stderr).lines().map_while(Result::ok) {
                if tx.send(line).is_err() {
                    break;
                }
            }
        });
        // Until the outlet has come back, sent its samples and closed again.
        let mut log = Vec::new();
        let mut back = false;
        loop {
            let line = rx
                .recv_timeout(Duration::from_secs(60))
                .unwrap_or_else(|_| panic!("the bridge went quiet: {log:#?}"));
            back |= line.contains("reconnected");
            let closed_again = back && line.contains("the outlet closed the stream");
            log.push(line);
            if closed_again {
                break;
            }
        }
        let interrupted = Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .expect("kill runs");
        assert!(interrupted.success());
        let out = child.wait_with_output().expect("foveal ends");
        log.extend(rx.try_iter());
        (
            String::from_utf8_lossy(&out.stdout).into_owned(),
            log.join("\n"),
        )
    })
    .await
    .expect("join");
    assert!(
        stderr.contains("the LSL outlet is back: reconnected, receiving the stream again"),
        "{stderr}"
    );
    assert!(stdout.contains("stopped: interrupted"), "{stdout}");
    // Five samples before the restart (one NaN), two after.
    assert!(
        stdout.contains("7 samples (6 valid, 1 invalid)"),
        "{stdout}\n{stderr}"
    );
    assert!(
        stdout.contains("accepted 6, rejected 1 (missing 1)"),
        "{stdout}"
    );
    server.stop().await;
}
