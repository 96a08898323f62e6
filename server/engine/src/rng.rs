//! A small, self-contained PRNG (xoshiro256**, seeded through splitmix64).
//!
//! The engine owns its generator instead of depending on `rand` so that a seed gives the same scene
//! on every platform and every dependency version: the golden-hash test depends on it.

use crate::math::{Quat, Vec3};

/// xoshiro256** by Blackman and Vigna: fast, 256 bits of state, passes BigCrush.
#[derive(Debug, Clone)]
pub struct Rng {
    s: [u64; 4],
}

/// splitmix64 step: used to expand a 64-bit seed into the generator state.
fn splitmix64(x: &mut u64) -> u64 {
    *x = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *x;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Rng {
    /// A generator whose whole sequence is fixed by `seed`.
    pub fn new(seed: u64) -> Self {
        let mut x = seed;
        let s = [
            splitmix64(&mut x),
            splitmix64(&mut x),
            splitmix64(&mut x),
            splitmix64(&mut x),
        ];
        Self { s }
    }

    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let result = self.s[1].wrapping_mul(5).rotate_left(7).wrapping_mul(9);
        let t = self.s[1] << 17;
        self.s[2] ^= self.s[0];
        self.s[3] ^= self.s[1];
        self.s[1] ^= self.s[2];
        self.s[0] ^= self.s[3];
        self.s[2] ^= t;
        self.s[3] = self.s[3].rotate_left(45);
        result
    }

    /// Uniform in [0, 1) with 53 bits of precision.
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    /// Uniform direction on the unit sphere (Archimedes: z uniform, azimuth uniform).
    pub fn unit_vector(&mut self) -> Vec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f64::consts::TAU);
        let rho = (1.0 - z * z).max(0.0).sqrt();
        Vec3::new(rho * phi.cos(), rho * phi.sin(), z)
    }

    /// Uniformly distributed rotation (Shoemake's subgroup algorithm).
    pub fn unit_quat(&mut self) -> Quat {
        let u1 = self.next_f64();
        let u2 = self.range(0.0, std::f64::consts::TAU);
        let u3 = self.range(0.0, std::f64::consts::TAU);
        let a = (1.0 - u1).sqrt();
        let b = u1.sqrt();
        Quat::from_xyzw(a * u2.sin(), a * u2.cos(), b * u3.sin(), b * u3.cos()).normalize()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn same_seed_same_sequence_and_ranges_hold() {
        let mut a = Rng::new(42);
        let mut b = Rng::new(42);
        for _ in 0..1000 {
            let x = a.next_f64();
            assert_eq!(x.to_bits(), b.next_f64().to_bits());
            assert!((0.0..1.0).contains(&x));
        }
        let mut c = Rng::new(43);
        assert_ne!(Rng::new(42).next_u64(), c.next_u64());
        for _ in 0..1000 {
            assert!((a.unit_vector().length() - 1.0).abs() < 1e-12);
            assert!((a.unit_quat().length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn unit_vectors_are_not_biased() {
        let mut r = Rng::new(7);
        let mut sum = Vec3::ZERO;
        for _ in 0..20_000 {
            sum += r.unit_vector();
        }
        assert!((sum / 20_000.0).length() < 0.03, "{sum}");
    }
}
