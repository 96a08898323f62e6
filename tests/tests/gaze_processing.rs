//! Online gaze processing on the server, over real sockets: with a fixation detector, a saccade
//! does not steer (the last fixation is held while the raw sample is reported), and a blink is
//! reported as track loss; one wild timestamp does not block the stream. Two trackers at once
//! are processed apart; a long blink widens what the schedulers treat as foveal.

use foveal_gaze::detect::DetectorParams;
use foveal_gaze::online::ProcessorConfig;
use foveal_proto::pb;
use foveal_proto::pb::foveal_client::FovealClient;
use foveal_tests::*;
use tonic::transport::Channel;

fn missing(t: f64) -> pb::GazeSample {
    pb::GazeSample {
        validity: 0.0,
        ..sample(t, 0.0, 0.0)
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_detector_holds_the_fixation_through_a_saccade_and_reports_a_blink() {
    let mut config = small_config(200, 100.0);
    config.gaze_processing = ProcessorConfig {
        detector: Some(DetectorParams::default()),
        ..ProcessorConfig::default()
    };
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;

    // 200 ms of a fixation at (0.25, 0.5) at 1 kHz tracker time, then two saccade samples.
    let mut samples: Vec<pb::GazeSample> = (0..200)
        .map(|i| sample(f64::from(i) * 0.001, 0.25, 0.5))
        .collect();
    samples.push(sample(0.200, 0.5, 0.5));
    samples.push(sample(0.201, 0.75, 0.5));
    let response = client
        .push_gaze(pb::PushGazeRequest {
            samples,
            source: "test".into(),
        })
        .await
        .expect("PushGaze")
        .into_inner();
    assert_eq!((response.accepted, response.rejected), (202, 0));
    let done = frames_so_far(&mut client).await;
    let f = frame_where(&mut frames, "the frame after the saccade", |f| {
        f.index > done
    })
    .await;
    let used = fixation(&f);
    assert_eq!(used.source, pb::FixationSource::Gaze as i32);
    assert_eq!(used.track, pb::GazeTrack::Saccade as i32);
    assert_eq!(
        (used.x, used.y),
        (0.25, 0.5),
        "the fixation, not the saccade"
    );
    let raw = used.raw.expect("the raw sample is reported");
    assert_eq!((raw.x, raw.tracker_time_s), (0.75, 0.201));
    assert!(raw.age_s >= 0.0 && raw.age_s < 1.0, "{raw:?}");

    // A blink, with one wild timestamp in it: rejected on its own, counted.
    let response = client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![missing(0.202), sample(1e9, 0.5, 0.5), missing(0.203)],
            source: "test".into(),
        })
        .await
        .expect("PushGaze")
        .into_inner();
    assert_eq!((response.accepted, response.rejected), (0, 3));
    assert_eq!(response.rejections[1].field, "tracker_time_s");
    assert!(
        response.rejections[1].reason.contains("jumps forward"),
        "{:?}",
        response.rejections
    );
    let done = frames_so_far(&mut client).await;
    let f = frame_where(&mut frames, "the frame after the blink", |f| f.index > done).await;
    let used = fixation(&f);
    assert_eq!(used.track, pb::GazeTrack::Holding as i32, "{used:?}");
    assert_eq!((used.x, used.y), (0.25, 0.5));
    server.stop().await.expect("clean stop");
}

async fn push(client: &mut FovealClient<Channel>, source: &str, samples: Vec<pb::GazeSample>) {
    let n = samples.len() as u64;
    let r = client
        .push_gaze(pb::PushGazeRequest {
            samples,
            source: source.into(),
        })
        .await
        .expect("PushGaze")
        .into_inner();
    assert_eq!(r.accepted + r.rejected, n);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn two_trackers_at_once_each_keep_their_own_processing_and_the_newest_steers() {
    let mut config = small_config(200, 100.0);
    config.gaze_processing = ProcessorConfig {
        detector: Some(DetectorParams::default()),
        ..ProcessorConfig::default()
    };
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    // Tracker A since 10 s on its clock, at (0.2, 0.3); tracker B, on a clock 500 s ahead, at
    // (0.7, 0.6), interleaved batch by batch. Through one processor every batch would be a
    // saccade and a clock reset; each through its own, both are fixations.
    for k in 0..20 {
        let batch = |t0: f64, x, y| -> Vec<pb::GazeSample> {
            (0..10)
                .map(|i| sample(t0 + f64::from(k * 10 + i) * 0.001, x, y))
                .collect()
        };
        push(&mut client, "tracker-a", batch(10.0, 0.2, 0.3)).await;
        push(&mut client, "tracker-b", batch(510.0, 0.7, 0.6)).await;
    }
    assert_eq!(status(&mut client).await.gaze_sources_live, 2);
    let done = frames_so_far(&mut client).await;
    let f = frame_where(&mut frames, "a frame after both trackers", |f| {
        f.index > done
    })
    .await;
    let used = fixation(&f);
    assert_eq!(used.source, pb::FixationSource::Gaze as i32);
    assert_eq!(used.track, pb::GazeTrack::Fixation as i32, "{used:?}");
    assert!(
        (used.x - 0.7).abs() < 1e-9 && (used.y - 0.6).abs() < 1e-9,
        "the newer tracker steers: {used:?}"
    );
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_long_blink_widens_the_region_the_scheduler_treats_as_foveal() {
    let mut config = small_config(200, 100.0);
    // Fall back only after 10 s, so that a slow machine cannot turn the widening into a loss.
    config.gaze_processing.fallback_s = 10.0;
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    push(&mut client, "t", vec![sample(1.0, 0.3, 0.4)]).await;
    // The eye is lost and the tracker says so every 50 ms: hold for 300 ms, then widen.
    let start = tokio::time::Instant::now();
    for k in 1..=12u32 {
        push(&mut client, "t", vec![missing(1.0 + 0.05 * f64::from(k))]).await;
        tokio::time::sleep_until(start + std::time::Duration::from_millis(50 * u64::from(k))).await;
    }
    let done = frames_so_far(&mut client).await;
    let f = frame_where(&mut frames, "a frame late in the blink", |f| f.index > done).await;
    let used = fixation(&f);
    assert_eq!(used.track, pb::GazeTrack::Widened as i32, "{used:?}");
    assert_eq!((used.x, used.y), (0.3, 0.4), "the last fixation is kept");
    // 20 deg/s after the 300 ms hold; the frame is at least 550 ms into the loss.
    assert!(used.widen_deg >= 5.0 && used.widen_deg <= 200.0, "{used:?}");
    server.stop().await.expect("clean stop");
}
