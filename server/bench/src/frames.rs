//! Exact frames of the paper scene and nothing else: the run a profiler wraps.
//!
//! Instruction counts (`valgrind --tool=cachegrind`) of a steady frame are the difference of
//! two runs of different lengths divided by the frames between them, so that start-up (scene,
//! trees, calibration) cancels out. `foveal-bench frames` is that run: it builds the scene,
//! steps `frames` exact frames on a frozen clock (no wall-clock reads that a profiler would
//! count) and prints what the last frame did, so the two runs can be checked to be of the same
//! frames (docs/BENCHMARKS.md "Shape truth").

use std::time::Instant;

use foveal_engine::{
    BudgetSpec, FrameReport, FrozenClock, SceneConfig, SimConfig, Simulation, Truth,
};

use crate::error::BenchError;

/// One run: the paper scene at `n` bodies and `seed`, under `truth`, on `threads` threads.
#[derive(Debug, Clone, Copy)]
pub struct FramesConfig {
    /// Bodies.
    pub n: u32,
    /// The scene's seed.
    pub seed: u64,
    /// Exact frames stepped.
    pub frames: u32,
    /// What "colliding" means.
    pub truth: Truth,
    /// Narrow-phase threads.
    pub threads: u32,
}

/// What a run did: its last frame's report and the mean wall time of a frame.
#[derive(Debug, Clone)]
pub struct FramesSummary {
    /// The last frame's report (counts are deterministic: they do not depend on the machine).
    pub last: FrameReport,
    /// Wall time of all frames over their number, in milliseconds (start-up excluded).
    pub mean_step_ms: f64,
}

/// Step `cfg.frames` exact frames.
pub fn run(cfg: &FramesConfig) -> Result<FramesSummary, BenchError> {
    let mut sim = Simulation::new(SimConfig {
        scene: SceneConfig {
            truth: cfg.truth,
            ..SceneConfig::paper(cfg.n, cfg.seed)
        },
        budget: BudgetSpec::Exact,
        threads: cfg.threads,
        ..SimConfig::default()
    })?;
    let frames = cfg.frames.max(1);
    let started = Instant::now();
    for _ in 1..frames {
        sim.step(None, &FrozenClock);
    }
    let last = sim.step(None, &FrozenClock).clone();
    Ok(FramesSummary {
        last,
        mean_step_ms: started.elapsed().as_secs_f64() * 1e3 / f64::from(frames),
    })
}

/// One line: the run, its last frame's counts and the mean frame time.
pub fn line(cfg: &FramesConfig, s: &FramesSummary) -> String {
    let r = &s.last;
    format!(
        "N = {} seed {} truth {} threads {}: {} frames, mean {:.3} ms a frame; last frame: {} \
         candidate pairs, {} real collisions, {} sphere tests",
        cfg.n,
        cfg.seed,
        cfg.truth,
        cfg.threads,
        cfg.frames.max(1),
        s.mean_step_ms,
        r.candidate_pairs,
        r.real_collisions,
        r.sphere_tests
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The run is deterministic (the two runs of a cachegrind difference are of the same
    /// frames), and a longer run reaches later frames.
    #[test]
    fn two_runs_are_of_the_same_frames() {
        let cfg = FramesConfig {
            n: 60,
            seed: 3,
            frames: 12,
            truth: Truth::Shape,
            threads: 1,
        };
        let a = run(&cfg).expect("run");
        let b = run(&cfg).expect("run");
        assert_eq!(a.last.index, b.last.index);
        assert_eq!(a.last.sphere_tests, b.last.sphere_tests);
        assert_eq!(a.last.candidate_pairs, b.last.candidate_pairs);
        assert!(
            a.last.sphere_tests > 0,
            "an exact frame of 60 bodies tests spheres"
        );
        let longer = run(&FramesConfig { frames: 20, ..cfg }).expect("run");
        assert!(longer.last.index > a.last.index);
    }
}
