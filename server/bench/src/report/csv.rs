//! The study's CSV files: one row per run, and one row per condition across seeds.

use std::fmt::Write as _;
use std::path::Path;

use super::{Group, METRICS};
use crate::error::BenchError;
use crate::runner::RunSummary;

/// Write a CSV with the commit and engine hash on every row ([`crate::stamp`]).
fn write_file(path: &Path, text: &str) -> Result<(), BenchError> {
    let stamped = crate::stamp::current().csv(text);
    std::fs::write(path, stamped).map_err(|e| BenchError::io(path, e))
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
            "{},{},{},{},{},{},{},{:.1},{},{:.5},{:.5},{:.5},{:.6e},{:.6e},{:.6e},{:.6e},{:.3},{:.3},{:.3},{:.3},{:.1},{:.4},{:.3}",
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
