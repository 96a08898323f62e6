//! The fit a user reads: detection per cell with its interval, each function's fit and
//! cross-validated standing, F2's C with its bootstrap interval, and the model string to hand
//! the server (`--schedule-model`, `--measure-model`).

use std::fmt::Write as _;

use crate::bootstrap::{Bootstrap, bootstrap};
use crate::compare::{Standing, compare};
use crate::fit::{Cell, FitError, MAX_C, cells};
use crate::model::Function;
use crate::trial::Trial;

/// How to fit.
#[derive(Debug, Clone, PartialEq)]
pub struct Options {
    /// Bootstrap replicates.
    pub replicates: usize,
    /// Cross-validation folds.
    pub folds: usize,
    /// Seed of the bootstrap and the folds.
    pub seed: u64,
    /// F3's two breaks (degrees).
    pub f3_breaks: [f64; 2],
    /// Fit each participant apart as well as pooled.
    pub per_participant: bool,
}

impl Default for Options {
    fn default() -> Self {
        Self {
            replicates: 200,
            folds: 5,
            seed: 1,
            f3_breaks: [2.5, 10.0],
            per_participant: true,
        }
    }
}

/// The fit of one group of trials (a participant, or all pooled).
#[derive(Debug, Clone, PartialEq)]
pub struct GroupFit {
    /// Who: a participant id, or `pooled`.
    pub group: String,
    /// Cells fitted.
    pub cells: Vec<Cell>,
    /// Functions by cross-validated likelihood, best first.
    pub standings: Vec<Standing>,
    /// F2's C (and α, β) with intervals.
    pub f2: Bootstrap,
}

impl GroupFit {
    /// The model string of the best function by cross-validation.
    pub fn best_model(&self) -> String {
        self.standings
            .first()
            .map(|s| s.fit.observer.function.to_string())
            .unwrap_or_default()
    }

    /// The model string of the fitted F2.
    pub fn f2_model(&self) -> String {
        Function::F2 {
            c: self.f2.constants.first().map_or(f64::NAN, |i| i.estimate),
        }
        .to_string()
    }
}

/// Fit F1, F2 and F3 to `trials`, pooled and (if asked and there are several) per participant.
pub fn fit_groups(trials: &[Trial], options: &Options) -> Result<Vec<GroupFit>, FitError> {
    let mut groups: Vec<(String, Vec<Trial>)> = vec![("pooled".into(), trials.to_vec())];
    if options.per_participant {
        let mut ids: Vec<&str> = trials.iter().map(|t| t.participant.as_str()).collect();
        ids.sort_unstable();
        ids.dedup();
        if ids.len() > 1 {
            for id in ids {
                let mine: Vec<Trial> = trials
                    .iter()
                    .filter(|t| t.participant == id)
                    .cloned()
                    .collect();
                groups.push((id.to_string(), mine));
            }
        }
    }
    let [e1, e2] = options.f3_breaks;
    let functions = [
        Function::F1,
        Function::F2 { c: 1.0 },
        Function::F3 {
            c1: 1.0,
            c2: 1.0,
            c3: 1.0,
            e1,
            e2,
        },
    ];
    groups
        .into_iter()
        .map(|(group, trials)| {
            let standings = compare(&trials, &functions, options.folds, options.seed)
                .map_err(|e| FitError::Data(format!("{group}: {e}")))?;
            let cells = cells(&trials);
            let f2 = standings
                .iter()
                .find(|s| s.fit.observer.function.name() == "F2")
                .map(|s| s.fit.clone())
                .ok_or_else(|| FitError::Data("F2 was not fitted".into()))?;
            let f2 = bootstrap(&cells, &f2, options.replicates, 0.95, options.seed)
                .map_err(|e| FitError::Data(format!("{group}: {e}")))?;
            Ok(GroupFit {
                group,
                cells,
                standings,
                f2,
            })
        })
        .collect()
}

/// Wilson's 95% interval of a binomial proportion `k` of `n`.
pub fn wilson(k: u32, n: u32) -> (f64, f64) {
    if n == 0 {
        return (0.0, 1.0);
    }
    let (n, p, z) = (f64::from(n), f64::from(k) / f64::from(n), 1.959_964);
    let centre = (p + z * z / (2.0 * n)) / (1.0 + z * z / n);
    let half = z / (1.0 + z * z / n) * (p * (1.0 - p) / n + z * z / (4.0 * n * n)).sqrt();
    ((centre - half).max(0.0), (centre + half).min(1.0))
}

/// The fits as a markdown report.
pub fn markdown(fits: &[GroupFit], options: &Options) -> String {
    let mut s = String::new();
    for g in fits {
        let n: u32 = g.cells.iter().map(|c| c.n).sum();
        let _ = writeln!(s, "## {} ({n} trials)\n", g.group);
        let _ = writeln!(
            s,
            "| eccentricity (deg) | gap (deg) | n | reported apart | 95% CI (Wilson) |\n|---|---|---|---|---|"
        );
        for c in &g.cells {
            let (lo, hi) = wilson(c.apart, c.n);
            let _ = writeln!(
                s,
                "| {} | {} | {} | {:.2} | {lo:.2}-{hi:.2} |",
                c.eccentricity_deg,
                c.gap_deg,
                c.n,
                f64::from(c.apart) / f64::from(c.n)
            );
        }
        let _ = writeln!(
            s,
            "\n| function | constants (deg) | α (deg) | β | γ | λ | ln L | AIC | cross-validated ln L ({} folds) |\n|---|---|---|---|---|---|---|---|---|",
            options.folds
        );
        for st in &g.standings {
            let o = &st.fit.observer;
            let k: Vec<String> = o
                .function
                .constants()
                .iter()
                .map(|&c| {
                    if c >= 0.999 * MAX_C {
                        format!("{MAX_C} (unbounded: not identified)")
                    } else {
                        format!("{c:.3}")
                    }
                })
                .collect();
            let _ = writeln!(
                s,
                "| {} | {} | {:.4} | {:.2} | {:.3} | {:.3} | {:.1} | {:.1} | {:.1} |",
                o.function.name(),
                if k.is_empty() {
                    "-".into()
                } else {
                    k.join(", ")
                },
                o.alpha,
                o.beta,
                o.guess,
                o.lapse,
                st.fit.log_likelihood,
                st.fit.aic(),
                st.cross_validated
            );
        }
        if let Some(c) = g.f2.constants.first() {
            let _ = writeln!(
                s,
                "\nF2: C = {:.3} deg, {:.0}% CI {:.3}-{:.3} (basic bootstrap on log C, {} of {} replicates).  ",
                c.estimate,
                100.0 * g.f2.level,
                c.lo,
                c.hi,
                g.f2.replicates,
                options.replicates
            );
        }
        let _ = writeln!(
            s,
            "Best by cross-validation: {}. Model strings: `--schedule-model {}` (F2), `{}` (best).\n",
            g.standings
                .first()
                .map_or("-", |s| s.fit.observer.function.name()),
            g.f2_model(),
            g.best_model()
        );
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wilson_intervals_hold_the_proportion_and_stay_in_range() {
        let (lo, hi) = wilson(0, 10);
        assert_eq!(lo, 0.0);
        assert!(hi > 0.25 && hi < 0.35, "{hi}");
        let (lo, hi) = wilson(50, 100);
        assert!(lo < 0.5 && hi > 0.5 && (0.5 - lo - (hi - 0.5)).abs() < 1e-12);
    }
}
