//! Summaries across seeds and paired ratios; what is written from them lives in [`csv`] (the
//! machine-readable runs and summaries) and [`markdown`] (the tables and headlines of a report).
//!
//! Every mean across seeds carries a 95% confidence interval (Student's t over seeds). Ratios between
//! two conditions are *paired*: computed per seed (same scene, same gaze), then averaged with a CI.

pub mod csv;
pub mod markdown;

pub use csv::{write_runs_csv, write_summary_csv};
pub use markdown::{
    best_vs_expected_gain, curves_markdown, describe, f1_markdown, headlines, table_markdown,
};

use foveal_engine::SchedulerKind;

use crate::protocol::{Mode, Part};
use crate::ratio::RatioCi;
use crate::runner::RunSummary;
use crate::stats::MeanCi;

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

    /// Whether no frame of any seed was interrupted: the budget covered the whole exact narrow
    /// phase every time, so the cell says nothing about interruption (nothing is deemed and P is
    /// zero by construction). Reports mark such cells and headlines leave them out.
    pub fn never_interrupts(&self) -> bool {
        self.mode != crate::protocol::Mode::Exact
            && !self.runs.is_empty()
            && self.runs.iter().all(|r| r.exhausted.mean() == 0.0)
    }

    /// Whether no frame of any seed did a sphere test under an interrupted budget: it ran out
    /// before the narrow phase (a wall-clock budget the broad phase spends), so every candidate
    /// was deemed whatever the scheduler, and schedulers cannot differ there.
    pub fn never_tests(&self) -> bool {
        !matches!(
            self.mode,
            crate::protocol::Mode::Exact | crate::protocol::Mode::Zero
        ) && !self.runs.is_empty()
            && self.runs.iter().all(|r| r.tests.mean() == 0.0)
    }

    /// Mean of a metric across seeds with its bootstrap interval (what a figure draws: on a log
    /// axis it stays positive where every seed is).
    pub fn boot(&self, m: Metric) -> RatioCi {
        RatioCi::mean(self.runs.iter().map(|r| m(r)))
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

/// Paired ratio of `m` over seeds: the ratio of the means of `a` and `b` on the seeds both ran,
/// with its bootstrap interval over seeds ([`RatioCi`]).
pub fn paired_ratio(a: &Group<'_>, b: &Group<'_>, m: Metric) -> RatioCi {
    RatioCi::of(a.runs.iter().filter_map(|ra| {
        b.runs
            .iter()
            .find(|rb| rb.spec.seed == ra.spec.seed)
            .map(|rb| (m(ra), m(rb)))
    }))
}
