//! Summaries across seeds, paired ratios, and the CSV and markdown writers.
//!
//! Every mean across seeds carries a 95% confidence interval (Student's t over seeds). Ratios between
//! two conditions are *paired*: computed per seed (same scene, same gaze), then averaged with a CI.

use std::fmt::Write as _;
use std::path::Path;

use foveal_engine::SchedulerKind;

use crate::BenchError;
use crate::protocol::{Mode, Part, StudyConfig};
use crate::runner::RunSummary;
use crate::stats::{MeanCi, sig};

/// A per-run scalar.
pub type Metric = fn(&RunSummary) -> f64;

/// The metrics summarised across seeds: (CSV name, accessor).
pub const METRICS: [(&str, Metric); 12] = [
    ("t_mean_ms", |r| r.t_ms.mean()),
    ("t_sd_ms", |r| r.t_ms.sd()),
    ("narrow_mean_ms", |r| r.narrow_ms.mean()),
    ("delta", |r| r.delta.mean()),
    ("p", |r| r.p.mean()),
    ("true_delta", |r| r.true_delta.mean()),
    ("true_p", |r| r.true_p.mean()),
    ("false_positives", |r| r.false_positives.mean()),
    ("deemed", |r| r.deemed.mean()),
    ("candidates", |r| r.candidates.mean()),
    ("sphere_tests", |r| r.tests.mean()),
    ("exact_cost_tests", |r| r.exact_cost),
];

/// Runs of one condition (part, N, mode, scheduler) across seeds.
#[derive(Debug, Clone)]
pub struct Group<'a> {
    /// Part.
    pub part: Part,
    /// Bodies.
    pub n: u32,
    /// Budget.
    pub mode: Mode,
    /// Scheduler.
    pub scheduler: SchedulerKind,
    /// One run per seed.
    pub runs: Vec<&'a RunSummary>,
}

impl Group<'_> {
    /// Mean and CI of a metric across seeds.
    pub fn ci(&self, m: Metric) -> MeanCi {
        MeanCi::of(self.runs.iter().map(|r| m(r)))
    }
}

/// Group runs by condition, in order of first appearance.
pub fn groups(runs: &[RunSummary]) -> Vec<Group<'_>> {
    let mut out: Vec<Group<'_>> = Vec::new();
    for r in runs {
        let s = &r.spec;
        match out.iter_mut().find(|g| {
            g.part == s.part && g.n == s.n && g.mode == s.mode && g.scheduler == s.scheduler
        }) {
            Some(g) => g.runs.push(r),
            None => out.push(Group {
                part: s.part,
                n: s.n,
                mode: s.mode,
                scheduler: s.scheduler,
                runs: vec![r],
            }),
        }
    }
    out
}

/// Find a condition.
pub fn find<'g, 'a>(
    gs: &'g [Group<'a>],
    part: Part,
    n: u32,
    mode: Mode,
    scheduler: SchedulerKind,
) -> Option<&'g Group<'a>> {
    gs.iter()
        .find(|g| g.part == part && g.n == n && g.mode == mode && g.scheduler == scheduler)
}

/// Paired ratio `m(a) / m(b)` per seed, then mean and CI across seeds.
pub fn paired_ratio(a: &Group<'_>, b: &Group<'_>, m: Metric) -> MeanCi {
    MeanCi::of(a.runs.iter().filter_map(|ra| {
        b.runs
            .iter()
            .find(|rb| rb.spec.seed == ra.spec.seed)
            .map(|rb| m(ra) / m(rb))
    }))
}

fn write_file(path: &Path, text: &str) -> Result<(), BenchError> {
    std::fs::write(path, text).map_err(|e| BenchError::io(path, e))
}

/// One row per run.
pub fn write_runs_csv(path: &Path, runs: &[RunSummary]) -> Result<(), BenchError> {
    let mut s = String::from(
        "part,n,seed,mode,param,scheduler,frames,exact_cost_tests,budget_tests,t_mean_ms,t_sd_ms,\
narrow_mean_ms,delta,p,true_delta,true_p,false_positives,deemed,candidates,real_collisions,\
sphere_tests,exhausted_frac,wall_s\n",
    );
    for r in runs {
        let sp = &r.spec;
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{:.1},{},{:.5},{:.5},{:.5},{:.6},{:.6},{:.6},{:.6},{:.3},{:.3},{:.3},{:.3},{:.1},{:.4},{:.3}",
            sp.part.name(),
            sp.n,
            sp.seed,
            sp.mode.kind(),
            sp.mode.param(),
            sp.scheduler.name(),
            sp.frames,
            r.exact_cost,
            r.budget_tests.map(|t| t.to_string()).unwrap_or_default(),
            r.t_ms.mean(),
            r.t_ms.sd(),
            r.narrow_ms.mean(),
            r.delta.mean(),
            r.p.mean(),
            r.true_delta.mean(),
            r.true_p.mean(),
            r.false_positives.mean(),
            r.deemed.mean(),
            r.candidates.mean(),
            r.real.mean(),
            r.tests.mean(),
            r.exhausted.mean(),
            r.wall_s,
        );
    }
    write_file(path, &s)
}

/// One row per condition: mean and 95% CI half-width across seeds of every metric.
pub fn write_summary_csv(path: &Path, gs: &[Group<'_>]) -> Result<(), BenchError> {
    let mut s = String::from("part,n,mode,param,scheduler,seeds,frames");
    for (name, _) in METRICS {
        let _ = write!(s, ",{name},{name}_ci95");
    }
    s.push('\n');
    for g in gs {
        let frames = g.runs.first().map(|r| r.spec.frames).unwrap_or(0);
        let _ = write!(
            s,
            "{},{},{},{},{},{},{}",
            g.part.name(),
            g.n,
            g.mode.kind(),
            g.mode.param(),
            g.scheduler.name(),
            g.runs.len(),
            frames
        );
        for (_, m) in METRICS {
            let c = g.ci(m);
            let _ = write!(s, ",{:.6e},{:.3e}", c.mean, c.half);
        }
        s.push('\n');
    }
    write_file(path, &s)
}

fn model_name(cfg: &StudyConfig) -> String {
    use foveal_engine::{EccentricityUnit, PerceptualFunction};
    let unit = match cfg.model.unit {
        EccentricityUnit::Pixels => "px",
        EccentricityUnit::Degrees => "deg",
    };
    match cfg.model.function {
        PerceptualFunction::F1 => format!("F1 ({unit})"),
        PerceptualFunction::F2 { c } => format!("F2, C = {c} {unit}"),
        PerceptualFunction::F2Range { c_min, c_max } => {
            format!("F2 over C in [{c_min}, {c_max}] {unit}")
        }
        PerceptualFunction::F3 { .. } => format!("F3 ({unit})"),
    }
}

/// The protocol as a bullet list (for reports).
pub fn describe(cfg: &StudyConfig) -> String {
    let mut s = String::new();
    let seeds: Vec<String> = cfg.seeds.iter().map(u64::to_string).collect();
    let _ = writeln!(
        s,
        "- seeds: {} ({}); gaze: {}",
        seeds.len(),
        seeds.join(", "),
        match &cfg.gaze {
            crate::protocol::GazeSpec::Scripted =>
                "scripted fixations (150-400 ms) and saccades, seeded".to_string(),
            crate::protocol::GazeSpec::Csv(p) => format!("recorded trace `{}`", p.display()),
        }
    );
    let _ = writeln!(
        s,
        "- perceptual model (schedule and measure): {}; priority-queue threshold {}°; audit on",
        model_name(cfg),
        cfg.threshold_deg
    );
    if cfg.table {
        let ns: Vec<String> = cfg.ns.iter().map(u32::to_string).collect();
        let _ = writeln!(
            s,
            "- table: N = {}; {} frames per run; interrupted at fractions {:?} of exact cost{}{}",
            ns.join(", "),
            cfg.frames,
            cfg.fractions,
            cfg.paper_ms_scale
                .map(|k| format!(", at the paper's target times / {k} (wall clock)"))
                .unwrap_or_default(),
            if cfg.tests_budgets.is_empty() {
                String::new()
            } else {
                format!(", at {:?} sphere tests", cfg.tests_budgets)
            }
        );
    }
    if let Some(c) = &cfg.curves {
        let ns: Vec<String> = c.ns.iter().map(u32::to_string).collect();
        let _ = writeln!(
            s,
            "- curves: N = {}; {} frames per run; fractions of exact cost {:?}",
            ns.join(", "),
            c.frames,
            c.fractions
        );
    }
    let _ = writeln!(
        s,
        "- every run first steps {} unrecorded warm-up frames; exact cost per (N, seed): mean \
sphere tests per frame over {} exact frames after the same warm-up",
        cfg.warmup_frames, cfg.calibration_frames
    );
    s
}

const PAPER_SCHEDULERS: [SchedulerKind; 5] = [
    SchedulerKind::RoundRobin,
    SchedulerKind::Sequential,
    SchedulerKind::SortedSequential,
    SchedulerKind::PriorityOnly,
    SchedulerKind::PrioritySorted,
];

/// Markdown for the table part: figure 4 (T), figure 5 (Δ, P), figure 6 (P per scheduler) and the
/// headline ratios.
pub fn table_markdown(cfg: &StudyConfig, gs: &[Group<'_>]) -> String {
    let mut s = String::new();
    let t_mean: Metric = |r| r.t_ms.mean();
    let t_sd: Metric = |r| r.t_ms.sd();
    let rr = SchedulerKind::RoundRobin;
    let _ = writeln!(
        s,
        "### Collision time T (figure 4)\n\nT = broad + narrow phase + response, ms per frame; mean \
over frames, then mean ± 95% CI over seeds. Ratios are exact / interrupted, paired by seed.\n"
    );
    let _ = writeln!(
        s,
        "| N | mode | budget (tests) | mean T (ms) | sd T (ms) | mean ratio | sd ratio |\n|---|---|---|---|---|---|---|"
    );
    for &n in &cfg.ns {
        let Some(exact) = find(gs, Part::Table, n, Mode::Exact, rr) else {
            continue;
        };
        let mut modes = vec![Mode::Exact, Mode::Zero];
        modes.extend(cfg.table_modes(n));
        for mode in modes {
            let Some(g) = find(gs, Part::Table, n, mode, rr) else {
                continue;
            };
            let budget = MeanCi::of(
                g.runs
                    .iter()
                    .map(|r| r.budget_tests.map_or(f64::NAN, |t| t as f64)),
            );
            let (rm, rs) = if mode == Mode::Exact {
                ("1".to_string(), "1".to_string())
            } else {
                (
                    paired_ratio(exact, g, t_mean).fmt(3),
                    paired_ratio(exact, g, t_sd).fmt(3),
                )
            };
            let _ = writeln!(
                s,
                "| {n} | {} | {} | {} | {} | {rm} | {rs} |",
                mode.label(),
                if budget.n > 0 {
                    sig(budget.mean, 4)
                } else {
                    "–".into()
                },
                g.ci(t_mean).fmt(3),
                g.ci(t_sd).fmt(3),
            );
        }
    }
    let _ = writeln!(
        s,
        "\n### Inaccuracy at interruption (figure 5), round-robin\n\nΔ and P are the engine's \
estimates (section 3: gap of the last overlapping spheres); true Δ and true P come from the audit \
(exact separation of each deemed pair). FP = deemed pairs that do not collide.\n"
    );
    let _ = writeln!(
        s,
        "| N | mode | Δ | true Δ | P | true P | deemed | FP |\n|---|---|---|---|---|---|---|---|"
    );
    let m: [Metric; 6] = [
        |r| r.delta.mean(),
        |r| r.true_delta.mean(),
        |r| r.p.mean(),
        |r| r.true_p.mean(),
        |r| r.deemed.mean(),
        |r| r.false_positives.mean(),
    ];
    for &n in &cfg.ns {
        let mut modes = vec![Mode::Zero];
        modes.extend(cfg.table_modes(n));
        for mode in modes {
            if let Some(g) = find(gs, Part::Table, n, mode, rr) {
                let cells: Vec<String> = m.iter().map(|&f| g.ci(f).fmt(3)).collect();
                let _ = writeln!(s, "| {n} | {} | {} |", mode.label(), cells.join(" | "));
            }
        }
    }
    let _ = writeln!(
        s,
        "\n### Perceived inaccuracy per scheduler (figure 6)\n\nMean P per frame (estimate and \
audit), T, and the paired ratio to round-robin at the same budget.\n"
    );
    for &n in &cfg.ns {
        for mode in cfg.table_modes(n) {
            let Some(base) = find(gs, Part::Table, n, mode, rr) else {
                continue;
            };
            let _ = writeln!(
                s,
                "\nN = {n}, {}:\n\n| scheduler | P | P / RR | true P | true P / RR | true Δ | T (ms) |\n|---|---|---|---|---|---|---|",
                mode.label()
            );
            for &k in &cfg.schedulers {
                let Some(g) = find(gs, Part::Table, n, mode, k) else {
                    continue;
                };
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {} | {} | {} | {} |",
                    k.name(),
                    g.ci(|r| r.p.mean()).fmt(3),
                    paired_ratio(g, base, |r| r.p.mean()).fmt(3),
                    g.ci(|r| r.true_p.mean()).fmt(3),
                    paired_ratio(g, base, |r| r.true_p.mean()).fmt(3),
                    g.ci(|r| r.true_delta.mean()).fmt(3),
                    g.ci(t_mean).fmt(3),
                );
            }
        }
    }
    s
}

/// For one N and fraction of the curves: the paper scheduler with the lowest mean true P, and the
/// paired ratio expected-gain / that scheduler.
pub fn best_vs_expected_gain(
    gs: &[Group<'_>],
    n: u32,
    f: f64,
) -> Option<(SchedulerKind, MeanCi, MeanCi)> {
    let tp: Metric = |r| r.true_p.mean();
    let mode = Mode::Fraction(f);
    let best = PAPER_SCHEDULERS
        .iter()
        .filter_map(|&k| find(gs, Part::Curves, n, mode, k))
        .min_by(|a, b| a.ci(tp).mean.total_cmp(&b.ci(tp).mean))?;
    let eg = find(gs, Part::Curves, n, mode, SchedulerKind::ExpectedGain)?;
    Some((best.scheduler, best.ci(tp), paired_ratio(eg, best, tp)))
}

/// Markdown for the curves part: true P per scheduler and budget, and expected-gain against the
/// paper's best at each budget.
pub fn curves_markdown(cfg: &StudyConfig, gs: &[Group<'_>]) -> String {
    let mut s = String::new();
    let Some(c) = &cfg.curves else {
        return s;
    };
    let tp: Metric = |r| r.true_p.mean();
    for &n in &c.ns {
        let _ = writeln!(
            s,
            "\n### True P against budget, N = {n}\n\nMean true P per frame ± 95% CI over seeds; \
budget as a fraction of the exact narrow-phase cost.\n"
        );
        let mut head = String::from("| fraction | tests |");
        let mut rule = String::from("|---|---|");
        for k in &cfg.schedulers {
            let _ = write!(head, " {} |", k.name());
            rule.push_str("---|");
        }
        let _ = writeln!(
            s,
            "{head} best paper scheduler | expected-gain / best |\n{rule}---|---|"
        );
        for &f in &c.fractions {
            let mode = Mode::Fraction(f);
            let budget = cfg
                .schedulers
                .iter()
                .find_map(|&k| find(gs, Part::Curves, n, mode, k))
                .map(|g| {
                    MeanCi::of(
                        g.runs
                            .iter()
                            .map(|r| r.budget_tests.map_or(f64::NAN, |t| t as f64)),
                    )
                });
            let _ = write!(
                s,
                "| {f} | {} |",
                budget.map(|b| sig(b.mean, 4)).unwrap_or_default()
            );
            for &k in &cfg.schedulers {
                let cell = find(gs, Part::Curves, n, mode, k)
                    .map(|g| g.ci(tp).fmt(3))
                    .unwrap_or_default();
                let _ = write!(s, " {cell} |");
            }
            match best_vs_expected_gain(gs, n, f) {
                Some((k, _, ratio)) => {
                    let _ = writeln!(s, " {} | {} |", k.name(), ratio.fmt(3));
                }
                None => {
                    let _ = writeln!(s, " – | – |");
                }
            }
        }
    }
    s
}

/// Headline numbers (paper claims) as markdown bullets.
pub fn headlines(cfg: &StudyConfig, gs: &[Group<'_>]) -> String {
    let mut s = String::new();
    let rr = SchedulerKind::RoundRobin;
    let po = SchedulerKind::PriorityOnly;
    for &n in &cfg.ns {
        let Some(exact) = find(gs, Part::Table, n, Mode::Exact, rr) else {
            continue;
        };
        for mode in cfg.table_modes(n) {
            if let Some(g) = find(gs, Part::Table, n, mode, rr) {
                let _ = writeln!(
                    s,
                    "- N = {n}, {}: T exact / interrupted = {} (mean), {} (sd)",
                    mode.label(),
                    paired_ratio(exact, g, |r| r.t_ms.mean()).fmt(3),
                    paired_ratio(exact, g, |r| r.t_ms.sd()).fmt(3),
                );
            }
            if let (Some(a), Some(b)) = (
                find(gs, Part::Table, n, mode, po),
                find(gs, Part::Table, n, mode, rr),
            ) {
                let _ = writeln!(
                    s,
                    "- N = {n}, {}: P priority-only / round-robin = {} (estimate), {} (true)",
                    mode.label(),
                    paired_ratio(a, b, |r| r.p.mean()).fmt(3),
                    paired_ratio(a, b, |r| r.true_p.mean()).fmt(3),
                );
            }
        }
    }
    if let Some(c) = &cfg.curves {
        for &n in &c.ns {
            for &f in &c.fractions {
                if let Some((k, _, ratio)) = best_vs_expected_gain(gs, n, f) {
                    let _ = writeln!(
                        s,
                        "- curves N = {n}, fraction {f}: true P expected-gain / {} = {}",
                        k.name(),
                        ratio.fmt(3)
                    );
                }
            }
        }
    }
    s
}
