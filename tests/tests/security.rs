//! Roles by bearer token, TLS, and the refusal to serve beyond loopback without tokens, over real
//! sockets.

use std::time::Duration;

use clap::Parser;
use foveal_proto::pb;
use foveal_server::{Role, ServerConfig, ServerError, Tokens};
use foveal_tests::{TestCa, TestServer, sample, small_config, within};
use tonic::Code;
use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_client::HealthClient;

const VIEWER: &str = "viewer-secret-0123456789";
const GAZE: &str = "gaze-secret-0123456789";
const ADMIN: &str = "admin-secret-0123456789";

fn with_tokens(mut config: ServerConfig) -> ServerConfig {
    let mut tokens = Tokens::none();
    tokens.add(Role::Viewer, VIEWER, "test").expect("token");
    tokens.add(Role::Gaze, GAZE, "test").expect("token");
    tokens.add(Role::Admin, ADMIN, "test").expect("token");
    config.security.tokens = tokens;
    config
}

fn code<T>(r: Result<T, tonic::Status>) -> Code {
    r.map_or_else(|s| s.code(), |_| Code::Ok)
}

fn push() -> pb::PushGazeRequest {
    pb::PushGazeRequest {
        samples: vec![sample(0.0, 0.2, 0.3)],
        source: "test".into(),
    }
}

#[tokio::test]
async fn each_role_may_call_its_methods_only() {
    let server = TestServer::start(with_tokens(small_config(60, 60.0))).await;

    // No token, a wrong token: UNAUTHENTICATED, with a message that says what to send.
    let mut anon = server.client().await;
    let e = anon
        .get_status(pb::GetStatusRequest {})
        .await
        .expect_err("no token");
    assert_eq!(e.code(), Code::Unauthenticated);
    assert!(
        e.message().contains("authorization: Bearer"),
        "{}",
        e.message()
    );
    let mut wrong = server.client_as("not-a-token-of-this-server").await;
    assert_eq!(
        code(wrong.get_scene(pb::GetSceneRequest {}).await),
        Code::Unauthenticated
    );

    // Viewer: reads, but neither sends gaze nor configures.
    let mut viewer = server.client_as(VIEWER).await;
    assert_eq!(
        code(viewer.get_status(pb::GetStatusRequest {}).await),
        Code::Ok
    );
    assert_eq!(
        code(viewer.get_scene(pb::GetSceneRequest {}).await),
        Code::Ok
    );
    let mut frames = viewer
        .watch_frames(pb::WatchFramesRequest::default())
        .await
        .expect("viewer may watch")
        .into_inner();
    within("a frame", frames.message())
        .await
        .expect("stream ok")
        .expect("a frame");
    let e = viewer
        .push_gaze(push())
        .await
        .expect_err("viewer cannot push");
    assert_eq!(e.code(), Code::PermissionDenied);
    assert!(e.message().contains("`gaze`"), "{}", e.message());
    assert_eq!(
        code(viewer.configure(pb::ConfigureRequest::default()).await),
        Code::PermissionDenied
    );

    // Gaze: sends gaze only.
    let mut gaze = server.client_as(GAZE).await;
    let r = gaze
        .push_gaze(push())
        .await
        .expect("gaze may push")
        .into_inner();
    assert_eq!(r.accepted, 1);
    assert_eq!(
        code(gaze.watch_frames(pb::WatchFramesRequest::default()).await),
        Code::PermissionDenied
    );
    assert_eq!(
        code(gaze.configure(pb::ConfigureRequest::default()).await),
        Code::PermissionDenied
    );

    // Admin: everything.
    let mut admin = server.client_as(ADMIN).await;
    assert_eq!(code(admin.push_gaze(push()).await), Code::Ok);
    let applied = admin
        .configure(pb::ConfigureRequest {
            config: Some(pb::SceneConfig {
                bodies: 70,
                ..Default::default()
            }),
            update_mask: None,
        })
        .await
        .expect("admin may configure")
        .into_inner()
        .applied
        .expect("applied");
    assert_eq!(applied.bodies, 70);

    // Health stays open.
    let status = HealthClient::new(server.channel().await)
        .check(HealthCheckRequest {
            service: String::new(),
        })
        .await
        .expect("health needs no token")
        .into_inner();
    assert_eq!(
        status.status,
        tonic_health::pb::health_check_response::ServingStatus::Serving as i32
    );
    server.stop().await.expect("clean stop");
}

#[tokio::test]
async fn tls_with_a_generated_certificate_end_to_end() {
    let ca = TestCa::new();
    let server = TestServer::start_tls(with_tokens(small_config(60, 60.0)), &ca).await;
    let mut viewer = server.client_as(VIEWER).await;
    let scene = viewer
        .get_scene(pb::GetSceneRequest {})
        .await
        .expect("GetScene over TLS")
        .into_inner();
    assert_eq!(scene.config.expect("config").bodies, 60);
    let mut frames = viewer
        .watch_frames(pb::WatchFramesRequest::default())
        .await
        .expect("watch over TLS")
        .into_inner();
    within("a frame over TLS", frames.message())
        .await
        .expect("stream ok")
        .expect("a frame");

    // Plaintext to the TLS port does not get through.
    let plain = tonic::transport::Channel::from_shared(format!("http://{}", server.addr))
        .expect("url")
        .connect_timeout(Duration::from_secs(2))
        .timeout(Duration::from_secs(2))
        .connect()
        .await;
    let reached = match plain {
        Err(_) => false,
        Ok(channel) => pb::foveal_client::FovealClient::new(channel)
            .get_status(pb::GetStatusRequest {})
            .await
            .is_ok(),
    };
    assert!(!reached, "a plaintext call must not reach a TLS server");
    server.stop().await.expect("clean stop");
}

async fn run_on_all_interfaces(config: ServerConfig) -> Result<(), ServerError> {
    let listener = tokio::net::TcpListener::bind("0.0.0.0:0")
        .await
        .expect("bind 0.0.0.0:0");
    let (stop, stopped) = tokio::sync::oneshot::channel::<()>();
    let run = tokio::spawn(foveal_server::run(listener, config, async move {
        let _ = stopped.await;
    }));
    // A refusal comes before the scene is built; a server that starts is stopped at once.
    tokio::time::sleep(Duration::from_millis(300)).await;
    let _ = stop.send(());
    within("run to return", run).await.expect("not panicked")
}

#[tokio::test]
async fn beyond_loopback_needs_tokens_or_insecure() {
    let e = run_on_all_interfaces(small_config(20, 60.0))
        .await
        .expect_err("open server on 0.0.0.0");
    assert!(matches!(e, ServerError::Insecure { .. }), "{e}");
    assert!(e.to_string().contains("FOVEAL_ADMIN_TOKEN"), "{e}");

    run_on_all_interfaces(with_tokens(small_config(20, 60.0)))
        .await
        .expect("tokens make it safe");
    let mut insecure = small_config(20, 60.0);
    insecure.security.insecure = true;
    run_on_all_interfaces(insecure)
        .await
        .expect("--insecure is the operator's choice");
}

#[test]
fn tls_files_that_are_not_pem_are_refused_at_start_up_naming_the_flag() {
    let dir = std::env::temp_dir().join(format!("foveal-tls-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("dir");
    let ca = TestCa::new();
    let (cert, key, junk) = (
        dir.join("cert.pem"),
        dir.join("key.pem"),
        dir.join("junk.pem"),
    );
    std::fs::write(&cert, &ca.cert_pem).expect("cert");
    std::fs::write(&key, &ca.key_pem).expect("key");
    std::fs::write(&junk, "not a certificate\n").expect("junk");
    let cli = |c: &std::path::Path, k: &std::path::Path| {
        foveal_server::cli::Cli::try_parse_from([
            "foveal-server".as_ref(),
            "--tls-cert".as_ref(),
            c.as_os_str(),
            "--tls-key".as_ref(),
            k.as_os_str(),
        ])
        .expect("flags parse")
    };
    let good = cli(&cert, &key)
        .security()
        .expect("a generated certificate and key");
    assert!(good.tls.is_some());
    let e = cli(&junk, &key)
        .security()
        .expect_err("junk certificate")
        .to_string();
    assert!(e.contains("--tls-cert") && e.contains("CERTIFICATE"), "{e}");
    let e = cli(&cert, &junk)
        .security()
        .expect_err("junk key")
        .to_string();
    assert!(e.contains("--tls-key") && e.contains("private key"), "{e}");
    // A certificate where the key should be is no key either.
    let e = cli(&cert, &cert)
        .security()
        .expect_err("certificate as key")
        .to_string();
    assert!(e.contains("--tls-key"), "{e}");
    let _ = std::fs::remove_dir_all(&dir);
}
