//! # foveal-tests
//!
//! End-to-end tests: a real server in-process on 127.0.0.1:0, driven over real sockets with the
//! generated gRPC client, as a gaze bridge or a viewer would.
//!
//! # Layout
//! - this file: [`TestServer`] (start, connect, stop), the one in-process server of the
//!   end-to-end tests, the client's tests and the latency bench, and helpers to script gaze and
//!   wait for frames with generous timeouts; [`Bearer`] presents a token; [`TestCa`] makes a
//!   certificate for TLS tests.
//! - `tests/gaze.rs`: the fixation follows scripted gaze; stale gaze falls back.
//! - `tests/validation.rs`: bad samples, oversize batches, bad Configure.
//! - `tests/scheduling.rs`: gaze-steered scheduling under a tight budget; the wall-clock budget.
//! - `tests/robustness.rs`: vanishing clients, many subscribers, shutdown.
//! - `tests/services.rs`: health, reflection, GetScene (with the truth and the star), Configure of
//!   the truth.
//! - `tests/viewer.rs`: quantised poses, collision lists, the page and grpc-web on the gRPC port.
//! - `tests/record_replay.rs`: a session recorded with `--record` replays bit for bit.
//! - `tests/security.rs`: roles, TLS, loopback-only without tokens; `tests/limits.rs`: scene
//!   cost, oversize messages, gaze rate limit, honest health, shutdown with stalled subscribers.
//! - `tests/psych_results.rs`: the `/psych` results endpoint: trials appended and read back by
//!   `foveal psych fit`'s reader, malformed ones refused by field, the writer's role.
//! - `tests/doc_citations.rs`: every document and section the code and docs cite exists, and
//!   nothing points outside the repository (no server involved).

// Test helpers panic with a message on setup failures; that is the failure report.
#![allow(clippy::missing_panics_doc)]

use std::future::Future;
use std::net::SocketAddr;
use std::time::{Duration, Instant};

use foveal_proto::pb;
use foveal_proto::pb::foveal_client::FovealClient;
use foveal_server::{ServerConfig, ServerError};
use tokio::sync::oneshot;
use tokio::task::JoinHandle;
use tonic::metadata::{Ascii, MetadataValue};
use tonic::service::Interceptor;
use tonic::service::interceptor::InterceptedService;
use tonic::transport::{Certificate, Channel, ClientTlsConfig};

pub use foveal_proto::pb::FixationSource;

/// Generous bound on anything that should take a few frames; tests finish far sooner.
pub const PATIENCE: Duration = Duration::from_secs(10);

/// A small, fast scene: `bodies` bodies at `frame_rate_hz`, everything else default.
pub fn small_config(bodies: u32, frame_rate_hz: f64) -> ServerConfig {
    let mut c = ServerConfig {
        frame_rate_hz,
        ..ServerConfig::default()
    };
    c.sim.scene.bodies = bodies;
    c
}

/// Presents a bearer token on every call (or nothing).
#[derive(Debug, Clone, Default)]
pub struct Bearer(Option<MetadataValue<Ascii>>);

impl Bearer {
    /// Present `token`.
    pub fn token(token: &str) -> Self {
        Self(Some(
            format!("Bearer {token}")
                .parse()
                .expect("a header-safe token"),
        ))
    }
}

impl Interceptor for Bearer {
    fn call(&mut self, mut req: tonic::Request<()>) -> Result<tonic::Request<()>, tonic::Status> {
        if let Some(h) = &self.0 {
            req.metadata_mut().insert("authorization", h.clone());
        }
        Ok(req)
    }
}

/// A client presenting a token.
pub type AuthClient = FovealClient<InterceptedService<Channel, Bearer>>;

/// A certificate authority made for one test, and a server certificate it signed for
/// `localhost` and 127.0.0.1.
#[derive(Debug)]
pub struct TestCa {
    /// The CA certificate, PEM (what clients trust).
    pub ca_pem: String,
    /// The server's certificate, PEM.
    pub cert_pem: String,
    /// The server's private key, PEM.
    pub key_pem: String,
}

impl TestCa {
    /// A fresh CA and server certificate.
    pub fn new() -> Self {
        use rcgen::{BasicConstraints, CertificateParams, IsCa, KeyPair};
        let ca_key = KeyPair::generate().expect("CA key");
        let mut ca_params = CertificateParams::new(Vec::<String>::new()).expect("CA params");
        ca_params.is_ca = IsCa::Ca(BasicConstraints::Unconstrained);
        let ca = ca_params.self_signed(&ca_key).expect("CA certificate");
        let key = KeyPair::generate().expect("server key");
        let params = CertificateParams::new(vec!["localhost".to_owned(), "127.0.0.1".to_owned()])
            .expect("server params");
        let ca_pem = ca.pem();
        let issuer = rcgen::Issuer::new(ca_params, &ca_key);
        let cert = params.signed_by(&key, &issuer).expect("server certificate");
        Self {
            ca_pem,
            cert_pem: cert.pem(),
            key_pem: key.serialize_pem(),
        }
    }

    /// The server side of it.
    pub fn identity(&self) -> foveal_server::TlsIdentity {
        foveal_server::TlsIdentity {
            cert_pem: self.cert_pem.clone().into_bytes(),
            key_pem: self.key_pem.clone().into_bytes(),
        }
    }
}

impl Default for TestCa {
    fn default() -> Self {
        Self::new()
    }
}

/// A server running in this process.
#[derive(Debug)]
pub struct TestServer {
    /// Where it listens.
    pub addr: SocketAddr,
    /// The CA to trust when the server speaks TLS.
    pub ca_pem: Option<String>,
    stop: Option<oneshot::Sender<()>>,
    handle: JoinHandle<Result<(), ServerError>>,
}

impl TestServer {
    /// Bind 127.0.0.1:0 and run the server with `config` until [`TestServer::stop`].
    pub async fn start(config: ServerConfig) -> Self {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
            .await
            .expect("bind 127.0.0.1:0");
        Self::start_on(listener, config, None)
    }

    /// Run the server with `config` behind TLS with a certificate from `ca`.
    pub async fn start_tls(mut config: ServerConfig, ca: &TestCa) -> Self {
        config.security.tls = Some(ca.identity());
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
            .await
            .expect("bind 127.0.0.1:0");
        Self::start_on(listener, config, Some(ca.ca_pem.clone()))
    }

    /// Run the server with `config` on a bound `listener`.
    pub fn start_on(
        listener: tokio::net::TcpListener,
        config: ServerConfig,
        ca_pem: Option<String>,
    ) -> Self {
        let addr = listener.local_addr().expect("local addr");
        let (stop, stopped) = oneshot::channel::<()>();
        let handle = tokio::spawn(foveal_server::run(listener, config, async move {
            // Err: the TestServer was dropped without stop(); shut down all the same.
            let _ = stopped.await;
        }));
        Self {
            addr,
            ca_pem,
            stop: Some(stop),
            handle,
        }
    }

    /// The channel URL (`https://localhost:PORT` behind TLS).
    pub fn url(&self) -> String {
        match self.ca_pem {
            Some(_) => format!("https://localhost:{}", self.addr.port()),
            None => format!("http://{}", self.addr),
        }
    }

    /// A connected channel (retrying while the server finishes starting).
    pub async fn channel(&self) -> Channel {
        let deadline = Instant::now() + PATIENCE;
        loop {
            let mut endpoint = Channel::from_shared(self.url())
                .expect("valid url")
                .tcp_nodelay(true);
            if let Some(ca) = &self.ca_pem {
                endpoint = endpoint
                    .tls_config(
                        ClientTlsConfig::new()
                            .ca_certificate(Certificate::from_pem(ca))
                            .domain_name("localhost"),
                    )
                    .expect("TLS config");
            }
            // Behind TLS, localhost may resolve to ::1 first: dial the bound address itself.
            let connected = if self.ca_pem.is_some() {
                let addr = self.addr;
                endpoint
                    .connect_with_connector(tower::service_fn(
                        move |_: tonic::codegen::http::Uri| async move {
                            tokio::net::TcpStream::connect(addr)
                                .await
                                .map(hyper_util::rt::TokioIo::new)
                        },
                    ))
                    .await
            } else {
                endpoint.connect().await
            };
            match connected {
                Ok(ch) => return ch,
                Err(e) if Instant::now() < deadline => {
                    let _ = e;
                    tokio::time::sleep(Duration::from_millis(20)).await;
                }
                Err(e) => panic!("cannot connect to {}: {e}", self.url()),
            }
        }
    }

    /// A client on a fresh connection, accepting large frames (poses).
    pub async fn client(&self) -> FovealClient<Channel> {
        FovealClient::new(self.channel().await).max_decoding_message_size(64 << 20)
    }

    /// A client on a fresh connection presenting `token`.
    pub async fn client_as(&self, token: &str) -> AuthClient {
        FovealClient::with_interceptor(self.channel().await, Bearer::token(token))
            .max_decoding_message_size(64 << 20)
    }

    /// Trigger shutdown without waiting; [`TestServer::stopped`] then waits for it.
    pub fn trigger_stop(&mut self) {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
    }

    /// Wait for `run` to return (after [`TestServer::trigger_stop`] or [`TestServer::stop`]).
    pub async fn stopped(mut self) -> Result<(), ServerError> {
        self.trigger_stop();
        tokio::time::timeout(PATIENCE, &mut self.handle)
            .await
            .expect("server stops within the patience bound")
            .expect("server task not panicked")
    }

    /// Trigger shutdown and wait for `run` to return.
    pub async fn stop(mut self) -> Result<(), ServerError> {
        if let Some(stop) = self.stop.take() {
            let _ = stop.send(());
        }
        tokio::time::timeout(PATIENCE, &mut self.handle)
            .await
            .expect("server stops within the patience bound")
            .expect("server task not panicked")
    }
}

/// A valid gaze sample at (x, y), tracker time `t`.
pub fn sample(t: f64, x: f64, y: f64) -> pb::GazeSample {
    pb::GazeSample {
        tracker_time_s: t,
        x,
        y,
        validity: 1.0,
        eye: pb::Eye::Binocular as i32,
        fixation: Some(true),
    }
}

/// Await `fut` or panic with `what` after [`PATIENCE`].
pub async fn within<T>(what: &str, fut: impl Future<Output = T>) -> T {
    tokio::time::timeout(PATIENCE, fut)
        .await
        .unwrap_or_else(|_| panic!("timed out waiting for {what}"))
}

/// Open a WatchFrames stream.
pub async fn watch(
    client: &mut FovealClient<Channel>,
    every_k: u32,
    include_poses: bool,
) -> tonic::Streaming<pb::Frame> {
    client
        .watch_frames(pb::WatchFramesRequest {
            every_k,
            include_poses,
            ..Default::default()
        })
        .await
        .expect("WatchFrames accepted")
        .into_inner()
}

/// The next frame of a stream (panics if the stream ends or errs).
pub async fn next_frame(frames: &mut tonic::Streaming<pb::Frame>) -> pb::Frame {
    within("a frame", frames.message())
        .await
        .expect("stream not failed")
        .expect("stream not ended")
}

/// The first frame satisfying `pred` (panics after [`PATIENCE`]).
pub async fn frame_where(
    frames: &mut tonic::Streaming<pb::Frame>,
    what: &str,
    mut pred: impl FnMut(&pb::Frame) -> bool,
) -> pb::Frame {
    within(what, async {
        loop {
            let f = frames
                .message()
                .await
                .expect("stream not failed")
                .expect("stream not ended");
            if pred(&f) {
                return f;
            }
        }
    })
    .await
}

/// The fixation of a frame (always present).
pub fn fixation(f: &pb::Frame) -> pb::Fixation {
    f.fixation.expect("every frame has a fixation")
}

/// Frames simulated so far, from GetStatus.
pub async fn frames_so_far(client: &mut FovealClient<Channel>) -> u64 {
    status(client).await.frames
}

/// GetStatus.
pub async fn status(client: &mut FovealClient<Channel>) -> pb::Status {
    client
        .get_status(pb::GetStatusRequest {})
        .await
        .expect("GetStatus")
        .into_inner()
}
