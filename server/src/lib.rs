//! # foveal-server
//!
//! The gRPC server around the foveal engine: it runs the budgeted collision loop headless, takes a
//! gaze stream in, and streams poses and per-frame accuracy metrics out to thin clients.
//!
//! # Layout
//! - [`run`]: the entry point (mini-redis style): serve on a bound listener until a shutdown
//!   future resolves, then end open streams, stop and join the frame loop.
//! - [`config`]: [`ServerConfig`], the engine config plus frame rate, gaze max age, buffers.
//! - [`cli`]: the `foveal-server` flags and `FOVEAL_*` environment variables; [`telemetry`]: logs.
//! - [`frame_loop`]: the frame loop's OS thread: fixed-rate pacing, overrun counting, scene swaps
//!   at frame boundaries; [`clock`]: the monotonic clock the engine's wall-clock budget runs on.
//! - [`fixation_cell`]: the latest-gaze cell the loop reads once per frame, with the fallback rule.
//! - [`gaze`]: gaze-sample validation shared by StreamGaze and PushGaze.
//! - [`fanout`]: the non-blocking frame broadcast and each WatchFrames subscriber's stream.
//! - [`service`]: the `foveal.v1.Foveal` handlers; [`convert`]: engine ↔ protocol conversions and
//!   Configure's merge rule.
//! - [`state`], [`metrics`], [`summary`], [`shutdown`]: shared state, counters, the per-second
//!   summary line, the shutdown signal.
//! - [`web`]: the browser viewer on the gRPC port: grpc-web and the embedded page.
//!
//! Data flow: gaze → [`gaze`] → [`fixation_cell`] → [`frame_loop`] (engine step) → [`fanout`] →
//! subscribers. Protocol semantics are documented in `docs/PROTOCOL.md`.

use std::future::Future;
use std::sync::Arc;

use foveal_engine::Simulation;
use foveal_proto::pb::foveal_server::FovealServer;
use tokio::net::TcpListener;
use tokio_stream::StreamExt;
use tokio_stream::wrappers::TcpListenerStream;

pub mod cli;
pub mod clock;
pub mod config;
pub mod convert;
pub mod error;
pub mod fanout;
pub mod fixation_cell;
pub mod frame_loop;
pub mod gaze;
pub mod metrics;
pub mod service;
pub mod shutdown;
pub mod state;
pub mod summary;
pub mod telemetry;
pub mod web;

pub use config::ServerConfig;
pub use error::ServerError;
pub use service::FovealService;

use frame_loop::FrameLoop;
use state::{Scene, Shared};

/// Serve the foveal service (plus health and reflection v1/v1alpha) on `listener` until `shutdown`
/// resolves. Then: health turns NOT_SERVING, open WatchFrames and StreamGaze calls end, calls
/// still open after [`ServerConfig::shutdown_grace`] are abandoned, and the frame loop thread is
/// stopped and joined.
pub async fn run(
    listener: TcpListener,
    config: ServerConfig,
    shutdown: impl Future<Output = ()>,
) -> Result<(), ServerError> {
    config.validate()?;
    let rate = config.frame_rate_hz;
    let sim_config = config.sim.clone();
    // Scene generation and budget calibration can take seconds at large N: not on a worker.
    let (sim, scene) = tokio::task::spawn_blocking(move || {
        Simulation::new(sim_config).map(|sim| {
            let scene = Scene::of(&sim, rate);
            (sim, scene)
        })
    })
    .await??;
    let shared = Arc::new(
        Shared::new(scene, config.gaze_max_age, config.frame_buffer)
            .with_gaze_processing(config.gaze_processing),
    );
    let frame_loop = FrameLoop::spawn(sim, Arc::clone(&shared), config.summary_interval)?;
    let (trigger, stop) = shutdown::channel();
    let service = FovealService::new(Arc::clone(&shared), frame_loop.commands(), stop.clone());

    let (health, health_service) = tonic_health::server::health_reporter();
    health.set_serving::<FovealServer<FovealService>>().await;
    let reflection = || {
        tonic_reflection::server::Builder::configure()
            .register_encoded_file_descriptor_set(foveal_proto::FILE_DESCRIPTOR_SET)
            .register_encoded_file_descriptor_set(tonic_health::pb::FILE_DESCRIPTOR_SET)
    };
    let reflection_v1 = reflection().build_v1()?;
    let reflection_v1alpha = reflection().build_v1alpha()?;

    let addr = listener
        .local_addr()
        .map_or_else(|e| format!("unknown ({e})"), |a| a.to_string());
    tracing::info!(
        %addr,
        bodies = config.sim.scene.bodies,
        scheduler = config.sim.scheduler.name(),
        budget = ?config.sim.budget,
        frame_rate_hz = rate,
        "serving"
    );
    // Frames are small writes that must leave at once: no Nagle delay on accepted connections.
    let incoming = TcpListenerStream::new(listener).map(|conn| {
        conn.inspect(|stream| {
            if let Err(e) = stream.set_nodelay(true) {
                tracing::debug!(error = %e, "could not set TCP_NODELAY");
            }
        })
    });
    let mut server_stop = stop.clone();
    // HTTP/1.1, grpc-web and the embedded page: the browser viewer on this port (see `web`).
    let server = tonic::transport::Server::builder()
        .accept_http1(true)
        .layer(web::ViewerLayer)
        .add_service(health_service)
        .add_service(reflection_v1)
        .add_service(reflection_v1alpha)
        .add_service(FovealServer::new(service))
        .serve_with_incoming_shutdown(incoming, async move { server_stop.wait().await });
    tokio::pin!(server);

    let served = tokio::select! {
        served = &mut server => served,
        () = shutdown => {
            tracing::info!("shutting down");
            health.set_not_serving::<FovealServer<FovealService>>().await;
            trigger.trigger();
            match tokio::time::timeout(config.shutdown_grace, &mut server).await {
                Ok(served) => served,
                Err(_) => {
                    tracing::warn!(
                        grace_s = config.shutdown_grace.as_secs_f64(),
                        "calls still open after the shutdown grace period; abandoning them"
                    );
                    Ok(())
                }
            }
        }
    };
    trigger.trigger();
    let joined = tokio::task::spawn_blocking(move || frame_loop.stop_and_join()).await?;
    tracing::info!("stopped");
    served?;
    joined
}
