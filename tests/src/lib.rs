//! # foveal-tests
//!
//! End-to-end tests: a real server in-process on 127.0.0.1:0, driven over real sockets with the
//! generated gRPC client, as a gaze bridge or a viewer would.
//!
//! # Layout
//! - this file: [`TestServer`] (start, connect, stop) and helpers to script gaze and wait for
//!   frames with generous timeouts.
//! - `tests/gaze.rs`: the fixation follows scripted gaze; stale gaze falls back.
//! - `tests/validation.rs`: bad samples, oversize batches, bad Configure.
//! - `tests/scheduling.rs`: gaze-steered scheduling under a tight budget; the wall-clock budget.
//! - `tests/robustness.rs`: vanishing clients, many subscribers, shutdown.
//! - `tests/services.rs`: health, reflection, GetScene.
//! - `tests/viewer.rs`: quantised poses, collision lists, the page and grpc-web on the gRPC port.

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
use tonic::transport::Channel;

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

/// A server running in this process.
#[derive(Debug)]
pub struct TestServer {
    /// Where it listens.
    pub addr: SocketAddr,
    stop: Option<oneshot::Sender<()>>,
    handle: JoinHandle<Result<(), ServerError>>,
}

impl TestServer {
    /// Bind 127.0.0.1:0 and run the server with `config` until [`TestServer::stop`].
    pub async fn start(config: ServerConfig) -> Self {
        let listener = tokio::net::TcpListener::bind("127.0.0.1:0")
            .await
            .expect("bind 127.0.0.1:0");
        let addr = listener.local_addr().expect("local addr");
        let (stop, stopped) = oneshot::channel::<()>();
        let handle = tokio::spawn(foveal_server::run(listener, config, async move {
            // Err: the TestServer was dropped without stop(); shut down all the same.
            let _ = stopped.await;
        }));
        Self {
            addr,
            stop: Some(stop),
            handle,
        }
    }

    /// The channel URL.
    pub fn url(&self) -> String {
        format!("http://{}", self.addr)
    }

    /// A connected channel (retrying while the server finishes starting).
    pub async fn channel(&self) -> Channel {
        let deadline = Instant::now() + PATIENCE;
        loop {
            match Channel::from_shared(self.url())
                .expect("valid url")
                .connect()
                .await
            {
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
