//! Summary statistics: per-run mean and standard deviation over frames, and across seeds the mean
//! with a 95% confidence interval from Student's t (the seeds are the independent replicates; frames
//! within a run are autocorrelated and are not treated as independent).

/// Running mean and variance (Welford), ignoring non-finite values.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Accum {
    n: u64,
    mean: f64,
    m2: f64,
}

impl Accum {
    /// Add one observation; NaN and infinities are skipped.
    pub fn push(&mut self, x: f64) {
        if !x.is_finite() {
            return;
        }
        self.n += 1;
        let d = x - self.mean;
        self.mean += d / self.n as f64;
        self.m2 += d * (x - self.mean);
    }

    /// The running state (count, mean, sum of squared deviations), written into a shard's
    /// partial result so that a merge rebuilds the summary bit for bit.
    pub fn raw(&self) -> (u64, f64, f64) {
        (self.n, self.mean, self.m2)
    }

    /// The accumulator whose running state is `(n, mean, m2)` (see [`Self::raw`]).
    pub fn from_raw(n: u64, mean: f64, m2: f64) -> Self {
        Self { n, mean, m2 }
    }

    /// Observations counted.
    pub fn count(&self) -> u64 {
        self.n
    }

    /// Mean (NaN when empty).
    pub fn mean(&self) -> f64 {
        if self.n == 0 { f64::NAN } else { self.mean }
    }

    /// Sample standard deviation (n - 1; 0 for one observation, NaN when empty).
    pub fn sd(&self) -> f64 {
        match self.n {
            0 => f64::NAN,
            1 => 0.0,
            n => (self.m2 / (n - 1) as f64).sqrt(),
        }
    }
}

/// Two-sided 97.5% quantile of Student's t with `df` degrees of freedom.
pub fn t975(df: u64) -> f64 {
    const TABLE: [f64; 30] = [
        12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.160,
        2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086, 2.080, 2.074, 2.069, 2.064, 2.060, 2.056,
        2.052, 2.048, 2.045, 2.042,
    ];
    match df {
        0 => f64::NAN,
        1..=30 => TABLE[df as usize - 1],
        31..=40 => 2.021,
        41..=60 => 2.000,
        61..=120 => 1.980,
        _ => 1.960,
    }
}

/// A point estimate with the ends of its interval (what a figure draws).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Interval {
    /// The estimate.
    pub value: f64,
    /// Lower end (NaN when unknown).
    pub lo: f64,
    /// Upper end (NaN when unknown).
    pub hi: f64,
}

/// Mean of independent replicates with the half-width of its 95% confidence interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeanCi {
    /// Mean across replicates.
    pub mean: f64,
    /// Half-width of the 95% CI (NaN with fewer than two replicates).
    pub half: f64,
    /// Replicates counted (finite values only).
    pub n: u64,
    /// Replicates given that were not finite (a ratio over a zero, a metric never measured):
    /// left out of the mean and the interval, and said so by [`Self::fmt`], never dropped
    /// silently.
    pub non_finite: u64,
}

impl MeanCi {
    /// From replicate values; non-finite ones are left out and counted ([`Self::non_finite`]).
    pub fn of(values: impl IntoIterator<Item = f64>) -> Self {
        let mut a = Accum::default();
        let mut non_finite = 0;
        for v in values {
            if v.is_finite() {
                a.push(v);
            } else {
                non_finite += 1;
            }
        }
        let n = a.count();
        let half = if n >= 2 {
            t975(n - 1) * a.sd() / (n as f64).sqrt()
        } else {
            f64::NAN
        };
        Self {
            mean: a.mean(),
            half,
            n,
            non_finite,
        }
    }

    /// Lower end of the interval.
    pub fn lo(&self) -> f64 {
        self.mean - self.half
    }

    /// Upper end of the interval.
    pub fn hi(&self) -> f64 {
        self.mean + self.half
    }

    /// The mean and the ends of its interval.
    pub fn interval(&self) -> Interval {
        Interval {
            value: self.mean,
            lo: self.lo(),
            hi: self.hi(),
        }
    }

    /// `mean ± half` with `digits` significant digits (`mean` alone without a CI); where some
    /// replicates were not finite, how many were counted and how many were not, e.g.
    /// `0.8 ± 0.1 (n = 3; 2 non-finite)`, or `non-finite (5 of 5)` when none was finite.
    pub fn fmt(&self, digits: usize) -> String {
        if self.non_finite > 0 && self.n == 0 {
            return format!("non-finite ({0} of {0})", self.non_finite);
        }
        let value = if self.half.is_finite() {
            format!("{} ± {}", sig(self.mean, digits), sig(self.half, 2))
        } else {
            sig(self.mean, digits)
        };
        if self.non_finite > 0 {
            format!("{value} (n = {}; {} non-finite)", self.n, self.non_finite)
        } else {
            value
        }
    }
}

/// `x` with `digits` significant digits, plain notation for moderate magnitudes.
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return "–".into();
    }
    if x == 0.0 {
        return "0".into();
    }
    let mag = x.abs().log10().floor() as i32;
    if !(-4..6).contains(&mag) {
        return format!("{:.*e}", digits.saturating_sub(1), x);
    }
    let decimals = (digits as i32 - 1 - mag).max(0) as usize;
    format!("{x:.decimals$}")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ratio over a zero (a scheduler with P against one without) is not finite: it is left
    /// out of the mean and said so, where it used to vanish and leave "0 ± 0".
    #[test]
    fn non_finite_replicates_are_counted_and_shown() {
        let ratios = [f64::NAN, 0.8, f64::INFINITY, 0.9, 0.7];
        let m = MeanCi::of(ratios);
        assert_eq!((m.n, m.non_finite), (3, 2));
        assert!((m.mean - 0.8).abs() < 1e-12);
        assert_eq!(
            m.fmt(2),
            format!("0.80 ± {} (n = 3; 2 non-finite)", sig(m.half, 2))
        );
        let none = MeanCi::of([f64::INFINITY; 5]);
        assert_eq!(none.fmt(2), "non-finite (5 of 5)");
    }

    #[test]
    fn welford_matches_two_pass() {
        let xs = [1.0, 2.0, 4.0, 8.0, f64::NAN];
        let mut a = Accum::default();
        xs.iter().for_each(|&x| a.push(x));
        assert_eq!(a.count(), 4);
        assert!((a.mean() - 3.75).abs() < 1e-12);
        let var = [1.0f64, 2.0, 4.0, 8.0]
            .iter()
            .map(|x| (x - 3.75).powi(2))
            .sum::<f64>()
            / 3.0;
        assert!((a.sd() - var.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn ci_uses_student_t() {
        let m = MeanCi::of([1.0, 2.0, 3.0, 4.0, 5.0]);
        assert_eq!(m.n, 5);
        assert!((m.mean - 3.0).abs() < 1e-12);
        // sd = sqrt(2.5), t(4) = 2.776
        assert!((m.half - 2.776 * 2.5f64.sqrt() / 5f64.sqrt()).abs() < 1e-9);
        assert!(MeanCi::of([1.0]).half.is_nan());
        assert_eq!(m.non_finite, 0);
        assert_eq!(m.fmt(3), "3.00 ± 2.0");
        assert_eq!(sig(0.012345, 3), "0.0123");
        assert_eq!(sig(1234.6, 3), "1235");
    }
}
