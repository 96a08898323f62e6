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
//! - `auth`: roles by bearer token; `gate`: the layer every request passes (shutdown, roles,
//!   calls in progress, oversize codes); `limits`: scene-cost limits, gaze rate limits, stream
//!   and connection limits; `watchdog`: health follows whether frames complete.
//! - [`compare`]: the side by side, a second gaze-blind collider on every frame (open loop).
//! - [`frame_loop`]: the frame loop's OS thread: fixed-rate pacing, overrun counting, scene swaps
//!   at frame boundaries; [`clock`]: the monotonic clock the engine's wall-clock budget runs on.
//! - `recorder`: `--record FILE`, the session written by its own thread, never blocking a frame.
//! - [`fixation_cell`]: the latest-gaze cell the loop reads once per frame, with the fallback rule.
//! - [`gaze`]: gaze-sample validation shared by StreamGaze and PushGaze.
//! - [`fanout`]: the non-blocking frame broadcast and each WatchFrames subscriber's stream.
//! - [`service`]: the `foveal.v1.Foveal` handlers; [`convert`]: engine ↔ protocol conversions and
//!   Configure's merge rule; `control`: Pause, Resume, Step, Restart and InspectBody, answered by
//!   the loop at a frame boundary.
//! - [`state`], [`metrics`], [`summary`], [`shutdown`]: shared state, counters, the per-second
//!   summary line, the shutdown signal.
//! - [`web`]: the browser viewer on the gRPC port: grpc-web and the embedded page; `origin`: the
//!   `Host` and `Origin` allow-list browsers' requests pass (DNS rebinding).
//! - [`psych`]: the `/psych` experiments' designs and results (`/psych/api/`), behind the
//!   viewer layer like the page.
//! - `transport`: the listener and the connections on hyper: the connection limit, accept
//!   back-off, timeouts (first byte, request head, idle body, idle connection), TLS with ALPN.
//!
//! Data flow: gaze → [`gaze`] → [`fixation_cell`] → [`frame_loop`] (engine step) → [`fanout`] →
//! subscribers. Protocol semantics are documented in `docs/PROTOCOL.md`.

use std::future::Future;
use std::net::SocketAddr;
use std::sync::Arc;
use std::time::Duration;

use foveal_engine::Simulation;
use foveal_proto::pb::foveal_server::FovealServer;
use tokio::net::TcpListener;
use tokio_stream::wrappers::TcpListenerStream;

mod auth;
pub mod cli;
mod clock;
pub mod compare;
pub mod config;
mod control;
mod convert;
pub mod error;
mod fanout;
mod fixation_cell;
mod frame_loop;
mod gate;
mod gaze;
mod limits;
mod metrics;
mod origin;
pub mod psych;
mod recorder;
mod service;
mod shutdown;
mod state;
mod summary;
pub mod telemetry;
mod transport;
mod watchdog;
mod web;

pub use auth::{MIN_TOKEN_LEN, Role, TokenError, Tokens};
pub use config::{Security, ServerConfig, TlsIdentity};
pub use error::ServerError;
pub use gaze::{MAX_BATCH_SAMPLES, MAX_SOURCE_BYTES};
pub use limits::{
    Limits, MAX_DENSITY, MAX_GAZE_STREAMS, MAX_HEALTH_WATCHES, MAX_HEALTH_WATCHES_PER_CONNECTION,
    MAX_REQUEST_BYTES, MAX_SUBSCRIBERS, MIN_DENSITY,
};
pub use origin::AllowedOrigin;
pub use transport::ConnectionLimits;

use frame_loop::FrameLoop;
use gate::{GateLayer, GateState};
use service::FovealService;
use state::{Scene, Shared};

/// The foveal service's name in the health registry.
const FOVEAL_SERVICE_NAME: &str = "foveal.v1.Foveal";

/// Refuse to serve an address other than loopback without tokens, unless told to.
fn check_exposure(addr: Option<SocketAddr>, security: &Security) -> Result<(), ServerError> {
    match addr {
        Some(a) if !a.ip().is_loopback() && security.tokens.is_empty() && !security.insecure => {
            Err(ServerError::Insecure {
                addr: a.to_string(),
            })
        }
        _ => Ok(()),
    }
}

/// Serve the foveal service (plus health and reflection v1/v1alpha) on `listener` until `shutdown`
/// resolves. Then: health turns NOT_SERVING, every new call answers UNAVAILABLE at once, open
/// StreamGaze calls end with their summary and WatchFrames streams end; once no call is in
/// progress (or after [`ServerConfig::shutdown_grace`]), connections still open, such as a
/// subscriber that stopped reading, are abandoned, and the frame loop thread is stopped and
/// joined.
pub async fn run(
    listener: TcpListener,
    config: ServerConfig,
    shutdown: impl Future<Output = ()>,
) -> Result<(), ServerError> {
    run_with_health(listener, None, config, shutdown).await
}

/// [`run`], and on `health` (if given) the standard health service alone, in plaintext and
/// without tokens, for probes that speak neither (Kubernetes' gRPC probe): it reports what the
/// main port's health does, NOT_SERVING through the shutdown's drain, and closes with it.
pub async fn run_with_health(
    listener: TcpListener,
    health_listener: Option<TcpListener>,
    config: ServerConfig,
    shutdown: impl Future<Output = ()>,
) -> Result<(), ServerError> {
    config.validate()?;
    let local = listener.local_addr().ok();
    check_exposure(local, &config.security)?;
    // Before the (possibly long) build: a file that cannot be written refuses start-up at once.
    let recorder = match &config.record {
        Some(path) => Some(Arc::new(recorder::Recorder::start(
            path,
            &recorder::header(&config),
        )?)),
        None => None,
    };
    let rate = config.frame_rate_hz;
    let sim_config = config.sim.clone();
    let compare = config.compare;
    // Scene generation and budget calibration can take seconds at large N: not on a worker.
    let (sim, scene, comparison) = tokio::task::spawn_blocking(move || {
        let sim = Simulation::new(sim_config)?;
        let comparison = compare::Comparison::new(compare, &sim)?;
        let scene = Scene::of(&sim, rate).with_compare(compare);
        Ok::<_, foveal_engine::ConfigError>((sim, scene, comparison))
    })
    .await??;
    let shared = Arc::new(
        Shared::new(scene, config.gaze_max_age, config.frame_buffer)
            .with_gaze_processing(config.gaze_processing)
            .with_recorder(recorder.clone()),
    );
    let frame_loop = FrameLoop::spawn(
        sim,
        comparison,
        Arc::clone(&shared),
        config.summary_interval,
    )?;
    let (trigger, stop) = shutdown::channel();
    let service = FovealService::new(
        Arc::clone(&shared),
        frame_loop.commands(),
        stop.clone(),
        config.limits,
    );
    let gate = GateState::new(config.security.tokens.clone(), stop.clone());

    let (health, health_service) = tonic_health::server::health_reporter();
    watchdog::set(&health, tonic_health::ServingStatus::Serving).await;
    let watchdog = tokio::spawn(watchdog::run(
        Arc::clone(&shared),
        health.clone(),
        config.stall_periods,
        stop.clone(),
    ));
    let (health_stop, health_stopped) = tokio::sync::oneshot::channel::<()>();
    let health_port = health_listener.map(|l| {
        if let Ok(a) = l.local_addr() {
            tracing::info!(addr = %a, "serving health alone in plaintext (--health-addr)");
        }
        let svc = health_service.clone();
        tokio::spawn(async move {
            let served = tonic::transport::Server::builder()
                .add_service(svc)
                .serve_with_incoming_shutdown(TcpListenerStream::new(l), async move {
                    // Err: run is returning either way.
                    let _ = health_stopped.await;
                })
                .await;
            if let Err(e) = served {
                tracing::error!(error = %e, "the health port failed");
            }
        })
    });
    let reflection = || {
        tonic_reflection::server::Builder::configure()
            .register_encoded_file_descriptor_set(foveal_proto::FILE_DESCRIPTOR_SET)
            .register_encoded_file_descriptor_set(tonic_health::pb::FILE_DESCRIPTOR_SET)
    };
    let reflection_v1 = reflection().build_v1()?;
    let reflection_v1alpha = reflection().build_v1alpha()?;

    let addr = local.map_or_else(|| "unknown".to_owned(), |a| a.to_string());
    tracing::info!(
        %addr,
        bodies = config.sim.scene.bodies,
        truth = config.sim.scene.truth.name(),
        scheduler = config.sim.scheduler.name(),
        budget = ?config.sim.budget,
        compare = config.compare.name(),
        frame_rate_hz = rate,
        tls = config.security.tls.is_some(),
        auth = if config.security.tokens.is_empty() { "open" } else { "tokens" },
        "serving"
    );
    if config.security.tokens.is_empty() && config.security.insecure {
        tracing::warn!(%addr, "serving without tokens on a non-loopback address (--insecure)");
    }
    let tls = match &config.security.tls {
        Some(identity) => Some(transport::tls_acceptor(identity)?),
        None => None,
    };
    let foveal = FovealServer::new(service).max_decoding_message_size(limits::MAX_REQUEST_BYTES);
    let routes = tonic::service::Routes::new(health_service)
        .add_service(reflection_v1)
        .add_service(reflection_v1alpha)
        .add_service(foveal)
        .prepare();
    // HTTP/1.1, grpc-web and the embedded page: the browser viewer on this port (see `web`). The
    // viewer layer is outermost, so the gate sees grpc-web calls as gRPC and its refusals reach a
    // browser as grpc-web errors.
    let service = tower::ServiceBuilder::new()
        .map_err(
            |e: std::convert::Infallible| -> Box<dyn std::error::Error + Send + Sync> {
                match e {}
            },
        )
        .layer(web::ViewerLayer::new(
            origin::Origins::new(config.security.allowed_origins.clone()),
            psych::Psych::new(
                psych::store::Store::new(
                    config.psych.results_dir.clone(),
                    psych::design::Designs {
                        dir: config.psych.designs_dir.clone(),
                    },
                    config.sim.display,
                ),
                config.security.tokens.clone(),
            ),
        ))
        .layer(GateLayer(Arc::clone(&gate)))
        .service(routes);
    let (drained_tx, drained_rx) = tokio::sync::oneshot::channel::<()>();
    // New connections keep being accepted while open calls drain, so that they are answered
    // UNAVAILABLE by the gate instead of waiting in the listen backlog.
    let server = transport::serve(
        listener,
        service,
        transport::Settings {
            limits: config.connections,
            tls,
            shutdown: stop.clone(),
        },
        async move {
            // Err: run is returning either way.
            let _ = drained_rx.await;
        },
    );
    let mut server = Box::pin(server);

    tokio::select! {
        () = &mut server => {}
        () = shutdown => {
            tracing::info!("shutting down");
            watchdog::set(&health, tonic_health::ServingStatus::NotServing).await;
            trigger.trigger();
            let drained = tokio::time::timeout(config.shutdown_grace, async {
                while gate.in_progress() > 0 {
                    tokio::time::sleep(Duration::from_millis(10)).await;
                }
            })
            .await;
            if drained.is_err() {
                tracing::warn!(
                    grace_s = config.shutdown_grace.as_secs_f64(),
                    in_progress = gate.in_progress(),
                    "calls still in progress after the shutdown grace period; abandoning them"
                );
            }
            // Err: the server already ended.
            let _ = drained_tx.send(());
            // Stops accepting, asks every connection to finish, and abandons the connections
            // still open after a short linger (a subscriber that stopped reading).
            server.await;
        }
    };
    // Err: the health port already ended.
    let _ = health_stop.send(());
    if let Some(h) = health_port
        && tokio::time::timeout(transport::SHUTDOWN_LINGER, h)
            .await
            .is_err()
    {
        tracing::info!("abandoning probes still connected to the health port");
    }
    trigger.trigger();
    watchdog.abort();
    let joined = tokio::task::spawn_blocking(move || {
        let joined = frame_loop.stop_and_join();
        // After the last frame: the trailer closes the session (Ctrl-C and SIGTERM end here too).
        if let Some(rec) = &recorder {
            rec.finish();
        }
        joined
    })
    .await?;
    tracing::info!("stopped");
    joined
}
