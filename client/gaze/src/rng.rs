//! The one seeded generator of gaze: [`SplitMix64`].
//!
//! Gaze scripts, the study's viewer and the latency bench all draw from it, so a seed means the
//! same gaze everywhere. It is self-contained (no `rand`) so that a sequence never changes with a
//! library's version. The engine keeps its own generator for scenes (xoshiro256**): a change to a
//! gaze script must never change a scene, and the engine's golden hash depends on that stream.

/// SplitMix64 (Steele, Lea, Flood 2014): tiny, fast, and well mixed enough for gaze scripts.
#[derive(Debug, Clone)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator whose whole sequence is fixed by `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        Self(seed)
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1), 53 bits.
    pub fn next_f64(&mut self) -> f64 {
        // A 53-bit integer converts to f64 exactly.
        #[allow(clippy::cast_precision_loss)]
        let mantissa = (self.next_u64() >> 11) as f64;
        mantissa * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn matches_reference_values() {
        // Reference outputs of SplitMix64 seeded with 1234567 (from the published C code).
        let mut rng = SplitMix64::new(1_234_567);
        let expected = [
            6_457_827_717_110_365_317,
            3_203_168_211_198_807_973,
            9_817_491_932_198_370_423,
            4_593_380_528_125_082_431,
            16_408_922_859_458_223_821,
        ];
        for value in expected {
            assert_eq!(rng.next_u64(), value);
        }
        let mut rng = SplitMix64::new(0);
        assert!(
            (0..10_000)
                .map(|_| rng.next_f64())
                .all(|v| (0.0..1.0).contains(&v))
        );
        let mut rng = SplitMix64::new(9);
        assert!(
            (0..1000)
                .map(|_| rng.range(2.0, 3.0))
                .all(|v| (2.0..3.0).contains(&v))
        );
    }
}
