//! Health, reflection (v1 and v1alpha) and GetScene, with the truth and the star it reports.

use foveal_proto::pb;
use foveal_proto::pb::foveal_client::FovealClient;
use foveal_tests::*;
use tonic::Code;
use tonic::transport::Channel;
use tonic_health::pb::health_check_response::ServingStatus;
use tonic_health::pb::{HealthCheckRequest, health_client::HealthClient};

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_reports_serving() {
    let server = TestServer::start(small_config(100, 60.0)).await;
    let mut health = HealthClient::new(server.channel().await);
    for service in ["", "foveal.v1.Foveal"] {
        let r = health
            .check(HealthCheckRequest {
                service: service.into(),
            })
            .await
            .expect("Check")
            .into_inner();
        assert_eq!(
            r.status,
            ServingStatus::Serving as i32,
            "service `{service}`"
        );
    }
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn reflection_lists_the_service_in_v1_and_v1alpha() {
    let server = TestServer::start(small_config(100, 60.0)).await;
    {
        use tonic_reflection::pb::v1::{
            ServerReflectionRequest, server_reflection_client::ServerReflectionClient,
            server_reflection_request::MessageRequest, server_reflection_response::MessageResponse,
        };
        let mut client = ServerReflectionClient::new(server.channel().await);
        let req = ServerReflectionRequest {
            host: String::new(),
            message_request: Some(MessageRequest::ListServices(String::new())),
        };
        let mut responses = client
            .server_reflection_info(tokio_stream::iter([req]))
            .await
            .expect("reflection v1")
            .into_inner();
        let r = responses.message().await.expect("ok").expect("a response");
        let Some(MessageResponse::ListServicesResponse(list)) = r.message_response else {
            panic!("unexpected response {r:?}");
        };
        let names: Vec<_> = list.service.iter().map(|s| s.name.as_str()).collect();
        assert!(names.contains(&"foveal.v1.Foveal"), "{names:?}");
    }
    {
        use tonic_reflection::pb::v1alpha::{
            ServerReflectionRequest, server_reflection_client::ServerReflectionClient,
            server_reflection_request::MessageRequest, server_reflection_response::MessageResponse,
        };
        let mut client = ServerReflectionClient::new(server.channel().await);
        let req = ServerReflectionRequest {
            host: String::new(),
            message_request: Some(MessageRequest::ListServices(String::new())),
        };
        let mut responses = client
            .server_reflection_info(tokio_stream::iter([req]))
            .await
            .expect("reflection v1alpha")
            .into_inner();
        let r = responses.message().await.expect("ok").expect("a response");
        let Some(MessageResponse::ListServicesResponse(list)) = r.message_response else {
            panic!("unexpected response {r:?}");
        };
        let names: Vec<_> = list.service.iter().map(|s| s.name.as_str()).collect();
        assert!(names.contains(&"foveal.v1.Foveal"), "{names:?}");
    }
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn get_scene_describes_the_running_scene() {
    let server = TestServer::start(small_config(100, 75.0)).await;
    let mut client = server.client().await;
    let scene = client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner();
    let config = scene.config.expect("config");
    assert_eq!((config.bodies, config.frame_rate_hz), (100, 75.0));
    let tree = scene.tree.expect("tree");
    // The default tree: the root, the star's core and six spikes, their runs of leaves, the leaves.
    assert_eq!(config.tree, pb::Tree::Parts as i32);
    assert_eq!(tree.spheres_per_level, [1, 7, 20, 80]);
    assert_eq!(tree.spheres.len(), 108);
    assert!((scene.volume_side - 10f64.cbrt()).abs() < 1e-12);
    let camera = scene.camera.expect("camera");
    assert!((camera.aspect - 1680.0 / 1050.0).abs() < 1e-12);
    server.stop().await.expect("clean stop");
}

async fn scene(client: &mut FovealClient<Channel>) -> pb::SceneDescription {
    client
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene")
        .into_inner()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn configure_sets_the_truth_get_scene_reports_it_and_the_star() {
    let server = TestServer::start(small_config(100, 60.0)).await;
    let mut client = server.client().await;
    let before = scene(&mut client).await;
    assert_eq!(
        before.config.expect("config").truth,
        pb::Truth::Shape as i32,
        "a server starts with the drawn shape as the truth"
    );

    let applied = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                truth: pb::Truth::LeafSpheres as i32,
                shape_radius: 0.25,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect("Configure")
        .into_inner()
        .applied
        .expect("applied");
    assert_eq!(applied.truth, pb::Truth::LeafSpheres as i32);
    let after = scene(&mut client).await;
    let config = after.config.expect("config");
    assert_eq!(config.truth, pb::Truth::LeafSpheres as i32);
    let star = after.star.expect("star");
    let r = config.shape_radius;
    assert_eq!((r, star.radius), (0.25, 0.25));
    assert!((star.core_radius - 0.3 * r).abs() < 1e-12, "{star:?}");
    assert!(
        (star.spike_base_radius - 0.25 * r).abs() < 1e-12,
        "{star:?}"
    );

    // A number outside the enum is refused, naming the field, and changes nothing.
    let err = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                truth: 7,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect_err("truth 7");
    assert_eq!(err.code(), Code::InvalidArgument);
    assert!(
        err.message().contains("ConfigureRequest.config")
            && err.message().contains("`scene.truth` = 7"),
        "{}",
        err.message()
    );
    assert_eq!(
        status(&mut client).await.config.expect("config").truth,
        pb::Truth::LeafSpheres as i32
    );

    // Unspecified keeps the truth in force.
    let applied = client
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                bodies: 120,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect("Configure")
        .into_inner()
        .applied
        .expect("applied");
    assert_eq!(
        (applied.bodies, applied.truth),
        (120, pb::Truth::LeafSpheres as i32)
    );
    server.stop().await.expect("clean stop");
}
