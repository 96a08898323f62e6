//! Primary endpoints: for each claim the open loop tests, one cell named before the run (in the
//! protocol, [`crate::open_loop::OpenLoopConfig::primary`]) and tested alone at α = 0.05; every
//! other cell is secondary, and its "halves round-robin's P" is reported only after Holm's
//! correction over all of them. Without this a table of hundreds of cells will show some
//! "halvings" by chance, and a reader cannot tell the claim from the search for one.

use std::fmt::Write as _;

use crate::open_loop::{Budget, SummaryRow};
use crate::ratio::holm;
use crate::stats::sig;

/// Significance level of every test of the study.
pub const ALPHA: f64 = 0.05;

/// One claim and the cell that decides it.
#[derive(Debug, Clone, PartialEq)]
pub struct Endpoint {
    /// The claim, as a reader would state it, with where it comes from.
    pub claim: String,
    /// Bodies.
    pub n: u32,
    /// Condition name (the perceptual model and what the scheduler is told of the gaze).
    pub condition: String,
    /// Budget.
    pub budget: Budget,
    /// Scheduler label, compared with round-robin on the same frames. Every claim is the
    /// paper's form, "halves round-robin's true P": it holds when the ratio is shown below
    /// [`crate::plots::PAPER_P_RATIO`].
    pub scheduler: String,
}

impl Endpoint {
    /// Whether `row` is this endpoint's cell.
    pub fn is(&self, row: &SummaryRow) -> bool {
        row.n == self.n
            && row.condition == self.condition
            && row.budget == self.budget.label()
            && row.scheduler == self.scheduler
    }
}

/// What the test of an endpoint found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Verdict {
    /// The ratio is shown below one half.
    Reproduces,
    /// The ratio is shown below 1 (the scheduler beats round-robin) but not below one half.
    Partly,
    /// Not shown below 1.
    DoesNot,
    /// The test could not be computed (a seed with zero P, fewer than two seeds).
    Untestable,
    /// The cell was not run by this protocol.
    NotRun,
}

impl Verdict {
    /// The phrase the report uses.
    pub fn phrase(&self) -> &'static str {
        match self {
            Self::Reproduces => "reproduces",
            Self::Partly => "only in part (below round-robin, not below half of it)",
            Self::DoesNot => "does not reproduce",
            Self::Untestable => {
                "untestable (a seed with zero or no error, too few seeds, or no spread)"
            }
            Self::NotRun => "not run by this protocol",
        }
    }
}

/// The verdict on `e` from the summary rows: its cell's one-sided p-values against one half and
/// against 1, unadjusted (it is the one test of its claim).
pub fn verdict(e: &Endpoint, rows: &[SummaryRow]) -> Verdict {
    let Some(row) = rows.iter().find(|r| e.is(r)) else {
        return Verdict::NotRun;
    };
    match (row.p_halves, row.p_below_rr) {
        (Some(p), _) if p <= ALPHA => Verdict::Reproduces,
        (_, Some(p)) if p <= ALPHA => Verdict::Partly,
        (_, Some(_)) => Verdict::DoesNot,
        _ => Verdict::Untestable,
    }
}

/// Holm-adjusted p-values of "halves round-robin's P" for every secondary cell (a scheduler other
/// than round-robin and the clairvoyant bound, not a primary endpoint, with a computable test),
/// by row index; `None` outside the family.
pub fn secondary_halving(rows: &[SummaryRow], primary: &[Endpoint]) -> Vec<Option<f64>> {
    let family: Vec<(usize, f64)> = rows
        .iter()
        .enumerate()
        .filter(|(_, r)| r.scheduler != "round-robin" && r.scheduler != "clairvoyant")
        .filter(|(_, r)| !primary.iter().any(|e| e.is(r)))
        .filter_map(|(i, r)| r.p_halves.map(|p| (i, p)))
        .collect();
    let adjusted = holm(&family.iter().map(|f| f.1).collect::<Vec<_>>());
    let mut out = vec![None; rows.len()];
    for ((i, _), a) in family.iter().zip(adjusted) {
        out[*i] = Some(a);
    }
    out
}

/// The report's section on the primary endpoints: each claim, its cell, the ratio with its
/// interval and n, the p-value and the verdict.
pub fn markdown(primary: &[Endpoint], rows: &[SummaryRow]) -> String {
    if primary.is_empty() {
        // An exploratory protocol (the grid): every cell is secondary.
        return String::new();
    }
    let mut s = String::from(
        "### Primary endpoints\n\nNamed in the protocol before the run; each is the one test of \
         its claim (one-sided t on the per-seed log ratios, α = 0.05, no correction). Ratio: mean \
         true P over round-robin's on the same frames, 95% bootstrap interval over seeds.\n\n\
         | claim | cell | ratio [95% CI] | p (below 1/2) | p (below 1) | verdict |\n\
         | --- | --- | --- | --- | --- | --- |\n",
    );
    for e in primary {
        let row = rows.iter().find(|r| e.is(r));
        let p = |x: Option<f64>| x.map_or("–".to_string(), |p| sig(p, 2));
        let _ = writeln!(
            s,
            "| {} | N = {}, {}, {}, {} | {} | {} | {} | {} |",
            e.claim,
            e.n,
            e.condition,
            e.budget.label(),
            e.scheduler,
            row.map_or("–".to_string(), |r| r.ratio_rr.fmt(2)),
            p(row.and_then(|r| r.p_halves)),
            p(row.and_then(|r| r.p_below_rr)),
            verdict(e, rows).phrase()
        );
    }
    s.push('\n');
    s
}
