//! A small deterministic generator (SplitMix64) for resampling and simulated observers: the
//! same seed gives the same bootstrap and the same simulated responses on every machine, so a
//! fit's interval is reproducible from its seed.

use foveal_gaze::rng::SplitMix64;

/// The gaze crate's SplitMix64 (one generator for the whole client side), with the draws a
/// resampler needs.
#[derive(Debug, Clone)]
pub struct Rng(SplitMix64);

impl Rng {
    /// A generator from `seed`.
    pub fn new(seed: u64) -> Self {
        Self(SplitMix64::new(seed))
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0.next_u64()
    }

    /// Uniform in [0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.0.next_f64()
    }

    /// Uniform in `0..n` (`n > 0`), by rejection so that no index is favoured.
    pub fn below(&mut self, n: usize) -> usize {
        let n = n as u64;
        let zone = u64::MAX - u64::MAX % n;
        loop {
            let x = self.next_u64();
            if x < zone {
                return (x % n) as usize;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_draws_fill_the_unit_interval_evenly() {
        let mut r = Rng::new(7);
        let mut bins = [0u32; 10];
        for _ in 0..100_000 {
            let u = r.uniform();
            assert!((0.0..1.0).contains(&u));
            bins[(u * 10.0) as usize] += 1;
        }
        assert!(
            bins.iter().all(|&b| (9_500..10_500).contains(&b)),
            "{bins:?}"
        );
        let mut again = Rng::new(7);
        assert_eq!(Rng::new(7).next_u64(), again.next_u64());
    }
}
