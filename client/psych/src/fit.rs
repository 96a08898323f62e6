//! Maximum-likelihood fits of the observer model (the crate's doc) to trials.
//!
//! Trials are pooled into cells of equal gap and eccentricity (a binomial count each), and the
//! negative log-likelihood is minimised by Nelder-Mead (`argmin`) over unconstrained
//! parameters: logarithms of α, β and the constants C, and scaled logits of γ in (0, 0.5) and
//! λ in (0, 0.1), the bounds psignifit uses by default for a yes/no task. Likelihoods of this
//! kind have flat ridges (α against C when few eccentricities are tested), so the fit starts
//! from several points and keeps the best.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;
use thiserror::Error;

use crate::model::{Function, Observer};
use crate::trial::Trial;

/// Upper bound of the guess rate γ.
pub const MAX_GUESS: f64 = 0.5;
/// Upper bound of the lapse rate λ.
pub const MAX_LAPSE: f64 = 0.1;
/// Least fall-off constant C fitted (degrees).
pub const MIN_C: f64 = 0.01;
/// Greatest fall-off constant C fitted (degrees): beyond it F2 is flat over any display, and a
/// constant that runs here is not identified by the data (say, F3's C1 with no eccentricity
/// tested below its break).
pub const MAX_C: f64 = 1000.0;

/// A fit that cannot be made.
#[derive(Debug, Error, PartialEq)]
pub enum FitError {
    /// Too few trials, or none with a gap.
    #[error("{0}")]
    Data(String),
    /// The optimiser failed.
    #[error("optimiser: {0}")]
    Optimiser(String),
}

/// Trials of one gap and eccentricity: `apart` of `n` reported "apart".
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cell {
    /// Gap (degrees).
    pub gap_deg: f64,
    /// Eccentricity (degrees).
    pub eccentricity_deg: f64,
    /// Trials.
    pub n: u32,
    /// Of which reported "apart".
    pub apart: u32,
}

/// The trials pooled into cells, in order of eccentricity then gap.
pub fn cells(trials: &[Trial]) -> Vec<Cell> {
    let mut cells: Vec<Cell> = Vec::new();
    let mut sorted: Vec<&Trial> = trials.iter().collect();
    sorted.sort_by(|a, b| {
        a.eccentricity_deg
            .total_cmp(&b.eccentricity_deg)
            .then(a.gap_deg.total_cmp(&b.gap_deg))
    });
    for t in sorted {
        match cells.last_mut() {
            Some(c) if c.gap_deg == t.gap_deg && c.eccentricity_deg == t.eccentricity_deg => {
                c.n += 1;
                c.apart += u32::from(t.apart);
            }
            _ => cells.push(Cell {
                gap_deg: t.gap_deg,
                eccentricity_deg: t.eccentricity_deg,
                n: 1,
                apart: u32::from(t.apart),
            }),
        }
    }
    cells
}

/// A fitted observer.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The maximum-likelihood observer.
    pub observer: Observer,
    /// Its log-likelihood.
    pub log_likelihood: f64,
    /// Trials fitted.
    pub trials: u32,
    /// Free parameters (for AIC).
    pub parameters: usize,
}

impl Fit {
    /// Akaike's information criterion, 2k - 2 ln L.
    pub fn aic(&self) -> f64 {
        2.0 * self.parameters as f64 - 2.0 * self.log_likelihood
    }
}

/// Fit `function`'s constants (the values in `function` are ignored; the breaks of F3 are
/// kept) and the psychometric function to `trials`.
pub fn fit(trials: &[Trial], function: Function) -> Result<Fit, FitError> {
    fit_cells(&cells(trials), function)
}

/// [`fit`] on pooled cells.
pub fn fit_cells(cells: &[Cell], function: Function) -> Result<Fit, FitError> {
    let n: u32 = cells.iter().map(|c| c.n).sum();
    let gaps: Vec<f64> = cells
        .iter()
        .filter(|c| c.gap_deg > 0.0)
        .map(|c| c.gap_deg)
        .collect();
    if gaps.is_empty() {
        return Err(FitError::Data(
            "no trial with a gap: the threshold cannot be fitted".into(),
        ));
    }
    let k = function.constants().len();
    if n < 4 + k as u32 {
        return Err(FitError::Data(format!(
            "{n} trials for {} parameters",
            4 + k
        )));
    }
    let mut sorted = gaps.clone();
    sorted.sort_by(f64::total_cmp);
    let median_gap = sorted[sorted.len() / 2];
    let touching: (u32, u32) = cells
        .iter()
        .filter(|c| c.gap_deg <= 0.0)
        .fold((0, 0), |(n, a), c| (n + c.n, a + c.apart));
    let guess = if touching.0 > 0 {
        (f64::from(touching.1) / f64::from(touching.0)).clamp(0.01, 0.4)
    } else {
        0.05
    };
    let problem = Likelihood { cells, function };
    let mut best: Option<(Vec<f64>, f64)> = None;
    let c_starts: &[f64] = if k == 0 { &[1.0] } else { &[1.0, 4.0, 15.0] };
    for &alpha in &[0.5 * median_gap, 2.0 * median_gap] {
        for &c in c_starts {
            let start = Params {
                alpha,
                beta: 2.0,
                guess,
                lapse: 0.02,
                constants: vec![c; k],
            }
            .to_vec();
            let (p, cost) = minimise(&problem, start)?;
            if best.as_ref().is_none_or(|(_, b)| cost < *b) {
                best = Some((p, cost));
            }
        }
    }
    let Some((p, cost)) = best else {
        return Err(FitError::Optimiser("no start converged".into()));
    };
    let p = Params::from_vec(&p, k);
    Ok(Fit {
        observer: p.observer(function),
        log_likelihood: -cost,
        trials: n,
        parameters: 4 + k,
    })
}

/// [`fit_cells`] from one start, the observer `start` (a bootstrap replicate starts from the
/// original fit: its optimum is near).
pub fn refit(cells: &[Cell], start: &Observer) -> Result<Fit, FitError> {
    let function = start.function;
    let k = function.constants().len();
    let problem = Likelihood { cells, function };
    let p = Params {
        alpha: start.alpha,
        beta: start.beta,
        guess: start.guess.clamp(1e-6, MAX_GUESS - 1e-6),
        lapse: start.lapse.clamp(1e-6, MAX_LAPSE - 1e-6),
        constants: function.constants(),
    };
    let (v, cost) = minimise(&problem, p.to_vec())?;
    Ok(Fit {
        observer: Params::from_vec(&v, k).observer(function),
        log_likelihood: -cost,
        trials: cells.iter().map(|c| c.n).sum(),
        parameters: 4 + k,
    })
}

/// Nelder-Mead from `start`, restarted once from its own optimum (a simplex that collapsed on a
/// ridge recovers), returning the parameters and the negative log-likelihood.
fn minimise(problem: &Likelihood<'_>, start: Vec<f64>) -> Result<(Vec<f64>, f64), FitError> {
    let mut x = start;
    let mut cost = f64::INFINITY;
    for _ in 0..2 {
        let simplex: Vec<Vec<f64>> = std::iter::once(x.clone())
            .chain((0..x.len()).map(|i| {
                let mut v = x.clone();
                v[i] += 0.5;
                v
            }))
            .collect();
        let solver = NelderMead::new(simplex)
            .with_sd_tolerance(1e-9)
            .map_err(|e| FitError::Optimiser(e.to_string()))?;
        let run = Executor::new(problem.clone(), solver)
            .configure(|state| state.max_iters(4000))
            .run()
            .map_err(|e| FitError::Optimiser(e.to_string()))?;
        let state = run.state();
        if let Some(p) = state.get_best_param() {
            x = p.clone();
            cost = state.get_best_cost();
        }
    }
    Ok((x, cost))
}

/// The observer's parameters in the fit's unconstrained coordinates.
#[derive(Debug, Clone, PartialEq)]
struct Params {
    alpha: f64,
    beta: f64,
    guess: f64,
    lapse: f64,
    constants: Vec<f64>,
}

fn logit(p: f64) -> f64 {
    (p / (1.0 - p)).ln()
}

fn sigmoid(x: f64) -> f64 {
    1.0 / (1.0 + (-x).exp())
}

impl Params {
    fn to_vec(&self) -> Vec<f64> {
        let mut v = vec![
            self.alpha.ln(),
            self.beta.ln(),
            logit(self.guess / MAX_GUESS),
            logit(self.lapse / MAX_LAPSE),
        ];
        v.extend(self.constants.iter().map(|c| c.ln()));
        v
    }

    fn from_vec(v: &[f64], k: usize) -> Self {
        Self {
            alpha: v[0].exp(),
            beta: v[1].exp(),
            guess: MAX_GUESS * sigmoid(v[2]),
            lapse: MAX_LAPSE * sigmoid(v[3]),
            constants: v[4..4 + k].iter().map(|x| x.exp()).collect(),
        }
    }

    fn observer(&self, function: Function) -> Observer {
        Observer {
            function: function.with_constants(&self.constants),
            alpha: self.alpha,
            beta: self.beta,
            guess: self.guess,
            lapse: self.lapse,
        }
    }
}

/// The negative log-likelihood of cells under a function's observer.
#[derive(Debug, Clone)]
struct Likelihood<'a> {
    cells: &'a [Cell],
    function: Function,
}

impl CostFunction for Likelihood<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, v: &Self::Param) -> Result<f64, argmin::core::Error> {
        let k = self.function.constants().len();
        // Far outside any plausible value the likelihood is flat; a wall keeps the simplex home.
        if v.iter().any(|x| !x.is_finite() || x.abs() > 30.0)
            || v[4..]
                .iter()
                .any(|c| !(MIN_C.ln()..=MAX_C.ln()).contains(c))
        {
            return Ok(f64::MAX);
        }
        let observer = Params::from_vec(v, k).observer(self.function);
        Ok(-log_likelihood(&observer, self.cells))
    }
}

/// The log-likelihood of `cells` under `observer` (binomial, without the constant binomial
/// coefficients).
pub fn log_likelihood(observer: &Observer, cells: &[Cell]) -> f64 {
    cells
        .iter()
        .map(|c| {
            let p = observer
                .p_apart(c.gap_deg, c.eccentricity_deg)
                .clamp(1e-12, 1.0 - 1e-12);
            f64::from(c.apart) * p.ln() + f64::from(c.n - c.apart) * (1.0 - p).ln()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::simulate::{Design, simulate};

    fn observer(c: f64) -> Observer {
        Observer {
            function: Function::F2 { c },
            alpha: 0.05,
            beta: 2.5,
            guess: 0.08,
            lapse: 0.02,
        }
    }

    #[test]
    fn a_large_sample_recovers_the_observer() {
        let design = Design {
            repetitions: 60,
            ..Design::default()
        };
        let trials = simulate(&observer(4.0), &design, 11);
        let f = fit(&trials, Function::F2 { c: 1.0 }).expect("fits");
        let c = f.observer.function.constants()[0];
        assert!((c - 4.0).abs() < 0.6, "C = {c}");
        assert!((f.observer.alpha - 0.05).abs() < 0.01, "{:?}", f.observer);
        assert!((f.observer.guess - 0.08).abs() < 0.03, "{:?}", f.observer);
        // The maximum is a maximum: the true observer is no more likely.
        assert!(f.log_likelihood >= log_likelihood(&observer(4.0), &cells(&trials)) - 1e-6);
    }

    #[test]
    fn trials_without_a_gap_are_refused_plainly() {
        let trials = vec![
            Trial {
                participant: "p".into(),
                eccentricity_deg: 1.0,
                gap_deg: 0.0,
                apart: false,
            };
            10
        ];
        let e = fit(&trials, Function::F2 { c: 1.0 }).expect_err("refused");
        assert!(e.to_string().contains("no trial with a gap"), "{e}");
    }
}
