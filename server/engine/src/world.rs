//! Body state and its integration (paper section 2: "update the position of all objects").
//!
//! Hot and cold data are split: the narrow phase reads only `position` and the per-frame f32
//! rotation matrix `basis`; velocities and spins are touched once per frame by the integrator and by
//! the response. World state is f64 (see [`crate::math`]).

use crate::config::SceneConfig;
use crate::math::{LMat3, Quat, Vec3};
use crate::rng::Rng;

/// All bodies of a scene, structure-of-arrays.
#[derive(Debug, Clone)]
pub struct World {
    /// Centre of each body (world).
    pub position: Vec<Vec3>,
    /// Linear velocity (units/s).
    pub velocity: Vec<Vec3>,
    /// Orientation (unit quaternion, body to world).
    pub orientation: Vec<Quat>,
    /// Angular velocity (rad/s, world axes).
    pub spin: Vec<Vec3>,
    /// `orientation` as an f32 matrix, refreshed by [`World::integrate`] and [`World::refresh_bases`].
    pub basis: Vec<LMat3>,
    /// Minimum corner of the volume.
    pub lo: Vec3,
    /// Maximum corner of the volume.
    pub hi: Vec3,
    /// Per-body rotation over one step, exp(ω dt), for the dt in `spin_step_dt`. Spins never change
    /// (the response exchanges linear velocities only), so the trigonometry is done once, not per
    /// frame; the result is bit-identical to recomputing it.
    spin_step: Vec<Quat>,
    spin_step_dt: f64,
    /// Sum of the velocity changes made by wall reflections since generation (unit masses, so this
    /// is the momentum the walls put in): momentum minus this is conserved by everything else.
    pub wall_impulse: Vec3,
}

impl World {
    /// The paper scene of `cfg` (DESIGN.md "Scene"): uniform positions in the cube, uniform random
    /// orientations, speeds uniform in [min, max] in a uniform direction, spin uniform in
    /// [0, max_spin] about a uniform axis. Everything is drawn from one seeded generator, body by body.
    pub fn generate(cfg: &SceneConfig) -> Self {
        let n = cfg.bodies as usize;
        let side = cfg.volume_side();
        let lo = Vec3::from_array(cfg.origin);
        let hi = lo + Vec3::splat(side);
        let mut rng = Rng::new(cfg.seed);
        let mut w = Self {
            position: Vec::with_capacity(n),
            velocity: Vec::with_capacity(n),
            orientation: Vec::with_capacity(n),
            spin: Vec::with_capacity(n),
            basis: Vec::with_capacity(n),
            lo,
            hi,
            wall_impulse: Vec3::ZERO,
            spin_step: Vec::new(),
            spin_step_dt: f64::NAN,
        };
        for _ in 0..n {
            let p = Vec3::new(
                rng.range(0.0, side),
                rng.range(0.0, side),
                rng.range(0.0, side),
            );
            w.position.push(lo + p);
            w.orientation.push(rng.unit_quat());
            let speed = rng.range(cfg.min_speed, cfg.max_speed);
            w.velocity.push(rng.unit_vector() * speed);
            let spin = rng.range(0.0, cfg.max_spin);
            w.spin.push(rng.unit_vector() * spin);
        }
        w.refresh_bases();
        w
    }

    /// Number of bodies.
    pub fn len(&self) -> usize {
        self.position.len()
    }

    /// True when there are no bodies.
    pub fn is_empty(&self) -> bool {
        self.position.is_empty()
    }

    /// Recompute every f32 basis from the orientation.
    pub fn refresh_bases(&mut self) {
        self.basis.clear();
        self.basis.extend(
            self.orientation
                .iter()
                .map(|q| LMat3::from(glam::DMat3::from_quat(*q).as_mat3())),
        );
    }

    /// Advance one step: explicit Euler for positions (exact for constant velocity), the exact
    /// rotation exp(ω dt) for orientations, renormalised so drift cannot accumulate. A body whose
    /// centre leaves the volume is mirrored back across the wall and its normal velocity component
    /// reflected (DESIGN.md "walls reflect the normal velocity component"), which keeps the speed.
    pub fn integrate(&mut self, dt: f64) {
        let (lo, hi) = (self.lo, self.hi);
        if self.spin_step_dt.to_bits() != dt.to_bits() || self.spin_step.len() != self.spin.len() {
            self.spin_step.clear();
            self.spin_step
                .extend(self.spin.iter().map(|&w| Quat::from_scaled_axis(w * dt)));
            self.spin_step_dt = dt;
        }
        for i in 0..self.position.len() {
            let mut p = self.position[i] + self.velocity[i] * dt;
            let mut v = self.velocity[i];
            for a in 0..3 {
                if p[a] < lo[a] {
                    p[a] = (2.0 * lo[a] - p[a]).min(hi[a]);
                    v[a] = v[a].abs();
                } else if p[a] > hi[a] {
                    p[a] = (2.0 * hi[a] - p[a]).max(lo[a]);
                    v[a] = -v[a].abs();
                }
            }
            self.wall_impulse += v - self.velocity[i];
            self.position[i] = p;
            self.velocity[i] = v;
            if self.spin[i] != Vec3::ZERO {
                let q = (self.spin_step[i] * self.orientation[i]).normalize();
                self.orientation[i] = q;
                self.basis[i] = LMat3::from(glam::DMat3::from_quat(q).as_mat3());
            }
        }
    }

    /// Total linear momentum (unit masses).
    pub fn momentum(&self) -> Vec3 {
        self.velocity.iter().copied().sum()
    }

    /// Total translational kinetic energy (unit masses).
    pub fn kinetic_energy(&self) -> f64 {
        0.5 * self
            .velocity
            .iter()
            .map(|v| v.length_squared())
            .sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn generated_scene_is_inside_and_within_ranges() {
        let cfg = SceneConfig::paper(1000, 3);
        let w = World::generate(&cfg);
        assert_eq!(w.len(), 1000);
        let side = cfg.volume_side();
        assert!((side - 100f64.cbrt()).abs() < 1e-12);
        for i in 0..w.len() {
            assert!(w.position[i].cmpge(w.lo).all() && w.position[i].cmple(w.hi).all());
            let s = w.velocity[i].length();
            assert!((0.2..=1.0).contains(&s), "{s}");
            assert!(w.spin[i].length() <= std::f64::consts::PI);
            assert!((w.orientation[i].length() - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn walls_reflect_and_keep_bodies_inside_and_speed_unchanged() {
        let mut w = World::generate(&SceneConfig::paper(200, 5));
        let speeds: Vec<f64> = w.velocity.iter().map(|v| v.length()).collect();
        for _ in 0..2000 {
            w.integrate(1.0 / 60.0);
        }
        for i in 0..w.len() {
            assert!(w.position[i].cmpge(w.lo).all() && w.position[i].cmple(w.hi).all());
            assert!((w.velocity[i].length() - speeds[i]).abs() < 1e-12);
            assert!((w.orientation[i].length() - 1.0).abs() < 1e-9);
        }
    }
}
