//! Paired ratios across seeds, the form of every claim the study tests ("16 times lower",
//! "roughly halves"): the ratio of the means, with a 95% interval from a bootstrap over seeds,
//! and a one-sided test of "below a factor" on the per-seed log ratios.
//!
//! Why a ratio of means and not a mean of ratios: a seed where a scheduler's P is zero gives a
//! per-seed ratio of 0 (its log is minus infinity), and one where round-robin's is zero gives an
//! infinite one; the ratio of the means stays defined while any seed has round-robin error, and a
//! percentile bootstrap of it is the same on the log scale as on the linear one, so its interval
//! is two-sided on a log axis whenever every resample is positive. Seeds are the replicates
//! (frames within a run are autocorrelated), so resampling is over seeds, pairs kept together.
//! The definitions are written once in `docs/DESIGN.md` ("Statistics of the study").

use foveal_gaze::rng::SplitMix64;
use statrs::distribution::{ContinuousCDF, StudentsT};

use crate::stats::{Interval, sig};

/// Bootstrap resamples per interval: enough that the 2.5% and 97.5% quantiles move by well under
/// the interval's own width between generator seeds.
pub const RESAMPLES: usize = 4000;

/// Fixed generator seed: an interval is a function of its data, the same on every run.
const BOOT_SEED: u64 = 0x5eed_b007;

/// The ratio of two paired means across seeds, `Σ num / Σ den`, with its 95% percentile-bootstrap
/// interval over seeds.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RatioCi {
    /// `Σ num / Σ den` over the finite pairs.
    pub ratio: f64,
    /// 2.5% quantile of the bootstrap (NaN with fewer than two pairs).
    pub lo: f64,
    /// 97.5% quantile of the bootstrap (NaN with fewer than two pairs).
    pub hi: f64,
    /// Pairs counted (both values finite).
    pub n: u64,
    /// Pairs given with a value that was not finite (a metric never measured): left out and
    /// said so by [`Self::fmt`], never dropped silently.
    pub non_finite: u64,
}

impl RatioCi {
    /// From paired per-seed values `(num, den)`, e.g. (a scheduler's mean true P, round-robin's).
    pub fn of(pairs: impl IntoIterator<Item = (f64, f64)>) -> Self {
        let mut kept = Vec::new();
        let mut non_finite = 0;
        for (a, b) in pairs {
            if a.is_finite() && b.is_finite() {
                kept.push((a, b));
            } else {
                non_finite += 1;
            }
        }
        let ratio_of = |idx: &mut dyn Iterator<Item = usize>| {
            let (mut a, mut b) = (0.0, 0.0);
            for i in idx {
                a += kept[i].0;
                b += kept[i].1;
            }
            a / b
        };
        let n = kept.len();
        let ratio = if n == 0 {
            f64::NAN
        } else {
            ratio_of(&mut (0..n))
        };
        let (lo, hi) = if n >= 2 {
            let mut rng = SplitMix64::new(BOOT_SEED);
            let mut reps: Vec<f64> = (0..RESAMPLES)
                .map(|_| ratio_of(&mut (0..n).map(|_| (rng.next_u64() % n as u64) as usize)))
                .collect();
            // A resample whose denominators are all zero has no ratio: it sorts last (NaN), so an
            // interval that reaches it has no finite upper end.
            reps.sort_by(|x, y| match (x.is_nan(), y.is_nan()) {
                (false, false) => x.total_cmp(y),
                (a, b) => a.cmp(&b),
            });
            let at = |q: f64| reps[((q * RESAMPLES as f64) as usize).min(RESAMPLES - 1)];
            (at(0.025), at(0.975))
        } else {
            (f64::NAN, f64::NAN)
        };
        Self {
            ratio,
            lo,
            hi,
            n: n as u64,
            non_finite,
        }
    }

    /// The mean of `values` with the same bootstrap interval (a ratio over a denominator of 1).
    pub fn mean(values: impl IntoIterator<Item = f64>) -> Self {
        Self::of(values.into_iter().map(|v| (v, 1.0)))
    }

    /// The estimate and its interval.
    pub fn interval(&self) -> Interval {
        Interval {
            value: self.ratio,
            lo: self.lo,
            hi: self.hi,
        }
    }

    /// `ratio [lo, hi]` with `digits` significant digits and the number of seeds, e.g.
    /// `0.42 [0.31, 0.55] (n = 5)`; values left out are counted, e.g. `(n = 4; 1 non-finite)`,
    /// and a ratio with no finite value reads `non-finite (5 of 5)`.
    pub fn fmt(&self, digits: usize) -> String {
        if self.n == 0 || self.non_finite > 0 {
            return self.fmt_cell(digits);
        }
        format!("{} (n = {})", self.fmt_cell(digits), self.n)
    }

    /// [`Self::fmt`] without the number of seeds where every value counted (a table that states
    /// its n once, in its heading).
    pub fn fmt_cell(&self, digits: usize) -> String {
        if self.n == 0 {
            return format!("non-finite ({0} of {0})", self.non_finite);
        }
        let point = if self.ratio == f64::INFINITY {
            "∞".to_string()
        } else {
            sig(self.ratio, digits)
        };
        let value = if self.lo.is_nan() && self.hi.is_nan() {
            point
        } else {
            format!(
                "{point} [{}, {}]",
                end(self.lo, digits),
                end(self.hi, digits)
            )
        };
        if self.non_finite > 0 {
            format!("{value} (n = {}; {} non-finite)", self.n, self.non_finite)
        } else {
            value
        }
    }
}

/// An interval's end: `∞` where resamples had no finite ratio.
fn end(x: f64, digits: usize) -> String {
    if x.is_nan() || x == f64::INFINITY {
        "∞".into()
    } else {
        sig(x, digits)
    }
}

/// One-sided paired test of "the ratio is below `factor`": Student's t on the per-seed log ratios
/// against `ln factor` (H0: their mean is at least `ln factor`). `None` where it cannot be
/// computed: fewer than two seeds, a per-seed ratio that is zero or not finite (its log is not),
/// or no spread. The p-value is what a Holm correction takes ([`holm`]).
pub fn p_below(pairs: &[(f64, f64)], factor: f64) -> Option<f64> {
    let logs: Vec<f64> = pairs.iter().map(|&(a, b)| (a / b).ln()).collect();
    if logs.len() < 2 || logs.iter().any(|l| !l.is_finite()) {
        return None;
    }
    let n = logs.len() as f64;
    let mean = logs.iter().sum::<f64>() / n;
    let var = logs.iter().map(|l| (l - mean).powi(2)).sum::<f64>() / (n - 1.0);
    let se = (var / n).sqrt();
    if se.is_nan() || se <= 0.0 {
        return None;
    }
    let t = (mean - factor.ln()) / se;
    let dist = StudentsT::new(0.0, 1.0, n - 1.0).ok()?;
    Some(dist.cdf(t))
}

/// Holm's step-down adjustment of a family of p-values (Holm 1979): the adjusted p-values, in the
/// input's order; a hypothesis is rejected at level α when its adjusted p is at most α. It holds
/// the family-wise error rate at α under any dependence between the tests, which the study's cells
/// (the same frames under many budgets) have.
pub fn holm(ps: &[f64]) -> Vec<f64> {
    let m = ps.len();
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by(|&i, &j| ps[i].total_cmp(&ps[j]));
    let mut adjusted = vec![0.0; m];
    let mut running: f64 = 0.0;
    for (rank, &i) in order.iter().enumerate() {
        let a = ((m - rank) as f64 * ps[i]).min(1.0);
        running = running.max(a);
        adjusted[i] = running;
    }
    adjusted
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ratio_is_of_the_means_and_its_interval_brackets_it() {
        let pairs = [(1.0, 4.0), (2.0, 4.0), (1.5, 5.0), (1.0, 3.0), (2.5, 6.0)];
        let r = RatioCi::of(pairs);
        assert!((r.ratio - 8.0 / 22.0).abs() < 1e-12);
        assert_eq!((r.n, r.non_finite), (5, 0));
        // Every resample is a ratio of sums of these pairs, so it lies between the smallest and
        // the largest per-seed ratio.
        assert!(r.lo >= 0.25 - 1e-12 && r.hi <= 0.5 + 1e-12, "{r:?}");
        assert!(r.lo < r.ratio && r.ratio < r.hi, "{r:?}");
        assert_eq!(
            RatioCi::of(pairs),
            r,
            "the interval is a function of its data"
        );
        assert!(r.fmt(2).ends_with("(n = 5)"), "{}", r.fmt(2));
    }

    /// A seed where the scheduler's P is zero keeps the ratio defined (a mean of ratios would take
    /// the log of zero); a value never measured is counted, not dropped.
    #[test]
    fn zeros_stay_in_and_non_finite_values_are_counted() {
        let r = RatioCi::of([(0.0, 2.0), (1.0, 2.0), (f64::NAN, 1.0), (0.5, 2.0)]);
        assert_eq!((r.n, r.non_finite), (3, 1));
        assert!((r.ratio - 1.5 / 6.0).abs() < 1e-12);
        assert!(r.fmt(2).contains("(n = 3; 1 non-finite)"), "{}", r.fmt(2));
        assert_eq!(
            RatioCi::of([(1.0, f64::INFINITY); 3]).fmt(2),
            "non-finite (3 of 3)"
        );
        // All denominators zero in some resamples: the upper end is unbounded, said as such.
        let open = RatioCi::of([(1.0, 0.0), (1.0, 1.0), (1.0, 1.0)]);
        assert!(open.fmt(2).contains("∞"), "{}", open.fmt(2));
    }

    #[test]
    fn the_mean_is_a_ratio_over_ones() {
        let m = RatioCi::mean([1.0, 2.0, 3.0, 4.0, 5.0]);
        assert!((m.ratio - 3.0).abs() < 1e-12);
        assert!(
            m.lo > 1.0 && m.hi < 5.0 && m.lo < 3.0 && m.hi > 3.0,
            "{m:?}"
        );
        assert!(RatioCi::mean([2.0]).lo.is_nan());
    }

    #[test]
    fn the_test_of_below_a_factor_follows_the_log_ratios() {
        let clearly = [
            (0.2, 1.0),
            (0.25, 1.0),
            (0.3, 1.0),
            (0.22, 1.0),
            (0.27, 1.0),
        ];
        let p = p_below(&clearly, 0.5).expect("computable");
        assert!(p < 0.001, "{p}");
        let near = [(0.45, 1.0), (0.55, 1.0), (0.5, 1.0), (0.6, 1.0), (0.4, 1.0)];
        let p = p_below(&near, 0.5).expect("computable");
        assert!(p > 0.3 && p < 0.7, "{p}");
        assert!(p_below(&[(0.0, 1.0), (0.2, 1.0)], 0.5).is_none());
        assert!(p_below(&[(0.2, 1.0)], 0.5).is_none());
        assert!(p_below(&[(0.2, 1.0), (0.2, 1.0)], 0.5).is_none());
    }

    /// Holm's adjustment on the textbook example: p = 0.01, 0.04, 0.03, 0.005 (m = 4).
    #[test]
    fn holm_steps_down_and_stays_monotone() {
        let adj = holm(&[0.01, 0.04, 0.03, 0.005]);
        let want = [0.03, 0.06, 0.06, 0.02];
        for (a, w) in adj.iter().zip(want) {
            assert!((a - w).abs() < 1e-12, "{adj:?}");
        }
        assert_eq!(holm(&[0.3, 0.02]), vec![0.3, 0.04]);
        assert_eq!(holm(&[0.9, 0.8]), vec![1.0, 1.0]);
        assert!(holm(&[]).is_empty());
    }
}
