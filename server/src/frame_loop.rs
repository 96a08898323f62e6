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
        shared: Arc<Shared>,
        summary_interval: Duration,
    ) -> Result<Self, ServerError> {
        let (commands, rx) = mpsc::channel();
        let thread = std::thread::Builder::new()
            .name("foveal-frame-loop".into())
            .spawn(move || run(sim, &shared, &rx, summary_interval))
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

/// Whether the loop should keep going after handling a command.
fn handle(
    cmd: Command,
    sim: &mut Simulation,
    offset: &mut u64,
    period: &mut Duration,
    shared: &Shared,
) -> bool {
    match cmd {
        Command::Stop => false,
        Command::Swap(swap) => {
            let Swap {
                sim: new,
                scene,
                reply,
            } = *swap;
            *sim = new;
            // The new simulation counts its frames from 0; the protocol's index keeps counting.
            *offset = shared.metrics.frames();
            *period = frame_period(scene.frame_rate_hz);
            tracing::info!(
                first_frame = *offset,
                bodies = scene.sim.scene.bodies,
                scheduler = scene.sim.scheduler.name(),
                budget = ?scene.sim.budget,
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
    mut sim: Simulation,
    shared: &Shared,
    commands: &mpsc::Receiver<Command>,
    summary_interval: Duration,
) {
    let clock = InstantClock::new();
    let mut period = frame_period(shared.scene().frame_rate_hz);
    let mut offset = 0u64;
    let mut summary = Summary::new(summary_interval, Instant::now(), &shared.metrics);
    let mut deadline = Instant::now();
    tracing::info!(period_ms = period.as_secs_f64() * 1e3, "frame loop started");
    'frames: loop {
        // Wait for the deadline, serving commands meanwhile; with the deadline already past, only
        // drain what is pending. A simulation with a pool stops waiting POOL_WARM early and keeps
        // its pool busy until the deadline (see `Simulation::warm_pool_until`).
        let warm = if sim.config().threads > 1 {
            POOL_WARM
        } else {
            Duration::ZERO
        };
        loop {
            let wait = deadline
                .checked_sub(warm)
                .unwrap_or(deadline)
                .saturating_duration_since(Instant::now());
            let cmd = if wait.is_zero() {
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
            if !handle(cmd, &mut sim, &mut offset, &mut period, shared) {
                break 'frames;
            }
        }

        let left = deadline.saturating_duration_since(Instant::now());
        if !left.is_zero() {
            let until = clock.now_ns().saturating_add(left.as_nanos() as u64);
            sim.warm_pool_until(&clock, until);
        }
        let start = Instant::now();
        let resolved = shared.fixation.resolve(start, shared.gaze_max_age);
        let report = sim.step(Some(resolved.fixation), &clock);
        let step = start.elapsed();
        // The frame reports what the step used (the engine's record), not what was handed in.
        let used = convert::fixation_used(report, &resolved);
        let frame = convert::frame_to_pb(report, offset + report.index, &used);
        summary.record(report, step);
        if let Some(rec) = &shared.recorder {
            let t_s = shared.fixation.seconds(start);
            rec.frame(offset + report.index, t_s, &resolved, report);
        }
        let poses = shared
            .fanout
            .wants_poses()
            .then(|| Arc::new(convert::poses(&sim)));
        let quantised_poses = shared
            .fanout
            .wants_quantised_poses()
            .then(|| Arc::new(convert::quantised_poses(&sim)));
        let collisions = shared
            .fanout
            .wants_collisions()
            .then(|| Arc::new(convert::collisions(&sim)));
        let end = Instant::now();
        shared.metrics.frame_done(used, end);
        shared.fanout.publish(FrameMsg {
            frame,
            poses,
            quantised_poses,
            collisions,
        });

        deadline += period;
        if end > deadline {
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
        let lp = FrameLoop::spawn(sim, Arc::clone(&shared), Duration::from_secs(1)).expect("spawn");
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
