//! A session recorded over a real socket (streamed and pushed gaze, a Configure swap) replays
//! bit for bit; a path that cannot be written refuses start-up.

use std::path::PathBuf;
use std::time::Duration;

use foveal_engine::BudgetSpec;
use foveal_proto::pb;
use foveal_session::Session;
use foveal_tests::*;

/// A fresh path in the system's temporary directory, removed on drop.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str) -> Self {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_nanos());
        Self(std::env::temp_dir().join(format!(
            "foveal-{name}-{}-{nanos}.jsonl",
            std::process::id()
        )))
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_recorded_session_replays_bit_for_bit() {
    let file = TempFile::new("session");
    let mut config = small_config(300, 120.0);
    config.sim.budget = BudgetSpec::SphereTests(400);
    config.record = Some(file.0.clone());
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;

    // Streamed gaze, slowly enough that several samples steer frames.
    let (tx, rx) = tokio::sync::mpsc::channel(8);
    let mut gaze_client = client.clone();
    let call = tokio::spawn(async move {
        gaze_client
            .stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });
    let streamed: Vec<(f64, f64)> = (0..30)
        .map(|i| (0.1 + 0.025 * f64::from(i), 0.8 - 0.02 * f64::from(i)))
        .collect();
    for (i, &(x, y)) in streamed.iter().enumerate() {
        tx.send(sample(i as f64 * 0.004, x, y))
            .await
            .expect("stream open");
        tokio::time::sleep(Duration::from_millis(4)).await;
    }
    frame_where(&mut frames, "a frame steered by the stream", |f| {
        fixation(f).source == FixationSource::Gaze as i32
    })
    .await;

    // A scene change mid-session, then pushed gaze on the new scene.
    let first_frame_index = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                seed: 5,
                ..Default::default()
            }),
            update_mask: Some(prost_types::FieldMask {
                paths: vec!["seed".into()],
            }),
        })
        .await
        .expect("configure")
        .into_inner()
        .first_frame_index;
    client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![sample(1.0, 0.3, 0.3), sample(1.004, 0.31, 0.29)],
            source: "e2e".into(),
        })
        .await
        .expect("PushGaze");
    frame_where(&mut frames, "frames of the new scene", |f| {
        f.index > first_frame_index + 20
    })
    .await;
    drop(tx);
    let summary = within("StreamGaze's summary", call)
        .await
        .expect("task")
        .expect("StreamGaze")
        .into_inner();
    assert_eq!(summary.accepted, 30);
    server.stop().await.expect("clean stop");

    let f = std::fs::File::open(&file.0).expect("the session file exists");
    let s = Session::read(std::io::BufReader::new(f)).expect("a complete session");
    assert_eq!(
        s.trailer.dropped, 0,
        "a few hundred records never fill the channel"
    );
    assert_eq!(s.header.sim.budget, BudgetSpec::SphereTests(400));
    assert_eq!(s.header.server.frame_rate_hz, 120.0);
    // Every accepted sample, with its source, in the order sent.
    let sources: Vec<&str> = s.gaze.iter().map(|g| g.source.as_str()).collect();
    assert_eq!(sources.len(), 32, "{sources:?}");
    assert!(
        sources[..30].iter().all(|&s| s == "stream:0"),
        "{sources:?}"
    );
    assert!(
        sources[30..].iter().all(|&s| s == "push:e2e@127.0.0.1"),
        "{sources:?}"
    );
    let xs: Vec<f64> = s.gaze[..30].iter().filter_map(|g| g.x).collect();
    assert_eq!(xs, streamed.iter().map(|p| p.0).collect::<Vec<_>>());
    assert!(
        s.gaze
            .windows(2)
            .all(|w| w[0].received_s <= w[1].received_s)
    );
    // Every frame, in order, the swap at its boundary.
    assert!(s.frames.len() as u64 > first_frame_index + 20);
    assert!(
        s.frames
            .iter()
            .enumerate()
            .all(|(i, f)| f.index == i as u64)
    );
    assert_eq!(s.scenes.len(), 1);
    assert_eq!(
        (s.scenes[0].first_frame, s.scenes[0].sim.scene.seed),
        (first_frame_index, 5)
    );
    let steered = s
        .frames
        .iter()
        .filter(|f| f.fixation_source == "gaze")
        .count();
    assert!(steered > 0, "the gaze reached the recorded fixations");
    assert!(
        s.frames.iter().any(|f| f.report.deemed > 0),
        "the budget bites, so the fixation matters to the metrics"
    );

    let out = foveal_session::replay(&s).expect("replays");
    assert!(out.is_bit_for_bit(), "{out:?}");
    assert_eq!(out.frames, s.frames.len() as u64);
}

#[tokio::test]
async fn a_record_path_that_cannot_be_created_refuses_start_up() {
    let dir = TempFile::new("no-such-dir");
    let path = dir.0.join("session.jsonl");
    let mut config = small_config(50, 60.0);
    config.record = Some(path.clone());
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let e = within(
        "start-up to be refused",
        foveal_server::run(listener, config, std::future::pending()),
    )
    .await
    .expect_err("refused");
    let msg = e.to_string();
    assert!(
        msg.contains("--record") && msg.contains(&path.display().to_string()),
        "{msg}"
    );
}
