//! Percentile intervals by bootstrap: each replicate redraws every cell's responses from its
//! observed proportion (the nonparametric bootstrap of trials within a cell, which keeps the
//! design fixed as psignifit's and Palamedes' do) and refits from the original estimate.

use crate::fit::{Cell, Fit, FitError, refit};
use crate::rng::Rng;

/// A parameter's estimate and its two-sided percentile interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// The maximum-likelihood estimate.
    pub estimate: f64,
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

impl Interval {
    /// Whether `x` lies within the interval (ends included).
    pub fn covers(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }
}

/// What a bootstrap gives: an interval for each fitted constant (C, or C1..C3), the
/// threshold α and the slope β, at `level` (0.95 for 95%).
#[derive(Debug, Clone, PartialEq)]
pub struct Bootstrap {
    /// One interval per constant of the function.
    pub constants: Vec<Interval>,
    /// Threshold α.
    pub alpha: Interval,
    /// Slope β.
    pub beta: Interval,
    /// Replicates that converged (of those asked).
    pub replicates: usize,
    /// Confidence level.
    pub level: f64,
}

/// Bootstrap `fit` (made on `cells`) with `replicates` resamples drawn from `seed`.
pub fn bootstrap(
    cells: &[Cell],
    fit: &Fit,
    replicates: usize,
    level: f64,
    seed: u64,
) -> Result<Bootstrap, FitError> {
    if replicates < 20 || !(0.5..1.0).contains(&level) {
        return Err(FitError::Data(format!(
            "bootstrap needs at least 20 replicates (got {replicates}) and a level in [0.5, 1) (got {level})"
        )));
    }
    let mut rng = Rng::new(seed);
    let k = fit.observer.function.constants().len();
    let mut draws: Vec<Vec<f64>> = vec![Vec::with_capacity(replicates); k + 2];
    for _ in 0..replicates {
        let resampled: Vec<Cell> = cells
            .iter()
            .map(|c| {
                let p = f64::from(c.apart) / f64::from(c.n);
                let apart = (0..c.n).filter(|_| rng.uniform() < p).count() as u32;
                Cell { apart, ..*c }
            })
            .collect();
        // A replicate the optimiser cannot fit is left out and counted: never a silent zero.
        let Ok(r) = refit(&resampled, &fit.observer) else {
            continue;
        };
        for (i, c) in r.observer.function.constants().into_iter().enumerate() {
            draws[i].push(c);
        }
        draws[k].push(r.observer.alpha);
        draws[k + 1].push(r.observer.beta);
    }
    let done = draws[k].len();
    if done < replicates / 2 {
        return Err(FitError::Optimiser(format!(
            "only {done} of {replicates} bootstrap replicates converged"
        )));
    }
    let interval = |mut v: Vec<f64>, estimate: f64| {
        v.sort_by(f64::total_cmp);
        let q = |p: f64| v[((p * (v.len() - 1) as f64).round() as usize).min(v.len() - 1)];
        let (lo, hi) = (q((1.0 - level) / 2.0), q(1.0 - (1.0 - level) / 2.0));
        // The basic bootstrap on the log scale: the replicates' spread about the estimate,
        // mirrored, which corrects the percentile interval's skew for a scale parameter.
        Interval {
            estimate,
            lo: estimate * estimate / hi,
            hi: estimate * estimate / lo,
        }
    };
    let estimates = fit.observer.function.constants();
    let mut it = draws.into_iter();
    let constants = estimates
        .iter()
        .map(|&e| interval(it.next().unwrap_or_default(), e))
        .collect();
    Ok(Bootstrap {
        constants,
        alpha: interval(it.next().unwrap_or_default(), fit.observer.alpha),
        beta: interval(it.next().unwrap_or_default(), fit.observer.beta),
        replicates: done,
        level,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::{cells, fit_cells};
    use crate::model::{Function, Observer};
    use crate::simulate::{Design, simulate};

    #[test]
    fn the_interval_brackets_the_estimate_and_narrows_with_data() {
        let truth = Observer {
            function: Function::F2 { c: 4.0 },
            alpha: 0.05,
            beta: 2.5,
            guess: 0.05,
            lapse: 0.02,
        };
        let width = |repetitions: u32| {
            let design = Design {
                repetitions,
                ..Design::default()
            };
            let cells = cells(&simulate(&truth, &design, 5));
            let f = fit_cells(&cells, Function::F2 { c: 1.0 }).expect("fits");
            let b = bootstrap(&cells, &f, 60, 0.95, 9).expect("bootstraps");
            let c = b.constants[0];
            assert!(c.lo <= c.estimate && c.estimate <= c.hi, "{c:?}");
            assert!(b.replicates >= 55, "{}", b.replicates);
            c.hi - c.lo
        };
        let (small, large) = (width(10), width(80));
        assert!(large < 0.75 * small, "{large} vs {small}");
    }

    #[test]
    fn too_few_replicates_are_refused() {
        let f = Fit {
            observer: Observer {
                function: Function::F1,
                alpha: 1.0,
                beta: 1.0,
                guess: 0.1,
                lapse: 0.01,
            },
            log_likelihood: 0.0,
            trials: 0,
            parameters: 4,
        };
        assert!(bootstrap(&[], &f, 5, 0.95, 1).is_err());
    }
}
