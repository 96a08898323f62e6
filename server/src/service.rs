//! The `foveal.v1.Foveal` gRPC service.
//!
//! Handlers are thin: they validate, touch the shared state, and talk to the loop through its
//! command channel. Nothing here ever waits on the loop except Configure, which waits for the
//! frame boundary where its new simulation takes over.

use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};
use std::sync::{Arc, mpsc};
use std::time::{Duration, Instant};

use foveal_engine::Simulation;
use foveal_gaze::validate::RejectKind;
use foveal_proto::pb;
use tokio::sync::oneshot;
use tokio_stream::wrappers::ReceiverStream;
use tonic::{Request, Response, Status};

use crate::auth::Caller;
use crate::compare::{Compare, Comparison};
use crate::control;
use crate::convert;
use crate::fanout;
use crate::fixation_cell::SourceKey;
use crate::frame_loop::{Command, Swap};
use crate::gaze::{self, GazeValidator};
use crate::limits::{self, Limits, PushLimiters, RateLimiter};
use crate::shutdown::Shutdown;
use crate::state::{Scene, Shared};

/// How long Configure waits for the loop to take over the new simulation: one frame at the slowest
/// rate plus a long step, with room to spare.
const SWAP_TIMEOUT: Duration = Duration::from_secs(30);

/// The service implementation.
#[derive(Debug)]
pub struct FovealService {
    shared: Arc<Shared>,
    commands: mpsc::Sender<Command>,
    shutdown: Shutdown,
    /// Configure calls are serialised so that each merges onto the configuration the previous one
    /// left, not onto a snapshot both read.
    configure: tokio::sync::Mutex<()>,
    limits: Limits,
    push_limiters: PushLimiters,
    gaze_streams: Arc<AtomicU32>,
    /// Numbers StreamGaze calls: each is its own gaze source.
    next_stream: AtomicU64,
}

/// One StreamGaze's place among [`limits::MAX_GAZE_STREAMS`]; given back on drop.
struct GazeStreamSlot(Arc<AtomicU32>);

impl Drop for GazeStreamSlot {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::AcqRel);
    }
}

impl FovealService {
    /// A service over the shared state, talking to the loop through `commands`, enforcing `limits`.
    pub fn new(
        shared: Arc<Shared>,
        commands: mpsc::Sender<Command>,
        shutdown: Shutdown,
        limits: Limits,
    ) -> Self {
        Self {
            shared,
            commands,
            shutdown,
            configure: tokio::sync::Mutex::new(()),
            limits,
            push_limiters: PushLimiters::default(),
            gaze_streams: Arc::new(AtomicU32::new(0)),
            next_stream: AtomicU64::new(0),
        }
    }

    /// Record samples about to be handed to the processing, at their receipt time on its clock.
    fn record_gaze<'a>(
        &self,
        samples: impl IntoIterator<Item = &'a foveal_gaze::GazeSample>,
        received: Instant,
        source: &SourceKey,
    ) {
        if let Some(rec) = &self.shared.recorder {
            let received_s = self.shared.fixation.seconds(received);
            let source = source.to_string();
            for s in samples {
                rec.gaze(s, received_s, &source);
            }
        }
    }
}

#[tonic::async_trait]
impl pb::foveal_server::Foveal for FovealService {
    async fn stream_gaze(
        &self,
        request: Request<tonic::Streaming<pb::GazeSample>>,
    ) -> Result<Response<pb::StreamGazeSummary>, Status> {
        let peer = request.remote_addr();
        let open = self.gaze_streams.fetch_add(1, Ordering::AcqRel);
        let _slot = GazeStreamSlot(Arc::clone(&self.gaze_streams));
        if open >= limits::MAX_GAZE_STREAMS {
            return Err(Status::resource_exhausted(format!(
                "the server already serves {} gaze streams (limit {}): close one or retry later",
                open,
                limits::MAX_GAZE_STREAMS
            )));
        }
        let mut stream = request.into_inner();
        let key = SourceKey::Stream(self.next_stream.fetch_add(1, Ordering::Relaxed));
        let mut validator = GazeValidator::new();
        let mut limiter = RateLimiter::new(self.limits.max_gaze_rate_hz, Instant::now());
        let mut rate_limited = 0u64;
        let mut shutdown = self.shutdown.clone();
        loop {
            let next = tokio::select! {
                _ = shutdown.wait() => break,
                next = stream.message() => next,
            };
            match next {
                Ok(Some(sample)) => {
                    let now = Instant::now();
                    if !limiter.allow(now) {
                        // Over the rate: dropped unread, counted, and the stream goes on.
                        validator.skip();
                        rate_limited += 1;
                        self.shared.metrics.gaze_limited(1);
                        continue;
                    }
                    let s = gaze::from_pb(&sample);
                    match validator.check(&s) {
                        Ok(()) => {
                            self.record_gaze([&s], now, &key);
                            self.shared.fixation.push(&key, [&s], now);
                            self.shared.metrics.gaze(1, 0);
                        }
                        Err(r) => {
                            if r.kind == RejectKind::Missing {
                                // A blink or track loss: not gaze, but the processing must know.
                                self.record_gaze([&s], now, &key);
                                self.shared.fixation.push(&key, [&s], now);
                            }
                            self.shared.metrics.gaze(0, 1);
                            tracing::debug!(?peer, field = r.field, reason = %r.reason, "gaze sample rejected");
                        }
                    }
                }
                Ok(None) => break,
                Err(status) => {
                    // The client vanished or sent garbage; what it sent before still counts.
                    tracing::info!(?peer, accepted = validator.accepted(), %status, "StreamGaze ended by the client side");
                    return Err(oversize_is_exhaustion(status));
                }
            }
        }
        if rate_limited > 0 {
            tracing::info!(
                ?peer,
                rate_limited,
                limit_hz = self.limits.max_gaze_rate_hz,
                "StreamGaze exceeded the gaze rate limit; samples over it were dropped"
            );
        }
        tracing::debug!(
            ?peer,
            accepted = validator.accepted(),
            rejected = validator.rejected(),
            rate_limited,
            "StreamGaze finished"
        );
        let mut summary = validator.into_summary();
        summary.rate_limited = rate_limited;
        Ok(Response::new(summary))
    }

    async fn push_gaze(
        &self,
        request: Request<pb::PushGazeRequest>,
    ) -> Result<Response<pb::PushGazeResponse>, Status> {
        let received = Instant::now();
        let peer = request.remote_addr();
        let req = request.into_inner();
        gaze::check_batch_size(req.samples.len())
            .and_then(|()| gaze::check_source(&req.source))
            .map_err(|e| Status::invalid_argument(format!("PushGazeRequest.{e}")))?;
        let admitted = self.push_limiters.admit(
            peer,
            req.samples.len(),
            self.limits.max_gaze_rate_hz,
            received,
        );
        // Over the rate limit, the oldest samples go: the newest are the gaze that steers now.
        let dropped = req.samples.len() - admitted;
        let rate_limited = dropped as u64;
        if rate_limited > 0 {
            self.shared.metrics.gaze_limited(rate_limited);
        }
        let mut validator = GazeValidator::new();
        for _ in 0..dropped {
            validator.skip();
        }
        // Every accepted sample (and every missing one, which marks track loss) goes through the
        // online processing in order, under one lock; samples over the rate limit are not read.
        let usable: Vec<_> = req.samples[dropped..]
            .iter()
            .map(gaze::from_pb)
            .filter(|sample| match validator.check(sample) {
                Ok(()) => true,
                Err(r) => r.kind == RejectKind::Missing,
            })
            .collect();
        if !usable.is_empty() {
            let key = SourceKey::Push(peer.map(|p| p.ip()), req.source.clone());
            self.record_gaze(&usable, received, &key);
            self.shared.fixation.push(&key, &usable, received);
        }
        self.shared
            .metrics
            .gaze(validator.accepted(), validator.rejected());
        if validator.rejected() > 0 {
            tracing::debug!(
                source = %req.source,
                accepted = validator.accepted(),
                rejected = validator.rejected(),
                "PushGaze batch had rejected samples"
            );
        }
        let mut response = validator.into_push_response();
        response.rate_limited = rate_limited;
        Ok(Response::new(response))
    }

    type WatchFramesStream = ReceiverStream<Result<pb::Frame, Status>>;

    async fn watch_frames(
        &self,
        request: Request<pb::WatchFramesRequest>,
    ) -> Result<Response<Self::WatchFramesStream>, Status> {
        if self.shutdown.is_triggered() {
            return Err(Status::unavailable("server is shutting down"));
        }
        let subscribers = self.shared.fanout.subscribers();
        if subscribers >= limits::MAX_SUBSCRIBERS {
            return Err(Status::resource_exhausted(format!(
                "the server already serves {subscribers} WatchFrames subscribers (limit {}): close one or retry later",
                limits::MAX_SUBSCRIBERS
            )));
        }
        let req = request.into_inner();
        let sub = self
            .shared
            .fanout
            .subscribe_to(req.every_k, fanout::Wants::of(&req));
        Ok(Response::new(fanout::into_stream(
            sub,
            self.shutdown.clone(),
        )))
    }

    async fn get_scene(
        &self,
        _request: Request<pb::GetSceneRequest>,
    ) -> Result<Response<pb::SceneDescription>, Status> {
        Ok(Response::new(self.shared.scene().description.clone()))
    }

    async fn configure(
        &self,
        request: Request<pb::ConfigureRequest>,
    ) -> Result<Response<pb::ConfigureResponse>, Status> {
        let peer = request.remote_addr();
        let caller = request.extensions().get::<Caller>().copied();
        let role = caller.map_or("open", |c| c.role_name());
        let inner = request.into_inner();
        let mask = inner.update_mask.map(|m| m.paths).unwrap_or_default();
        let req = inner.config.unwrap_or_default();
        let _serial = self.configure.lock().await;
        let current = self.shared.scene();
        let merged = if mask.is_empty() {
            convert::merge_scene_config(&current.sim, current.frame_rate_hz, &req)
        } else {
            convert::merge_masked(&current.sim, current.frame_rate_hz, &req, &mask)
        };
        let (config, rate, compare) = merged
            .and_then(|(config, rate)| {
                let compare = Compare::merge(current.compare, &req, &mask)?;
                compare.check(&config)?;
                self.limits.check(&config).map(|_| (config, rate, compare))
            })
            .map_err(|e| {
                tracing::info!(?peer, role, error = %e, "Configure refused");
                Status::invalid_argument(format!("ConfigureRequest.config: {e}"))
            })?;
        let changed = convert::changed_fields(
            &current.description.config.unwrap_or_default(),
            &pb::SceneConfig {
                compare: compare.to_pb() as i32,
                ..convert::scene_config_to_pb(&config, rate)
            },
        );
        // An empty change list is a restart of the same scene (admins use it to replay a run).
        tracing::info!(?peer, role, changed = ?changed, "Configure accepted");
        // Building can take long (scene generation, calibration of fraction-of-exact budgets):
        // do it on the blocking pool so neither the loop nor the async workers wait for it.
        let built = tokio::task::spawn_blocking(move || {
            let sim = Simulation::new(config)?;
            let comparison = Comparison::new(compare, &sim)?;
            let scene = Arc::new(Scene::of(&sim, rate).with_compare(compare));
            Ok::<_, foveal_engine::ConfigError>((sim, scene, comparison))
        })
        .await
        .map_err(|e| Status::internal(format!("building the simulation failed: {e}")))?;
        let (sim, scene, comparison) =
            built.map_err(|e| Status::invalid_argument(format!("ConfigureRequest.config: {e}")))?;
        let applied = scene.description.config;
        let (reply, first) = oneshot::channel();
        self.commands
            .send(Command::Swap(Box::new(Swap {
                sim,
                comparison,
                scene,
                reply,
            })))
            .map_err(|_| Status::unavailable("the frame loop is not running"))?;
        let first_frame_index = tokio::time::timeout(SWAP_TIMEOUT, first)
            .await
            .map_err(|_| {
                Status::deadline_exceeded("the frame loop did not reach a frame boundary in time")
            })?
            .map_err(|_| Status::unavailable("the frame loop stopped before the swap"))?;
        Ok(Response::new(pb::ConfigureResponse {
            applied,
            first_frame_index,
        }))
    }

    async fn get_status(
        &self,
        _request: Request<pb::GetStatusRequest>,
    ) -> Result<Response<pb::Status>, Status> {
        let s = &self.shared;
        let m = &s.metrics;
        let scene = s.scene();
        Ok(Response::new(pb::Status {
            uptime_s: s.started.elapsed().as_secs_f64(),
            frames: m.frames(),
            fps: m.fps(Instant::now()),
            subscribers: s.fanout.subscribers(),
            gaze_samples_accepted: m.gaze_accepted(),
            gaze_samples_rejected: m.gaze_rejected(),
            gaze_rate_hz: m.gaze_rate_hz(),
            last_fixation: m.last_fixation(),
            config: scene.description.config,
            gaze_samples_rate_limited: m.gaze_rate_limited(),
            gaze_sources_live: s.fixation.live_sources(Instant::now(), s.gaze_max_age) as u32,
            paused: s.paused(),
        }))
    }

    async fn pause(
        &self,
        request: Request<pb::PauseRequest>,
    ) -> Result<Response<pb::LoopState>, Status> {
        control::log_call("Pause", &request);
        control::pause(&self.commands).await.map(Response::new)
    }

    async fn resume(
        &self,
        request: Request<pb::ResumeRequest>,
    ) -> Result<Response<pb::LoopState>, Status> {
        control::log_call("Resume", &request);
        control::resume(&self.commands).await.map(Response::new)
    }

    async fn step(
        &self,
        request: Request<pb::StepRequest>,
    ) -> Result<Response<pb::LoopState>, Status> {
        control::log_call("Step", &request);
        let frames = request.into_inner().frames;
        control::step(&self.commands, frames)
            .await
            .map(Response::new)
    }

    async fn restart(
        &self,
        request: Request<pb::RestartRequest>,
    ) -> Result<Response<pb::ConfigureResponse>, Status> {
        // A Configure of the seed alone (or of nothing: the same scene again), with the caller's
        // metadata and extensions, so that it is checked, logged and applied as one.
        let (metadata, extensions, req) = request.into_parts();
        self.configure(Request::from_parts(
            metadata,
            extensions,
            control::restart_request(req.seed),
        ))
        .await
    }

    async fn inspect_body(
        &self,
        request: Request<pb::InspectBodyRequest>,
    ) -> Result<Response<pb::BodyInspection>, Status> {
        let body = request.into_inner().body;
        let bodies = self.shared.scene().sim.scene.bodies;
        control::inspect(&self.commands, body, bodies)
            .await
            .map(Response::new)
    }
}

/// tonic's codec refuses an oversize message with OUT_OF_RANGE; gRPC's convention (and what
/// clients treat as "too big") is RESOURCE_EXHAUSTED.
fn oversize_is_exhaustion(status: Status) -> Status {
    if status.code() == tonic::Code::OutOfRange && status.message().contains("too large") {
        Status::resource_exhausted(format!(
            "a message is larger than the server's limit of {} bytes: {}",
            limits::MAX_REQUEST_BYTES,
            status.message()
        ))
    } else {
        status
    }
}
