//! The engine's shape truth held to an independent judge on whole scenes: every candidate pair of
//! every exact frame, its status (colliding or not) against the [`shape_oracle`] judge's verdict,
//! and on every [`ShapeCheckConfig::gap_every`]-th frame, for every pair the judge proves apart,
//! the engine's gap ([`shape_separation`]) against the judge's bracket. Bracketing a distance to
//! 1e-10 R takes about ten times the work of settling a verdict (some 200 patch evaluations a
//! pair against 20), hence the sampling of frames for gaps.
//!
//! The pose of each pair is computed here from the bodies' world state (not by the engine's
//! `shape_pose`). A *mismatch* is a pair the engine calls colliding that the judge proves apart,
//! or one it does not that the judge finds touching; pairs the judge cannot settle (within its
//! bracket of grazing) are counted as ambiguous. The *gap error* of a pair proven apart is how far
//! the engine's gap lies outside the judge's bracket (0 inside it), in R.

use std::fmt::Write as _;
use std::time::Instant;

use foveal_engine::math::Vec3;
use foveal_engine::narrow_phase::{PairStatus, shape_separation};
use foveal_engine::{BudgetSpec, FrozenClock, SceneConfig, SimConfig, Simulation};

use crate::error::BenchError;
use crate::shape_oracle::{Judgement, Oracle, Placement, TOLERANCE, V3, Verdict};

/// One scene to check.
#[derive(Debug, Clone, PartialEq)]
pub struct Scene {
    /// Bodies.
    pub n: u32,
    /// Scene seed.
    pub seed: u64,
    /// The volume's minimum corner.
    pub origin: [f64; 3],
}

/// The scenes, how many frames each, and how many threads judge the pairs.
#[derive(Debug, Clone)]
pub struct ShapeCheckConfig {
    /// Scenes, in order.
    pub scenes: Vec<Scene>,
    /// Exact frames per scene.
    pub frames: u32,
    /// Threads judging a frame's pairs.
    pub threads: usize,
    /// Gaps are checked on frames 1, 1 + this, 1 + twice this... (1: every frame).
    pub gap_every: u32,
}

/// The far-from-origin corner of the standard check.
pub const FAR_ORIGIN: [f64; 3] = [1e7, -1e7, 5e6];

impl ShapeCheckConfig {
    /// N = 500 seeds 1-3 and N = 10,000 seed 1 at the origin, N = 10,000 seed 1 at
    /// [`FAR_ORIGIN`]; 300 frames each.
    pub fn standard() -> Self {
        let at = |n, seed, origin| Scene { n, seed, origin };
        Self {
            scenes: vec![
                at(500, 1, [0.0; 3]),
                at(500, 2, [0.0; 3]),
                at(500, 3, [0.0; 3]),
                at(10_000, 1, [0.0; 3]),
                at(10_000, 1, FAR_ORIGIN),
            ],
            frames: 300,
            threads: default_threads(),
            gap_every: 10,
        }
    }

    /// The same scenes, 20 frames each.
    pub fn quick() -> Self {
        Self {
            frames: 20,
            ..Self::standard()
        }
    }
}

/// The machine's parallelism (1 if unknown).
pub fn default_threads() -> usize {
    std::thread::available_parallelism().map_or(1, usize::from)
}

/// What one scene gave.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SceneCheck {
    /// The scene.
    pub n: u32,
    /// Its seed.
    pub seed: u64,
    /// Its corner.
    pub origin: [f64; 3],
    /// The stars' bounding radius R.
    pub radius: f64,
    /// Frames run.
    pub frames: u32,
    /// Candidate pairs checked, over all frames.
    pub pairs: u64,
    /// Of those, the judge found touching.
    pub touching: u64,
    /// Proven apart.
    pub apart: u64,
    /// Neither.
    pub ambiguous: u64,
    /// Engine statuses the judge contradicts.
    pub mismatches: u64,
    /// The first few mismatches, described.
    pub mismatch_examples: Vec<String>,
    /// Pairs proven apart on the frames whose gaps are checked.
    pub gaps_checked: u64,
    /// Of those, the pairs whose engine gap lies more than the tolerance (1e-9 R) outside the
    /// judge's bracket.
    pub gap_errors: u64,
    /// The largest gap error, in R.
    pub max_gap_error: f64,
    /// The pair with the largest gap error, described.
    pub worst_gap: Option<String>,
    /// The widest bracket of a pair proven apart, in R.
    pub max_bracket: f64,
    /// Mean patch evaluations a pair.
    pub evaluations: f64,
    /// Wall time of the scene (simulation and judging), s.
    pub seconds: f64,
}

/// A candidate pair as the judge sees it.
#[derive(Debug, Clone, Copy)]
struct Job {
    a: u32,
    b: u32,
    placement: Placement,
    colliding: bool,
}

/// B's centre and axes in A's frame, from the bodies' positions and orientations.
fn placement(sim: &Simulation, a: usize, b: usize) -> Placement {
    let w = sim.world();
    let qa = w.orientation[a].conjugate();
    let rel = qa * w.orientation[b];
    let v = |p: Vec3| V3::new(p.x, p.y, p.z);
    Placement {
        centre: v(qa * (w.position[b] - w.position[a])),
        axes: [v(rel * Vec3::X), v(rel * Vec3::Y), v(rel * Vec3::Z)],
    }
}

/// A placement as a report gives it: the rotation's rows and the translation.
fn describe(p: &Placement) -> String {
    let [x, y, z] = p.axes;
    format!(
        "rotation rows [[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]], translation [{}, {}, {}]",
        x.x, y.x, z.x, x.y, y.y, z.y, x.z, y.z, z.z, p.centre.x, p.centre.y, p.centre.z
    )
}

/// Run and check one scene.
pub fn check_scene(
    scene: &Scene,
    cfg: &ShapeCheckConfig,
    mut progress: impl FnMut(u32),
) -> Result<SceneCheck, BenchError> {
    let frames = cfg.frames;
    let started = Instant::now();
    let mut sim = Simulation::new(SimConfig {
        scene: SceneConfig {
            origin: scene.origin,
            ..SceneConfig::paper(scene.n, scene.seed)
        },
        budget: BudgetSpec::Exact,
        ..SimConfig::default()
    })?;
    let r = sim.config().scene.shape_radius;
    let oracle = Oracle::new(r);
    let mut out = SceneCheck {
        n: scene.n,
        seed: scene.seed,
        origin: scene.origin,
        radius: r,
        frames,
        ..SceneCheck::default()
    };
    let mut evaluations = 0u64;
    for frame in 0..frames {
        sim.step(None, &FrozenClock);
        let jobs: Vec<Job> = sim
            .pairs()
            .iter()
            .map(|p| {
                let (a, b) = (p.a as usize, p.b as usize);
                let colliding = match p.status {
                    PairStatus::Colliding => true,
                    PairStatus::Separate => false,
                    s => panic!("an exact frame left pair {a}-{b} {s:?}"),
                };
                Job {
                    a: p.a,
                    b: p.b,
                    placement: placement(&sim, a, b),
                    colliding,
                }
            })
            .collect();
        let gaps = frame % cfg.gap_every.max(1) == 0;
        let verdicts = judge_all(&oracle, &jobs, cfg.threads, gaps);
        for (job, j) in jobs.iter().zip(&verdicts) {
            out.pairs += 1;
            evaluations += j.evaluations as u64;
            let wrong = match j.verdict {
                Verdict::Touching => {
                    out.touching += 1;
                    !job.colliding
                }
                Verdict::Apart if gaps => {
                    out.apart += 1;
                    out.gaps_checked += 1;
                    out.max_bracket = out.max_bracket.max((j.upper - j.lower) / r);
                    let (a, b) = (job.a as usize, job.b as usize);
                    let gap = shape_separation(sim.tree(), sim.world(), a, b).0;
                    let error = (j.lower - gap).max(gap - j.upper).max(0.0) / r;
                    if error > TOLERANCE {
                        out.gap_errors += 1;
                    }
                    if error > out.max_gap_error {
                        out.max_gap_error = error;
                        out.worst_gap = Some(format!(
                            "frame {frame}, pair {}-{}: gap {} outside [{}, {}]; {}",
                            job.a,
                            job.b,
                            gap,
                            j.lower,
                            j.upper,
                            describe(&job.placement)
                        ));
                    }
                    job.colliding
                }
                Verdict::Apart => {
                    out.apart += 1;
                    job.colliding
                }
                Verdict::Ambiguous => {
                    out.ambiguous += 1;
                    false
                }
            };
            if wrong {
                out.mismatches += 1;
                if out.mismatch_examples.len() < 5 {
                    out.mismatch_examples.push(format!(
                        "frame {frame}, pair {}-{}: engine {}, judge {:?} [{}, {}]; {}",
                        job.a,
                        job.b,
                        if job.colliding {
                            "colliding"
                        } else {
                            "not colliding"
                        },
                        j.verdict,
                        j.lower,
                        j.upper,
                        describe(&job.placement)
                    ));
                }
            }
        }
        progress(frame + 1);
    }
    out.evaluations = evaluations as f64 / out.pairs.max(1) as f64;
    out.seconds = started.elapsed().as_secs_f64();
    Ok(out)
}

/// The judge's answer on every job, on `threads` threads: the distance bracketed to the judge's
/// precision with `gaps`, else the verdict only.
fn judge_all(oracle: &Oracle, jobs: &[Job], threads: usize, gaps: bool) -> Vec<Judgement> {
    let chunk = jobs.len().div_ceil(threads.max(1)).max(1);
    std::thread::scope(|s| {
        let handles: Vec<_> = jobs
            .chunks(chunk)
            .map(|part| {
                s.spawn(move || {
                    part.iter()
                        .map(|j| {
                            if gaps {
                                oracle.judge(&j.placement)
                            } else {
                                oracle.verdict(&j.placement)
                            }
                        })
                        .collect::<Vec<Judgement>>()
                })
            })
            .collect();
        let mut out = Vec::with_capacity(jobs.len());
        for h in handles {
            match h.join() {
                Ok(v) => out.extend(v),
                Err(e) => std::panic::resume_unwind(e),
            }
        }
        out
    })
}

/// Run every scene of `cfg`.
pub fn run(
    cfg: &ShapeCheckConfig,
    mut progress: impl FnMut(&Scene, u32),
) -> Result<Vec<SceneCheck>, BenchError> {
    cfg.scenes
        .iter()
        .map(|s| check_scene(s, cfg, |f| progress(s, f)))
        .collect()
}

/// The checks as a markdown table, totals and the worst cases.
pub fn markdown(cfg: &ShapeCheckConfig, rows: &[SceneCheck]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Shape check: the engine's shape truth against the independent judge\n\n\
         Every candidate pair of {} exact frames per scene ({} threads judging); the gaps of the \
         pairs proven apart on every {}th frame from the first. Gap error: how far the engine's \
         gap lies outside the judge's bracket, in R (tolerance {TOLERANCE:e}).\n",
        cfg.frames,
        cfg.threads,
        cfg.gap_every.max(1)
    );
    let _ = writeln!(
        s,
        "| N | seed | origin | pairs | touching | apart | ambiguous | mismatches | gaps checked | \
         gaps beyond tolerance | max gap error (R) | widest bracket (R) | evaluations a pair | time (s) |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    );
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {:?} | {} | {} | {} | {} | {} | {} | {} | {:.2e} | {:.2e} | {:.0} | {:.1} |",
            r.n,
            r.seed,
            r.origin,
            r.pairs,
            r.touching,
            r.apart,
            r.ambiguous,
            r.mismatches,
            r.gaps_checked,
            r.gap_errors,
            r.max_gap_error,
            r.max_bracket,
            r.evaluations,
            r.seconds
        );
    }
    let sum = |f: fn(&SceneCheck) -> u64| rows.iter().map(f).sum::<u64>();
    let max = |f: fn(&SceneCheck) -> f64| rows.iter().map(f).fold(0.0, f64::max);
    let _ = writeln!(
        s,
        "\nTotal: {} pairs checked: {} surely touching, {} surely apart, {} ambiguous; {} \
         mismatches; {} gaps checked, {} beyond tolerance, max gap error {:.2e} R; {:.1} s.",
        sum(|r| r.pairs),
        sum(|r| r.touching),
        sum(|r| r.apart),
        sum(|r| r.ambiguous),
        sum(|r| r.mismatches),
        sum(|r| r.gaps_checked),
        sum(|r| r.gap_errors),
        max(|r| r.max_gap_error),
        rows.iter().map(|r| r.seconds).sum::<f64>()
    );
    for r in rows {
        for m in &r.mismatch_examples {
            let _ = writeln!(
                s,
                "\nMismatch (N = {}, seed {}, origin {:?}, R = {}): {m}",
                r.n, r.seed, r.origin, r.radius
            );
        }
        if let Some(w) = &r.worst_gap
            && r.max_gap_error > TOLERANCE
        {
            let _ = writeln!(
                s,
                "\nLargest gap error (N = {}, seed {}, origin {:?}, R = {}): {w}",
                r.n, r.seed, r.origin, r.radius
            );
        }
    }
    s
}
