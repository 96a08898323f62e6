//! The side by side (`SceneConfig.compare`) over real sockets: Configure turns it on, every frame
//! then carries a gaze-blind collider's run on the same frame under the same budget with its own
//! collision list and both sides' true P on the same pairs, the gaze-steered side leaves less true
//! P about the fixation, turning it off removes it, and it is refused above its body limit, naming the
//! field and the limit, with nothing changed.

use std::time::Duration;

use foveal_engine::BudgetSpec;
use foveal_proto::pb;
use foveal_server::ServerConfig;
use foveal_server::compare::{Compare, MAX_COMPARE_BODIES};
use foveal_tests::*;
use tonic::Code;

/// Configure `compare` alone (an update mask), answering the applied configuration and the first
/// frame under it, or the refusal.
async fn set_compare(
    client: &mut pb::foveal_client::FovealClient<tonic::transport::Channel>,
    compare: pb::Compare,
    bodies: Option<u32>,
) -> Result<pb::ConfigureResponse, tonic::Status> {
    let mut paths = vec!["compare".to_owned()];
    if bodies.is_some() {
        paths.push("bodies".to_owned());
    }
    client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                compare: compare as i32,
                bodies: bodies.unwrap_or(0),
                ..Default::default()
            }),
            update_mask: Some(prost_types::FieldMask { paths }),
        })
        .await
        .map(tonic::Response::into_inner)
}

fn count(packed: &[u8]) -> u64 {
    packed.len() as u64 / 8
}

/// Under a sphere-test budget every frame is deterministic, so the comparison of the two sides'
/// true P is the same on every machine, loaded or not.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn both_colliders_settle_the_same_frame_and_the_gaze_side_leaves_less_true_p() {
    let mut config = small_config(1_500, 60.0);
    config.sim.budget = BudgetSpec::SphereTests(1_500);
    config.gaze_max_age = Duration::from_secs(600);
    let server = TestServer::start(config).await;
    let mut client = server.client().await;
    client
        .push_gaze(pb::PushGazeRequest {
            samples: vec![sample(0.0, 0.3, 0.35)],
            source: "test".into(),
        })
        .await
        .expect("PushGaze");
    // Off by default: no comparison in the frames.
    let mut plain = watch(&mut client, 1, false).await;
    assert!(next_frame(&mut plain).await.comparison.is_none());
    drop(plain);

    let on = set_compare(&mut client, pb::Compare::RoundRobin, None)
        .await
        .expect("compare on");
    let applied = on.applied.expect("applied");
    assert_eq!(applied.compare, pb::Compare::RoundRobin as i32);
    assert!(!applied.audit, "the side by side audits both sides itself");
    let scene = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();
    assert_eq!(
        scene.config.expect("config").compare,
        pb::Compare::RoundRobin as i32
    );

    let mut frames = client
        .watch_frames(pb::WatchFramesRequest {
            every_k: 1,
            include_collisions: true,
            ..Default::default()
        })
        .await
        .expect("WatchFrames")
        .into_inner();
    let (mut gaze_p, mut blind_p, mut seen) = (0.0, 0.0, 0);
    while seen < 60 {
        let f = next_frame(&mut frames).await;
        if f.index < on.first_frame_index {
            continue;
        }
        assert_eq!(fixation(&f).source, FixationSource::Gaze as i32);
        let m = f.metrics.expect("metrics");
        let c = f.comparison.expect("every frame carries the comparison");
        assert_eq!(c.collider, pb::Compare::RoundRobin as i32);
        let cm = c.metrics.expect("comparison metrics");
        // The same frame: the same candidate pairs; the same budget: at most one step over it.
        assert_eq!(cm.candidate_pairs, m.candidate_pairs);
        assert!(cm.sphere_tests <= 1_500 + 6_400, "{}", cm.sphere_tests);
        assert!(cm.budget_exhausted && m.budget_exhausted);
        assert!(c.run_s > 0.0, "the second collider's time is measured");
        // Its own collision list, as its metrics count it.
        let cc = c.collisions.expect("comparison collisions");
        assert_eq!(count(&cc.real), cm.real_collisions);
        assert_eq!(count(&cc.deemed), cm.deemed_at_interruption);
        let mc = f.collisions.expect("main collisions");
        assert_eq!(count(&mc.deemed), m.deemed_at_interruption);
        assert!(m.audit.is_none(), "the frame's own audit stays off");
        assert!(c.audit_stride >= 1);
        let (main_audit, blind_audit) = (
            c.main_audit.expect("the gaze side's audit"),
            cm.audit.expect("the gaze-blind side's audit"),
        );
        // The paired audit settles only pairs a side deemed (one in audit_stride of them, each
        // counted audit_stride times).
        assert!(
            blind_audit.true_false_positives
                <= u64::from(c.audit_stride) * cm.deemed_at_interruption
        );
        gaze_p += main_audit.true_perceived_inaccuracy;
        blind_p += blind_audit.true_perceived_inaccuracy;
        seen += 1;
    }
    assert!(
        gaze_p < 0.8 * blind_p,
        "true P over 60 frames: gaze-steered {gaze_p:.3}, gaze-blind {blind_p:.3}"
    );

    // Off again: the frames carry no comparison.
    let off = set_compare(&mut client, pb::Compare::Off, None)
        .await
        .expect("compare off");
    assert_eq!(
        off.applied.expect("applied").compare,
        pb::Compare::Off as i32
    );
    let f = frame_where(&mut frames, "a frame with compare off", |f| {
        f.index >= off.first_frame_index
    })
    .await;
    assert!(f.comparison.is_none());
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn refused_above_the_body_limit_naming_the_field_and_the_limit() {
    let server = TestServer::start(small_config(300, 60.0)).await;
    let mut client = server.client().await;
    let before = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();

    let e = set_compare(
        &mut client,
        pb::Compare::RoundRobin,
        Some(MAX_COMPARE_BODIES + 1),
    )
    .await
    .expect_err("over the limit");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(e.message().contains("`compare`"), "{}", e.message());
    assert!(
        e.message().contains(&MAX_COMPARE_BODIES.to_string()),
        "{}",
        e.message()
    );
    // Nothing changed.
    let after = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();
    assert_eq!(before, after);

    // At the limit's side of it, the mode is taken; then a scene over the limit is refused while
    // it is on, and a mask that lists `compare` without a value is refused.
    let on = set_compare(&mut client, pb::Compare::Exact, None)
        .await
        .expect("compare on at 300 bodies");
    assert_eq!(
        on.applied.expect("applied").compare,
        pb::Compare::Exact as i32
    );
    let e = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                bodies: MAX_COMPARE_BODIES + 1,
                ..Default::default()
            }),
            update_mask: Some(prost_types::FieldMask {
                paths: vec!["bodies".into()],
            }),
        })
        .await
        .expect_err("more bodies than the side by side allows");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(e.message().contains("`compare`"), "{}", e.message());
    let e = set_compare(&mut client, pb::Compare::Unspecified, None)
        .await
        .expect_err("unspecified under a mask");
    assert_eq!(e.code(), Code::InvalidArgument);
    assert!(e.message().contains("compare"), "{}", e.message());

    // Exact frames on the right: nothing deemed there.
    let mut frames = watch(&mut client, 1, false).await;
    let f = frame_where(&mut frames, "an exact-compared frame", |f| {
        f.index >= on.first_frame_index
    })
    .await;
    let c = f.comparison.expect("comparison");
    assert_eq!(
        c.metrics.expect("metrics").deemed_at_interruption,
        0,
        "exact deems nothing"
    );
    server.stop().await.expect("clean stop");
}

/// A server that starts with the mode above the limit refuses to start, naming the field.
#[test]
fn start_up_above_the_limit_is_refused() {
    let mut config = ServerConfig {
        compare: Compare::RoundRobin,
        ..ServerConfig::default()
    };
    config.sim.scene.bodies = MAX_COMPARE_BODIES + 1;
    let e = config.validate().expect_err("over the limit");
    assert_eq!(e.field, "compare");
    config.compare = Compare::Off;
    config
        .validate()
        .expect("without the side by side it is fine");
}
