//! Pause, Resume, Step, Restart and InspectBody over real sockets: the loop's frame counter stops
//! and moves by exactly the frames stepped, health stays SERVING while paused, Restart replays or
//! reseeds the scene, InspectBody lists a body's pairs as the frame's collision list has them, and
//! the loop's controls are the admin's.

use std::time::Duration;

use foveal_proto::pb;
use foveal_tests::{TestServer, frame_where, next_frame, small_config, status, watch, within};
use tonic::Code;
use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_check_response::ServingStatus;
use tonic_health::pb::health_client::HealthClient;

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

#[tokio::test]
async fn pause_stops_the_frame_counter_and_step_advances_it_by_exactly_the_frames_asked() {
    // 100 Hz with a stall threshold of 3 periods (30 ms): a paused loop would be "stalled" at once
    // if pausing were not told apart from stalling.
    let mut config = small_config(200, 100.0);
    config.stall_periods = 3;
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = watch(&mut client, 1, false).await;
    next_frame(&mut frames).await;
    // Stepped frames reach a subscriber of every 1000th frame too: someone asked to see them.
    let mut sparse = watch(&mut client, 1000, false).await;

    let paused = client
        .pause(pb::PauseRequest {})
        .await
        .expect("Pause")
        .into_inner();
    assert!(paused.paused);
    tokio::time::sleep(Duration::from_millis(300)).await;
    let s = status(&mut client).await;
    assert!(s.paused, "GetStatus says paused");
    assert_eq!(s.frames, paused.frames, "no frame simulated while paused");
    assert_eq!(health(&server).await, ServingStatus::Serving as i32);
    // Pausing again changes nothing.
    let again = client
        .pause(pb::PauseRequest {})
        .await
        .expect("Pause again");
    assert_eq!(again.into_inner(), paused);

    // The frames published before the pause, then the stepped ones, indices without a gap.
    let mut last = paused.frames - 1;
    while let Ok(Ok(Some(f))) =
        tokio::time::timeout(Duration::from_millis(100), frames.message()).await
    {
        last = f.index;
    }
    assert_eq!(
        last,
        paused.frames - 1,
        "the last frame published is the last simulated"
    );

    let one = client
        .step(pb::StepRequest { frames: 0 })
        .await
        .expect("Step")
        .into_inner();
    assert_eq!(
        one.frames,
        paused.frames + 1,
        "Step with 0 frames steps one"
    );
    assert!(one.paused, "the loop stays paused after a Step");
    assert_eq!(next_frame(&mut frames).await.index, paused.frames);
    let five = client
        .step(pb::StepRequest { frames: 5 })
        .await
        .expect("Step 5")
        .into_inner();
    assert_eq!(five.frames, one.frames + 5);
    for i in 0..5 {
        assert_eq!(next_frame(&mut frames).await.index, one.frames + i);
    }
    tokio::time::sleep(Duration::from_millis(200)).await;
    assert_eq!(status(&mut client).await.frames, five.frames);
    let mut seen = Vec::new();
    while let Ok(Ok(Some(f))) =
        tokio::time::timeout(Duration::from_millis(100), sparse.message()).await
    {
        seen.push(f.index);
    }
    let stepped: Vec<u64> = (paused.frames..five.frames).collect();
    assert!(
        seen.ends_with(&stepped),
        "every_k 1000 saw {seen:?}, stepped {stepped:?}"
    );

    let e = client
        .step(pb::StepRequest { frames: 601 })
        .await
        .expect_err("too many frames");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(
        e.message().contains("StepRequest.frames"),
        "{}",
        e.message()
    );

    let running = client
        .resume(pb::ResumeRequest {})
        .await
        .expect("Resume")
        .into_inner();
    assert!(!running.paused);
    frame_where(&mut frames, "frames after Resume", |f| {
        f.index > five.frames + 5
    })
    .await;
    assert!(!status(&mut client).await.paused);
    assert_eq!(health(&server).await, ServingStatus::Serving as i32);
    let e = client
        .step(pb::StepRequest { frames: 1 })
        .await
        .expect_err("Step of a running loop");
    assert_eq!(e.code(), Code::FailedPrecondition);
    assert!(e.message().contains("call Pause first"), "{}", e.message());
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn a_paused_server_shuts_down() {
    let server = TestServer::start(small_config(100, 60.0)).await;
    let mut client = server.client().await;
    client.pause(pb::PauseRequest {}).await.expect("Pause");
    within("a paused server's shutdown", server.stop())
        .await
        .expect("clean stop");
}

#[tokio::test]
async fn restart_replays_the_scene_or_reseeds_it_and_keeps_a_pause() {
    let server = TestServer::start(small_config(150, 60.0)).await;
    let mut client = server.client().await;
    let seed = status(&mut client).await.config.expect("config").seed;
    client.pause(pb::PauseRequest {}).await.expect("Pause");
    let same = client
        .restart(pb::RestartRequest { seed: None })
        .await
        .expect("Restart")
        .into_inner();
    assert_eq!(same.applied.expect("applied").seed, seed);
    let zero = client
        .restart(pb::RestartRequest { seed: Some(0) })
        .await
        .expect("Restart with seed 0")
        .into_inner();
    assert_eq!(zero.applied.expect("applied").seed, 0, "0 is a seed");
    let s = status(&mut client).await;
    assert!(s.paused, "a Restart keeps the pause");
    assert_eq!(s.frames, zero.first_frame_index);
    assert_eq!(s.config.expect("config").seed, 0);
    // The restarted scene's first frame is the next one stepped.
    let mut frames = watch(&mut client, 1, false).await;
    let stepped = client
        .step(pb::StepRequest { frames: 1 })
        .await
        .expect("Step")
        .into_inner();
    let f = next_frame(&mut frames).await;
    assert_eq!(f.index, zero.first_frame_index);
    assert_eq!(stepped.frames, zero.first_frame_index + 1);
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn inspect_body_lists_its_pairs_as_the_collision_list_has_them() {
    // A tight budget at density 10: bodies with real, deemed and separate pairs.
    let mut config = small_config(400, 60.0);
    config.sim.budget = foveal_engine::BudgetSpec::SphereTests(300);
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    let mut frames = client
        .watch_frames(pb::WatchFramesRequest {
            every_k: 1,
            include_collisions: true,
            ..Default::default()
        })
        .await
        .expect("watch")
        .into_inner();
    let f = frame_where(&mut frames, "a frame with deemed pairs", |f| {
        f.metrics
            .as_ref()
            .is_some_and(|m| m.deemed_at_interruption > 0)
    })
    .await;
    client.pause(pb::PauseRequest {}).await.expect("Pause");
    // The latest frame: the one published last before the pause.
    let mut latest = f;
    while let Ok(Ok(Some(f))) =
        tokio::time::timeout(Duration::from_millis(200), frames.message()).await
    {
        latest = f;
    }
    let c = latest.collisions.expect("collisions");
    let deemed: Vec<_> = c.deemed_pairs().collect();
    let (a, b) = deemed.first().copied().expect("a deemed pair");
    let seen = client
        .inspect_body(pb::InspectBodyRequest { body: a })
        .await
        .expect("InspectBody")
        .into_inner();
    assert_eq!(seen.frame_index, latest.index);
    assert_eq!(seen.body, a);
    assert_eq!(seen.pairs_total as usize, seen.pairs.len());
    let pair = seen
        .pairs
        .iter()
        .find(|p| p.other == b)
        .expect("the deemed pair is listed");
    assert_eq!(pair.status, pb::PairStatus::Deemed as i32);
    // Every listed pair's status agrees with the frame's collision list.
    let real: Vec<_> = c.real_pairs().collect();
    for p in &seen.pairs {
        let key = (a.min(p.other), a.max(p.other));
        let on_real = real.contains(&key);
        let on_deemed = deemed.contains(&key);
        match pb::PairStatus::try_from(p.status).expect("known status") {
            pb::PairStatus::Colliding => assert!(on_real, "{key:?}"),
            pb::PairStatus::Deemed => assert!(on_deemed, "{key:?}"),
            _ => assert!(!on_real && !on_deemed, "{key:?}"),
        }
    }
    let e = client
        .inspect_body(pb::InspectBodyRequest { body: 400 })
        .await
        .expect_err("no body 400");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(
        e.message().contains("InspectBodyRequest.body = 400") && e.message().contains("0..=399"),
        "{}",
        e.message()
    );
    server.stop().await.expect("clean stop");
}
