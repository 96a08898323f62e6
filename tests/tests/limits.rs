//! Limits that protect the loop, honest health, and shutdown, over real sockets.

use std::time::{Duration, Instant};

use foveal_proto::pb;
use foveal_server::{Limits, MAX_REQUEST_BYTES};
use foveal_tests::{TestServer, frames_so_far, sample, small_config, status, within};
use tonic::Code;
use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_check_response::ServingStatus;
use tonic_health::pb::health_client::HealthClient;

fn configure(config: pb::SceneConfig, mask: &[&str]) -> pb::ConfigureRequest {
    pb::ConfigureRequest {
        config: Some(config),
        update_mask: (!mask.is_empty()).then(|| prost_types::FieldMask {
            paths: mask.iter().map(|&p| p.to_owned()).collect(),
        }),
    }
}

#[tokio::test]
async fn costly_scenes_are_refused_naming_the_field_and_the_limit() {
    let mut config = small_config(80, 60.0);
    config.limits.max_candidate_pairs = 1_000_000;
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let tiny = client
        .configure(configure(
            pb::SceneConfig {
                density: 1e-300,
                ..Default::default()
            },
            &[],
        ))
        .await
        .expect_err("density out of range");
    assert_eq!(tiny.code(), Code::InvalidArgument);
    assert!(
        tiny.message().contains("scene.density") && tiny.message().contains("[0.001, 100]"),
        "{}",
        tiny.message()
    );
    // 400,000 bodies of the paper scene are about 1.4 million candidate pairs.
    let dense = client
        .configure(configure(
            pb::SceneConfig {
                bodies: 400_000,
                ..Default::default()
            },
            &[],
        ))
        .await
        .expect_err("too many candidate pairs");
    assert_eq!(dense.code(), Code::InvalidArgument);
    assert!(
        dense.message().contains("scene.bodies") && dense.message().contains("1000000"),
        "{}",
        dense.message()
    );
    assert_eq!(status(&mut client).await.config.expect("config").bodies, 80);
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn start_up_refuses_a_scene_over_the_limits() {
    let mut config = small_config(400_000, 60.0);
    config.limits.max_candidate_pairs = 1_000_000;
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
        .await
        .expect("bind");
    let e = foveal_server::run(listener, config, std::future::pending())
        .await
        .expect_err("refused before building");
    assert!(e.to_string().contains("--max-candidate-pairs"), "{e}");
}

#[tokio::test]
async fn an_update_mask_sets_fields_to_zero() {
    let server = TestServer::start(small_config(80, 60.0)).await;
    let mut client = server.client().await;
    let mut c = pb::SceneConfig {
        seed: 0,
        audit: true,
        ..Default::default()
    };
    // Without a mask, 0 means "keep": the seed stays 1.
    let applied = client
        .configure(configure(c, &[]))
        .await
        .expect("configure")
        .into_inner()
        .applied
        .expect("applied");
    assert_eq!((applied.seed, applied.audit), (1, true));
    // With a mask, exactly the listed fields are applied, 0 and false included.
    c.audit = false;
    let applied = client
        .configure(configure(c, &["seed", "audit"]))
        .await
        .expect("configure")
        .into_inner()
        .applied
        .expect("applied");
    assert_eq!(
        (applied.seed, applied.audit, applied.bodies),
        (0, false, 80)
    );
    let e = client
        .configure(configure(c, &["bodys"]))
        .await
        .expect_err("unknown path");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(e.message().contains("update_mask") && e.message().contains("bodys"));
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn oversize_messages_are_resource_exhausted() {
    let server = TestServer::start(small_config(40, 60.0)).await;
    let mut client = server.client().await.max_encoding_message_size(64 << 20);
    // About 5 MiB of samples in one PushGaze.
    let samples: Vec<_> = (0..150_000)
        .map(|i| sample(f64::from(i) * 1e-3, 0.5, 0.5))
        .collect();
    let e = client
        .push_gaze(pb::PushGazeRequest {
            samples,
            source: "oversize".into(),
        })
        .await
        .expect_err("over the limit");
    assert_eq!(e.code(), Code::ResourceExhausted, "{e:?}");
    assert!(
        e.message().contains(&MAX_REQUEST_BYTES.to_string()),
        "{}",
        e.message()
    );
    // Nothing of it was applied, and the server goes on.
    assert_eq!(status(&mut client).await.gaze_samples_accepted, 0);
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn gaze_above_the_rate_limit_is_dropped_and_counted() {
    let mut config = small_config(40, 60.0);
    config.limits = Limits {
        max_gaze_rate_hz: 1000.0,
        ..Limits::default()
    };
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let n = 5000u32;
    let start = Instant::now();
    let samples = tokio_stream::iter((0..n).map(|i| sample(f64::from(i) * 1e-4, 0.4, 0.6)));
    let summary = client
        .stream_gaze(samples)
        .await
        .expect("StreamGaze")
        .into_inner();
    let elapsed = start.elapsed().as_secs_f64();
    assert_eq!(
        summary.accepted + summary.rejected + summary.rate_limited,
        u64::from(n),
        "every sample is accounted for"
    );
    assert_eq!(summary.rejected, 0);
    assert!(summary.rate_limited > 0, "{summary:?}");
    // A full bucket (0.25 s of the rate) plus the rate over the time it took.
    let bound = 250.0 + 1000.0 * elapsed + 1.0;
    assert!(
        (summary.accepted as f64) <= bound,
        "{} accepted in {elapsed:.3} s (bound {bound:.0})",
        summary.accepted
    );
    let s = status(&mut client).await;
    assert_eq!(s.gaze_samples_rate_limited, summary.rate_limited);
    assert_eq!(s.gaze_samples_accepted, summary.accepted);
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn calls_over_the_per_connection_limit_are_shed() {
    let server = TestServer::start(small_config(40, 60.0)).await;
    let channel = server.channel().await;
    // Hold 64 gaze streams open on one connection; the next call on it is shed.
    let mut held = Vec::new();
    let mut senders = Vec::new();
    for _ in 0..64 {
        let (tx, rx) = tokio::sync::mpsc::channel::<pb::GazeSample>(1);
        let mut c = pb::foveal_client::FovealClient::new(channel.clone());
        held.push(tokio::spawn(async move {
            c.stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
                .await
        }));
        senders.push(tx);
    }
    let mut c = pb::foveal_client::FovealClient::new(channel.clone());
    let shed = within("a shed call", async {
        loop {
            match c.get_status(pb::GetStatusRequest {}).await {
                Err(e) if e.code() == Code::ResourceExhausted => return e,
                // The streams may not all be open yet.
                _ => tokio::time::sleep(Duration::from_millis(20)).await,
            }
        }
    })
    .await;
    assert_eq!(shed.code(), Code::ResourceExhausted);
    drop(senders);
    for h in held {
        within("held stream to end", h)
            .await
            .expect("not panicked")
            .expect("stream summary");
    }
    // With the streams closed, the connection serves again.
    assert_eq!(
        status(&mut c.clone()).await.config.expect("config").bodies,
        40
    );
    server.stop().await.expect("clean stop");
}

async fn health(server: &TestServer) -> i32 {
    HealthClient::new(server.channel().await)
        .check(HealthCheckRequest {
            service: "foveal.v1.Foveal".into(),
        })
        .await
        .expect("health")
        .into_inner()
        .status
}

async fn wait_for_health(server: &TestServer, want: ServingStatus) {
    within(&format!("health {want:?}"), async {
        while health(server).await != want as i32 {
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
}

#[tokio::test]
async fn health_follows_the_loop_and_fps_counts_the_last_second() {
    // 1,000 Hz with a stall threshold of 2 periods (2 ms): a 20,000-body exact step takes
    // several times longer on any machine (about 8 ms optimised on a fast core).
    let mut config = small_config(20_000, 1000.0);
    config.stall_periods = 2;
    let server = TestServer::start(config).await;
    wait_for_health(&server, ServingStatus::NotServing).await;
    let mut client = server.client().await;
    // A light scene at 20 Hz (threshold 100 ms): frames flow again.
    client
        .configure(configure(
            pb::SceneConfig {
                bodies: 50,
                frame_rate_hz: 20.0,
                ..Default::default()
            },
            &[],
        ))
        .await
        .expect("configure");
    wait_for_health(&server, ServingStatus::Serving).await;
    tokio::time::sleep(Duration::from_millis(1200)).await;
    let fps = status(&mut client).await.fps;
    assert!((10.0..=21.0).contains(&fps), "fps {fps} at 20 Hz");
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn shutdown_does_not_wait_on_stalled_subscribers_and_keeps_accepted_gaze() {
    let mut config = small_config(3000, 60.0);
    config.shutdown_grace = Duration::from_secs(5);
    let mut server = TestServer::start(config).await;
    // Subscribers that never read, with poses (36 kB a frame) to fill their windows.
    let mut stalled = Vec::new();
    for _ in 0..3 {
        let mut c = server.client().await;
        stalled.push(
            c.watch_frames(pb::WatchFramesRequest {
                every_k: 1,
                include_poses: true,
                ..Default::default()
            })
            .await
            .expect("watch")
            .into_inner(),
        );
    }
    let mut viewer = server.client().await;
    let before = frames_so_far(&mut viewer).await;
    within("frames to pile up", async {
        while frames_so_far(&mut viewer).await < before + 120 {
            tokio::time::sleep(Duration::from_millis(50)).await;
        }
    })
    .await;
    // A gaze stream with 100 accepted samples still open at shutdown.
    let (tx, rx) = tokio::sync::mpsc::channel(128);
    let mut gaze = server.client().await;
    let call = tokio::spawn(async move {
        gaze.stream_gaze(tokio_stream::wrappers::ReceiverStream::new(rx))
            .await
    });
    for i in 0..100 {
        tx.send(sample(f64::from(i) * 0.01, 0.3, 0.3))
            .await
            .expect("stream open");
    }
    within("100 accepted", async {
        while status(&mut viewer).await.gaze_samples_accepted < 100 {
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;

    let t0 = Instant::now();
    server.trigger_stop();
    // A call during shutdown is answered UNAVAILABLE at once.
    let late = tokio::time::timeout(
        Duration::from_secs(2),
        viewer.watch_frames(pb::WatchFramesRequest::default()),
    )
    .await
    .expect("answered at once");
    assert_eq!(
        late.map(|_| ()).expect_err("refused").code(),
        Code::Unavailable
    );
    let summary = within("gaze summary", call)
        .await
        .expect("not panicked")
        .expect("summary, not an error")
        .into_inner();
    assert_eq!(summary.accepted, 100, "nothing accepted is lost");
    server.stopped().await.expect("clean stop");
    let took = t0.elapsed();
    assert!(
        took < Duration::from_secs(2),
        "shutdown took {took:?} with stalled subscribers (grace 5 s)"
    );
    drop(tx);
    drop(stalled);
}

#[tokio::test]
async fn sphere_test_budget_overshoots_by_at_most_one_step() {
    let budget = 20_000u64;
    let mut config = small_config(2000, 60.0);
    config.sim.budget = foveal_engine::BudgetSpec::SphereTests(budget);
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let scene = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();
    let widest = scene
        .tree
        .expect("tree")
        .spheres_per_level
        .into_iter()
        .max()
        .expect("levels");
    // One step tests at most every sphere pair of one level: the documented overshoot bound.
    let bound = budget + u64::from(widest) * u64::from(widest);
    let mut frames = foveal_tests::watch(&mut client, 1, false).await;
    let mut exhausted = 0;
    for _ in 0..30 {
        let f = foveal_tests::next_frame(&mut frames).await;
        let m = f.metrics.expect("metrics");
        assert!(
            m.sphere_tests <= bound,
            "frame {}: {} sphere tests over a budget of {budget} (bound {bound})",
            f.index,
            m.sphere_tests
        );
        if m.budget_exhausted {
            exhausted += 1;
            assert!(m.sphere_tests >= budget, "{m:?}");
        }
    }
    assert!(exhausted > 0, "the scene needs more than the budget");
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_push_batch_over_the_rate_limit_keeps_its_newest_samples() {
    // The default limit: 4,000 samples/s with a burst of 1,000.
    let server = TestServer::start(small_config(40, 30.0)).await;
    let mut client = server.client().await;
    let n = 10_000u32;
    // A sweep from x = 0 to 0.9999 at 10 kHz: only the end of it is where the viewer looks now.
    let samples = (0..n)
        .map(|i| {
            let x = f64::from(i) / f64::from(n);
            sample(f64::from(i) * 1e-4, x, 0.5)
        })
        .collect();
    let r = client
        .push_gaze(pb::PushGazeRequest {
            samples,
            source: "sweep".into(),
        })
        .await
        .expect("PushGaze")
        .into_inner();
    assert_eq!(r.accepted + r.rejected + r.rate_limited, u64::from(n));
    assert_eq!(r.rejected, 0, "{:?}", r.rejections);
    assert!(r.rate_limited >= 8_000, "{r:?}");
    // The last sample of the batch was kept, and it is the gaze the frames use.
    assert_eq!(r.last_accepted_time_s, f64::from(n - 1) * 1e-4);
    let mut frames = foveal_tests::watch(&mut client, 1, false).await;
    let f = foveal_tests::frame_where(&mut frames, "a frame steered by the batch", |f| {
        foveal_tests::fixation(f).source == foveal_tests::FixationSource::Gaze as i32
    })
    .await;
    let x = foveal_tests::fixation(&f).x;
    assert!((x - 0.9999).abs() < 1e-9, "the fixation is at x = {x}");
    server.stop().await.expect("clean stop");
}
