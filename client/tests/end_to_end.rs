//! The client library against an in-process server over loopback: replaying a real recording,
//! bridging a (fake) Gazepoint tracker, watching frames into CSV, and the health check.

mod common;

use std::fs::File;
use std::io::BufReader;
use std::time::Duration;

use common::{TestServer, gaze_data};
use foveal_client::bridge::{self, BridgeReport, ForwardOptions, StopReason};
use foveal_client::gaze::csv::CsvGazeReader;
use foveal_client::gaze::opengaze;
use foveal_client::health::{self, ServingStatus};
use foveal_client::pacer::Pace;
use foveal_client::sender::{GazeSender, Transport};
use foveal_client::source::{self, GazepointOptions, RecordingFormat};
use foveal_client::watch::{self, CSV_COLUMNS, CSV_HEADER, WatchOptions};
use foveal_proto::pb;
use tokio::io::{AsyncBufReadExt, AsyncWriteExt, BufReader as AsyncBufReader};
use tokio::net::TcpListener;

const RECORDING: &str = "eyelink-1000hz-left.samples.csv";
/// Seconds of the recording to replay: 3000 samples, all valid (the first blink is at 11.3 s).
const REPLAY_S: f64 = 3.0;

/// The frames that follow a connect, `n` of them, through the library's watcher.
async fn frames(addr: &str, n: u64) -> Vec<pb::Frame> {
    let mut client = foveal_client::connect(addr).await.expect("connect");
    let mut stream = client
        .watch_frames(pb::WatchFramesRequest {
            every_k: 1,
            include_poses: false,
            ..Default::default()
        })
        .await
        .expect("watch")
        .into_inner();
    let mut out = Vec::new();
    while (out.len() as u64) < n {
        let frame = tokio::time::timeout(Duration::from_secs(10), stream.message())
            .await
            .expect("a frame within 10 s")
            .expect("stream ok")
            .expect("stream open");
        out.push(frame);
    }
    out
}

async fn status(addr: &str) -> pb::Status {
    foveal_client::connect(addr)
        .await
        .expect("connect")
        .get_status(pb::GetStatusRequest {})
        .await
        .expect("status")
        .into_inner()
}

async fn replay(addr: &str, transport: Transport, format: RecordingFormat) -> BridgeReport {
    let name = match format {
        RecordingFormat::Csv => RECORDING,
        RecordingFormat::Asc => "eyelink-1000hz-left.asc",
    };
    let (detected, rx) = source::recording(&gaze_data(name), source::ReadOptions::default())
        .expect("open recording");
    assert_eq!(detected, format);
    let client = foveal_client::connect(addr).await.expect("connect");
    let sender = GazeSender::open(client, transport, "test:replay").expect("sender");
    let options = ForwardOptions {
        pace: Pace::AsFastAsPossible,
        duration_s: Some(REPLAY_S),
    };
    bridge::forward(rx, sender, options, std::future::pending())
        .await
        .expect("replay")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn replayed_recording_is_accepted_and_steers_the_fixation() {
    let server = TestServer::start().await;
    let expected: Vec<_> = CsvGazeReader::new(BufReader::new(
        File::open(gaze_data(RECORDING)).expect("open recording"),
    ))
    .map(|s| s.expect("recording parses"))
    .take_while(|s| s.t_s < REPLAY_S)
    .collect();
    assert_eq!(expected.len(), 3000);
    assert!(expected.iter().all(|s| s.is_valid()));

    let report = replay(&server.addr, Transport::Stream, RecordingFormat::Csv).await;
    assert_eq!(report.stopped, StopReason::Duration);
    assert_eq!(report.counts.valid, 3000, "{report}");
    assert_eq!((report.counts.invalid, report.counts.malformed), (0, 0));
    assert_eq!(report.summary.sent, 3000);
    assert_eq!(report.summary.accepted, 3000, "{report}");
    assert_eq!(report.summary.rejected, 0, "{report}");
    let last = expected.last().expect("samples");
    assert_eq!(report.summary.last_accepted_time_s, Some(last.t_s));
    assert_eq!(status(&server.addr).await.gaze_samples_accepted, 3000);

    // The frames now use the last replayed position. The first ones a new watcher gets may have
    // been stepped before the replay ended (a frame in progress when the last sample arrived,
    // and on a loaded machine the loop runs late): those carry an older sample, or none. Every
    // frame after the first that carries the last sample carries it too.
    let watched = frames(&server.addr, 60).await;
    let carries_last = |f: &pb::Frame| {
        f.fixation.as_ref().is_some_and(|x| {
            x.source == pb::FixationSource::Gaze as i32
                && x.raw.as_ref().is_some_and(|r| r.tracker_time_s == last.t_s)
        })
    };
    let fresh: Vec<_> = watched.iter().skip_while(|f| !carries_last(f)).collect();
    assert!(fresh.len() >= 3, "{watched:?}");
    for frame in fresh {
        let fixation = frame.fixation.expect("fixation");
        assert!(carries_last(frame), "{fixation:?}");
        assert!(
            (fixation.x - last.x).abs() < 1e-9 && (fixation.y - last.y).abs() < 1e-9,
            "fixation {fixation:?}, last replayed {last:?}"
        );
    }

    // The same seconds from the ASC file, pushed in batches, add as many samples again.
    let report = replay(
        &server.addr,
        Transport::Push { batch: 64 },
        RecordingFormat::Asc,
    )
    .await;
    assert_eq!(
        (report.counts.valid, report.summary.accepted),
        (3000, 3000),
        "{report}"
    );
    assert_eq!(status(&server.addr).await.gaze_samples_accepted, 6000);
    server.stop().await;
}

/// REC lines of the fake tracker: four valid, one invalid (FPOGV="0"), one malformed.
const TRACKER_LINES: [&str; 7] = [
    "<ACK ID=\"ENABLE_SEND_DATA\" STATE=\"1\" />",
    "<REC TIME=\"10.000\" FPOGX=\"0.25\" FPOGY=\"0.50\" FPOGS=\"9.9\" FPOGD=\"0.1\" FPOGID=\"3\" FPOGV=\"1\" />",
    "<REC TIME=\"10.016\" FPOGX=\"0.26\" FPOGY=\"0.51\" FPOGV=\"1\" />",
    "<REC TIME=\"10.033\" FPOGX=\"0\" FPOGY=\"0\" FPOGV=\"0\" />",
    "<REC TIME=\"10.050\" FPOGX=\"zero point three\" FPOGY=\"0.5\" FPOGV=\"1\" />",
    "<REC TIME=\"10.066\" FPOGX=\"0.30\" FPOGY=\"0.55\" FPOGV=\"1\" />",
    "<REC TIME=\"10.083\" FPOGX=\"0.31\" FPOGY=\"0.56\" FPOGV=\"1\" />",
];

/// A Gazepoint stand-in: checks the SET handshake, sends [`TRACKER_LINES`], closes.
async fn fake_gazepoint(listener: TcpListener) {
    let (socket, _) = listener.accept().await.expect("accept");
    let (read, mut write) = socket.into_split();
    let mut lines = AsyncBufReader::new(read).lines();
    for expected in opengaze::handshake_commands() {
        let line = tokio::time::timeout(Duration::from_secs(5), lines.next_line())
            .await
            .expect("handshake within 5 s")
            .expect("readable")
            .expect("a handshake line");
        assert_eq!(format!("{line}\n"), expected.replace("\r\n", "\n"));
    }
    for line in TRACKER_LINES {
        write
            .write_all(format!("{line}\r\n").as_bytes())
            .await
            .expect("write");
    }
    write.shutdown().await.expect("close");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn gazepoint_bridge_forwards_valid_and_invalid_and_skips_malformed() {
    let server = TestServer::start().await;
    let tracker = TcpListener::bind("127.0.0.1:0").await.expect("bind");
    let port = tracker.local_addr().expect("addr").port();
    let fake = tokio::spawn(fake_gazepoint(tracker));

    let rx = source::gazepoint(GazepointOptions {
        port,
        max_retries: 0,
        ..GazepointOptions::default()
    });
    let client = foveal_client::connect(&server.addr).await.expect("connect");
    let sender = GazeSender::open(client, Transport::Stream, "test:gazepoint").expect("sender");
    let report = bridge::forward(
        rx,
        sender,
        ForwardOptions::default(),
        std::future::pending(),
    )
    .await
    .expect("bridge");
    fake.await
        .expect("the fake tracker saw the right handshake");

    assert_eq!(report.stopped, StopReason::EndOfInput, "{report}");
    let c = report.counts;
    assert_eq!((c.valid, c.invalid, c.malformed), (4, 1, 1), "{report}");
    assert_eq!(
        (report.summary.accepted, report.summary.rejected),
        (4, 1),
        "{report}"
    );
    assert_eq!(report.summary.rejections[0].index, 2);
    assert_eq!(report.summary.rejections[0].field, "validity");
    assert_eq!(report.summary.last_accepted_time_s, Some(10.083));
    let s = status(&server.addr).await;
    assert_eq!((s.gaze_samples_accepted, s.gaze_samples_rejected), (4, 1));
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn unreachable_gazepoint_gives_up_after_its_retries() {
    let port = {
        let l = TcpListener::bind("127.0.0.1:0").await.expect("bind");
        l.local_addr().expect("addr").port()
    };
    let mut rx = source::gazepoint(GazepointOptions {
        port,
        max_retries: 2,
        initial_backoff: Duration::from_millis(10),
        ..GazepointOptions::default()
    });
    let item = tokio::time::timeout(Duration::from_secs(10), rx.recv())
        .await
        .expect("gives up in time")
        .expect("an item");
    let err = item.expect_err("no tracker, no sample");
    assert!(err.to_string().contains("gave up after 2 retries"), "{err}");
    assert!(rx.recv().await.is_none(), "the source ends");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn watch_writes_a_parseable_csv_of_n_frames() {
    let server = TestServer::start().await;
    let mut client = foveal_client::connect(&server.addr).await.expect("connect");
    let options = WatchOptions {
        frames: Some(12),
        every_k: 2,
        ..WatchOptions::default()
    };
    let mut csv = Vec::new();
    let mut summary = Vec::new();
    let report = watch::watch(
        &mut client,
        options,
        Some(&mut csv),
        Some(&mut summary),
        std::future::pending(),
    )
    .await
    .expect("watch");
    assert_eq!(report.frames, 12);

    let text = String::from_utf8(csv).expect("utf-8");
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some(CSV_HEADER));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len(), 12);
    let col = |name: &str| CSV_COLUMNS.iter().position(|c| *c == name).expect(name);
    let mut previous: Option<u64> = None;
    for row in &rows {
        assert_eq!(row.len(), CSV_COLUMNS.len(), "{row:?}");
        let index: u64 = row[col("index")].parse().expect("index");
        assert_eq!(index % 2, 0, "every_k = 2");
        assert!(previous.is_none_or(|p| index > p));
        previous = Some(index);
        for name in ["sim_time_s", "collision_time_s", "delta", "p", "fixation_x"] {
            let v: f64 = row[col(name)].parse().expect(name);
            assert!(v.is_finite() && v >= 0.0, "{name} = {v}");
        }
        for name in [
            "candidate_pairs",
            "real_collisions",
            "deemed",
            "sphere_tests",
        ] {
            row[col(name)].parse::<u64>().expect(name);
        }
        assert_eq!(row[col("fixation_source")], "FALLBACK_NO_GAZE");
    }
    // The last, partial summary window is printed at the end.
    let summary = String::from_utf8(summary).expect("utf-8");
    assert!(
        summary.contains("fps") && summary.contains("T p50"),
        "{summary}"
    );
    server.stop().await;
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_reports_serving() {
    let server = TestServer::start().await;
    let timeout = Duration::from_secs(5);
    for service in ["", health::FOVEAL_SERVICE] {
        let status = health::check(&server.addr, service, timeout)
            .await
            .expect("health check");
        assert_eq!(status, ServingStatus::Serving, "service {service:?}");
    }
    let unknown = health::check(&server.addr, "no.such.Service", timeout)
        .await
        .expect("health check");
    assert_eq!(unknown, ServingStatus::ServiceUnknown);
    let addr = server.addr.clone();
    server.stop().await;

    let refused = health::check(&addr, "", Duration::from_millis(500)).await;
    assert!(refused.is_err(), "{refused:?}");
}
