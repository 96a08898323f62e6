//! What a client may hold, and for how long, over real sockets: a silent connection, a half-sent
//! head, a body that never ends, an idle keep-alive connection, the connection limit, shutdown
//! with a stalled body, the browsers' Host/Origin allow-list, HTTP/1.1 over TLS (ALPN), and the
//! caps on health watches. Timeouts are configured short, and every assertion waits for the
//! event with the generous patience bound instead of sleeping for a fixed time.

use std::time::{Duration, Instant};

use foveal_proto::pb;
use foveal_server::{ConnectionLimits, MAX_HEALTH_WATCHES_PER_CONNECTION, ServerConfig};
use foveal_tests::{PATIENCE, TestCa, TestServer, small_config, status, within};
use tokio::io::{AsyncRead, AsyncReadExt, AsyncWriteExt};
use tokio::net::TcpStream;
use tonic::Code;
use tonic_health::pb::HealthCheckRequest;
use tonic_health::pb::health_client::HealthClient;

/// Short timeouts, so that a test sees each one fire in a fraction of a second.
fn quick(mut config: ServerConfig) -> ServerConfig {
    config.connections = ConnectionLimits {
        first_byte_timeout: Duration::from_millis(300),
        header_timeout: Duration::from_millis(300),
        body_idle_timeout: Duration::from_millis(300),
        idle_timeout: Duration::from_millis(300),
        ..ConnectionLimits::default()
    };
    config
}

/// Read until the server closes the connection; everything it sent, and how long it took.
async fn until_closed(s: &mut (impl AsyncRead + Unpin)) -> (Vec<u8>, Duration) {
    let t0 = Instant::now();
    let mut out = Vec::new();
    let mut buf = [0u8; 4096];
    within("the server to close the connection", async {
        loop {
            match s.read(&mut buf).await {
                Ok(0) | Err(_) => break,
                Ok(n) => out.extend_from_slice(&buf[..n]),
            }
        }
    })
    .await;
    (out, t0.elapsed())
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

/// A grpc-web call's HTTP/1.1 request: `message` behind the 5-byte frame header.
fn grpc_web(method: &str, host: &str, origin: Option<&str>, message: &[u8]) -> Vec<u8> {
    let mut r = format!(
        "POST /foveal.v1.Foveal/{method} HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\
         Content-Type: application/grpc-web+proto\r\nX-Grpc-Web: 1\r\nContent-Length: {}\r\n",
        message.len() + 5
    );
    if let Some(o) = origin {
        r.push_str(&format!("Origin: {o}\r\n"));
    }
    r.push_str("\r\n");
    let mut bytes = r.into_bytes();
    bytes.push(0);
    bytes.extend_from_slice(&u32::try_from(message.len()).expect("small").to_be_bytes());
    bytes.extend_from_slice(message);
    bytes
}

async fn exchange(server: &TestServer, request: &[u8]) -> String {
    let mut s = TcpStream::connect(server.addr).await.expect("connect");
    s.write_all(request).await.expect("send");
    text(&until_closed(&mut s).await.0)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn silent_connections_half_heads_and_idle_keep_alive_are_closed() {
    let server = TestServer::start(quick(small_config(50, 30.0))).await;
    let _ = server.client().await;

    // Connects and sends nothing.
    let mut silent = TcpStream::connect(server.addr).await.expect("connect");
    let (sent, took) = until_closed(&mut silent).await;
    assert!(sent.is_empty(), "{}", text(&sent));
    println!("silent connection closed after {took:?}");

    // Half an HTTP/1.1 head.
    let mut half = TcpStream::connect(server.addr).await.expect("connect");
    half.write_all(b"GET / HTTP/1.1\r\nHost: localhost\r\n")
        .await
        .expect("send");
    let (_, took) = until_closed(&mut half).await;
    println!("half a head closed after {took:?}");

    // One HTTP/1.1 request on a keep-alive connection, then nothing.
    let mut kept = TcpStream::connect(server.addr).await.expect("connect");
    kept.write_all(b"GET /nope HTTP/1.1\r\nHost: localhost\r\n\r\n")
        .await
        .expect("send");
    let (answer, took) = until_closed(&mut kept).await;
    assert!(
        text(&answer).starts_with("HTTP/1.1 404"),
        "{}",
        text(&answer)
    );
    println!("idle keep-alive connection closed after {took:?}");

    // An HTTP/2 preface and nothing after it: no request within the header timeout.
    let mut h2 = TcpStream::connect(server.addr).await.expect("connect");
    h2.write_all(b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n\0\0\0\x04\0\0\0\0\0")
        .await
        .expect("send");
    let (_, took) = until_closed(&mut h2).await;
    println!("HTTP/2 connection without a request closed after {took:?}");

    // The server still answers at once.
    let mut client = server.client().await;
    assert!(status(&mut client).await.frames > 0 || status(&mut client).await.uptime_s > 0.0);
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn an_http2_connection_without_calls_is_closed_after_the_idle_timeout() {
    let server = TestServer::start(quick(small_config(50, 30.0))).await;
    let _ = server.client().await;
    let tcp = TcpStream::connect(server.addr).await.expect("connect");
    let (mut send, conn) = hyper::client::conn::http2::handshake(
        hyper_util::rt::TokioExecutor::new(),
        hyper_util::rt::TokioIo::new(tcp),
    )
    .await
    .expect("HTTP/2 handshake");
    let conn = tokio::spawn(conn);
    let page = hyper::Request::get(format!("http://{}/", server.addr))
        .body(String::new())
        .expect("request");
    let response = send.send_request(page).await.expect("GET / over HTTP/2");
    assert_eq!(response.status(), 200);
    drop(response);
    // The client keeps the connection (and would answer keepalive pings) but calls nothing.
    let t0 = Instant::now();
    let ended = within("the server to close the idle connection", conn).await;
    println!(
        "idle HTTP/2 connection closed after {:?}: {ended:?}",
        t0.elapsed()
    );
    drop(send);
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_request_body_that_stops_fails_the_call_naming_the_limit() {
    let server = TestServer::start(quick(small_config(50, 30.0))).await;
    let _ = server.client().await;
    let request = grpc_web("GetStatus", "localhost", None, &[]);
    let mut s = TcpStream::connect(server.addr).await.expect("connect");
    // The head and 2 of the 5 bytes of the body, then silence.
    s.write_all(&request[..request.len() - 3])
        .await
        .expect("send");
    let (answer, took) = until_closed(&mut s).await;
    let answer = text(&answer);
    println!("stalled body answered after {took:?}");
    assert!(
        answer.contains("grpc-status: 4") || answer.contains("grpc-status:4"),
        "{answer}"
    );
    assert!(answer.contains("--body-idle-timeout"), "{answer}");
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shutdown_does_not_wait_for_a_body_that_never_arrives() {
    let mut config = small_config(50, 30.0);
    // Long enough that waiting for it could not pass for a prompt stop.
    config.shutdown_grace = Duration::from_secs(30);
    let server = TestServer::start(config).await;
    let _ = server.client().await;
    let request = grpc_web("GetStatus", "localhost", None, &[]);
    let mut s = TcpStream::connect(server.addr).await.expect("connect");
    s.write_all(&request[..request.len() - 3])
        .await
        .expect("send");
    // The call reaches its handler as soon as the head is read; let the server read it.
    tokio::time::sleep(Duration::from_millis(100)).await;
    let t0 = Instant::now();
    server.stop().await.expect("clean stop");
    let took = t0.elapsed();
    println!("stopped after {took:?} with a stalled request body");
    assert!(took < PATIENCE / 2, "shutdown took {took:?}");
    let (answer, _) = until_closed(&mut s).await;
    let answer = text(&answer);
    assert!(
        answer.is_empty() || answer.contains("grpc-status: 14"),
        "{answer}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn connections_over_the_limit_are_closed_at_once() {
    let mut config = small_config(50, 30.0);
    config.connections = ConnectionLimits {
        max_connections: Some(4),
        // Far beyond the patience bound: only the limit can close the fifth.
        first_byte_timeout: Duration::from_secs(600),
        ..ConnectionLimits::default()
    };
    let server = TestServer::start(config).await;
    let mut held = Vec::new();
    for _ in 0..4 {
        held.push(TcpStream::connect(server.addr).await.expect("connect"));
    }
    let mut fifth = TcpStream::connect(server.addr).await.expect("connect");
    let (_, took) = until_closed(&mut fifth).await;
    println!("the fifth connection was closed after {took:?}");
    // One of the four goes; a client is served again once the server has seen it go.
    drop(held.pop());
    within("a client served after a connection ended", async {
        loop {
            let mut client = server.client().await;
            if client.get_status(pb::GetStatusRequest {}).await.is_ok() {
                return;
            }
            tokio::time::sleep(Duration::from_millis(20)).await;
        }
    })
    .await;
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn browsers_are_answered_only_at_allowed_hosts_and_origins() {
    let server = TestServer::start(small_config(50, 30.0)).await;
    let mut client = server.client().await;
    let before = status(&mut client).await;
    let configure = prost_encode(&pb::ConfigureRequest::default());

    // DNS rebinding: the attacker's name, pointed at 127.0.0.1.
    let answer = exchange(
        &server,
        &grpc_web(
            "Configure",
            "rebind.evil.example",
            Some("http://rebind.evil.example"),
            &configure,
        ),
    )
    .await;
    assert!(answer.contains("grpc-status: 7"), "{answer}");
    assert!(answer.contains("rebind.evil.example"), "{answer}");
    assert!(answer.contains("--allowed-origin"), "{answer}");
    // A page on another site calling the loopback address directly.
    let host = format!("127.0.0.1:{}", server.addr.port());
    let answer = exchange(
        &server,
        &grpc_web("Configure", &host, Some("http://evil.example"), &configure),
    )
    .await;
    assert!(answer.contains("grpc-status: 7"), "{answer}");
    // The page itself under the attacker's name.
    let page = exchange(
        &server,
        b"GET / HTTP/1.1\r\nHost: rebind.evil.example\r\nConnection: close\r\n\r\n",
    )
    .await;
    assert!(page.starts_with("HTTP/1.1 403"), "{page}");
    assert!(page.contains("DNS rebinding"), "{page}");
    let after = status(&mut client).await;
    assert_eq!(
        after.config.map(|c| c.seed),
        before.config.map(|c| c.seed),
        "nothing was reconfigured"
    );

    // The viewer at its own address, and at localhost, still works.
    let origin = format!("http://{host}");
    let answer = exchange(&server, &grpc_web("GetStatus", &host, Some(&origin), &[])).await;
    assert!(answer.contains("grpc-status:0"), "{answer}");
    let answer = exchange(
        &server,
        &grpc_web(
            "GetStatus",
            &format!("localhost:{}", server.addr.port()),
            Some(&format!("http://localhost:{}", server.addr.port())),
            &[],
        ),
    )
    .await;
    assert!(answer.contains("grpc-status:0"), "{answer}");
    server.stop().await.expect("clean stop");

    // With --allowed-origin, that name is served.
    let mut config = small_config(50, 30.0);
    config.security.allowed_origins = vec!["http://lab-pc.example".parse().expect("origin")];
    let server = TestServer::start(config).await;
    let _ = server.client().await;
    let answer = exchange(
        &server,
        &grpc_web(
            "GetStatus",
            "lab-pc.example",
            Some("http://lab-pc.example"),
            &[],
        ),
    )
    .await;
    assert!(answer.contains("grpc-status:0"), "{answer}");
    server.stop().await.expect("clean stop");
}

fn prost_encode(m: &impl prost::Message) -> Vec<u8> {
    m.encode_to_vec()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tls_offers_http1_so_browsers_reach_the_viewer_over_https() {
    use rustls_pki_types::pem::PemObject;
    use tokio_rustls::rustls;
    let ca = TestCa::new();
    let server = TestServer::start_tls(small_config(50, 30.0), &ca).await;
    let _ = server.client().await;

    let mut roots = rustls::RootCertStore::empty();
    for cert in rustls_pki_types::CertificateDer::pem_slice_iter(ca.ca_pem.as_bytes()) {
        roots.add(cert.expect("CA PEM")).expect("CA certificate");
    }
    let provider = std::sync::Arc::new(rustls::crypto::ring::default_provider());
    let mut tls = rustls::ClientConfig::builder_with_provider(provider)
        .with_safe_default_protocol_versions()
        .expect("protocol versions")
        .with_root_certificates(roots)
        .with_no_client_auth();
    // What a browser offers for a fetch that cannot use HTTP/2 (and what grpc-web needs).
    tls.alpn_protocols = vec![b"http/1.1".to_vec()];
    let connector = tokio_rustls::TlsConnector::from(std::sync::Arc::new(tls));
    let name = rustls_pki_types::ServerName::try_from("localhost").expect("name");

    let tcp = TcpStream::connect(server.addr).await.expect("connect");
    let mut s = within("the TLS handshake", connector.connect(name.clone(), tcp))
        .await
        .expect("a TLS handshake offering only http/1.1");
    assert_eq!(s.get_ref().1.alpn_protocol(), Some(&b"http/1.1"[..]));
    let host = format!("localhost:{}", server.addr.port());
    s.write_all(format!("GET / HTTP/1.1\r\nHost: {host}\r\nConnection: close\r\n\r\n").as_bytes())
        .await
        .expect("send");
    let page = text(&until_closed(&mut s).await.0);
    assert!(page.starts_with("HTTP/1.1 200"), "{page}");
    assert!(page.contains("viewer.js"), "{page}");

    let tcp = TcpStream::connect(server.addr).await.expect("connect");
    let mut s = connector.connect(name, tcp).await.expect("handshake");
    s.write_all(&grpc_web(
        "GetStatus",
        &host,
        Some(&format!("https://{host}")),
        &[],
    ))
    .await
    .expect("send");
    let answer = text(&until_closed(&mut s).await.0);
    assert!(answer.contains("grpc-status:0"), "{answer}");
    drop(s);
    server.stop().await.expect("clean stop");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn health_watches_are_capped_per_connection() {
    let server = TestServer::start(small_config(50, 30.0)).await;
    let channel = server.channel().await;
    let mut health = HealthClient::new(channel.clone());
    let watch = || HealthCheckRequest {
        service: String::new(),
    };
    let mut open = Vec::new();
    for _ in 0..MAX_HEALTH_WATCHES_PER_CONNECTION {
        let mut stream = health.watch(watch()).await.expect("a watch").into_inner();
        within("the first status", stream.message())
            .await
            .expect("status")
            .expect("a status");
        open.push(stream);
    }
    let refused = health.watch(watch()).await.expect_err("one too many");
    assert_eq!(refused.code(), Code::ResourceExhausted);
    assert!(
        refused
            .message()
            .contains(&MAX_HEALTH_WATCHES_PER_CONNECTION.to_string()),
        "{}",
        refused.message()
    );
    // Another connection is not affected, and a closed watch gives its place back.
    let mut other = HealthClient::new(server.channel().await);
    let _ = other.watch(watch()).await.expect("another connection");
    drop(open.pop());
    let again = within("a freed watch slot", async {
        loop {
            match health.watch(watch()).await {
                Ok(s) => return s,
                Err(_) => tokio::time::sleep(Duration::from_millis(10)).await,
            }
        }
    })
    .await;
    drop(again);
    // Check stays open whatever the watches.
    let _ = health.check(watch()).await.expect("Check");
    drop(open);
    server.stop().await.expect("clean stop");
}
