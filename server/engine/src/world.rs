//! Body state and its integration (paper section 2: "update the position of all objects").
//!
//! Hot and cold data are split: the narrow phase reads only `position` and the per-frame f32
//! rotation matrix `basis`; velocities and spins are touched once per frame by the integrator and by
//! the response. World state is f64 (see [`crate::math`]).
//!
//! Integration can run on several threads ([`World::integrate_threads`]). Every body is advanced
//! on its own, so any partition gives the same bits; the one quantity summed across bodies,
//! [`World::wall_impulse`], is summed afterwards on the calling thread in body order, from the
//! velocity changes each thread recorded for the few bodies that hit a wall.

use crate::config::SceneConfig;
use crate::math::{LMat3, Quat, Vec3};
use crate::rng::Rng;

/// Below this many bodies [`World::integrate_threads`] runs on the calling thread whatever it is
/// asked. Integration costs about 17 ns per body on one core; handing half of it to a thread of
/// the frame's pool costs about a microsecond when that thread is awake and 20-40 µs when it has
/// gone to sleep (starting a thread, as before the pool, cost 30-70 µs). At N = 10,000 on two
/// threads the phase's median went from 0.18 to 0.09-0.12 ms.
pub const PARALLEL_MIN_BODIES: usize = 4_000;

/// Fewest bodies worth giving to one thread; more threads than `len / this` are not started.
const MIN_BODIES_PER_THREAD: usize = PARALLEL_MIN_BODIES / 2;

/// Body indices sorted by the Morton code of their positions.
pub fn morton_order(position: &[Vec3], lo: Vec3, side: f64) -> Vec<u32> {
    fn spread(v: u32) -> u64 {
        let mut x = u64::from(v) & 0x1f_ffff;
        x = (x | x << 32) & 0x1f00000000ffff;
        x = (x | x << 16) & 0x1f0000ff0000ff;
        x = (x | x << 8) & 0x100f00f00f00f00f;
        x = (x | x << 4) & 0x10c30c30c30c30c3;
        (x | x << 2) & 0x1249249249249249
    }
    let scale = f64::from(1u32 << 21) / side.max(f64::MIN_POSITIVE);
    let q = |x: f64| ((x * scale).clamp(0.0, f64::from((1u32 << 21) - 1))) as u32;
    let mut keys: Vec<(u64, u32)> = position
        .iter()
        .enumerate()
        .map(|(i, p)| {
            let d = *p - lo;
            (
                spread(q(d.x)) | spread(q(d.y)) << 1 | spread(q(d.z)) << 2,
                i as u32,
            )
        })
        .collect();
    keys.sort_unstable();
    keys.into_iter().map(|k| k.1).collect()
}

/// Marks a body without spin in the per-step rotation cache, so the integrator need not read
/// `spin`. `from_scaled_axis` never yields w > 1 (w is a cosine, or NaN), so this cannot collide
/// with a real rotation.
const NO_SPIN: Quat = Quat::from_xyzw(0.0, 0.0, 0.0, 2.0);

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
    /// Per-body rotation over one step, exp(ω dt), for the dt in `spin_step_dt`, or [`NO_SPIN`].
    /// Spins never change (the response exchanges linear velocities only), so the trigonometry is
    /// done once, not per frame; the result is bit-identical to recomputing it.
    spin_step: Vec<Quat>,
    spin_step_dt: f64,
    /// Velocity changes of the bodies that hit a wall in the last step, one list per thread's
    /// chunk, in body order (kept to reuse the allocations).
    wall_hits: Vec<Vec<Vec3>>,
    /// Sum of the velocity changes made by wall reflections since generation (unit masses, so this
    /// is the momentum the walls put in): momentum minus this is conserved by everything else.
    pub wall_impulse: Vec3,
}

/// One thread's contiguous share of the per-body arrays.
struct Chunk<'a> {
    position: &'a mut [Vec3],
    velocity: &'a mut [Vec3],
    orientation: &'a mut [Quat],
    basis: &'a mut [LMat3],
    spin_step: &'a [Quat],
}

impl Chunk<'_> {
    /// Advance every body of the chunk; push the velocity change of each body a wall reflected.
    fn integrate(self, dt: f64, lo: Vec3, hi: Vec3, hits: &mut Vec<Vec3>) {
        hits.clear();
        let bodies = self
            .position
            .iter_mut()
            .zip(self.velocity.iter_mut())
            .zip(self.orientation.iter_mut())
            .zip(self.basis.iter_mut())
            .zip(self.spin_step);
        for ((((pos, vel), ori), basis), step) in bodies {
            let v0 = *vel;
            let mut p = *pos + v0 * dt;
            let mut v = v0;
            for a in 0..3 {
                if p[a] < lo[a] {
                    p[a] = (2.0 * lo[a] - p[a]).min(hi[a]);
                    v[a] = v[a].abs();
                } else if p[a] > hi[a] {
                    p[a] = (2.0 * hi[a] - p[a]).max(lo[a]);
                    v[a] = -v[a].abs();
                }
            }
            *pos = p;
            // Adding a zero change leaves the sum's bits as they are (it starts at +0 and a sum of
            // floats is -0 only when both terms are), so only non-zero changes are kept; a NaN
            // velocity compares unequal and is kept, as the sequential sum would have taken it.
            let dv = v - v0;
            if dv != Vec3::ZERO {
                hits.push(dv);
                *vel = v;
            }
            if *step != NO_SPIN {
                let q = (*step * *ori).normalize();
                *ori = q;
                *basis = LMat3::from(glam::DMat3::from_quat(q).as_mat3());
            }
        }
    }
}

/// exp(ω dt) for one body, or [`NO_SPIN`] when it does not spin.
fn spin_step(w: Vec3, dt: f64) -> Quat {
    if w == Vec3::ZERO {
        NO_SPIN
    } else {
        Quat::from_scaled_axis(w * dt)
    }
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
            wall_hits: Vec::new(),
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
    /// The same as [`World::integrate_threads`] with one thread.
    pub fn integrate(&mut self, dt: f64) {
        self.integrate_threads(dt, 1);
    }

    /// [`World::integrate`] with the bodies split into contiguous chunks, one per thread, on up to
    /// `threads` threads (the calling thread takes the first chunk, the others are jobs of the
    /// rayon pool it runs on). The result is
    /// bit-identical to one thread for every `threads`, including [`World::wall_impulse`]. Below
    /// [`PARALLEL_MIN_BODIES`] bodies, or with `threads` <= 1, it runs on the calling thread.
    pub fn integrate_threads(&mut self, dt: f64, threads: usize) {
        let n = self.position.len();
        let chunks = if n < PARALLEL_MIN_BODIES {
            1
        } else {
            threads.clamp(1, (n / MIN_BODIES_PER_THREAD).max(1))
        };
        let size = n.div_ceil(chunks).max(1);
        let chunks = n.div_ceil(size).max(1);
        if self.spin_step_dt.to_bits() != dt.to_bits() || self.spin_step.len() != self.spin.len() {
            self.refresh_spin_steps(dt, chunks, size);
        }
        let (lo, hi) = (self.lo, self.hi);
        self.wall_hits.resize_with(chunks, Vec::new);
        let parts = self
            .position
            .chunks_mut(size)
            .zip(self.velocity.chunks_mut(size))
            .zip(self.orientation.chunks_mut(size))
            .zip(self.basis.chunks_mut(size))
            .zip(self.spin_step.chunks(size))
            .map(
                |((((position, velocity), orientation), basis), spin_step)| Chunk {
                    position,
                    velocity,
                    orientation,
                    basis,
                    spin_step,
                },
            );
        let mut jobs = parts.zip(self.wall_hits.iter_mut());
        if chunks == 1 {
            if let Some((chunk, hits)) = jobs.next() {
                chunk.integrate(dt, lo, hi, hits);
            }
        } else {
            rayon::in_place_scope(|s| {
                let first = jobs.next();
                for (chunk, hits) in jobs {
                    s.spawn(move |_| chunk.integrate(dt, lo, hi, hits));
                }
                if let Some((chunk, hits)) = first {
                    chunk.integrate(dt, lo, hi, hits);
                }
            });
        }
        // Chunks are in body order and each lists its hits in body order: this is the
        // sequential sum.
        for dv in self.wall_hits.iter().flatten() {
            self.wall_impulse += *dv;
        }
    }

    /// Recompute the per-step rotation cache for `dt`, in chunks of `size` on as many threads.
    fn refresh_spin_steps(&mut self, dt: f64, chunks: usize, size: usize) {
        self.spin_step.clear();
        self.spin_step.resize(self.spin.len(), NO_SPIN);
        let fill = |steps: &mut [Quat], spins: &[Vec3]| {
            for (q, &w) in steps.iter_mut().zip(spins) {
                *q = spin_step(w, dt);
            }
        };
        if chunks <= 1 {
            fill(&mut self.spin_step, &self.spin);
        } else {
            rayon::in_place_scope(|s| {
                let fill = &fill;
                for (steps, spins) in self.spin_step.chunks_mut(size).zip(self.spin.chunks(size)) {
                    s.spawn(move |_| fill(steps, spins));
                }
            });
        }
        self.spin_step_dt = dt;
    }

    /// Renumber the bodies: body `i` afterwards is body `order[i]` before (every per-body array
    /// and the per-step rotation cache move together). Used to keep bodies in spatial order, so
    /// that bodies near in space are near in memory.
    ///
    /// # Panics
    /// If `order` is not a permutation of `0..len()`.
    pub fn reorder(&mut self, order: &[u32]) {
        let n = self.len();
        assert_eq!(order.len(), n, "reorder: order has the wrong length");
        let words = n.div_ceil(64);
        let mut seen = vec![0u64; words];
        for &i in order {
            let i = i as usize;
            assert!(
                i < n && seen[i / 64] & (1 << (i % 64)) == 0,
                "reorder: not a permutation"
            );
            seen[i / 64] |= 1 << (i % 64);
        }
        // In place, one cycle of the permutation at a time and every array together: no array
        // is copied (at a million bodies a copy of each is ~180 MB of fresh pages), and an order
        // close to the current one (as the grid's is, refreshed every few seconds) is a walk
        // over nearby memory.
        let spin_step = self.spin_step.len() == n;
        let mut done = seen;
        done.iter_mut().for_each(|w| *w = 0);
        for start in 0..n {
            if done[start / 64] & (1 << (start % 64)) != 0 {
                continue;
            }
            let keep = (
                self.position[start],
                self.velocity[start],
                self.orientation[start],
                self.spin[start],
                self.basis[start],
                if spin_step {
                    self.spin_step[start]
                } else {
                    NO_SPIN
                },
            );
            let mut to = start;
            loop {
                done[to / 64] |= 1 << (to % 64);
                let from = order[to] as usize;
                if from == start {
                    self.position[to] = keep.0;
                    self.velocity[to] = keep.1;
                    self.orientation[to] = keep.2;
                    self.spin[to] = keep.3;
                    self.basis[to] = keep.4;
                    if spin_step {
                        self.spin_step[to] = keep.5;
                    }
                    break;
                }
                self.position[to] = self.position[from];
                self.velocity[to] = self.velocity[from];
                self.orientation[to] = self.orientation[from];
                self.spin[to] = self.spin[from];
                self.basis[to] = self.basis[from];
                if spin_step {
                    self.spin_step[to] = self.spin_step[from];
                }
                to = from;
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

    /// The integrator as it was before threads: one loop, the wall impulse summed over every body.
    fn integrate_reference(w: &mut World, steps: &mut Vec<Quat>, dt: f64) {
        let (lo, hi) = (w.lo, w.hi);
        if steps.len() != w.spin.len() {
            steps.clear();
            steps.extend(w.spin.iter().map(|&s| Quat::from_scaled_axis(s * dt)));
        }
        for i in 0..w.position.len() {
            let mut p = w.position[i] + w.velocity[i] * dt;
            let mut v = w.velocity[i];
            for a in 0..3 {
                if p[a] < lo[a] {
                    p[a] = (2.0 * lo[a] - p[a]).min(hi[a]);
                    v[a] = v[a].abs();
                } else if p[a] > hi[a] {
                    p[a] = (2.0 * hi[a] - p[a]).max(lo[a]);
                    v[a] = -v[a].abs();
                }
            }
            w.wall_impulse += v - w.velocity[i];
            w.position[i] = p;
            w.velocity[i] = v;
            if w.spin[i] != Vec3::ZERO {
                let q = (steps[i] * w.orientation[i]).normalize();
                w.orientation[i] = q;
                w.basis[i] = LMat3::from(glam::DMat3::from_quat(q).as_mat3());
            }
        }
    }

    /// Every per-body value and the wall impulse, as bits.
    fn state_bits(w: &World) -> Vec<u64> {
        let mut out = Vec::with_capacity(w.len() * 19 + 3);
        for i in 0..w.len() {
            out.extend(w.position[i].to_array().map(f64::to_bits));
            out.extend(w.velocity[i].to_array().map(f64::to_bits));
            out.extend(w.orientation[i].to_array().map(f64::to_bits));
            out.extend(w.basis[i].to_cols_array().map(|x| u64::from(x.to_bits())));
        }
        out.extend(w.wall_impulse.to_array().map(f64::to_bits));
        out
    }

    /// A scene big enough for three threads, with some bodies that do not spin.
    fn threaded_scene() -> World {
        let mut w = World::generate(&SceneConfig::paper(
            3 * MIN_BODIES_PER_THREAD as u32 + 7,
            11,
        ));
        for i in (0..w.len()).step_by(7) {
            w.spin[i] = Vec3::ZERO;
        }
        w
    }

    #[test]
    fn one_two_and_three_threads_match_the_sequential_integrator_bit_for_bit() {
        let dt = 1.0 / 60.0;
        let mut reference = threaded_scene();
        let mut steps = Vec::new();
        for _ in 0..200 {
            integrate_reference(&mut reference, &mut steps, dt);
        }
        assert!(
            reference.wall_impulse.length() > 1.0,
            "the run must include wall hits: {}",
            reference.wall_impulse
        );
        let expected = state_bits(&reference);
        for threads in [1, 2, 3] {
            let mut w = threaded_scene();
            for _ in 0..200 {
                w.integrate_threads(dt, threads);
            }
            assert_eq!(
                w.wall_hits.len(),
                threads,
                "{threads} threads were not used"
            );
            assert!(state_bits(&w) == expected, "{threads} threads differ");
        }
        let mut w = threaded_scene();
        for _ in 0..200 {
            w.integrate(dt);
        }
        assert!(state_bits(&w) == expected, "integrate differs");
    }

    #[test]
    fn small_scenes_and_odd_thread_counts_integrate_on_one_thread_alike() {
        let dt = 1.0 / 60.0;
        let mut one = World::generate(&SceneConfig::paper(500, 2));
        let mut many = one.clone();
        for _ in 0..100 {
            one.integrate(dt);
            many.integrate_threads(dt, 64);
        }
        assert_eq!(many.wall_hits.len(), 1);
        assert!(state_bits(&one) == state_bits(&many));
        let mut empty = World::generate(&SceneConfig::paper(500, 2));
        empty.position.clear();
        empty.velocity.clear();
        empty.orientation.clear();
        empty.spin.clear();
        empty.basis.clear();
        empty.integrate_threads(dt, 0);
        assert_eq!(empty.wall_impulse, Vec3::ZERO);
    }

    #[test]
    fn reorder_commutes_with_integration() {
        let dt = 1.0 / 60.0;
        let mut a = World::generate(&SceneConfig::paper(300, 4));
        a.integrate(dt); // fills the rotation cache, which reorder must move too
        let mut b = a.clone();
        let order: Vec<u32> = (0..300u32).map(|i| (i * 7) % 300).collect();
        for _ in 0..50 {
            a.integrate(dt);
        }
        b.reorder(&order);
        for _ in 0..50 {
            b.integrate(dt);
        }
        a.reorder(&order);
        // Bodies, not the wall impulse (its sum runs in a different body order).
        let bodies = |w: &World| state_bits(w)[..w.len() * 19].to_vec();
        assert!(bodies(&a) == bodies(&b));
    }

    #[test]
    #[should_panic(expected = "not a permutation")]
    fn reorder_refuses_a_repeated_index() {
        let mut w = World::generate(&SceneConfig::paper(3, 1));
        w.reorder(&[0, 1, 1]);
    }
}
