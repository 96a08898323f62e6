//! One candidate pair's traversal state: its frame (body B in body A's frame), its status and the
//! outcome of a step (section 2), and the evidence of section 3 that a deemed pair leaves.

use super::*;

/// Body B's frame expressed in body A's frame: `x_A = m * x_B + t`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairFrame {
    pub(super) m: LMat3,
    pub(super) t: LVec3,
}

impl PairFrame {
    /// A placeholder (B's frame is A's) for storage not yet written.
    pub(super) const IDENTITY: Self = Self {
        m: LMat3::IDENTITY,
        t: LVec3::ZERO,
    };

    /// Relative frame of bodies `a` and `b`. The translation is formed in f64 before rounding, so a
    /// pair far from the origin is as exact as one at it.
    #[inline]
    pub fn new(world: &World, a: usize, b: usize) -> Self {
        let t = Self::translation(world, a, b);
        Self::with_translation(world, a, b, t)
    }

    /// The translation alone: B's centre in A's frame. The root test needs only this (the root
    /// sphere is centred on its body), so the rotation is formed only for pairs that pass it.
    #[inline]
    pub fn translation(world: &World, a: usize, b: usize) -> LVec3 {
        let d = (world.position[b] - world.position[a]).as_vec3();
        world.basis[a].transpose() * LVec3::from(d)
    }

    /// The frame with a translation already computed by [`Self::translation`].
    #[inline]
    pub fn with_translation(world: &World, a: usize, b: usize, t: LVec3) -> Self {
        Self {
            m: world.basis[a].transpose() * world.basis[b],
            t,
        }
    }

    /// Centre of B-sphere `s` in A's frame.
    #[inline]
    pub fn map(&self, s: Vec4) -> LVec3 {
        self.m * LVec3::from_vec4(s) + self.t
    }

    /// Centres of four B-spheres in A's frame, one vector per coordinate: lane q is
    /// `map(sphere q)` bit for bit (the matrix product sums its three columns' terms in the same
    /// order before the translation is added).
    #[inline]
    pub fn map_lanes(&self, x: Vec4, y: Vec4, z: Vec4) -> [Vec4; 3] {
        let (m, t) = (&self.m, self.t);
        let row = |c: usize| {
            ((Vec4::splat(m.x_axis[c]) * x + Vec4::splat(m.y_axis[c]) * y)
                + Vec4::splat(m.z_axis[c]) * z)
                + Vec4::splat(t[c])
        };
        [row(0), row(1), row(2)]
    }
}

/// Where a pair stands.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PairStatus {
    /// Not yet tested at all.
    Untested,
    /// Overlap found above leaf level; more steps needed.
    Active,
    /// Resolved: a leaf sphere of each overlaps (a real collision).
    Colliding,
    /// Resolved: no overlapping spheres (not colliding).
    Separate,
    /// Interrupted while untested or active: deemed colliding (section 2).
    Deemed,
}

impl PairStatus {
    /// Whether the pair still needs work.
    #[inline]
    pub fn is_open(self) -> bool {
        matches!(self, Self::Untested | Self::Active)
    }

    /// Whether the pair ends up on the collision list (real or deemed).
    #[inline]
    pub fn is_collision(self) -> bool {
        matches!(self, Self::Colliding | Self::Deemed)
    }
}

/// Result of one step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepOutcome {
    /// Leaf-leaf overlap: colliding, resolved.
    Hit,
    /// No overlap left: not colliding, resolved.
    Separate,
    /// Overlap above leaf level: stays active.
    Active,
}

/// Traversal state of one candidate pair.
#[derive(Debug, Clone, Copy)]
pub struct PairState {
    /// First body (smaller id).
    pub a: u32,
    /// Second body.
    pub b: u32,
    /// Status.
    pub status: PairStatus,
    /// Current level of A's and B's tree (1-based; 0 while untested).
    pub levels: [u8; 2],
    /// Level at which the pair was resolved (max of the two trees' levels), 0 if not resolved.
    pub resolved_level: u8,
    /// Last overlapping sphere pair found (A index, B index), for the gap estimate of section 3.
    pub last: [u16; 2],
    pub(super) list_start: u32,
    pub(super) list_len: u32,
}

impl PairState {
    pub(super) fn new(a: u32, b: u32) -> Self {
        Self {
            a,
            b,
            status: PairStatus::Untested,
            levels: [0, 0],
            resolved_level: 0,
            last: [NONE, NONE],
            list_start: 0,
            list_len: 0,
        }
    }

    /// Steps taken so far: 0 untested, then one per level descended (`levels` summed, less one).
    #[inline]
    pub fn stage(&self) -> u8 {
        if self.status == PairStatus::Untested {
            0
        } else {
            (self.levels[0] + self.levels[1]).saturating_sub(1)
        }
    }

    /// Sphere pairs still to test (0 once resolved).
    pub fn pending(&self) -> u32 {
        if self.status == PairStatus::Active {
            self.list_len
        } else {
            0
        }
    }
}

/// The two spheres whose overlap is the pair's current evidence, in world coordinates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evidence {
    /// Centre of the A sphere (world).
    pub center_a: Vec3,
    /// Centre of the B sphere (world).
    pub center_b: Vec3,
    /// Gap estimate g: distance between the two centres (section 3).
    pub gap: f64,
    /// Centre of collision: midpoint of the segment of the centre line inside both spheres.
    pub centre_of_collision: Vec3,
}

/// Midpoint of the part of the segment from `ca` to `cb` that lies in both spheres (or of the gap
/// between them if they do not overlap). Coincident centres give `ca`.
pub fn centre_of_collision(ca: Vec3, ra: f64, cb: Vec3, rb: f64) -> Vec3 {
    let d = cb - ca;
    let len = d.length();
    if len <= 0.0 {
        return ca;
    }
    ca + d * ((len + ra - rb) * 0.5 / len)
}
