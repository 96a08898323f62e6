//! Online gaze processing on the server, over real sockets: with a fixation detector, a saccade
//! does not steer (the last fixation is held while the raw sample is reported), and a blink is
//! reported as track loss; one wild timestamp does not block the stream.

use foveal_gaze::detect::DetectorParams;
use foveal_gaze::online::ProcessorConfig;
use foveal_proto::pb;
use foveal_tests::*;

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
