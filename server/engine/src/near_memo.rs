//! Memory across frames for near misses under the shape truth (docs/DESIGN.md "Exact answer").
//!
//! A pair whose leaf spheres overlap while its stars do not touch (a *near miss*: approaching,
//! or interlocked spike between spikes) is the shape truth's common case: at N = 10,000 about
//! 9,000 of 31,000 candidate pairs in the steady state, against 2,000 pairs colliding on the
//! leaves under the leaf truth, because bodies now pass into each other's leaf-sphere envelope
//! before they touch. Proving each apart again from its roots costs a descent through two
//! interpenetrating trees (hundreds to thousands of sphere tests) and a shape test.
//!
//! So each near miss keeps, until the next frame, the proof it was settled with: the leaf pair
//! that overlapped, a lower bound on the stars' distance ([`StarGeometry::intersects_or_bound`])
//! and the relative pose it holds at. Next frame, if the relative motion since then (translation
//! plus rotation times R, which bounds how far any point of B moved in A's frame) is below the
//! bound, the pair is still apart and is settled with one test; otherwise its leaf pair is tried
//! first (two tests) and, if it still overlaps, the pair goes straight to its shape test.
//! Either way the answer is the one a full test gives: the memory saves work, never changes an
//! outcome (tested against memoryless runs).
//!
//! The table is keyed by the pair's bodies, written between frames and read by every thread of a
//! frame; open addressing with a multiplicative hash, deterministic.
//!
//! [`StarGeometry::intersects_or_bound`]: crate::star_contact::StarGeometry::intersects_or_bound

use glam::{DMat3, DVec3};

use crate::star_contact::Pose;

/// Added to the motion bound before it is compared with a stored clearance: the stored pose is
/// kept in f32, whose rounding moves a point of B by about 3e-7 R at most.
const MARGIN: f64 = 1e-5;

/// What a near miss keeps for the next frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Memo {
    /// Bodies, `a < b` (0 marks an empty slot with `b` 0: no pair has `b` 0).
    key: u64,
    /// The leaf pair that overlapped (A's, B's).
    pub leaves: [u16; 2],
    /// Proven lower bound on the stars' distance at `pose` (scene units).
    pub clearance: f32,
    /// B's axes in A's frame when the bound was proven.
    rotation: [f32; 9],
    /// B's centre in A's frame then.
    translation: [f32; 3],
}

impl Memo {
    /// No memo (an empty slot).
    pub const EMPTY: Self = Self {
        key: EMPTY,
        leaves: [0, 0],
        clearance: 0.0,
        rotation: [0.0; 9],
        translation: [0.0; 3],
    };

    /// A memo for bodies `a < b` apart by at least `clearance` at `pose`.
    pub fn new(a: u32, b: u32, leaves: [u16; 2], clearance: f64, pose: &Pose) -> Self {
        // Rounded down: a clearance stored larger than proven would be unsound.
        let mut c = clearance.max(0.0) as f32;
        if f64::from(c) > clearance {
            c = c.next_down().max(0.0);
        }
        Self {
            key: key(a, b),
            leaves,
            clearance: c,
            rotation: pose.rotation.to_cols_array().map(|x| x as f32),
            translation: pose.translation.to_array().map(|x| x as f32),
        }
    }

    /// How far any point of a star of bounding radius `radius` (B's) can have moved in A's
    /// frame between the memo's pose and `pose`: |Δt| + ‖ΔR‖ R, with the Frobenius norm
    /// bounding the operator norm, plus [`MARGIN`] R for the stored pose's rounding.
    pub fn motion(&self, pose: &Pose, radius: f64) -> f64 {
        let t0 = DVec3::from_array(self.translation.map(f64::from));
        let r0 = DMat3::from_cols_array(&self.rotation.map(f64::from));
        let dr = pose.rotation - r0;
        let frob =
            (dr.x_axis.length_squared() + dr.y_axis.length_squared() + dr.z_axis.length_squared())
                .sqrt();
        (pose.translation - t0).length() + (frob + MARGIN) * radius
    }
}

#[inline]
fn key(a: u32, b: u32) -> u64 {
    (u64::from(a) << 32) | u64::from(b)
}

const EMPTY: u64 = 0;

/// Near misses of one frame, keyed by their bodies.
#[derive(Debug, Clone, Default)]
pub struct NearTable {
    slots: Vec<Memo>,
    len: usize,
}

impl NearTable {
    /// Forget every memo (keeps the storage).
    pub fn clear(&mut self) {
        // Storage for one pathological frame is not kept for good.
        if self.slots.len() > 4096 && self.slots.len() > 16 * self.len.max(1) {
            self.slots = Vec::new();
        } else if self.len > 0 {
            self.slots.iter_mut().for_each(|m| m.key = EMPTY);
        }
        self.len = 0;
    }

    /// Memos held.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether no memo is held.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    #[inline]
    fn slot(&self, k: u64) -> usize {
        let mask = self.slots.len() - 1;
        (k.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 32) as usize & mask
    }

    /// Keep `memo` (replacing one for the same pair).
    pub fn insert(&mut self, memo: Memo) {
        if (self.len + 1) * 2 > self.slots.len() {
            self.grow();
        }
        let mut i = self.slot(memo.key);
        loop {
            let s = &mut self.slots[i];
            if s.key == EMPTY {
                *s = memo;
                self.len += 1;
                return;
            }
            if s.key == memo.key {
                *s = memo;
                return;
            }
            i = (i + 1) & (self.slots.len() - 1);
        }
    }

    fn grow(&mut self) {
        let cap = (self.slots.len() * 2).max(64);
        let old = std::mem::replace(&mut self.slots, vec![Memo::EMPTY; cap]);
        self.len = 0;
        for m in old.into_iter().filter(|m| m.key != EMPTY) {
            self.insert(m);
        }
    }

    /// The memo of bodies `a < b`, if last frame left one.
    #[inline]
    pub fn get(&self, a: u32, b: u32) -> Option<&Memo> {
        if self.len == 0 {
            return None;
        }
        let k = key(a, b);
        let mut i = self.slot(k);
        loop {
            let s = &self.slots[i];
            if s.key == k {
                return Some(s);
            }
            if s.key == EMPTY {
                return None;
            }
            i = (i + 1) & (self.slots.len() - 1);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(angle: f64, t: DVec3) -> Pose {
        Pose {
            rotation: DMat3::from_rotation_z(angle),
            translation: t,
        }
    }

    #[test]
    fn inserted_memos_are_found_and_others_are_not() {
        let mut table = NearTable::default();
        let p = pose(0.0, DVec3::X);
        for a in 0..1000u32 {
            table.insert(Memo::new(a, a + 7, [1, 2], 0.5, &p));
        }
        assert_eq!(table.len(), 1000);
        for a in 0..1000u32 {
            assert_eq!(table.get(a, a + 7).map(|m| m.leaves), Some([1, 2]));
            assert!(table.get(a, a + 8).is_none());
        }
        table.insert(Memo::new(3, 10, [4, 5], 0.5, &p));
        assert_eq!(
            (table.len(), table.get(3, 10).map(|m| m.leaves)),
            (1000, Some([4, 5]))
        );
        table.clear();
        assert!(table.is_empty() && table.get(3, 10).is_none());
    }

    /// The motion bound covers how far every point of B actually moved.
    #[test]
    fn the_motion_bound_covers_every_point_of_b() {
        let r = 0.2;
        let (p0, p1) = (
            pose(0.3, DVec3::new(0.3, 0.1, 0.0)),
            pose(0.37, DVec3::new(0.31, 0.09, 0.01)),
        );
        let m = Memo::new(0, 1, [0, 0], 0.1, &p0).motion(&p1, r);
        for k in 0..200 {
            let u = DVec3::new(
                (k as f64).sin(),
                (k as f64 * 0.7).cos(),
                (k as f64 * 1.3).sin(),
            );
            let x = u.normalize() * r;
            let moved = (p1.rotation * x + p1.translation) - (p0.rotation * x + p0.translation);
            assert!(moved.length() <= m, "{} > {m}", moved.length());
        }
        assert!(m < 0.05, "{m}");
    }
}
