//! The fixation a frame uses follows the scripted gaze within one frame, and falls back to the
//! screen centre, flagged, when gaze is missing or stale.

use std::time::Duration;

use foveal_proto::pb;
use foveal_tests::*;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fixation_follows_pushed_gaze_within_one_frame_then_goes_stale() {
    let mut config = small_config(300, 100.0);
    config.gaze_max_age = Duration::from_millis(300);
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;

    let first = next_frame(&mut frames).await;
    let f = fixation(&first);
    assert_eq!(f.source, FixationSource::FallbackNoGaze as i32);
    assert_eq!((f.x, f.y), (0.5, 0.5));

    for (i, (x, y)) in [(0.2, 0.3), (0.8, 0.1), (1.1, -0.05)]
        .into_iter()
        .enumerate()
    {
        client
            .push_gaze(pb::PushGazeRequest {
                samples: vec![sample(i as f64, x, y)],
                source: "test".into(),
            })
            .await
            .expect("PushGaze");
        // Frame `done` may have started before the push; the one after it cannot have.
        let done = frames_so_far(&mut client).await;
        let next = frame_where(&mut frames, "the frame after the push", |f| f.index > done).await;
        let used = fixation(&next);
        assert_eq!(
            used.source,
            FixationSource::Gaze as i32,
            "frame {}",
            next.index
        );
        assert_eq!((used.x, used.y), (x, y), "frame {}", next.index);
        assert!((0.0..0.3).contains(&used.age_s), "{used:?}");
    }

    let stale = frame_where(&mut frames, "a stale fallback frame", |f| {
        fixation(f).source == FixationSource::FallbackStale as i32
    })
    .await;
    let used = fixation(&stale);
    assert_eq!((used.x, used.y), (0.5, 0.5));
    assert!(used.age_s > 0.3, "stale age is reported: {used:?}");
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn fixation_follows_streamed_gaze() {
    let server = TestServer::start(small_config(200, 120.0)).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    let (tx, rx) = tokio::sync::mpsc::channel(16);
    let mut gaze_client = client.clone();
    let call = tokio::spawn(async move {
        gaze_client
            .stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });
    // A scripted sweep: each point must show up in a frame before the next is sent.
    let points = [(0.1, 0.1), (0.4, 0.6), (0.9, 0.9), (0.5, 0.25)];
    for (i, &(x, y)) in points.iter().enumerate() {
        tx.send(sample(i as f64 * 0.01, x, y))
            .await
            .expect("stream open");
        let f = frame_where(&mut frames, "a frame with the streamed point", |f| {
            let used = fixation(f);
            (used.x, used.y) == (x, y)
        })
        .await;
        assert_eq!(fixation(&f).source, FixationSource::Gaze as i32);
    }
    drop(tx);
    let summary = within("the StreamGaze summary", call)
        .await
        .expect("task")
        .expect("StreamGaze")
        .into_inner();
    assert_eq!((summary.accepted, summary.rejected), (4, 0));
    assert!((summary.last_accepted_time_s - 0.03).abs() < 1e-12);
    server.stop().await.expect("clean stop");
}
