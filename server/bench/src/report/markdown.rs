//! The study's markdown: the protocol, the tables of each part and the headline ratios.

use std::fmt::Write as _;

use foveal_engine::SchedulerKind;

use super::{Group, Metric, find, paired_ratio};
use crate::protocol::{Mode, Part, StudyConfig};
use crate::ratio::RatioCi;
use crate::stats::{MeanCi, sig};

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
        "- perceptual model (schedule and measure): {}{}; priority-queue threshold {}°; audit on",
        model_name(cfg),
        if cfg.f1 {
            " (the F1 case: F1 in pixels, both)"
        } else {
            ""
        },
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
                "| {n} | {}{} | {} | {} | {} | {rm} | {rs} |",
                mode.label(),
                never_mark(g),
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
    let m: Vec<Metric> = INACCURACY
        .into_iter()
        .chain([(|r| r.false_positives.mean()) as Metric])
        .collect();
    for &n in &cfg.ns {
        let mut modes = vec![Mode::Zero];
        modes.extend(cfg.table_modes(n));
        for mode in modes {
            if let Some(g) = find(gs, Part::Table, n, mode, rr) {
                let cells: Vec<String> = m.iter().map(|&f| g.ci(f).fmt(3)).collect();
                let _ = writeln!(
                    s,
                    "| {n} | {}{} | {} |",
                    mode.label(),
                    never_mark(g),
                    cells.join(" | ")
                );
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
                "\nN = {n}, {}{}:\n\n| scheduler | P | P / RR | true P | true P / RR | true Δ | T (ms) |\n|---|---|---|---|---|---|---|",
                mode.label(),
                never_mark(base)
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
    let _ = writeln!(s, "{NEVER_NOTE}");
    s
}

/// Δ, true Δ, P, true P and the deemed pairs: the columns every inaccuracy table starts with.
const INACCURACY: [Metric; 5] = [
    |r| r.delta.mean(),
    |r| r.true_delta.mean(),
    |r| r.p.mean(),
    |r| r.true_p.mean(),
    |r| r.deemed.mean(),
];

/// What marks a cell whose budget never interrupted ([`Group::never_interrupts`]).
const NEVER: &str = " (never interrupts)";

/// What marks a cell whose budget ended before any sphere test ([`Group::never_tests`]).
const NO_TESTS: &str = " (no sphere test)";

/// The note under a table that may hold such cells.
const NEVER_NOTE: &str = "\n*(never interrupts)*: no frame of any seed ran out of budget; the \
cell measures nothing about interruption and the headlines leave it out. *(no sphere test)*: no \
frame of any seed reached the narrow phase (the budget ended in the broad phase), so every \
candidate was deemed whatever the scheduler.";

fn never_mark(g: &Group<'_>) -> &'static str {
    if g.never_interrupts() {
        NEVER
    } else if g.never_tests() {
        NO_TESTS
    } else {
        ""
    }
}

/// The paper's F1 case ([`Part::F1`]): perceptually sorted sequential scheduling against
/// round-robin, F1 in pixels both to schedule and to measure, at the paper's target times
/// (figures 5(b) and 6(a)). The paper: sorted scheduling "decoupled" P's increase from Δ's, but
/// its sort costs time, so at 300 objects Δ and even the absolute P rose, while at 500 P "is
/// slightly improved".
pub fn f1_markdown(cfg: &StudyConfig, gs: &[Group<'_>]) -> String {
    let mut s = String::new();
    let rr = SchedulerKind::RoundRobin;
    let sorted = SchedulerKind::SortedSequential;
    let _ = writeln!(
        s,
        "### The paper's F1 case (figures 5(b) and 6(a))\n\nPerceptually sorted sequential \
scheduling against round-robin with F1 (gap over eccentricity, in pixels) both to schedule and to \
measure, closed loop, at each N's budget. P is the paper's estimate, true P the audit's. Means \
over seeds with 95% t intervals; ratios sorted / round-robin paired by seed (ratio of means, \
95% bootstrap interval).\n"
    );
    let _ = writeln!(
        s,
        "| N | mode | scheduler | Δ | true Δ | P (F1) | true P (F1) | deemed | T (ms) |\n|---|---|---|---|---|---|---|---|---|"
    );
    let m: Vec<Metric> = INACCURACY
        .into_iter()
        .chain([(|r| r.t_ms.mean()) as Metric])
        .collect();
    for &n in &cfg.ns {
        let mut rows = vec![(Mode::Zero, rr)];
        for mode in cfg.f1_modes(n) {
            rows.extend(StudyConfig::F1_SCHEDULERS.iter().map(|&k| (mode, k)));
        }
        for (mode, k) in rows {
            if let Some(g) = find(gs, Part::F1, n, mode, k) {
                let cells: Vec<String> = m.iter().map(|&f| g.ci(f).fmt(3)).collect();
                let _ = writeln!(
                    s,
                    "| {n} | {}{} | {} | {} |",
                    mode.label(),
                    never_mark(g),
                    k.name(),
                    cells.join(" | ")
                );
            }
        }
    }
    let _ = writeln!(
        s,
        "\nSorted / round-robin at the same budget: P falls further than Δ where sorting \
decouples them (the paper's figure 5(b)).\n\n| N | mode | Δ | true Δ | P (F1) | true P (F1) |\n|---|---|---|---|---|---|"
    );
    for &n in &cfg.ns {
        for mode in cfg.f1_modes(n) {
            let (Some(a), Some(b)) = (
                find(gs, Part::F1, n, mode, sorted),
                find(gs, Part::F1, n, mode, rr),
            ) else {
                continue;
            };
            let cells: Vec<String> = m[..4]
                .iter()
                .map(|&f| paired_ratio(a, b, f).fmt(3))
                .collect();
            let _ = writeln!(
                s,
                "| {n} | {}{} | {} |",
                mode.label(),
                never_mark(b),
                cells.join(" | ")
            );
        }
    }
    let _ = writeln!(s, "{NEVER_NOTE}");
    s
}

/// For one N and fraction of the curves: the paper scheduler with the lowest mean true P, and the
/// paired ratio expected-gain / that scheduler.
pub fn best_vs_expected_gain(
    gs: &[Group<'_>],
    n: u32,
    f: f64,
) -> Option<(SchedulerKind, MeanCi, RatioCi)> {
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
            if find(gs, Part::Table, n, mode, rr).is_some_and(Group::never_interrupts) {
                let _ = writeln!(
                    s,
                    "- N = {n}, {}: never interrupts (the budget covers every exact frame); left \
                     out",
                    mode.label()
                );
                continue;
            }
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
