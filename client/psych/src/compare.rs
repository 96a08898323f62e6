//! Which perceptual function predicts held-out responses best: k-fold cross-validated
//! log-likelihood, with AIC beside it. A function with more constants (F3) can only fit the
//! data it saw better; on trials it did not see it must earn its constants.

use crate::fit::{Cell, Fit, FitError, cells, fit_cells, log_likelihood};
use crate::model::Function;
use crate::rng::Rng;
use crate::trial::Trial;

/// One function's standing.
#[derive(Debug, Clone, PartialEq)]
pub struct Standing {
    /// The function, with the constants fitted on all trials.
    pub fit: Fit,
    /// Held-out log-likelihood summed over folds.
    pub cross_validated: f64,
}

/// Each function of `functions` fitted to `trials` and scored on `folds` held-out folds
/// (trials dealt to folds at random from `seed`), best first.
pub fn compare(
    trials: &[Trial],
    functions: &[Function],
    folds: usize,
    seed: u64,
) -> Result<Vec<Standing>, FitError> {
    if folds < 2 || trials.len() < 2 * folds {
        return Err(FitError::Data(format!(
            "{} trials cannot be split into {folds} folds of at least 2 (folds must be >= 2)",
            trials.len()
        )));
    }
    let mut order: Vec<usize> = (0..trials.len()).collect();
    let mut rng = Rng::new(seed);
    for i in (1..order.len()).rev() {
        order.swap(i, rng.below(i + 1));
    }
    let fold_of: Vec<usize> = {
        let mut f = vec![0; trials.len()];
        for (rank, &i) in order.iter().enumerate() {
            f[i] = rank % folds;
        }
        f
    };
    let split = |k: usize, held: bool| -> Vec<Cell> {
        let chosen: Vec<Trial> = trials
            .iter()
            .zip(&fold_of)
            .filter(|(_, f)| (**f == k) == held)
            .map(|(t, _)| t.clone())
            .collect();
        cells(&chosen)
    };
    let mut out = Vec::new();
    for &function in functions {
        let all = fit_cells(&cells(trials), function)?;
        let mut held_out = 0.0;
        for k in 0..folds {
            let f = fit_cells(&split(k, false), function)?;
            held_out += log_likelihood(&f.observer, &split(k, true));
        }
        out.push(Standing {
            fit: all,
            cross_validated: held_out,
        });
    }
    out.sort_by(|a, b| b.cross_validated.total_cmp(&a.cross_validated));
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Observer;
    use crate::simulate::{Design, simulate};

    #[test]
    fn the_generating_function_wins_on_held_out_trials() {
        // With C = 8 F2 falls off far more gently than F1 beyond the fovea (0.73 against 0.4
        // at 2.5 degrees); at C of about 3 the two are alike over this design.
        let truth = Observer {
            function: Function::F2 { c: 8.0 },
            alpha: 0.05,
            beta: 2.5,
            guess: 0.05,
            lapse: 0.02,
        };
        let design = Design {
            repetitions: 20,
            ..Design::default()
        };
        let trials = simulate(&truth, &design, 21);
        let standings =
            compare(&trials, &[Function::F1, Function::F2 { c: 1.0 }], 5, 2).expect("compares");
        assert_eq!(
            standings[0].fit.observer.function.name(),
            "F2",
            "{standings:?}"
        );
        assert!(standings[0].cross_validated > standings[1].cross_validated + 5.0);
    }
}
