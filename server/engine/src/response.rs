//! Collision response (paper section 2): colliding bodies exchange velocities. With equal masses
//! this is the elastic response along any direction and conserves momentum and kinetic energy
//! exactly. It is applied only while the pair approaches ((vB - vA)·(pB - pA) < 0); a pair that is
//! already separating keeps its velocities, so an overlap that persists for a few frames does not
//! make the bodies swap back and forth (jitter, sticking).

use rayon::prelude::*;

use crate::math::Vec3;
use crate::narrow_phase::shape_pose;
use crate::prefetch::Prefetcher;
use crate::sphere_tree::SphereTree;
use crate::world::World;

/// Pairs ahead of the one exchanged whose bodies' state is asked of the memory meanwhile.
///
/// The pairs come region by region in the order the frame searched them, not in the bodies'
/// order, so each pair's four reads (two positions, two velocities) were mostly misses of the
/// processor's caches: at 100,000 bodies with a 16 ms budget (130,000 pairs on the list, most of
/// them deemed) the response took 3 ms a frame, a fifth of the budget, all of it in the frame's
/// tail. 8, 16, 32 and 64 ahead took 0.81, 0.75, 0.73 and 0.73 of the time without (medians over
/// ten frames, docs/BENCHMARKS.md).
const AHEAD: usize = 32;

/// The response phase, with storage for a frame's pairs kept from frame to frame.
#[derive(Debug, Default)]
pub struct Response {
    pairs: Vec<(u32, u32)>,
    /// The shape truth's pairs (with whether each is a real collision) and their normals.
    shape_pairs: Vec<(u32, u32, bool)>,
    normals: Vec<Vec3>,
}

impl Response {
    /// Exchange velocities of each approaching pair in `pairs`, in order. Returns how many
    /// exchanged.
    ///
    /// The order matters (a body on two approaching pairs takes the second's exchange after the
    /// first's) and is kept. The pairs are listed first: a loop over a list can ask for the
    /// bodies of the pair [`AHEAD`] places on, which took half the time of reading the same
    /// pairs ahead through the iterator (the list costs a pass over the pairs, which the iterator
    /// made anyway).
    pub fn exchange(
        &mut self,
        world: &mut World,
        pairs: impl IntoIterator<Item = (u32, u32)>,
    ) -> u32 {
        self.pairs.clear();
        self.pairs.extend(pairs);
        let n = exchange_listed(world, &self.pairs);
        // Storage for one pathological frame's pairs is not kept for good.
        if self.pairs.capacity() > 4 * self.pairs.len().max(KEEP) {
            self.pairs.shrink_to(2 * self.pairs.len().max(KEEP));
        }
        n
    }
}

impl Response {
    /// The shape truth's response: each approaching pair on the collision list, in order,
    /// exchanges its velocity components along a normal: for a real collision (`true`) the
    /// stars' contact normal ([`crate::star_contact`]), for a pair deemed at interruption (no
    /// contact was found) the centre line. Returns how many exchanged.
    ///
    /// With equal masses this is the elastic response along the normal: momentum and kinetic
    /// energy are kept exactly (up to rounding), and the tangential motion is left alone, so a
    /// glancing touch between two spikes deflects the bodies instead of swapping their paths.
    pub fn exchange_on_shape(
        &mut self,
        world: &mut World,
        tree: &SphereTree,
        pairs: impl IntoIterator<Item = (u32, u32, bool)>,
        threads: usize,
    ) -> u32 {
        self.shape_pairs.clear();
        self.shape_pairs.extend(pairs);
        // The normals depend on the poses alone, which the exchanges leave alone: they are found
        // first, on up to `threads` threads (a real collision's contact costs microseconds, the
        // exchange nanoseconds), and the exchanges then run in the list's order as before.
        let world_ref: &World = world;
        let normal = |&(a, b, real): &(u32, u32, bool)| -> Vec3 {
            let (a, b) = (a as usize, b as usize);
            if real {
                // A real collision was settled touching by the shape test on this very pose.
                let c = tree
                    .geometry()
                    .contact_of_touching(&shape_pose(world_ref, a, b));
                world_ref.orientation[a] * c.normal()
            } else {
                (world_ref.position[b] - world_ref.position[a]).normalize_or(Vec3::X)
            }
        };
        let real = self.shape_pairs.iter().filter(|p| p.2).count();
        self.normals.clear();
        if threads > 1 && real >= PARALLEL_CONTACTS {
            self.shape_pairs
                .par_iter()
                .with_min_len(PARALLEL_CONTACTS / 2)
                .map(normal)
                .collect_into_vec(&mut self.normals);
        } else {
            self.normals.extend(self.shape_pairs.iter().map(normal));
        }
        let mut n = 0;
        for (&(a, b, _), &normal) in self.shape_pairs.iter().zip(&self.normals) {
            let (a, b) = (a as usize, b as usize);
            let approach = (world.velocity[b] - world.velocity[a]).dot(normal);
            if approach < 0.0 {
                let dv = normal * approach;
                world.velocity[a] += dv;
                world.velocity[b] -= dv;
                n += 1;
            }
        }
        n
    }
}

/// Real collisions in a frame from which the shape truth's contacts are found on more than one
/// thread: below it the hand-off costs more than the contacts (a few microseconds each).
const PARALLEL_CONTACTS: usize = 64;

/// Pairs' worth of storage a [`Response`] keeps however few the last frame had.
const KEEP: usize = 4096;

fn exchange_listed(world: &mut World, pairs: &[(u32, u32)]) -> u32 {
    let prefetch = Prefetcher::new();
    let (velocity, position) = (&mut world.velocity, &world.position);
    let mut n = 0;
    for (i, &(a, b)) in pairs.iter().enumerate() {
        if let Some(&(c, d)) = pairs.get(i + AHEAD) {
            for body in [c as usize, d as usize] {
                prefetch.hint(velocity, body);
                prefetch.hint(position, body);
            }
        }
        let (a, b) = (a as usize, b as usize);
        let approach = (velocity[b] - velocity[a]).dot(position[b] - position[a]);
        if approach < 0.0 {
            velocity.swap(a, b);
            n += 1;
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::SceneConfig;

    /// The look-ahead changes what is read early, not the order of the exchanges: over many
    /// pairs sharing bodies (a body on several approaching pairs takes each exchange in turn),
    /// the velocities and the count are those of exchanging pair by pair, and a second frame's
    /// shorter list on the same storage gives its own answer.
    #[test]
    fn listed_exchanges_match_exchanging_pair_by_pair() {
        let mut rng = crate::rng::Rng::new(7);
        let mut response = Response::default();
        for (len, seed) in [(5_000, 3), (40, 4)] {
            let mut w = World::generate(&SceneConfig::paper(500, seed));
            let pairs: Vec<(u32, u32)> = (0..len)
                .map(|_| {
                    let a = (rng.next_f64() * 50.0) as u32;
                    (a, a + 1 + (rng.next_f64() * 400.0) as u32)
                })
                .collect();
            let mut naive = w.clone();
            let mut swaps = 0;
            for &(a, b) in &pairs {
                let (a, b) = (a as usize, b as usize);
                let v = &naive.velocity;
                if (v[b] - v[a]).dot(naive.position[b] - naive.position[a]) < 0.0 {
                    naive.velocity.swap(a, b);
                    swaps += 1;
                }
            }
            assert_eq!(response.exchange(&mut w, pairs.iter().copied()), swaps);
            assert!(swaps > 0 && swaps < len, "{swaps} of {len}");
            assert_eq!(w.velocity, naive.velocity, "{len} pairs");
        }
    }

    #[test]
    fn approaching_pairs_swap_and_separating_pairs_do_not() {
        let mut w = World::generate(&SceneConfig::paper(3, 1));
        w.position = vec![Vec3::ZERO, Vec3::X, Vec3::new(5.0, 0.0, 0.0)];
        w.velocity = vec![Vec3::X, -Vec3::X, Vec3::Y];
        let (p0, e0) = (w.momentum(), w.kinetic_energy());
        assert_eq!(Response::default().exchange(&mut w, [(0, 1)]), 1);
        assert_eq!(w.velocity[0], -Vec3::X);
        assert_eq!(
            Response::default().exchange(&mut w, [(0, 1)]),
            0,
            "now separating: no swap back"
        );
        assert_eq!((w.momentum(), w.kinetic_energy()), (p0, e0));
    }
}
