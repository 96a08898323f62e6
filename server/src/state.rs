//! State shared between the service handlers and the frame loop.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, PoisonError, RwLock};
use std::time::{Duration, Instant};

use foveal_engine::{SimConfig, Simulation};
use foveal_proto::pb;

use crate::compare::Compare;
use crate::convert;
use crate::fanout::Fanout;
use crate::fixation_cell::FixationCell;
use crate::metrics::Metrics;
use crate::recorder::Recorder;

/// The scene in force: its configuration and everything GetScene reports. Replaced as a whole
/// when the loop swaps simulations, so readers always see one consistent scene.
#[derive(Debug)]
pub struct Scene {
    /// Engine configuration.
    pub sim: SimConfig,
    /// Frame rate of the loop (frames per second).
    pub frame_rate_hz: f64,
    /// GetScene's answer.
    pub description: pb::SceneDescription,
    /// The side by side's second collider, if any (`SceneConfig.compare`).
    pub compare: Compare,
}

impl Scene {
    /// Describe a freshly built simulation.
    pub fn of(sim: &Simulation, frame_rate_hz: f64) -> Self {
        Self {
            sim: sim.config().clone(),
            frame_rate_hz,
            description: convert::scene_description(sim, frame_rate_hz),
            compare: Compare::Off,
        }
    }

    /// The same scene with the side by side set to `compare` (GetScene reports it).
    #[must_use]
    pub fn with_compare(mut self, compare: Compare) -> Self {
        self.compare = compare;
        if let Some(c) = self.description.config.as_mut() {
            c.compare = compare.to_pb() as i32;
        }
        self
    }
}

/// Everything the handlers and the loop share.
#[derive(Debug)]
pub struct Shared {
    /// When the server started (uptime).
    pub started: Instant,
    /// Gaze older than this falls back to the screen centre.
    pub gaze_max_age: Duration,
    /// Latest accepted gaze.
    pub fixation: FixationCell,
    /// Counters.
    pub metrics: Metrics,
    /// Frames out.
    pub fanout: Arc<Fanout>,
    /// The session recording (`--record`), if any.
    pub recorder: Option<Arc<Recorder>>,
    scene: RwLock<Arc<Scene>>,
    /// Whether the loop is paused (Pause), and when it last resumed: a paused loop is not a
    /// stalled one, and the watchdog counts a resumed loop's silence from its resumption.
    paused: AtomicBool,
    resumed_at: Mutex<Option<Instant>>,
}

impl Shared {
    /// State for a server starting with `scene`.
    pub fn new(scene: Scene, gaze_max_age: Duration, frame_buffer: usize) -> Self {
        Self {
            started: Instant::now(),
            gaze_max_age,
            fixation: FixationCell::new(),
            metrics: Metrics::default(),
            fanout: Arc::new(Fanout::new(frame_buffer)),
            recorder: None,
            scene: RwLock::new(Arc::new(scene)),
            paused: AtomicBool::new(false),
            resumed_at: Mutex::new(None),
        }
    }

    /// The same state with this online gaze processing (assumed valid).
    #[must_use]
    pub fn with_gaze_processing(mut self, config: foveal_gaze::online::ProcessorConfig) -> Self {
        self.fixation = FixationCell::with_config(config);
        self
    }

    /// The same state recording the session through `recorder`.
    #[must_use]
    pub fn with_recorder(mut self, recorder: Option<Arc<Recorder>>) -> Self {
        self.recorder = recorder;
        self
    }

    /// The scene in force.
    pub fn scene(&self) -> Arc<Scene> {
        Arc::clone(&self.scene.read().unwrap_or_else(PoisonError::into_inner))
    }

    /// Whether the loop is paused.
    pub fn paused(&self) -> bool {
        self.paused.load(Ordering::Acquire)
    }

    /// When the loop last resumed from a pause, if it ever did.
    pub fn resumed_at(&self) -> Option<Instant> {
        *self
            .resumed_at
            .lock()
            .unwrap_or_else(PoisonError::into_inner)
    }

    /// Record that the loop paused or resumed (called by the loop).
    pub fn set_paused(&self, paused: bool) {
        if !paused {
            *self
                .resumed_at
                .lock()
                .unwrap_or_else(PoisonError::into_inner) = Some(Instant::now());
        }
        self.paused.store(paused, Ordering::Release);
    }

    /// Replace the scene (called by the loop at the frame boundary where it swaps simulations).
    /// The gaze processing measures degrees on the new scene's display from then on.
    pub fn set_scene(&self, scene: Arc<Scene>) {
        self.fixation
            .set_geometry(crate::fixation_cell::viewing_geometry(&scene.sim.display));
        *self.scene.write().unwrap_or_else(PoisonError::into_inner) = scene;
    }
}
