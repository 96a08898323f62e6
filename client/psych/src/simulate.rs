//! Simulated observers: responses drawn from a known observer on a design, so that a fit can be
//! checked against the truth it should recover (tests, and the coverage run of
//! `foveal psych simulate`).

use crate::model::Observer;
use crate::rng::Rng;
use crate::trial::Trial;

/// A factorial design: every gap at every eccentricity, `repetitions` times, with touching
/// trials as the paper's experiment 1 has them (half of all trials).
#[derive(Debug, Clone, PartialEq)]
pub struct Design {
    /// Eccentricities (degrees).
    pub eccentricities_deg: Vec<f64>,
    /// Gaps (degrees, > 0); each cell also gets as many touching trials as gap trials over all
    /// gaps, split evenly.
    pub gaps_deg: Vec<f64>,
    /// Repetitions of each gap cell.
    pub repetitions: u32,
}

impl Default for Design {
    /// Five eccentricities from the fovea to 20 degrees and four gaps from 0.02 to 0.2
    /// degrees (about 1 to 10 pixels on the paper's 22-inch display at 70 cm): 400 trials at
    /// 10 repetitions, the size the issue of a fitted C asks to be recovered from.
    fn default() -> Self {
        Self {
            eccentricities_deg: vec![0.0, 2.5, 5.0, 10.0, 20.0],
            gaps_deg: vec![0.02, 0.05, 0.1, 0.2],
            repetitions: 10,
        }
    }
}

impl Design {
    /// Trials the design holds.
    pub fn trials(&self) -> usize {
        2 * self.eccentricities_deg.len() * self.gaps_deg.len() * self.repetitions as usize
    }
}

/// Responses of `observer` to `design`, participant id `sim<seed>`, drawn from `seed`.
pub fn simulate(observer: &Observer, design: &Design, seed: u64) -> Vec<Trial> {
    let mut rng = Rng::new(seed);
    let mut trials = Vec::with_capacity(design.trials());
    let participant = format!("sim{seed}");
    for &e in &design.eccentricities_deg {
        for &g in &design.gaps_deg {
            for _ in 0..design.repetitions {
                for gap in [g, 0.0] {
                    let apart = rng.uniform() < observer.p_apart(gap, e);
                    trials.push(Trial {
                        participant: participant.clone(),
                        eccentricity_deg: e,
                        gap_deg: gap,
                        apart,
                    });
                }
            }
        }
    }
    trials
}

/// How well fits recover a known observer: per simulated observer, the fitted constant (C of
/// F2) and whether its bootstrap interval covers the truth.
#[derive(Debug, Clone, PartialEq)]
pub struct Coverage {
    /// The true C.
    pub truth: f64,
    /// Each observer's fitted C and interval.
    pub fits: Vec<crate::bootstrap::Interval>,
    /// Observers whose fit or bootstrap failed.
    pub failed: usize,
}

impl Coverage {
    /// Share of observers whose fitted C is within `tolerance` (0.2 for ±20%) of the truth.
    pub fn recovered(&self, tolerance: f64) -> f64 {
        let ok = self
            .fits
            .iter()
            .filter(|i| (i.estimate / self.truth - 1.0).abs() <= tolerance)
            .count();
        ok as f64 / (self.fits.len() + self.failed).max(1) as f64
    }

    /// Share of observers whose interval covers the truth.
    pub fn covered(&self) -> f64 {
        let ok = self.fits.iter().filter(|i| i.covers(self.truth)).count();
        ok as f64 / (self.fits.len() + self.failed).max(1) as f64
    }

    /// The median fitted C.
    pub fn median(&self) -> f64 {
        let mut v: Vec<f64> = self.fits.iter().map(|i| i.estimate).collect();
        v.sort_by(f64::total_cmp);
        v.get(v.len() / 2).copied().unwrap_or(f64::NAN)
    }
}

/// Simulate `observers` observers like `truth` (an F2 observer) on `design`, fit F2 to each and
/// bootstrap its C with `replicates` resamples at 95%: observer `i` draws from seed `seed + i`.
pub fn coverage(
    truth: &Observer,
    design: &Design,
    observers: usize,
    replicates: usize,
    seed: u64,
) -> Coverage {
    let c = truth
        .function
        .constants()
        .first()
        .copied()
        .unwrap_or(f64::NAN);
    let mut out = Coverage {
        truth: c,
        fits: Vec::new(),
        failed: 0,
    };
    for i in 0..observers as u64 {
        let cells = crate::fit::cells(&simulate(truth, design, seed + i));
        let fitted = crate::fit::fit_cells(&cells, truth.function).and_then(|f| {
            crate::bootstrap::bootstrap(&cells, &f, replicates, 0.95, seed ^ (i << 32))
        });
        match fitted {
            Ok(b) if !b.constants.is_empty() => out.fits.push(b.constants[0]),
            _ => out.failed += 1,
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Function;

    #[test]
    fn responses_follow_the_observer() {
        let o = Observer {
            function: Function::F2 { c: 5.0 },
            alpha: 0.05,
            beta: 2.0,
            guess: 0.1,
            lapse: 0.0,
        };
        let design = Design {
            eccentricities_deg: vec![0.0],
            gaps_deg: vec![1.0],
            repetitions: 4000,
        };
        let t = simulate(&o, &design, 3);
        assert_eq!(t.len(), design.trials());
        let rate = |gap: f64| {
            let sel: Vec<_> = t.iter().filter(|x| x.gap_deg == gap).collect();
            sel.iter().filter(|x| x.apart).count() as f64 / sel.len() as f64
        };
        assert!((rate(0.0) - 0.1).abs() < 0.02, "{}", rate(0.0));
        assert!(rate(1.0) > 0.99);
    }
}
