//! Collision response (paper section 2): colliding bodies exchange velocities. With equal masses
//! this is the elastic response along any direction and conserves momentum and kinetic energy
//! exactly. It is applied only while the pair approaches ((vB - vA)·(pB - pA) < 0); a pair that is
//! already separating keeps its velocities, so an overlap that persists for a few frames does not
//! make the bodies swap back and forth (jitter, sticking).

use crate::world::World;

/// Exchange velocities of each approaching pair in `pairs`, in order. Returns how many exchanged.
pub fn exchange_velocities(world: &mut World, pairs: impl IntoIterator<Item = (u32, u32)>) -> u32 {
    let mut n = 0;
    for (a, b) in pairs {
        let (a, b) = (a as usize, b as usize);
        let approach =
            (world.velocity[b] - world.velocity[a]).dot(world.position[b] - world.position[a]);
        if approach < 0.0 {
            world.velocity.swap(a, b);
            n += 1;
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::config::SceneConfig;
    use crate::math::Vec3;

    #[test]
    fn approaching_pairs_swap_and_separating_pairs_do_not() {
        let mut w = World::generate(&SceneConfig::paper(3, 1));
        w.position = vec![Vec3::ZERO, Vec3::X, Vec3::new(5.0, 0.0, 0.0)];
        w.velocity = vec![Vec3::X, -Vec3::X, Vec3::Y];
        let (p0, e0) = (w.momentum(), w.kinetic_energy());
        assert_eq!(exchange_velocities(&mut w, [(0, 1)]), 1);
        assert_eq!(w.velocity[0], -Vec3::X);
        assert_eq!(
            exchange_velocities(&mut w, [(0, 1)]),
            0,
            "now separating: no swap back"
        );
        assert_eq!((w.momentum(), w.kinetic_energy()), (p0, e0));
    }
}
