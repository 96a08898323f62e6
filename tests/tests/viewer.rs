//! What the browser viewer relies on, over real sockets: quantised poses and the collision list on
//! WatchFrames, the page served on the gRPC port over HTTP/1.1, and grpc-web calls on that port.

use foveal_engine::BudgetSpec;
use foveal_proto::pb;
use foveal_tests::{TestServer, frame_where, small_config, within};
use tokio::io::{AsyncReadExt, AsyncWriteExt};

fn viewer_request(quantised: bool) -> pb::WatchFramesRequest {
    pb::WatchFramesRequest {
        every_k: 1,
        include_poses: true,
        quantised_poses: quantised,
        include_collisions: true,
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn quantised_poses_match_f32_poses_and_collisions_match_the_metrics() {
    let mut config = small_config(400, 60.0);
    // A tight deterministic budget: every frame has both real and deemed pairs.
    config.sim.budget = BudgetSpec::SphereTests(600);
    let server = TestServer::start(config).await;
    let mut full = server.client().await;
    let mut quant = server.client().await;
    let mut f32_frames = full
        .watch_frames(viewer_request(false))
        .await
        .expect("WatchFrames")
        .into_inner();
    let mut q_frames = quant
        .watch_frames(viewer_request(true))
        .await
        .expect("WatchFrames")
        .into_inner();

    let q = frame_where(&mut q_frames, "a quantised frame with deemed pairs", |f| {
        f.metrics
            .as_ref()
            .is_some_and(|m| m.deemed_at_interruption > 0)
    })
    .await;
    assert!(q.poses.is_none(), "quantised frames carry no f32 poses");
    let f = frame_where(&mut f32_frames, "the same frame as f32", |f| {
        f.index >= q.index
    })
    .await;
    assert_eq!(f.index, q.index, "both subscribers see every frame");
    assert!(f.quantised_poses.is_none());

    let qp = q.quantised_poses.as_ref().expect("quantised poses");
    let fp = f.poses.as_ref().expect("f32 poses");
    assert_eq!((qp.bodies, fp.bodies), (400, 400));
    assert_eq!(qp.positions.len(), 6 * 400);
    assert_eq!(qp.orientations.len(), 4 * 400);
    assert!(
        2 * (qp.positions.len() + qp.orientations.len())
            <= fp.positions.len() + fp.orientations.len()
    );
    assert_eq!(qp.origin, fp.origin);
    let step = qp.extent as f32 / 65535.0;
    for (a, b) in qp.positions_f32().zip(fp.positions_f32()) {
        for (x, y) in a.iter().zip(b) {
            // Half a step of rounding, plus f32 noise on a volume of side ~3.4.
            assert!((x - y).abs() <= 0.5 * step + 1e-5, "{a:?} vs {b:?}");
        }
    }
    for (a, b) in qp.orientations_f32().zip(fp.orientations_f32()) {
        let dot: f32 = a.iter().zip(b).map(|(x, y)| x * y).sum();
        let deg = 2.0 * dot.abs().min(1.0).acos().to_degrees();
        assert!(deg < 0.25, "{a:?} vs {b:?}: {deg} degrees apart");
    }

    for frame in [&q, &f] {
        let m = frame.metrics.as_ref().expect("metrics");
        let c = frame.collisions.as_ref().expect("collisions asked for");
        assert_eq!(c.deemed_pairs().count() as u64, m.deemed_at_interruption);
        assert_eq!(c.real_pairs().count() as u64, m.real_collisions);
        for (a, b) in c.real_pairs().chain(c.deemed_pairs()) {
            assert!(a < b && b < 400, "pair ({a}, {b})");
        }
    }
    assert_eq!(q.collisions, f.collisions);
    server.stop().await.expect("clean stop");
}

/// One HTTP/1.1 exchange on a fresh connection; the whole response as bytes.
async fn http1(server: &TestServer, request: &[u8]) -> Vec<u8> {
    let mut s = tokio::net::TcpStream::connect(server.addr)
        .await
        .expect("connect");
    s.write_all(request).await.expect("send");
    let mut out = Vec::new();
    within("the HTTP response", s.read_to_end(&mut out))
        .await
        .expect("read");
    out
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_viewer_page_and_grpc_web_share_the_grpc_port() {
    let server = TestServer::start(small_config(50, 60.0)).await;
    // Wait until it serves gRPC (the listener is bound before `run` is polled).
    let _ = server.client().await;

    let page = text(
        &http1(
            &server,
            b"GET / HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n",
        )
        .await,
    );
    assert!(page.starts_with("HTTP/1.1 200"), "{page}");
    assert!(
        page.to_lowercase().contains("content-type: text/html"),
        "{page}"
    );
    assert!(page.contains("<script src=\"viewer.js\">"), "{page}");

    let script = text(
        &http1(
            &server,
            b"GET /viewer.js HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n",
        )
        .await,
    );
    assert!(script.starts_with("HTTP/1.1 200"));
    assert!(
        script
            .to_lowercase()
            .contains("content-type: text/javascript")
    );

    let missing = text(
        &http1(
            &server,
            b"GET /nope HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\r\n",
        )
        .await,
    );
    assert!(missing.starts_with("HTTP/1.1 404"), "{missing}");

    // GetStatus as grpc-web over HTTP/1.1: an empty message behind the 5-byte frame header.
    let call = b"POST /foveal.v1.Foveal/GetStatus HTTP/1.1\r\nHost: localhost\r\nConnection: close\r\n\
        Content-Type: application/grpc-web+proto\r\nX-Grpc-Web: 1\r\nContent-Length: 5\r\n\r\n\0\0\0\0\0";
    let answer = http1(&server, call).await;
    let head = text(&answer);
    assert!(head.starts_with("HTTP/1.1 200"), "{head}");
    assert!(
        head.to_lowercase()
            .contains("content-type: application/grpc-web"),
        "{head}"
    );
    // The trailer frame (flag 0x80) carries grpc-status 0.
    assert!(head.contains("grpc-status:0"), "{head}");
    server.stop().await.expect("clean stop");
}
