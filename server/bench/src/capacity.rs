//! `foveal-bench capacity`: how many bodies a fixed frame budget holds with what the viewer looks
//! at exact, and what the rest costs in perceived error, for foveal's scheduler with the gaze,
//! the same scheduler told only the screen centre (no eye tracker), round-robin told the screen
//! centre (gaze-blind), and the exact frame.
//!
//! Each (N, variant) is one run of [`crate::scale`]'s child process (its own peak RSS, one after
//! another): the paper scene at the given seed, a wall clock, the viewer fixating one point off
//! the centre. After every frame, off the clock, the frame is measured where the viewer looked
//! ([`foveal_engine::Simulation::measured_at`]) and audited: whether every candidate pair within
//! 5 degrees of the viewer's fixation was settled exactly (none deemed, no region that may hold
//! one left unsearched) and the audited true P. Every variant does that same work between its
//! frames, so none has a colder cache than another. True P scores the deemed pairs (bounces
//! across a gap); the pairs of a region left unsearched are neither tested nor scored (a missed
//! bounce), so the foveal-exact share and the stale foveal regions are the figures for those.
//!
//! The capacity of a budgeted variant is the largest N of the sweep at which at least
//! [`FOVEAL_TARGET`] of frames were foveal-exact; of the exact frame, the largest N whose step
//! p99 kept within the budget. Closed loop: each variant's scene evolves under its own answers,
//! so its frames are its own (the open-loop protocol compares schedulers on identical frames).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use foveal_engine::broad_phase::BroadPhaseKind;
use foveal_engine::{SchedulerKind, TreeKind, Truth};

use crate::plots::{Figure, Panel, Series};
use crate::scale::{self, Machine, Mode, RunResult, RunSpec, ScaleError};
use crate::stats::Interval;

/// Share of frames that must be foveal-exact for a budgeted variant to hold an N.
pub const FOVEAL_TARGET: f64 = 0.99;

/// Body counts swept by default: around where the 16 ms frame stops holding the fovea on two
/// cores (200,000 held it in 99.5% of frames and 300,000 in 49% before this command).
pub const DEFAULT_NS: [u32; 6] = [50_000, 100_000, 200_000, 300_000, 400_000, 600_000];

/// Default output directory.
pub const DEFAULT_OUT: &str = "results/capacity";

/// What the narrow phase is told and how it is bounded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Variant {
    /// The priced scheduler fed the viewer's fixation (foveal's default).
    PricedGaze,
    /// The priced scheduler fed the screen centre while the viewer looks elsewhere.
    PricedCentre,
    /// Round-robin, told the screen centre: gaze-blind. (Fed the fixation, round-robin is not
    /// blind at large N: a shedding broad phase searches the regions nearest the fixation
    /// first and lists their pairs first, so round-robin settles the fovea first too.)
    RoundRobin,
    /// Every pair settled, whatever the frame takes.
    Exact,
}

impl Variant {
    /// Every variant, in table order.
    pub const ALL: [Self; 4] = [
        Self::PricedGaze,
        Self::PricedCentre,
        Self::RoundRobin,
        Self::Exact,
    ];

    /// Label in tables and legends.
    pub fn label(self) -> &'static str {
        match self {
            Self::PricedGaze => "priced, gaze",
            Self::PricedCentre => "priced, screen centre",
            Self::RoundRobin => "round-robin, screen centre",
            Self::Exact => "exact",
        }
    }
}

/// The whole command.
#[derive(Debug, Clone, PartialEq)]
pub struct CapacityConfig {
    /// Body counts, increasing.
    pub ns: Vec<u32>,
    /// The whole frame's budget (ms).
    pub budget_ms: f64,
    /// Threads of every run.
    pub threads: u32,
    /// Measured frames per run.
    pub frames: u32,
    /// Uncounted warm-up frames per run.
    pub warmup: u32,
    /// Where the viewer looks, as a fraction of the screen.
    pub viewer: [f64; 2],
    /// Scene seed.
    pub seed: u64,
    /// What "colliding" means.
    pub truth: Truth,
    /// The sphere tree.
    pub tree: TreeKind,
    /// Output directory.
    pub out: PathBuf,
}

impl Default for CapacityConfig {
    fn default() -> Self {
        Self {
            ns: DEFAULT_NS.to_vec(),
            budget_ms: 16.0,
            threads: 2,
            frames: 100,
            warmup: 30,
            viewer: [0.3, 0.4],
            seed: 1,
            truth: Truth::default(),
            tree: TreeKind::default(),
            out: PathBuf::from(DEFAULT_OUT),
        }
    }
}

impl CapacityConfig {
    /// The run of `variant` at `n`.
    pub fn spec(&self, n: u32, variant: Variant) -> RunSpec {
        let (mode, scheduler) = match variant {
            Variant::PricedGaze | Variant::PricedCentre => {
                (Mode::BudgetMs(self.budget_ms), SchedulerKind::Priced)
            }
            Variant::RoundRobin => (Mode::BudgetMs(self.budget_ms), SchedulerKind::RoundRobin),
            Variant::Exact => (Mode::Exact, SchedulerKind::Priced),
        };
        RunSpec {
            n,
            threads: self.threads,
            broad_phase: BroadPhaseKind::Auto,
            mode,
            scheduler,
            fovea_first: false,
            truth: self.truth,
            tree: self.tree,
            seed: self.seed,
            warmup: self.warmup,
            frames: self.frames,
            viewer: Some(self.viewer),
            steer_centre: matches!(variant, Variant::PricedCentre | Variant::RoundRobin),
            audit: true,
        }
    }

    /// Every run, N by N, the variants in [`Variant::ALL`]'s order.
    pub fn plan(&self) -> Vec<(Variant, RunSpec)> {
        self.ns
            .iter()
            .flat_map(|&n| Variant::ALL.map(|v| (v, self.spec(n, v))))
            .collect()
    }

    /// Refuse what cannot be measured, naming the field and the limit.
    pub fn validate(&self) -> Result<(), ScaleError> {
        let bad = |m: String| Err(ScaleError::Invalid(m));
        if self.ns.is_empty() || self.ns.iter().any(|&n| n < 2) {
            return bad(format!(
                "--n: give body counts of at least 2, not {:?}",
                self.ns
            ));
        }
        if !(self.budget_ms.is_finite() && self.budget_ms > 0.0) {
            return bad(format!(
                "--budget-ms: a positive time, not {}",
                self.budget_ms
            ));
        }
        if self.frames == 0 {
            return bad("--frames: at least 1".into());
        }
        if !self.viewer.iter().all(|v| (0.0..=1.0).contains(v)) {
            return bad(format!(
                "--viewer: two fractions of the screen in [0, 1], not {:?}",
                self.viewer
            ));
        }
        Ok(())
    }
}

/// One run's outcome.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The variant.
    pub variant: Variant,
    /// What it measured.
    pub result: RunResult,
}

/// What the command measured.
#[derive(Debug, Clone, PartialEq)]
pub struct CapacityOutput {
    /// The configuration.
    pub config: CapacityConfig,
    /// Every run, in plan order.
    pub rows: Vec<Row>,
    /// The machine.
    pub machine: Machine,
    /// Load averages before and after.
    pub load: [Option<[f64; 3]>; 2],
}

/// Whether `row` holds its N: for a budgeted variant, at least [`FOVEAL_TARGET`] of its frames
/// foveal-exact; for the exact frame, its step p99 within `budget_ms`.
pub fn holds(row: &Row, budget_ms: f64) -> bool {
    match row.variant {
        Variant::Exact => row.result.step_p99_ms <= budget_ms,
        _ => row.result.foveal_exact_share >= FOVEAL_TARGET,
    }
}

/// The largest N of the sweep `variant` holds (None: not even the smallest).
pub fn capacity(rows: &[Row], variant: Variant, budget_ms: f64) -> Option<u32> {
    rows.iter()
        .filter(|r| r.variant == variant && holds(r, budget_ms))
        .map(|r| r.result.spec.n)
        .max()
}

/// Run the plan, one child after another, with `exe` the bench binary.
pub fn run(cfg: &CapacityConfig, exe: &Path, progress: bool) -> Result<CapacityOutput, ScaleError> {
    cfg.validate()?;
    let load_before = scale::load_average();
    let plan = cfg.plan();
    let mut rows = Vec::with_capacity(plan.len());
    for (k, (variant, spec)) in plan.into_iter().enumerate() {
        if progress {
            eprintln!(
                "[{}/{}] N = {}, {}",
                k + 1,
                cfg.ns.len() * Variant::ALL.len(),
                spec.n,
                variant.label()
            );
        }
        let result = scale::run_child(exe, &spec)?;
        rows.push(Row { variant, result });
    }
    Ok(CapacityOutput {
        config: cfg.clone(),
        rows,
        machine: Machine::this(),
        load: [load_before, scale::load_average()],
    })
}

/// The results as markdown: the protocol, the capacities and the table.
pub fn markdown(out: &CapacityOutput) -> String {
    let c = &out.config;
    let mut s = String::new();
    let _ = writeln!(s, "# Capacity at a {} ms frame\n", c.budget_ms);
    let _ = writeln!(
        s,
        "Paper scene (seed {}, truth {}, tree {}), {} thread{}, wall clock; the viewer looks at \
         ({}, {}) of the screen; round-robin and the control are told the screen centre. {} measured frames after {} warm-up frames per run, each run \
         in its own process. Foveal exact: every candidate pair within 5 degrees of the \
         viewer's fixation settled exactly (none deemed, no region that may hold one left \
         unsearched). True P: the audited perceived error where the viewer looked, mean per \
         frame. Closed loop: each run's scene evolves under its own answers.\n",
        c.seed,
        c.truth,
        c.tree.name(),
        c.threads,
        if c.threads == 1 { "" } else { "s" },
        c.viewer[0],
        c.viewer[1],
        c.frames,
        c.warmup
    );
    let _ = writeln!(s, "Machine: {}.\n", out.machine);
    let _ = writeln!(
        s,
        "Load average (1, 5, 15 min) before: {}; after: {}.\n",
        scale::fmt_load(out.load[0]),
        scale::fmt_load(out.load[1])
    );
    let _ = writeln!(
        s,
        "Capacity: the largest N of the sweep at which at least {:.0}% of frames were foveal \
         exact (exact: whose step p99 kept within {} ms).\n",
        FOVEAL_TARGET * 100.0,
        c.budget_ms
    );
    let _ = writeln!(s, "| variant | capacity |");
    let _ = writeln!(s, "|---|---|");
    for v in Variant::ALL {
        let cap = capacity(&out.rows, v, c.budget_ms)
            .map_or("below the sweep".to_string(), scale::grouped);
        let _ = writeln!(s, "| {} | {} |", v.label(), cap);
    }
    let _ = writeln!(
        s,
        "\n| N | variant | step p50 (ms) | step p99 (ms) | foveal exact | true P / frame | \
         true P / round-robin's | deemed / candidates | pairs within 5° | stale foveal regions \
         | peak RSS (MiB) |"
    );
    let _ = writeln!(s, "|---|---|---|---|---|---|---|---|---|---|---|");
    for row in &out.rows {
        let r = &row.result;
        let rr = out
            .rows
            .iter()
            .find(|o| o.variant == Variant::RoundRobin && o.result.spec.n == r.spec.n)
            .and_then(|o| o.result.true_p_mean);
        let ratio = match (r.true_p_mean, rr) {
            (Some(p), Some(q)) if q > 0.0 => format!("{:.2}", p / q),
            (Some(_), Some(_)) => "round-robin's is 0".into(),
            _ => "not audited".into(),
        };
        let _ = writeln!(
            s,
            "| {} | {} | {:.2} | {:.2} | {:.1}% | {} | {} | {:.0} / {:.0} | {:.0} | {:.1} | {} |",
            scale::grouped(r.spec.n),
            row.variant.label(),
            r.step_p50_ms,
            r.step_p99_ms,
            r.foveal_exact_share * 100.0,
            r.true_p_mean
                .map_or("not audited".into(), |p| crate::stats::sig(p, 3)),
            ratio,
            r.deemed_mean,
            r.candidates_mean,
            r.foveal_pairs_mean,
            r.foveal_stale_mean,
            r.peak_rss_kib / 1024
        );
    }
    s
}

/// One row per run.
pub fn csv(out: &CapacityOutput) -> String {
    let mut s = String::from(
        "n,variant,budget_ms,threads,frames,step_p50_ms,step_p99_ms,foveal_exact_share,\
         true_p_mean,deemed_mean,candidates_mean,foveal_pairs_mean,foveal_stale_mean,peak_rss_kib,\
         holds\n",
    );
    for row in &out.rows {
        let r = &row.result;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{:.4},{:.4},{:.4},{},{:.1},{:.1},{:.1},{:.2},{},{}",
            r.spec.n,
            row.variant.label(),
            out.config.budget_ms,
            r.spec.threads,
            r.spec.frames,
            r.step_p50_ms,
            r.step_p99_ms,
            r.foveal_exact_share,
            r.true_p_mean.map_or(String::new(), |p| format!("{p}")),
            r.deemed_mean,
            r.candidates_mean,
            r.foveal_pairs_mean,
            r.foveal_stale_mean,
            r.peak_rss_kib,
            holds(row, out.config.budget_ms)
        );
    }
    s
}

/// The curves: true P against N per variant, and the foveal-exact share against N.
pub fn figure(out: &CapacityOutput) -> Figure {
    let series = |value: &dyn Fn(&RunResult) -> Option<f64>| -> Vec<Series> {
        Variant::ALL
            .iter()
            .map(|&v| Series {
                name: v.label().to_string(),
                points: out
                    .rows
                    .iter()
                    .filter(|r| r.variant == v)
                    .filter_map(|r| {
                        value(&r.result).map(|y| {
                            let one = Interval {
                                value: y,
                                lo: f64::NAN,
                                hi: f64::NAN,
                            };
                            (f64::from(r.result.spec.n), one)
                        })
                    })
                    .collect(),
                dashed: v == Variant::PricedCentre,
            })
            .collect()
    };
    let budget = out.config.budget_ms;
    Figure {
        panels: vec![
            Panel {
                title: format!(
                    "True P per frame at a {budget} ms frame (deemed pairs; unsearched regions' \
                     pairs are not scored)"
                ),
                x_label: "bodies N".into(),
                y_label: "audited true P where the viewer looked".into(),
                log_x: true,
                log_y: false,
                series: series(&|r| r.true_p_mean),
                references: Vec::new(),
            },
            Panel {
                title: format!("Frames with the fovea exact at a {budget} ms frame"),
                x_label: "bodies N".into(),
                y_label: "share of frames".into(),
                log_x: true,
                log_y: false,
                series: series(&|r| Some(r.foveal_exact_share)),
                references: vec![(FOVEAL_TARGET, format!("{:.0}%", FOVEAL_TARGET * 100.0))],
            },
        ],
        caption: format!(
            "Capacity at a {budget} ms frame on {} threads: each point is one closed-loop run of \
             its variant at that N (no replicates, no interval). Left: mean audited true P per \
             frame where the viewer looked; right: share of frames in which every pair within \
             5 degrees of the fixation was settled exactly. Dashed: the priced scheduler told \
             the screen centre instead of the gaze.",
            out.config.threads
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plan measures every variant at every N under the same scene and viewer, the control
    /// told the centre, every run audited; and a malformed configuration names its field.
    #[test]
    fn the_plan_runs_every_variant_alike_and_bad_input_names_the_field() {
        let cfg = CapacityConfig {
            ns: vec![1_000, 2_000],
            ..CapacityConfig::default()
        };
        let plan = cfg.plan();
        assert_eq!(plan.len(), 8);
        for (v, spec) in &plan {
            assert_eq!(spec.viewer, Some([0.3, 0.4]));
            assert!(spec.audit);
            assert_eq!(
                spec.steer_centre,
                matches!(v, Variant::PricedCentre | Variant::RoundRobin)
            );
            assert_eq!(spec.mode == Mode::Exact, *v == Variant::Exact);
        }
        for (bad, field) in [
            (
                CapacityConfig {
                    budget_ms: f64::NAN,
                    ..cfg.clone()
                },
                "--budget-ms",
            ),
            (
                CapacityConfig {
                    viewer: [1.5, 0.4],
                    ..cfg.clone()
                },
                "--viewer",
            ),
            (
                CapacityConfig {
                    ns: vec![],
                    ..cfg.clone()
                },
                "--n",
            ),
        ] {
            let e = bad.validate().expect_err("refused").to_string();
            assert!(e.contains(field), "{e}");
        }
    }

    /// A short run of two variants at one small N: each frame measured and audited where the
    /// viewer looked, the control's fovea counted there too, and the capacity read off the
    /// foveal-exact share.
    #[test]
    fn a_small_sweep_audits_where_the_viewer_looked() {
        let cfg = CapacityConfig {
            ns: vec![3_000],
            frames: 4,
            warmup: 2,
            threads: 1,
            budget_ms: 0.3,
            ..CapacityConfig::default()
        };
        let rows: Vec<Row> = [Variant::PricedGaze, Variant::PricedCentre, Variant::Exact]
            .into_iter()
            .map(|variant| Row {
                variant,
                result: scale::run_one(&cfg.spec(3_000, variant)).expect("a small run"),
            })
            .collect();
        for row in &rows {
            let r = &row.result;
            assert_eq!(r.frame_trace.len(), 4);
            assert!(
                r.true_p_mean.is_some_and(f64::is_finite),
                "{:?}",
                row.variant
            );
            assert!(r.foveal_pairs_mean > 0.0, "{:?}", row.variant);
        }
        let exact = &rows[2].result;
        assert_eq!((exact.deemed_mean, exact.true_p_mean), (0.0, Some(0.0)));
        assert_eq!(exact.foveal_exact_share, 1.0);
        for row in &rows {
            assert_eq!(
                capacity(std::slice::from_ref(row), row.variant, 1e9),
                holds(row, 1e9).then_some(3_000)
            );
        }
    }
}
