//! Health, reflection (v1 and v1alpha) and GetScene.

use foveal_proto::pb;
use foveal_tests::*;
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
    assert_eq!(tree.spheres_per_level, [1, 8, 32, 80]);
    assert_eq!(tree.spheres.len(), 121);
    assert!((scene.volume_side - 10f64.cbrt()).abs() < 1e-12);
    let camera = scene.camera.expect("camera");
    assert!((camera.aspect - 1680.0 / 1050.0).abs() < 1e-12);
    server.stop().await.expect("clean stop");
}
