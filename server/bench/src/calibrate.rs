//! Regenerates the priced scheduler's calibration table from exact runs of the paper scene and
//! measures how well it is calibrated on seeds it was not fitted on.
//!
//! Training runs: N = 500, 2,000 and 10,000, seeds 1-2; held-out runs: the same N, seeds 101-102.
//! The table (`server/engine/data/calibration-shape.bin` for the shape truth,
//! `calibration-leaf-spheres.bin` for the leaf truth, each on the default tree; `-octree` before
//! `.bin` for the paper's octree) is written in the engine's binary format; the
//! reliability report (predicted probability of "not colliding" against the observed frequency, in
//! ten bins, with the Brier score and the expected calibration error) is written as markdown.

use std::fmt::Write as _;

use foveal_engine::calibrate::{Observations, ReliabilityRow};
use foveal_engine::schedule::calibration::Calibration;
use foveal_engine::{SceneConfig, TreeKind, Truth};

use crate::error::BenchError;

/// Runs of the calibration: (N, frames) with warm-up.
#[derive(Debug, Clone)]
pub struct CalibrateConfig {
    /// (bodies, recorded frames) per scene.
    pub scenes: Vec<(u32, u32)>,
    /// Seeds of the training runs.
    pub train_seeds: Vec<u64>,
    /// Seeds of the held-out runs.
    pub test_seeds: Vec<u64>,
    /// Unrecorded frames first.
    pub warmup: u32,
    /// The truth the table prices outcomes on (each truth ships its own table).
    pub truth: Truth,
    /// The sphere tree the table's states are traversed in (the default tree and the octree
    /// each ship their own).
    pub tree: TreeKind,
}

impl Default for CalibrateConfig {
    fn default() -> Self {
        Self {
            scenes: vec![(500, 300), (2_000, 100), (10_000, 20)],
            train_seeds: vec![1, 2],
            test_seeds: vec![101, 102],
            warmup: 60,
            truth: Truth::Shape,
            tree: TreeKind::default(),
        }
    }
}

/// What a calibration produced.
#[derive(Debug, Clone)]
pub struct CalibrateOutput {
    /// The fitted table.
    pub calibration: Calibration,
    /// Held-out reliability rows.
    pub reliability: Vec<ReliabilityRow>,
    /// Held-out Brier score.
    pub brier: f64,
    /// Held-out expected calibration error.
    pub ece: f64,
    /// In-sample Brier score and ECE, for comparison.
    pub in_sample: (f64, f64),
}

fn scenes(cfg: &CalibrateConfig, seeds: &[u64]) -> Vec<(SceneConfig, u32)> {
    cfg.scenes
        .iter()
        .flat_map(|&(n, f)| {
            seeds.iter().map(move |&s| {
                let mut scene = SceneConfig::paper(n, s);
                scene.truth = cfg.truth;
                scene.tree = cfg.tree;
                (scene, f)
            })
        })
        .collect()
}

fn record(cfg: &CalibrateConfig, seeds: &[u64]) -> Result<Observations, BenchError> {
    let mut all: Option<Observations> = None;
    for (scene, frames) in scenes(cfg, seeds) {
        let o = Observations::record(&[scene], cfg.warmup, frames)?;
        match all.as_mut() {
            None => all = Some(o),
            Some(a) => a.merge(&o),
        }
    }
    all.ok_or_else(|| BenchError::Invalid("no calibration scenes".into()))
}

/// Fit on the training seeds, evaluate on the held-out ones.
pub fn run(cfg: &CalibrateConfig) -> Result<CalibrateOutput, BenchError> {
    let train = record(cfg, &cfg.train_seeds)?;
    let calibration = train.calibration();
    let test = record(cfg, &cfg.test_seeds)?;
    let (reliability, brier, ece) = test.reliability(&calibration, 10);
    let (_, b_in, e_in) = train.reliability(&calibration, 10);
    Ok(CalibrateOutput {
        calibration,
        reliability,
        brier,
        ece,
        in_sample: (b_in, e_in),
    })
}

/// The reliability report as markdown.
pub fn markdown(cfg: &CalibrateConfig, out: &CalibrateOutput) -> String {
    let mut s = String::new();
    let scenes: Vec<String> = cfg
        .scenes
        .iter()
        .map(|(n, f)| format!("N = {n} x {f} frames"))
        .collect();
    let _ = writeln!(
        s,
        "Fitted on seeds {:?}, evaluated on held-out seeds {:?} ({}; {} warm-up frames each). \
         Each visit of a traversal state is one prediction of \"not colliding\".\n",
        cfg.train_seeds,
        cfg.test_seeds,
        scenes.join(", "),
        cfg.warmup
    );
    let _ = writeln!(
        s,
        "Held-out Brier score {:.4}, expected calibration error {:.4} (in sample: {:.4}, {:.4}).\n",
        out.brier, out.ece, out.in_sample.0, out.in_sample.1
    );
    s.push_str("| predicted P(not colliding) | mean predicted | observed | visits |\n");
    s.push_str("| --- | --- | --- | --- |\n");
    for r in &out.reliability {
        if r.count > 0.0 {
            let _ = writeln!(
                s,
                "| {:.1}-{:.1} | {:.3} | {:.3} | {:.0} |",
                r.lo, r.hi, r.predicted, r.observed, r.count
            );
        }
    }
    s
}
