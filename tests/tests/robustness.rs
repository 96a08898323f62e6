//! Clients that vanish, many subscribers at once, and shutdown with streams open.

use std::time::Duration;

use foveal_proto::pb;
use foveal_tests::*;

/// Poll GetStatus until `pred` holds.
async fn status_where(
    client: &mut pb::foveal_client::FovealClient<tonic::transport::Channel>,
    what: &str,
    pred: impl Fn(&pb::Status) -> bool,
) -> pb::Status {
    within(what, async {
        loop {
            let s = status(client).await;
            if pred(&s) {
                return s;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn vanishing_clients_leave_the_loop_running() {
    let server = TestServer::start(small_config(200, 100.0)).await;
    let mut client = server.client().await;

    // A gaze stream whose client goes away mid-stream, without closing it.
    let (tx, rx) = tokio::sync::mpsc::channel(16);
    let mut gaze_client = server.client().await;
    let call = tokio::spawn(async move {
        gaze_client
            .stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });
    for i in 0..3 {
        tx.send(sample(f64::from(i), 0.4, 0.4)).await.expect("open");
    }
    status_where(&mut client, "3 accepted samples", |s| {
        s.gaze_samples_accepted == 3
    })
    .await;
    call.abort();
    drop(tx);

    // A frame watcher that goes away after one frame.
    let mut watcher = server.client().await;
    let mut frames = watch(&mut watcher, 1, true).await;
    next_frame(&mut frames).await;
    drop(frames);
    drop(watcher);

    let s = status_where(&mut client, "the dropped subscriber to be gone", |s| {
        s.subscribers == 0
    })
    .await;
    let later = status_where(&mut client, "frames to keep coming", |later| {
        later.frames >= s.frames + 10
    })
    .await;
    assert_eq!(later.gaze_samples_accepted, 3);

    // And the server still serves new callers.
    let mut frames = watch(&mut client, 1, false).await;
    let f = next_frame(&mut frames).await;
    assert!(f.index >= later.frames.saturating_sub(1));
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn thirty_two_subscribers_with_poses_all_receive_frames() {
    const BODIES: u32 = 200;
    let server = TestServer::start(small_config(BODIES, 60.0)).await;
    let mut clients = Vec::new();
    for _ in 0..4 {
        clients.push(server.client().await);
    }
    let mut streams = Vec::new();
    for i in 0..32 {
        let client = &mut clients[i % 4];
        streams.push(watch(client, 1 + (i as u32 % 3), true).await);
    }
    let tasks: Vec<_> = streams
        .into_iter()
        .map(|mut frames| {
            tokio::spawn(async move {
                let mut last = None;
                for _ in 0..5 {
                    let f = next_frame(&mut frames).await;
                    let poses = f.poses.expect("poses asked for");
                    assert_eq!(poses.bodies, BODIES);
                    assert_eq!(poses.positions_f32().count(), BODIES as usize);
                    assert_eq!(poses.orientations_f32().count(), BODIES as usize);
                    assert!(poses.origin.is_some());
                    if let Some(last) = last {
                        assert!(f.index > last);
                    }
                    last = Some(f.index);
                }
            })
        })
        .collect();
    let mut client = server.client().await;
    assert_eq!(status(&mut client).await.subscribers, 32);
    for t in tasks {
        within("a subscriber's frames", t)
            .await
            .expect("subscriber ok");
    }
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shutdown_ends_open_streams_promptly() {
    let server = TestServer::start(small_config(200, 60.0)).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    next_frame(&mut frames).await;
    let (tx, rx) = tokio::sync::mpsc::channel(4);
    tx.send(sample(0.0, 0.5, 0.5)).await.expect("open");
    let mut gaze_client = server.client().await;
    let gaze_call = tokio::spawn(async move {
        gaze_client
            .stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });

    let started = std::time::Instant::now();
    server.stop().await.expect("clean stop");
    let took = started.elapsed();
    assert!(took < Duration::from_secs(3), "shutdown took {took:?}");
    // The watch stream ends (cleanly or with an error), it does not hang.
    within("the watch stream to end", async {
        while let Ok(Some(_)) = frames.message().await {}
    })
    .await;
    // The open gaze stream is answered with what it sent so far.
    let summary = within("the gaze call to end", gaze_call)
        .await
        .expect("task");
    if let Ok(summary) = summary {
        assert!(summary.into_inner().accepted <= 1);
    }
    drop(tx);
}
