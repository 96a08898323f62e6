//! The `foveal.v1.Foveal` gRPC service.
//!
//! Handlers are thin: they validate, touch the shared state, and talk to the loop through its
//! command channel. Nothing here ever waits on the loop except Configure, which waits for the
//! frame boundary where its new simulation takes over.

use std::sync::{Arc, mpsc};
use std::time::{Duration, Instant};

use foveal_engine::Simulation;
use foveal_gaze::validate::RejectKind;
use foveal_proto::pb;
use tokio::sync::oneshot;
use tokio_stream::wrappers::ReceiverStream;
use tonic::{Request, Response, Status};

use crate::convert;
use crate::fanout;
use crate::frame_loop::{Command, Swap};
use crate::gaze::{self, GazeValidator};
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
}

impl FovealService {
    /// A service over the shared state, talking to the loop through `commands`.
    pub fn new(shared: Arc<Shared>, commands: mpsc::Sender<Command>, shutdown: Shutdown) -> Self {
        Self {
            shared,
            commands,
            shutdown,
            configure: tokio::sync::Mutex::new(()),
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
        let mut stream = request.into_inner();
        let mut validator = GazeValidator::new();
        let mut shutdown = self.shutdown.clone();
        loop {
            let next = tokio::select! {
                _ = shutdown.wait() => break,
                next = stream.message() => next,
            };
            match next {
                Ok(Some(sample)) => match validator.check(&sample) {
                    Ok(_) => {
                        let s = gaze::from_pb(&sample);
                        self.shared.fixation.push([&s], Instant::now());
                        self.shared.metrics.gaze(1, 0);
                    }
                    Err(r) => {
                        if r.kind == RejectKind::Missing {
                            // A blink or track loss: not gaze, but the processing must know.
                            let s = gaze::from_pb(&sample);
                            self.shared.fixation.push([&s], Instant::now());
                        }
                        self.shared.metrics.gaze(0, 1);
                        tracing::debug!(?peer, field = r.field, reason = %r.reason, "gaze sample rejected");
                    }
                },
                Ok(None) => break,
                Err(status) => {
                    // The client vanished or sent garbage; what it sent before still counts.
                    tracing::info!(?peer, accepted = validator.accepted(), %status, "StreamGaze ended by the client side");
                    return Err(status);
                }
            }
        }
        tracing::debug!(
            ?peer,
            accepted = validator.accepted(),
            rejected = validator.rejected(),
            "StreamGaze finished"
        );
        Ok(Response::new(validator.into_summary()))
    }

    async fn push_gaze(
        &self,
        request: Request<pb::PushGazeRequest>,
    ) -> Result<Response<pb::PushGazeResponse>, Status> {
        let received = Instant::now();
        let req = request.into_inner();
        gaze::check_batch_size(req.samples.len()).map_err(Status::invalid_argument)?;
        let mut validator = GazeValidator::new();
        // Every accepted sample (and every missing one, which marks track loss) goes through the
        // online processing in order, under one lock.
        let usable: Vec<_> = req
            .samples
            .iter()
            .filter(|sample| match validator.check(sample) {
                Ok(_) => true,
                Err(r) => r.kind == RejectKind::Missing,
            })
            .map(gaze::from_pb)
            .collect();
        if !usable.is_empty() {
            self.shared.fixation.push(&usable, received);
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
        Ok(Response::new(validator.into_push_response()))
    }

    type WatchFramesStream = ReceiverStream<Result<pb::Frame, Status>>;

    async fn watch_frames(
        &self,
        request: Request<pb::WatchFramesRequest>,
    ) -> Result<Response<Self::WatchFramesStream>, Status> {
        if self.shutdown.is_triggered() {
            return Err(Status::unavailable("server is shutting down"));
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
        let req = request.into_inner().config.unwrap_or_default();
        let _serial = self.configure.lock().await;
        let current = self.shared.scene();
        let (config, rate) = convert::merge_scene_config(&current.sim, current.frame_rate_hz, &req)
            .map_err(|e| Status::invalid_argument(format!("ConfigureRequest.config: {e}")))?;
        // Building can take long (scene generation, calibration of fraction-of-exact budgets):
        // do it on the blocking pool so neither the loop nor the async workers wait for it.
        let built = tokio::task::spawn_blocking(move || {
            Simulation::new(config).map(|sim| {
                let scene = Arc::new(Scene::of(&sim, rate));
                (sim, scene)
            })
        })
        .await
        .map_err(|e| Status::internal(format!("building the simulation failed: {e}")))?;
        let (sim, scene) =
            built.map_err(|e| Status::invalid_argument(format!("ConfigureRequest.config: {e}")))?;
        let applied = scene.description.config;
        let (reply, first) = oneshot::channel();
        self.commands
            .send(Command::Swap(Box::new(Swap { sim, scene, reply })))
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
            fps: m.fps(),
            subscribers: s.fanout.subscribers(),
            gaze_samples_accepted: m.gaze_accepted(),
            gaze_samples_rejected: m.gaze_rejected(),
            gaze_rate_hz: m.gaze_rate_hz(),
            last_fixation: m.last_fixation(),
            config: scene.description.config,
        }))
    }
}
