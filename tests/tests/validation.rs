//! Bad input is refused with reasons that name the field, counted, and never disturbs good input.

use foveal_proto::pb;
use foveal_tests::*;
use tonic::Code;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_streamed_samples_are_rejected_individually_and_good_ones_kept() {
    let server = TestServer::start(small_config(200, 100.0)).await;
    let mut client = server.client().await;
    let blink = pb::GazeSample {
        validity: 0.0,
        x: f64::NAN,
        ..sample(0.35, 0.0, 0.0)
    };
    let samples = vec![
        sample(0.0, 0.5, 0.5),           // 0 ok
        sample(0.1, f64::NAN, 0.5),      // 1 x not finite
        sample(0.2, 0.3, 0.3),           // 2 ok
        sample(0.3, 0.3, 7.0),           // 3 y off range
        sample(0.15, 0.3, 0.3),          // 4 time goes backwards
        blink,                           // 5 validity 0
        sample(f64::INFINITY, 0.3, 0.3), // 6 time not finite
        pb::GazeSample {
            validity: 1.5,
            ..sample(0.4, 0.3, 0.3)
        }, // 7 validity off range
        sample(0.5, 0.25, 0.75),         // 8 ok
    ];
    let summary = client
        .stream_gaze(tokio_stream::iter(samples))
        .await
        .expect("StreamGaze answers OK even with rejections")
        .into_inner();
    assert_eq!((summary.accepted, summary.rejected), (3, 6));
    let fields: Vec<(u64, &str)> = summary
        .rejections
        .iter()
        .map(|r| (r.index, r.field.as_str()))
        .collect();
    assert_eq!(
        fields,
        [
            (1, "x"),
            (3, "y"),
            (4, "tracker_time_s"),
            (5, "validity"),
            (6, "tracker_time_s"),
            (7, "validity"),
        ]
    );
    assert!(summary.rejections.iter().all(|r| !r.reason.is_empty()));
    assert_eq!(summary.last_accepted_time_s, 0.5);

    // The last good sample is the fixation.
    let mut frames = watch(&mut client, 1, false).await;
    let f = frame_where(&mut frames, "a frame using the last good sample", |f| {
        fixation(f).source == FixationSource::Gaze as i32
    })
    .await;
    assert_eq!((fixation(&f).x, fixation(&f).y), (0.25, 0.75));

    let s = status(&mut client).await;
    assert_eq!((s.gaze_samples_accepted, s.gaze_samples_rejected), (3, 6));
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn push_gaze_applies_good_samples_and_refuses_bad_batches_whole() {
    let server = TestServer::start(small_config(200, 100.0)).await;
    let mut client = server.client().await;

    let oversize = pb::PushGazeRequest {
        samples: (0..10_001)
            .map(|i| sample(f64::from(i), 0.5, 0.5))
            .collect(),
        source: "test".into(),
    };
    let err = client
        .push_gaze(oversize)
        .await
        .expect_err("oversize batch");
    assert_eq!(err.code(), Code::InvalidArgument);
    assert!(
        err.message().contains("samples") && err.message().contains("10000"),
        "{}",
        err.message()
    );
    let err = client
        .push_gaze(pb::PushGazeRequest::default())
        .await
        .expect_err("empty batch");
    assert_eq!(err.code(), Code::InvalidArgument);
    assert!(err.message().contains("samples"), "{}", err.message());
    let s = status(&mut client).await;
    assert_eq!(
        (s.gaze_samples_accepted, s.gaze_samples_rejected),
        (0, 0),
        "nothing of a refused batch is applied or counted"
    );

    let mixed = pb::PushGazeRequest {
        samples: vec![
            sample(1.0, 0.6, 0.4),
            sample(0.5, 0.1, 0.1),  // backwards
            sample(2.0, -3.0, 0.1), // x off range
        ],
        source: "test".into(),
    };
    let r = client
        .push_gaze(mixed)
        .await
        .expect("OK with rejections")
        .into_inner();
    assert_eq!((r.accepted, r.rejected), (1, 2));
    assert_eq!(r.rejections[0].field, "tracker_time_s");
    assert_eq!(r.rejections[1].field, "x");
    assert!(
        r.rejections[1].reason.contains("[-1, 2]"),
        "{:?}",
        r.rejections[1]
    );

    // A frame already under way when the batch landed still carries the old fixation; the next
    // one must use the accepted sample.
    let mut frames = watch(&mut client, 1, false).await;
    let first = next_frame(&mut frames).await;
    let f = frame_where(&mut frames, "a frame using the pushed gaze", |f| {
        fixation(f).source == FixationSource::Gaze as i32
    })
    .await;
    assert!(
        f.index <= first.index + 1,
        "gaze used {} frames late",
        f.index - first.index
    );
    assert_eq!((fixation(&f).x, fixation(&f).y), (0.6, 0.4));

    // A batch whose every sample is bad still answers OK: the caller gets the reasons.
    let r = client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![sample(f64::NAN, 0.5, 0.5)],
            source: "test".into(),
        })
        .await
        .expect("OK")
        .into_inner();
    assert_eq!((r.accepted, r.rejected), (0, 1));
    let s = status(&mut client).await;
    assert_eq!((s.gaze_samples_accepted, s.gaze_samples_rejected), (1, 3));
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn bad_configure_is_invalid_argument_naming_the_field_and_changes_nothing() {
    let server = TestServer::start(small_config(200, 100.0)).await;
    let mut client = server.client().await;
    let cases = [
        (
            pb::SceneConfig {
                bodies: 3_000_000,
                ..Default::default()
            },
            "scene.bodies",
        ),
        (
            pb::SceneConfig {
                density: f64::NAN,
                ..Default::default()
            },
            "scene.density",
        ),
        (
            pb::SceneConfig {
                budget: Some(pb::Budget {
                    kind: Some(pb::budget::Kind::WallMs(-1.0)),
                }),
                ..Default::default()
            },
            "budget.wall_ms",
        ),
        (
            pb::SceneConfig {
                frame_rate_hz: 1e6,
                ..Default::default()
            },
            "frame_rate_hz",
        ),
        (
            pb::SceneConfig {
                depth: 9,
                ..Default::default()
            },
            "scene.depth",
        ),
    ];
    for (config, field) in cases {
        let err = client
            .configure(pb::ConfigureRequest {
                config: Some(config),
                update_mask: None,
            })
            .await
            .expect_err("invalid config");
        assert_eq!(err.code(), Code::InvalidArgument, "{field}");
        assert!(err.message().contains(field), "{field}: {}", err.message());
    }
    let s = status(&mut client).await;
    assert_eq!(s.config.expect("config").bodies, 200);

    // A valid change goes through and says from which frame on it applies.
    let before = frames_so_far(&mut client).await;
    let r = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                bodies: 250,
                seed: 7,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect("valid config")
        .into_inner();
    assert!(r.first_frame_index >= before);
    let applied = r.applied.expect("applied");
    assert_eq!((applied.bodies, applied.seed), (250, 7));
    assert_eq!(
        applied.frame_rate_hz, 100.0,
        "unset fields keep their value"
    );
    let scene = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();
    assert_eq!(scene.config.expect("config").bodies, 250);
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn push_gaze_sources_are_short_printable_names() {
    let server = TestServer::start(small_config(50, 30.0)).await;
    let mut client = server.client().await;
    for (source, why) in [
        ("s".repeat(256 << 10), "262144 bytes long"),
        (
            "x".repeat(foveal_server::MAX_SOURCE_BYTES + 1),
            "65 bytes long",
        ),
        (
            "tracker\n\u{1b}[31mforged log line".to_owned(),
            "control character",
        ),
    ] {
        let err = client
            .push_gaze(pb::PushGazeRequest {
                samples: vec![sample(1.0, 0.5, 0.5)],
                source,
            })
            .await
            .expect_err("refused");
        assert_eq!(err.code(), Code::InvalidArgument);
        let m = err.message();
        assert!(
            m.contains("PushGazeRequest.`source`") && m.contains(why),
            "{m}"
        );
        assert!(
            m.contains(&foveal_server::MAX_SOURCE_BYTES.to_string()),
            "{m}"
        );
        assert!(m.len() < 300, "the message does not quote the source: {m}");
    }
    assert_eq!(
        status(&mut client).await.gaze_samples_accepted,
        0,
        "nothing of a refused batch is applied"
    );
    let ok = client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![sample(1.0, 0.5, 0.5)],
            source: "x".repeat(foveal_server::MAX_SOURCE_BYTES),
        })
        .await
        .expect("a 64-byte name")
        .into_inner();
    assert_eq!(ok.accepted, 1);
    server.stop().await.expect("clean stop");
}
