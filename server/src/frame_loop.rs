//! The frame loop: one OS thread that steps the simulation at a fixed rate.
//!
//! It runs on its own thread, never on an async worker, because a step is long, CPU-bound,
//! non-yielding work that would stall every connection sharing the worker. Pacing sleeps until
//! the next deadline; a frame that ends past its deadline is counted as an overrun and the next
//! one starts at once on a fresh grid, without a burst of catch-up frames (catching up would
//! make every later frame late too, and a frame is about *now*).
//!
//! The thread waits on its command channel with a timeout, so a swap or a stop is picked up at
//! the next frame boundary without polling. New simulations are built elsewhere and handed over
//! whole; the loop never pauses to build one.

use std::sync::Arc;
use std::sync::mpsc::{self, RecvTimeoutError};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use foveal_engine::Simulation;
use tokio::sync::oneshot;

use crate::clock::InstantClock;
use crate::compare::Comparison;
use crate::config::frame_period;
use crate::convert;
use crate::error::ServerError;
use crate::fanout::FrameMsg;
use crate::state::{Scene, Shared};
use crate::summary::Summary;
use foveal_engine::Clock;

/// A new simulation to run from the next frame boundary.
#[derive(Debug)]
pub struct Swap {
    /// The simulation, already built and validated.
    pub sim: Simulation,
    /// Its side by side's second collider, if the scene asks for one.
    pub comparison: Option<Comparison>,
    /// Its description (and the frame rate to run it at).
    pub scene: Arc<Scene>,
    /// Receives the global index of the first frame simulated with it.
    pub reply: oneshot::Sender<u64>,
}

/// What the loop can be told.
#[derive(Debug)]
pub enum Command {
    /// Replace the simulation at the next frame boundary.
    Swap(Box<Swap>),
    /// Finish the current frame and exit.
    Stop,
    /// Stop simulating at the next frame boundary until Resume (or Step); answers the state.
    Pause(oneshot::Sender<LoopState>),
    /// Simulate at the frame rate again from now; answers the state.
    Resume(oneshot::Sender<LoopState>),
    /// Simulate this many frames of a paused loop back to back, then answer (Err: the loop runs).
    Step(u32, oneshot::Sender<Result<LoopState, StepRefused>>),
    /// Answer a body's candidate pairs in the latest frame (by body id).
    Inspect(u32, oneshot::Sender<Inspection>),
}

/// The loop's state as a control call answers it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LoopState {
    /// Whether the loop is paused.
    pub paused: bool,
    /// Frames simulated since the server started.
    pub frames: u64,
}

/// Step asked of a loop that is not paused.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct StepRefused;

/// A body's candidate pairs in the latest frame, as InspectBody answers them.
#[derive(Debug, Clone, PartialEq)]
pub struct Inspection {
    /// The frame's protocol index (0 before any frame of the scene: nothing to inspect).
    pub frame_index: u64,
    /// Bodies in the scene.
    pub bodies: u32,
    /// The body's pairs, by the other body's id.
    pub pairs: Vec<foveal_proto::pb::PairInspection>,
    /// How many pairs the body had in all.
    pub pairs_total: u32,
}

/// The most pairs an inspection lists.
pub const MAX_INSPECTED_PAIRS: usize = 256;

/// The pause state and the steps owed, kept by the loop.
#[derive(Debug, Default)]
struct Control {
    paused: bool,
    steps_left: u32,
    step_reply: Option<oneshot::Sender<Result<LoopState, StepRefused>>>,
}

/// The running loop thread.
#[derive(Debug)]
pub struct FrameLoop {
    commands: mpsc::Sender<Command>,
    thread: Option<JoinHandle<()>>,
}

impl FrameLoop {
    /// Start the loop thread on `sim`.
    pub fn spawn(
        sim: Simulation,
        comparison: Option<Comparison>,
        shared: Arc<Shared>,
        summary_interval: Duration,
    ) -> Result<Self, ServerError> {
        let (commands, rx) = mpsc::channel();
        let thread = std::thread::Builder::new()
            .name("foveal-frame-loop".into())
            .spawn(move || {
                let mut running = Running { sim, comparison };
                run(&mut running, &shared, &rx, summary_interval);
            })
            .map_err(ServerError::SpawnLoop)?;
        Ok(Self {
            commands,
            thread: Some(thread),
        })
    }

    /// A handle for sending commands from other threads.
    pub fn commands(&self) -> mpsc::Sender<Command> {
        self.commands.clone()
    }

    /// Stop the loop and wait for the thread (blocking: call from a blocking context).
    pub fn stop_and_join(mut self) -> Result<(), ServerError> {
        // Err: the thread is already gone; joining tells us how.
        let _ = self.commands.send(Command::Stop);
        match self.thread.take().map(JoinHandle::join) {
            Some(Err(panic)) => Err(ServerError::LoopPanicked(panic_message(&*panic))),
            _ => Ok(()),
        }
    }
}

fn panic_message(panic: &(dyn std::any::Any + Send)) -> String {
    panic
        .downcast_ref::<&str>()
        .map(|s| (*s).to_owned())
        .or_else(|| panic.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "unknown panic".into())
}

fn state(control: &Control, shared: &Shared) -> LoopState {
    LoopState {
        paused: control.paused,
        frames: shared.metrics.frames(),
    }
}

/// The pairs of body `body` (an id) in `sim`'s latest frame.
pub fn inspect(sim: &Simulation, body: u32, frame_index: u64) -> Inspection {
    use foveal_engine::narrow_phase::PairStatus;
    use foveal_proto::pb;
    let priorities = sim.priorities();
    let mut pairs: Vec<pb::PairInspection> = Vec::new();
    let mut total = 0u32;
    for (i, p) in sim.pairs().iter().enumerate() {
        let (a, b) = sim.id_pair((p.a, p.b));
        if a != body && b != body {
            continue;
        }
        total += 1;
        // Levels are by slot order of the engine's pair: the one of the slot holding `body`.
        let mine = usize::from(sim.body_ids()[p.a as usize] != body);
        let status = match p.status {
            PairStatus::Untested => pb::PairStatus::Untested,
            PairStatus::Active => pb::PairStatus::Active,
            PairStatus::Colliding => pb::PairStatus::Colliding,
            PairStatus::Separate => pb::PairStatus::Separate,
            PairStatus::Deemed => pb::PairStatus::Deemed,
        };
        pairs.push(pb::PairInspection {
            other: if a == body { b } else { a },
            status: status as i32,
            level: u32::from(p.levels[mine]),
            other_level: u32::from(p.levels[1 - mine]),
            resolved_level: u32::from(p.resolved_level),
            priority: f64::from(priorities.weight(i)),
            foveal: priorities.inner(i),
        });
    }
    pairs.sort_by_key(|p| p.other);
    pairs.truncate(MAX_INSPECTED_PAIRS);
    Inspection {
        frame_index,
        bodies: sim.world().len() as u32,
        pairs,
        pairs_total: total,
    }
}

/// What the loop runs: the simulation and the side by side's second collider.
#[derive(Debug)]
struct Running {
    sim: Simulation,
    comparison: Option<Comparison>,
}

/// Whether the loop should keep going after handling a command.
fn handle(
    cmd: Command,
    running: &mut Running,
    offset: &mut u64,
    period: &mut Duration,
    control: &mut Control,
    shared: &Shared,
) -> bool {
    match cmd {
        Command::Stop => false,
        Command::Pause(reply) => {
            if !control.paused {
                control.paused = true;
                shared.set_paused(true);
                tracing::info!(frames = shared.metrics.frames(), "frame loop paused");
            }
            // Err: the caller gave up waiting; the pause stands regardless.
            let _ = reply.send(state(control, shared));
            true
        }
        Command::Resume(reply) => {
            if control.paused {
                control.paused = false;
                shared.set_paused(false);
                tracing::info!(frames = shared.metrics.frames(), "frame loop resumed");
            }
            let _ = reply.send(state(control, shared));
            true
        }
        Command::Step(frames, reply) => {
            if !control.paused || control.step_reply.is_some() {
                let _ = reply.send(Err(StepRefused));
            } else if frames == 0 {
                let _ = reply.send(Ok(state(control, shared)));
            } else {
                control.steps_left = frames;
                control.step_reply = Some(reply);
            }
            true
        }
        Command::Inspect(body, reply) => {
            let sim = &running.sim;
            let index = if shared.metrics.frames() > *offset {
                *offset + sim.last_report().index
            } else {
                0
            };
            let _ = reply.send(inspect(sim, body, index));
            true
        }
        Command::Swap(swap) => {
            let Swap {
                sim: new,
                comparison,
                scene,
                reply,
            } = *swap;
            *running = Running {
                sim: new,
                comparison,
            };
            // The new simulation counts its frames from 0; the protocol's index keeps counting.
            *offset = shared.metrics.frames();
            *period = frame_period(scene.frame_rate_hz);
            tracing::info!(
                first_frame = *offset,
                bodies = scene.sim.scene.bodies,
                scheduler = scene.sim.scheduler.name(),
                budget = ?scene.sim.budget,
                compare = scene.compare.name(),
                frame_rate_hz = scene.frame_rate_hz,
                "scene swapped"
            );
            if let Some(rec) = &shared.recorder {
                rec.scene(*offset, scene.frame_rate_hz, &scene.sim);
            }
            shared.set_scene(scene);
            // Err: the caller gave up waiting; the swap stands regardless.
            let _ = reply.send(*offset);
            true
        }
    }
}

/// How long before each frame's deadline the loop keeps a simulation's pool busy instead of
/// asleep: the threads of a pool that slept through the pause between frames (and the processors
/// under them) woke slowly enough to make a paced 10,000-body exact frame on two threads up to
/// twice as slow as a back-to-back one. 200 us of spinning a thread a frame (1.2% of a core at
/// 60 Hz) recovered most of it; longer did no better (docs/BENCHMARKS.md).
const POOL_WARM: Duration = Duration::from_micros(200);

fn run(
    running: &mut Running,
    shared: &Shared,
    commands: &mpsc::Receiver<Command>,
    summary_interval: Duration,
) {
    let clock = InstantClock::new();
    let mut period = frame_period(shared.scene().frame_rate_hz);
    let mut offset = 0u64;
    let mut summary = Summary::new(summary_interval, Instant::now(), &shared.metrics);
    let mut deadline = Instant::now();
    let mut control = Control::default();
    tracing::info!(period_ms = period.as_secs_f64() * 1e3, "frame loop started");
    'frames: loop {
        // Paused with no step owed: wait for commands only; the next frame after a Resume starts
        // at once and is paced from there.
        while control.paused && control.steps_left == 0 {
            let Ok(cmd) = commands.recv() else {
                break 'frames;
            };
            if !handle(cmd, running, &mut offset, &mut period, &mut control, shared) {
                break 'frames;
            }
            deadline = Instant::now();
        }
        let stepping = control.steps_left > 0;
        // Wait for the deadline, serving commands meanwhile; with the deadline already past, only
        // drain what is pending. A simulation with a pool stops waiting POOL_WARM early and keeps
        // its pool busy until the deadline (see `Simulation::warm_pool_until`).
        let warm = if running.sim.config().threads > 1 {
            POOL_WARM
        } else {
            Duration::ZERO
        };
        loop {
            let wait = deadline
                .checked_sub(warm)
                .unwrap_or(deadline)
                .saturating_duration_since(Instant::now());
            let cmd = if wait.is_zero() || stepping {
                match commands.try_recv() {
                    Ok(cmd) => cmd,
                    Err(mpsc::TryRecvError::Empty) => break,
                    Err(mpsc::TryRecvError::Disconnected) => break 'frames,
                }
            } else {
                match commands.recv_timeout(wait) {
                    Ok(cmd) => cmd,
                    Err(RecvTimeoutError::Timeout) => break,
                    Err(RecvTimeoutError::Disconnected) => break 'frames,
                }
            };
            if !handle(cmd, running, &mut offset, &mut period, &mut control, shared) {
                break 'frames;
            }
        }
        if control.paused && control.steps_left == 0 {
            // Paused while waiting for this frame's deadline.
            continue 'frames;
        }

        let left = deadline.saturating_duration_since(Instant::now());
        if !left.is_zero() && !stepping {
            let until = clock.now_ns().saturating_add(left.as_nanos() as u64);
            running.sim.warm_pool_until(&clock, until);
        }
        let start = Instant::now();
        let resolved = shared.fixation.resolve(start, shared.gaze_max_age);
        let Running { sim, comparison } = running;
        sim.step(Some(resolved.fixation), &clock);
        let step = start.elapsed();
        let report = sim.last_report();
        // The frame reports what the step used (the engine's record), not what was handed in.
        let used = convert::fixation_used(report, &resolved);
        let mut frame = convert::frame_to_pb(report, offset + report.index, &used);
        summary.record(report, step);
        if let Some(c) = comparison.as_mut() {
            let out = c.run(sim, report, &clock);
            summary.record_comparison(&out.audit, out.run_ns);
            frame.comparison = Some(convert::comparison_to_pb(c.kind(), &out));
        }
        let compared = comparison.as_ref();
        if let Some(rec) = &shared.recorder {
            let t_s = shared.fixation.seconds(start);
            rec.frame(offset + report.index, t_s, &resolved, report);
        }
        let poses = shared
            .fanout
            .wants_poses()
            .then(|| Arc::new(convert::poses(sim)));
        let quantised_poses = shared
            .fanout
            .wants_quantised_poses()
            .then(|| Arc::new(convert::quantised_poses(sim)));
        let wants_collisions = shared.fanout.wants_collisions();
        let collisions = wants_collisions.then(|| {
            let paired = compared.map(crate::compare::Comparison::main_truth);
            Arc::new(convert::collisions(sim, paired))
        });
        let comparison_collisions = compared
            .filter(|_| wants_collisions)
            .map(|c| Arc::new(c.collisions(sim)));
        let end = Instant::now();
        shared.metrics.frame_done(used, end);
        shared.fanout.publish(FrameMsg {
            frame,
            poses,
            quantised_poses,
            collisions,
            comparison_collisions,
            stepped: stepping,
        });

        if control.steps_left > 0 {
            control.steps_left -= 1;
            if control.steps_left == 0
                && let Some(reply) = control.step_reply.take()
            {
                // Err: the caller gave up waiting; the frames were simulated regardless.
                let _ = reply.send(Ok(state(&control, shared)));
            }
        }
        deadline += period;
        if stepping {
            deadline = end;
        } else if end > deadline {
            shared.metrics.overrun();
            tracing::debug!(
                late_ms = (end - deadline).as_secs_f64() * 1e3,
                "frame overran its period"
            );
            deadline = end;
        }
        summary.flush_if_due(end, &shared.metrics, shared.fanout.subscribers());
    }
    tracing::info!(frames = shared.metrics.frames(), "frame loop stopped");
}

#[cfg(test)]
mod tests {
    use super::*;
    use foveal_engine::SimConfig;

    fn small() -> (Simulation, Arc<Shared>) {
        let mut c = SimConfig::default();
        c.scene.bodies = 50;
        let sim = Simulation::new(c).expect("valid");
        let shared = Arc::new(Shared::new(
            Scene::of(&sim, 200.0),
            Duration::from_millis(500),
            8,
        ));
        (sim, shared)
    }

    #[test]
    fn runs_at_its_rate_swaps_and_stops() {
        let (sim, shared) = small();
        let lp = FrameLoop::spawn(sim, None, Arc::clone(&shared), Duration::from_secs(1))
            .expect("spawn");
        std::thread::sleep(Duration::from_millis(200));
        let frames = shared.metrics.frames();
        // 200 Hz for 0.2 s is 40 frames; allow a loaded machine plenty of slack, but no bursts.
        assert!((5..=45).contains(&frames), "{frames}");

        let mut c = SimConfig::default();
        c.scene.bodies = 30;
        let new = Simulation::new(c).expect("valid");
        let scene = Arc::new(Scene::of(&new, 100.0));
        let (reply, rx) = oneshot::channel();
        lp.commands()
            .send(Command::Swap(Box::new(Swap {
                sim: new,
                comparison: None,
                scene,
                reply,
            })))
            .expect("loop alive");
        let first = rx.blocking_recv().expect("swap acknowledged");
        assert!(first >= frames);
        assert_eq!(shared.scene().sim.scene.bodies, 30);
        lp.stop_and_join().expect("clean stop");
        let after = shared.metrics.frames();
        std::thread::sleep(Duration::from_millis(50));
        assert_eq!(shared.metrics.frames(), after, "stopped");
    }
}
